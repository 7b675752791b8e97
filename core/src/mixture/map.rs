//! The inelastic collision of particles of masses `m_s`, `m_t`: GRW (3) in the centre-of-mass
//! frame. The relative velocity `u = v - w` becomes
//!
//! ```text
//! u' = (1 - alpha)/2 u + (1 + alpha)/2 |u| e,         |e| = 1,
//! v' = v - mu_t D,   w' = w + mu_s D,                 D = u - u' = (1 + alpha)/2 (u - |u| e),
//! ```
//!
//! with `mu_s = m_s / (m_s + m_t)`, `mu_t = m_t / (m_s + m_t)`: momentum `m_s v + m_t w` is
//! kept, and for equal masses this is GRW (3) itself (then [`fn@inelastic`] is used, so a
//! one-species mixture has the one-species bits). With `e = u_hat - 2 (u_hat . s) s` it is the
//! impact form `v' = v - mu_t (1 + alpha) (u . s) s` of inelastic hard-sphere mixtures
//! (Garzó and Dufty 1999, (2)), as [`crate::collision::scattering_direction_from_impact`]
//! shows for one species.
//!
//! ```
//! use gdsmc_core::{mixture::MassRatio, vec3::Vec3};
//! let m = MassRatio::new(1.0, 3.0);
//! let (v, w) = (Vec3::new(1.0, 0.0, 0.0), Vec3::new(-1.0, 0.0, 0.0));
//! let (v1, w1) = m.collide(v, w, Vec3::new(0.0, 1.0, 0.0), 0.5);
//! let p = (1.0 * v1 + 3.0 * w1) - (1.0 * v + 3.0 * w);
//! assert!(p.norm() < 1e-15); // momentum kept
//! ```

use crate::collision::inelastic;
use crate::engine::Counts;
use crate::engine::collision_map::{CollisionMap, clamped_coefficient};
use crate::geometry::Geometry;
use crate::kernel::Kernel;
use crate::math::Real;
use crate::particles::Particles;
use crate::restitution::Restitution;
use crate::rng::Rng;
use crate::vec3::Vec3;

/// The particle model of a mixture's pair type: what it becomes between partners of masses
/// `m_s` and `m_t` (the masses live in [`super::Species`], once). Every restitution law is one
/// ([`MassMap`]: smooth particles); rough particles: [`crate::rough::RoughPairLaw`].
pub trait PairLaw: Copy + core::fmt::Debug {
    /// The collision map of the pair type.
    type Map: CollisionMap + core::fmt::Debug;

    /// The map between partners of masses `m_s` (first) and `m_t` (second).
    fn between(&self, m_s: Real, m_t: Real) -> Self::Map;

    /// The partners' reduced moments of inertia `(kappa_1, kappa_2)` of a law with spins (a
    /// mixture's per-species rotational temperatures read them); `(0, 0)` for smooth particles.
    fn inertia(&self) -> (Real, Real) {
        (0.0, 0.0)
    }
}

impl<A: Restitution + core::fmt::Debug> PairLaw for A {
    type Map = MassMap<A>;

    fn between(&self, m_s: Real, m_t: Real) -> MassMap<A> {
        MassMap {
            law: *self,
            masses: MassRatio::new(m_s, m_t),
        }
    }
}

/// Smooth particles of two masses: a restitution law and the pair's [`MassRatio`].
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct MassMap<A> {
    /// The restitution law of the pair.
    pub law: A,
    /// The partners' mass fractions.
    pub masses: MassRatio,
}

impl<A: Restitution> MassMap<A> {
    /// [`MassRatio::collide`] of the pair `(i, j)` with scattering direction `e` and the law's
    /// clamped coefficient: writes and returns the new velocities.
    #[inline(always)]
    fn collide_along(
        &self,
        p: &mut Particles<'_>,
        (i, j): (usize, usize),
        (vi, vj): (Vec3, Vec3),
        e: Vec3,
        counts: &mut Counts,
    ) -> (Vec3, Vec3) {
        let alpha = clamped_coefficient(&self.law, vi - vj, e, counts);
        let (a, b) = self.masses.collide(vi, vj, e, alpha);
        p.set_velocity(i, a);
        p.set_velocity(j, b);
        (a, b)
    }
}

