//! The inelastic collision map GRW (3) / RW (4):
//!
//! ```text
//! v' = (v + w)/2 + (1 - alpha)/4 u + (1 + alpha)/4 |u| e,
//! w' = (v + w)/2 - (1 - alpha)/4 u - (1 + alpha)/4 |u| e,      u = v - w, |e| = 1,
//! ```
//!
//! for restitution `alpha` in (0, 1]. It is implemented once, here. The same physics appears in
//! two other sets of variables, and the tests show the equivalences:
//!
//! - MS (Section 3, after (56)), the impact-parameter form
//!   `v_{1,2}' = v_{1,2} -/+ (1 + alpha)/2 (v12 . s) s` with `s` the unit vector along the line
//!   of centres: it equals GRW (3) with `e = u/|u| - 2 (u/|u| . s) s` (the reflection of the
//!   relative direction in the plane normal to `s`), see [`scattering_direction_from_impact`].
//!   For hard spheres, `s` drawn with density proportional to `Theta(u . s)(u . s)` gives `e`
//!   uniform on the sphere.
//! - BRS (4) with `beta = (1 - e)/2` (BRS (5)): `v* = (1+beta)/2 v + (1-beta)/2 w + (1-beta)/2 |g| w_hat`,
//!   which is GRW (3) with `alpha = e` and `e = w_hat`.
//!
//! ```
//! use gdsmc_core::{collision::inelastic, vec3::Vec3};
//! let (v, w) = (Vec3::new(1.0, 0.0, 0.0), Vec3::new(-1.0, 0.0, 0.0));
//! let (v1, w1) = inelastic(v, w, Vec3::new(0.0, 1.0, 0.0), 0.5);
//! assert!((v1 + w1).norm() < 1e-15); // momentum kept
//! ```

use crate::math::Real;
use crate::vec3::Vec3;

/// Post-collisional velocities `(v', w')` of GRW (3).
#[inline(always)]
pub fn inelastic(v: Vec3, w: Vec3, e: Vec3, alpha: Real) -> (Vec3, Vec3) {
    let u = v - w;
    let centre = 0.5 * (v + w);
    let d = (0.25 * (1.0 - alpha)) * u + (0.25 * (1.0 + alpha) * u.norm()) * e;
    (centre + d, centre - d)
}

/// The energy change `|v'|^2 + |w'|^2 - |v|^2 - |w|^2 = -(1 - alpha^2)/4 (1 - mu) |u|^2` of GRW
/// (Section 1, after (14)), `mu = (u . e)/|u|`; written as `-(1 - alpha^2)/4 (|u|^2 - |u| (u . e))`
/// so that `u = 0` needs no division.
#[inline]
pub fn energy_change(u: Vec3, e: Vec3, alpha: Real) -> Real {
    -(1.0 - alpha * alpha) / 4.0 * (u.norm2() - u.norm() * u.dot(e))
}

/// The direction `e` of GRW (3) that reproduces the impact-parameter collision of MS with unit
/// vector `s` along the line of centres: `e = u_hat - 2 (u_hat . s) s`. For `u = 0` any `e`
/// gives the same (trivial) collision; `s` is returned.
#[inline]
pub fn scattering_direction_from_impact(u: Vec3, s: Vec3) -> Vec3 {
    let un = u.norm();
    if un > 0.0 {
        let uh = (1.0 / un) * u;
        uh - (2.0 * uh.dot(s)) * s
    } else {
        s
    }
}
