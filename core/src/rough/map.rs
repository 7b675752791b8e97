//! The collision of two rough spheres of equal mass `m`, diameter `sigma` and moment of
//! inertia `I = kappa m sigma^2 / 4` (Huthmann and Zippelius 1997; Luding et al. 1998).
//!
//! Angular velocities are kept as rim velocities `w = (sigma/2) omega` (velocity units, so the
//! diameter drops out). With `n` the unit vector from the centre of particle 1 to that of 2 at
//! contact, the contact points' relative velocity is
//!
//! ```text
//! g = v1 - v2 + (w1 + w2) x n,      g_n = (g . n) n,   g_t = g - g_n,
//! ```
//!
//! and the collision reverses and shrinks its components, `g_n' = -alpha g_n`,
//! `g_t' = -beta g_t` (`0 < alpha <= 1`, `-1 <= beta <= 1`). The impulse `J = m dv1 = -m dv2`
//! that does it, with the torques `I d omega_i = (sigma/2) n x J` on both particles:
//!
//! ```text
//! dv1 = -dv2 = -eta_n g_n - eta_t g_t,       eta_n = (1 + alpha)/2,
//! dw1 =  dw2 = (n x dv1) / kappa,            eta_t = (1 + beta)/2 kappa/(1 + kappa).
//! ```
//!
//! Computed as `dw = -(eta_t / kappa) n x g_t` with `eta_t / kappa = (1 + beta)/(2 (1 + kappa))`:
//! `n x g_n = 0` exactly, but not in floating point, and dividing its rounding residue by a
//! small kappa blew the spins up (found by the `rough_maps` fuzz target at kappa = 8e-308).
//!
//! Linear momentum is kept, and the angular momentum about the contact point; the energy
//! `E = (m/2) sum (|v|^2 + kappa |w|^2)` changes by
//! `-(m/4) [(1 - alpha^2) |g_n|^2 + (1 - beta^2) kappa/(1 + kappa) |g_t|^2]`
//! (Huthmann and Zippelius 1997, in these variables). `beta = -1` leaves the rotation alone
//! (smooth spheres: GRW (3) with the impact direction, MS (56)); `alpha = beta = 1` keeps the
//! energy (perfectly rough elastic spheres).
//!
//! ```
//! use gdsmc_core::{rough::RoughMap, vec3::Vec3};
//! let map = RoughMap::new(0.9, 0.5, 0.4).unwrap(); // kappa = 2/5: uniform spheres
//! let (v1, w1) = (Vec3::new(1.0, 0.2, 0.0), Vec3::new(0.0, 0.0, 0.3));
//! let (v2, w2) = (Vec3::new(-1.0, 0.0, 0.1), Vec3::ZERO);
//! let n = Vec3::new(-1.0, 0.0, 0.0); // 2 is behind 1 along x: they approach
//! let (a1, b1, a2, b2) = map.collide(v1, w1, v2, w2, n);
//! assert!(((a1 + a2) - (v1 + v2)).norm() < 1e-15); // momentum kept
//! ```

use super::RoughObservables;
use crate::engine::Counts;
use crate::engine::collision_map::clamped_at_normal_speed;
use crate::geometry::{DimensionChoice, Geometry};
use crate::math::{Real, abs};
use crate::particles::Particles;
use crate::restitution::{Constant, Restitution};
use crate::rng::Rng;
use crate::vec3::Vec3;

/// A rough-sphere parameter out of its domain.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum RoughError {
    /// The normal restitution is not in (0, 1].
    Alpha,
    /// The tangential restitution is not in [-1, 1].
    Beta,
    /// The reduced moment of inertia is not in (0, 2/3] (2/5: uniform spheres; 2/3: a
    /// hollow shell, the largest a sphere can have).
    Kappa,
    /// The reduced moment of inertia of a disk is not in (0, 1] (1/2: uniform disks; 1: a
    /// ring, the largest a disk can have).
    DiskKappa,
}

impl core::fmt::Display for RoughError {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        f.write_str(match self {
            RoughError::Alpha => {
                return write!(
                    f,
                    "normal restitution alpha must lie in {}",
                    crate::restitution::ALPHA_RANGE
                );
            }
            RoughError::Beta => "tangential restitution beta must lie in [-1, 1]",
            RoughError::Kappa => "reduced moment of inertia kappa must lie in (0, 2/3]",
            RoughError::DiskKappa => "reduced moment of inertia kappa of disks must lie in (0, 1]",
        })
    }
}

impl core::error::Error for RoughError {}

