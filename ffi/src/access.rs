//! Running a simulation and reading or writing its state: advance, observables, particle
//! count, velocities, reseed.

use crate::guard::{check_ptr, guard};
use crate::observables::{
    gdsmc_observables, gdsmc_rotation_observables, gdsmc_species_observables,
};
use crate::sim::{check_len, gdsmc_sim, live, particles_of};
use crate::status::{engine_error, fail, gdsmc_status, msg};
use gdsmc_core::engine::{EventLoop, work_to};
use gdsmc_core::rng::seeded;
use gdsmc_core::vec3::Vec3;

/// Runs the simulation to time `t` (>= its current time), kicks every particle there and, if
/// `out` is not NULL, writes the observables at `t` to `*out`. GDSMC_TIME_BACKWARDS for an
/// earlier (or non-finite) `t`, GDSMC_NON_FINITE if the state overflowed, GDSMC_TOO_MUCH_WORK
/// (nothing run, the state unchanged) when the work the current state asks for up to `t` (its
/// event rate times `t` minus the current time; see gdsmc_sim_set_work_limit) is above the
/// simulation's limit: a time or velocities far beyond what the call was meant for. The rate
/// is today's: a heated gas's grows during the call.
///
/// # Safety
/// `sim` must be NULL or a handle from gdsmc; `out` NULL or writable for one gdsmc_observables.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn gdsmc_sim_advance(
    sim: *mut gdsmc_sim,
    t: f64,
    out: *mut gdsmc_observables,
) -> gdsmc_status {
    guard(|| {
        let s = live(sim)?;
        if !out.is_null() {
            check_ptr(out, "out")?;
        }
        if t.is_finite() && t > s.engine.time() {
            let work = work_to(&s.engine, s.n, t);
            if work > s.work_limit {
                return fail(
                    gdsmc_status::GDSMC_TOO_MUCH_WORK,
                    msg!(
                        "advancing from t = {} to t = {t} asks for about {work:.1e} events and particle updates ({:.1e} per unit time now), above the limit {:.1e}; advance to an earlier time, check the velocities, or raise the limit with gdsmc_sim_set_work_limit",
                        s.engine.time(),
                        s.engine.work_rate(s.n),
                        s.work_limit
                    ),
                );
            }
        }
        let mut rng = s.rng.clone();
        let mut p = particles_of(s);
        let o = s.engine.advance_to(&mut p, t, &mut rng);
        // The weighted scheme's particles in use, as the engine left them (even on an error).
        s.n = p.len();
        let o = o.map_err(engine_error)?;
        s.rng = rng;
        s.last = o;
        if !out.is_null() {
            // SAFETY: checked non-null and aligned.
            unsafe {
                out.write(gdsmc_observables::new(
                    s.engine.time(),
                    &o,
                    &s.engine.counts(),
                ))
            };
        }
        Ok(())
    })
}

/// Writes the observables at the simulation's current time to `*out`.
///
/// # Safety
/// `sim` must be NULL or a handle from gdsmc; `out` NULL or writable for one gdsmc_observables.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn gdsmc_sim_observables(
    sim: *mut gdsmc_sim,
    out: *mut gdsmc_observables,
) -> gdsmc_status {
    guard(|| {
        let s = live(sim)?;
        check_ptr(out, "out")?;
        // SAFETY: checked non-null and aligned.
        unsafe {
            out.write(gdsmc_observables::new(
                s.engine.time(),
                &s.last,
                &s.engine.counts(),
            ))
        };
        Ok(())
    })
}

/// Writes the observables of species `k` of a mixture at the current time to `*out`.
/// GDSMC_INVALID_ARGUMENT when the simulation is not a mixture or `k` is not one of its
/// species.
///
/// # Safety
/// `sim` must be NULL or a handle from gdsmc; `out` NULL or writable for one
/// gdsmc_species_observables.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn gdsmc_sim_species(
    sim: *mut gdsmc_sim,
    k: u32,
    out: *mut gdsmc_species_observables,
) -> gdsmc_status {
    guard(|| {
        let s = live(sim)?;
        check_ptr(out, "out")?;
        let p = particles_of(s);
        let Some(m) = s.engine.species(&p) else {
            return fail(
                gdsmc_status::GDSMC_INVALID_ARGUMENT,
                msg!("the simulation is not a mixture (config.species = 0)"),
            );
        };
        if k as usize >= m.len {
            return fail(
                gdsmc_status::GDSMC_INVALID_ARGUMENT,
                msg!("k = {k} is not a species: the mixture has {}", m.len),
            );
        }
        // SAFETY: checked non-null and aligned.
        unsafe { out.write(gdsmc_species_observables::new(&m, k as usize)) };
        Ok(())
    })
}

