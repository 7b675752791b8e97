//! The collisional moments `mu_2` and `mu_4` of MS (64)-(67) for inelastic hard spheres,
//! estimated from `N'` random pairs of the particle system:
//! `mu_p = v_0^{-p-1} (1/N') sum' Phi_p(v_i, v_j)` (MS (67)), `v_0 = (2 T)^{1/2}` (MS, after
//! (63)), with `Phi_2 = pi (1 - alpha^2)/8 v12^3` (MS (65)) and `Phi_4` of MS (66). Velocities are
//! taken about the bulk velocity. At the Maxwellian, `mu_2^(0) = sqrt(2 pi) (1 - alpha^2)` and
//! `mu_4^(0) = (9/2 + alpha^2) mu_2^(0)` (MS (27), (29) with d = 3).

use crate::math::{PI, Real, sqrt};
use crate::particles::Particles;
use crate::rng::{Rng, uniform_pair};
use crate::vec3::Vec3;

/// `Phi_2(v1, v2)` of MS (65).
#[inline]
pub fn phi2(v1: Vec3, v2: Vec3, alpha: Real) -> Real {
    let u = (v1 - v2).norm();
    PI * (1.0 - alpha * alpha) / 8.0 * u * u * u
}

/// `Phi_4(v1, v2)` of MS (66).
#[inline]
pub fn phi4(v1: Vec3, v2: Vec3, alpha: Real) -> Real {
    let u = v1 - v2;
    let w = 0.5 * (v1 + v2);
    let (u2, w2, uw) = (u.norm2(), w.norm2(), u.dot(w));
    let a2 = alpha * alpha;
    PI / 4.0
        * sqrt(u2)
        * (5.0 * (1.0 - a2) / 3.0 * u2 * w2
            + (1.0 - a2) * (2.0 + a2) / 12.0 * u2 * u2
            + (3.0 - alpha) * (1.0 + alpha) * (uw * uw - u2 * w2 / 3.0))
}

/// `(mu_2, mu_4)` from `pairs` uniform random pairs (MS (67)) of the system `p`, whose bulk
/// velocity `bulk` and temperature `t_bulk` the caller knows (e.g. from
/// [`crate::moments::Observables`]).
pub fn collisional_moments<R: Rng + ?Sized>(
    p: &Particles<'_>,
    bulk: Vec3,
    t_bulk: Real,
    alpha: Real,
    pairs: u64,
    rng: &mut R,
) -> (Real, Real) {
    let n = p.len();
    let (mut s2, mut s4) = (0.0, 0.0);
    for _ in 0..pairs {
        let (i, j) = uniform_pair(rng, n);
        let (a, b) = (p.velocity(i) - bulk, p.velocity(j) - bulk);
        s2 += phi2(a, b, alpha);
        s4 += phi4(a, b, alpha);
    }
    let v0 = sqrt(2.0 * t_bulk);
    let k = pairs as Real;
    (s2 / k / (v0 * v0 * v0), s4 / k / (v0 * v0 * v0 * v0 * v0))
}
