//! The impact-speed law BRS (9)-(10).

use gdsmc_core::restitution::{ImpactSpeed, Restitution};
use gdsmc_core::vec3::Vec3;

#[test]
fn delta_zero_is_constant_and_normal_speed_matches_brs_10() {
    let law = ImpactSpeed::new(0.25, 0.0).unwrap();
    let u = Vec3::new(1.0, 2.0, -0.5);
    for e in [
        Vec3::new(1.0, 0.0, 0.0),
        Vec3::new(0.0, 0.6, 0.8),
        Vec3::new(0.0, 0.0, -1.0),
    ] {
        assert!((law.coefficient(u, e) - 0.5).abs() < 1e-15);
    }
    // Head-on reversal (e = -u_hat): |g . n| = |g|; grazing (e = u_hat): 0.
    let uh = (1.0 / u.norm()) * u;
    assert!((ImpactSpeed::normal_speed(u, -uh) - 0.0).abs() < 1e-12 * u.norm());
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
