//! The hard-sphere background kernel's thinning gives the exact collision rate of BRS (26):
//! a grain at velocity `v` meets the background at the rate
//! `E_1(v) = 4 pi C_1 rho^B b [(x + 1/(2x)) erf(x) + exp(-x^2)/sqrt(pi)]`, `x = |v - u^B| / b`,
//! `b = (2 T^B / m^B)^{1/2}` (the mean of `4 pi C_1 |v - w|` over `M^B`), so its first real
//! collision within `dt` comes with probability `1 - exp(-E_1(v) dt)`, whatever majorant and
//! partner mixture draw the candidates. Checked at three speeds (slow, thermal, fast) by the
//! binomial count of first collisions, each within 3.59 standard deviations (99.9% over the
//! three, Bonferroni). Fixed seed.
//!
//! Disks (the plane's kernels, `drive::host_medium`): the rate is `4 pi C_1 E|v - w|` over the
//! planar `M^B`, the mean of a Rice law, `sigma sqrt(pi/2) e^{-y} [(1 + 2y) I_0(y) + 2y
//! I_1(y)]`, `y = |v - u^B|^2 / (4 sigma^2)`, `sigma^2 = T^B/m^B`; checked the same way.

use gdsmc_core::drive::HostMediumParams;
use gdsmc_core::drive::host_medium::{BackgroundKernel, HardSphereBackground};
use gdsmc_core::geometry::{Disks, Spheres};
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
            .filter(|_| {
                HardSphereBackground
                    .next::<Spheres, _>(&m, v, dt, &mut rng)
                    .is_some()
            })
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
                HardSphereBackground
                    .next::<Spheres, _>(&m, v, dt, &mut rng)
                    .is_none(),
                "dt = {dt}, v = {v:?}"
            );
        }
    }
}

/// The modified Bessel function `I_n(y)` (n = 0, 1) by its power series (all terms positive;
/// 80 terms reach f64 for `y` up to 40).
fn bessel_i(n: i32, y: f64) -> f64 {
    let mut term = (y / 2.0).powi(n);
    let mut sum = term;
    for k in 1..80 {
        term *= (y / 2.0).powi(2) / (k as f64 * (k + n) as f64);
        sum += term;
    }
    sum
}

/// The planar hard-disk background rate `4 pi C_1 E|v - w|` (module docs).
fn exact_rate_2d(m: &HostMediumParams, v: Vec3) -> f64 {
    let bg = m.background;
    let sigma2 = bg.temperature() / bg.mass();
    let y = (v - bg.drift()).norm2() / (4.0 * sigma2);
    let mean_speed = (sigma2 * PI / 2.0).sqrt()
        * (-y).exp()
        * ((1.0 + 2.0 * y) * bessel_i(0, y) + 2.0 * y * bessel_i(1, y));
    4.0 * PI * m.c1 * m.density * mean_speed
}

#[test]
fn first_collision_comes_at_the_exact_rate_on_disks() {
    // The Rice mean at zero offset is sigma sqrt(pi/2), the planar Maxwellian's mean speed.
    let unit =
        HostMediumParams::new(Maxwellian::new(1.0, 1.0, Vec3::ZERO).unwrap(), 1.0, 1.0).unwrap();
    let at_rest = exact_rate_2d(&unit, Vec3::ZERO) / (4.0 * PI);
    assert!((at_rest - (PI / 2.0).sqrt()).abs() < 1e-15);
    let bg = Maxwellian::new(2.0, 1.5, Vec3::new(0.3, 1.0, 0.0)).unwrap();
    let m = HostMediumParams::new(bg, 0.7, 1.3).unwrap();
    let mut rng = seeded(2027);
    let trials = 200_000;
    for v in [
        Vec3::new(0.4, 1.1, 0.0),
        Vec3::new(-1.0, 0.2, 0.0),
        Vec3::new(4.0, -3.0, 0.0),
    ] {
        let rate = exact_rate_2d(&m, v);
        let dt = core::f64::consts::LN_2 / rate;
        let p = 1.0 - (-rate * dt).exp();
        let mut planar = true;
        let hits = (0..trials)
            .filter(
                |_| match HardSphereBackground.next::<Disks, _>(&m, v, dt, &mut rng) {
                    Some((w, _)) => {
                        planar &= w.z == 0.0;
                        true
                    }
                    None => false,
                },
            )
            .count();
        assert!(planar, "v = {v:?}: a collision left the plane");
        let n = trials as f64;
        let z = (hits as f64 - n * p) / (n * p * (1.0 - p)).sqrt();
        assert!(
            z.abs() < 3.59,
            "disks, v = {v:?}: {hits} of {trials} collided within dt, expected {:.0} (z = {z:.2})",
            n * p
        );
    }
}
