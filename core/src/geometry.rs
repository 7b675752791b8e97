//! The dimension `d` of velocity space, composed into the loops at compile time: spheres
//! (`d = 3`, every paper's setting) or disks (`d = 2`, the vibrated monolayers of the
//! granular-gas literature; van Noije and Ernst 1998 give the smooth gas for any `d`).
//!
//! Disks keep the one particle record: their velocities lie in the `(x, y)` plane with `z = 0`
//! exactly (every map, kick and sampler here keeps it so), and a rough disk's rim velocity
//! lies along `z` (its one rotational degree of freedom). What `d` changes:
//!
//! - the scattering direction `e` of GRW (3): uniform on S^{d-1} for the Maxwell and VHS
//!   kernels (isotropic scattering); for hard particles the reflection of `u_hat` at an impact
//!   direction with density proportional to `u_hat . n`, which is uniform in d = 3 but not in
//!   d = 2: there the impact parameter `b` is uniform on `(-1, 1)`, `n = sqrt(1 - b^2) u_hat +
//!   b u_perp` and `e = (2b^2 - 1) u_hat - 2b sqrt(1 - b^2) u_perp`; for the impact form of
//!   the inelastic Maxwell model the reflection at a uniform `n`, not uniform in d = 3 and
//!   uniform in d = 2 (the reflection doubles a uniform angle);
//! - the white-noise kick GRW (18) acts on `d` components;
//! - temperatures and cumulants count `d` degrees of freedom: `T = <|c|^2>/d`, MS (3)
//!   `a2 = <c^4>/(d(d+2) T^2) - 1` ([`crate::moments::Observables::of_dim`]).
//!
//! The kernels keep their total pair rate `int B de = 4 pi gamma C_lambda |u|^lambda` in both
//! dimensions (the time unit is set by the rate constant). A hard-disk gas of diameter `sigma`
//! at areal density `n_A` has `4 pi gamma C_1 = 2 sigma n_A` (the cross-section of disks is the
//! length `2 sigma`: they meet when the impact parameter lies in `(-sigma, sigma)`), hard
//! spheres at number density `n` have `4 pi gamma C_1 = pi sigma^2 n` (times Enskog's `chi`
//! for a dense gas, MS Section 3); `core/tests/disks.rs` counts the disks' collisions.

use crate::kernel::Kernel;
use crate::math::{Real, sqrt};
use crate::rng::{Rng, uniform01};
use crate::sample::{
    standard_normal, standard_normal_pair, standard_normal3, unit_circle, unit_sphere,
};
use crate::vec3::Vec3;

/// The choice of dimension as plain data (a front end's `dimension = 2`).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum DimensionChoice {
    /// Spheres, `d = 3`.
    #[default]
    Three,
    /// Disks, `d = 2`.
    Two,
}

impl DimensionChoice {
    /// `d` as a number.
    pub const fn d(self) -> usize {
        match self {
            DimensionChoice::Three => 3,
            DimensionChoice::Two => 2,
        }
    }

    /// Rotational degrees of freedom of a rough particle: 3 for spheres, 1 for disks.
    pub const fn spin_dof(self) -> usize {
        match self {
            DimensionChoice::Three => 3,
            DimensionChoice::Two => 1,
        }
    }
}

/// The dimension as a type: what the loops draw and how they count degrees of freedom
/// (module docs). Implemented by [`Spheres`] and [`Disks`].
pub trait Geometry: Copy + Default + core::fmt::Debug + PartialEq + 'static {
    /// The plain-data choice this type implements.
    const CHOICE: DimensionChoice;

    /// The scattering direction `e` of GRW (3) for a pair of relative velocity `u` under
    /// kernel `K` (module docs).
    fn scattering<K: Kernel, R: Rng + ?Sized>(u: Vec3, rng: &mut R) -> Vec3;

    /// The unit vector `n` from particle 1 to 2 at a hard-particle collision of relative
    /// velocity `u = v1 - v2`: density proportional to `u_hat . n` where the pair approaches
    /// (`u . n >= 0`), uniform when `u = 0`.
    fn impact<R: Rng + ?Sized>(u: Vec3, rng: &mut R) -> Vec3;

    /// A standard normal vector of velocity space (`z = 0` for disks): the white-noise kick's.
    fn normal<R: Rng + ?Sized>(rng: &mut R) -> Vec3;

    /// A direction uniform on the unit sphere of velocity space (the circle for disks): MS
    /// Section 3's candidate direction `s`.
    fn direction<R: Rng + ?Sized>(rng: &mut R) -> Vec3;

    /// `w` of MS Section 3's acceptance rate `omega_ij = w pi gamma C (u . s)` for `s` uniform
    /// ([`Geometry::direction`]), chosen so that averaged over `s` a pair collides at the
    /// no-splitting rate `4 pi gamma C |u|`: `E[max(0, u_hat . s)]` is 1/4 on the sphere and
    /// `1/pi` on the circle, so `w` = 16 for spheres (MS's `16 pi`) and `4 pi` for disks.
    const OMEGA_FACTOR: Real;

    /// A standard normal vector of the rim velocity's degrees of freedom (along `z` only for
    /// disks).
    fn spin_normal<R: Rng + ?Sized>(rng: &mut R) -> Vec3;
}

