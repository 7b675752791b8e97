//! Property tests of every collision map (GRW (3), its MS and BRS (4) forms, BRS (2)).
//! Tolerances are rounding bounds: a few ulps of the largest magnitude involved.

use gdsmc_core::collision::*;
use gdsmc_core::vec3::Vec3;
use proptest::prelude::*;

use crate::common;

use common::strategies::{alpha, unit, vec3};

/// Rounding allowance: `k` ulps of the scale `s`.
fn tol(s: f64, k: f64) -> f64 {
    k * f64::EPSILON * s.max(1e-300)
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(4000))]

    #[test]
    fn inelastic_keeps_momentum(v in vec3(1e3), w in vec3(1e3), e in unit(), a in alpha()) {
        let (v1, w1) = inelastic(v, w, e, a);
        let s = v.norm() + w.norm();
        prop_assert!(((v1 + w1) - (v + w)).norm() <= tol(s, 16.0));
    }

    #[test]
    fn inelastic_energy_change_has_its_closed_form(v in vec3(1e3), w in vec3(1e3), e in unit(), a in alpha()) {
        let (v1, w1) = inelastic(v, w, e, a);
        let de = v1.norm2() + w1.norm2() - v.norm2() - w.norm2();
        let s = v.norm2() + w.norm2();
        prop_assert!((de - energy_change(v - w, e, a)).abs() <= tol(s, 64.0), "{} vs {}", de, energy_change(v - w, e, a));
        if a == 1.0 {
            prop_assert!(de.abs() <= tol(s, 64.0));
        }
        // Never gains energy: (1 - mu) >= 0.
        prop_assert!(de <= tol(s, 64.0));
    }

    #[test]
    fn inelastic_is_finite_for_finite_input(v in vec3(1e150), e in unit(), a in alpha(), same in any::<bool>(), w0 in vec3(1e150)) {
        let w = if same { v } else { w0 }; // u = 0 included
        let (v1, w1) = inelastic(v, w, e, a);
        prop_assert!(v1.is_finite() && w1.is_finite());
        if same {
            prop_assert_eq!(v1, v);
            prop_assert_eq!(w1, w);
        }
    }

    #[test]
    fn ms_impact_form_is_grw3(v in vec3(100.0), w in vec3(100.0), s in unit(), a in alpha()) {
        // MS: v_{1,2}' = v_{1,2} -/+ (1 + alpha)/2 (v12 . s) s.
        let u = v - w;
        let k = 0.5 * (1.0 + a) * u.dot(s);
        let (ms1, ms2) = (v - k * s, w + k * s);
        let (g1, g2) = inelastic(v, w, scattering_direction_from_impact(u, s), a);
        let sc = v.norm() + w.norm();
        prop_assert!((ms1 - g1).norm() <= tol(sc, 64.0));
        prop_assert!((ms2 - g2).norm() <= tol(sc, 64.0));
    }

    #[test]
    fn brs4_form_is_grw3(v in vec3(100.0), w in vec3(100.0), om in unit(), e in 1e-6f64..=1.0) {
        // BRS (4) with beta = (1 - e)/2 (BRS (5)).
        let beta = (1.0 - e) / 2.0;
        let g = (v - w).norm();
        let b1 = (0.5 * (1.0 + beta)) * v + (0.5 * (1.0 - beta)) * w + (0.5 * (1.0 - beta) * g) * om;
        let b2 = (0.5 * (1.0 - beta)) * v + (0.5 * (1.0 + beta)) * w - (0.5 * (1.0 - beta) * g) * om;
        let (g1, g2) = inelastic(v, w, om, e);
        let sc = v.norm() + w.norm();
        prop_assert!((b1 - g1).norm() <= tol(sc, 64.0));
        prop_assert!((b2 - g2).norm() <= tol(sc, 64.0));
    }

    #[test]
    fn background_map_keeps_momentum_and_energy(v in vec3(100.0), w in vec3(100.0), om in unit(), m in 1e-3f64..1e3, mb in 1e-3f64..1e3) {
        let a = MassRatio::new(m, mb).unwrap();
        let (v1, w1) = elastic_background(v, w, om, a);
        let p0 = m * v + mb * w;
        let p1 = m * v1 + mb * w1;
        let e0 = m * v.norm2() + mb * w.norm2();
        let e1 = m * v1.norm2() + mb * w1.norm2();
        let sp = (m + mb) * (v.norm() + w.norm());
        prop_assert!((p1 - p0).norm() <= tol(sp, 64.0), "momentum {:?} vs {:?}", p1, p0);
        prop_assert!((e1 - e0).abs() <= tol(e0 + sp * (v.norm() + w.norm()), 64.0), "energy {} vs {}", e1, e0);
        prop_assert!(v1.is_finite() && w1.is_finite());
    }
}

#[test]
fn mass_ratio_validates() {
    assert!(MassRatio::new(0.0, 1.0).is_none());
    assert!(MassRatio::new(1.0, f64::NAN).is_none());
    assert_eq!(MassRatio::new(1.0, 1.0).unwrap().get(), 0.5);
}

#[test]
fn impact_rule_gives_uniform_scattering_directions() {
    // MS: s with density proportional to Theta(u . s)(u . s) (cos theta = sqrt(U) about u_hat,
    // azimuth uniform) maps to e uniform on the sphere, so e . u_hat is uniform on [-1, 1].
    // KS at level 99.9%.
    use gdsmc_core::rng::{seeded, uniform01};
    let mut rng = seeded(21);
    let u = Vec3::new(0.3, -1.2, 0.7);
    let uh = (1.0 / u.norm()) * u;
    // An orthonormal frame (uh, p, q).
    let p = {
        let t = Vec3::new(1.0, 0.0, 0.0);
        let p = t - t.dot(uh) * uh;
        (1.0 / p.norm()) * p
    };
    let q = Vec3::new(
        uh.y * p.z - uh.z * p.y,
        uh.z * p.x - uh.x * p.z,
        uh.x * p.y - uh.y * p.x,
    );
    let n = 100_000;
    let mut xs: Vec<f64> = (0..n)
        .map(|_| {
            let c = uniform01(&mut rng).sqrt();
            let s_ = (1.0 - c * c).sqrt();
            let phi = std::f64::consts::TAU * uniform01(&mut rng);
            let s = c * uh + (s_ * phi.cos()) * p + (s_ * phi.sin()) * q;
            scattering_direction_from_impact(u, s).dot(uh)
        })
        .collect();
    xs.sort_by(|a, b| a.partial_cmp(b).unwrap());
    let d = xs
        .iter()
        .enumerate()
        .map(|(i, &x)| {
            let f = (x + 1.0) / 2.0;
            ((i as f64 + 1.0) / n as f64 - f).max(f - i as f64 / n as f64)
        })
        .fold(0.0, f64::max);
    assert!(d < 1.9495 / (n as f64).sqrt(), "KS D = {d}");
}
