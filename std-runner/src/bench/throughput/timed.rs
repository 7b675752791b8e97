//! What the bench times: the event loops on the run's own buffer, each until its budget of
//! this thread's CPU time has passed, and the machine's limits it compares them with (the pair
//! reference, the generator's raw rate).

use cpu_time::ThreadTime;
use gdsmc_core::drive::Drive;
use gdsmc_core::engine::{EventLoop, NoSplitting, SumNoSplitting};
use gdsmc_core::kernel::{HardSpheres, Kernel};
use gdsmc_core::particles::{Particle, Particles, Spin};
use gdsmc_core::restitution::Constant;
use gdsmc_core::rng::{Rng, seeded, uniform_pair};
use gdsmc_core::rough::RoughMap;
use gdsmc_core::sample::Maxwellian;
use gdsmc_core::vec3::Vec3;
use std::f64::consts::PI;
use std::hint::black_box;
use std::time::Duration;

pub(super) fn system(n: usize, seed: u64) -> Vec<Particle> {
    // The run's own buffer (huge pages at large n), so the bench measures what a run does.
    let mut buf = crate::run::particle_buffer(n).expect("the bench's sizes fit in memory");
    let mut p = Particles::new(&mut buf).expect("n >= 2");
    let mut rng = seeded(seed);
    let f0 = Maxwellian::standard();
    p.fill_with(0.0, || f0.sample(&mut rng));
    buf
}

/// Runs the event loop in growing time steps until `budget` has passed; returns
/// (collisions per second, attempts per second).
pub(super) fn event_loop<K: Kernel, D: Drive>(
    kernel: K,
    drive: D,
    alpha: f64,
    n: usize,
    budget: Duration,
) -> (f64, f64) {
    let mut buf = system(n, 1);
    let mut p = Particles::new(&mut buf).expect("n >= 2");
    let law = Constant::new(alpha).expect("alpha in (0, 1]");
    let (mut e, _) = NoSplitting::start(kernel, drive, law, &mut p, 0.0).expect("finite start");
    timed(&mut e, &mut p, budget)
}

/// The loop runs use for hard spheres with no drive: the sum-form majorant
/// ([`SumNoSplitting`]); returns (collisions per second, attempts per second, the weighted
/// choice's particle reads per candidate).
pub(super) fn sum_form_loop(
    kernel: HardSpheres,
    alpha: f64,
    n: usize,
    budget: Duration,
) -> (f64, f64, f64) {
    let mut buf = system(n, 1);
    let mut p = Particles::new(&mut buf).expect("n >= 2");
    let law = Constant::new(alpha).expect("alpha in (0, 1]");
    let (mut e, _) = SumNoSplitting::start(kernel, law, &mut p, 0.0).expect("finite start");
    let (draws, candidates) = (e.choice_draws(), e.counts().candidates);
    let (coll, att) = timed(&mut e, &mut p, budget);
    let reads = (e.choice_draws() - draws) as f64 / (e.counts().candidates - candidates) as f64;
    (coll, att, reads)
}

/// The rough gas's loop (hard spheres, the rough map with `alpha`, `beta`, uniform spheres,
/// spins at the translational temperature) in growing time steps until `budget` has passed;
/// returns (collisions per second, attempts per second).
pub(super) fn rough_loop<D: Drive>(
    drive: D,
    alpha: f64,
    beta: f64,
    n: usize,
    budget: Duration,
) -> (f64, f64) {
    let mut buf = system(n, 1);
    let mut spins: Vec<Spin> = {
        let mut rng = seeded(5);
        let f0 = Maxwellian::new(1.0, 1.0 / 0.4, Vec3::ZERO).expect("valid");
        (0..n).map(|_| Spin::new(f0.sample(&mut rng))).collect()
    };
    let mut p = Particles::with_spins(&mut buf, &mut spins).expect("n >= 2");
    let map = RoughMap::new(alpha, beta, 0.4).expect("valid");
    let k = HardSpheres::new(4.0, 1.0 / (4.0 * PI)).expect("valid");
    let (mut e, _) = NoSplitting::start(k, drive, map, &mut p, 0.0).expect("finite start");
    timed(&mut e, &mut p, budget)
}

