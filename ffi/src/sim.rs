//! The simulation handle: create (on the heap, or in caller memory), advance, read, write,
//! reseed, destroy.

use crate::config::gdsmc_config;
use crate::guard::{check_ptr, guard};
use crate::status::{Failure, engine_error, fail, gdsmc_status, msg};
use core::ffi::c_void;
use core::mem::{align_of, size_of};
use gdsmc_core::moments::Observables;
use gdsmc_core::particles::{Particle, Particles, ParticlesError, Spin};
use gdsmc_core::physics::{Engine, Model, Physics};
use gdsmc_core::rng::{Xoshiro256PlusPlus, stream};

/// The largest stream a configuration may name (`config.stream`).
pub const GDSMC_MAX_STREAM: u64 = 1 << 20;
const MAX_STREAM: u64 = GDSMC_MAX_STREAM;
const ALIVE: u64 = 0x6764_736d_635f_6f6b; // "gdsmc_ok"
const DEAD: u64 = 0x6764_736d_635f_7878; // "gdsmc_xx"

/// A simulation: `n` particles, its engine, generator and current time. Opaque to C.
pub struct gdsmc_sim {
    magic: u64,
    /// Made by gdsmc_sim_create (freed by destroy); never true in the no_std build.
    #[cfg_attr(not(feature = "std"), allow(dead_code))]
    pub(crate) owned: bool,
    /// The particles in use (the weighted scheme's number changes as it runs).
    pub(crate) n: usize,
    /// The 32-byte records the handle owns or was given ([`slots`]).
    #[cfg_attr(not(feature = "std"), allow(dead_code))]
    pub(crate) records: usize,
    pub(crate) particles: *mut Particle,
    /// The weighted scheme's room: its particle records and weights (NULL: equal weights).
    pub(crate) cap: usize,
    pub(crate) weights: *mut f64,
    /// A rough gas's spins, the `n` records after the particles (NULL: smooth particles).
    pub(crate) spins: *mut Spin,
    pub(crate) engine: Engine,
    pub(crate) rng: Xoshiro256PlusPlus,
    pub(crate) last: Observables,
    /// The most work units one gdsmc_sim_advance may ask for (gdsmc_sim_set_work_limit).
    pub(crate) work_limit: f64,
}

// A rough gas's spins live in the records after its particles: the same size and alignment.
const _: () = assert!(
    size_of::<Spin>() == size_of::<Particle>() && align_of::<Spin>() == align_of::<Particle>()
);

// The weighted scheme's weights live in the records after its particles, four to a record.
const WEIGHTS_PER_RECORD: usize = size_of::<Particle>() / size_of::<f64>();
const _: () = assert!(
    WEIGHTS_PER_RECORD * size_of::<f64>() == size_of::<Particle>()
        && align_of::<Particle>() >= align_of::<f64>()
);

/// The 32-byte records a simulation of `model` needs: `n` particles, and for a rough gas `n`
/// spins after them; for the weighted scheme its `capacity` particles
/// ([`Model::capacity`]) and their weights after them.
pub(crate) fn slots(model: &Model) -> usize {
    if model.rotates() {
        2 * model.n()
    } else if model.weighted() {
        let cap = model.capacity();
        cap + cap.div_ceil(WEIGHTS_PER_RECORD)
    } else {
        model.n()
    }
}

/// The particles of a handle's memory: `n` in use at `particles`, a rough gas's spins at
/// `spins` (else NULL), the weighted scheme's `cap` records and their weights at `weights`
/// (else NULL).
///
/// # Safety
/// `particles` must point to `cap` (weighted) or `n` initialized records, `spins` (non-null)
/// to `n` initialized spins, `weights` (non-null) to `cap` initialized weights, none of them
/// overlapping, and nothing else may touch them while the view lives.
unsafe fn view<'a>(
    particles: *mut Particle,
    (n, cap): (usize, usize),
    spins: *mut Spin,
    weights: *mut f64,
) -> Result<Particles<'a>, ParticlesError> {
    // SAFETY: the caller's promise above, for each branch's slices.
    unsafe {
        if !weights.is_null() {
            Particles::weighted(
                core::slice::from_raw_parts_mut(particles, cap),
                core::slice::from_raw_parts_mut(weights, cap),
                n,
            )
        } else if spins.is_null() {
            Particles::new(core::slice::from_raw_parts_mut(particles, n))
        } else {
            Particles::with_spins(
                core::slice::from_raw_parts_mut(particles, n),
                core::slice::from_raw_parts_mut(spins, n),
            )
        }
    }
}