/// The collision map of rough spheres with normal restitution law `A` (a constant `alpha`, or
/// BRS (9) at the normal impact speed `|g . n|`), tangential restitution `beta` and inertia
/// `kappa`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct RoughMap<A = Constant> {
    /// The normal restitution as the smooth law (the `beta = -1` collision's; one rule for its
    /// range).
    law: A,
    beta: Real,
    kappa: Real,
    /// `(1 + alpha)/2` of a constant law (unused when the law varies).
    eta_n: Real,
    eta_t: Real,
    /// `eta_t / kappa = (1 + beta) / (2 (1 + kappa))`.
    eta_w: Real,
}

impl RoughMap<Constant> {
    /// The map for `0 < alpha <= 1`, `-1 <= beta <= 1`, `0 < kappa <= 2/3`.
    pub fn new(alpha: Real, beta: Real, kappa: Real) -> Result<Self, RoughError> {
        Self::checked(alpha, beta, kappa, 2.0 / 3.0, RoughError::Kappa)
    }

    /// The map of rough disks (`d = 2`: velocities in the plane, rim velocities along `z`, the
    /// same formulas), `0 < kappa <= 1` (1/2: uniform disks).
    pub fn for_disks(alpha: Real, beta: Real, kappa: Real) -> Result<Self, RoughError> {
        Self::checked(alpha, beta, kappa, 1.0, RoughError::DiskKappa)
    }

    fn checked(
        alpha: Real,
        beta: Real,
        kappa: Real,
        max_kappa: Real,
        bad_kappa: RoughError,
    ) -> Result<Self, RoughError> {
        // The restitution's one rule.
        let law = Constant::new(alpha).map_err(|_| RoughError::Alpha)?;
        if !(-1.0..=1.0).contains(&beta) {
            return Err(RoughError::Beta);
        }
        if !(kappa > 0.0 && kappa <= max_kappa) {
            return Err(bad_kappa);
        }
        Ok(RoughMap {
            law,
            beta,
            kappa,
            eta_n: 0.5 * (1.0 + alpha),
            eta_t: spin_transfer(beta, kappa),
            eta_w: 0.5 * (1.0 + beta) / (1.0 + kappa),
        })
    }

    /// The normal restitution `alpha`.
    pub fn alpha(&self) -> Real {
        self.law.alpha()
    }

    /// `alpha` as the smooth restitution law.
    pub fn smooth(&self) -> Constant {
        self.law
    }

    /// The contact points' relative velocity `g = v1 - v2 + (w1 + w2) x n`.
    #[inline(always)]
    pub fn contact_velocity(v1: Vec3, w1: Vec3, v2: Vec3, w2: Vec3, n: Vec3) -> Vec3 {
        v1 - v2 + (w1 + w2).cross(n)
    }
}

impl<A: Restitution> RoughMap<A> {
    /// The same map with the normal restitution law `law` in place of this one's (`beta` and
    /// `kappa` kept, with their rules already checked; a law's own rules are its constructor's).
    #[must_use]
    pub fn with_law<B: Restitution>(&self, law: B) -> RoughMap<B> {
        RoughMap {
            law,
            beta: self.beta,
            kappa: self.kappa,
            // A constant law's coefficient at any speed.
            eta_n: 0.5 * (1.0 + law.at_normal_speed(0.0)),
            eta_t: self.eta_t,
            eta_w: self.eta_w,
        }
    }

    /// The normal restitution law.
    pub fn law(&self) -> A {
        self.law
    }

    /// The spin-transfer coefficients `(eta_t, eta_t / kappa)` (module docs).
    pub(crate) fn spin_transfer(&self) -> (Real, Real) {
        (self.eta_t, self.eta_w)
    }

    /// The tangential restitution `beta`.
    pub fn beta(&self) -> Real {
        self.beta
    }

    /// The reduced moment of inertia `kappa = 4 I / (m sigma^2)`.
    pub fn kappa(&self) -> Real {
        self.kappa
    }

    /// Post-collisional `(v1', w1', v2', w2')` for the unit vector `n` from 1 to 2 (module
    /// docs); `alpha` is the law's at `|g . n|`, clamped to [0, 1]. With `beta = -1` the rim
    /// velocities are returned unchanged, bit for bit.
    #[inline(always)]
    pub fn collide(
        &self,
        v1: Vec3,
        w1: Vec3,
        v2: Vec3,
        w2: Vec3,
        n: Vec3,
    ) -> (Vec3, Vec3, Vec3, Vec3) {
        self.collide_counting(v1, w1, v2, w2, n, &mut Counts::default())
    }

