//! Scenes: a TOML file that names only the physics a setting uses.
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
//! kind = "white-noise"        # "white-noise" (then `beta`) | "none"
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
//! default; unknown keys are errors. Values out of their domain are reported with the file,
//! line and dotted key.

use crate::error::Error;
use serde::Deserialize;
use std::path::{Path, PathBuf};
use toml::Spanned;

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
    pub n: Spanned<i64>,
    /// Initial distribution. Default: the standard Maxwellian GRW (27).
    #[serde(default)]
    pub initial: InitialSpec,
}

fn default_n() -> Spanned<i64> {
    Spanned::new(0..0, 1024)
}

impl Default for ParticlesSpec {
    fn default() -> Self {
        ParticlesSpec {
            n: default_n(),
            initial: InitialSpec::default(),
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
    pub drift: Option<Spanned<[f64; 3]>>,
}

fn one() -> Spanned<f64> {
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
    pub drift: Option<Spanned<[f64; 3]>>,
    /// Components of a mixture.
    #[serde(default)]
    pub components: Option<Spanned<Vec<ComponentSpec>>>,
}

/// `collisions.kernel`.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Deserialize)]
#[serde(rename_all = "kebab-case")]
pub enum KernelKind {
    /// Maxwell pseudo-molecules, `B = gamma C_0`.
    Maxwell,
    /// Hard spheres, `B = gamma C_1 |u|`.
    HardSpheres,
    /// Variable hard spheres, `B = gamma C_lambda |u|^lambda`.
    Vhs,
}

/// `[collisions]`.
#[derive(Debug, Clone, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct CollisionsSpec {
    /// The kernel.
    pub kernel: KernelKind,
    /// VHS exponent in [0, 1] (only for `kernel = "vhs"`).
    #[serde(default)]
    pub lambda: Option<Spanned<f64>>,
    /// Collision-rate constant gamma of GRW (1) (> 0). Default 1.
    #[serde(default = "one")]
    pub gamma: Spanned<f64>,
    /// Kernel constant C_lambda (> 0). Default 1/(4 pi).
    #[serde(default = "default_c")]
    pub c: Spanned<f64>,
    /// Restitution coefficient alpha in (0, 1] (a constant law).
    #[serde(default)]
    pub restitution: Option<Spanned<f64>>,
    /// The impact-speed law BRS (9)-(10) instead of a constant: `{ beta0 = ..., delta = ... }`.
    #[serde(default)]
    pub impact_speed_law: Option<Spanned<ImpactSpeedSpec>>,
}

/// `collisions.impact_speed_law`: `1 - e = 2 beta0 |g . n|^delta` (BRS (9)-(10)).
#[derive(Debug, Clone, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct ImpactSpeedSpec {
    /// `beta_0 >= 0`.
    pub beta0: f64,
    /// `delta >= 0` (1/5: viscoelastic spheres).
    pub delta: f64,
}

fn default_c() -> Spanned<f64> {
    Spanned::new(0..0, 1.0 / (4.0 * std::f64::consts::PI))
}