/// The particles (and spins, or weights) of a live handle. The returned view must not outlive
/// the handle's borrow by its caller (each exported function makes one view and drops it
/// before returning).
pub(crate) fn particles_of<'a>(s: &gdsmc_sim) -> Particles<'a> {
    // SAFETY: a live handle's pointers are its own memory as `view` asks (a boxed slice, or
    // the caller's memory behind the header), written at creation and kept by the engine
    // (every weight in use > 0); only this view touches them.
    unsafe { view(s.particles, (s.n, s.cap), s.spins, s.weights) }
        .expect("n >= 2, the spins and weights checked at creation")
}

/// Fills the particles from the initial distribution and starts the engine (the core's one
/// dispatch, [`Model::launch`]); builds the handle's contents (not yet placed).
pub(crate) fn build(
    c: &gdsmc_config,
    model: &Model,
    particles: *mut Particle,
    n: usize,
    owned: bool,
) -> Result<gdsmc_sim, Failure> {
    let mut rng = stream(c.seed, c.stream);
    let records = slots(model);
    for i in 0..records {
        // SAFETY: `particles` points to room for `slots(model)` records (see callers); every
        // one is written here before any is read.
        unsafe { particles.add(i).write(Particle::default()) };
    }
    let (cap, weights) = if model.weighted() {
        let cap = model.capacity();
        // SAFETY: the records after the `cap` particles, written above, hold `cap` weights
        // (aligned: a record's alignment is a double's); each starts at 1.
        let weights = unsafe { particles.add(cap).cast::<f64>() };
        for i in 0..cap {
            // SAFETY: as above.
            unsafe { weights.add(i).write(1.0) };
        }
        (cap, weights)
    } else {
        (n, core::ptr::null_mut())
    };
    let spins = if model.rotates() {
        // SAFETY: the n records after the particles, written above as default particles,
        // which are default spins (the same four zero doubles).
        unsafe { particles.add(n).cast::<Spin>() }
    } else {
        core::ptr::null_mut()
    };
    // SAFETY: the records, spins and weights written above, apart, used by this view alone.
    let mut p = unsafe { view(particles, (n, cap), spins, weights) }
        .map_err(|e| Failure(gdsmc_status::GDSMC_INVALID_ARGUMENT, msg!("{e}")))?;
    #[cfg(feature = "fault-injection")]
    crate::guard::fault::check();
    let (engine, last) = model.launch(&mut p, 0.0, &mut rng).map_err(engine_error)?;
    Ok(gdsmc_sim {
        magic: ALIVE,
        owned,
        n: p.len(),
        records,
        particles,
        cap,
        weights,
        spins,
        engine,
        rng,
        last,
        work_limit: gdsmc_core::engine::WORK_LIMIT,
    })
}

/// A buffer of `len` doubles must hold `3 n` velocity components.
pub(crate) fn check_len(len: usize, n: usize) -> Result<(), Failure> {
    if len / 3 < n {
        return fail(
            gdsmc_status::GDSMC_BUFFER_TOO_SMALL,
            msg!("`len` = {len} < 3 n = {}", 3 * n),
        );
    }
    Ok(())
}

/// The caller's configuration and its validated model.
pub(crate) fn read_config(cfg: *const gdsmc_config) -> Result<(gdsmc_config, Model), Failure> {
    check_ptr(cfg, "config")?;
    // SAFETY: checked non-null and aligned; the caller provides a readable gdsmc_config.
    let c = unsafe { cfg.read() };
    // Stream k costs k jumps of the generator (2^20 take about 0.3 s); 2^24, once allowed,
    // took seconds and showed as a hang to the C ABI fuzz target.
    if c.stream > MAX_STREAM {
        return fail(
            gdsmc_status::GDSMC_INVALID_ARGUMENT,
            msg!(
                "config.stream = {} is above 2^20 (stream k costs k jumps of the generator)",
                c.stream
            ),
        );
    }
    let model = c.model()?;
    Ok((c, model))
}

