//! The C ABI with arbitrary arguments: configurations of any field values and enumeration
//! integers, buffers of any size and alignment, any sequence of calls on a handle, NULL
//! pointers. Every call must return a status and leave the handle usable or refused, never
//! crash (the fuzz build runs under AddressSanitizer); a destroyed in-place handle must be
//! refused with GDSMC_INVALID_HANDLE.
//!
//! The harness advances a simulation only when its configuration bounds the work (at most 256
//! particles, rates and speeds of order 100, time steps not tiny, to time 0.01): refusing
//! configurations whose work is absurd before running is issue 18's subject, not this target's.
//! Velocities set through the ABI are not guarded here: each handle gets a work limit of 1e6
//! (gdsmc_sim_set_work_limit), and the ABI refuses an advance its state makes absurd.

use crate::wild;
use arbitrary::Unstructured;
use gdsmc::*;
use gdsmc_core::physics::{DriveKind, KernelKind, LawKind, SchemeKind};
use std::ptr::{null, null_mut};

/// A 32-byte aligned block: the unit of the caller memory handed to gdsmc_sim_init_in.
#[derive(Clone, Copy)]
#[repr(C, align(32))]
struct Block([u8; 32]);

/// The most kinds any axis has (the core's declarations): an enumeration field is drawn from
/// `0..=MOST_KINDS`, every kind of every axis and one past them, or anything.
pub const MOST_KINDS: usize = {
    let k = [
        KernelKind::ALL.len(),
        LawKind::ALL.len(),
        DriveKind::ALL.len(),
        SchemeKind::ALL.len(),
    ];
    let (mut i, mut most) = (0, 0);
    while i < k.len() {
        if k[i] > most {
            most = k[i];
        }
        i += 1;
    }
    most
};
// The draw below reaches every code of every axis and one past them.
const _: () = assert!(MOST_KINDS + 1 < 9);

fn small_enum(u: &mut Unstructured<'_>) -> u32 {
    match u.int_in_range(0u8..=9).unwrap_or(0) {
        9 => u.arbitrary().unwrap_or(u32::MAX),
        k => (k as usize % (MOST_KINDS + 1)) as u32,
    }
}

fn config(u: &mut Unstructured<'_>) -> gdsmc_config {
    let mut c = gdsmc_config::example3();
    c.n = match u.int_in_range(0u8..=7).unwrap_or(0) {
        0 => u.arbitrary().unwrap_or(0),
        1 => u.int_in_range(0u64..=3).unwrap_or(0),
        _ => u.int_in_range(2u64..=300).unwrap_or(2),
    };
    c.seed = u.arbitrary().unwrap_or(1);
    c.stream = if u.ratio(1u8, 8u8).unwrap_or(false) {
        u.arbitrary().unwrap_or(0)
    } else {
        u.int_in_range(0u64..=3).unwrap_or(0)
    };
    c.kernel = small_enum(u);
    c.drive = small_enum(u);
    c.scheme = small_enum(u);
    c.restitution_law = small_enum(u);
    c.background_kernel = small_enum(u);
    // Each number either keeps GRW Example 3's value or takes a wild one.
    for f in [
        &mut c.gamma,
        &mut c.c,
        &mut c.restitution,
        &mut c.impact_beta0,
        &mut c.impact_delta,
        &mut c.beta,
        &mut c.mass,
        &mut c.temperature,
        &mut c.dt,
        &mut c.step_factor,
        &mut c.background_c,
        &mut c.background_density,
        &mut c.background_mass,
        &mut c.background_temperature,
    ] {
        if u.ratio(1u8, 4u8).unwrap_or(false) {
            *f = wild(u);
        }
    }
    // A declared drive's parameters (the Gaussian and Langevin thermostats, the constant
    // force, ...), in `drive_params`; a kernel's own (VHS's lambda), in `kernel_params`; the
    // weighted scheme's, in `scheme_params`.
    for f in c
        .drive_params
        .iter_mut()
        .chain(&mut c.kernel_params)
        .chain(&mut c.scheme_params)
    {
        if u.ratio(1u8, 2u8).unwrap_or(false) {
            *f = wild(u);
        }
    }
    for d in c.drift.iter_mut().chain(c.background_drift.iter_mut()) {
        if u.ratio(1u8, 8u8).unwrap_or(false) {
            *d = wild(u);
        }
    }
    // A mixture now and then: up to GDSMC_MAX_SPECIES + 1 species (one too many is refused),
    // counts that usually add up to n, wild species values and pair coefficients.
    if u.ratio(1u8, 4u8).unwrap_or(false) {
        c.species = u
            .int_in_range(0u32..=GDSMC_MAX_SPECIES as u32 + 1)
            .unwrap_or(0);
        let s = (c.species as usize).min(GDSMC_MAX_SPECIES);
        let mut left = c.n;
        for k in 0..s {
            c.species_count[k] = if k + 1 == s {
                left
            } else {
                u.int_in_range(0..=left).unwrap_or(0)
            };
            left -= c.species_count[k];
            if u.ratio(1u8, 16u8).unwrap_or(false) {
                c.species_count[k] = u.arbitrary().unwrap_or(0);
            }
        }
        for f in c
            .species_mass
            .iter_mut()
            .chain(c.species_temperature.iter_mut())
            .chain(c.species_diameter.iter_mut())
            .chain(c.species_beta.iter_mut())
            .chain(c.pair_restitution.iter_mut())
        {
            if u.ratio(1u8, 4u8).unwrap_or(false) {
                *f = wild(u);
            }
        }
        c.pair_restitution_set = u.int_in_range(0u32..=1).unwrap_or(0);
    }
    // Rough particles now and then, with wild rotation values.
    if u.ratio(1u8, 4u8).unwrap_or(false) {
        c.rough = u.int_in_range(0u32..=2).unwrap_or(1);
        c.tangential_restitution = u.int_in_range(-4i32..=4).unwrap_or(0) as f64 / 4.0;
        for f in [
            &mut c.tangential_restitution,
            &mut c.inertia,
            &mut c.rotation_temperature,
            &mut c.rotation_noise,
        ] {
            if u.ratio(1u8, 4u8).unwrap_or(false) {
                *f = wild(u);
            }
        }
    }
    // The start with exact momentum now and then (any nonzero value means it).
    if u.ratio(1u8, 8u8).unwrap_or(false) {
        c.exact_momentum = u.arbitrary().unwrap_or(1);
    }
    c
}

