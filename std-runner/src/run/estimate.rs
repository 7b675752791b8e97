//! The work a run asks for, estimated before it starts, and the limits that refuse absurd
//! runs (a rate, a time or a count so large that the run would take centuries) with the keys
//! to change, before any allocation or simulation.
//!
//! The estimate counts work units per run: candidate events of the grain-grain process (the
//! majorant rate GRW Section 3 / RW (20) times the time), background events of a host medium
//! (BRS (26), its majorant (28) for hard spheres), `n` per observation and per step of a
//! stepped scheme, and the random pairs of the collisional moments at every observation. Rates use a temperature scale: the initial one, or for white noise the
//! stationary one of GRW (13) (Maxwell) or of the energy balance with the hard-sphere collision
//! frequency, whichever is larger. The thermostats heat or cool towards the temperature where
//! their work balances the collisional cooling: the Gaussian thermostat's `dT/dt = 2 zeta T -
//! zeta_0 (T/T0)^s T` (MS (12) against Haff's law, `s = lambda/2`) is solved in closed form (a
//! logistic law for `(T/T0)^s`, which the candidate rate follows), the constant force's
//! (MS (14)) `dT/dt = (2/3) g <|c|>` is bounded by its balance and by the speed it can add. The
//! output phase counts the values written (rows times columns). It is an order of magnitude,
//! shown in the summary; the limit is far above any useful run.

use crate::error::Error;
use crate::scene::{DriveChoice, RestitutionLaw, Scene, SchemeChoice};
use gdsmc_core::drive::WorkInput;
use std::f64::consts::PI;

/// Work units (events and particle updates) a run may need without `--allow-long`: the core's
/// [`gdsmc_core::engine::WORK_LIMIT`], about a day of one core, which the C ABI applies too.
pub const MAX_WORK: f64 = gdsmc_core::engine::WORK_LIMIT;

/// Most worker threads.
pub const MAX_THREADS: usize = 4096;

/// Bytes of particle memory one ensemble may need.
pub const MAX_PARTICLE_BYTES: f64 = 64.0 * (1u64 << 30) as f64;

/// Most values in one ensemble's row (observation times times columns, and histograms): each
/// worker holds one row, the fold two more, and observables.csv writes two text cells per
/// value, so 2^24 values are 128 MiB a row and about a GB of CSV.
pub const MAX_ROW_VALUES: usize = 1 << 24;

/// Work units per value written: formatting a cell of the CSV and a point of a chart costs
/// about as much as a few collision events (measured: 200 ns a value, 1e5 observation times
/// of GRW Example 3 written in 1.4 s).
const OUTPUT_UNITS: f64 = 4.0;

/// The estimate of one run.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct WorkEstimate {
    /// Grain-grain candidate events, all ensembles.
    pub events: f64,
    /// Background (host-medium) events, all ensembles.
    pub background: f64,
    /// Particle updates of observations and of stepped schemes' steps, and the random pairs of
    /// the collisional moments (MS (67)) at every observation, all ensembles.
    pub updates: f64,
    /// Bytes of particles per ensemble.
    pub particle_bytes: f64,
    /// Values in one ensemble's row (observation times times columns, and histograms).
    pub row_values: usize,
    /// The fold of every ensemble's row and the writing of the outputs.
    pub output: f64,
}

impl WorkEstimate {
    /// All work units.
    pub fn total(&self) -> f64 {
        self.events + self.background + self.updates + self.output
    }
}

/// The restitution coefficient the estimates use (here and in the step-error warnings): the
/// constant, or for the impact-speed law BRS (9) its value at unit normal impact speed,
/// `1 - 2 beta0` (in [0, 1]); for a mixture with `pair_restitution`, the coefficient whose
/// dissipation `1 - alpha^2` is the pairs' mean over the random pair of species `(s, t)`, drawn
/// with the mole fractions `x_s x_t` (the scene's own `restitution` is then not used).
pub fn typical_alpha(scene: &Scene) -> f64 {
    let p = scene.physics();
    if !p.pair_restitution.is_empty() {
        let dissipation = pair_mean(p, &p.pair_restitution, |a| 1.0 - a * a);
        return (1.0 - dissipation).max(0.0).sqrt();
    }
    match p.restitution {
        RestitutionLaw::Constant(a) => a,
        RestitutionLaw::ImpactSpeed { beta0, .. } => (1.0 - 2.0 * beta0).clamp(0.0, 1.0),
    }
}

/// The mean of `f` of a per-pair value (`values` in the order of
/// [`gdsmc_core::mixture::pair_index`]) over the random pair of species `(s, t)` drawn with the
/// mole fractions, `sum_{s,t} x_s x_t f(value_st)`.
fn pair_mean(p: &crate::scene::Physics, values: &[f64], f: impl Fn(f64) -> f64) -> f64 {
    let total: f64 = p.species.iter().map(|s| s.count as f64).sum();
    let k = p.species.len();
    let mut mean = 0.0;
    for s in 0..k {
        for t in 0..k {
            let x = p.species[s].count as f64 * p.species[t].count as f64 / (total * total);
            mean += x * f(values[gdsmc_core::mixture::pair_index(k, s, t)]);
        }
    }
    mean
}

