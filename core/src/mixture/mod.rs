//! Granular mixtures: several species of different masses, kernels and restitution
//! coefficients in one homogeneous gas, simulated exactly (no time step) by the no-splitting
//! scheme with one majorant per pair of species, by RW's splittings of it, or by MS's
//! time-stepped scheme with one collision stage per pair of species.
//!
//! - [`Species`]: counts and masses, the particles of each species a contiguous range of the
//!   caller's buffer, the pair types `(s, t)`;
//! - [`MassRatio`]: the collision of unequal masses (GRW (3) in the centre-of-mass frame);
//! - [`PairLaw`]: what a pair type's law becomes between given masses: a collision map
//!   ([`MassMap`] for smooth particles, [`crate::rough::RoughPair`] for rough ones);
//! - [`MixtureNoSplitting`]: the event loop, generic over the kernel, the drive (one per
//!   species), the pair law (one per pair type) and the dimension;
//! - [`MixtureSplitting`]: RW's Euler and Strang splittings on it (its collision process with
//!   the drives off, then every species kicked);
//! - [`MixtureTimeStepped`]: MS's time-stepped scheme, one collision stage per pair type;
//! - [`MixtureObservables`]: each species' moments and temperature `T_s` about the flow
//!   velocity (Garzó and Dufty 1999).
//!
//! ```
//! use gdsmc_core::{drive::NoDrive, kernel::Maxwell, math::PI,
//!                  mixture::{MixtureNoSplitting, PairPhysics, Species},
//!                  particles::{Particle, Particles}, restitution::Constant, rng::seeded,
//!                  sample::Maxwellian};
//! // Two species, masses 1 and 4, Maxwell pseudo-molecules, alpha = 0.8 for every pair.
//! let sp = Species::new(&[32, 32], &[1.0, 4.0]).unwrap();
//! let pair = PairPhysics {
//!     kernel: Maxwell::new(1.0, 1.0 / (4.0 * PI)).unwrap(),
//!     restitution: Constant::new(0.8).unwrap(),
//! };
//! let mut buf = vec![Particle::default(); 64];
//! let mut p = Particles::new(&mut buf).unwrap();
//! let mut rng = seeded(1);
//! let f0 = Maxwellian::standard();
//! p.fill_with(0.0, || f0.sample(&mut rng));
//! let (mut engine, start) =
//!     MixtureNoSplitting::start(sp, &[pair; 3], &[NoDrive; 2], &mut p, 0.0).unwrap();
//! let obs = engine.advance_to(&mut p, 1.0, &mut rng).unwrap();
//! assert!(obs.mixture_temperature() < start.mixture_temperature()); // the mixture cools
//! ```

mod drives;
pub mod map;
pub mod nosplit;
pub mod splitting;
pub mod time_stepped;

use crate::engine::EngineError;
pub use crate::observe::MixtureObservables;
pub use crate::species::{MAX_PAIRS, MAX_SPECIES, MixtureError, Species, pair_index};
pub use map::{MassMap, MassRatio, PairLaw};
pub use nosplit::{MixtureNoSplitting, PairPhysics};
pub use splitting::MixtureSplitting;
pub use time_stepped::MixtureTimeStepped;

/// Why a mixture loop could not start.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum StartError {
    /// The mixture description does not fit the data given.
    Mixture(MixtureError),
    /// The engine refused (non-finite start time or velocities).
    Engine(EngineError),
}

impl core::fmt::Display for StartError {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        match self {
            StartError::Mixture(e) => e.fmt(f),
            StartError::Engine(e) => e.fmt(f),
        }
    }
}

impl core::error::Error for StartError {}