/// Advances `e` in growing time steps until each step has at least `4 n` attempts (an
/// observation's O(n) cost then stays small), then for `budget`; (collisions per second,
/// attempts per second) over the timed part.
pub(super) fn timed<E: EventLoop>(
    e: &mut E,
    p: &mut Particles<'_>,
    budget: Duration,
) -> (f64, f64) {
    let (coll, att, _) = timed_with_background(e, p, budget);
    (coll, att)
}

/// As [`timed`], with the drive's background events per second third (a host medium's
/// grain-background collisions, BRS (26); 0 for other drives).
pub(super) fn timed_with_background<E: EventLoop>(
    e: &mut E,
    p: &mut Particles<'_>,
    budget: Duration,
) -> (f64, f64, f64) {
    let n = p.len();
    let mut rng = seeded(2);
    let mut dt = 1e-3;
    loop {
        let c0 = e.counts();
        let t = e.time() + dt;
        e.advance_to(p, t, &mut rng).expect("finite");
        if e.counts().candidates - c0.candidates >= 4 * n as u64 {
            break;
        }
        dt *= 2.0;
    }
    let c0 = e.counts();
    let start = ThreadTime::now();
    while start.elapsed() < budget {
        let t = e.time() + dt;
        black_box(e.advance_to(p, t, &mut rng).expect("finite"));
    }
    let s = start.elapsed().as_secs_f64();
    let c = e.counts();
    (
        (c.collisions - c0.collisions) as f64 / s,
        (c.candidates - c0.candidates) as f64 / s,
        (c.background - c0.background) as f64 / s,
    )
}

/// The lookaheads the pair-update limit tries.
pub const LOOKAHEADS: [usize; 5] = [1, 8, 16, 32, 64];

/// A reference rate for the event loop's memory traffic at size `n` (not a bound: the best of
/// short timings of one loop, which another loop can exceed): random pairs `(i, j)` drawn as
/// the loop draws them, each particle of the pair read and written back, with the pairs drawn
/// `L` ahead and prefetched, in the run's buffer (huge pages). Returns the best pairs per CPU
/// second over [`LOOKAHEADS`] and the lookahead that gave it.
pub(super) fn pair_reference(n: usize, budget: Duration) -> (f64, usize) {
    let mut buf = system(n, 8);
    let mut rng = seeded(9);
    let mut best = (0.0, 0);
    for l in LOOKAHEADS {
        let mut p = Particles::new(&mut buf).expect("n >= 2");
        let mut ring: Vec<(usize, usize)> = (0..l).map(|_| uniform_pair(&mut rng, n)).collect();
        let per = 1 << 16;
        let r = rate(budget / LOOKAHEADS.len() as u32, per, || {
            for k in 0..per {
                let next = uniform_pair(&mut rng, n);
                p.prefetch(next.0);
                p.prefetch(next.1);
                let (i, j) = std::mem::replace(&mut ring[k % l], next);
                let (a, b) = (p.velocity(i), p.velocity(j));
                p.set_velocity(i, b);
                p.set_velocity(j, a);
            }
        });
        if r > best.0 {
            best = (r, l);
        }
    }
    best
}

/// Repeats `f` (which handles `per` items) until `budget` of this thread's CPU time has
/// passed; items per CPU second.
pub(super) fn rate(budget: Duration, per: usize, mut f: impl FnMut()) -> f64 {
    f();
    let start = ThreadTime::now();
    let mut k = 0u64;
    while start.elapsed() < budget {
        f();
        k += 1;
    }
    (k as f64 * per as f64) / start.elapsed().as_secs_f64()
}

/// One event-loop line: its collisions and candidates per second against the limits `lim`
/// Raw xoshiro256++ numbers per second, one core.
pub(super) fn rng_limit(budget: Duration) -> f64 {
    let mut rng = seeded(6);
    rate(budget, 1 << 16, || {
        let mut x = 0u64;
        for _ in 0..1 << 16 {
            x ^= rng.next_u64();
        }
        black_box(x);
    })
}