/// The estimate for `scene`.
pub fn estimate(scene: &Scene) -> WorkEstimate {
    let p = &scene.physics();
    let n = p.n as f64;
    let t_end = scene.times().last().copied().unwrap_or(0.0);
    let m = scene.ensembles() as f64;
    let t0 = gdsmc_theory::initial::initial_temperature(scene);
    // A kernel that is no power law is estimated with the hard spheres' growth with speed: the
    // estimate is an order of magnitude for the work limit, not a reference.
    let (gc, lambda) = (p.kernel.strength(), p.kernel.exponent().unwrap_or(1.0));
    let alpha = typical_alpha(scene);
    // A rough gas: its noise on rotation heats it too (through the collisions), its start
    // rotational temperature is energy the translation can take, and the tangential
    // restitution dissipates besides alpha (the two terms of the energy change's closed form,
    // weighted alike: an order of magnitude is all the estimate needs).
    // A mixture's pairs each with their own tangential restitution: their mean loss.
    let (noise_rot, t_rot0, rough_loss) = p.rotation.map_or((0.0, 0.0, 0.0), |r| {
        let loss = |beta: f64| (1.0 - beta * beta) * r.kappa / (1.0 + r.kappa);
        let loss = if p.pair_tangential_restitution.is_empty() {
            loss(r.beta)
        } else {
            pair_mean(p, &p.pair_tangential_restitution, loss)
        };
        (r.noise, r.temperature, loss)
    });
    // None, white noise and the host medium are written out; a declared drive gives its own
    // bound ([`gdsmc_core::drive::Declared::work`]: the largest temperature, and the time
    // at the start's collision rate).
    let (s, zeta0) = haff(t0, gc, lambda, alpha);
    let work = scene.model().drive_work(WorkInput {
        t0,
        t_end,
        s,
        zeta0,
    });
    let beta = match p.drive {
        DriveChoice::WhiteNoise(beta) => beta,
        DriveChoice::None | DriveChoice::HostMedium { .. } | DriveChoice::Declared(_) => 0.0,
    };
    let heated = matches!(p.drive, DriveChoice::WhiteNoise(_)) || noise_rot > 0.0;
    let temperature = match p.drive {
        DriveChoice::WhiteNoise(_) | DriveChoice::None if heated => {
            let heating = beta + noise_rot;
            let dissipation = 1.0 - alpha * alpha + rough_loss;
            let stationary = if lambda == 0.0 {
                2.0 * heating / (gc * PI * dissipation)
            } else {
                // 3 beta = (1 - alpha^2)/4 nu T, nu = 4 pi gamma C <|u|>, <|u|> = 4 sqrt(T/pi).
                libm::pow(
                    3.0 * heating / (dissipation * 4.0 * PI.sqrt() * gc),
                    2.0 / 3.0,
                )
            };
            // No dissipation at all: the energy bound (every unit of noise kept).
            let bound = t0 + t_rot0 + 2.0 * heating * t_end;
            t0.max(stationary.min(bound))
        }
        DriveChoice::HostMedium {
            temperature, mass, ..
        } => {
            // Grains of mass m settle at the velocity variance T^B/m (with T^B/m^B the
            // background's own): a mixture's lightest species moves fastest.
            let lightest = p.species.iter().map(|s| s.mass).fold(1.0, f64::min);
            t0.max(temperature / mass).max(temperature / lightest)
        }
        DriveChoice::Declared(_) => work.map_or(t0, |(t, _)| t),
        // Not heated: the start's temperature.
        DriveChoice::WhiteNoise(_) | DriveChoice::None => t0,
    };
    // A rough gas's rotation can hand its energy to the translation.
    let temperature = if p.rotation.is_some() {
        temperature.max(t0 + t_rot0)
    } else {
        temperature
    };
    // Umax = 2 max |v - V|: about sqrt(2 ln n + 3) sqrt(T). The rates are the core's
    // (its majorant and background bounds), from the validated physics.
    let model = scene.model();
    let umax = 2.0 * (temperature * (2.0 * libm::log(n) + 3.0)).sqrt();
    let rate = model.majorant_rate(p.n, umax);
    // A gas with no drive cools (Haff's law for hard spheres): with the cooling rate
    // zeta0 = (1 - alpha^2)/4 nu0 and the rate going as T^(lambda/2), T = T0 (1 + s zeta0
    // t)^(-1/s), s = lambda/2, the rate integrates to ln(1 + s zeta0 t)/(s zeta0) instead of t.
    // A declared drive gives its own time (the Gaussian thermostat: the logistic law of its
    // heating 2 zeta T against the cooling).
    let effective_time = match p.drive {
        DriveChoice::None if !heated && s * zeta0 * t_end > 1e-6 => {
            libm::log1p(s * zeta0 * t_end) / (s * zeta0)
        }
        DriveChoice::Declared(_) => work.map_or(t_end, |(_, time)| time),
        DriveChoice::None | DriveChoice::WhiteNoise(_) | DriveChoice::HostMedium { .. } => t_end,
    };
    // A host medium's grains at a typical speed `sqrt(3 T)`.
    let background = model.background_rate((3.0 * temperature).sqrt()) * n * t_end * m;
    // Weighted particles: the candidates of up to `capacity n` particles, at the majorant's
    // largest transfer (docs/weighted.md); each particle's record and weight.
    let (weighted_events, bytes_per_particle) = match p.scheme {
        SchemeChoice::Weighted(v) => {
            let named = |key| {
                gdsmc_core::declared::named(
                    gdsmc_core::physics::SchemeKind::Weighted.params(),
                    &v,
                    key,
                )
                .unwrap_or(1.0)
            };
            let (tail_kappa, capacity) = (named("tail_kappa"), named("capacity"));
            ((1.0 + tail_kappa) * capacity * capacity, 40.0 * capacity)
        }
        SchemeChoice::NoSplitting
        | SchemeChoice::Euler(_)
        | SchemeChoice::Strang(_)
        | SchemeChoice::TimeStepped(_) => (1.0, 32.0),
    };
    let steps = match p.scheme {
        SchemeChoice::NoSplitting | SchemeChoice::Weighted(_) => 0.0,
        SchemeChoice::Euler(dt) | SchemeChoice::Strang(dt) => t_end / dt,
        SchemeChoice::TimeStepped(f) => {
            // h = f lambda / v0, lambda = 1 / (sqrt 2 4 pi gamma C), v0 = sqrt(2 T).
            let mfp = 1.0 / (2f64.sqrt() * 4.0 * PI * gc);
            t_end / (f * mfp / (2.0 * temperature).sqrt())
        }
    };
    let row_values = crate::run::totals::Totals::row_len_of(scene);
    WorkEstimate {
        row_values,
        output: row_values as f64 * (m + OUTPUT_UNITS),
        events: rate * effective_time * m * weighted_events,
        background,
        updates: (n * (scene.times().len() as f64 + steps)
            + scene.collisional_pairs() as f64 * scene.times().len() as f64)
            * m,
        particle_bytes: bytes_per_particle * n,
    }
}

