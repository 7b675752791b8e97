//! The scene file as written: one serde struct per TOML table, unknown keys refused, values
//! kept with their byte spans so that errors can name the line.

use serde::Deserialize;
use toml::Spanned;

mod collisions;
mod drive;
mod scheme;
pub use collisions::CollisionsSpec;
pub use drive::DriveSpec;
pub use scheme::SchemeSpec;

/// A scene file as written.
#[derive(Debug, Clone, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct SceneFile {
    /// Human-readable name.
    #[serde(default)]
    pub name: Option<String>,
    /// Free text: which paper and example the scene reproduces.
    #[serde(default)]
    pub description: Option<String>,
    /// Particle count and initial distribution.
    #[serde(default)]
    pub particles: ParticlesSpec,
    /// Kernel and restitution.
    pub collisions: CollisionsSpec,
    /// What acts between collisions (default: no drive).
    #[serde(default)]
    pub drive: DriveSpec,
    /// The scheme (default: the exact no-splitting scheme).
    #[serde(default)]
    pub scheme: SchemeSpec,
    /// Observation times.
    pub observe: ObserveSpec,
    /// Ensembles and seed.
    #[serde(default)]
    pub run: RunSpec,
    /// Radial-shell histogram of the speed at the last observation time (GRW (31)-(33)).
    #[serde(default)]
    pub histogram: Option<HistogramSpec>,
    /// Histogram of the reduced speed `c = |v - V| / v0` (MS): f(c), Delta(c), G(c).
    #[serde(default)]
    pub reduced_histogram: Option<HistogramSpec>,
    /// Marginal histogram of one velocity component (BRS Figure 4).
    #[serde(default)]
    pub marginal_histogram: Option<MarginalSpec>,
    /// `[[species]]`: the species of a granular mixture (none: one species).
    #[serde(default)]
    pub species: Option<Spanned<Vec<SpeciesSpec>>>,
    /// `[rotation]`: rough particles (none: smooth particles).
    #[serde(default)]
    pub rotation: Option<RotationSpec>,
    /// `[sweep]`: the keys `gdsmc sweep` varies when it is given no `--vary` (`gdsmc run`
    /// runs the scene as written).
    #[serde(default)]
    pub sweep: Option<SweepSpec>,
}

/// `[sweep]`: what `gdsmc sweep` varies, in the syntax of its `--vary`.
#[derive(Debug, Clone, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct SweepSpec {
    /// `KEY=VALUES` strings, e.g. `["collisions.restitution=0.3:0.9:7"]`.
    pub vary: Spanned<Vec<String>>,
    /// Pair the k-th values of every key instead of making a grid (default false).
    #[serde(default)]
    pub zip: bool,
}

/// `[rotation]`: rough particles with tangential restitution (Huthmann and Zippelius 1997);
/// their normal restitution is `collisions.restitution`.
#[derive(Debug, Clone, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct RotationSpec {
    /// Tangential restitution beta in [-1, 1] (-1: smooth, 1: perfectly rough).
    pub tangential_restitution: Spanned<f64>,
    /// Reduced moment of inertia kappa: in (0, 2/3] for spheres, default 2/5 (uniform
    /// spheres); in (0, 1] for disks, default 1/2 (uniform disks).
    #[serde(default)]
    pub inertia: Option<Spanned<f64>>,
    /// Start rotational temperature (>= 0), a Maxwellian of the angular velocities. Default 1.
    #[serde(default = "default_rotation_temperature")]
    pub temperature: Spanned<f64>,
    /// White-noise strength on rotation (>= 0): `dT_rot/dt = 2 noise` from it alone, as
    /// `drive.beta` gives `dT_tr/dt = 2 beta`. Default 0.
    #[serde(default = "default_rotation_noise")]
    pub noise: Spanned<f64>,
    /// A mixture's tangential restitution per species pair: a symmetric matrix, one row per
    /// species (default: `tangential_restitution` for every pair).
    #[serde(default)]
    pub pair_tangential_restitution: Option<Spanned<Vec<Vec<f64>>>>,
}

/// The core's defaults of a rough gas (`RotationChoice::spheres`), one place for every front
/// end.
fn default_rotation() -> gdsmc_core::physics::RotationChoice {
    gdsmc_core::physics::RotationChoice::spheres(-1.0)
}

fn default_rotation_temperature() -> Spanned<f64> {
    Spanned::new(0..0, default_rotation().temperature)
}

fn default_rotation_noise() -> Spanned<f64> {
    Spanned::new(0..0, default_rotation().noise)
}

