//! The scene's initial distribution and its temperature: where every exact solution starts.

use gdsmc_core::physics::MAX_COMPONENTS;
use gdsmc_core::sample::MaxwellianMixture;
use gdsmc_scene::Scene;

/// The initial distribution of a scene as a core sampler.
pub fn initial_sampler(scene: &Scene) -> MaxwellianMixture<MAX_COMPONENTS> {
    scene.model().initial().clone()
}

/// The temperature of a scene's initial distribution, per degree of freedom of its dimension
/// (the drifts' spread counts over `d` components).
pub fn initial_temperature(scene: &Scene) -> f64 {
    initial_sampler(scene).temperature_in(scene.dimension())
}
