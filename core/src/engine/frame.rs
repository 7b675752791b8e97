//! The velocity frame of the exact loops: how stored velocities map to physical ones,
//! `v_phys = offset + scale v` (and a rough particle's rim velocity `w_phys = scale w`).
//!
//! A gas with no drive cools for ever (the homogeneous cooling state). Its peculiar velocities,
//! stored beside a bulk velocity `V`, would lose digits (and stop at a rounding floor near
//! `T ~ (1e-16 |V|)^2`), and its temperature would underflow. So that it can be followed for as
//! long as asked, when at a synchronization its temperature has fallen below
//! `1e-8 max(1, |V|^2)` ([`RESCALE_BELOW`]), the velocities are stored rescaled: the stored
//! peculiar velocities at unit temperature. The collision maps are linear (the rough map in
//! `(v, w)` together) and the fictitious-collision test depends on ratios only, so the stored
//! system evolves by the same rules, with the physical majorant rate `scale^lambda` times the
//! stored one: time is not rescaled, the event rate is. Observables are returned in physical
//! units, `log10_t_bulk` included, which stays finite where the temperature itself would
//! underflow ([`super::Counts::rescales`]). One type for every loop (one species, a mixture's
//! species, rough spins) and for the histograms of a rescaled gas.

use crate::math::{Real, max, sqrt};
use crate::moments::Observables;
use crate::particles::{Particle, Particles, Spin};
use crate::vec3::Vec3;

/// A gas with no drive is rescaled when its stored temperature falls below this times
/// `max(1, |V|^2)` (stored units): the peculiar velocities then still carry 12 of their 16
/// digits beside the bulk velocity (module docs).
pub const RESCALE_BELOW: Real = 1e-8;

/// The map `v_phys = offset + scale v`, `w_phys = scale w` from stored to physical velocities
/// (module docs); the identity unless a cooling gas was rescaled.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Frame {
    /// The factor from stored to physical peculiar (and rim) velocities.
    pub scale: Real,
    /// The physical velocity of the stored origin.
    pub offset: Vec3,
}

impl Default for Frame {
    fn default() -> Self {
        Frame::IDENTITY
    }
}

impl Frame {
    /// Stored velocities are physical.
    pub const IDENTITY: Frame = Frame {
        scale: 1.0,
        offset: Vec3::ZERO,
    };

    /// Whether stored and physical velocities coincide.
    #[must_use]
    pub fn is_identity(&self) -> bool {
        self.scale == 1.0 && self.offset == Vec3::ZERO
    }

    /// The physical velocity of a stored one.
    #[must_use]
    #[inline(always)]
    pub fn physical(&self, v: Vec3) -> Vec3 {
        self.offset + self.scale * v
    }

    /// The observables of the stored system (`d` dimensions) in physical units.
    #[must_use]
    pub fn observables(&self, obs: &Observables, d: usize) -> Observables {
        obs.in_units_dim(self.scale, self.offset, d)
    }

    /// The caller replaced the velocities with physical ones between calls: the frame becomes
    /// the identity, and rim velocities (`spins`: a rough gas's, left as stored) are converted
    /// to physical units. Returns the factor `1/scale` from the new stored (physical)
    /// velocities to the old stored ones (a map's [`super::CollisionMap::stored_map`] takes it).
    #[must_use]
    pub fn reset(&mut self, p: &mut Particles<'_>, spins: bool) -> Real {
        let back = 1.0 / self.scale;
        if spins && self.scale != 1.0 {
            for w in p.spins_mut() {
                *w = Spin::new(self.scale * w.rim_velocity());
            }
        }
        *self = Frame::IDENTITY;
        back
    }

    /// Stores a cooling gas rescaled (module docs) when its temperature `obs.t_bulk` (stored
    /// units) has fallen below `below` times `max(1, |V|^2)`: the stored peculiar velocities
    /// (and the rim velocities with `spins`) at unit temperature; `obs` becomes the stored
    /// system's (in `d` dimensions). When it rescaled, the factor `sqrt(T)` from the new stored
    /// velocities to the old ones (a map's [`super::CollisionMap::stored_map`] takes it).
    pub fn rescale(
        &mut self,
        p: &mut Particles<'_>,
        obs: &mut Observables,
        below: Real,
        d: usize,
        spins: bool,
    ) -> Option<Real> {
        self.rescale_with(p, obs, (below, spins), |p| Observables::of_dim(p, d))
    }

    /// As [`Frame::rescale`], the stored system's observables from `observe` (a weighted
    /// system's are weighted means, [`crate::weighted::moments::observables`]).
    pub fn rescale_with(
        &mut self,
        p: &mut Particles<'_>,
        obs: &mut Observables,
        (below, spins): (Real, bool),
        observe: impl FnOnce(&Particles<'_>) -> Observables,
    ) -> Option<Real> {
        if !rescale_due(obs.t_bulk, obs.bulk, below) {
            return None;
        }
        let s = 1.0 / sqrt(obs.t_bulk);
        for q in p.as_mut_slice() {
            let v = q.velocity();
            q.set_velocity(s * (v - obs.bulk));
        }
        if spins {
            for w in p.spins_mut() {
                *w = Spin::new(s * w.rim_velocity());
            }
        }
        self.offset += self.scale * obs.bulk;
        self.scale /= s;
        *obs = observe(p);
        Some(1.0 / s)
    }

    /// `<|v|^6>` of a gas stored rescaled about a bulk velocity cannot be rebuilt from the
    /// central moments ([`Observables::in_units`] leaves it NaN); at an observation it is
    /// summed directly from the physical velocities of `q` (their peculiar parts are below the
    /// bulk's last digits there, so this is as accurate as the sum can be).
    #[must_use]
    pub fn with_raw_v6(&self, q: &[Particle], obs: Observables) -> Observables {
        self.with_raw_v6_weighted(q, &[], obs)
    }

    /// As [`Frame::with_raw_v6`], each record `q[i]` counted by `weights[i]` (all 1 when
    /// `weights` is empty): the weighted mean.
    #[must_use]
    pub fn with_raw_v6_weighted(
        &self,
        q: &[Particle],
        weights: &[Real],
        mut obs: Observables,
    ) -> Observables {
        if obs.v6.is_nan() && self.offset != Vec3::ZERO {
            let (mut s, mut w) = (0.0, 0.0);
            for (i, x) in q.iter().enumerate() {
                let g = weights.get(i).copied().unwrap_or(1.0);
                let v2 = self.physical(x.velocity()).norm2();
                s += g * (v2 * v2 * v2);
                w += g;
            }
            obs.v6 = if weights.is_empty() {
                s / q.len() as Real
            } else {
                s / w
            };
        }
        obs
    }
}

/// Whether a gas with no drive at temperature `t_bulk` about the bulk velocity `bulk` (stored
/// units) is due to be stored rescaled: below `below` times `max(1, |V|^2)` (module docs).
pub(crate) fn rescale_due(t_bulk: Real, bulk: Vec3, below: Real) -> bool {
    t_bulk > 0.0 && t_bulk < below * max(1.0, bulk.norm2())
}
