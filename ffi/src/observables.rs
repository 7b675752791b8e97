//! The observables a caller reads back.

use gdsmc_core::engine::Counts;
use gdsmc_core::mixture::MixtureObservables;
use gdsmc_core::moments::Observables;

/// Moments and derived quantities of a simulation at its current time, and its event counts.
#[repr(C)]
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct gdsmc_observables {
    /// Time.
    pub t: f64,
    /// Temperature `(1/3n) sum |v|^2` as GRW and RW use it (RW (23)).
    pub temperature: f64,
    /// Temperature about the bulk velocity (GRW (11), BRS (8)).
    pub temperature_bulk: f64,
    /// log10 of temperature_bulk: finite where a cooling gas's temperature underflows.
    pub log10_temperature_bulk: f64,
    /// Bulk velocity (GRW (10)).
    pub bulk_velocity: [f64; 3],
    /// Pressure `rho T_bulk`.
    pub pressure: f64,
    /// Stress tensor `M - rho V V^T`, upper triangle `xx, yy, zz, xy, xz, yz`.
    pub stress: [f64; 6],
    /// Heat flux (GRW Section 1).
    pub heat_flux: [f64; 3],
    /// `<|v|^4>`, raw.
    pub v4: f64,
    /// `<|v|^6>`, raw.
    pub v6: f64,
    /// Fourth cumulant a2 (MS (3)), about the bulk velocity.
    pub a2: f64,
    /// Sixth cumulant a3 (MS (70)).
    pub a3: f64,
    /// Deviation-from-Maxwell criterion (RW (29)).
    pub crit: f64,
    /// Real collisions so far.
    pub collisions: u64,
    /// Fictitious collisions so far.
    pub fictitious: u64,
    /// Candidates whose relative speed exceeded the majorant (kernel truncated there).
    pub overshoots: u64,
    /// Real collisions of grains with the host medium's background so far (0 without one).
    pub background_collisions: u64,
}

impl gdsmc_observables {
    pub(crate) fn new(t: f64, o: &Observables, c: &Counts) -> Self {
        gdsmc_observables {
            t,
            temperature: o.t_raw,
            temperature_bulk: o.t_bulk,
            log10_temperature_bulk: o.log10_t_bulk,
            bulk_velocity: o.bulk.to_array(),
            pressure: o.pressure,
            stress: o.stress,
            heat_flux: o.heat_flux.to_array(),
            v4: o.v4,
            v6: o.v6,
            a2: o.a2,
            a3: o.a3,
            crit: o.crit,
            collisions: c.collisions,
            fictitious: c.fictitious,
            overshoots: c.overshoots,
            background_collisions: c.background,
        }
    }
}

/// One species of a mixture at the simulation's current time (Garzó and Dufty 1999).
#[repr(C)]
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct gdsmc_species_observables {
    /// Particles of this species.
    pub count: u64,
    /// Its temperature `m_s <|v - U|^2>/3` about the mixture's flow velocity `U`.
    pub temperature: f64,
    /// The mixture temperature `T_mix = sum_s x_s T_s`.
    pub mixture_temperature: f64,
    /// `temperature / mixture_temperature`.
    pub temperature_ratio: f64,
    /// Its fourth cumulant a2 (MS (3)) about its own bulk velocity.
    pub a2: f64,
    /// Its bulk velocity.
    pub bulk_velocity: [f64; 3],
    /// The mixture's flow velocity `U = sum_s m_s N_s V_s / sum_s m_s N_s`.
    pub flow_velocity: [f64; 3],
    /// A rough mixture: the species' rotational temperature `kappa_s m_s <|w|^2>/d_rot`
    /// (0 when the particles are smooth).
    pub rotational_temperature: f64,
    /// A rough mixture: `rotational_temperature / temperature` (0 when the particles are
    /// smooth).
    pub theta: f64,
}

impl gdsmc_species_observables {
    pub(crate) fn new(m: &MixtureObservables, s: usize) -> Self {
        let (t, mix) = (m.temperature(s), m.mixture_temperature());
        gdsmc_species_observables {
            count: m.counts[s] as u64,
            temperature: t,
            mixture_temperature: mix,
            temperature_ratio: t / mix,
            a2: m.species[s].a2,
            bulk_velocity: m.species[s].bulk.to_array(),
            flow_velocity: m.flow_velocity().to_array(),
            rotational_temperature: m.rotational_temperature(s).unwrap_or(0.0),
            theta: m.rotational_temperature(s).map_or(0.0, |r| r / t),
        }
    }
}

/// A rough gas's rotation at the simulation's current time (Huthmann and Zippelius 1997).
#[repr(C)]
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct gdsmc_rotation_observables {
    /// Translational temperature `<|v - V|^2>/3` (the observables' `t_bulk`).
    pub translational_temperature: f64,
    /// Rotational temperature `kappa <|w|^2>/3`.
    pub rotational_temperature: f64,
    /// `theta = rotational / translational temperature`.
    pub theta: f64,
    /// Fourth cumulant of the rim velocities, `(3/5) <|w|^4>/<|w|^2>^2 - 1`.
    pub a2_rot: f64,
    /// Translation-rotation correlation `3 <(c . w)^2>/(<c^2> <w^2>) - 1`.
    pub cw2: f64,
}

impl gdsmc_rotation_observables {
    pub(crate) fn new(r: &gdsmc_core::rough::RoughObservables) -> Self {
        gdsmc_rotation_observables {
            translational_temperature: r.t_tr,
            rotational_temperature: r.t_rot,
            theta: r.theta(),
            a2_rot: r.a2_rot,
            cw2: r.cw2,
        }
    }
}
