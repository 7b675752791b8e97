//! Simulations on the heap (`gdsmc_sim_create`, and their release in `gdsmc_sim_destroy`).
//! Needs the standard library; the no_std build has the caller-memory variant only.

use crate::config::gdsmc_config;
use crate::guard::{check_ptr, guard};
use crate::sim::{build, gdsmc_sim, read_config, slots};
use crate::status::{fail, gdsmc_status, msg};
use gdsmc_core::particles::Particle;
use std::mem::size_of;

/// Creates a simulation on the heap from `*config`: `n` particles drawn from the initial
/// Maxwellian with the configured seed, time 0. On success `*out` holds the new handle, which
/// the caller owns and must pass to gdsmc_sim_destroy. On failure `*out` is set to NULL (when
/// `out` is valid) and the last-error message names the bad field. Not in the no_std build
/// (use gdsmc_sim_init_in there).
///
/// # Safety
/// `config` must be NULL or point to a gdsmc_config; `out` NULL or writable for one pointer.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn gdsmc_sim_create(
    config: *const gdsmc_config,
    out: *mut *mut gdsmc_sim,
) -> gdsmc_status {
    guard(|| {
        check_ptr(out, "out")?;
        // SAFETY: checked non-null and aligned.
        unsafe { out.write(std::ptr::null_mut()) };
        let (c, model) = read_config(config)?;
        let n = model.n();
        // n particles, and for a rough gas n spins after them.
        let records = slots(&model);
        let mut buf: Vec<Particle> = Vec::new();
        if buf.try_reserve_exact(records).is_err() {
            return fail(
                gdsmc_status::GDSMC_OUT_OF_MEMORY,
                msg!(
                    "n = {n} particles ({} bytes) cannot be allocated",
                    records.saturating_mul(size_of::<Particle>())
                ),
            );
        }
        buf.resize(records, Particle::default());
        // The box owns the particles until the handle does: an error or a panic in `build`
        // drops it (no leak on any path).
        let mut particles = buf.into_boxed_slice();
        let s = build(&c, &model, particles.as_mut_ptr(), n, true)?;
        let ptr = Box::into_raw(particles).cast::<Particle>();
        debug_assert_eq!(ptr, s.particles);
        // SAFETY: checked non-null and aligned.
        unsafe { out.write(Box::into_raw(Box::new(s))) };
        Ok(())
    })
}
