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

/// Runs the event loop in [`ROUNDS`] timed rounds of `budget / ROUNDS`, each after a timing
/// of the pair reference ([`timed`]).
pub(super) fn event_loop<K: Kernel, D: Drive>(
    kernel: K,
    drive: D,
    alpha: f64,
    n: usize,
    (budget, reference): (Duration, &mut PairReference),
) -> Rounds {
    let mut buf = system(n, 1);
    let mut p = Particles::new(&mut buf).expect("n >= 2");
    let law = Constant::new(alpha).expect("alpha in (0, 1]");
    let (mut e, _) = NoSplitting::start(kernel, drive, law, &mut p, 0.0).expect("finite start");
    timed(&mut e, &mut p, budget, reference)
}

/// The loop runs use for hard spheres with no drive: the sum-form majorant
/// ([`SumNoSplitting`]); returns its rounds and the weighted choice's particle reads per
/// candidate.
pub(super) fn sum_form_loop(
    kernel: HardSpheres,
    alpha: f64,
    n: usize,
    (budget, reference): (Duration, &mut PairReference),
) -> (Rounds, f64) {
    let mut buf = system(n, 1);
    let mut p = Particles::new(&mut buf).expect("n >= 2");
    let law = Constant::new(alpha).expect("alpha in (0, 1]");
    let (mut e, _) = SumNoSplitting::start(kernel, law, &mut p, 0.0).expect("finite start");
    let (draws, candidates) = (e.choice_draws(), e.counts().candidates);
    let rounds = timed(&mut e, &mut p, budget, reference);
    let reads = (e.choice_draws() - draws) as f64 / (e.counts().candidates - candidates) as f64;
    (rounds, reads)
}

/// The rough gas's loop (hard spheres, the rough map with `alpha`, `beta`, uniform spheres,
/// spins at the translational temperature), timed as [`event_loop`].
pub(super) fn rough_loop<D: Drive>(
    drive: D,
    (alpha, beta): (f64, f64),
    n: usize,
    (budget, reference): (Duration, &mut PairReference),
) -> Rounds {
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
    timed(&mut e, &mut p, budget, reference)
}

/// Timed rounds of each loop and rate: the figure is their median, the spread their range
/// over it, so that a machine busy in one round moves neither.
pub const ROUNDS: usize = 5;

/// A loop's figures per round (per CPU second of the measuring thread): collisions,
/// candidates, background events (a host medium's, BRS (26); 0 for other drives), and the
/// pair reference's pairs timed just before the round.
#[derive(Clone, Debug, Default, PartialEq)]
pub(super) struct Rounds {
    pub collisions: Vec<f64>,
    pub attempts: Vec<f64>,
    pub background: Vec<f64>,
    pub pairs: Vec<f64>,
}

impl Rounds {
    /// Candidates per second over the pair reference's pairs, round by round.
    pub fn of_pairs(&self) -> Vec<f64> {
        self.attempts
            .iter()
            .zip(&self.pairs)
            .map(|(a, p)| a / p)
            .collect()
    }
}

/// The median of `xs` (the mean of the middle two for an even count); NaN for none.
pub(super) fn median(xs: &[f64]) -> f64 {
    let mut v = xs.to_vec();
    v.sort_by(f64::total_cmp);
    match v.len() {
        0 => f64::NAN,
        k if k % 2 == 1 => v[k / 2],
        k => 0.5 * (v[k / 2 - 1] + v[k / 2]),
    }
}

/// The range of `xs` over their median: how far the rounds of one figure lie apart.
pub(super) fn spread(xs: &[f64]) -> f64 {
    let (lo, hi) = xs
        .iter()
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), &x| {
            (a.min(x), b.max(x))
        });
    (hi - lo) / median(xs)
}

/// Advances `e` in growing time steps until each step has at least `4 n` attempts (an
/// observation's O(n) cost then stays small), then in [`ROUNDS`] rounds of `budget / ROUNDS`
/// each after a timing of the pair reference (`budget / (2 ROUNDS)`: interleaved, so a loop
/// and the reference it is set against see the same machine).
pub(super) fn timed<E: EventLoop>(
    e: &mut E,
    p: &mut Particles<'_>,
    budget: Duration,
    reference: &mut PairReference,
) -> Rounds {
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
    let mut r = Rounds::default();
    let each = budget / ROUNDS as u32;
    for _ in 0..ROUNDS {
        r.pairs.push(reference.measure(each / 2));
        let c0 = e.counts();
        let start = ThreadTime::now();
        while start.elapsed() < each {
            let t = e.time() + dt;
            black_box(e.advance_to(p, t, &mut rng).expect("finite"));
        }
        let s = start.elapsed().as_secs_f64();
        let c = e.counts();
        r.collisions.push((c.collisions - c0.collisions) as f64 / s);
        r.attempts.push((c.candidates - c0.candidates) as f64 / s);
        r.background.push((c.background - c0.background) as f64 / s);
    }
    r
}