    /// As [`RoughMap::collide`], counting a clamped coefficient in `counts`
    /// ([`Counts::clamped`]).
    #[inline(always)]
    pub fn collide_counting(
        &self,
        v1: Vec3,
        w1: Vec3,
        v2: Vec3,
        w2: Vec3,
        n: Vec3,
        counts: &mut Counts,
    ) -> (Vec3, Vec3, Vec3, Vec3) {
        // Equal partners share one impulse: computed once (the general [`impulse`] gives the
        // same bits with two, 1.4% more instructions per collision on the Cortex-M4F).
        let g = RoughMap::contact_velocity(v1, w1, v2, w2, n);
        let c = g.dot(n);
        let gn = c * n;
        let gt = g - gn;
        // The normal part of `g` is that of `v1 - v2`: the spins add only a tangential one.
        let eta_n = if A::VARIES {
            0.5 * (1.0 + clamped_at_normal_speed(&self.law, abs(c), counts))
        } else {
            self.eta_n
        };
        let dv = -(eta_n * gn) - self.eta_t * gt;
        if self.eta_t == 0.0 {
            return (v1 + dv, w1, v2 - dv, w2);
        }
        let dw = -self.eta_w * n.cross(gt);
        (v1 + dv, w1 + dw, v2 - dv, w2 + dw)
    }

    /// The energy change `-(1/4) [(1 - alpha^2) |g_n|^2 + (1 - beta^2) kappa/(1 + kappa)
    /// |g_t|^2]` of `sum (|v|^2 + kappa |w|^2)/2` per unit mass (module docs), `alpha` the
    /// law's at `|g . n|`, clamped.
    pub fn energy_change(&self, g: Vec3, n: Vec3) -> Real {
        let c = g.dot(n);
        let gn2 = c * c;
        let alpha = clamped_at_normal_speed(&self.law, abs(c), &mut Counts::default());
        let gt2 = (g.norm2() - gn2).max(0.0);
        -0.25
            * ((1.0 - alpha * alpha) * gn2
                + (1.0 - self.beta * self.beta) * self.kappa / (1.0 + self.kappa) * gt2)
    }
}

/// The collision of two rough particles with the coefficients `(a_1, a_2)` of each partner's
/// normal change, given by `normal` from `g . n` (the normal restitution may depend on it), and
/// `[(t_1, t_2), (c_1, c_2)]` of each partner's tangential and spin change: `dv1 = -a_1 g_n -
/// t_1 g_t`, `dv2 = a_2 g_n + t_2 g_t`, `dw_i = -c_i n x g_t` (equal partners: this module's
/// `eta_n`, `eta_t`, `eta_t / kappa`; unequal: [`super::pair`]). No spin change when both
/// `c_i` are 0 (`beta = -1`), bit for bit.
#[inline(always)]
pub(crate) fn impulse(
    (v1, w1, v2, w2): (Vec3, Vec3, Vec3, Vec3),
    n: Vec3,
    normal: impl FnOnce(Real) -> (Real, Real),
    [tangential, spin]: [(Real, Real); 2],
) -> (Vec3, Vec3, Vec3, Vec3) {
    let g = RoughMap::contact_velocity(v1, w1, v2, w2, n);
    let c = g.dot(n);
    let gn = c * n;
    let gt = g - gn;
    let normal = normal(c);
    let dv1 = -(normal.0 * gn) - tangential.0 * gt;
    let dv2 = normal.1 * gn + tangential.1 * gt;
    if spin.0 == 0.0 && spin.1 == 0.0 {
        return (v1 + dv1, w1, v2 + dv2, w2);
    }
    let nt = n.cross(gt);
    (v1 + dv1, w1 - spin.0 * nt, v2 + dv2, w2 - spin.1 * nt)
}

/// Writes a rough collision's `(v1', w1', v2', w2')` into particles `(i, j)` of `p` and returns
/// the new velocities (what [`crate::engine::CollisionMap`]'s methods return).
#[inline(always)]
pub(crate) fn store(
    p: &mut Particles<'_>,
    (i, j): (usize, usize),
    (a, wa, b, wb): (Vec3, Vec3, Vec3, Vec3),
) -> (Vec3, Vec3) {
    p.set_velocity(i, a);
    p.set_spin(i, wa);
    p.set_velocity(j, b);
    p.set_spin(j, wb);
    (a, b)
}

/// Whether a rough pair whose spin transfer is `eta_t` collides as smooth particles: `beta =
/// -1` leaves the rotation alone (`eta_t = 0`), and the smooth collision of the scattering form
/// (GRW (3)) is then the impact form's in distribution ([`impact_direction`] draws `n` through
/// that very `e`), so the smooth loop's code collides the pair and a rough gas with `beta = -1`
/// has the smooth gas's bits. Not for pseudo-Maxwell disks: their smooth scattering is
/// isotropic, while rough disks of any kernel collide with the hard-disk impact law.
#[inline(always)]
pub(crate) fn smooth_limit<K: crate::kernel::Kernel, G: Geometry>(eta_t: Real) -> bool {
    collides_smooth(K::HARD, G::CHOICE, eta_t)
}

