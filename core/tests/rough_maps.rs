//! Property tests of the rough-sphere collision map (`rough::RoughMap`, Huthmann and
//! Zippelius 1997): momentum, angular momentum about the contact point, the contact
//! velocity's components reversed and shrunk by alpha and beta, the energy change in closed
//! form, the elastic perfectly rough and the smooth limits; and the impact direction's law.
//! Tolerances are rounding bounds: a few hundred ulps of the magnitudes involved.

use crate::common;

use common::strategies::{unit, vec3};
use gdsmc_core::rng::seeded;
use gdsmc_core::rough::{RoughError, RoughMap, impact_direction};
use gdsmc_core::vec3::Vec3;
use proptest::prelude::*;

const EPS: f64 = f64::EPSILON;

fn map() -> impl Strategy<Value = RoughMap> {
    (
        prop_oneof![Just(1.0), 1e-3f64..=1.0],
        prop_oneof![Just(-1.0), Just(1.0), -1.0f64..=1.0],
        prop_oneof![Just(0.4), Just(2.0 / 3.0), 1e-3f64..=2.0 / 3.0],
    )
        .prop_map(|(a, b, k)| RoughMap::new(a, b, k).unwrap())
}

/// `sum (|v|^2 + kappa |w|^2)`: twice the energy per unit mass.
fn energy(m: &RoughMap, v: [Vec3; 4]) -> f64 {
    v[0].norm2() + m.kappa() * v[1].norm2() + v[2].norm2() + m.kappa() * v[3].norm2()
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(4000))]

    #[test]
    fn momentum_and_angular_momentum_about_the_contact_are_kept(
        m in map(), v1 in vec3(1e2), w1 in vec3(1e2), v2 in vec3(1e2), w2 in vec3(1e2), n in unit(),
    ) {
        let (a1, b1, a2, b2) = m.collide(v1, w1, v2, w2, n);
        let scale = v1.norm() + v2.norm() + w1.norm() + w2.norm();
        prop_assert!(((a1 + a2) - (v1 + v2)).norm() <= 64.0 * EPS * scale);
        // About the contact point (sigma/2 = 1 in rim units): L_i = kappa w_i + r_i x v_i with
        // r_1 = -n, r_2 = n; the sum is kept.
        let l = |v1: Vec3, w1: Vec3, v2: Vec3, w2: Vec3| {
            m.kappa() * (w1 + w2) + (-1.0 * n).cross(v1) + n.cross(v2)
        };
        let dl = l(a1, b1, a2, b2) - l(v1, w1, v2, w2);
        prop_assert!(dl.norm() <= 256.0 * EPS * scale, "{dl:?}");
    }

    #[test]
    fn the_contact_velocity_is_reversed_and_shrunk(
        m in map(), v1 in vec3(1e2), w1 in vec3(1e2), v2 in vec3(1e2), w2 in vec3(1e2), n in unit(),
    ) {
        let g = RoughMap::contact_velocity(v1, w1, v2, w2, n);
        let (a1, b1, a2, b2) = m.collide(v1, w1, v2, w2, n);
        let g1 = RoughMap::contact_velocity(a1, b1, a2, b2, n);
        let gn = g.dot(n) * n;
        let expect = -m.alpha() * gn - m.beta() * (g - gn);
        let scale = (v1.norm() + v2.norm() + w1.norm() + w2.norm()) / m.kappa();
        prop_assert!((g1 - expect).norm() <= 256.0 * EPS * scale, "{g1:?} vs {expect:?}");
    }

    #[test]
    fn the_energy_change_has_its_closed_form(
        m in map(), v1 in vec3(1e2), w1 in vec3(1e2), v2 in vec3(1e2), w2 in vec3(1e2), n in unit(),
    ) {
        let (a1, b1, a2, b2) = m.collide(v1, w1, v2, w2, n);
        let g = RoughMap::contact_velocity(v1, w1, v2, w2, n);
        let de = 0.5 * (energy(&m, [a1, b1, a2, b2]) - energy(&m, [v1, w1, v2, w2]));
        let closed = m.energy_change(g, n);
        let scale = (v1.norm() + v2.norm() + w1.norm() + w2.norm()).powi(2) / m.kappa();
        prop_assert!((de - closed).abs() <= 1024.0 * EPS * scale, "{de} vs {closed}");
        prop_assert!(closed <= 0.0);
        if m.alpha() == 1.0 && m.beta().abs() == 1.0 {
            prop_assert!(de.abs() <= 1024.0 * EPS * scale, "elastic: {de}");
        }
    }

    #[test]
    fn beta_minus_one_leaves_the_rotation_alone(
        v1 in vec3(1e2), w1 in vec3(1e2), v2 in vec3(1e2), w2 in vec3(1e2), n in unit(),
        a in prop_oneof![Just(1.0), 1e-3f64..=1.0], k in 1e-3f64..=2.0 / 3.0,
    ) {
        let m = RoughMap::new(a, -1.0, k).unwrap();
        let (a1, b1, a2, b2) = m.collide(v1, w1, v2, w2, n);
        prop_assert_eq!((b1, b2), (w1, w2));
        // The translational part is the smooth impact form v1' = v1 - (1 + alpha)/2 (g . n) n
        // with g . n = (v1 - v2) . n (the rotation adds nothing along n).
        let dv = -(0.5 * (1.0 + a) * (v1 - v2).dot(n)) * n;
        let scale = v1.norm() + v2.norm();
        prop_assert!((a1 - (v1 + dv)).norm() <= 64.0 * EPS * scale);
        prop_assert!((a2 - (v2 - dv)).norm() <= 64.0 * EPS * scale);
    }
}

