//! Observables of a particle system, from the moment sums of [`crate::batch::sums`].
//!
//! Densities are per particle (`rho = 1`, GRW's normalization). Two temperatures are kept, and
//! every number says which it is:
//!
//! - `t_raw = (1/3n) sum |v|^2`: the temperature of GRW Section 1 (after (12)) and RW (23), which
//!   assume the bulk velocity zero. GRW (13) and RW (24) are exact for it.
//! - `t_bulk = (1/3n) sum |v - V|^2 = (2/3) e` with `e` of GRW (11): about the bulk velocity, as
//!   BRS (8) and MS use it.
//!
//! Disks (`d = 2`, [`crate::geometry`]) count two degrees of freedom: `T = <|v|^2>/2`, and the
//! cumulants take MS (3) and (70) at `d = 2` ([`Observables::of_dim`]); the formulas below say
//! `d = 3`, the general ones are `a2 = <c^4>/(d(d+2)T^2) - 1`,
//! `a3 = 1 + 3 a2 - <c^6>/(d(d+2)(d+4) T^3)`.

use crate::batch::sums::{Sums, accumulate};
use crate::math::{Real, log10, sqrt};
use crate::particles::Particles;
use crate::vec3::Vec3;

/// The moments and derived quantities of one particle system at one time.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Observables {
    /// Bulk velocity `V = m / rho`, GRW (10).
    pub bulk: Vec3,
    /// `(1/3n) sum |v|^2`: GRW/RW temperature (RW (23)).
    pub t_raw: Real,
    /// `(1/3n) sum |v - V|^2`: temperature about the bulk velocity, GRW (11), BRS (8).
    pub t_bulk: Real,
    /// Pressure `p = rho T` (about the bulk velocity), GRW Section 1.
    pub pressure: Real,
    /// Stress tensor `P = M - rho V V^T`, upper triangle `[xx, yy, zz, xy, xz, yz]`.
    pub stress: [Real; 6],
    /// Heat flux `q = r - (M + (tr M / 2 - rho |V|^2) I) V`, GRW Section 1
    /// (equals `(1/2n) sum c |c|^2`, `c = v - V`).
    pub heat_flux: Vec3,
    /// Momentum flow `M = (1/n) sum v v^T`, GRW (8), upper triangle.
    pub momentum_flow: [Real; 6],
    /// Energy flow `r = (1/2n) sum v |v|^2`, GRW (9).
    pub energy_flow: Vec3,
    /// `<|v|^4>`, raw.
    pub v4: Real,
    /// `<|v|^6>`, raw.
    pub v6: Real,
    /// `<|v - V|>`.
    pub c1: Real,
    /// `<|v - V|^3>`.
    pub c3: Real,
    /// `<|v - V|^4>`.
    pub c4: Real,
    /// `<|v - V|^6>`.
    pub c6: Real,
    /// Fourth cumulant MS (3) with `d = 3`: `a2 = <c^4> / (15 T^2) - 1` (about the bulk);
    /// NaN (undefined) when `t_bulk = 0`, as are `a3` and `crit`.
    pub a2: Real,
    /// Sixth cumulant MS (70) with `d = 3`: `a3 = 1 + 3 a2 - <c^6> / (105 T^3)`.
    pub a3: Real,
    /// RW (29): `(1/T) (1/2 |P - pI|_F^2 + 2/(5T) |q|^2 + gamma^2 / (120 T^2))^{1/2}`,
    /// `gamma = <|c|^4> - 15 T^2`, with `T = t_bulk` (peculiar velocities throughout).
    pub crit: Real,
    /// `max |v - V|`: half the majorant `Umax` of GRW step 1.4.
    pub max_peculiar_speed: Real,
    /// `log10 t_bulk`, kept finite when the engine has rescaled a cooling gas far below the
    /// smallest double (see [`Observables::in_units`]).
    pub log10_t_bulk: Real,
}

impl Observables {
    /// Observables of the current velocities of `p` (which the caller has brought to one time).
    pub fn of(p: &Particles<'_>) -> Self {
        Self::from_sums(&accumulate(p.as_slice()))
    }

    /// As [`Observables::of`] in `d` dimensions (2: disks, whose `z` components are zero).
    pub fn of_dim(p: &Particles<'_>, d: usize) -> Self {
        Self::from_sums_dim(&accumulate(p.as_slice()), d)
    }