/// Writes a rough gas's rotational observables at the current time to `*out`.
/// GDSMC_INVALID_ARGUMENT when the particles are smooth (`config.rough = 0`) or a rough
/// mixture (its rotation is per species: gdsmc_sim_species).
///
/// # Safety
/// `sim` must be NULL or a handle from gdsmc; `out` NULL or writable for one
/// gdsmc_rotation_observables.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn gdsmc_sim_rotation(
    sim: *mut gdsmc_sim,
    out: *mut gdsmc_rotation_observables,
) -> gdsmc_status {
    guard(|| {
        let s = live(sim)?;
        check_ptr(out, "out")?;
        let p = particles_of(s);
        let Some(r) = s.engine.rough(&p) else {
            return fail(
                gdsmc_status::GDSMC_INVALID_ARGUMENT,
                if p.has_spins() {
                    msg!("a rough mixture's rotation is per species: gdsmc_sim_species")
                } else {
                    msg!("the particles are smooth (config.rough = 0)")
                },
            );
        };
        // SAFETY: checked non-null and aligned.
        unsafe { out.write(gdsmc_rotation_observables::new(&r)) };
        Ok(())
    })
}

/// The number of particles in `*n`: the particles in use, which under GDSMC_SCHEME_WEIGHTED
/// change as it runs (collisions make particles, reductions merge them; at most
/// `scheme_params[GDSMC_WEIGHTED_CAPACITY]` times `config.n`): size the buffers of the
/// velocity and weight copies from it after each advance.
///
/// # Safety
/// `sim` must be NULL or a handle from gdsmc; `n` NULL or writable for one uint64_t.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn gdsmc_sim_particle_count(
    sim: *mut gdsmc_sim,
    n: *mut u64,
) -> gdsmc_status {
    guard(|| {
        let s = live(sim)?;
        check_ptr(n, "n")?;
        // SAFETY: checked non-null and aligned.
        unsafe { n.write(s.n as u64) };
        Ok(())
    })
}

/// Copies the velocities out: `out[3i], out[3i+1], out[3i+2]` = particle i's x, y, z, for
/// `len >= 3 n` doubles (GDSMC_BUFFER_TOO_SMALL otherwise). All particles are at the current
/// time after create, advance and set_velocities.
///
/// # Safety
/// `sim` must be NULL or a handle from gdsmc; `out` NULL or writable for `len` doubles.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn gdsmc_sim_get_velocities(
    sim: *mut gdsmc_sim,
    out: *mut f64,
    len: usize,
) -> gdsmc_status {
    guard(|| {
        let s = live(sim)?;
        check_ptr(out, "out")?;
        check_len(len, s.n)?;
        // SAFETY: `out` is non-null, aligned and has `len >= 3 n` doubles.
        let dst = unsafe { core::slice::from_raw_parts_mut(out, 3 * s.n) };
        let p = particles_of(s);
        let frame = s.engine.velocity_map();
        for (d, q) in dst.chunks_exact_mut(3).zip(p.as_slice()) {
            let v = frame.physical(q.velocity());
            d.copy_from_slice(&[v.x, v.y, v.z]);
        }
        Ok(())
    })
}

/// Copies the particles' weights out, `out[i]` = particle i's, for `len >=` the particle count
/// (gdsmc_sim_particle_count; GDSMC_BUFFER_TOO_SMALL otherwise): under GDSMC_SCHEME_WEIGHTED
/// the weights of Rjasanow and Wagner's SWPM, which sum to `config.n`; 1 each otherwise.
/// Every moment gdsmc reports is the weighted mean `sum g_i phi(v_i) / sum g_i`.
///
/// # Safety
/// `sim` must be NULL or a handle from gdsmc; `out` NULL or writable for `len` doubles.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn gdsmc_sim_get_weights(
    sim: *mut gdsmc_sim,
    out: *mut f64,
    len: usize,
) -> gdsmc_status {
    guard(|| {
        let s = live(sim)?;
        check_ptr(out, "out")?;
        if len < s.n {
            return fail(
                gdsmc_status::GDSMC_BUFFER_TOO_SMALL,
                msg!("`len` = {len} < the {} particles in use", s.n),
            );
        }
        // SAFETY: `out` is non-null, aligned and has `len >= n` doubles.
        let dst = unsafe { core::slice::from_raw_parts_mut(out, s.n) };
        let p = particles_of(s);
        for (i, d) in dst.iter_mut().enumerate() {
            *d = p.weight(i);
        }
        Ok(())
    })
}

