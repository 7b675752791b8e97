//! The collision of two rough particles of different species: masses `m_1`, `m_2`, reduced
//! moments of inertia `kappa_1`, `kappa_2` (`I_i = kappa_i m_i sigma_i^2 / 4`), one normal and
//! one tangential restitution for the pair (Santos, Kremer and Garzó 2010, Section 2; the
//! binary form of Huthmann and Zippelius 1997, [`super::map`]).
//!
//! In rim velocities `w_i = (sigma_i/2) omega_i` the diameters drop out, and the contact
//! velocity is `g = v1 - v2 + (w1 + w2) x n` as for one species. The impulse `J = m_1 dv1 =
//! -m_2 dv2` with the torques `I_i d omega_i = (sigma_i/2) n x J` changes it by
//! `dg_n = J_n / mu` and `dg_t = J_t D`, `mu = m_1 m_2/(m_1 + m_2)`,
//! `D = 1/mu + 1/(kappa_1 m_1) + 1/(kappa_2 m_2)`. Asking `g_n' = -alpha g_n`,
//! `g_t' = -beta g_t`:
//!
//! ```text
//! dv1 = -(1 + alpha) mu_2 g_n - kappa_1 c_1 g_t,    dw1 = -c_1 n x g_t,   mu_2 = m_2/(m_1 + m_2),
//! dv2 =  (1 + alpha) mu_1 g_n + kappa_2 c_2 g_t,    dw2 = -c_2 n x g_t,
//! c_i = (1 + beta) / (kappa_i m_i D) = (1 + beta) / (1 + kappa_i m_i/mu + kappa_i m_i/(kappa_j m_j)).
//! ```
//!
//! Momentum `m_1 v1 + m_2 v2` is kept, and the energy `sum m_i (|v_i|^2 + kappa_i |w_i|^2)/2`
//! when `alpha = beta = 1`. For equal masses and inertia `c_i` is [`RoughMap`]'s `eta_t/kappa`
//! and `kappa c_i` its `eta_t`: such a pair takes [`RoughMap`]'s own coefficients, and the
//! same operations give [`RoughMap::collide`]'s bits, so a one-species rough mixture has the
//! one-species rough gas's bits. `c_i` is computed in the
//! form above, finite for any kappa (no division of a rounding residue by a small kappa; see
//! [`super::map`]).
//!
//! ```
//! use gdsmc_core::{rough::RoughPairLaw, mixture::PairLaw, vec3::Vec3};
//! let law = RoughPairLaw::new(1.0, 1.0, 0.4, 0.2).unwrap(); // elastic, perfectly rough
//! let map = law.between(1.0, 3.0);
//! let (v1, w1, v2, w2) = (Vec3::new(1.0, 0.2, 0.0), Vec3::new(0.0, 0.0, 0.3),
//!                         Vec3::new(-1.0, 0.0, 0.1), Vec3::new(0.1, 0.0, 0.0));
//! let (a1, b1, a2, b2) = map.collide(v1, w1, v2, w2, Vec3::new(-1.0, 0.0, 0.0));
//! let e = |v: Vec3, w: Vec3, m: f64, k: f64| m * (v.norm2() + k * w.norm2());
//! let before = e(v1, w1, 1.0, 0.4) + e(v2, w2, 3.0, 0.2);
//! let after = e(a1, b1, 1.0, 0.4) + e(a2, b2, 3.0, 0.2);
//! assert!((after - before).abs() < 1e-14);
//! assert!(((1.0 * a1 + 3.0 * a2) - (1.0 * v1 + 3.0 * v2)).norm() < 1e-15);
//! ```

use super::map::{RoughError, RoughMap, impulse, smooth_limit, store};
use crate::engine::collision_map::clamped_at_normal_speed;
use crate::engine::{CollisionMap, Counts};
use crate::geometry::Geometry;
use crate::kernel::Kernel;
use crate::math::{Real, abs};
use crate::mixture::{MassMap, PairLaw};
use crate::particles::Particles;
use crate::restitution::{Constant, Restitution};
use crate::rng::Rng;
use crate::vec3::Vec3;

/// The rough particles of one pair type of a mixture: the normal restitution law `A` (a
/// constant `alpha`, or BRS (9) at `|g . n|`), `beta` and the partners' `kappa` (each by
/// [`RoughMap`]'s rules); the masses come from the species ([`PairLaw::between`]).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct RoughPairLaw<A = Constant> {
    /// The map of the first partner's inertia (holds the law, `beta`, `kappa_1`).
    first: RoughMap<A>,
    /// The second partner's `kappa`.
    kappa_2: Real,
}

impl RoughPairLaw<Constant> {
    /// Spheres: `0 < alpha <= 1`, `-1 <= beta <= 1`, each `kappa` in `(0, 2/3]`.
    pub fn new(alpha: Real, beta: Real, kappa_1: Real, kappa_2: Real) -> Result<Self, RoughError> {
        RoughMap::new(alpha, beta, kappa_2)?;
        Ok(RoughPairLaw {
            first: RoughMap::new(alpha, beta, kappa_1)?,
            kappa_2,
        })
    }

    /// Disks: as [`RoughPairLaw::new`] with each `kappa` in `(0, 1]`.
    pub fn for_disks(
        alpha: Real,
        beta: Real,
        kappa_1: Real,
        kappa_2: Real,
    ) -> Result<Self, RoughError> {
        RoughMap::for_disks(alpha, beta, kappa_2)?;
        Ok(RoughPairLaw {
            first: RoughMap::for_disks(alpha, beta, kappa_1)?,
            kappa_2,
        })
    }