/// The impact direction of a rough pair of relative velocity `u` under kernel `K`: the
/// hard-particle impact law ([`Geometry::impact`], density proportional to `u_hat . n`) for
/// every kernel but the inelastic Maxwell model's impact form, whose `n` is uniform
/// ([`crate::kernel::MaxwellImpact`]; turned to face the approach, `u . n >= 0`).
#[inline(always)]
pub(crate) fn impact_of<K: crate::kernel::Kernel, G: Geometry, R: Rng + ?Sized>(
    u: Vec3,
    rng: &mut R,
) -> Vec3 {
    if K::UNIFORM_IMPACT {
        let n = G::direction(rng);
        return if u.dot(n) < 0.0 { -n } else { n };
    }
    G::impact(u, rng)
}

/// The rule of the engine's `smooth_limit` for a kernel that is `hard` (hard spheres or disks) in
/// `dimension`: the one statement of where a rough gas's translation is the smooth gas's, for
/// the engine (above, at compile time) and for whatever must know it at run time (a reference
/// of the smooth gas holds for a rough gas exactly here: `Physics::translation_is_smooth`).
#[inline(always)]
#[must_use]
pub const fn collides_smooth(hard: bool, dimension: DimensionChoice, eta_t: Real) -> bool {
    eta_t == 0.0 && (hard || matches!(dimension, DimensionChoice::Three))
}

/// The spin transfer `eta_t = (1 + beta)/2 kappa/(1 + kappa)` of tangential restitution `beta`
/// and reduced moment of inertia `kappa` (module docs; Huthmann and Zippelius 1997): 0 exactly
/// when `beta = -1`.
#[inline(always)]
#[must_use]
pub fn spin_transfer(beta: Real, kappa: Real) -> Real {
    0.5 * (1.0 + beta) * kappa / (1.0 + kappa)
}

impl<A: Restitution> crate::engine::collision_map::Inertia for RoughMap<A> {
    /// The particles' `kappa`.
    fn kappa(&self) -> Real {
        self.kappa
    }
}

impl<A: Restitution> crate::engine::CollisionMap for RoughMap<A> {
    const SPINS: bool = true;

    /// The normal restitution law's [`Restitution::in_stored_units`].
    #[inline(always)]
    fn stored_map(&self, scale: Real) -> Self {
        RoughMap {
            law: self.law.in_stored_units(scale),
            ..*self
        }
    }

    /// The impact direction of `K` and `G` (`impact_of`) and [`RoughMap::collide`] on the
    /// velocities and rim velocities; with `beta = -1` the smooth collision itself
    /// (`smooth_limit`).
    #[inline(always)]
    fn collide_pair<K: crate::kernel::Kernel, G: Geometry, R: Rng + ?Sized>(
        &self,
        p: &mut Particles<'_>,
        (i, j): (usize, usize),
        (vi, vj): (Vec3, Vec3),
        rng: &mut R,
        counts: &mut crate::engine::Counts,
    ) -> (Vec3, Vec3) {
        if smooth_limit::<K, G>(self.eta_t) {
            return self
                .law
                .collide_pair::<K, G, R>(p, (i, j), (vi, vj), rng, counts);
        }
        let nrm = impact_of::<K, G, R>(vi - vj, rng);
        let after = self.collide_counting(vi, p.spin(i), vj, p.spin(j), nrm, counts);
        store(p, (i, j), after)
    }

    /// At the impact `n` drawn by the caller (MS's time-stepped scheme); with `beta = -1` the
    /// smooth collision's own code at that impact, so the rough gas has the smooth gas's bits.
    #[inline(always)]
    fn collide_at_impact(
        &self,
        p: &mut Particles<'_>,
        (i, j): (usize, usize),
        (vi, vj): (Vec3, Vec3),
        n: Vec3,
        counts: &mut crate::engine::Counts,
    ) -> (Vec3, Vec3) {
        if self.eta_t == 0.0 {
            return self.law.collide_at_impact(p, (i, j), (vi, vj), n, counts);
        }
        let after = self.collide_counting(vi, p.spin(i), vj, p.spin(j), n, counts);
        store(p, (i, j), after)
    }

    fn rough(
        &self,
        p: &Particles<'_>,
        scale: Real,
        dim: DimensionChoice,
    ) -> Option<RoughObservables> {
        Some(RoughObservables::of_dim(p, self.kappa, scale, dim))
    }
}
