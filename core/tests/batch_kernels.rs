//! Every SIMD batch kernel against its plain scalar twin with a fixed seed (RustFFT style).

mod common;
use common::*;
use gdsmc_core::batch::kick::*;
use gdsmc_core::batch::sums::*;
use gdsmc_core::particles::Particles;
use gdsmc_core::rng::{seeded, uniform_open01, uniform01};
use gdsmc_core::sample::{Maxwellian, standard_normal};
use gdsmc_core::vec3::Vec3;

fn rel(a: f64, b: f64) -> f64 {
    (a - b).abs() / a.abs().max(b.abs()).max(1e-300)
}

#[test]
fn simd_sums_equal_scalar_sums() {
    let mut rng = seeded(31);
    let mx = Maxwellian::new(1.0, 2.0, Vec3::new(0.3, -0.2, 1.0)).unwrap();
    for n in [1usize, 2, 3, 4, 5, 7, 8, 9, 63, 64, 65, 1001] {
        let vs: Vec<Vec3> = (0..n).map(|_| mx.sample(&mut rng)).collect();
        let vx: Vec<f64> = vs.iter().map(|v| v.x).collect();
        let vy: Vec<f64> = vs.iter().map(|v| v.y).collect();
        let vz: Vec<f64> = vs.iter().map(|v| v.z).collect();
        let a = accumulate_simd(&vx, &vy, &vz);
        let b = accumulate_scalar(&vx, &vy, &vz);
        assert_eq!(a.n, b.n);
        let pairs =
            a.s1.iter()
                .zip(&b.s1)
                .chain(a.s2.iter().zip(&b.s2))
                .chain(a.s3.iter().zip(&b.s3));
        for (x, y) in pairs {
            // Different summation order: relative to the sum of magnitudes, a few ulps per term.
            assert!(
                (x - y).abs() <= 1e-13 * (n as f64) * (1.0 + y.abs()),
                "n = {n}: {x} vs {y}"
            );
        }
        for (x, y) in [(a.s4, b.s4), (a.s6, b.s6), (a.c4, b.c4), (a.c6, b.c6)] {
            assert!(rel(x, y) < 1e-13, "n = {n}: {x} vs {y}");
        }
        assert!(rel(a.max_c2, b.max_c2) < 1e-13, "n = {n}");
    }
}

#[test]
fn box_muller_simd_equals_scalar_box_muller_on_the_same_draws() {
    let mut a = seeded(32);
    let mut b = seeded(32);
    for _ in 0..1000 {
        let (c, s) = box_muller4(&mut a);
        let u1: [f64; 4] = std::array::from_fn(|_| uniform_open01(&mut b));
        let u2: [f64; 4] = std::array::from_fn(|_| uniform01(&mut b));
        for k in 0..4 {
            let r = (-2.0 * u1[k].ln()).sqrt();
            let th = std::f64::consts::TAU * u2[k];
            assert!(
                (c.to_array()[k] - r * th.cos()).abs() < 1e-13 * (1.0 + r),
                "cos lane {k}"
            );
            assert!(
                (s.to_array()[k] - r * th.sin()).abs() < 1e-13 * (1.0 + r),
                "sin lane {k}"
            );
        }
    }
}

#[test]
fn simd_normals_are_normal() {
    let mut rng = seeded(33);
    let mut xs = Vec::with_capacity(200_000);
    while xs.len() < 200_000 {
        let (c, s) = box_muller4(&mut rng);
        xs.extend_from_slice(&c.to_array());
        xs.extend_from_slice(&s.to_array());
    }
    let d = ks_statistic(&mut xs, normal_cdf);
    assert!(d < ks_critical_999(xs.len()), "KS D = {d}");
}

/// Runs a kick kernel on a system with staggered last-kick times; returns the increments
/// divided by their standard deviation sqrt(2 beta dt), which must be standard normal.
fn kicked(
    kernel: fn(f64, &mut Particles<'_>, f64, &mut gdsmc_core::rng::Xoshiro256PlusPlus),
    n: usize,
) -> (Vec<f64>, Vec<f64>) {
    let mut rng = seeded(34);
    let mut buf = vec![0.0; 4 * n];
    let mut p = Particles::from_buffer(&mut buf, n).unwrap();
    for i in 0..n {
        p.set_velocity(i, Vec3::new(standard_normal(&mut rng), 1.0, -2.0));
        p.set_kick_time(i, (i % 7) as f64 * 0.1);
    }
    let before: Vec<Vec3> = (0..n).map(|i| p.velocity(i)).collect();
    let t0: Vec<f64> = (0..n).map(|i| p.kick_time(i)).collect();
    let (beta, t) = (0.8, 1.0);
    kernel(2.0 * beta, &mut p, t, &mut rng);
    let mut z = Vec::new();
    for i in 0..n {
        assert_eq!(p.kick_time(i), t);
        let s = (2.0 * beta * (t - t0[i])).sqrt();
        let d = p.velocity(i) - before[i];
        z.extend_from_slice(&[d.x / s, d.y / s, d.z / s]);
    }
    (z, t0)
}

#[test]
fn simd_kick_and_scalar_kick_give_the_same_law() {
    // Both kernels must turn each velocity into v + sqrt(2 beta dt) xi with xi standard normal:
    // KS at 99.9% for each, and the scalar and SIMD samples against each other (two-sample KS,
    // critical value 1.9495 sqrt(2/N)).
    let n = 30_003; // not a multiple of 8: the remainder path runs too
    let (mut a, _) = kicked(white_noise_kick_all_simd, n);
    let (mut b, _) = kicked(white_noise_kick_all_scalar, n);
    let m = a.len();
    let da = ks_statistic(&mut a, normal_cdf);
    let db = ks_statistic(&mut b, normal_cdf);
    assert!(da < ks_critical_999(m), "SIMD KS D = {da}");
    assert!(db < ks_critical_999(m), "scalar KS D = {db}");
    let (mut i, mut j, mut d) = (0usize, 0usize, 0.0f64);
    while i < m && j < m {
        if a[i] <= b[j] {
            i += 1
        } else {
            j += 1
        }
        d = d.max((i as f64 / m as f64 - j as f64 / m as f64).abs());
    }
    assert!(
        d < 1.9495 * (2.0 / m as f64).sqrt(),
        "two-sample KS D = {d}"
    );
}