/// Whether advancing `c` to time 0.01 is a bounded amount of work (see the module docs).
fn bounded_work(c: &gdsmc_config) -> bool {
    let within = |x: f64, lo: f64, hi: f64| x.is_finite() && x >= lo && x <= hi;
    let speed2 = |t: f64, m: f64| m > 0.0 && within(t / m, 0.0, 100.0);
    c.n <= 256
        && within(c.gamma * c.c, 0.0, 100.0)
        && speed2(c.temperature, c.mass)
        && c.drift.iter().all(|d| within(*d, -10.0, 10.0))
        && within(c.beta, 0.0, 100.0)
        && c.drive_params.iter().all(|x| within(*x, -1.0, 100.0))
        && within(c.background_c * c.background_density, 0.0, 100.0)
        && speed2(c.background_temperature, c.background_mass)
        && c.background_drift.iter().all(|d| within(*d, -10.0, 10.0))
        && (0..(c.species as usize).min(GDSMC_MAX_SPECIES)).all(|k| {
            speed2(c.species_temperature[k], c.species_mass[k])
                && within(c.species_diameter[k], 1e-3, 10.0)
                && within(c.species_beta[k], 0.0, 100.0)
        })
        && (c.rough == 0
            || (speed2(c.rotation_temperature, c.inertia)
                && within(c.inertia, 1e-3, 1.0)
                && within(c.rotation_noise, 0.0, 100.0)))
        && match c.scheme {
            GDSMC_SCHEME_EULER | GDSMC_SCHEME_STRANG => within(c.dt, 1e-3, 1e300),
            // Found by a 10-minute run: a step factor of 1e-300 with a valid dt passed an
            // earlier version of this guard and never returned (before the C ABI's work
            // limit; kept: the step shrinks as the gas heats, which the limit cannot see).
            GDSMC_SCHEME_TIME_STEPPED => within(c.step_factor, 0.1, 1e300),
            // Buffers of at most 8 n particles, windows that split at most 64-fold at once.
            GDSMC_SCHEME_WEIGHTED => within(c.scheme_params[GDSMC_WEIGHTED_CAPACITY], 2.0, 8.0),
            _ => true,
        }
}

