//! Rough inelastic hard spheres: translational and angular velocities, normal restitution
//! `alpha` and tangential restitution `beta` (Huthmann and Zippelius 1997; Luding, Huthmann,
//! McNamara and Zippelius 1998; the notation of Santos, Kremer and Garzó 2010).
//!
//! The collision map and the impact direction ([`map`]: the particle model's
//! [`crate::engine::CollisionMap`]), white noise on translation and rotation ([`drive`]: a
//! [`crate::drive::Drive`]) and the rotational observables (`observables`). A rough gas runs
//! in the one exact loop, [`crate::engine::NoSplitting`], with the rough map as its collision
//! map. The spins live beside the particles ([`crate::particles::Spin`],
//! [`crate::particles::Particles::with_spins`]).

pub mod drive;
pub mod map;
pub mod pair;

pub use crate::observe::RoughObservables;
pub use crate::sample::impact_direction;
pub use drive::RoughNoise;
pub use map::{RoughError, RoughMap, collides_smooth, spin_transfer};
pub use pair::{RoughPair, RoughPairLaw};