/// `drive.kind`.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Deserialize, Default)]
#[serde(rename_all = "kebab-case")]
pub enum DriveKind {
    /// No drive: the freely cooling gas.
    #[default]
    None,
    /// White-noise heating of strength `beta` (GRW (1), (18)).
    WhiteNoise,
    /// Elastic collisions with a Maxwellian host medium (BRS).
    HostMedium,
    /// The Gaussian thermostat `F = m zeta v` (MS (12)); key `zeta`.
    Gaussian,
    /// The constant-magnitude force along `v`, `F = m g v_hat` (MS (14)); key `g`.
    ConstantForce,
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

/// `[drive]`.
#[derive(Debug, Clone, Deserialize, Default)]
#[serde(deny_unknown_fields)]
pub struct DriveSpec {
    /// Which drive. Default `"none"`.
    #[serde(default)]
    pub kind: DriveKind,
    /// White-noise strength beta >= 0 (required for `"white-noise"`).
    #[serde(default)]
    pub beta: Option<Spanned<f64>>,
    /// Gaussian thermostat rate zeta (required for `"gaussian"`).
    #[serde(default)]
    pub zeta: Option<Spanned<f64>>,
    /// Constant force per unit mass g >= 0 (required for `"constant-force"`).
    #[serde(default)]
    pub g: Option<Spanned<f64>>,
    /// Host medium: background kernel (required for `"host-medium"`).
    #[serde(default)]
    pub kernel: Option<BackgroundKind>,
    /// Host medium: kernel constant C_1 > 0. Default 1.
    #[serde(default)]
    pub c: Option<Spanned<f64>>,
    /// Host medium: number density rho^B > 0. Default 1.
    #[serde(default)]
    pub density: Option<Spanned<f64>>,
    /// Host medium: background particle mass m^B > 0. Default 1.
    #[serde(default)]
    pub mass: Option<Spanned<f64>>,
    /// Host medium: background temperature T^B >= 0. Default 1.
    #[serde(default)]
    pub temperature: Option<Spanned<f64>>,
    /// Host medium: background drift u^B. Default 0.
    #[serde(default)]
    pub drift: Option<Spanned<[f64; 3]>>,
}

/// `scheme.kind`.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Deserialize, Default)]
#[serde(rename_all = "kebab-case")]
pub enum SchemeKind {
    /// The exact no-splitting scheme (GRW Section 3, RW Algorithm 3).
    #[default]
    NoSplitting,
    /// Euler splitting with time step `dt` (RW Algorithm 1).
    Euler,
    /// Strang splitting with time step `dt` (RW Algorithm 2).
    Strang,
    /// The time-stepped scheme of MS Section 3 (hard spheres), step `step_factor` mean free
    /// paths over the thermal speed.
    TimeStepped,
}

/// `[scheme]`.
#[derive(Debug, Clone, Deserialize, Default)]
#[serde(deny_unknown_fields)]
pub struct SchemeSpec {
    /// Which scheme. Default `"no-splitting"`.
    #[serde(default)]
    pub kind: SchemeKind,
    /// Time step (> 0) of the splitting schemes; observation times must be multiples of it.
    #[serde(default)]
    pub dt: Option<Spanned<f64>>,
    /// Time-stepped scheme: `h = step_factor * lambda / v0(t)` (MS: 0.01). Default 0.01.
    #[serde(default)]
    pub step_factor: Option<Spanned<f64>>,
}

/// The validated scheme.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum SchemeChoice {
    /// No splitting.
    NoSplitting,
    /// Euler splitting with this time step.
    Euler(f64),
    /// Strang splitting with this time step.
    Strang(f64),
    /// MS's time-stepped scheme with this step factor.
    TimeStepped(f64),
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
    /// Number of equal intervals between observations (>= 1). Default 32.
    #[serde(default)]
    pub intervals: Option<Spanned<i64>>,
    /// Collisional moments mu2, mu4 (MS (67)) from this many random pairs per observation
    /// (0 or absent: not computed).
    #[serde(default)]
    pub collisional_pairs: Option<Spanned<i64>>,
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

/// The validated kernel.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum KernelChoice {
    /// Maxwell pseudo-molecules with `gamma C_0`.
    Maxwell {
        /// gamma of GRW (1).
        gamma: f64,
        /// C_0.
        c: f64,
    },
    /// Hard spheres.
    HardSpheres {
        /// gamma of GRW (1).
        gamma: f64,
        /// C_1.
        c: f64,
    },
    /// VHS.
    Vhs {
        /// gamma of GRW (1).
        gamma: f64,
        /// C_lambda.
        c: f64,
        /// lambda.
        lambda: f64,
    },
}

