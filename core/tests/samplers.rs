//! Every sampler against its distribution: Kolmogorov-Smirnov at level 99.9% (critical value
//! 1.9495/sqrt(N)) where the CDF is known, moments within their 99.9% confidence interval
//! (lambda = 3.2 standard errors) otherwise. Fixed seeds.

use crate::common;
use common::*;
use gdsmc_core::math::PI;
use gdsmc_core::rng::{seeded, uniform_open01, uniform01};
use gdsmc_core::sample::ziggurat_tables as zt;
use gdsmc_core::sample::*;
use gdsmc_core::vec3::Vec3;

const N: usize = 200_000;

#[test]
fn normal_ks() {
    let mut rng = seeded(11);
    let mut xs: Vec<f64> = (0..N).map(|_| standard_normal(&mut rng)).collect();
    let d = ks_statistic(&mut xs, normal_cdf);
    assert!(d < ks_critical_999(N), "KS D = {d}");
}

#[test]
fn normal_tail_beyond_r_has_the_right_mass() {
    // P(|X| > R) = 2 (1 - Phi(R)) = 2.58e-4 for R = 3.654; 4e6 draws give ~1033 expected,
    // Poisson sd ~ 32; 99.9% bound 3.2 sd.
    let mut rng = seeded(12);
    let m = 4_000_000;
    let count = (0..m)
        .filter(|_| standard_normal(&mut rng).abs() > zt::NORM_R)
        .count() as f64;
    let expect = m as f64 * 2.0 * (1.0 - normal_cdf(zt::NORM_R));
    assert!(
        (count - expect).abs() < gdsmc_stats::LAMBDA_999 * expect.sqrt(),
        "{count} vs {expect}"
    );
}

#[test]
fn exponential_ks() {
    let mut rng = seeded(13);
    let mut xs: Vec<f64> = (0..N).map(|_| standard_exponential(&mut rng)).collect();
    let d = ks_statistic(&mut xs, |x| 1.0 - (-x).exp());
    assert!(d < ks_critical_999(N), "KS D = {d}");
}

#[test]
fn uniforms_ks() {
    let mut rng = seeded(14);
    let mut a: Vec<f64> = (0..N).map(|_| uniform_open01(&mut rng)).collect();
    assert!(a.iter().all(|&x| x > 0.0 && x < 1.0));
    let d = ks_statistic(&mut a, |x| x);
    assert!(d < ks_critical_999(N), "KS D = {d}");
    let mut b: Vec<f64> = (0..N).map(|_| uniform01(&mut rng)).collect();
    let d = ks_statistic(&mut b, |x| x);
    assert!(d < ks_critical_999(N), "KS D = {d}");
}

#[test]
fn sphere_is_uniform() {
    // Archimedes: each coordinate of a uniform point on S^2 is uniform on [-1, 1]; the azimuth
    // about z is uniform on (-pi, pi].
    let mut rng = seeded(15);
    let pts: Vec<Vec3> = (0..N).map(|_| unit_sphere(&mut rng)).collect();
    assert!(pts.iter().all(|e| (e.norm() - 1.0).abs() < 1e-14));
    for comp in 0..3 {
        let mut c: Vec<f64> = pts.iter().map(|e| e.to_array()[comp]).collect();
        let d = ks_statistic(&mut c, |x| (x + 1.0) / 2.0);
        assert!(d < ks_critical_999(N), "component {comp}: KS D = {d}");
    }
    let mut phi: Vec<f64> = pts.iter().map(|e| e.y.atan2(e.x)).collect();
    let d = ks_statistic(&mut phi, |x| (x + PI) / (2.0 * PI));
    assert!(d < ks_critical_999(N), "azimuth: KS D = {d}");
}

#[test]
fn maxwellian_components_are_normal_with_mass_temperature_drift() {
    let (m, t) = (2.0, 3.0);
    let u = Vec3::new(0.5, -1.0, 2.0);
    let mx = Maxwellian::new(m, t, u).unwrap();
    let mut rng = seeded(16);
    let vs: Vec<Vec3> = (0..N).map(|_| mx.sample(&mut rng)).collect();
    let sd = (t / m).sqrt();
    for comp in 0..3 {
        let mu = u.to_array()[comp];
        let mut c: Vec<f64> = vs.iter().map(|v| (v.to_array()[comp] - mu) / sd).collect();
        let d = ks_statistic(&mut c, normal_cdf);
        assert!(d < ks_critical_999(N), "component {comp}: KS D = {d}");
    }
}

#[test]
fn maxwellian_rejects_bad_parameters() {
    assert_eq!(Maxwellian::new(0.0, 1.0, Vec3::ZERO), Err(ParamError::Mass));
    assert_eq!(
        Maxwellian::new(1.0, -1.0, Vec3::ZERO),
        Err(ParamError::Temperature)
    );
    assert_eq!(
        Maxwellian::new(1.0, f64::NAN, Vec3::ZERO),
        Err(ParamError::Temperature)
    );
    assert_eq!(
        Maxwellian::new(1.0, 1.0, Vec3::new(f64::INFINITY, 0.0, 0.0)),
        Err(ParamError::Drift)
    );
}