/// A live handle from a caller pointer, or the status saying why not.
pub(crate) fn live<'a>(sim: *mut gdsmc_sim) -> Result<&'a mut gdsmc_sim, Failure> {
    check_ptr(sim, "sim")?;
    // SAFETY: non-null and aligned; the caller passes a handle from gdsmc. The magic word tells
    // a live handle from a destroyed one made with gdsmc_sim_init_in (whose memory stays valid).
    let s = unsafe { &mut *sim };
    if s.magic != ALIVE {
        return fail(
            gdsmc_status::GDSMC_INVALID_HANDLE,
            "`sim` is not a live simulation (destroyed?)",
        );
    }
    Ok(s)
}

fn header_bytes() -> usize {
    size_of::<gdsmc_sim>().next_multiple_of(align_of::<Particle>())
}

/// For the allocation-free variant: the number of bytes and the alignment a caller buffer must
/// have to hold a simulation of `n` particles (the handle's header followed by the particles).
///
/// # Safety
/// `bytes` and `align` must be NULL or writable for one size_t each.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn gdsmc_sim_footprint(
    n: u64,
    bytes: *mut usize,
    align: *mut usize,
) -> gdsmc_status {
    guard(|| {
        check_ptr(bytes, "bytes")?;
        check_ptr(align, "align")?;
        // The particle-count rule of the core (n >= 2, addressable).
        let n = usize::try_from(n).unwrap_or(usize::MAX);
        if let Err(e) = Physics::check_n(n) {
            return fail(
                gdsmc_status::GDSMC_INVALID_ARGUMENT,
                msg!("n {}", e.problem),
            );
        }
        let Some(total) = n
            .checked_mul(size_of::<Particle>())
            .and_then(|b| b.checked_add(header_bytes()))
            .filter(|&b| b <= isize::MAX as usize)
        else {
            return fail(
                gdsmc_status::GDSMC_INVALID_ARGUMENT,
                msg!("n = {n} is too large"),
            );
        };
        // SAFETY: both checked non-null and aligned.
        unsafe {
            bytes.write(total);
            align.write(align_of::<gdsmc_sim>().max(align_of::<Particle>()));
        }
        Ok(())
    })
}

/// For the allocation-free variant: the bytes and alignment a caller buffer must have for the
/// simulation `*config` describes. The same as gdsmc_sim_footprint for smooth particles; a rough
/// gas (`config.rough`) needs room for its spins too. Refuses an invalid configuration with the
/// message gdsmc_sim_init_in would give.
///
/// # Safety
/// `config` must be NULL or point to a gdsmc_config; `bytes` and `align` NULL or writable for
/// one size_t each.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn gdsmc_config_footprint(
    config: *const gdsmc_config,
    bytes: *mut usize,
    align: *mut usize,
) -> gdsmc_status {
    guard(|| {
        check_ptr(bytes, "bytes")?;
        check_ptr(align, "align")?;
        let (_, model) = read_config(config)?;
        let total = need(&model)?;
        // SAFETY: both checked non-null and aligned.
        unsafe {
            bytes.write(total);
            align.write(align_of::<gdsmc_sim>().max(align_of::<Particle>()));
        }
        Ok(())
    })
}

/// The bytes of a caller buffer for a simulation of `model`: the header and its records.
fn need(model: &Model) -> Result<usize, Failure> {
    slots(model)
        .checked_mul(size_of::<Particle>())
        .and_then(|b| b.checked_add(header_bytes()))
        .filter(|&b| b <= isize::MAX as usize)
        .ok_or_else(|| {
            Failure(
                gdsmc_status::GDSMC_INVALID_ARGUMENT,
                msg!("n = {} is too large", model.n()),
            )
        })
}