/// The validated drive.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum DriveChoice {
    /// No drive.
    None,
    /// White noise with this beta.
    WhiteNoise(f64),
    /// The Gaussian thermostat with this zeta.
    Gaussian(f64),
    /// The constant force with this g.
    ConstantForce(f64),
    /// A Maxwellian host medium (unit-mass grains).
    HostMedium {
        /// Hard-sphere (true) or Maxwell (false) background kernel.
        hard_spheres: bool,
        /// C_1.
        c1: f64,
        /// rho^B.
        density: f64,
        /// m^B.
        mass: f64,
        /// T^B.
        temperature: f64,
        /// u^B.
        drift: [f64; 3],
    },
}

/// The validated initial distribution: weighted Maxwellians `(weight, mass, temperature, drift)`.
#[derive(Debug, Clone, PartialEq)]
pub struct Initial {
    /// Components (one for a plain Maxwellian).
    pub components: Vec<(f64, f64, f64, [f64; 3])>,
}

/// A validated scene, ready to run.
#[derive(Debug, Clone, PartialEq)]
pub struct Scene {
    /// Name (file stem when the file names none).
    pub name: String,
    /// Description.
    pub description: String,
    /// Particles per ensemble.
    pub n: usize,
    /// Initial distribution.
    pub initial: Initial,
    /// Kernel.
    pub kernel: KernelChoice,
    /// Restitution coefficient of a constant law (for the impact-speed law: `1 - 2 beta0`, the
    /// value at unit normal impact speed, used by nothing that assumes a constant law).
    pub restitution: f64,
    /// The impact-speed law `(beta0, delta)` of BRS (9)-(10), when the scene uses it.
    pub impact_speed: Option<(f64, f64)>,
    /// Drive.
    pub drive: DriveChoice,
    /// Scheme.
    pub scheme: SchemeChoice,
    /// Observation times, increasing.
    pub times: Vec<f64>,
    /// Index of the first observation time of the steady-state average, if any.
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
}

impl Scene {
    /// Values each ensemble appends after its observables: the speed histogram, the reduced
    /// histogram and the marginal histograms (first and last observation).
    pub fn extra_len(&self) -> usize {
        self.histogram.map_or(0, |(k, _)| k + 1)
            + self.reduced_histogram.map_or(0, |(k, _)| k + 1)
            + self.marginal_histogram.map_or(0, |(_, k, _)| 2 * (k + 2))
    }
}

/// Turns byte offsets into 1-based line numbers.
struct Lines<'a> {
    path: &'a Path,
    text: &'a str,
}

impl Lines<'_> {
    fn line(&self, span: std::ops::Range<usize>) -> usize {
        if span == (0..0) {
            return 0;
        }
        self.text[..span.start.min(self.text.len())]
            .bytes()
            .filter(|&b| b == b'\n')
            .count()
            + 1
    }
    fn invalid<T>(
        &self,
        span: std::ops::Range<usize>,
        key: &str,
        message: impl Into<String>,
    ) -> Result<T, Error> {
        Err(Error::Invalid {
            path: self.path.to_path_buf(),
            line: self.line(span),
            key: key.to_string(),
            message: message.into(),
        })
    }
}

fn finite(l: &Lines<'_>, v: &Spanned<f64>, key: &str) -> Result<f64, Error> {
    let x = *v.get_ref();
    if x.is_finite() {
        Ok(x)
    } else {
        l.invalid(v.span(), key, format!("must be a finite number, got {x}"))
    }
}

/// A bin or shell count in 1..=100000.
fn count(l: &Lines<'_>, v: &Spanned<i64>, key: &str) -> Result<usize, Error> {
    let k = *v.get_ref();
    if !(1..=100_000).contains(&k) {
        return l.invalid(v.span(), key, format!("must lie in 1..=100000, got {k}"));
    }
    Ok(k as usize)
}

fn positive(l: &Lines<'_>, v: &Spanned<f64>, key: &str) -> Result<f64, Error> {
    let x = finite(l, v, key)?;
    if x > 0.0 {
        Ok(x)
    } else {
        l.invalid(v.span(), key, format!("must be > 0, got {x}"))
    }
}

