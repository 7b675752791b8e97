//! # gdsmc-scene: scene files
//!
//! A scene is a TOML file that names only the physics a setting uses, when to observe and how
//! many ensembles to run:
//!
//! ```toml
//! name = "GRW Example 3"
//! [particles]
//! n = 1024
//! initial = { kind = "maxwellian", temperature = 1.0 }
//! [collisions]
//! kernel = "maxwell"          # "maxwell" | "hard-spheres" | "vhs" (then `lambda`)
//! gamma = 4.0                 # collision-rate constant of GRW (1)
//! c = 0.07957747154594767     # C_lambda = 1/(4 pi)
//! restitution = 0.5
//! [drive]
//! kind = "white-noise"        # "white-noise" (then `beta`) | "none" | ...
//! beta = 1.0
//! [observe]
//! t_end = 8.0
//! intervals = 32              # observation times k t_end / intervals, k = 0..=intervals
//! [run]
//! ensembles = 1000
//! seed = 1
//! ```
//!
//! Every key but `collisions.kernel`, `collisions.restitution` and `observe.t_end` has a
//! default; unknown keys are errors (every key: `docs/scenes.md`). The physics goes into the
//! core's [`Physics`], whose [`Physics::validate`] holds every physical rule; a bad value is
//! reported with the file, line and dotted key that hold it. Command-line overrides (`--set
//! key=value`, `--n`, `--ensembles`, `--seed`) are applied to the text and validated the same
//! way ([`Override`]).
//!
//! The crate depends on the core, serde and toml only, so the command, the C ABI and other
//! front ends read scenes alike.

mod error;
mod overrides;
pub mod schema;
mod validate;

pub use error::Error;
pub use gdsmc_core::physics::{
    BackgroundKernel, Component, DriveChoice, KernelChoice, Model, Physics, RestitutionLaw,
    SchemeChoice,
};
pub use overrides::{
    Override, Sourced, load_with, load_with_overrides, parse_with, parse_with_overrides,
};
pub use schema::SceneFile;
pub use validate::DEFAULT_STEP_FACTOR;

use std::path::{Path, PathBuf};

/// A validated scene, ready to run.
#[derive(Debug, Clone)]
pub struct Scene {
    /// Name (file stem when the file names none).
    pub name: String,
    /// Description.
    pub description: String,
    /// The physics: particles, initial distribution, kernel, restitution, drive, scheme
    /// (read with [`Scene::physics`], changed only through [`Scene::with_physics`]).
    physics: Physics,
    /// The physics validated by the core: what every run starts from ([`Scene::model`]).
    model: Model,
    /// The key that held each physics parameter in the file (to name a later change's error).
    keys: Vec<(gdsmc_core::physics::Param, String)>,
    /// Observation times, increasing.
    pub times: Vec<f64>,
    /// Index of the first observation time of the steady-state average, if any (it must leave
    /// two observation times at or after it; [`Scene::set_times`] keeps its start time).
    pub steady_from: Option<usize>,
    /// Random pairs per observation for mu2, mu4 (0: off).
    pub collisional_pairs: u64,
    /// Radial-shell histogram `(K, R)` at the last observation, if asked.
    pub histogram: Option<(usize, f64)>,
    /// Reduced-speed histogram `(K, c_max)`: shells of `c = |v - V| / sqrt(2 T_bulk)`,
    /// averaged over the steady-state observations (or the last one), if asked.
    pub reduced_histogram: Option<(usize, f64)>,
    /// Marginal histogram `(axis 0..=2, bins, R)` at the first and last observation, if asked.
    pub marginal_histogram: Option<(usize, usize, f64)>,
    /// Ensembles.
    pub ensembles: u64,
    /// Seed.
    pub seed: u64,
    /// The labels of a mixture's species (empty: one species).
    pub species_names: Vec<String>,
    /// The mole fractions of a mixture's species, as written (normalized when counted).
    pub species_fractions: Vec<f64>,
}

impl PartialEq for Scene {
    /// Every field but the model, which is a function of the physics.
    fn eq(&self, o: &Self) -> bool {
        let Scene {
            name,
            description,
            physics,
            model: _,
            keys: _,
            times,
            steady_from,
            collisional_pairs,
            histogram,
            reduced_histogram,
            marginal_histogram,
            ensembles,
            seed,
            species_names,
            species_fractions,
        } = self;
        (
            name,
            description,
            physics,
            times,
            steady_from,
            collisional_pairs,
        ) == (
            &o.name,
            &o.description,
            &o.physics,
            &o.times,
            &o.steady_from,
            &o.collisional_pairs,
        ) && (
            histogram,
            reduced_histogram,
            marginal_histogram,
            ensembles,
            seed,
        ) == (
            &o.histogram,
            &o.reduced_histogram,
            &o.marginal_histogram,
            &o.ensembles,
            &o.seed,
        ) && (species_names, species_fractions) == (&o.species_names, &o.species_fractions)
    }
}

impl Scene {
    /// Particles per ensemble.
    pub fn n(&self) -> usize {
        self.physics.n
    }

    /// The physics as plain data (validated: [`Scene::model`] is its model).
    pub fn physics(&self) -> &Physics {
        &self.physics
    }

    /// The validated physics every run of the scene starts from: the runner never validates
    /// again.
    pub fn model(&self) -> &Model {
        &self.model
    }

