//! The observables a caller reads back.

use gdsmc_core::engine::Counts;
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