    /// Observables from moment sums. The raw quantities (`t_raw`, `M`, `r`, `v4`, `v6`) come
    /// from the raw sums, everything about the bulk velocity from the central sums, which keep
    /// their accuracy when `|V|` is large against the thermal speed (cooling gases, drifts).
    pub fn from_sums(s: &Sums) -> Self {
        Self::from_sums_dim(s, 3)
    }

    /// As [`Observables::from_sums`] in `d` dimensions (2 or 3): temperatures per degree of
    /// freedom, MS (3) and (70) at that `d`, RW (29)'s weights at that `d` (Grad's: the stress
    /// deviator within the plane, `2/((d+2)T)` for the heat flux, `gamma = <|c|^4> - d(d+2)T^2`
    /// over `8 d(d+2) T^2`).
    pub fn from_sums_dim(s: &Sums, d: usize) -> Self {
        let dr = d as Real;
        let (m4, m6) = (dr * (dr + 2.0), dr * (dr + 2.0) * (dr + 4.0));
        let inv = 1.0 / s.n as Real;
        let bulk = Vec3::new(s.s1[0] * inv, s.s1[1] * inv, s.s1[2] * inv);
        let m: [Real; 6] = core::array::from_fn(|k| s.s2[k] * inv);
        let r = Vec3::new(
            0.5 * s.s3[0] * inv,
            0.5 * s.s3[1] * inv,
            0.5 * s.s3[2] * inv,
        );
        let t_raw = trace(&m, d) / dr;
        // GRW Section 1: P = M - rho V V^T and q = r - (M + (tr M/2 - rho |V|^2) I) V are the
        // central second moment and half the central third moment.
        let stress: [Real; 6] = core::array::from_fn(|k| s.c2[k] * inv);
        let t_bulk = trace(&stress, d) / dr;
        let heat_flux = Vec3::new(
            0.5 * s.c3[0] * inv,
            0.5 * s.c3[1] * inv,
            0.5 * s.c3[2] * inv,
        );
        let c4 = s.c4 * inv;
        let c6 = s.c6 * inv;
        let (c1, c3) = (s.c1 * inv, s.c3n * inv);
        let t = t_bulk;
        let a2 = c4 / (m4 * t * t) - 1.0;
        let a3 = 1.0 + 3.0 * a2 - c6 / (m6 * t * t * t);
        let frob2 = if d == 2 {
            let dev = [stress[0] - t, stress[1] - t];
            dev[0] * dev[0] + dev[1] * dev[1] + 2.0 * (stress[3] * stress[3])
        } else {
            let dev = [stress[0] - t, stress[1] - t, stress[2] - t];
            dev[0] * dev[0]
                + dev[1] * dev[1]
                + dev[2] * dev[2]
                + 2.0 * (stress[3] * stress[3] + stress[4] * stress[4] + stress[5] * stress[5])
        };
        let gamma = c4 - m4 * t * t;
        let crit = sqrt(
            0.5 * frob2
                + 2.0 / ((dr + 2.0) * t) * heat_flux.norm2()
                + gamma * gamma / (8.0 * m4 * t * t),
        ) / t;
        Observables {
            bulk,
            t_raw,
            t_bulk,
            pressure: t_bulk,
            stress,
            heat_flux,
            momentum_flow: m,
            energy_flow: r,
            v4: s.s4 * inv,
            v6: s.s6 * inv,
            c1,
            c3,
            c4,
            c6,
            a2,
            a3,
            crit,
            max_peculiar_speed: sqrt(s.max_c2),
            log10_t_bulk: log10(t_bulk),
        }
    }

    /// The observables of velocities `offset + s v` given those of `v` (a cooling gas stored
    /// rescaled, see [`crate::engine::NoSplitting`]): central moments scale with powers of `s`,
    /// the raw ones are rebuilt from them and the bulk velocity (GRW Section 1 inverted;
    /// `<|v|^4> = |V|^4 + 4 V.P.V + <|c|^4> + 6 |V|^2 T + 8 V.q`). `<|v|^6>` needs moments not
    /// kept and is NaN when both `s != 1` and `offset != 0` (the no-splitting loop then sums it
    /// directly at observations). `log10_t_bulk` stays finite where
    /// `t_bulk` underflows.
    pub fn in_units(&self, s: Real, offset: Vec3) -> Observables {
        self.in_units_dim(s, offset, 3)
    }

