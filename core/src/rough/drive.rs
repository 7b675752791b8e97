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

use crate::batch::kick::white_noise_kick_all;
use crate::drive::Drive;
use crate::drive::white_noise::white_noise_kick_pair;
use crate::geometry::{DimensionChoice, Geometry, Spheres};
use crate::math::{Real, sqrt};
use crate::particles::Particles;
use crate::rng::Rng;
use crate::vec3::Vec3;

/// White noise of strength `beta` on translation and `beta_rot` on rotation (module docs), in
/// dimension `G` (disks: in the plane and along the rim velocity's one axis, `z`). The
/// translational part draws whenever it is on, even at `beta = 0`, exactly as the smooth
/// [`crate::drive::WhiteNoise`] does (so a rough gas whose collisions leave the rotation alone
/// has the smooth gas's bits); a zero rotational strength draws nothing. With no noise a rough
/// gas takes [`crate::drive::NoDrive`], as a smooth one does.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct RoughNoise<G = Spheres> {
    /// `2 beta`: the variance rate of each translational component; `None` when translation
    /// is not driven.
    tr: Option<Real>,
    /// `2 beta_rot / kappa`: the variance rate of each rim-velocity component.
    rot: Real,
    dim: core::marker::PhantomData<G>,
}

impl RoughNoise {
    /// The noise of strengths `beta >= 0` (`None`: translation not driven) and
    /// `beta_rot >= 0` on a gas of reduced moment of inertia `kappa > 0`; `None` when a
    /// strength is negative or a rate not finite. Spheres; disks:
    /// [`RoughNoise::in_dim`].
    pub fn new(beta: Option<Real>, beta_rot: Real, kappa: Real) -> Option<Self> {
        let (tr, rot) = (beta.map(|b| 2.0 * b), 2.0 * beta_rot / kappa);
        let ok = |x: Real| x.is_finite() && x >= 0.0;
        (tr.is_none_or(ok) && ok(rot) && kappa > 0.0).then_some(RoughNoise {
            tr,
            rot,
            dim: core::marker::PhantomData,
        })
    }
}

impl<G: Geometry> RoughNoise<G> {
    /// The same strengths in dimension `H`.
    #[must_use]
    pub fn in_dim<H: Geometry>(self) -> RoughNoise<H> {
        RoughNoise {
            tr: self.tr,
            rot: self.rot,
            dim: core::marker::PhantomData,
        }
    }

    /// `dT_tr/dt` from the noise: `2 beta` (0 when translation is not driven); per unit
    /// mass, the variance rate of each translational component.
    pub fn heating_tr(&self) -> Real {
        self.tr.unwrap_or(0.0)
    }

    /// `2 beta_rot / kappa`, the variance rate of each rim-velocity component: `dT_rot/dt =
    /// 2 beta_rot` per unit mass.
    pub fn rim_rate(&self) -> Real {
        self.rot
    }
}

impl<G: Geometry> RoughNoise<G> {
    /// `2 beta` when this noise is the smooth white noise on spheres (translation driven, no
    /// rotational noise): its kicks then draw as [`crate::drive::WhiteNoise`]'s, so a rough
    /// gas with `beta = -1` is the smooth gas to the bit.
    #[inline(always)]
    fn smooth_noise(&self) -> Option<Real> {
        self.tr
            .filter(|_| self.rot == 0.0 && G::CHOICE == DimensionChoice::Three)
    }
}

impl<G: Geometry> Drive for RoughNoise<G> {
    const ACTS: bool = true;

    /// The translational part alone (GRW (18) in `G`); the loops kick with
    /// [`Drive::kick`], which moves the rim velocity too.
    #[inline(always)]
    fn evolve<R: Rng + ?Sized>(&self, mut v: Vec3, dt: Real, rng: &mut R) -> Vec3 {
        if let Some(tr) = self.tr {
            v += sqrt(tr * dt) * G::normal(rng);
        }
        v
    }

    /// Brings particle `i`'s velocity and rim velocity to `t` (translation drawn first). As
    /// the smooth [`Drive::kick`], it draws even for a particle already at `t` (a zero kick),
    /// so the translational draws are the smooth gas's.
    #[inline(always)]
    fn kick<R: Rng + ?Sized>(&self, p: &mut Particles<'_>, i: usize, t: Real, rng: &mut R) {
        let dt = t - p.kick_time(i);
        let v = self.evolve(p.velocity(i), dt, rng);
        p.set_velocity(i, v);
        if self.rot > 0.0 {
            let w = p.spin(i) + sqrt(self.rot * dt) * G::spin_normal(rng);
            p.set_spin(i, w);
        }
        p.get_mut(i).t_kick = t;
    }

    /// Brings a candidate's partners to `t`. With no rotational noise on spheres, the smooth
    /// white noise's pair kick ([`white_noise_kick_pair`]: the translational draws stay the
    /// smooth gas's); else partner by partner.
    #[inline(always)]
    fn kick_pair_counting<R: Rng + ?Sized>(
        &self,
        p: &mut Particles<'_>,
        (i, j): (usize, usize),
        t: Real,
        rng: &mut R,
        _events: &mut u64,
    ) {
        match self.smooth_noise() {
            Some(tr) => {
                white_noise_kick_pair(tr, p, (i, j), t, rng);
            }
            _ => {
                self.kick(p, i, t, rng);
                self.kick(p, j, t, rng);
            }
        }
    }

    /// Brings every particle to `t`. With no rotational noise on spheres, the smooth white
    /// noise's batch kick ([`white_noise_kick_all`]: its normals drawn for blocks of four), so
    /// that the translational draws stay the smooth gas's; else particle by particle.
    fn kick_all<R: Rng + ?Sized>(&self, p: &mut Particles<'_>, t: Real, rng: &mut R) {
        match self.smooth_noise() {
            Some(tr) => {
                white_noise_kick_all(tr, p, t, rng);
            }
            _ => {
                for i in 0..p.len() {
                    self.kick(p, i, t, rng);
                }
            }
        }
    }
}
