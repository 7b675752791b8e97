//! # gdsmc-core
//!
//! A `#![no_std]`, allocation-free direct simulation Monte Carlo engine for the spatially
//! homogeneous inelastic (granular) Boltzmann equation. Every buffer belongs to the caller.
//!
//! The physics and the algorithms follow four papers, cited by short name and equation
//! (full citations: `docs/papers.md` in the repository):
//! GRW (Gamba, Rjasanow, Wagner: the uniformly heated gas and the no-splitting scheme),
//! RW (Rjasanow, Wagner: splitting schemes), BRS (Bisi, Rjasanow, Spiga: host medium),
//! MS (Montanero, Santos: thermostats).
//!
//! The event loop [`engine::NoSplitting`] is generic over the collision [`kernel`], the
//! [`drive`] and the [`restitution`] law, so a scene's loop holds only the physics it uses.
//!
//! ```
//! use gdsmc_core::{drive::WhiteNoise, engine::NoSplitting, kernel::Maxwell, math::PI,
//!                  particles::{Particle, Particles}, restitution::Constant, rng::seeded,
//!                  sample::Maxwellian};
//! // GRW Example 3 with 64 particles: alpha = 1/2, beta = 1, gamma = 4, C0 = 1/(4 pi).
//! let n = 64;
//! let mut buf = vec![Particle::default(); n];
//! let mut p = Particles::new(&mut buf).unwrap();
//! let mut rng = seeded(1);
//! let f0 = Maxwellian::standard();
//! p.fill_with(0.0, || f0.sample(&mut rng));
//! let (mut engine, _) = NoSplitting::start(
//!     Maxwell::new(4.0, 1.0 / (4.0 * PI)).unwrap(),
//!     WhiteNoise::new(1.0).unwrap(),
//!     Constant::new(0.5).unwrap(),
//!     &mut p, 0.0).unwrap();
//! let obs = engine.advance_to(&mut p, 8.0, &mut rng).unwrap();
//! assert!(obs.t_raw > 1.0); // heated towards T_inf = 8/3
//! ```

#![no_std]
#![deny(unsafe_code)]
#![warn(missing_docs)]

pub mod batch;
pub mod collision;
pub mod collisional;
pub mod declared;
pub mod drive;
pub mod engine;
pub mod geometry;
pub mod histogram;
pub mod kernel;
pub mod math;
pub mod mixture;
pub mod moments;
pub mod observe;
pub mod particles;
pub mod physics;
pub mod prefetch;
pub mod restitution;
pub mod rng;
pub mod rough;
pub mod sample;
pub mod species;
pub mod vec3;
pub mod weighted;