#[test]
fn mixture_brs_example1_moments() {
    // BRS (35), Example 1: u0 = (0, 1, 0), T0 = 8/3.
    let mut mix = MaxwellianMixture::<2>::new();
    mix.push(
        0.5,
        Maxwellian::new(1.0, 1.0, Vec3::new(-2.0, 2.0, 0.0)).unwrap(),
    )
    .unwrap();
    mix.push(
        0.5,
        Maxwellian::new(1.0, 1.0, Vec3::new(2.0, 0.0, 0.0)).unwrap(),
    )
    .unwrap();
    assert!(
        mix.push(1.0, Maxwellian::standard()).is_err(),
        "capacity is fallible"
    );
    assert!((mix.mean() - Vec3::new(0.0, 1.0, 0.0)).norm() < 1e-15);
    assert!((mix.temperature() - 8.0 / 3.0).abs() < 1e-15);
    let mut rng = seeded(17);
    let vs: Vec<Vec3> = (0..N).map(|_| mix.sample(&mut rng).unwrap()).collect();
    for comp in 0..3 {
        let xs: Vec<f64> = vs.iter().map(|v| v.to_array()[comp]).collect();
        let (m, ci) = mean_ci(&xs);
        let exact = mix.mean().to_array()[comp];
        assert!(
            (m - exact).abs() < ci,
            "mean {comp}: {m} +- {ci} vs {exact}"
        );
    }
    let u = mix.mean();
    let ts: Vec<f64> = vs.iter().map(|v| (*v - u).norm2() / 3.0).collect();
    let (m, ci) = mean_ci(&ts);
    assert!((m - 8.0 / 3.0).abs() < ci, "T {m} +- {ci}");
    // The x component is an equal mixture of N(-2, 1) and N(2, 1): KS against that CDF.
    let mut xs: Vec<f64> = vs.iter().map(|v| v.x).collect();
    let d = ks_statistic(&mut xs, |x| {
        0.5 * normal_cdf(x + 2.0) + 0.5 * normal_cdf(x - 2.0)
    });
    assert!(d < ks_critical_999(N), "KS D = {d}");
}

#[test]
fn background_partner_is_brs_29() {
    // y = |w - u^B|^2 / b^2 is Gamma(2, 1): CDF 1 - (1 + y) e^-y; the direction is uniform.
    let bg = Maxwellian::new(2.0, 0.7, Vec3::new(1.0, 2.0, -3.0)).unwrap();
    let p = BackgroundPartner::new(&bg);
    let b = (2.0 * 0.7 / 2.0f64).sqrt();
    assert!((p.b() - b).abs() < 1e-15);
    let mut rng = seeded(18);
    let ws: Vec<Vec3> = (0..N).map(|_| p.sample(&mut rng)).collect();
    let mut ys: Vec<f64> = ws
        .iter()
        .map(|w| (*w - bg.drift()).norm2() / (b * b))
        .collect();
    let d = ks_statistic(&mut ys, |y| 1.0 - (1.0 + y) * (-y).exp());
    assert!(d < ks_critical_999(N), "KS D = {d}");
    let mut zs: Vec<f64> = ws
        .iter()
        .map(|w| {
            let c = *w - bg.drift();
            c.z / c.norm()
        })
        .collect();
    let d = ks_statistic(&mut zs, |x| (x + 1.0) / 2.0);
    assert!(d < ks_critical_999(N), "direction: KS D = {d}");
    // Mean speed 3 sqrt(pi)/4 b under p_2 (the Gamma(2) law of y gives E sqrt(y) = Gamma(5/2)).
    let speeds: Vec<f64> = ws.iter().map(|w| (*w - bg.drift()).norm()).collect();
    let (m, ci) = mean_ci(&speeds);
    let exact = 0.75 * PI.sqrt() * b;
    assert!((m - exact).abs() < ci, "{m} +- {ci} vs {exact}");
}

#[test]
fn ziggurat_tables_match_libm_recomputation() {
    let check = |x: &[f64; 257],
                 f: &[f64; 257],
                 r: f64,
                 v: f64,
                 pdf: &dyn Fn(f64) -> f64,
                 inv: &dyn Fn(f64) -> f64| {
        assert_eq!(x[1], r);
        assert!((x[0] - v / pdf(r)).abs() <= 1e-15 * x[0]);
        for i in 2..256 {
            let xi = inv(v / x[i - 1] + f[i - 1]);
            assert!((x[i] - xi).abs() <= 1e-12 * xi, "layer {i}");
            assert!((f[i] - pdf(x[i])).abs() <= 1e-15, "layer {i}");
        }
        assert_eq!(x[256], 0.0);
        assert_eq!(f[256], 1.0);
        // Each layer box has area V: x_i (f_{i+1} - f_i) = V for the inner layers.
        for i in 1..255 {
            assert!(
                (x[i] * (f[i + 1] - f[i]) - v).abs() < 1e-12,
                "area of layer {i}"
            );
        }
    };
    check(
        &zt::NORM_X,
        &zt::NORM_F,
        zt::NORM_R,
        zt::NORM_V,
        &|x| libm::exp(-0.5 * x * x),
        &|y| libm::sqrt(-2.0 * libm::log(y)),
    );
    check(
        &zt::EXP_X,
        &zt::EXP_F,
        zt::EXP_R,
        zt::EXP_V,
        &|x| libm::exp(-x),
        &|y| -libm::log(y),
    );
}