impl<A: Restitution> CollisionMap for MassMap<A> {
    const SPINS: bool = false;

    /// The restitution law's [`Restitution::in_stored_units`].
    #[inline(always)]
    fn stored_map(&self, scale: Real) -> Self {
        MassMap {
            law: self.law.in_stored_units(scale),
            ..*self
        }
    }

    /// The scattering direction of `G`, the law's clamped coefficient and
    /// [`MassRatio::collide`] (GRW (3) in the centre-of-mass frame; module docs).
    #[inline(always)]
    fn collide_pair<K: Kernel, G: Geometry, R: Rng + ?Sized>(
        &self,
        p: &mut Particles<'_>,
        (i, j): (usize, usize),
        (vi, vj): (Vec3, Vec3),
        rng: &mut R,
        counts: &mut Counts,
    ) -> (Vec3, Vec3) {
        let e = G::scattering::<K, R>(vi - vj, rng);
        self.collide_along(p, (i, j), (vi, vj), e, counts)
    }

    /// [`MassRatio::collide`] with the scattering direction of the impact `n`.
    #[inline(always)]
    fn collide_at_impact(
        &self,
        p: &mut Particles<'_>,
        (i, j): (usize, usize),
        (vi, vj): (Vec3, Vec3),
        n: Vec3,
        counts: &mut Counts,
    ) -> (Vec3, Vec3) {
        let e = crate::collision::scattering_direction_from_impact(vi - vj, n);
        self.collide_along(p, (i, j), (vi, vj), e, counts)
    }
}

/// The mass fractions of one pair type: `mu_s = m_s / (m_s + m_t)` and `mu_t`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct MassRatio {
    /// `mu_s = m_s / (m_s + m_t)`: the share of `D` the second partner takes.
    pub mu_s: Real,
    /// `mu_t = m_t / (m_s + m_t)`: the share of `D` the first partner takes.
    pub mu_t: Real,
    /// `m_s m_t / (m_s + m_t)`, the reduced mass.
    pub reduced: Real,
    equal: bool,
}

impl MassRatio {
    /// The pair of masses `m_s` (first partner) and `m_t` (second).
    pub fn new(m_s: Real, m_t: Real) -> Self {
        let total = m_s + m_t;
        MassRatio {
            mu_s: m_s / total,
            mu_t: m_t / total,
            reduced: m_s * m_t / total,
            equal: m_s == m_t,
        }
    }

    /// Post-collisional velocities `(v', w')` of the partners (masses `m_s`, `m_t`) with
    /// scattering direction `e` and restitution `alpha` (module docs).
    #[inline(always)]
    pub fn collide(&self, v: Vec3, w: Vec3, e: Vec3, alpha: Real) -> (Vec3, Vec3) {
        if self.equal {
            return inelastic(v, w, e, alpha);
        }
        let u = v - w;
        let d = (0.5 * (1.0 + alpha)) * (u - u.norm() * e);
        (v - self.mu_t * d, w + self.mu_s * d)
    }

    /// The change of `m_s |v|^2 + m_t |w|^2` in the collision:
    /// `-m_st (1 - alpha^2)/2 (|u|^2 - |u| (u . e))` with the reduced mass `m_st` (the
    /// relative kinetic energy `m_st |u|^2 / 2` loses the fraction GRW (Section 1, after (14))
    /// gives for one species).
    pub fn energy_change(&self, u: Vec3, e: Vec3, alpha: Real) -> Real {
        -self.reduced * (1.0 - alpha * alpha) / 2.0 * (u.norm2() - u.norm() * u.dot(e))
    }
}