    /// The normal restitution `alpha`.
    pub fn alpha(&self) -> Real {
        self.first.alpha()
    }
}

impl<A: Restitution> RoughPairLaw<A> {
    /// The same pair type with the normal restitution law `law` in place of this one's.
    #[must_use]
    pub fn with_law<B: Restitution>(&self, law: B) -> RoughPairLaw<B> {
        RoughPairLaw {
            first: self.first.with_law(law),
            kappa_2: self.kappa_2,
        }
    }

    /// The normal restitution law.
    pub fn law(&self) -> A {
        self.first.law()
    }

    /// The tangential restitution `beta`.
    pub fn beta(&self) -> Real {
        self.first.beta()
    }

    /// The partners' reduced moments of inertia `(kappa_1, kappa_2)`.
    pub fn inertia(&self) -> (Real, Real) {
        (self.first.kappa(), self.kappa_2)
    }
}

impl<A: Restitution> PairLaw for RoughPairLaw<A> {
    type Map = RoughPair<A>;

    fn inertia(&self) -> (Real, Real) {
        RoughPairLaw::inertia(self)
    }

    fn between(&self, m_1: Real, m_2: Real) -> RoughPair<A> {
        let beta = self.first.beta();
        let (k1, k2) = self.inertia();
        // The restitution's one rule was checked by `first`.
        let smooth = self.first.law().between(m_1, m_2);
        if m_1 == m_2 && k1 == k2 {
            // The one-species map's own coefficients: the same bits.
            let (t, w) = self.first.spin_transfer();
            return RoughPair {
                smooth,
                tangential: (t, t),
                spin: (w, w),
            };
        }
        let total = m_1 + m_2;
        let mu = m_1 * m_2 / total;
        let (i1, i2) = (k1 * m_1, k2 * m_2);
        let c1 = (1.0 + beta) / (1.0 + i1 / mu + i1 / i2);
        let c2 = (1.0 + beta) / (1.0 + i2 / mu + i2 / i1);
        RoughPair {
            smooth,
            tangential: (k1 * c1, k2 * c2),
            spin: (c1, c2),
        }
    }
}

/// The collision map of a rough pair type between given masses (module docs). Compact (nine
/// numbers with a constant law): a mixture's loop holds one per pair type, and the firmware's
/// memory holds the loop.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct RoughPair<A = Constant> {
    /// The smooth pair of these masses: the law and `mu_s`, `mu_t` (the normal part, and the
    /// whole collision at `beta = -1`, [`super::map`]'s smooth limit).
    smooth: MassMap<A>,
    /// `(kappa_1 c_1, kappa_2 c_2)`; equal partners: [`RoughMap`]'s `eta_t`.
    tangential: (Real, Real),
    /// `(c_1, c_2)`; equal partners: [`RoughMap`]'s `eta_t / kappa`.
    spin: (Real, Real),
}

impl<A: Restitution> RoughPair<A> {
    /// Post-collisional `(v1', w1', v2', w2')` for the unit vector `n` from 1 to 2 (module
    /// docs); `alpha` is the law's at `|g . n|`, clamped to [0, 1]. With `beta = -1` the rim
    /// velocities are returned unchanged, bit for bit; equal partners get
    /// [`RoughMap::collide`]'s bits (the same coefficients, and `(1 + alpha) mu = (1 + alpha)/2`
    /// exactly).
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

    /// As [`RoughPair::collide`], counting a clamped coefficient in `counts`.
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
        let m = &self.smooth.masses;
        let law = &self.smooth.law;
        let normal = |c: Real| {
            let a = 1.0 + clamped_at_normal_speed(law, abs(c), counts);
            (a * m.mu_t, a * m.mu_s)
        };
        impulse((v1, w1, v2, w2), n, normal, [self.tangential, self.spin])
    }
}

impl<A: Restitution> CollisionMap for RoughPair<A> {
    const SPINS: bool = true;

    /// The normal restitution law's [`Restitution::in_stored_units`].
    #[inline(always)]
    fn stored_map(&self, scale: Real) -> Self {
        RoughPair {
            smooth: self.smooth.stored_map(scale),
            ..*self
        }
    }

    /// The impact direction of `G` ([`Geometry::impact`]) and [`RoughPair::collide`]; with
    /// `beta = -1` the smooth pair's own code (the smooth
    /// limit of [`super::map`]), so a rough mixture with `beta = -1` has the smooth mixture's
    /// bits.
    #[inline(always)]
    fn collide_pair<K: Kernel, G: Geometry, R: Rng + ?Sized>(
        &self,
        p: &mut Particles<'_>,
        (i, j): (usize, usize),
        (vi, vj): (Vec3, Vec3),
        rng: &mut R,
        counts: &mut Counts,
    ) -> (Vec3, Vec3) {
        if self.spin == (0.0, 0.0) && smooth_limit::<K, G>(0.0) {
            return self
                .smooth
                .collide_pair::<K, G, R>(p, (i, j), (vi, vj), rng, counts);
        }
        let nrm = super::map::impact_of::<K, G, R>(vi - vj, rng);
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
        if self.spin == (0.0, 0.0) {
            return self
                .smooth
                .collide_at_impact(p, (i, j), (vi, vj), n, counts);
        }
        let after = self.collide_counting(vi, p.spin(i), vj, p.spin(j), n, counts);
        store(p, (i, j), after)
    }
}
