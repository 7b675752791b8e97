//! What acts on a rough gas between collisions: nothing (the cooling state) or white noise on
//! translation and on rotation, each of its own strength (the drives of the rough-gas DSMC of
//! Megías and Santos 2019; GRW (18) applied to each part).
//!
//! Translation: `v(t + dt) = v(t) + sqrt(2 beta dt) xi` (GRW (18)), so `dT_tr/dt = 2 beta`
//! from the noise alone. Rotation: the rim velocity `w` gets `sqrt(2 beta_rot dt / kappa) xi`
//! on each of its degrees of freedom (3 for spheres, 1 for disks), so that
//! `T_rot = kappa <|w|^2>/d_rot` grows at `dT_rot/dt = 2 beta_rot`: the two strengths put
//! the same energy per unit time into their part when they are equal. Both are exact for any
//! `dt` (the kick solves the heat equation of its part), so the lazy kicks of the no-splitting
//! loop keep it exact.

use crate::drive::NoDrive;
use crate::geometry::Geometry;
use crate::math::{Real, sqrt};
use crate::rng::Rng;
use crate::vec3::Vec3;

/// A drive of a rough gas: how `(v, w)` evolve over `dt` with no collision.
pub trait RoughDrive: Copy {
    /// False when nothing acts (the loop then skips the kicks and keeps every particle current).
    const ACTS: bool;

    /// `(v, w)` after `dt >= 0` of the drive alone, in dimension `G` (disks: noise in the plane
    /// and along the rim velocity's one axis, `z`).
    fn evolve<G: Geometry, R: Rng + ?Sized>(
        &self,
        v: Vec3,
        w: Vec3,
        dt: Real,
        rng: &mut R,
    ) -> (Vec3, Vec3);
}

impl RoughDrive for NoDrive {
    const ACTS: bool = false;

    #[inline(always)]
    fn evolve<G: Geometry, R: Rng + ?Sized>(
        &self,
        v: Vec3,
        w: Vec3,
        _dt: Real,
        _rng: &mut R,
    ) -> (Vec3, Vec3) {
        (v, w)
    }
}

/// White noise of strength `beta` on translation and `beta_rot` on rotation (module docs).
/// A zero strength draws nothing for its part.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct RoughNoise {
    /// `2 beta`: the variance rate of each translational component.
    tr: Real,
    /// `2 beta_rot / kappa`: the variance rate of each rim-velocity component.
    rot: Real,
}

impl RoughNoise {
    /// The noise of strengths `beta, beta_rot >= 0` on a gas of reduced moment of inertia
    /// `kappa > 0`; `None` when a strength is negative or a rate not finite.
    pub fn new(beta: Real, beta_rot: Real, kappa: Real) -> Option<Self> {
        let (tr, rot) = (2.0 * beta, 2.0 * beta_rot / kappa);
        let ok = |x: Real| x.is_finite() && x >= 0.0;
        (ok(tr) && ok(rot) && kappa > 0.0).then_some(RoughNoise { tr, rot })
    }

    /// `dT_tr/dt` from the noise: `2 beta`.
    pub fn heating_tr(&self) -> Real {
        self.tr
    }
}

impl RoughDrive for RoughNoise {
    const ACTS: bool = true;

    #[inline(always)]
    fn evolve<G: Geometry, R: Rng + ?Sized>(
        &self,
        mut v: Vec3,
        mut w: Vec3,
        dt: Real,
        rng: &mut R,
    ) -> (Vec3, Vec3) {
        if self.tr > 0.0 {
            v += sqrt(self.tr * dt) * G::normal(rng);
        }
        if self.rot > 0.0 {
            w += sqrt(self.rot * dt) * G::spin_normal(rng);
        }
        (v, w)
    }
}