/// The allocation-free variant of gdsmc_sim_create: builds the simulation inside `memory`
/// (`size` bytes, aligned as gdsmc_sim_footprint says; gdsmc allocates nothing). `*out`
/// becomes a handle pointing into `memory`. The caller keeps owning the memory; call
/// gdsmc_sim_destroy before reusing or freeing it. After destroy, calls with the old handle
/// return GDSMC_INVALID_HANDLE as long as the memory is untouched.
///
/// # Safety
/// `memory` must be NULL or point to `size` writable bytes that outlive the handle and are not
/// otherwise accessed while it lives; `config` as in gdsmc_sim_create; `out` NULL or writable.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn gdsmc_sim_init_in(
    memory: *mut c_void,
    size: usize,
    config: *const gdsmc_config,
    out: *mut *mut gdsmc_sim,
) -> gdsmc_status {
    guard(|| {
        check_ptr(out, "out")?;
        // SAFETY: checked non-null and aligned.
        unsafe { out.write(core::ptr::null_mut()) };
        let (c, model) = read_config(config)?;
        if memory.is_null() {
            return fail(gdsmc_status::GDSMC_NULL_POINTER, "`memory` is NULL");
        }
        let align = align_of::<gdsmc_sim>().max(align_of::<Particle>());
        if !(memory as usize).is_multiple_of(align) {
            return fail(
                gdsmc_status::GDSMC_MISALIGNED,
                msg!("`memory` is not aligned to {align} bytes"),
            );
        }
        let n = model.n();
        let need = need(&model)?;
        if size < need {
            return fail(
                gdsmc_status::GDSMC_BUFFER_TOO_SMALL,
                msg!(
                    "`memory` holds {size} bytes; n = {n} needs {need} (gdsmc_sim_footprint, or gdsmc_config_footprint for rough or weighted particles)"
                ),
            );
        }
        let head = memory.cast::<gdsmc_sim>();
        // SAFETY: `memory` has `need` bytes aligned to `align`; the particles start at an offset
        // that is a multiple of their alignment, after the header.
        let particles = unsafe { memory.cast::<u8>().add(header_bytes()).cast::<Particle>() };
        let s = build(&c, &model, particles, n, false)?;
        // SAFETY: the header fits before the particles and `head` is aligned.
        unsafe {
            head.write(s);
            out.write(head);
        }
        Ok(())
    })
}

/// Destroys the simulation `*sim` and sets `*sim` to NULL. Heap handles are freed; for a handle
/// made by gdsmc_sim_init_in the caller's memory is left to the caller (marked dead, so later
/// calls with a copy of the old handle report GDSMC_INVALID_HANDLE). A NULL `*sim` is a no-op.
///
/// # Safety
/// `sim` must be NULL or point to NULL or to a handle from gdsmc not destroyed before.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn gdsmc_sim_destroy(sim: *mut *mut gdsmc_sim) -> gdsmc_status {
    guard(|| {
        check_ptr(sim, "sim")?;
        // SAFETY: checked non-null and aligned.
        let h = unsafe { sim.read() };
        if h.is_null() {
            return Ok(());
        }
        let s = live(h)?;
        s.magic = DEAD;
        #[cfg(feature = "std")]
        if s.owned {
            free(h);
        }
        // SAFETY: checked non-null and aligned.
        unsafe { sim.write(core::ptr::null_mut()) };
        Ok(())
    })
}

/// Frees a heap handle made by `gdsmc_sim_create` (`heap.rs`).
#[cfg(feature = "std")]
fn free(h: *mut gdsmc_sim) {
    // SAFETY: an owned handle was made by gdsmc_sim_create: the header by Box::new and the
    // particles (and a rough gas's spins or the weighted scheme's weights after them) by a
    // boxed slice of `records` records; the caller marked it dead and uses neither again.
    unsafe {
        let (ptr, records) = ((*h).particles, (*h).records);
        drop(Box::from_raw(h));
        drop(Box::from_raw(std::ptr::slice_from_raw_parts_mut(
            ptr, records,
        )));
    }
}
