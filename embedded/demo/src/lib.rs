//! # gdsmc-demo: what the firmware runs
//!
//! Four runs over caller-owned particle buffers, each reaching the engine through the core's
//! physics description (`Physics::validate`, `Model::launch`): GRW Example 3 (the heated
//! Maxwell gas, GRW (13): `T -> 8/3`), the homogeneous cooling of hard spheres (Haff's law),
//! the cooling of rough hard spheres (Huthmann and Zippelius 1997: theta = T_rot/T_tr
//! settles) with its spins in a second caller buffer, and a binary mixture of rough hard disks
//! heated by white noise (the driven state of Megías and Santos 2019; the shipped scene
//! `scenes/rough-disk-mixture-white-noise.toml` at 256 particles), each species' translational
//! and rotational temperature printed.
//! Each run prints one line per observation time with the observables in round-trip digits and
//! a last line with a checksum of every particle velocity's bits, so that two machines that
//! print the same lines have followed the same trajectory bit for bit.
//!
//! The firmware (Cortex-M, semihosting) and the host runner (`gdsmc-demo-host`) call the same
//! [`run`]; `embedded/run.sh` compares their output.

#![no_std]

use core::fmt::Write;
use gdsmc_core::engine::{Counts, EventLoop};
use gdsmc_core::particles::{Particle, Particles, Spin};
use gdsmc_core::physics::{
    DimensionChoice, DriveChoice, KernelChoice, Physics, RestitutionLaw, RotationChoice,
    SchemeChoice, SpeciesChoice,
};
use gdsmc_core::rng::stream;

/// 1/(4 pi), GRW's C_0 for Maxwell pseudo-molecules and C_1 of the hard spheres here.
const C_QUARTER_PI: f64 = 0.079_577_471_545_947_67;

/// GRW Example 3 with `n` particles: Maxwell kernel, gamma = 4, C_0 = 1/(4 pi), alpha = 1/2,
/// white noise beta = 1, standard Maxwellian start, no splitting.
pub fn grw_example3(n: usize) -> Physics {
    Physics::new(
        n,
        KernelChoice::maxwell(4.0, C_QUARTER_PI),
        RestitutionLaw::Constant(0.5),
        DriveChoice::WhiteNoise(1.0),
        SchemeChoice::NoSplitting,
    )
}

/// The homogeneous cooling state of hard spheres with `n` particles (Haff's law):
/// gamma = 1, C_1 = 1/(4 pi), alpha = 0.9, no drive, no splitting.
pub fn hcs_hard_spheres(n: usize) -> Physics {
    Physics::new(
        n,
        KernelChoice::hard_spheres(1.0, C_QUARTER_PI),
        RestitutionLaw::Constant(0.9),
        DriveChoice::None,
        SchemeChoice::NoSplitting,
    )
}

/// The homogeneous cooling state of rough hard spheres with `n` particles: the hard spheres
/// of [`hcs_hard_spheres`] with tangential restitution beta = 0, uniform spheres (kappa =
/// 2/5), starting at `T_rot = T_tr = 1`.
pub fn rough_hcs(n: usize) -> Physics {
    let mut p = hcs_hard_spheres(n);
    p.rotation = Some(RotationChoice::spheres(0.0));
    p
}

/// A binary mixture of rough hard disks heated by white noise on translation with `n`
/// particles (Megías and Santos 2019's driven state; `scenes/rough-disk-mixture-white-noise.toml`):
/// a heavy species (mass 2, diameter 1, uniform disks kappa = 1/2) and a light one (mass 1,
/// diameter 0.8, rings kappa = 1), `n/2` each; hard-sphere kernel gamma = 4, C_1 = 1/(4 pi),
/// alpha = 0.8 for every pair, tangential restitution 0.5 between like particles and 0 between
/// unlike, white noise beta = 1 on each species, every temperature starting at 1.
pub fn rough_disk_mixture(n: usize) -> Physics {
    let mut p = Physics::new(
        n,
        KernelChoice::hard_spheres(4.0, C_QUARTER_PI),
        RestitutionLaw::Constant(0.8),
        DriveChoice::WhiteNoise(1.0),
        SchemeChoice::NoSplitting,
    );
    let heavy = SpeciesChoice {
        beta: 1.0,
        ..SpeciesChoice::new(n / 2, 2.0, 1.0)
    };
    let light = SpeciesChoice {
        beta: 1.0,
        diameter: 0.8,
        inertia: Some(1.0),
        ..SpeciesChoice::new(n - n / 2, 1.0, 1.0)
    };
    // Two species and three pairs: within the core's MAX_SPECIES and MAX_PAIRS.
    let _ = p.species.push(heavy);
    let _ = p.species.push(light);
    for beta in [0.5, 0.0, 0.5] {
        let _ = p.pair_tangential_restitution.push(beta);
    }
    p.rotation = Some(RotationChoice {
        beta: 0.5,
        kappa: 0.5,
        temperature: 1.0,
        noise: 0.0,
    });
    p.dimension = DimensionChoice::Two;
    p
}