/// Spheres: `d = 3`.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Spheres;

/// Disks: `d = 2`, velocities in the `(x, y)` plane, rim velocities along `z`.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Disks;

impl Geometry for Spheres {
    const CHOICE: DimensionChoice = DimensionChoice::Three;
    const OMEGA_FACTOR: Real = 16.0;

    #[inline(always)]
    fn direction<R: Rng + ?Sized>(rng: &mut R) -> Vec3 {
        unit_sphere(rng)
    }

    #[inline(always)]
    fn scattering<K: Kernel, R: Rng + ?Sized>(u: Vec3, rng: &mut R) -> Vec3 {
        if K::UNIFORM_IMPACT {
            // The reflection of `u_hat` at a uniform impact direction (the impact form).
            return crate::collision::scattering_direction_from_impact(u, unit_sphere(rng));
        }
        unit_sphere(rng)
    }

    #[inline(always)]
    fn impact<R: Rng + ?Sized>(u: Vec3, rng: &mut R) -> Vec3 {
        crate::sample::impact_direction(u, rng)
    }

    #[inline(always)]
    fn normal<R: Rng + ?Sized>(rng: &mut R) -> Vec3 {
        standard_normal3(rng)
    }

    #[inline(always)]
    fn spin_normal<R: Rng + ?Sized>(rng: &mut R) -> Vec3 {
        standard_normal3(rng)
    }
}

/// `u_hat` and the in-plane unit vector `u_perp` a quarter turn from it, or `None` for `u = 0`
/// (scaled by the largest component first, so that a tiny `u` does not underflow).
#[inline(always)]
fn plane_frame(u: Vec3) -> Option<(Vec3, Vec3)> {
    let big = u.x.abs().max(u.y.abs());
    if big == 0.0 {
        return None;
    }
    let (x, y) = (u.x / big, u.y / big);
    let inv = 1.0 / sqrt(x * x + y * y);
    let (x, y) = (x * inv, y * inv);
    Some((Vec3::new(x, y, 0.0), Vec3::new(-y, x, 0.0)))
}

/// The impact parameter `b` uniform on `(-1, 1)` and `sqrt(1 - b^2)`.
#[inline(always)]
fn impact_parameter<R: Rng + ?Sized>(rng: &mut R) -> (Real, Real) {
    let b = 2.0 * uniform01(rng) - 1.0;
    (b, sqrt(1.0 - b * b))
}

impl Geometry for Disks {
    const CHOICE: DimensionChoice = DimensionChoice::Two;
    const OMEGA_FACTOR: Real = 4.0 * core::f64::consts::PI;

    #[inline(always)]
    fn direction<R: Rng + ?Sized>(rng: &mut R) -> Vec3 {
        unit_circle(rng)
    }

    #[inline(always)]
    fn scattering<K: Kernel, R: Rng + ?Sized>(u: Vec3, rng: &mut R) -> Vec3 {
        if !K::HARD {
            // Isotropic scattering; the impact form's reflection of `u_hat` at a uniform `n`
            // doubles a uniform angle, so its `e` is uniform too (module docs).
            return unit_circle(rng);
        }
        match plane_frame(u) {
            // A pair at rest collides trivially whatever e is.
            None => unit_circle(rng),
            Some((uh, up)) => {
                let (b, c) = impact_parameter(rng);
                (2.0 * b * b - 1.0) * uh - (2.0 * b * c) * up
            }
        }
    }

    #[inline(always)]
    fn impact<R: Rng + ?Sized>(u: Vec3, rng: &mut R) -> Vec3 {
        match plane_frame(u) {
            None => unit_circle(rng),
            Some((uh, up)) => {
                let (b, c) = impact_parameter(rng);
                c * uh + b * up
            }
        }
    }

    #[inline(always)]
    fn normal<R: Rng + ?Sized>(rng: &mut R) -> Vec3 {
        let (x, y) = standard_normal_pair(rng);
        Vec3::new(x, y, 0.0)
    }

    #[inline(always)]
    fn spin_normal<R: Rng + ?Sized>(rng: &mut R) -> Vec3 {
        Vec3::new(0.0, 0.0, standard_normal(rng))
    }
}
