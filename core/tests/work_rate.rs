//! `EventLoop::work_rate` against the work a run does: where the majorant's rate does not
//! depend on the state (the Maxwell kernel, GRW Section 3 / RW (20); a Maxwell background,
//! BRS (26) with `B_1 = C_1`), the candidates and background events of an advance by `dt` are
//! Poisson with mean `work_rate(n) dt`, so the count must lie within 3.29 standard deviations
//! of it (99.9%, normal approximation at means of 1e5 and more; two checks, each at 99.95%
//! for a Bonferroni total of 99.9%: z = 3.48). Fixed seeds.

use gdsmc_core::drive::{HostMedium, HostMediumParams, MaxwellBackground, NoDrive};
use gdsmc_core::engine::{NoSplitting, SumNoSplitting, work_to};
use gdsmc_core::kernel::{HardSpheres, Maxwell};
use gdsmc_core::particles::{Particle, Particles};
use gdsmc_core::restitution::Constant;
use gdsmc_core::rng::seeded;
use gdsmc_core::sample::Maxwellian;
use gdsmc_core::vec3::Vec3;

const Z: f64 = 3.48;

fn gas(n: usize, seed: u64) -> Vec<Particle> {
    let (mut rng, f0) = (seeded(seed), Maxwellian::standard());
    (0..n)
        .map(|_| Particle::new(f0.sample(&mut rng), 0.0))
        .collect()
}

/// Counts within `Z` Poisson standard deviations of `mean`.
fn poisson_agrees(count: u64, mean: f64) -> bool {
    (count as f64 - mean).abs() <= Z * mean.sqrt()
}

#[test]
fn maxwell_candidates_and_background_events_match_the_rate() {
    let n = 1000;
    let mut buf = gas(n, 1);
    let mut p = Particles::new(&mut buf).unwrap();
    let bg = Maxwellian::new(4.0, 0.5, Vec3::new(0.1, 0.0, 0.0)).unwrap();
    let drive = HostMedium::new(
        HostMediumParams::new(bg, 2.0, 0.25).unwrap(),
        MaxwellBackground,
    );
    let kernel = Maxwell::new(1.0, 1.0 / (4.0 * std::f64::consts::PI)).unwrap();
    let law = Constant::new(0.8).unwrap();
    let (mut e, _) = NoSplitting::start(kernel, drive, law, &mut p, 0.0).unwrap();
    let dt = 250.0;
    let rate = e.work_rate(n);
    // Grain-grain: (n - 1)/2 pairs' worth of 4 pi gamma C; background: 4 pi C_1 rho^B a grain.
    let grains = 0.5 * (n - 1) as f64;
    let background = n as f64 * 4.0 * std::f64::consts::PI * 0.25 * 2.0;
    assert!(
        (rate - (grains + background)).abs() <= 1e-12 * rate,
        "rate {rate}"
    );
    assert_eq!(work_to(&e, n, dt), rate * dt);
    let mut rng = seeded(7);
    e.advance_to(&mut p, dt, &mut rng).unwrap();
    let c = e.counts();
    assert!(
        poisson_agrees(c.candidates, grains * dt),
        "{} candidates against a mean of {}",
        c.candidates,
        grains * dt
    );
    assert!(
        poisson_agrees(c.background, background * dt),
        "{} background events against a mean of {}",
        c.background,
        background * dt
    );
}

#[test]
fn work_to_is_zero_backwards_and_infinite_for_nan() {
    let n = 64;
    let mut buf = gas(n, 2);
    let mut p = Particles::new(&mut buf).unwrap();
    let kernel = HardSpheres::new(1.0, 1.0 / (4.0 * std::f64::consts::PI)).unwrap();
    let (e, _) = SumNoSplitting::start(kernel, Constant::new(1.0).unwrap(), &mut p, 1.0).unwrap();
    assert_eq!(work_to(&e, n, 0.5), 0.0);
    assert_eq!(work_to(&e, n, 1.0), 0.0);
    assert_eq!(work_to(&e, n, f64::NAN), f64::INFINITY);
    assert_eq!(work_to(&e, n, f64::INFINITY), f64::INFINITY);
    // Hard spheres: the rate follows the speeds (sum form: 4 pi gamma C (n - 1)/n sum |c|).
    let w = work_to(&e, n, 2.0);
    assert!(w > 0.0 && w.is_finite());
    let mut fast = buf.clone();
    fast[3].vx = 1e30;
    let mut p = Particles::new(&mut fast).unwrap();
    let (e, _) = SumNoSplitting::start(kernel, Constant::new(1.0).unwrap(), &mut p, 1.0).unwrap();
    assert!(work_to(&e, n, 1.01) > 1e27, "{}", work_to(&e, n, 1.01));
    let _ = NoDrive;
}