/// The exact temperature of GRW Example 3, GRW (13): `T(t) = 8/3 + (1 - 8/3) exp(-3t/4)`.
pub fn grw_example3_exact(t: f64) -> f64 {
    let t_inf = 8.0 / 3.0;
    t_inf + (1.0 - t_inf) * libm::exp(-0.75 * t)
}

/// Why a run stopped.
#[derive(Debug)]
pub enum DemoError {
    /// The physics was refused (the message names the parameter).
    Physics(gdsmc_core::physics::PhysicsError),
    /// The engine stopped.
    Engine(gdsmc_core::engine::EngineError),
    /// The output sink failed.
    Write,
}

impl From<core::fmt::Error> for DemoError {
    fn from(_: core::fmt::Error) -> Self {
        DemoError::Write
    }
}

/// What a run did: its event counts and the instructions it took (from `clock`).
#[derive(Clone, Copy, Debug, Default)]
pub struct Summary {
    /// Event counts.
    pub counts: Counts,
    /// Instructions (or whatever `clock` counts) between the start and the last observation.
    pub instructions: u64,
}

/// A number printed with the fewest digits that read back to the same bits (Ryu, with its
/// small tables: core's own float formatting, Grisu with the Dragon fallback, takes about 20
/// KiB of flash, a third of the Cortex-M0 build's budget).
pub struct Digits(pub f64);

impl core::fmt::Display for Digits {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        f.write_str(ryu::Buffer::new().format(self.0))
    }
}

/// What stopped a run, in words that print no number (so that the firmware does not link the
/// float formatting for its error path): the parameter a refused physics names, or the engine's
/// error.
impl core::fmt::Display for DemoError {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        match self {
            DemoError::Physics(e) => write!(f, "the physics was refused at `{}`", e.param),
            DemoError::Engine(e) => write!(f, "the engine stopped: {e}"),
            DemoError::Write => f.write_str("the output failed"),
        }
    }
}

/// Validates the physics `make` builds, out of line: the physics and the validation's
/// temporaries take stack only while it runs, not beside the run's engine (a Cortex-M0 has 16
/// KiB of RAM).
#[inline(never)]
fn validated(make: impl FnOnce() -> Physics) -> Result<gdsmc_core::physics::Model, DemoError> {
    make().validate().map_err(DemoError::Physics)
}

/// FNV-1a over the bits of every velocity component (and rim velocity component).
fn checksum(p: &Particles<'_>) -> u64 {
    let mut h: u64 = 0xcbf2_9ce4_8422_2325;
    let spins = p.spins().iter().map(|w| [w.wx, w.wy, w.wz]);
    for x in p.as_slice().iter().map(|q| [q.vx, q.vy, q.vz]).chain(spins) {
        for x in x {
            for b in x.to_bits().to_le_bytes() {
                h ^= b as u64;
                h = h.wrapping_mul(0x0100_0000_01b3);
            }
        }
    }
    h
}

/// Runs `physics` on the buffers `(buf, spins)` (`buf` must hold `physics.n` particles; a
/// rough gas's spins in `spins`, else empty) from stream 0 of `seed`, observing at `times`, and
/// writes to `out`: `NAME t=T T=.. T_bulk=.. log10_T_bulk=.. a2=.. collisions=..` per
/// observation (a rough gas adds `T_rot=.. theta=..`; a mixture each species' `T_S=..`, and if
/// rough `T_rot_S=..`, `S` its index) and `NAME checksum=..` at the end. `clock` is read before the start and after the last
/// observation (the firmware counts instructions; the host may return 0).
pub fn run(
    name: &str,
    physics: impl FnOnce() -> Physics,
    (buf, spins): (&mut [Particle], &mut [Spin]),
    seed: u64,
    times: &[f64],
    out: &mut impl Write,
    mut clock: impl FnMut() -> u64,
) -> Result<Summary, DemoError> {
    let model = validated(physics)?;
    let mut p = if spins.is_empty() {
        Particles::new(buf)
    } else {
        Particles::with_spins(buf, spins)
    }
    .map_err(|_| DemoError::Engine(gdsmc_core::engine::EngineError::ParticleCount))?;
    let mut rng = stream(seed, 0);
    let start = clock();
    let (mut engine, mut obs) = model
        .launch(&mut p, 0.0, &mut rng)
        .map_err(DemoError::Engine)?;
    for &t in times {
        if t > 0.0 {
            obs = engine
                .advance_to(&mut p, t, &mut rng)
                .map_err(DemoError::Engine)?;
        }
        write!(
            out,
            "{name} t={} T={} T_bulk={} log10_T_bulk={} a2={} collisions={}",
            Digits(t),
            Digits(obs.t_raw),
            Digits(obs.t_bulk),
            Digits(obs.log10_t_bulk),
            Digits(obs.a2),
            engine.counts().collisions
        )?;
        if let Some(m) = engine.species(&p) {
            for s in 0..m.len {
                write!(out, " T_{s}={}", Digits(m.temperature(s)))?;
                if let Some(t_rot) = m.rotational_temperature(s) {
                    write!(out, " T_rot_{s}={}", Digits(t_rot))?;
                }
            }
        } else if let Some(r) = engine.rough(&p) {
            write!(
                out,
                " T_rot={} theta={}",
                Digits(r.t_rot),
                Digits(r.theta())
            )?;
        }
        writeln!(out)?;
    }
    let instructions = clock().wrapping_sub(start);
    let gdsmc_core::engine::Frame { scale, offset } = engine.velocity_map();
    writeln!(
        out,
        "{name} checksum={:016x} scale={} offset=[{}, {}, {}]",
        checksum(&p),
        Digits(scale),
        Digits(offset.x),
        Digits(offset.y),
        Digits(offset.z)
    )?;
    Ok(Summary {
        counts: engine.counts(),
        instructions,
    })
}