fn non_negative(l: &Lines<'_>, v: &Spanned<f64>, key: &str) -> Result<f64, Error> {
    let x = finite(l, v, key)?;
    if x >= 0.0 {
        Ok(x)
    } else {
        l.invalid(
            v.span(),
            key,
            format!("must be >= 0 (a negative value is not a rate), got {x}"),
        )
    }
}

fn drift(l: &Lines<'_>, d: &Option<Spanned<[f64; 3]>>, key: &str) -> Result<[f64; 3], Error> {
    match d {
        None => Ok([0.0; 3]),
        Some(d) if d.get_ref().iter().all(|x| x.is_finite()) => Ok(*d.get_ref()),
        Some(d) => l.invalid(d.span(), key, "must be three finite numbers"),
    }
}

fn opt_or_one(v: &Option<Spanned<f64>>) -> Spanned<f64> {
    v.clone().unwrap_or_else(one)
}

impl SceneFile {
    /// Validates the file's values; `path` and `text` are used to name the line of a bad value.
    pub fn validate(&self, path: &Path, text: &str) -> Result<Scene, Error> {
        let l = Lines { path, text };
        let n = *self.particles.n.get_ref();
        if n < 2 {
            return l.invalid(
                self.particles.n.span(),
                "particles.n",
                format!("must be >= 2 (a pair is needed to collide), got {n}"),
            );
        }
        let ini = &self.particles.initial;
        let initial = match ini.kind {
            InitialKind::Maxwellian => {
                if let Some(c) = &ini.components {
                    return l.invalid(
                        c.span(),
                        "particles.initial.components",
                        "is only used with kind = \"mixture\"",
                    );
                }
                let mass = positive(&l, &opt_or_one(&ini.mass), "particles.initial.mass")?;
                let t = non_negative(
                    &l,
                    &opt_or_one(&ini.temperature),
                    "particles.initial.temperature",
                )?;
                let u = drift(&l, &ini.drift, "particles.initial.drift")?;
                Initial {
                    components: vec![(1.0, mass, t, u)],
                }
            }
            InitialKind::Mixture => {
                for (key, span) in [
                    ("mass", ini.mass.as_ref().map(|s| s.span())),
                    ("temperature", ini.temperature.as_ref().map(|s| s.span())),
                    ("drift", ini.drift.as_ref().map(|s| s.span())),
                ] {
                    if let Some(span) = span {
                        return l.invalid(
                            span,
                            &format!("particles.initial.{key}"),
                            "belongs in each of `components` for kind = \"mixture\"",
                        );
                    }
                }
                let Some(components) = &ini.components else {
                    return l.invalid(
                        0..0,
                        "particles.initial.components",
                        "is required with kind = \"mixture\"",
                    );
                };
                if components.get_ref().is_empty() {
                    return l.invalid(
                        components.span(),
                        "particles.initial.components",
                        "must hold at least one component",
                    );
                }
                let mut out = Vec::new();
                for (k, c) in components.get_ref().iter().enumerate() {
                    let key = format!("particles.initial.components[{k}]");
                    let w = non_negative(&l, &c.weight, &format!("{key}.weight"))?;
                    let mass = positive(&l, &c.mass, &format!("{key}.mass"))?;
                    let t = non_negative(&l, &c.temperature, &format!("{key}.temperature"))?;
                    let u = drift(&l, &c.drift, &format!("{key}.drift"))?;
                    out.push((w, mass, t, u));
                }
                if out.len() > crate::ensemble::MAX_COMPONENTS {
                    return l.invalid(
                        components.span(),
                        "particles.initial.components",
                        format!(
                            "holds {} components; at most {} are supported",
                            out.len(),
                            crate::ensemble::MAX_COMPONENTS
                        ),
                    );
                }
                if out.iter().map(|c| c.0).sum::<f64>() <= 0.0 {
                    return l.invalid(
                        components.span(),
                        "particles.initial.components",
                        "weights must not all be 0",
                    );
                }
                Initial { components: out }
            }
        };
        let c = &self.collisions;
        let gamma = positive(&l, &c.gamma, "collisions.gamma")?;
        let cc = positive(&l, &c.c, "collisions.c")?;
        let kernel = match c.kernel {
            KernelKind::Maxwell | KernelKind::HardSpheres if c.lambda.is_some() => {
                let s = c.lambda.as_ref().unwrap().span();
                return l.invalid(s, "collisions.lambda", "is only used with kernel = \"vhs\"");
            }
            KernelKind::Maxwell => KernelChoice::Maxwell { gamma, c: cc },
            KernelKind::HardSpheres => KernelChoice::HardSpheres { gamma, c: cc },
            KernelKind::Vhs => {
                let Some(lam) = &c.lambda else {
                    return l.invalid(
                        0..0,
                        "collisions.lambda",
                        "is required with kernel = \"vhs\"",
                    );
                };
                let x = finite(&l, lam, "collisions.lambda")?;
                if !(0.0..=1.0).contains(&x) {
                    return l.invalid(
                        lam.span(),
                        "collisions.lambda",
                        format!("must lie in [0, 1], got {x}"),
                    );
                }
                KernelChoice::Vhs {
                    gamma,
                    c: cc,
                    lambda: x,
                }
            }
        };
        let (alpha, impact_speed) = match (&c.restitution, &c.impact_speed_law) {
            (Some(r), None) => {
                let alpha = finite(&l, r, "collisions.restitution")?;
                if !(alpha > 0.0 && alpha <= 1.0) {
                    return l.invalid(
                        r.span(),
                        "collisions.restitution",
                        format!("must lie in (0, 1], got {alpha}"),
                    );
                }
                (alpha, None)
            }
            (None, Some(law)) => {
                let ImpactSpeedSpec { beta0, delta } = *law.get_ref();
                if !(beta0.is_finite() && beta0 >= 0.0 && delta.is_finite() && delta >= 0.0) {
                    return l.invalid(law.span(), "collisions.impact_speed_law", format!("needs finite beta0 >= 0 and delta >= 0, got beta0 = {beta0}, delta = {delta}"));
                }
                (1.0 - 2.0 * beta0, Some((beta0, delta)))
            }
            (Some(r), Some(_)) => {
                return l.invalid(
                    r.span(),
                    "collisions.restitution",
                    "and collisions.impact_speed_law exclude each other",
                );
            }
            (None, None) => {
                return l.invalid(
                    0..0,
                    "collisions.restitution",
                    "is required (a coefficient in (0, 1]), or give collisions.impact_speed_law",
                );
            }
        };
        let d = &self.drive;
        let host_keys = [
            ("kernel", d.kernel.is_some()),
            ("c", d.c.is_some()),
            ("density", d.density.is_some()),
            ("mass", d.mass.is_some()),
            ("temperature", d.temperature.is_some()),
            ("drift", d.drift.is_some()),
        ];
        if d.kind != DriveKind::HostMedium
            && let Some((k, _)) = host_keys.iter().find(|(_, set)| *set)
        {
            return l.invalid(
                0..0,
                &format!("drive.{k}"),
                "is only used with kind = \"host-medium\"",
            );
        }
        for (key, kind, v, name) in [
            ("beta", DriveKind::WhiteNoise, &d.beta, "white-noise"),
            ("zeta", DriveKind::Gaussian, &d.zeta, "gaussian"),
            ("g", DriveKind::ConstantForce, &d.g, "constant-force"),
        ] {
            if d.kind != kind
                && let Some(b) = v
            {
                return l.invalid(
                    b.span(),
                    &format!("drive.{key}"),
                    format!("is only used with kind = \"{name}\""),
                );
            }
        }
        let drive = match d.kind {
            DriveKind::None => DriveChoice::None,
            DriveKind::WhiteNoise => match &d.beta {
                Some(b) => DriveChoice::WhiteNoise(non_negative(&l, b, "drive.beta")?),
                None => {
                    return l.invalid(
                        0..0,
                        "drive.beta",
                        "is required with kind = \"white-noise\"",
                    );
                }
            },
            DriveKind::Gaussian => match &d.zeta {
                Some(z) => DriveChoice::Gaussian(finite(&l, z, "drive.zeta")?),
                None => {
                    return l.invalid(0..0, "drive.zeta", "is required with kind = \"gaussian\"");
                }
            },
            DriveKind::ConstantForce => match &d.g {
                Some(g) => DriveChoice::ConstantForce(non_negative(&l, g, "drive.g")?),
                None => {
                    return l.invalid(
                        0..0,
                        "drive.g",
                        "is required with kind = \"constant-force\"",
                    );
                }
            },
            DriveKind::HostMedium => {
                let Some(kernel) = d.kernel else {
                    return l.invalid(
                        0..0,
                        "drive.kernel",
                        "is required with kind = \"host-medium\" (\"maxwell\" or \"hard-spheres\")",
                    );
                };
                DriveChoice::HostMedium {
                    hard_spheres: kernel == BackgroundKind::HardSpheres,
                    c1: positive(&l, &opt_or_one(&d.c), "drive.c")?,
                    density: positive(&l, &opt_or_one(&d.density), "drive.density")?,
                    mass: positive(&l, &opt_or_one(&d.mass), "drive.mass")?,
                    temperature: non_negative(
                        &l,
                        &opt_or_one(&d.temperature),
                        "drive.temperature",
                    )?,
                    drift: drift(&l, &d.drift, "drive.drift")?,
                }
            }
        };
        let t0 = match &self.observe.t_start {
            Some(s) => non_negative(&l, s, "observe.t_start")?,
            None => 0.0,
        };
        let t1 = finite(&l, &self.observe.t_end, "observe.t_end")?;
        if t1 <= t0 {
            return l.invalid(
                self.observe.t_end.span(),
                "observe.t_end",
                format!("must be later than observe.t_start = {t0}, got {t1}"),
            );
        }
        let k = match &self.observe.intervals {
            Some(s) => {
                let k = *s.get_ref();
                if !(1..=10_000_000).contains(&k) {
                    return l.invalid(
                        s.span(),
                        "observe.intervals",
                        format!("must lie in 1..=10000000, got {k}"),
                    );
                }
                k as usize
            }
            None => 32,
        };
        let times: Vec<f64> = (0..=k)
            .map(|i| t0 + (t1 - t0) * i as f64 / k as f64)
            .collect();
        let sch = &self.scheme;
        if sch.kind != SchemeKind::TimeStepped
            && let Some(f) = &sch.step_factor
        {
            return l.invalid(
                f.span(),
                "scheme.step_factor",
                "is only used with kind = \"time-stepped\"",
            );
        }
        let scheme = match (sch.kind, &sch.dt) {
            (SchemeKind::NoSplitting | SchemeKind::TimeStepped, Some(d)) => {
                return l.invalid(
                    d.span(),
                    "scheme.dt",
                    "is only used with kind = \"euler\" or \"strang\"",
                );
            }
            (SchemeKind::NoSplitting, None) => SchemeChoice::NoSplitting,
            (SchemeKind::TimeStepped, None) => {
                if !matches!(kernel, KernelChoice::HardSpheres { .. }) {
                    return l.invalid(0..0, "scheme.kind", "\"time-stepped\" (MS Section 3) needs collisions.kernel = \"hard-spheres\"");
                }
                let f = match &sch.step_factor {
                    Some(f) => positive(&l, f, "scheme.step_factor")?,
                    None => 0.01,
                };
                SchemeChoice::TimeStepped(f)
            }
            (_, None) => {
                return l.invalid(
                    0..0,
                    "scheme.dt",
                    "is required with kind = \"euler\" or \"strang\"",
                );
            }
            (kind, Some(d)) => {
                let dt = positive(&l, d, "scheme.dt")?;
                if let Some(t) = times.iter().find(|&&t| {
                    let k = t / dt;
                    (k - k.round()).abs() > 1e-9 * (1.0 + k)
                }) {
                    return l.invalid(
                        d.span(),
                        "scheme.dt",
                        format!(
                            "must divide every observation time; {t} is not a multiple of {dt}"
                        ),
                    );
                }
                if kind == SchemeKind::Euler {
                    SchemeChoice::Euler(dt)
                } else {
                    SchemeChoice::Strang(dt)
                }
            }
        };
        let steady_from = match &self.observe.steady_from {
            None => None,
            Some(sf) => {
                let x = finite(&l, sf, "observe.steady_from")?;
                match times.iter().position(|&t| t >= x - 1e-12 * (1.0 + x.abs())) {
                    Some(i) if i + 1 < times.len() => Some(i),
                    _ => {
                        return l.invalid(sf.span(), "observe.steady_from", format!("must leave at least two observation times at or after it (t_end = {t1}), got {x}"));
                    }
                }
            }
        };
        let collisional_pairs = match &self.observe.collisional_pairs {
            None => 0,
            Some(k) if *k.get_ref() >= 0 => *k.get_ref() as u64,
            Some(k) => {
                return l.invalid(
                    k.span(),
                    "observe.collisional_pairs",
                    format!("must be >= 0, got {}", k.get_ref()),
                );
            }
        };
        if matches!(drive, DriveChoice::ConstantForce(_)) && scheme == SchemeChoice::NoSplitting {
            return l.invalid(0..0, "scheme.kind", "must be \"time-stepped\", \"euler\" or \"strang\" with drive.kind = \"constant-force\": its momentum-keeping correction (MS (62)) couples all particles at every step, which the lazy no-splitting scheme cannot do");
        }
        let shells = |h: &Option<HistogramSpec>, table: &str| -> Result<_, Error> {
            let Some(h) = h else { return Ok(None) };
            let key = format!("{table}.shells");
            let k = count(&l, &h.shells, &key)?;
            Ok(Some((
                k,
                positive(&l, &h.radius, &format!("{table}.radius"))?,
            )))
        };
        let histogram = shells(&self.histogram, "histogram")?;
        let reduced_histogram = shells(&self.reduced_histogram, "reduced_histogram")?;
        let marginal_histogram = match &self.marginal_histogram {
            None => None,
            Some(h) => {
                let axis = *h.axis.get_ref();
                if !(1..=3).contains(&axis) {
                    return l.invalid(
                        h.axis.span(),
                        "marginal_histogram.axis",
                        format!("must be 1, 2 or 3 (the velocity component), got {axis}"),
                    );
                }
                let k = count(&l, &h.bins, "marginal_histogram.bins")?;
                let r = positive(&l, &h.radius, "marginal_histogram.radius")?;
                Some((axis as usize - 1, k, r))
            }
        };
        if impact_speed.is_some() && collisional_pairs > 0 {
            return l.invalid(0..0, "observe.collisional_pairs", "assumes a constant restitution coefficient (MS (65)-(66)); not available with collisions.impact_speed_law");
        }
        let m = *self.run.ensembles.get_ref();
        if m < 1 {
            return l.invalid(
                self.run.ensembles.span(),
                "run.ensembles",
                format!("must be >= 1, got {m}"),
            );
        }
        let seed = *self.run.seed.get_ref();
        if seed < 0 {
            return l.invalid(
                self.run.seed.span(),
                "run.seed",
                format!("must be >= 0, got {seed}"),
            );
        }
        let name = self.name.clone().unwrap_or_else(|| {
            path.file_stem()
                .map(|s| s.to_string_lossy().into_owned())
                .unwrap_or_default()
        });
        Ok(Scene {
            name,
            description: self.description.clone().unwrap_or_default(),
            n: n as usize,
            initial,
            kernel,
            restitution: alpha,
            impact_speed,
            drive,
            scheme,
            times,
            steady_from,
            collisional_pairs,
            histogram,
            reduced_histogram,
            marginal_histogram,
            ensembles: m as u64,
            seed: seed as u64,
        })
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

/// Reads, parses and validates a scene file.
pub fn load(path: &Path) -> Result<Scene, Error> {
    let text = std::fs::read_to_string(path).map_err(|source| Error::Read {
        path: path.to_path_buf(),
        source,
    })?;
    parse(path, &text)
}

/// Applies `--set key.path=value` overrides to scene text and validates the result. The file
/// is validated first, so its own errors keep their line numbers; an override's error names
/// the override. Values are TOML (`0.4`, `"hard-spheres"`, `[1.0, 0.0, 0.0]`); a bare word
/// that is not TOML is taken as a string (`--set collisions.kernel=vhs`); an empty value removes
/// the key (`--set collisions.restitution=`).
pub fn parse_with_overrides(path: &Path, text: &str, overrides: &[String]) -> Result<Scene, Error> {
    let scene = parse(path, text)?;
    if overrides.is_empty() {
        return Ok(scene);
    }
    let bad = |key: &str, message: String| Error::Invalid {
        path: PathBuf::from("--set"),
        line: 0,
        key: key.to_string(),
        message,
    };
    let mut doc: toml::Table = toml::from_str(text).map_err(|e| Error::Parse {
        path: path.to_path_buf(),
        message: e.to_string(),
    })?;
    for o in overrides {
        let Some((key, raw)) = o.split_once('=') else {
            return Err(bad(o, "must have the form key.path=value".into()));
        };
        let key = key.trim();
        // An empty value removes the key (`--set collisions.restitution=`).
        let remove = raw.trim().is_empty();
        let value: toml::Value = match toml::from_str::<toml::Table>(&format!("v = {raw}")) {
            Ok(mut t) => t.remove("v").expect("parsed"),
            Err(_) => toml::Value::String(raw.trim().to_string()),
        };
        let parts: Vec<&str> = key.split('.').collect();
        if parts.iter().any(|p| p.is_empty()) {
            return Err(bad(key, "is not a dotted key path".into()));
        }
        let mut table = &mut doc;
        for part in &parts[..parts.len() - 1] {
            let entry = table
                .entry(part.to_string())
                .or_insert_with(|| toml::Value::Table(toml::Table::new()));
            table = match entry {
                toml::Value::Table(t) => t,
                _ => return Err(bad(key, format!("`{part}` is a value, not a table"))),
            };
        }
        if remove {
            table.remove(parts[parts.len() - 1]);
        } else {
            table.insert(parts[parts.len() - 1].to_string(), value);
        }
    }
    let merged = toml::to_string(&doc).expect("a table serializes");
    let keys: Vec<&str> = overrides
        .iter()
        .filter_map(|o| o.split_once('=').map(|(k, _)| k.trim()))
        .collect();
    parse(Path::new("--set"), &merged).map_err(|e| match e {
        Error::Invalid { key, message, .. } => bad(&key, message),
        Error::Parse { message, .. } => {
            let first = message.lines().last().unwrap_or("").trim().to_string();
            bad(
                &keys.join(", "),
                format!("does not fit the scene schema: {first}"),
            )
        }
        other => other,
    })
}

/// Reads a scene file and applies `--set` overrides.
pub fn load_with_overrides(path: &Path, overrides: &[String]) -> Result<Scene, Error> {
    let text = std::fs::read_to_string(path).map_err(|source| Error::Read {
        path: path.to_path_buf(),
        source,
    })?;
    parse_with_overrides(path, &text, overrides)
}