    /// Changes the physics through `f` and validates the result as a scene file's would be:
    /// the core's one validation, then the scene's rules that depend on the physics (every
    /// observation time on a splitting scheme's grid, what collisional pairs and disks allow).
    /// On error the scene is unchanged; the error names the key.
    pub fn with_physics(&mut self, f: impl FnOnce(&mut Physics)) -> Result<(), Error> {
        let mut physics = self.physics.clone();
        f(&mut physics);
        let model = physics.validate().map_err(|e| {
            let key = self.keys.iter().find(|(p, _)| *p == e.param);
            let key = key.map_or_else(|| e.param.to_string(), |(_, k)| k.clone());
            self.invalid(&key, e.problem.to_string())
        })?;
        self.rules(&physics, &self.times)?;
        self.physics = physics;
        self.model = model;
        Ok(())
    }

    /// An error of a change made in code (no line), at `key`.
    fn invalid(&self, key: &str, message: String) -> Error {
        Error::Invalid {
            path: PathBuf::from(format!("scene {}", self.name)),
            line: 0,
            key: key.to_string(),
            message,
        }
    }

    /// The scene's rules that depend on the physics ([`validate::physics_rules`]) for
    /// `physics` observed at `times`.
    fn rules(&self, physics: &Physics, times: &[f64]) -> Result<(), Error> {
        let histograms = (
            self.reduced_histogram.is_some(),
            self.marginal_histogram.is_some(),
        );
        match validate::physics_rules(physics, times, self.collisional_pairs, histograms) {
            Some((key, message)) => Err(self.invalid(key, message)),
            None => Ok(()),
        }
    }

    /// Sets the observation times (finite, from 0 on, increasing), validated against the
    /// physics as [`Scene::with_physics`] does (a splitting scheme's grid). The steady-state
    /// window keeps its start time (`steady_from` becomes the first new time at or after it),
    /// or is dropped (`None`) when fewer than two new times lie in it. Set the times
    /// first when both change. On error the scene is unchanged.
    pub fn set_times(&mut self, times: Vec<f64>) -> Result<(), Error> {
        let ordered = times.windows(2).all(|w| w[0] < w[1]);
        if times.is_empty() || !ordered || !times.iter().all(|t| t.is_finite() && *t >= 0.0) {
            return Err(self.invalid(
                "observe.times",
                "must be finite, from 0 on and increasing".to_string(),
            ));
        }
        self.rules(&self.physics, &times)?;
        // The steady window starts at the same time: its first new observation at or after
        // the old start (an index into the old times means nothing in the new ones). Times that
        // leave it fewer than two observations have no steady window.
        let steady_from = self.steady_from.and_then(|k| {
            let start = self.times.get(k).copied().unwrap_or(f64::INFINITY);
            let first = times.iter().position(|&t| t >= start)?;
            (first + 2 <= times.len()).then_some(first)
        });
        self.times = times;
        self.steady_from = steady_from;
        Ok(())
    }

    /// Sets the particle count, and a mixture's species counts from their fractions as the
    /// file's `particles.n` does (`validate::species::counts`), validated as
    /// [`Scene::with_physics`] does (a species left without a particle is refused).
    pub fn set_n(&mut self, n: usize) -> Result<(), Error> {
        let fractions = self.species_fractions.clone();
        self.with_physics(|ph| {
            ph.n = n;
            if !fractions.is_empty() {
                let counts = validate::species::counts(&fractions, n);
                for (s, c) in ph.species.iter_mut().zip(counts) {
                    s.count = c;
                }
            }
        })
    }

    /// Whether the translation follows the smooth gas's law: smooth particles, or rough ones
    /// with `tangential_restitution = -1` (no collision touches the rotation, and the
    /// translation's collisions are the smooth ones). The smooth gas's exact solutions and
    /// tail laws apply only then.
    pub fn translation_is_smooth(&self) -> bool {
        self.physics.rotation.is_none_or(|r| r.beta == -1.0)
    }

    /// Whether the particles are disks (`particles.dimension = 2`).
    pub fn is_disks(&self) -> bool {
        self.physics.dimension == gdsmc_core::physics::DimensionChoice::Two
    }

    /// The dimension `d`: 3 for spheres, 2 for disks.
    pub fn dimension(&self) -> usize {
        self.physics.dimension.d()
    }

    /// Values each ensemble appends after its observables: the speed histogram, the reduced
    /// histogram and the marginal histograms (first and last observation).
    pub fn extra_len(&self) -> usize {
        self.histogram.map_or(0, |(k, _)| k + 1)
            + self.reduced_histogram.map_or(0, |(k, _)| k + 1)
            + self.marginal_histogram.map_or(0, |(_, k, _)| 2 * (k + 2))
    }
}

/// Parses and validates scene text; `path` names the source in errors.
pub fn parse(path: &Path, text: &str) -> Result<Scene, Error> {
    let file: SceneFile = toml::from_str(text).map_err(|e| Error::Parse {
        path: PathBuf::from(path),
        message: e.to_string().trim_end().to_string(),
    })?;
    file.validate(path, text)
}

/// Reads a scene file.
pub(crate) fn read(path: &Path) -> Result<String, Error> {
    std::fs::read_to_string(path).map_err(|source| Error::Read {
        path: path.to_path_buf(),
        source,
    })
}

/// Reads, parses and validates a scene file.
pub fn load(path: &Path) -> Result<Scene, Error> {
    parse(path, &read(path)?)
}
