//! The references of a configuration (`gdsmc-theory`): the exact solutions, finite-n means and
//! approximations that hold for its physics, as `gdsmc run` writes them beside its means. The
//! same code computes both, so a C caller's values equal the command's columns to the bit.
//! Needs the standard library.

use crate::config::gdsmc_config;
use crate::guard::{check_ptr, guard};
use crate::status::{Failure, fail, gdsmc_status, msg};
use gdsmc_theory::curves::{Kind, ReferenceCurve, for_scene};
use std::ffi::{CStr, CString, c_char};
use std::sync::Mutex;

/// `gdsmc_reference.kind`: the exact ensemble mean at the configuration's n (and scheme); a
/// run's mean must lie within its interval of it.
pub const GDSMC_REFERENCE_MEAN_AT_N: u32 = 0;

/// `gdsmc_reference.kind`: an exact solution of the Boltzmann equation (n -> infinity); a mean
/// at finite n lies O(1/n) from it.
pub const GDSMC_REFERENCE_LIMIT: u32 = 1;

/// `gdsmc_reference.kind`: an approximation (Sonine, Maxwellian, a hydrodynamic closure):
/// shown, not judged.
pub const GDSMC_REFERENCE_APPROXIMATION: u32 = 2;

/// One reference curve of a configuration.
#[repr(C)]
#[derive(Clone, Copy, Debug)]
pub struct gdsmc_reference {
    /// Its column name (`T_mean_n`), NUL-terminated, in static storage (never free it).
    pub name: *const c_char,
    /// The observable it is the reference of (`T`, `T_bulk`, `a2`), static as `name`.
    pub of: *const c_char,
    /// Its paper and equation, static as `name`.
    pub source: *const c_char,
    /// What it is to a run's means: GDSMC_REFERENCE_MEAN_AT_N, _LIMIT or _APPROXIMATION.
    pub kind: u32,
    /// How many of the asked times its arithmetic cannot hold at (their values are NaN).
    pub not_computable: usize,
}

/// A static string as a NUL-terminated C string in static storage: each distinct one is copied
/// once, for the life of the program (the references' names and sources are a fixed set).
fn c_static(s: &'static str) -> *const c_char {
    static TABLE: Mutex<Vec<(&'static str, &'static CStr)>> = Mutex::new(Vec::new());
    let mut table = TABLE.lock().unwrap_or_else(|e| e.into_inner());
    if let Some((_, c)) = table.iter().find(|(k, _)| *k == s) {
        return c.as_ptr();
    }
    let c: &'static CStr = Box::leak(
        CString::new(s.replace('\0', " "))
            .expect("no NUL")
            .into_boxed_c_str(),
    );
    table.push((s, c));
    c.as_ptr()
}

/// The references of `*config` observed at `times[0..n_times]` (finite, from 0 on,
/// increasing: the ODE-solved ones are solved up to the last), as `gdsmc run` attaches them.
///
/// # Safety
/// As the exported functions that call it.
unsafe fn references(
    config: *const gdsmc_config,
    times: *const f64,
    n_times: usize,
) -> Result<(Vec<ReferenceCurve>, Vec<f64>), Failure> {
    check_ptr(config, "config")?;
    check_ptr(times, "times")?;
    if n_times == 0 {
        return fail(gdsmc_status::GDSMC_INVALID_ARGUMENT, "`n_times` is 0");
    }
    // SAFETY: checked non-null and aligned; the caller provides a readable gdsmc_config.
    let c = unsafe { config.read() };
    // SAFETY: checked non-null and aligned; the caller provides n_times readable doubles.
    let t = unsafe { std::slice::from_raw_parts(times, n_times) }.to_vec();
    let physics = c.physics()?;
    let scene = gdsmc_scene::Scene::of_physics(physics, t.clone()).map_err(|e| {
        Failure(
            gdsmc_status::GDSMC_INVALID_ARGUMENT,
            msg!("{}", e.to_string().replace("observe.times", "times")),
        )
    })?;
    Ok((for_scene(&scene), t))
}

