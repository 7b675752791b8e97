//! A scene made from a physics rather than a file: what a caller that holds a physics (the C
//! ABI's `gdsmc_config`) asks the references of.

use crate::{Error, Physics, Scene, TimeAxis};
use std::path::PathBuf;

impl Scene {
    /// A scene of `physics` observed at `times` and nothing more (no histograms, snapshots,
    /// steady window or collisional pairs; one ensemble, seed 0): what a caller that holds a
    /// physics rather than a file (the C ABI's `gdsmc_config`) asks the references of. The
    /// physics is validated by the core and the times by [`Scene::set_times`]'s rules; a
    /// mixture's species are named `s0`, `s1`, .. with their counts' fractions.
    pub fn of_physics(physics: Physics, times: Vec<f64>) -> Result<Scene, Error> {
        let model = physics.validate().map_err(|e| Error::Invalid {
            path: PathBuf::from("physics"),
            line: 0,
            key: e.param.to_string(),
            message: e.problem.to_string(),
        })?;
        let n = physics.n.max(1) as f64;
        let mut scene = Scene {
            name: String::new(),
            description: String::new(),
            species_names: (0..physics.species.len())
                .map(|k| format!("s{k}"))
                .collect(),
            species_fractions: physics.species.iter().map(|s| s.count as f64 / n).collect(),
            physics,
            model,
            keys: Vec::new(),
            times: vec![0.0],
            steady_from: None,
            collisional_pairs: 0,
            time_axis: TimeAxis::default(),
            snapshots: Vec::new(),
            histogram: None,
            reduced_histogram: None,
            marginal_histogram: None,
            ensembles: 1,
            seed: 0,
            derived: Vec::new(),
        };
        scene.set_times(times)?;
        Ok(scene)
    }
}
