//! The mutation check's hook: an exact reference made wrong on purpose, to show which cells of
//! `gdsmc reproduce` notice (std-runner/tests/mutation.rs). Off unless a caller turns it on
//! for its own thread with [`with`]; then the one named reference returns its value times a
//! factor. Every exact value `reproduce` judges by passes through [`mutated`] where it is
//! computed, so the check perturbs the reference itself, not a cell's copy of it.

use std::cell::Cell;

/// The exact references `gdsmc reproduce` judges by.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Reference {
    /// GRW (13)-(14) / RW (24)-(25): the heated Maxwell gas's temperature `T(t)`.
    MaxwellTemperature,
    /// `E T_bulk,n = (1 - 1/n) T(t)`: the finite-n mean of the bulk temperature.
    FiniteNBulk,
    /// `E |P|^2 / (3 n^2)`: what the raw temperature's mean adds to the bulk one.
    BulkToRaw,
    /// The splitting schemes' exact mean of `T_bulk` (RW Algorithms 1-2).
    SplittingBulk,
    /// The range of GRW's `||V||_inf` (chi_3 quantile and Doob bound).
    SupNormRange,
    /// MS (29): the Maxwellian collisional moments `mu_2^(0)`, `mu_4^(0)`.
    MaxwellianMoments,
    /// BRS (14)-(17): the temperature of a Maxwell gas in a Maxwellian host medium.
    HostMediumTemperature,
    /// Its exact finite-n mean of `T_bulk` (the closed second-moment system).
    HostMediumFiniteN,
}

impl Reference {
    /// Every reference, in the order above.
    pub const ALL: [Reference; 8] = [
        Reference::MaxwellTemperature,
        Reference::FiniteNBulk,
        Reference::BulkToRaw,
        Reference::SplittingBulk,
        Reference::SupNormRange,
        Reference::MaxwellianMoments,
        Reference::HostMediumTemperature,
        Reference::HostMediumFiniteN,
    ];
}

thread_local! {
    /// The reference perturbed on this thread and its factor, if any.
    static ACTIVE: Cell<Option<(Reference, f64)>> = const { Cell::new(None) };
}

/// `value` of reference `r`: itself, or times the factor while [`with`] perturbs `r` on this
/// thread.
#[must_use]
pub fn mutated(r: Reference, value: f64) -> f64 {
    match ACTIVE.with(Cell::get) {
        Some((m, factor)) if m == r => value * factor,
        _ => value,
    }
}

/// Runs `f` with reference `r` multiplied by `factor` on this thread (restored afterwards,
/// also when `f` panics).
pub fn with<T>(r: Reference, factor: f64, f: impl FnOnce() -> T) -> T {
    struct Restore(Option<(Reference, f64)>);
    impl Drop for Restore {
        fn drop(&mut self) {
            ACTIVE.with(|a| a.set(self.0));
        }
    }
    let _restore = Restore(ACTIVE.with(|a| a.replace(Some((r, factor)))));
    f()
}
