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
//! On the core, serde and toml only: the command, the C ABI and other front ends read alike.

mod error;
mod histograms;
mod of_physics;
mod overrides;
mod read;
pub mod schema;
mod set;
mod time_axis;
mod validate;
pub use time_axis::TimeAxis;
pub mod vary;

pub use error::Error;
pub use gdsmc_core::physics::{
    BackgroundKernel, Component, DriveChoice, DriveKind, DriveParams, KernelChoice, KernelKind,
    Model, Physics, RestitutionLaw, SchemeChoice,
};
pub use histograms::{Marginal, Shells};
pub use overrides::{
    Override, Sourced, load_with, load_with_overrides, merged_text, parse_with,
    parse_with_overrides,
};
pub(crate) use read::toml_of;
pub use read::{MAX_LINE_CHARS, MAX_SCENE_BYTES, cut_lines, load, parse, read, sweep_plan};
pub use schema::SceneFile;
pub use validate::DEFAULT_STEP_FACTOR;
pub use validate::collisions::COMMON_KEYS as COLLISION_KEYS;

/// A validated scene, ready to run.
#[derive(Debug, Clone)]
pub struct Scene {
    /// Name (file stem when the file names none).
    name: String,
    /// Description.
    description: String,
    /// The physics: particles, initial distribution, kernel, restitution, drive, scheme
    /// (read with [`Scene::physics`], changed only through [`Scene::with_physics`]).
    physics: Physics,
    /// The physics validated by the core: what every run starts from ([`Scene::model`]).
    model: Model,
    /// The key that held each physics parameter in the file (to name a later change's error).
    keys: Vec<(gdsmc_core::physics::Param, String)>,
    /// Observation times, increasing.
    times: Vec<f64>,
    /// Index of the first observation time of the steady-state average, if any (it must leave
    /// two observation times at or after it; [`Scene::set_times`] keeps its start time).
    steady_from: Option<usize>,
    /// Random pairs per observation for the collisional cooling (0: off).
    collisional_pairs: u64,
    /// What the time charts draw against.
    time_axis: TimeAxis,
    /// Velocity snapshot times as asked (each at most the last observation time).
    snapshots: Vec<f64>,
    /// Radial-shell histogram of `|v - V|` at the last observation, if asked.
    histogram: Option<Shells>,
    /// Reduced-speed histogram: shells of `c = |v - V| / sqrt(2 T_bulk)` up to `c_max` (its
    /// `radius`), averaged over the steady-state observations (or the last one), if asked.
    reduced_histogram: Option<Shells>,
    /// Marginal histogram of one velocity component at the first and last observation, if
    /// asked.
    marginal_histogram: Option<Marginal>,
    /// Ensembles.
    ensembles: u64,
    /// Seed.
    seed: u64,
    /// The labels of a mixture's species (empty: one species).
    species_names: Vec<String>,
    /// The mole fractions of a mixture's species, as written (normalized when counted).
    species_fractions: Vec<f64>,
    /// What the scene derived from other keys, in words (`gamma C` from
    /// `collisions.diameter` and `density`).
    derived: Vec<String>,
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
            time_axis,
            snapshots,
            histogram,
            reduced_histogram,
            marginal_histogram,
            ensembles,
            seed,
            species_names,
            species_fractions,
            derived: _,
        } = self;
        (
            name,
            description,
            physics,
            times,
            steady_from,
            (collisional_pairs, time_axis, snapshots),
        ) == (
            &o.name,
            &o.description,
            &o.physics,
            &o.times,
            &o.steady_from,
            (&o.collisional_pairs, &o.time_axis, &o.snapshots),
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

    /// Name (file stem when the file names none).
    #[must_use]
    pub fn name(&self) -> &str {
        &self.name
    }

    /// Description.
    #[must_use]
    pub fn description(&self) -> &str {
        &self.description
    }

    /// Observation times, increasing, from 0 on.
    #[must_use]
    pub fn times(&self) -> &[f64] {
        &self.times
    }

    /// Index of the first observation time of the steady-state average, if any (at least
    /// two observation times lie at or after it).
    #[must_use]
    pub fn steady_from(&self) -> Option<usize> {
        self.steady_from
    }

    /// Random pairs per observation for the collisional cooling: `nu`, `zeta`, `zeta_star`
    /// for every gas, with MS's `mu2`, `mu4` or a mixture's rates where they apply (0: off).
    #[must_use]
    pub fn collisional_pairs(&self) -> u64 {
        self.collisional_pairs
    }

    /// The observations at which velocity snapshots are taken (`observe.snapshots`: the first
    /// observation at or after each time asked), increasing and distinct.
    pub fn snapshots(&self) -> Vec<usize> {
        let mut at: Vec<usize> = (self.snapshots.iter())
            .filter_map(|&x| validate::observe::snapshot_index(&self.times, x).ok())
            .collect();
        at.sort_unstable();
        at.dedup();
        at
    }

    /// What the time charts draw against (`observe.time_axis`).
    pub fn time_axis(&self) -> TimeAxis {
        self.time_axis
    }

    /// Radial-shell histogram of `|v - V|` at the last observation, if asked.
    #[must_use]
    pub fn histogram(&self) -> Option<Shells> {
        self.histogram
    }

    /// Reduced-speed histogram: shells of `c = |v - V| / sqrt(2 T_bulk)` up to `c_max` (its
    /// `radius`), averaged over the steady-state observations (or the last one), if asked.
    #[must_use]
    pub fn reduced_histogram(&self) -> Option<Shells> {
        self.reduced_histogram
    }

    /// Marginal histogram of one velocity component at the first and last observation, if
    /// asked.
    #[must_use]
    pub fn marginal_histogram(&self) -> Option<Marginal> {
        self.marginal_histogram
    }

    /// Ensembles (at least 1).
    #[must_use]
    pub fn ensembles(&self) -> u64 {
        self.ensembles
    }

    /// Seed: ensemble k uses its generator jumped k times.
    #[must_use]
    pub fn seed(&self) -> u64 {
        self.seed
    }

    /// The labels of a mixture's species (empty: one species).
    #[must_use]
    pub fn species_names(&self) -> &[String] {
        &self.species_names
    }

    /// The mole fractions of a mixture's species, as written (normalized when counted).
    #[must_use]
    pub fn species_fractions(&self) -> &[f64] {
        &self.species_fractions
    }

    /// What the scene derived from other keys, in words, for the summary (the kernel's
    /// strength from `collisions.diameter` and `collisions.density`).
    pub fn derived(&self) -> &[String] {
        &self.derived
    }

    /// Whether the translation follows the smooth gas's law, as the engine decides it
    /// ([`gdsmc_core::physics::Physics::translation_is_smooth`]): smooth particles, or rough
    /// ones with `tangential_restitution = -1` whose collisions the engine makes the smooth
    /// ones (hard particles, or spheres of any kernel; rough pseudo-Maxwell disks collide with
    /// the hard-disk impact law). The smooth gas's exact solutions and tail laws apply only
    /// then.
    pub fn translation_is_smooth(&self) -> bool {
        self.physics.translation_is_smooth()
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
        self.histogram.map_or(0, |h| h.weights())
            + self.reduced_histogram.map_or(0, |h| h.weights())
            + self.marginal_histogram.map_or(0, |h| 2 * h.weights())
    }
}
