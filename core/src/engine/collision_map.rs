//! The particle-model axis of the exact loops: what an accepted candidate pair does.
//!
//! - Smooth particles: every restitution law ([`Restitution`]) is a map: a scattering
//!   direction `e` ([`Geometry::scattering`]: uniform on the sphere, or the hard-disk law),
//!   the law's coefficient clamped to [0, 1] and GRW (3).
//! - Rough particles: [`crate::rough::RoughMap`] draws the impact direction
//!   ([`Geometry::impact`]) and applies the map of Huthmann and Zippelius (1997) to the
//!   velocities and the rim velocities (the spins beside the particles).
//!
//! The loops ([`super::NoSplitting`]) are written once over this trait: whether the particles
//! carry spins ([`CollisionMap::SPINS`]) is a constant in each leaf, so a smooth gas compiles
//! no spin check, rescale or observable.

use super::Counts;
use crate::collision::{inelastic, scattering_direction_from_impact};
use crate::geometry::{DimensionChoice, Geometry};
use crate::kernel::Kernel;
use crate::math::Real;
use crate::observe::RoughObservables;
use crate::particles::Particles;
use crate::restitution::Restitution;
use crate::rng::Rng;
use crate::vec3::Vec3;

/// What a collision does to an accepted pair: the particle model (module docs).
pub trait CollisionMap: Copy + core::fmt::Debug {
    /// Whether the particles carry rim velocities (a rough gas): the loops then need a spin
    /// buffer, check the spins' finiteness and rescale them with the velocities.
    const SPINS: bool;

    /// Collides the `pair` `(i, j)` of `velocities` `(vi, vj)` (at the event time) under kernel `K`
    /// in dimension `G`: draws the direction, writes the new velocities (and spins) into `p`,
    /// counts a clamped coefficient, and returns the new velocities (the majorant covers them).
    fn collide_pair<K: Kernel, G: Geometry, R: Rng + ?Sized>(
        &self,
        p: &mut Particles<'_>,
        pair: (usize, usize),
        velocities: (Vec3, Vec3),
        rng: &mut R,
        counts: &mut Counts,
    ) -> (Vec3, Vec3);

    /// Collides the `pair` `(i, j)` of `velocities` `(vi, vj)` at the impact direction `n`
    /// (the unit vector from `i` to `j`, `(vi - vj) . n > 0`) that the caller drew: MS's
    /// time-stepped scheme draws it itself (MS Section 3). Writes the new velocities (and
    /// spins), counts a clamped coefficient, returns the new velocities.
    fn collide_at_impact(
        &self,
        p: &mut Particles<'_>,
        pair: (usize, usize),
        velocities: (Vec3, Vec3),
        n: Vec3,
        counts: &mut Counts,
    ) -> (Vec3, Vec3);

    /// The same map for velocities stored in new units, `scale` times which are the ones this
    /// map takes (a cooling gas stored rescaled, [`super::frame`]): its restitution law's
    /// [`Restitution::in_stored_units`], so that an impact-speed law keeps taking the physical
    /// impact speed.
    #[must_use]
    fn stored_map(&self, scale: Real) -> Self;

    /// The rotational observables of `p` (stored with rim velocities `w_phys = scale w`) in
    /// dimension `dim`; `None` for smooth particles.
    fn rough(
        &self,
        _p: &Particles<'_>,
        _scale: crate::math::Real,
        _dim: DimensionChoice,
    ) -> Option<RoughObservables> {
        None
    }
}

impl<A: Restitution> CollisionMap for A {
    const SPINS: bool = false;

    /// GRW (3) with the scattering direction of `G` and the law's clamped coefficient.
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
        collide_along(self, p, (i, j), (vi, vj), e, counts)
    }

    /// GRW (3) with the scattering direction of the impact `n`
    /// ([`scattering_direction_from_impact`]: MS's impact map `v_{1,2} -/+ (1 + alpha)/2
    /// (u . n) n`).
    #[inline(always)]
    fn collide_at_impact(
        &self,
        p: &mut Particles<'_>,
        (i, j): (usize, usize),
        (vi, vj): (Vec3, Vec3),
        n: Vec3,
        counts: &mut Counts,
    ) -> (Vec3, Vec3) {
        let e = scattering_direction_from_impact(vi - vj, n);
        collide_along(self, p, (i, j), (vi, vj), e, counts)
    }

    #[inline(always)]
    fn stored_map(&self, scale: Real) -> Self {
        self.in_stored_units(scale)
    }
}

