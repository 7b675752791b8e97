//! `[scheme]`: which scheme and its parameters, read by the scheme's declaration
//! ([`gdsmc_core::physics::SchemeKind::params`]: a splitting's `dt`, the time-stepped scheme's
//! `step_factor` with its default), and (a rule of observing) that the observation times lie
//! on a splitting scheme's grid.

use super::Ctx;
use super::declared::Table;
use crate::error::Error;
use crate::schema::SchemeSpec;
use gdsmc_core::physics::{Param, SchemeChoice};

pub use gdsmc_core::physics::DEFAULT_STEP_FACTOR;

/// The scheme, with the keys that hold its parameters; a key the scheme does not have is
/// refused naming the keys it has.
pub(super) fn scheme(ctx: &mut Ctx<'_>, sch: &SchemeSpec) -> Result<SchemeChoice, Error> {
    ctx.holds(Param::Scheme, "scheme.kind", sch.kind.span());
    let kind = *sch.kind.get_ref();
    let kind_words = format!("kind = \"{}\"", kind.scene_name());
    let table = Table {
        name: "scheme",
        numbers: &sch.numbers,
        kind_span: sch.kind.span(),
        kind_words: kind_words.clone(),
    };
    let keys: Vec<&str> = std::iter::once("kind")
        .chain(kind.params().iter().map(|p| p.name))
        .collect();
    table.only(
        ctx,
        &keys,
        std::iter::empty(),
        &format!("[scheme] with {kind_words}"),
    )?;
    let values = table.declared(ctx, kind.params(), |i| Param::Step(kind, i))?;
    Ok(SchemeChoice::new(kind, &values).expect("one value per declared parameter"))
}

/// A splitting scheme observes only on its grid: every observation time a multiple of `dt`.
pub(super) fn on_grid(
    ctx: &Ctx<'_>,
    sch: &SchemeSpec,
    scheme: SchemeChoice,
    times: &[f64],
) -> Result<(), Error> {
    let at = sch.numbers.get("dt").map_or(0..0, |d| d.span());
    match grid_problem(scheme, times) {
        Some(message) => ctx.invalid(at, "scheme.dt", message),
        None => Ok(()),
    }
}

/// The rule of `scheme.dt` against the observation times (a splitting scheme observes only on
/// its grid, [`gdsmc_core::engine::grid_index`]): what is wrong, or `None`.
pub(crate) fn grid_problem(scheme: SchemeChoice, times: &[f64]) -> Option<String> {
    let (SchemeChoice::Euler(dt) | SchemeChoice::Strang(dt)) = scheme else {
        return None;
    };
    // The run starts at 0 (the engine is launched there) and ends at its last time.
    let t_end = times.last().copied().unwrap_or(0.0);
    if let Err(e) = scheme.check_span(t_end) {
        return Some(e.problem.to_string());
    }
    let t = *times
        .iter()
        .find(|&&t| gdsmc_core::engine::grid_index(0.0, dt, t).is_none())?;
    Some(if t / dt >= u64::MAX as f64 {
        format!("= {dt} is too small: reaching t = {t} would take more than 2^64 steps")
    } else {
        format!("must divide every observation time; {t} is not a multiple of {dt}")
    })
}
