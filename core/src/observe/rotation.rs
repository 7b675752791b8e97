//! What a rough gas shows beyond its translational moments: the rotational temperature, the
//! ratio `theta = T_rot / T_tr` (Huthmann and Zippelius 1997; Luding et al. 1998), the fourth
//! cumulant of the rim velocities, and the translation-rotation correlation `<(c . w)^2>`
//! (Brilliantov, Pöschel, Kranz and Zippelius 2007), all per unit mass.

use crate::batch::sums::accumulate;
use crate::geometry::DimensionChoice;
use crate::math::Real;
use crate::moments::Observables;
use crate::particles::{Particle, Particles, Spin};
use crate::vec3::Vec3;

/// The rotational observables of a rough gas at one time (physical units).
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct RoughObservables {
    /// Translational temperature `T_tr = <|v - V|^2>/d` (the smooth gas's `T_bulk`).
    pub t_tr: Real,
    /// Rotational temperature `T_rot = kappa <|w|^2>/d_rot`, `w` the rim velocity
    /// (`(I/2)|omega|^2 = (kappa/2)|w|^2` per unit mass; `d_rot` = 3 for spheres, 1 for disks).
    pub t_rot: Real,
    /// Fourth cumulant of the rim velocities, `d_rot/(d_rot + 2) <|w|^4> / <|w|^2>^2 - 1`
    /// (0 for a Maxwellian; the rotational twin of MS (3)).
    pub a2_rot: Real,
    /// Translation-rotation correlation, 0 when `c = v - V` and `w` are independent and
    /// isotropic: spheres `3 <(c . w)^2> / (<|c|^2> <|w|^2>) - 1`; disks, whose `w` is normal
    /// to every `c`, `<|c|^2 |w|^2> / (<|c|^2> <|w|^2>) - 1`.
    pub cw2: Real,
}

impl RoughObservables {
    /// The observables of the system `p` (with spins), stored as `v_phys = offset + scale v`,
    /// `w_phys = scale w` (the offset drops out: `c` is taken about the bulk velocity), with
    /// reduced moment of inertia `kappa`. Ratios are scale-free.
    pub fn of(p: &Particles<'_>, kappa: Real, scale: Real) -> Self {
        Self::of_dim(p, kappa, scale, DimensionChoice::Three)
    }

    /// As [`RoughObservables::of`] for spheres or disks.
    pub fn of_dim(p: &Particles<'_>, kappa: Real, scale: Real, dim: DimensionChoice) -> Self {
        Self::of_parts(p.as_slice(), p.spins(), kappa, scale, dim)
    }

    /// As [`RoughObservables::of_dim`] for the particles `q` with the rim velocities `spins`
    /// (one per particle; a mixture's species).
    pub fn of_parts(
        q: &[Particle],
        spins: &[Spin],
        kappa: Real,
        scale: Real,
        dim: DimensionChoice,
    ) -> Self {
        let disks = dim == DimensionChoice::Two;
        let n = q.len() as Real;
        let mut bulk = Vec3::ZERO;
        for x in q {
            bulk += x.velocity();
        }
        bulk = (1.0 / n) * bulk;
        let (mut c2, mut w2, mut w4, mut cw) = (0.0, 0.0, 0.0, 0.0);
        for (x, s) in q.iter().zip(spins) {
            let c = x.velocity() - bulk;
            let w = s.rim_velocity();
            let ww = w.norm2();
            let cc = c.norm2();
            c2 += cc;
            w2 += ww;
            w4 += ww * ww;
            cw += if disks {
                cc * ww
            } else {
                let d = c.dot(w);
                d * d
            };
        }
        let (c2, w2, w4, cw) = (c2 / n, w2 / n, w4 / n, cw / n);
        let s2 = scale * scale;
        let dof = dim.spin_dof() as Real;
        RoughObservables {
            // The translational moments' own sums, so that T_tr is T_bulk to the bit.
            t_tr: s2 * Observables::from_sums_dim(&accumulate(q), dim.d()).t_bulk,
            t_rot: s2 * kappa * w2 / dof,
            a2_rot: dof / (dof + 2.0) * w4 / (w2 * w2) - 1.0,
            cw2: if disks { 1.0 } else { 3.0 } * cw / (c2 * w2) - 1.0,
        }
    }

    /// `theta = T_rot / T_tr`.
    pub fn theta(&self) -> Real {
        self.t_rot / self.t_tr
    }

    /// The mean energy per degree of freedom of spheres, `(T_tr + T_rot)/2`.
    pub fn t_total(&self) -> Real {
        0.5 * (self.t_tr + self.t_rot)
    }

    /// The mean energy per degree of freedom, `(d T_tr + d_rot T_rot)/(d + d_rot)`: for
    /// spheres [`RoughObservables::t_total`], for disks `(2 T_tr + T_rot)/3`.
    pub fn t_total_in(&self, dim: DimensionChoice) -> Real {
        match dim {
            DimensionChoice::Three => self.t_total(),
            DimensionChoice::Two => (2.0 * self.t_tr + self.t_rot) / 3.0,
        }
    }
}
