//! Rough inelastic hard spheres: translational and angular velocities, normal restitution
//! `alpha` and tangential restitution `beta` (Huthmann and Zippelius 1997; Luding, Huthmann,
//! McNamara and Zippelius 1998; the notation of Santos, Kremer and Garzó 2010).
//!
//! So far the collision map and the impact direction ([`map`]); the event loop, drives and
//! observables of a rough gas, and disks, are to come (issue 16).

pub mod map;

pub use map::{RoughError, RoughMap, impact_direction};
