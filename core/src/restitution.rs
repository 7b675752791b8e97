//! Restitution laws: the coefficient `alpha` used in GRW (3) for a given pair and direction.
//!
//! The engine is generic over [`Restitution`]; a constant coefficient compiles to a constant.

use crate::math::Real;
use crate::vec3::Vec3;

/// A law giving the restitution coefficient of a collision with relative velocity `u` and
/// direction `e` (GRW (3)).
pub trait Restitution: Copy {
    /// The coefficient, in (0, 1].
    fn coefficient(&self, u: Vec3, e: Vec3) -> Real;
}

/// A constant restitution coefficient `alpha` in (0, 1] (GRW (3), BRS (9) with `delta = 0`).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Constant(Real);

impl Constant {
    /// `None` unless `0 < alpha <= 1`.
    pub fn new(alpha: Real) -> Option<Self> {
        if alpha > 0.0 && alpha <= 1.0 {
            Some(Constant(alpha))
        } else {
            None
        }
    }
    /// The coefficient.
    pub fn alpha(&self) -> Real {
        self.0
    }
}

impl Restitution for Constant {
    #[inline(always)]
    fn coefficient(&self, _u: Vec3, _e: Vec3) -> Real {
        self.0
    }
}