#[test]
fn bad_coefficients_are_refused() {
    assert_eq!(RoughMap::new(0.0, 0.5, 0.4), Err(RoughError::Alpha));
    assert_eq!(RoughMap::new(1.5, 0.5, 0.4), Err(RoughError::Alpha));
    assert_eq!(RoughMap::new(0.9, -1.5, 0.4), Err(RoughError::Beta));
    assert_eq!(RoughMap::new(0.9, f64::NAN, 0.4), Err(RoughError::Beta));
    assert_eq!(RoughMap::new(0.9, 0.5, 0.0), Err(RoughError::Kappa));
    assert_eq!(RoughMap::new(0.9, 0.5, 0.7), Err(RoughError::Kappa));
    assert!(RoughMap::new(1.0, 1.0, 2.0 / 3.0).is_ok());
}

/// The impact direction: unit, on the approaching hemisphere, and `c = u_hat . n` with
/// density `2 c` on [0, 1] (the CDF `c^2`): a Kolmogorov-Smirnov test at the 99.9% level
/// (fixed seed, 20,000 draws), and its azimuth about `u` uniform (the mean of `n` projected
/// off `u` within 4 standard errors of 0 in each component: Bonferroni over the two).
#[test]
fn the_impact_direction_has_the_hard_sphere_law() {
    let mut rng = seeded(42);
    let u = Vec3::new(0.3, -1.2, 0.7);
    let uh = (1.0 / u.norm()) * u;
    let k = 20_000;
    let mut cs = Vec::with_capacity(k);
    let mut off = Vec3::ZERO;
    for _ in 0..k {
        let n = impact_direction(u, &mut rng);
        assert!((n.norm() - 1.0).abs() < 1e-12);
        let c = n.dot(uh);
        assert!(c >= 0.0, "receding: {c}");
        cs.push(c);
        off += n - c * uh;
    }
    let d = common::ks_statistic(&mut cs, |c| c * c);
    assert!(d < common::ks_critical_999(k), "KS {d}");
    // Each component of the perpendicular part has variance at most 1/2 per draw.
    let bound = 4.0 * (0.5 / k as f64).sqrt();
    let mean = (1.0 / k as f64) * off;
    assert!(
        mean.x.abs() < bound && mean.y.abs() < bound && mean.z.abs() < bound,
        "{mean:?}"
    );
}
