//! Collision maps: the inelastic grain-grain map GRW (3) (with its equivalent impact-parameter
//! and BRS forms) and the elastic grain-background map BRS (2).

pub mod background;
pub mod inelastic;

pub use background::{MassRatio, elastic_background, grain_after_background};
pub use inelastic::{energy_change, inelastic, scattering_direction_from_impact};