/// One `[[species]]` table: a species of a granular mixture (Garzó and Dufty 1999).
#[derive(Debug, Clone, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct SpeciesSpec {
    /// A label for outputs. Default `s0`, `s1`, ...
    #[serde(default)]
    pub name: Option<String>,
    /// Mole (number) fraction > 0; the fractions are normalized, and species `s` gets
    /// `x_s n` particles rounded (largest remainders), at least one.
    pub fraction: Spanned<f64>,
    /// Mass (> 0). Default 1.
    #[serde(default = "one")]
    pub mass: Spanned<f64>,
    /// Start temperature (>= 0) of the species' Maxwellian. Default 1.
    #[serde(default = "one")]
    pub temperature: Spanned<f64>,
    /// Diameter (> 0): the pair `(s, t)` has the kernel constant `c ((d_s + d_t)/2)^2`.
    /// Default 1.
    #[serde(default = "one")]
    pub diameter: Spanned<f64>,
    /// White-noise strength of this species (with `drive.kind = "white-noise"`). Default:
    /// `drive.beta`.
    #[serde(default)]
    pub beta: Option<Spanned<f64>>,
    /// Rough particles: this species' reduced moment of inertia kappa. Default:
    /// `rotation.inertia`.
    #[serde(default)]
    pub inertia: Option<Spanned<f64>>,
    /// Rough particles: this species' start rotational temperature
    /// `T_rot = m kappa <|w|^2>/d_rot` (>= 0). Default: `rotation.temperature`.
    #[serde(default)]
    pub rotation_temperature: Option<Spanned<f64>>,
    /// Rough particles: the white-noise strength on this species' rotation (>= 0). Default:
    /// `rotation.noise`.
    #[serde(default)]
    pub rotation_noise: Option<Spanned<f64>>,
}

/// `[marginal_histogram]`: `bins` bins over `[-radius, radius)` of velocity component `axis`.
#[derive(Debug, Clone, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct MarginalSpec {
    /// Component 1, 2 or 3 (BRS's `v_1`, `v_2`, `v_3`). Default 1.
    #[serde(default = "default_axis")]
    pub axis: Spanned<i64>,
    /// Number of bins.
    pub bins: Spanned<i64>,
    /// Half-width R of the binned range.
    pub radius: Spanned<f64>,
}

fn default_axis() -> Spanned<i64> {
    Spanned::new(0..0, 1)
}

/// `[histogram]`: `shells` (K) shells of width `radius / shells`, plus `|v| >= radius`.
#[derive(Debug, Clone, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct HistogramSpec {
    /// Number of shells K (GRW: 128).
    pub shells: Spanned<i64>,
    /// Outer radius R (GRW: 40, 16, 24 for Examples 6-8).
    pub radius: Spanned<f64>,
}

/// `[particles]`.
#[derive(Debug, Clone, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct ParticlesSpec {
    /// Number of particles per ensemble (>= 2). Default 1024.
    #[serde(default = "default_n")]
    pub n: Spanned<usize>,
    /// Initial distribution. Default: the standard Maxwellian GRW (27).
    #[serde(default)]
    pub initial: InitialSpec,
    /// The dimension: 3 (spheres, the default) or 2 (disks: velocities in a plane).
    #[serde(default)]
    pub dimension: Option<Spanned<i64>>,
    /// How the sample's total momentum starts: `"drawn"` (the default: independent draws) or
    /// `"exact"` (the draws shifted onto the distribution's mean,
    /// [`gdsmc_core::physics::Momentum`]).
    #[serde(default)]
    pub momentum: Option<Spanned<String>>,
}

fn default_n() -> Spanned<usize> {
    Spanned::new(0..0, 1024)
}

impl Default for ParticlesSpec {
    fn default() -> Self {
        ParticlesSpec {
            n: default_n(),
            initial: InitialSpec::default(),
            dimension: None,
            momentum: None,
        }
    }
}

/// One weighted component of a mixture (BRS (35)).
#[derive(Debug, Clone, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct ComponentSpec {
    /// Weight (>= 0; weights need not sum to one).
    pub weight: Spanned<f64>,
    /// Mass (> 0). Default 1.
    #[serde(default = "one")]
    pub mass: Spanned<f64>,
    /// Temperature (>= 0). Default 1.
    #[serde(default = "one")]
    pub temperature: Spanned<f64>,
    /// Drift velocity. Default 0.
    #[serde(default)]
    pub drift: Option<Spanned<Vector3>>,
}

/// A velocity as written: a TOML array of exactly three numbers. Serde's own `[f64; 3]` stops
/// reading after three elements and drops the rest silently (`drift = [1, 2, 3, 4]` read as
/// `[1, 2, 3]`); this type refuses any other length.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct Vector3(pub [f64; 3]);

impl<'de> Deserialize<'de> for Vector3 {
    fn deserialize<D: serde::Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        let v = Vec::<f64>::deserialize(d)?;
        <[f64; 3]>::try_from(v.as_slice())
            .map(Vector3)
            .map_err(|_| serde::de::Error::invalid_length(v.len(), &"an array of 3 numbers"))
    }
}