/// Copies a rough gas's rim velocities `w = (sigma/2) omega` out, in the layout of
/// gdsmc_sim_get_velocities (`len >= 3 n`); GDSMC_INVALID_ARGUMENT for smooth particles.
///
/// # Safety
/// `sim` must be NULL or a handle from gdsmc; `out` NULL or writable for `len` doubles.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn gdsmc_sim_get_rim_velocities(
    sim: *mut gdsmc_sim,
    out: *mut f64,
    len: usize,
) -> gdsmc_status {
    guard(|| {
        let s = live(sim)?;
        check_ptr(out, "out")?;
        if s.spins.is_null() {
            return fail(
                gdsmc_status::GDSMC_INVALID_ARGUMENT,
                msg!("the particles are smooth (config.rough = 0)"),
            );
        }
        check_len(len, s.n)?;
        // SAFETY: `out` is non-null, aligned and has `len >= 3 n` doubles.
        let dst = unsafe { core::slice::from_raw_parts_mut(out, 3 * s.n) };
        let p = particles_of(s);
        let scale = s.engine.velocity_map().scale;
        for (d, q) in dst.chunks_exact_mut(3).zip(p.spins()) {
            let w = scale * q.rim_velocity();
            d.copy_from_slice(&[w.x, w.y, w.z]);
        }
        Ok(())
    })
}

/// Copies velocities in (same layout as gdsmc_sim_get_velocities, `len >= 3 n`), at the
/// current time; the majorant and observables are recomputed. Non-finite values, and values so
/// large that the observables' sixth moments would overflow (|v| above about 1e50), are
/// refused with GDSMC_INVALID_ARGUMENT and leave the simulation unchanged. A rough gas keeps
/// its rim velocities.
///
/// # Safety
/// `sim` must be NULL or a handle from gdsmc; `velocities` NULL or readable for `len` doubles.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn gdsmc_sim_set_velocities(
    sim: *mut gdsmc_sim,
    velocities: *const f64,
    len: usize,
) -> gdsmc_status {
    guard(|| {
        let s = live(sim)?;
        check_ptr(velocities, "velocities")?;
        check_len(len, s.n)?;
        // SAFETY: non-null, aligned, `len >= 3 n` readable doubles.
        let src = unsafe { core::slice::from_raw_parts(velocities, 3 * s.n) };
        if let Some(k) = src.iter().position(|x| !x.is_finite()) {
            return fail(
                gdsmc_status::GDSMC_INVALID_ARGUMENT,
                msg!("velocities[{k}] is not finite"),
            );
        }
        // Refused before anything is stored: velocities whose sixth moments (the largest the
        // observables sum, about the bulk velocity: |v - V| <= 2 max |v|) would overflow.
        let max2 = src
            .chunks_exact(3)
            .map(|v| v[0] * v[0] + v[1] * v[1] + v[2] * v[2])
            .fold(0.0, f64::max);
        if !(64.0 * s.n as f64 * max2 * max2 * max2).is_finite() {
            return fail(
                gdsmc_status::GDSMC_INVALID_ARGUMENT,
                msg!(
                    "velocities too large: |v| = {:e} makes the sixth moments of {} particles overflow",
                    gdsmc_core::math::sqrt(max2),
                    s.n
                ),
            );
        }
        let mut p = particles_of(s);
        for (i, v) in src.chunks_exact(3).enumerate() {
            p.set_velocity(i, Vec3::new(v[0], v[1], v[2]));
        }
        let o = s.engine.resync(&mut p).map_err(engine_error)?;
        s.last = o;
        Ok(())
    })
}

/// Restarts the random numbers from `seed`, stream 0 (the particles' state is kept).
///
/// # Safety
/// `sim` must be NULL or a handle from gdsmc.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn gdsmc_sim_reseed(sim: *mut gdsmc_sim, seed: u64) -> gdsmc_status {
    guard(|| {
        let s = live(sim)?;
        s.rng = seeded(seed);
        Ok(())
    })
}

/// Sets the most work one gdsmc_sim_advance may ask for: events of the collision majorant,
/// background events of a host medium and particle updates of stepped schemes, estimated from
/// the current state before the call runs (default 1e12, about a day of one core on a desktop;
/// a microcontroller may want far less). `limit` must be positive (INFINITY: no limit);
/// GDSMC_INVALID_ARGUMENT otherwise.
///
/// # Safety
/// `sim` must be NULL or a handle from gdsmc.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn gdsmc_sim_set_work_limit(sim: *mut gdsmc_sim, limit: f64) -> gdsmc_status {
    guard(|| {
        let s = live(sim)?;
        if limit.is_nan() || limit <= 0.0 {
            return fail(
                gdsmc_status::GDSMC_INVALID_ARGUMENT,
                msg!("work limit {limit}: must be positive (INFINITY for none)"),
            );
        }
        s.work_limit = limit;
        Ok(())
    })
}
