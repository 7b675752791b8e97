//! Restitution laws: the coefficient `alpha` used in GRW (3) for a given pair and direction.
//!
//! The engine is generic over [`Restitution`]; a constant coefficient compiles to a constant.
//!
//! A law may give a value outside [0, 1] (the impact-speed law at high impact speeds); the
//! event loops then use the nearest value in [0, 1] and count the collision in
//! [`crate::engine::Counts::clamped`].

use crate::math::{Real, powf, sqrt};
use crate::vec3::Vec3;

/// A law giving the restitution coefficient of a collision with relative velocity `u` and
/// direction `e` (GRW (3)).
pub trait Restitution: Copy + core::fmt::Debug {
    /// True when the law can leave [0, 1] (then the loops clamp and count).
    const CAN_LEAVE_UNIT_INTERVAL: bool;
    /// True when the coefficient depends on the collision (a map may then not precompute
    /// what it derives from it).
    const VARIES: bool;
    /// The coefficient (before clamping).
    fn coefficient(&self, u: Vec3, e: Vec3) -> Real;
    /// The coefficient of a collision whose normal impact speed `|g . n|` is `speed` (before
    /// clamping; BRS (9) itself): the rough particles' map, which draws the impact direction `n`
    /// and so knows `g . n` without BRS (10).
    fn at_normal_speed(&self, speed: Real) -> Real;
    /// The same law for velocities stored in new units, `scale` times which are the velocities
    /// this law takes (a cooling gas stored rescaled, [`crate::engine::frame::Frame`]): its
    /// coefficient at a stored impact speed is this law's at `scale` times it. A law that does
    /// not depend on the speed is itself, as is every law at `scale = 1`; successive changes
    /// compose to rounding (`in_stored_units(a).in_stored_units(b)` is
    /// `in_stored_units(a b)` to a few ulps).
    #[must_use]
    fn in_stored_units(&self, scale: Real) -> Self;
}

/// The impact-speed law BRS (9)-(10): `1 - e = 2 beta_0 |g . n|^delta`, with the normal impact
/// speed `|g . n|^2 = (|g|^2 - |g| (g . w_hat)) / 2`, `g = u` the relative velocity and `w_hat =
/// e` the direction of GRW (3). BRS print (10) with `|g . w_hat|`; without the absolute value
/// it is the normal of map (4) itself: the impulse there is along `g - |g| w_hat`, the apse line
/// `n`, and `|g . n|^2 = |g - |g| w_hat|^2 / 4` is the expression above (docs/papers.md, "Where
/// the code departs from a printed equation"). The rough map, which draws `n`, takes the same
/// speed. `delta = 1/5`: viscoelastic spheres; `delta = 0`: constant `e = 1 - 2 beta_0`. For
/// impact speeds above `(1/(2 beta_0))^{1/delta}` the law gives `e < 0`; gdsmc then takes
/// `e = 0` (a perfectly inelastic normal impact) and counts it.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ImpactSpeed {
    beta0: Real,
    delta: Real,
}

/// A parameter of [`ImpactSpeed`] out of its domain.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum ImpactSpeedError {
    /// `beta_0` is not finite and `>= 0`.
    Beta0,
    /// `delta` is not finite and `>= 0`.
    Delta,
}

impl ImpactSpeed {
    /// The law with `beta0 >= 0` and `delta >= 0`, both finite; the error names the one that
    /// is not.
    pub fn new(beta0: Real, delta: Real) -> Result<Self, ImpactSpeedError> {
        if !(beta0.is_finite() && beta0 >= 0.0) {
            return Err(ImpactSpeedError::Beta0);
        }
        if !(delta.is_finite() && delta >= 0.0) {
            return Err(ImpactSpeedError::Delta);
        }
        Ok(ImpactSpeed { beta0, delta })
    }
    /// `beta_0`.
    pub fn beta0(&self) -> Real {
        self.beta0
    }
    /// `delta`.
    pub fn delta(&self) -> Real {
        self.delta
    }
    /// The normal impact speed `|g . n|` of the collision GRW (3) with relative velocity `u`
    /// and direction `e`: `sqrt((|u|^2 - |u| (u . e)) / 2)` (BRS (10) without its absolute
    /// value; type docs). A head-on reversal (`e = -u_hat`) gives `|u|`, a grazing collision
    /// (`e = u_hat`) 0.
    #[inline]
    pub fn normal_speed(u: Vec3, e: Vec3) -> Real {
        let un = u.norm();
        sqrt(crate::math::max(0.0, 0.5 * (un * un - un * u.dot(e))))
    }
}

impl Restitution for ImpactSpeed {
    const CAN_LEAVE_UNIT_INTERVAL: bool = true;
    const VARIES: bool = true;
    #[inline]
    fn coefficient(&self, u: Vec3, e: Vec3) -> Real {
        self.at_normal_speed(Self::normal_speed(u, e))
    }

    /// BRS (9): `1 - 2 beta_0 speed^delta`.
    #[inline]
    fn at_normal_speed(&self, speed: Real) -> Real {
        // Found by fuzzing: beta0 = 0 with an impact speed whose power overflows gave
        // 0 * inf = NaN (then clamped to e = 0) where the law says e = 1.
        if self.beta0 == 0.0 {
            return 1.0;
        }
        1.0 - 2.0 * self.beta0 * powf(speed, self.delta)
    }

    /// `1 - 2 beta_0 (scale s)^delta = 1 - 2 (beta_0 scale^delta) s^delta`: the law of
    /// `beta_0 scale^delta` (`pow(1, y) = 1` exactly, IEEE 754: `scale = 1` changes no bit).
    fn in_stored_units(&self, scale: Real) -> Self {
        ImpactSpeed {
            beta0: self.beta0 * powf(scale, self.delta),
            delta: self.delta,
        }
    }
}

/// The domain of a restitution coefficient `alpha` (GRW (3)): the words every message uses.
pub const ALPHA_RANGE: &str = "(0, 1]";

/// A restitution coefficient outside [`ALPHA_RANGE`] (the value given).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct AlphaError(pub Real);

impl core::fmt::Display for AlphaError {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        write!(
            f,
            "restitution coefficient alpha must lie in {ALPHA_RANGE}, got {}",
            self.0
        )
    }
}

impl core::error::Error for AlphaError {}

/// A constant restitution coefficient `alpha` in (0, 1] (GRW (3), BRS (9) with `delta = 0`).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Constant(Real);

impl Constant {
    /// The law of `alpha`, the rule of [`ALPHA_RANGE`] checked here and only here: `0 < alpha
    /// <= 1` (NaN refused).
    pub fn new(alpha: Real) -> Result<Self, AlphaError> {
        if alpha > 0.0 && alpha <= 1.0 {
            Ok(Constant(alpha))
        } else {
            Err(AlphaError(alpha))
        }
    }
    /// The coefficient.
    pub fn alpha(&self) -> Real {
        self.0
    }
}

impl Restitution for Constant {
    const CAN_LEAVE_UNIT_INTERVAL: bool = false;
    const VARIES: bool = false;
    #[inline(always)]
    fn coefficient(&self, _u: Vec3, _e: Vec3) -> Real {
        self.0
    }
    #[inline(always)]
    fn at_normal_speed(&self, _speed: Real) -> Real {
        self.0
    }
    #[inline(always)]
    fn in_stored_units(&self, _scale: Real) -> Self {
        *self
    }
}
