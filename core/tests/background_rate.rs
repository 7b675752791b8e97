//! The hard-sphere background kernel's thinning gives the exact collision rate of BRS (26):
//! a grain at velocity `v` meets the background at the rate
//! `E_1(v) = 4 pi C_1 rho^B b [(x + 1/(2x)) erf(x) + exp(-x^2)/sqrt(pi)]`, `x = |v - u^B| / b`,
//! `b = (2 T^B / m^B)^{1/2}` (the mean of `4 pi C_1 |v - w|` over `M^B`), so its first real
//! collision within `dt` comes with probability `1 - exp(-E_1(v) dt)`, whatever majorant and
//! partner mixture draw the candidates. Checked at three speeds (slow, thermal, fast) by the
//! binomial count of first collisions, each within 3.59 standard deviations (99.9% over the
//! three, Bonferroni). Fixed seed.

use gdsmc_core::drive::HostMediumParams;
use gdsmc_core::drive::host_medium::{BackgroundKernel, HardSphereBackground};
use gdsmc_core::math::PI;
use gdsmc_core::rng::seeded;
use gdsmc_core::sample::Maxwellian;
use gdsmc_core::vec3::Vec3;

/// BRS (26) for the hard-sphere kernel `B_1 = C_1 |g|`.
fn exact_rate(m: &HostMediumParams, v: Vec3) -> f64 {
    let bg = m.background;
    let b = (2.0 * bg.temperature() / bg.mass()).sqrt();
    let x = (v - bg.drift()).norm() / b;
    let mean_speed = b * ((x + 0.5 / x) * libm::erf(x) + (-x * x).exp() / PI.sqrt());
    4.0 * PI * m.c1 * m.density * mean_speed
}

#[test]
fn first_collision_comes_at_the_exact_rate() {
    let bg = Maxwellian::new(2.0, 1.5, Vec3::new(0.3, 1.0, -0.5)).unwrap();
    let m = HostMediumParams::new(bg, 0.7, 1.3).unwrap();
    let mut rng = seeded(2026);
    let trials = 200_000;
    for v in [
        Vec3::new(0.4, 1.1, -0.5),
        Vec3::new(-1.0, 0.2, 0.6),
        Vec3::new(4.0, -3.0, 2.0),
    ] {
        let rate = exact_rate(&m, v);
        // About half of the grains collide within dt.
        let dt = core::f64::consts::LN_2 / rate;
        let p = 1.0 - (-rate * dt).exp();
        let hits = (0..trials)
            .filter(|_| HardSphereBackground.next(&m, v, dt, &mut rng).is_some())
            .count();
        let n = trials as f64;
        let z = (hits as f64 - n * p) / (n * p * (1.0 - p)).sqrt();
        assert!(
            z.abs() < 3.59,
            "v = {v:?}: {hits} of {trials} collided within dt, expected {:.0} (z = {z:.2})",
            n * p
        );
    }
}

/// No time, a time a rounding left below zero, or no number at all: no candidate, no draw of
/// a collision.
#[test]
fn no_time_no_collision() {
    let bg = Maxwellian::new(1.0, 1.0, Vec3::new(0.0, 1.0, 0.0)).unwrap();
    let m = HostMediumParams::new(bg, 1.0, 1.0).unwrap();
    let mut rng = seeded(7);
    for dt in [0.0, -1e-300, -1.0, f64::NAN] {
        for v in [Vec3::ZERO, Vec3::new(1e3, 0.0, 0.0)] {
            assert!(
                HardSphereBackground.next(&m, v, dt, &mut rng).is_none(),
                "dt = {dt}, v = {v:?}"
            );
        }
    }
}