/// The reduced moment of inertia `kappa = 4 I / (m sigma^2)` of a one-species map's particles
/// (0 for smooth particles): the rotational energy `kappa |w|^2 / 2` per unit mass of a rim
/// velocity `w` ([`crate::observe::cooling`] weighs the spins' energy by it).
pub trait Inertia {
    /// `kappa`; 0 for smooth particles.
    fn kappa(&self) -> Real;
}

impl<A: Restitution> Inertia for A {
    /// Smooth particles carry no rotational energy.
    fn kappa(&self) -> Real {
        0.0
    }
}

/// The cooling of a one-species gas `p` (velocities stored at `scale` times the physical
/// ones) under kernel `K`, map `map` and dimension `G`, from `pairs` random pairs
/// ([`crate::observe::cooling::estimate`]: unit masses, the map's `kappa`).
pub(crate) fn one_species_cooling<K: Kernel, G: Geometry, A, R: Rng + ?Sized>(
    (kernel, map, scale): (&K, &A, Real),
    p: &Particles<'_>,
    pairs: u64,
    rng: &mut R,
) -> crate::observe::Cooling
where
    A: CollisionMap + Inertia,
{
    let kappa = map.kappa();
    crate::observe::cooling::estimate(
        p,
        pairs,
        rng,
        |_| (1.0, kappa),
        |_, s: &mut Particles<'_>, rng: &mut R| {
            let (vi, vj) = (s.velocity(0), s.velocity(1));
            map.collide_pair::<K, G, R>(s, (0, 1), (vi, vj), rng, &mut Counts::default());
            kernel.pair_rate(scale * (vi - vj).norm())
        },
    )
}

/// GRW (3) for the pair `(i, j)` of velocities `(vi, vj)` with scattering direction `e` and the
/// law's clamped coefficient: writes and returns the new velocities.
#[inline(always)]
fn collide_along<A: Restitution>(
    law: &A,
    p: &mut Particles<'_>,
    (i, j): (usize, usize),
    (vi, vj): (Vec3, Vec3),
    e: Vec3,
    counts: &mut Counts,
) -> (Vec3, Vec3) {
    let alpha = clamped_coefficient(law, vi - vj, e, counts);
    let (a, b) = inelastic(vi, vj, e, alpha);
    p.set_velocity(i, a);
    p.set_velocity(j, b);
    (a, b)
}

/// The restitution coefficient of a law, clamped to [0, 1] (counted in
/// [`Counts::clamped`] when it had to be).
#[inline(always)]
pub fn clamped_coefficient<A: Restitution>(a: &A, u: Vec3, e: Vec3, counts: &mut Counts) -> Real {
    clamped::<A>(a.coefficient(u, e), counts)
}

/// The restitution coefficient of a law at the normal impact speed `|g . n| = speed`
/// ([`Restitution::at_normal_speed`]), clamped to [0, 1] and counted as
/// [`clamped_coefficient`] does.
#[inline(always)]
pub fn clamped_at_normal_speed<A: Restitution>(a: &A, speed: Real, counts: &mut Counts) -> Real {
    clamped::<A>(a.at_normal_speed(speed), counts)
}

/// `alpha`, a coefficient of law `A`, clamped to [0, 1] and counted when it had to be.
#[inline(always)]
fn clamped<A: Restitution>(alpha: Real, counts: &mut Counts) -> Real {
    if A::CAN_LEAVE_UNIT_INTERVAL && !(0.0..=1.0).contains(&alpha) {
        counts.clamped += 1;
        return if alpha > 1.0 { 1.0 } else { 0.0 };
    }
    alpha
}
