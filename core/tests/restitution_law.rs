//! The impact-speed law BRS (9)-(10): its coefficient, and the normal impact speed the smooth
//! map gives it, which must be the impact's (the rough map's) for every pair.

use crate::common;

use common::strategies::{unit, vec3};
use gdsmc_core::collision::{inelastic, scattering_direction_from_impact};
use gdsmc_core::restitution::{ImpactSpeed, Restitution};
use gdsmc_core::rough::RoughMap;
use gdsmc_core::vec3::Vec3;
use proptest::prelude::*;

#[test]
fn delta_zero_is_constant_and_normal_speed_is_the_apse_lines() {
    let law = ImpactSpeed::new(0.25, 0.0).unwrap();
    let u = Vec3::new(1.0, 2.0, -0.5);
    for e in [
        Vec3::new(1.0, 0.0, 0.0),
        Vec3::new(0.0, 0.6, 0.8),
        Vec3::new(0.0, 0.0, -1.0),
    ] {
        assert!((law.coefficient(u, e) - 0.5).abs() < 1e-15);
    }
    // Head-on reversal (e = -u_hat): |g . n| = |g|; grazing (e = u_hat): 0. (BRS (10) as
    // printed, with |g . w_hat|, gives 0 for the head-on impact: it would be elastic.)
    let uh = (1.0 / u.norm()) * u;
    assert!((ImpactSpeed::normal_speed(u, -uh) - u.norm()).abs() < 1e-12 * u.norm());
    assert!((ImpactSpeed::normal_speed(u, uh) - 0.0).abs() < 1e-12 * u.norm());
    // Perpendicular: |g . n|^2 = |g|^2 / 2.
    let perp = {
        let t = Vec3::new(2.0, -1.0, 0.0);
        (1.0 / t.norm()) * t
    };
    assert!(perp.dot(u).abs() < 1e-15);
    assert!((ImpactSpeed::normal_speed(u, perp) - u.norm() / 2f64.sqrt()).abs() < 1e-12);
}

#[test]
fn viscoelastic_law_decreases_with_impact_speed() {
    let law = ImpactSpeed::new(0.1, 0.2).unwrap();
    let e = Vec3::new(0.0, 1.0, 0.0);
    let slow = law.coefficient(Vec3::new(0.1, 0.0, 0.0), e);
    let fast = law.coefficient(Vec3::new(10.0, 0.0, 0.0), e);
    assert!(slow > fast && slow < 1.0);
    // e = 1 - 2 beta0 (|g|/sqrt 2)^delta exactly.
    let want = 1.0 - 0.2 * (10.0f64 / 2f64.sqrt()).powf(0.2);
    assert!((fast - want).abs() < 1e-14);
    // Beyond (1/(2 beta0))^(1/delta) the law leaves [0, 1]: the loops clamp and count.
    assert!(law.coefficient(Vec3::new(1e6, 0.0, 0.0), e) < 0.0);
    assert!(ImpactSpeed::new(-0.1, 0.2).is_err() && ImpactSpeed::new(0.1, f64::NAN).is_err());
}

/// Approaching pairs `(v1, v2, n)`: `n` the unit vector from 1 to 2 with `(v1 - v2) . n > 0`.
fn approaching() -> impl Strategy<Value = (Vec3, Vec3, Vec3)> {
    (vec3(10.0), vec3(10.0), unit()).prop_filter_map("a pair that approaches", |(v1, v2, n)| {
        let c = (v1 - v2).dot(n);
        (c.abs() > 1e-9 * (v1 - v2).norm()).then(|| (v1, v2, if c > 0.0 { n } else { -n }))
    })
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(4000))]

    /// The smooth map's normal impact speed is the impact's own: GRW (3) with the direction
    /// `e` that the impact `n` scatters `u` into (MS's impact form) sees `|u . n|`, and under
    /// the law it moves the pair exactly as the rough map with `beta = -1` (no spin, the impact
    /// `n` itself) does. With BRS (10)'s printed `|u . e|` every head-on half (`u_hat . e < 0`)
    /// fails both: the smooth map would see the tangential speed.
    #[test]
    fn the_smooth_map_sees_the_impacts_normal_speed(
        (v1, v2, n) in approaching(), b0 in 0.0f64..0.3, d in prop_oneof![Just(0.2), 0.0f64..2.0],
    ) {
        let u = v1 - v2;
        let e = scattering_direction_from_impact(u, n);
        let speed = ImpactSpeed::normal_speed(u, e);
        // The bound of its rounding: `sqrt((|u|^2 - |u| (u . e)) / 2)` subtracts two numbers
        // of size |u|^2, each within a few eps |u|^2 (and `e` is a unit vector to a few eps),
        // so the argument is off by at most 8 eps |u|^2 and the root by that over twice the
        // root (a grazing impact, `u . n` small, magnifies it: seen 3.1e-11 at |u| = 23.8,
        // `u . n` = 0.0016, above the former flat 1e-12 |u|; regression file).
        let (un, normal) = (u.norm(), u.dot(n));
        let bound = 8.0 * f64::EPSILON * un * un / (2.0 * normal) + 4.0 * f64::EPSILON * un;
        prop_assert!((speed - normal).abs() <= bound, "{speed} vs {normal} (bound {bound:e})");
        let law = ImpactSpeed::new(b0, d).unwrap();
        let alpha = law.coefficient(u, e).clamp(0.0, 1.0);
        let (s1, s2) = inelastic(v1, v2, e, alpha);
        let rough = RoughMap::new(1.0, -1.0, 0.4).unwrap().with_law(law);
        let (r1, _, r2, _) = rough.collide(v1, Vec3::ZERO, v2, Vec3::ZERO, n);
        let scale = v1.norm() + v2.norm();
        prop_assert!((s1 - r1).norm() <= 1e-11 * scale && (s2 - r2).norm() <= 1e-11 * scale,
            "smooth {s1:?} {s2:?}, rough {r1:?} {r2:?}");
    }
}