    /// As [`Observables::in_units`] in `d` dimensions.
    pub fn in_units_dim(&self, s: Real, offset: Vec3, d: usize) -> Observables {
        if s == 1.0 && offset == Vec3::ZERO {
            return *self;
        }
        let s2 = s * s;
        let bulk = offset + s * self.bulk;
        let stress: [Real; 6] = core::array::from_fn(|k| s2 * self.stress[k]);
        let t_bulk = s2 * self.t_bulk;
        let heat_flux = (s2 * s) * self.heat_flux;
        let c4 = s2 * s2 * self.c4;
        let c6 = s2 * s2 * s2 * self.c6;
        let (c1, c3) = (s * self.c1, s2 * s * self.c3);
        let bb = [
            bulk.x * bulk.x,
            bulk.y * bulk.y,
            bulk.z * bulk.z,
            bulk.x * bulk.y,
            bulk.x * bulk.z,
            bulk.y * bulk.z,
        ];
        let m: [Real; 6] = core::array::from_fn(|k| stress[k] + bb[k]);
        let v2 = bulk.norm2();
        let mv = Vec3::new(
            m[0] * bulk.x + m[3] * bulk.y + m[4] * bulk.z,
            m[3] * bulk.x + m[1] * bulk.y + m[5] * bulk.z,
            m[4] * bulk.x + m[5] * bulk.y + m[2] * bulk.z,
        );
        let energy_flow = heat_flux + mv + (0.5 * (m[0] + m[1] + m[2]) - v2) * bulk;
        let pv = Vec3::new(
            stress[0] * bulk.x + stress[3] * bulk.y + stress[4] * bulk.z,
            stress[3] * bulk.x + stress[1] * bulk.y + stress[5] * bulk.z,
            stress[4] * bulk.x + stress[5] * bulk.y + stress[2] * bulk.z,
        );
        let v4 = v2 * v2 + 4.0 * bulk.dot(pv) + c4 + 6.0 * v2 * t_bulk + 8.0 * bulk.dot(heat_flux);
        let v6 = if offset == Vec3::ZERO {
            s2 * s2 * s2 * self.v6
        } else {
            Real::NAN
        };
        Observables {
            bulk,
            t_raw: t_bulk + v2 / d as Real,
            t_bulk,
            pressure: t_bulk,
            stress,
            heat_flux,
            momentum_flow: m,
            energy_flow,
            v4,
            v6,
            c1,
            c3,
            c4,
            c6,
            a2: self.a2,
            a3: self.a3,
            crit: self.crit,
            max_peculiar_speed: s * self.max_peculiar_speed,
            log10_t_bulk: self.log10_t_bulk + 2.0 * log10(s),
        }
    }

    /// True when every moment is finite (no silent NaN). The ratios `a2`, `a3` and `crit`
    /// are not checked: they are undefined (NaN) for a gas at zero temperature, a valid state.
    pub fn is_finite(&self) -> bool {
        self.non_finite().is_none()
    }

    /// The first moment that is not finite (by its column name), if any; see
    /// [`Observables::is_finite`].
    pub fn non_finite(&self) -> Option<&'static str> {
        let checks: [(&'static str, bool); 9] = [
            ("the bulk velocity V", self.bulk.is_finite()),
            ("T", self.t_raw.is_finite()),
            ("T_bulk", self.t_bulk.is_finite()),
            (
                "the stress tensor",
                self.stress.iter().all(|x| x.is_finite()),
            ),
            ("the heat flux q", self.heat_flux.is_finite()),
            ("v4", self.v4.is_finite()),
            ("v6", self.v6.is_finite()),
            ("<|c|^4>", self.c4.is_finite()),
            ("<|c|^6>", self.c6.is_finite()),
        ];
        checks.iter().find(|(_, ok)| !ok).map(|(name, _)| *name)
    }
}

/// The trace of an upper-triangle tensor `[xx, yy, zz, ..]` over the first `d` axes; for
/// `d = 3` the sum in the order it always was (the same bits).
#[inline]
fn trace(m: &[Real; 6], d: usize) -> Real {
    if d == 2 {
        m[0] + m[1]
    } else {
        m[0] + m[1] + m[2]
    }
}
