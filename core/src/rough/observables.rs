//! What a rough gas shows beyond its translational moments: the rotational temperature, the
//! ratio `theta = T_rot / T_tr` (Huthmann and Zippelius 1997; Luding et al. 1998), the fourth
//! cumulant of the rim velocities, and the translation-rotation correlation `<(c . w)^2>`
//! (Brilliantov, Pöschel, Kranz and Zippelius 2007), all per unit mass.

use crate::math::Real;
use crate::moments::Observables;
use crate::particles::Particles;
use crate::vec3::Vec3;

/// The rotational observables of a rough gas at one time (physical units).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct RoughObservables {
    /// Translational temperature `T_tr = <|v - V|^2>/3` (the smooth gas's `T_bulk`).
    pub t_tr: Real,
    /// Rotational temperature `T_rot = kappa <|w|^2>/3`, `w` the rim velocity
    /// (`(I/2)|omega|^2 = (kappa/2)|w|^2` per unit mass).
    pub t_rot: Real,
    /// Fourth cumulant of the rim velocities, `(3/5) <|w|^4> / <|w|^2>^2 - 1` (0 for a
    /// Maxwellian; the rotational twin of MS (3)).
    pub a2_rot: Real,
    /// Translation-rotation correlation `3 <(c . w)^2> / (<|c|^2> <|w|^2>) - 1`, `c = v - V`
    /// (0 when `c` and `w` are independent and isotropic).
    pub cw2: Real,
}

impl RoughObservables {
    /// The observables of the system `p` (with spins), stored as `v_phys = offset + scale v`,
    /// `w_phys = scale w` (the offset drops out: `c` is taken about the bulk velocity), with
    /// reduced moment of inertia `kappa`. Ratios are scale-free.
    pub fn of(p: &Particles<'_>, kappa: Real, scale: Real) -> Self {
        let n = p.len() as Real;
        let mut bulk = Vec3::ZERO;
        for q in p.as_slice() {
            bulk += q.velocity();
        }
        bulk = (1.0 / n) * bulk;
        let (mut c2, mut w2, mut w4, mut cw) = (0.0, 0.0, 0.0, 0.0);
        for (q, s) in p.as_slice().iter().zip(p.spins()) {
            let c = q.velocity() - bulk;
            let w = s.rim_velocity();
            let ww = w.norm2();
            let d = c.dot(w);
            c2 += c.norm2();
            w2 += ww;
            w4 += ww * ww;
            cw += d * d;
        }
        let (c2, w2, w4, cw) = (c2 / n, w2 / n, w4 / n, cw / n);
        let s2 = scale * scale;
        RoughObservables {
            // The translational moments' own sums, so that T_tr is T_bulk to the bit.
            t_tr: s2 * Observables::of(p).t_bulk,
            t_rot: s2 * kappa * w2 / 3.0,
            a2_rot: 0.6 * w4 / (w2 * w2) - 1.0,
            cw2: 3.0 * cw / (c2 * w2) - 1.0,
        }
    }

    /// `theta = T_rot / T_tr`.
    pub fn theta(&self) -> Real {
        self.t_rot / self.t_tr
    }

    /// The mean energy per degree of freedom, `(T_tr + T_rot)/2`.
    pub fn t_total(&self) -> Real {
        0.5 * (self.t_tr + self.t_rot)
    }
}