/// The particles in use of a live handle.
fn count(sim: *mut gdsmc_sim) -> usize {
    let mut k = 0u64;
    // SAFETY: `sim` is a live handle from gdsmc; `k` a valid out-pointer.
    let s = unsafe { gdsmc_sim_particle_count(sim, &mut k) };
    assert_eq!(s, gdsmc_status::GDSMC_OK);
    k as usize
}

/// Arbitrary calls on a live handle; ends with destroy and checks the handle is then refused.
fn exercise(u: &mut Unstructured<'_>, mut sim: *mut gdsmc_sim, c: &gdsmc_config, in_place: bool) {
    let n = c.n as usize;
    let mut o = gdsmc_observables::default();
    let mut buf = vec![0.0f64; 3 * n + 3];
    // `set_velocities` takes any finite velocities, and one of 4.7e18 among 28 hard spheres
    // made a run to t = 0.01 about 1e17 events (found with -seed=1, regressions/c_abi): the
    // handle's work limit refuses such an advance (GDSMC_TOO_MUCH_WORK).
    // SAFETY: `sim` is a live handle from gdsmc.
    let s = unsafe { gdsmc_sim_set_work_limit(sim, 1e6) };
    assert_eq!(s, gdsmc_status::GDSMC_OK, "set_work_limit {s:?}");
    for _ in 0..u.int_in_range(0u8..=8).unwrap_or(0) {
        // SAFETY: `sim` is a live handle from gdsmc; buffers are valid for the lengths passed.
        unsafe {
            match u.int_in_range(0u8..=6).unwrap_or(0) {
                0 => {
                    let t = wild(u);
                    let t = if bounded_work(c) && t.is_finite() && t > 0.0 {
                        t.min(0.01)
                    } else {
                        -t.abs() - 1.0
                    };
                    let _ = gdsmc_sim_advance(
                        sim,
                        t,
                        if u.arbitrary().unwrap_or(true) {
                            &mut o
                        } else {
                            null_mut()
                        },
                    );
                }
                1 => {
                    let _ = gdsmc_sim_observables(sim, &mut o);
                }
                2 => {
                    // The weighted scheme's number changes as it runs; the others' is n.
                    let k = count(sim);
                    assert!(
                        k == n || (c.scheme == GDSMC_SCHEME_WEIGHTED && k >= 2),
                        "{k}"
                    );
                }
                3 => {
                    let k = count(sim);
                    buf.resize(buf.len().max(3 * k + 3), 0.0);
                    let len = u.int_in_range(0..=buf.len()).unwrap_or(0);
                    let s = gdsmc_sim_get_velocities(sim, buf.as_mut_ptr(), len);
                    assert_eq!(
                        s == gdsmc_status::GDSMC_OK,
                        len >= 3 * k,
                        "get_velocities {s:?}"
                    );
                    let len = u.int_in_range(0..=buf.len()).unwrap_or(0);
                    let s = gdsmc_sim_get_weights(sim, buf.as_mut_ptr(), len);
                    assert_eq!(s == gdsmc_status::GDSMC_OK, len >= k, "get_weights {s:?}");
                    if s == gdsmc_status::GDSMC_OK {
                        assert!(buf[..k].iter().all(|&g| g.is_finite() && g > 0.0));
                    }
                }
                4 => {
                    for x in buf.iter_mut() {
                        if u.ratio(1u8, 16u8).unwrap_or(false) {
                            *x = wild(u);
                        }
                    }
                    let len = u.int_in_range(0..=buf.len()).unwrap_or(0);
                    let _ = gdsmc_sim_set_velocities(sim, buf.as_ptr(), len);
                }
                5 => {
                    let _ = gdsmc_sim_reseed(sim, u.arbitrary().unwrap_or(0));
                }
                6 if u.ratio(1u8, 3u8).unwrap_or(false) => {
                    // A rough gas's rotation, or a refusal for smooth particles and for a
                    // rough mixture (its rotation is per species; found by this target with
                    // -seed=1 when C took rough mixtures).
                    let mut r = gdsmc_rotation_observables::default();
                    let s = gdsmc_sim_rotation(sim, &mut r);
                    assert_eq!(
                        s == gdsmc_status::GDSMC_OK,
                        c.rough != 0 && c.species == 0,
                        "rotation {s:?}"
                    );
                    let len = u.int_in_range(0..=buf.len()).unwrap_or(0);
                    let s = gdsmc_sim_get_rim_velocities(sim, buf.as_mut_ptr(), len);
                    assert_eq!(
                        s == gdsmc_status::GDSMC_OK,
                        c.rough != 0 && len >= 3 * n,
                        "get_rim_velocities {s:?}"
                    );
                }
                6 if u.ratio(1u8, 2u8).unwrap_or(false) => {
                    // A species of a mixture, or a refusal naming why not.
                    let mut so = gdsmc_species_observables::default();
                    let k = u.int_in_range(0u32..=5).unwrap_or(0);
                    let s = gdsmc_sim_species(sim, k, &mut so);
                    assert_eq!(s == gdsmc_status::GDSMC_OK, k < c.species, "species {s:?}");
                    // A rough mixture's species rotate; a smooth one's report 0.
                    if s == gdsmc_status::GDSMC_OK && c.rough == 0 {
                        assert_eq!((so.rotational_temperature, so.theta), (0.0, 0.0));
                    }
                    let _ = gdsmc_sim_species(sim, k, null_mut());
                }
                _ => {
                    let _ = gdsmc_sim_get_velocities(sim, null_mut(), 3 * n);
                    let _ = gdsmc_sim_set_velocities(sim, null(), 3 * n);
                }
            }
        }
    }
    let stale = sim;
    // SAFETY: `sim` is live; destroy nulls it.
    unsafe {
        assert_eq!(gdsmc_sim_destroy(&mut sim), gdsmc_status::GDSMC_OK);
        assert!(sim.is_null());
        if in_place {
            // The caller's memory is still there: the stale handle must be recognized.
            assert_eq!(
                gdsmc_sim_observables(stale, &mut o),
                gdsmc_status::GDSMC_INVALID_HANDLE
            );
        }
    }
}

