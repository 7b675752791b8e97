//! Rough inelastic hard spheres: translational and angular velocities, normal restitution
//! `alpha` and tangential restitution `beta` (Huthmann and Zippelius 1997; Luding, Huthmann,
//! McNamara and Zippelius 1998; the notation of Santos, Kremer and Garzó 2010).
//!
//! The collision map and the impact direction ([`map`]), the drives ([`drive`]: none, white
//! noise on translation and rotation), the exact loop ([`nosplit`]) and the rotational
//! observables ([`observables`]). The spins live beside the particles
//! ([`crate::particles::Spin`], [`crate::particles::Particles::with_spins`]). Disks are to
//! come (issue 16).

pub mod drive;
pub mod map;
pub mod nosplit;
pub mod observables;

pub use drive::{RoughDrive, RoughNoise};
pub use map::{RoughError, RoughMap, impact_direction};
pub use nosplit::RoughNoSplitting;
pub use observables::RoughObservables;