/// The lookaheads the pair-update limit tries.
pub const LOOKAHEADS: [usize; 5] = [1, 8, 16, 32, 64];

/// A reference rate for the event loop's memory traffic at size `n` (not a bound: short
/// timings of one loop, which another loop can exceed): random pairs `(i, j)` drawn as the
/// loop draws them, each particle of the pair read and written back, with the pairs drawn
/// `L` ahead and prefetched, in the run's buffer (huge pages). [`PairReference::new`] finds
/// the best `L` of [`LOOKAHEADS`]; [`PairReference::measure`] times it again, between a
/// loop's rounds.
pub(super) struct PairReference {
    buf: Vec<Particle>,
    lookahead: usize,
    rng: gdsmc_core::rng::Xoshiro256PlusPlus,
}

impl PairReference {
    /// The reference at `n`, its lookahead the best of [`LOOKAHEADS`] (each timed for
    /// `budget / LOOKAHEADS.len()`), and its rate there in [`ROUNDS`] rounds.
    pub fn new(n: usize, budget: Duration) -> (Self, Vec<f64>) {
        let mut r = PairReference {
            buf: system(n, 8),
            lookahead: 1,
            rng: seeded(9),
        };
        let mut best = (0.0, 1);
        for l in LOOKAHEADS {
            r.lookahead = l;
            let x = r.measure(budget / LOOKAHEADS.len() as u32);
            if x > best.0 {
                best = (x, l);
            }
        }
        r.lookahead = best.1;
        let rounds = (0..ROUNDS)
            .map(|_| r.measure(budget / ROUNDS as u32))
            .collect();
        (r, rounds)
    }

    /// The lookahead it runs at.
    pub fn lookahead(&self) -> usize {
        self.lookahead
    }

    /// Pairs per CPU second over `budget`.
    pub fn measure(&mut self, budget: Duration) -> f64 {
        let n = self.buf.len();
        let l = self.lookahead;
        let rng = &mut self.rng;
        let mut p = Particles::new(&mut self.buf).expect("n >= 2");
        let mut ring: Vec<(usize, usize)> = (0..l).map(|_| uniform_pair(rng, n)).collect();
        let per = 1 << 16;
        rate(budget, per, || {
            for k in 0..per {
                let next = uniform_pair(rng, n);
                p.prefetch(next.0);
                p.prefetch(next.1);
                let (i, j) = std::mem::replace(&mut ring[k % l], next);
                let (a, b) = (p.velocity(i), p.velocity(j));
                p.set_velocity(i, b);
                p.set_velocity(j, a);
            }
        })
    }
}

/// A batch kernel's or a limit's rate in [`ROUNDS`] rounds of `budget / ROUNDS` ([`rate`]).
pub(super) fn rates(budget: Duration, per: usize, mut f: impl FnMut()) -> Vec<f64> {
    (0..ROUNDS)
        .map(|_| rate(budget / ROUNDS as u32, per, &mut f))
        .collect()
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

/// Raw xoshiro256++ numbers per second, one core, per round.
pub(super) fn rng_limit(budget: Duration) -> Vec<f64> {
    let mut rng = seeded(6);
    rates(budget, 1 << 16, || {
        let mut x = 0u64;
        for _ in 0..1 << 16 {
            x ^= rng.next_u64();
        }
        black_box(x);
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The median and the spread the lines print: a round far off moves the spread, not the
    /// median.
    #[test]
    fn median_and_spread() {
        assert_eq!(median(&[3.0, 1.0, 2.0]), 2.0);
        assert_eq!(median(&[4.0, 1.0, 3.0, 2.0]), 2.5);
        assert!(median(&[]).is_nan());
        let calm = [10.0, 10.2, 9.9, 10.1, 10.0];
        let busy = [10.0, 10.2, 9.9, 10.1, 2.0];
        assert!((median(&calm) - median(&busy)).abs() < 0.11);
        assert!((spread(&calm) - 0.03).abs() < 1e-12);
        assert!(spread(&busy) > 0.8);
    }
}