/// The C ABI with arbitrary arguments.
pub fn c_abi(data: &[u8]) {
    let mut u = Unstructured::new(data);
    let c = config(&mut u);
    if std::env::var_os("GDSMC_FUZZ_DEBUG").is_some() {
        eprintln!("{c:?}"); // what a crash or timeout input configures (fuzz/README.md)
    }
    let (mut bytes, mut align) = (0usize, 0usize);
    // SAFETY: valid out-pointers.
    // The configuration's own footprint (room for a rough gas's spins) when it is valid, else
    // the particle count's.
    let s = unsafe {
        match gdsmc_config_footprint(&c, &mut bytes, &mut align) {
            gdsmc_status::GDSMC_OK => gdsmc_status::GDSMC_OK,
            _ => gdsmc_sim_footprint(c.n, &mut bytes, &mut align),
        }
    };
    if s == gdsmc_status::GDSMC_OK && bytes <= 1 << 20 {
        assert!(align <= 32 && bytes >= 32 * c.n as usize);
        let mut memory = vec![Block([0; 32]); bytes / 32 + 2];
        let size = if u.ratio(1u8, 8u8).unwrap_or(false) {
            u.int_in_range(0..=bytes).unwrap_or(0)
        } else {
            bytes
        };
        let offset = if u.ratio(1u8, 16u8).unwrap_or(false) {
            8
        } else {
            0
        };
        let mut sim = null_mut();
        // SAFETY: `memory` holds `bytes + 64` bytes; offset + size stays inside it.
        let s = unsafe {
            let p = memory.as_mut_ptr().cast::<u8>().add(offset).cast();
            gdsmc_sim_init_in(p, size, &c, &mut sim)
        };
        if s == gdsmc_status::GDSMC_OK {
            assert!(
                size >= bytes && offset == 0,
                "init_in accepted {size} < {bytes} bytes or a misaligned buffer"
            );
            exercise(&mut u, sim, &c, true);
        } else {
            assert!(sim.is_null());
        }
    }
    if c.n <= 256 {
        let mut sim = null_mut();
        // SAFETY: valid pointers.
        if unsafe { gdsmc_sim_create(&c, &mut sim) } == gdsmc_status::GDSMC_OK {
            exercise(&mut u, sim, &c, false);
        } else {
            assert!(sim.is_null());
        }
    }
    // The message is always retrievable and NUL-terminated.
    let mut msg = [1u8; 64];
    // SAFETY: a 64-byte buffer.
    let len = unsafe { gdsmc_last_error(msg.as_mut_ptr().cast(), msg.len()) };
    assert!(msg[len.min(63)] == 0);
}