/// Haff's law for the kernel: `s = lambda/2` and the cooling rate `zeta_0 = (1 - alpha^2)/4
/// nu_0` of the temperature at `t0` (`nu_0 = 4 pi gamma C <|u|>^lambda`, `<|u|> = 4
/// sqrt(T/pi)`), so that `dT/dt = -zeta_0 (T/T0)^s T`.
fn haff(t0: f64, gc: f64, lambda: f64, alpha: f64) -> (f64, f64) {
    let nu0 = 4.0 * PI * gc * libm::pow(4.0 * (t0 / PI).sqrt(), lambda);
    (0.5 * lambda, 0.25 * (1.0 - alpha * alpha) * nu0)
}

/// Refuses a run whose estimate exceeds the limits (the work one only without `allow_long`),
/// naming the keys that set it.
pub fn check(scene: &Scene, threads: usize, allow_long: bool) -> Result<WorkEstimate, Error> {
    if threads > MAX_THREADS {
        return Err(Error::Argument {
            flag: "--threads".into(),
            message: format!("must be at most {MAX_THREADS}, got {threads}"),
        });
    }
    let e = estimate(scene);
    if e.particle_bytes.is_nan() || e.particle_bytes > MAX_PARTICLE_BYTES {
        return Err(Error::Argument {
            flag: "particles.n".into(),
            message: format!(
                "= {} needs {:.3e} bytes of particles per ensemble, above the limit {:.3e} (64 GiB)",
                scene.n(),
                e.particle_bytes,
                MAX_PARTICLE_BYTES
            ),
        });
    }
    if e.row_values > MAX_ROW_VALUES {
        return Err(Error::Argument {
            flag: "observe.intervals".into(),
            message: format!(
                "= {} gives {} observation times and {} values per ensemble ({:.1} GiB a row, \
                 held by every worker, and about {:.0} GB of observables.csv), above the limit \
                 {MAX_ROW_VALUES}: observe fewer times",
                scene.times().len() - 1,
                scene.times().len(),
                e.row_values,
                e.row_values as f64 * 8.0 / (1u64 << 30) as f64,
                e.row_values as f64 * 2.0 * 22.0 / 1e9,
            ),
        });
    }
    let total = e.total();
    if !allow_long && (total.is_nan() || total > MAX_WORK) {
        return Err(Error::Argument {
            flag: "observe.t_end, particles.n, run.ensembles and the rates".into(),
            message: format!(
                "ask for about {total:.1e} events and particle updates ({:.1e} collision candidates, {:.1e} background events, {:.1e} updates of observations and steps, {:.1e} for the outputs), above the limit {MAX_WORK:.0e} (about a day of one core); shorten the run or pass --allow-long",
                e.events, e.background, e.updates, e.output
            ),
        });
    }
    Ok(e)
}