/// The kind a scene word names among `kinds` (`(word, kind)`), or the error that lists them:
/// "unknown kernel `vsh`, expected one of `maxwell`, `hard-spheres`, `vhs`".
fn kind_word<K>(
    value: toml::Value,
    what: &str,
    kinds: impl Iterator<Item = (&'static str, K)>,
) -> Result<K, String> {
    let word = String::deserialize(value).map_err(|e| e.to_string())?;
    let mut words = Vec::new();
    for (w, k) in kinds {
        if w == word {
            return Ok(k);
        }
        words.push(w);
    }
    Err(format!(
        "unknown {what} `{word}`, expected one of `{}`",
        words.join("`, `")
    ))
}

pub(crate) fn one() -> Spanned<f64> {
    Spanned::new(0..0, 1.0)
}

/// `particles.initial.kind`.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Deserialize, Default)]
#[serde(rename_all = "kebab-case")]
pub enum InitialKind {
    /// A Maxwellian (BRS (36)) with `mass`, `temperature`, `drift`.
    #[default]
    Maxwellian,
    /// A mixture of Maxwellians (BRS (35)) given as `components`.
    Mixture,
}

/// `particles.initial`.
#[derive(Debug, Clone, Deserialize, Default)]
#[serde(deny_unknown_fields)]
pub struct InitialSpec {
    /// Which kind of distribution. Default `"maxwellian"`.
    #[serde(default)]
    pub kind: InitialKind,
    /// Mass of the Maxwellian (> 0). Default 1.
    #[serde(default)]
    pub mass: Option<Spanned<f64>>,
    /// Temperature of the Maxwellian (>= 0). Default 1.
    #[serde(default)]
    pub temperature: Option<Spanned<f64>>,
    /// Drift of the Maxwellian. Default 0.
    #[serde(default)]
    pub drift: Option<Spanned<Vector3>>,
    /// Components of a mixture.
    #[serde(default)]
    pub components: Option<Spanned<Vec<ComponentSpec>>>,
}

/// `drive.kernel` of a host medium.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Deserialize)]
#[serde(rename_all = "kebab-case")]
pub enum BackgroundKind {
    /// `B_1 = C_1` (BRS (11)).
    Maxwell,
    /// `B_1 = C_1 |g|` (BRS (19)).
    HardSpheres,
}

/// `[observe]`.
#[derive(Debug, Clone, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct ObserveSpec {
    /// Start time. Default 0.
    #[serde(default)]
    pub t_start: Option<Spanned<f64>>,
    /// Final time (> t_start).
    pub t_end: Spanned<f64>,
    /// Number of intervals between observations (>= 1). Default 32.
    #[serde(default)]
    pub intervals: Option<Spanned<i64>>,
    /// How the observation times are spaced: `"linear"` (equal intervals, the default) or
    /// `"log"` (the start, then `intervals` times evenly spaced in `log(t - t_start)` from
    /// `first` to `t_end`: decades of a cooling gas at equal resolution).
    #[serde(default)]
    pub spacing: Option<Spanned<String>>,
    /// What the time charts draw against: `"time"` (the scene's time, the default) or
    /// `"collisions"` (collisions per particle `s`, the usual axis of cooling-state studies).
    #[serde(default)]
    pub time_axis: Option<Spanned<String>>,
    /// With `spacing = "log"`: the first observation after the start, as a time after
    /// `t_start` (> 0, below `t_end - t_start`; checked, and ignored by the linear spacing).
    /// Default `(t_end - t_start) / intervals`.
    #[serde(default)]
    pub first: Option<Spanned<f64>>,
    /// The collisional cooling from this many random pairs per observation (0 or absent: not
    /// computed): the collision frequency `nu`, `zeta` and `zeta_star` for every gas, MS's
    /// moments mu2, mu4 (MS (67)) for smooth spheres of one species and a constant
    /// coefficient, a smooth mixture's cooling rates.
    #[serde(default)]
    pub collisional_pairs: Option<Spanned<i64>>,
    /// Velocity snapshots: at the first observation time at or after each of these times, every
    /// ensemble's particles are written to a state file (docs/state.md). Optional.
    #[serde(default)]
    pub snapshots: Option<Spanned<Vec<f64>>>,
    /// Steady state: average every observable over the observation times `t >= steady_from`
    /// (per ensemble, then over ensembles; RW Section 4.2). Optional.
    #[serde(default)]
    pub steady_from: Option<Spanned<f64>>,
}

/// `[run]`.
#[derive(Debug, Clone, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct RunSpec {
    /// Number of independent ensembles (>= 1). Default 100.
    #[serde(default = "default_ensembles")]
    pub ensembles: Spanned<i64>,
    /// Seed of the run's generator. Default 1.
    #[serde(default = "default_seed")]
    pub seed: Spanned<i64>,
}

fn default_ensembles() -> Spanned<i64> {
    Spanned::new(0..0, 100)
}
fn default_seed() -> Spanned<i64> {
    Spanned::new(0..0, 1)
}

impl Default for RunSpec {
    fn default() -> Self {
        RunSpec {
            ensembles: default_ensembles(),
            seed: default_seed(),
        }
    }
}