/// Fills `*out` with reference `r` and `values` with it at `times`; GDSMC_NOT_COMPUTABLE
/// naming the first such time where the values are not finite.
///
/// # Safety
/// `out` writable for one gdsmc_reference (checked); `values` writable for `times.len()`
/// doubles (checked non-null).
unsafe fn fill(
    r: &ReferenceCurve,
    times: &[f64],
    out: *mut gdsmc_reference,
    values: *mut f64,
) -> Result<(), Failure> {
    check_ptr(out, "out")?;
    check_ptr(values, "values")?;
    // SAFETY: checked non-null and aligned; the caller provides times.len() writable doubles.
    let v = unsafe { std::slice::from_raw_parts_mut(values, times.len()) };
    for (x, &t) in v.iter_mut().zip(times) {
        *x = (r.curve)(t);
    }
    let missed: Vec<f64> = (times.iter().zip(v.iter()))
        .filter(|(_, x)| !x.is_finite())
        .map(|(&t, _)| t)
        .collect();
    let kind = match r.kind {
        Kind::MeanAtN => GDSMC_REFERENCE_MEAN_AT_N,
        Kind::Limit => GDSMC_REFERENCE_LIMIT,
        Kind::Approximation => GDSMC_REFERENCE_APPROXIMATION,
    };
    let reference = gdsmc_reference {
        name: c_static(r.name),
        of: c_static(r.of),
        source: c_static(r.source),
        kind,
        not_computable: missed.len(),
    };
    // SAFETY: checked non-null and aligned.
    unsafe { out.write(reference) };
    match missed.first() {
        None => Ok(()),
        Some(t) => fail(
            gdsmc_status::GDSMC_NOT_COMPUTABLE,
            msg!(
                "{} is not computable here at {} of the {} times, from t = {t}: its closed form \
                 leaves the range of double at these parameters (the values are NaN there)",
                r.name,
                missed.len(),
                times.len()
            ),
        ),
    }
}

/// `*count` = how many reference curves hold for `*config` observed at `times[0..n_times]`
/// (finite, from 0 on, increasing), as `gdsmc run` writes them beside its means: the exact
/// solutions, the exact means at the configuration's n and the approximations whose physics
/// the configuration is (none for a physics no reference holds for). Fails with
/// GDSMC_INVALID_ARGUMENT naming the field or the times.
///
/// # Safety
/// `config` NULL or a readable gdsmc_config; `times` NULL or `n_times` readable doubles;
/// `count` NULL or writable.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn gdsmc_reference_count(
    config: *const gdsmc_config,
    times: *const f64,
    n_times: usize,
    count: *mut usize,
) -> gdsmc_status {
    guard(|| {
        check_ptr(count, "count")?;
        // SAFETY: the caller's promises, passed on.
        let (refs, _) = unsafe { references(config, times, n_times) }?;
        // SAFETY: checked non-null and aligned.
        unsafe { count.write(refs.len()) };
        Ok(())
    })
}

/// Reference `index` (from 0, below gdsmc_reference_count's count, in the order of the
/// command's columns) of `*config` observed at `times[0..n_times]`: its description in `*out`
/// and its values at the times in `values[0..n_times]`, equal to the command's column to the
/// bit. GDSMC_NOT_COMPUTABLE when its arithmetic cannot hold at some times (`*out` and the
/// values are filled, NaN there, `out->not_computable` counting them).
///
/// # Safety
/// As gdsmc_reference_count; `out` NULL or writable for one gdsmc_reference; `values` NULL or
/// writable for `n_times` doubles.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn gdsmc_reference_get(
    config: *const gdsmc_config,
    times: *const f64,
    n_times: usize,
    index: usize,
    out: *mut gdsmc_reference,
    values: *mut f64,
) -> gdsmc_status {
    guard(|| {
        // SAFETY: the caller's promises, passed on.
        let (refs, t) = unsafe { references(config, times, n_times) }?;
        let Some(r) = refs.get(index) else {
            return fail(
                gdsmc_status::GDSMC_INVALID_ARGUMENT,
                msg!("`index` = {index}, but {} references hold here", refs.len()),
            );
        };
        // SAFETY: the caller's promises for `out` and `values`.
        unsafe { fill(r, &t, out, values) }
    })
}

/// The reference named `name` (a column name: `T_mean_n`, `T_exact`, `a2_exact`) of `*config`
/// observed at `times[0..n_times]`, as gdsmc_reference_get; GDSMC_NOT_FOUND, naming those that
/// hold, when none of that name holds for this physics.
///
/// # Safety
/// As gdsmc_reference_get; `name` NULL or a NUL-terminated string.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn gdsmc_reference_find(
    config: *const gdsmc_config,
    times: *const f64,
    n_times: usize,
    name: *const c_char,
    out: *mut gdsmc_reference,
    values: *mut f64,
) -> gdsmc_status {
    guard(|| {
        check_ptr(name, "name")?;
        // SAFETY: non-null; the caller promises a NUL-terminated string.
        let name = unsafe { CStr::from_ptr(name) }.to_string_lossy();
        // SAFETY: the caller's promises, passed on.
        let (refs, t) = unsafe { references(config, times, n_times) }?;
        let Some(r) = refs.iter().find(|r| r.name == name) else {
            let held: Vec<&str> = refs.iter().map(|r| r.name).collect();
            return fail(
                gdsmc_status::GDSMC_NOT_FOUND,
                msg!(
                    "no reference `{name}` holds for this configuration (these do: {})",
                    if held.is_empty() {
                        "none".to_string()
                    } else {
                        held.join(", ")
                    }
                ),
            );
        };
        // SAFETY: the caller's promises for `out` and `values`.
        unsafe { fill(r, &t, out, values) }
    })
}
