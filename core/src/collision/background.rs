//! The elastic grain-background collision map BRS (2) with the mass ratio BRS (3):
//!
//! ```text
//! v' = (1 - a) v + a w + a |g| w_hat,
//! w' = (1 - a) v + a w - (1 - a) |g| w_hat,     g = v - w,  a = m^B / (m + m^B),
//! ```
//!
//! which keeps `m v + m^B w` and `m |v|^2 + m^B |w|^2`.
//!
//! ```
//! use gdsmc_core::{collision::{MassRatio, elastic_background}, vec3::Vec3};
//! let a = MassRatio::new(1.0, 1.0).unwrap(); // a = 1/2
//! let (v1, w1) = elastic_background(Vec3::new(1.0, 0.0, 0.0), Vec3::ZERO, Vec3::new(0.0, 0.0, 1.0), a);
//! assert!((v1.norm2() + w1.norm2() - 1.0).abs() < 1e-15);
//! ```

use crate::math::Real;
use crate::vec3::Vec3;

/// The mass ratio `a = m^B / (m + m^B)` of BRS (3), in (0, 1).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct MassRatio(Real);

impl MassRatio {
    /// From the grain mass `m` and the background mass `m_b`; `None` unless both are finite and
    /// positive.
    pub fn new(m: Real, m_b: Real) -> Option<Self> {
        if m.is_finite() && m > 0.0 && m_b.is_finite() && m_b > 0.0 {
            Some(MassRatio(m_b / (m + m_b)))
        } else {
            None
        }
    }

    /// The value `a`.
    pub fn get(self) -> Real {
        self.0
    }
}

/// Post-collisional grain and background velocities `(v', w')` of BRS (2).
#[inline(always)]
pub fn elastic_background(v: Vec3, w: Vec3, omega: Vec3, a: MassRatio) -> (Vec3, Vec3) {
    let g = v - w;
    let g_len = g.norm();
    (
        grain_after_background(v, g, g_len, omega, a),
        centre(v, g, a) - ((1.0 - a.0) * g_len) * omega,
    )
}

/// The grain's post-collisional velocity `v'` of BRS (2) from its relative velocity
/// `g = v - w` and `|g|` (a sampler that has both saves the background's half and a root):
/// `v' = v - a g + a |g| omega`, the same as `(1 - a) v + a w + a |g| omega`.
#[inline(always)]
pub fn grain_after_background(v: Vec3, g: Vec3, g_len: Real, omega: Vec3, a: MassRatio) -> Vec3 {
    centre(v, g, a) + (a.0 * g_len) * omega
}

/// The centre-of-mass velocity `(1 - a) v + a w = v - a g` of BRS (2).
#[inline(always)]
fn centre(v: Vec3, g: Vec3, a: MassRatio) -> Vec3 {
    v - a.0 * g
}