/// Particles per system in the smooth runs.
pub const N: usize = 512;

/// Particles (and spins) of the rough run.
pub const N_ROUGH: usize = 256;

/// Particles of GRW Example 3 on the Cortex-M0: GRW Table 1's smallest system. The micro:bit's
/// 16 KiB of RAM hold them (2 KiB) beside the stack the validation and the loop take (about 12
/// KiB; `embedded/run.sh` prints the peak).
pub const N_M0: usize = 64;

/// Observation times of GRW Example 3 (GRW Table 1's interval [0, 8]).
pub const GRW3_TIMES: [f64; 9] = [0.0, 1.0, 2.0, 3.0, 4.0, 5.0, 6.0, 7.0, 8.0];

/// Observation times of the heated rough disk mixture (its scene's steady state from t = 5).
pub const MIXTURE_TIMES: [f64; 6] = [0.0, 1.0, 2.0, 5.0, 7.5, 10.0];

/// Observation times of the cooling runs (Haff's law: `T ~ t^-2` for `t >> 1/nu0`).
pub const HCS_TIMES: [f64; 6] = [0.0, 10.0, 20.0, 50.0, 100.0, 200.0];

/// GRW Example 3 with seed `seed` on every particle of `buf`, then the exact temperature GRW
/// (13) at each observation time (the one run of the Cortex-M0 build, which holds only its
/// engine: gdsmc-core's features `maxwell`, `white-noise`).
pub fn grw3(
    buf: &mut [Particle],
    seed: u64,
    out: &mut impl Write,
    clock: impl FnMut() -> u64,
) -> Result<Summary, DemoError> {
    let n = buf.len();
    let s = run(
        "grw3",
        || grw_example3(n),
        (buf, &mut []),
        seed,
        &GRW3_TIMES,
        out,
        clock,
    )?;
    for &t in &GRW3_TIMES[1..] {
        writeln!(
            out,
            "grw3 exact t={} T_GRW13={}",
            Digits(t),
            Digits(grw_example3_exact(t))
        )?;
    }
    Ok(s)
}

/// The four runs with seed `seed` on the caller's buffers: GRW Example 3 ([`grw3`]), the
/// cooling hard spheres, then the cooling rough hard spheres and the heated rough disk mixture
/// on the first [`N_ROUGH`] particles and `spins`; one summary each.
pub fn all(
    buf: &mut [Particle; N],
    spins: &mut [Spin; N_ROUGH],
    seed: u64,
    out: &mut impl Write,
    mut clock: impl FnMut() -> u64,
) -> Result<[Summary; 4], DemoError> {
    let a = grw3(buf, seed, out, &mut clock)?;
    let b = run(
        "hcs",
        || hcs_hard_spheres(N),
        (buf, &mut []),
        seed,
        &HCS_TIMES,
        out,
        &mut clock,
    )?;
    let c = run(
        "rough",
        || rough_hcs(N_ROUGH),
        (&mut buf[..N_ROUGH], spins),
        seed,
        &HCS_TIMES,
        out,
        &mut clock,
    )?;
    let d = run(
        "rough-mix",
        || rough_disk_mixture(N_ROUGH),
        (&mut buf[..N_ROUGH], spins),
        seed,
        &MIXTURE_TIMES,
        out,
        &mut clock,
    )?;
    Ok([a, b, c, d])
}
