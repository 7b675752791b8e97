//! summary.json as types: what a run records beside its tables (scene, seed, version, timing,
//! collision counts, errors against the references, steady-state averages, tail fit, reduced
//! distribution, thermostat balance, warnings). Written with its keys in alphabetical order at
//! every level (serde_json's map order), so the file's bytes do not depend on field order here.

use crate::run::RunStats;
use crate::scene::Scene;
use gdsmc_theory::curves::ReferenceCurve;
use serde::Serialize;
use std::collections::BTreeMap;

/// The whole of summary.json.
#[derive(Clone, Debug, Serialize)]
pub struct Summary {
    /// The gdsmc version that wrote it.
    pub gdsmc_version: &'static str,
    /// The version of the random streams the run drew from
    /// ([`gdsmc_core::rng::STREAM_VERSION`]): the same scene and seed give the same numbers
    /// only under the same stream version.
    pub stream_version: u32,
    /// The scene's name.
    pub scene: String,
    /// The scene's description.
    pub description: String,
    /// Particles per ensemble.
    pub n: usize,
    /// Ensembles in the statistics.
    pub ensembles: u64,
    /// Ensembles the scene asks for (more than `ensembles` when interrupted).
    pub ensembles_requested: u64,
    /// Whether the run was stopped before every ensemble finished.
    pub interrupted: bool,
    /// The run's seed.
    pub seed: u64,
    /// Worker threads.
    pub threads: usize,
    /// Wall-clock seconds.
    pub wall_seconds: f64,
    /// CPU seconds, all threads.
    pub cpu_seconds: f64,
    /// Event counts summed over the ensembles.
    pub counts: Counts,
    /// The run's errors against each reference curve.
    pub errors: Vec<ReferenceError>,
    /// Steady-state averages, when the scene asks for them.
    pub steady_state: Option<Steady>,
    /// The fitted tail exponent, when the scene has a histogram to fit.
    pub tail: Option<Tail>,
    /// MS's reduced distribution, when the scene asks for it.
    pub reduced_distribution: Option<Reduced>,
    /// The reduced tail's power law, when the reduced histogram has one to measure.
    pub power_tail: Option<PowerTail>,
    /// The Gaussian thermostat's balance, for a thermostatted scene.
    pub thermostat: Option<Thermostat>,
    /// Warnings: what fired, how large the error is expected to be, what to do.
    pub warnings: Vec<Warning>,
    /// Why no interval is given (one ensemble), when none is.
    pub no_intervals: Option<String>,
}

/// The event counts of summary.json (the core's `Counts` under the file's names).
#[derive(Clone, Debug, Serialize)]
pub struct Counts {
    /// Candidate pairs drawn (events of the majorant process).
    pub candidates: u64,
    /// Real collisions (candidates accepted).
    pub collisions: u64,
    /// Fictitious collisions (candidates rejected, GRW (20)).
    pub fictitious: u64,
    /// Candidates faster than the majorant that generated their waiting time (RW (19)).
    pub majorant_overshoots: u64,
    /// Collisions whose restitution law gave a value outside [0, 1], clamped to it.
    pub restitution_clamped: u64,
    /// Majorant refreshes between observations.
    pub majorant_refreshes: u64,
    /// Rescalings of a cooling gas's stored velocities.
    pub rescales: u64,
    /// Real collisions with the host medium's background (BRS (26) events).
    pub background_collisions: u64,
    /// Observations (synchronizing kicks of all particles).
    pub observations: u64,
    /// Single-particle kicks: two per candidate and n per observation (RW Section 4.2).
    pub kicks: u64,
}

/// A run's error against one reference curve: relative where the reference is non-zero,
/// absolute where it vanishes (the components of V).
#[derive(Clone, Debug, Serialize)]
pub struct ReferenceError {
    /// The observable's column.
    pub observable: &'static str,
    /// The reference's column.
    pub reference: &'static str,
    /// Where the reference comes from (paper and equation).
    pub source: &'static str,
    /// The error at the last observation time.
    #[serde(rename = "E_end")]
    pub e_end: f64,
    /// The 99.9% half-width there, on the same scale.
    #[serde(rename = "Conf_end")]
    pub conf_end: f64,
    /// The largest error over the observation times where the reference is computable (null
    /// when it is at none).
    #[serde(rename = "E_max")]
    pub e_max: f64,
    /// The observation times where the reference is not computable (its arithmetic leaves the
    /// range of f64 there; the column holds NaN): flagged, never an error of 0.
    pub not_computable: usize,
    /// The time of the largest error.
    #[serde(rename = "t_of_E_max")]
    pub t_of_e_max: f64,
}

/// Steady-state averages: every observable's mean over the window with its interval.
#[derive(Clone, Debug, Serialize)]
pub struct Steady {
    /// The window's first observation time.
    pub from: f64,
    /// Observation times in the window.
    pub points: usize,
    /// Each observable's window mean and interval, by column name.
    pub observables: BTreeMap<String, MeanCi>,
}

/// A mean with the half-width of its 99.9% interval.
#[derive(Clone, Copy, Debug, Serialize)]
pub struct MeanCi {
    /// The mean.
    pub mean: f64,
    /// The half-width of its 99.9% interval.
    pub ci: f64,
}

/// The tail fit of the radial histogram (GRW (16)).
#[derive(Clone, Debug, Serialize)]
pub struct Tail {
    /// The first shell of the fit.
    pub k0: usize,
    /// The fitted exponent.
    pub slope: f64,
    /// Its 99.9% half-width.
    pub slope_ci: f64,
    /// Shells in the fit.
    pub shells_used: usize,
    /// The exponent GRW (16) predicts for the scene's kernel (null for a kernel that is not a
    /// power law).
    pub reference_exponent_grw_16: Option<f64>,
    /// The fit of the inner and outer halves (whether the tail is asymptotic).
    pub halves: Option<Halves>,
}

/// The tail fit's two halves.
#[derive(Clone, Debug, Serialize)]
pub struct Halves {
    /// The inner half.
    pub inner: HalfFit,
    /// The outer half.
    pub outer: HalfFit,
}

/// One half of the tail fit.
#[derive(Clone, Debug, Serialize)]
pub struct HalfFit {
    /// Its exponent.
    pub slope: f64,
    /// Its 99.9% half-width.
    pub slope_ci: f64,
    /// Its first and last shell.
    pub shells: [usize; 2],
}

/// MS's reduced distribution: a2 and the tail law, the shells in reduced.csv.
#[derive(Clone, Debug, Serialize)]
pub struct Reduced {
    /// The second Sonine coefficient.
    pub a2: f64,
    /// Its 99.9% half-width.
    pub a2_ci: f64,
    /// The tail law compared with, when one applies.
    pub tail_law: Option<TailLaw>,
    /// The file holding the shells.
    pub file: &'static str,
}

/// The reduced tail's measured power law ([`crate::analysis::power_tail`]).
#[derive(Clone, Debug, Serialize)]
pub struct PowerTail {
    /// The farthest resolved window `[x, 2x]`, when one is.
    pub window: Option<[f64; 2]>,
    /// Its slope: the measured exponent `s` of `P(c >= x) ~ x^-s`.
    pub exponent: Option<f64>,
    /// Its 99.9% half-width.
    pub exponent_ci: Option<f64>,
    /// The exponent extrapolated from the local slopes of the farthest resolved window `[x,
    /// 2x]` whose `x/2` is an edge and of `[x/2, x]`: `s(x) + (s(x) - s(x/2))/3` (their `x^-2`
    /// approach removed).
    pub extrapolated: Option<f64>,
    /// Its 99.9% half-width.
    pub extrapolated_ci: Option<f64>,
    /// Its outer window `[x, 2x]`.
    pub extrapolated_window: Option<[f64; 2]>,
    /// The exact exponent, when the scene's model has one.
    pub exact: Option<f64>,
    /// The verdict: the exact root within the extrapolated exponent's interval (none without
    /// both, when the interval is as wide as the value or when the window is pre-asymptotic).
    pub agrees: Option<bool>,
    /// The extrapolated window lies nearer than `x = 7`, where no verdict is given
    /// ([`crate::analysis::power_tail::JUDGED_FROM`]).
    pub pre_asymptotic: bool,
    /// The form of the inelastic Maxwell model the exact root is of (`"scattering"`: GRW (3),
    /// `e` uniform; `"impact"`: Ernst and Brito's, `n` uniform).
    pub form: &'static str,
    /// The file holding every window's slope.
    pub file: &'static str,
}

/// A tail law of MS (69), (71) or (77).
#[derive(Clone, Debug, Serialize)]
pub struct TailLaw {
    /// The equation.
    pub equation: &'static str,
    /// Its amplitude.
    pub amplitude: f64,
    /// Its power.
    pub power: f64,
    /// Where its mu2 comes from.
    pub mu2_from: &'static str,
}

/// The Gaussian thermostat's balance (MS Section 2).
#[derive(Clone, Debug, Serialize)]
pub struct Thermostat {
    /// The thermostat's strength.
    pub zeta: f64,
    /// The cooling constant.
    pub cooling_constant: f64,
    /// The temperature at which heating and cooling balance, when they do.
    pub steady_temperature: Option<f64>,
    /// The strength that holds the initial temperature.
    pub holding_zeta: f64,
    /// The balance in words.
    pub note: String,
}

/// A warning.
#[derive(Clone, Debug, Serialize)]
pub struct Warning {
    /// Its short code.
    pub code: &'static str,
    /// What fired, how large the error is expected to be, and what to do.
    pub message: String,
}

impl Summary {
    /// The summary of `stats` (a run of `scene`) against the reference curves `refs`.
    pub fn of(scene: &Scene, stats: &RunStats, refs: &[ReferenceCurve]) -> Self {
        let c = stats.counts;
        Summary {
            gdsmc_version: env!("CARGO_PKG_VERSION"),
            stream_version: gdsmc_core::rng::STREAM_VERSION,
            scene: scene.name().to_string(),
            description: scene.description().to_string(),
            n: scene.n(),
            ensembles: stats.ensembles,
            ensembles_requested: scene.ensembles(),
            interrupted: stats.ensembles < scene.ensembles(),
            seed: scene.seed(),
            threads: stats.threads,
            wall_seconds: stats.wall.as_secs_f64(),
            cpu_seconds: stats.cpu.as_secs_f64(),
            counts: Counts {
                candidates: c.candidates,
                collisions: c.collisions,
                fictitious: c.fictitious,
                majorant_overshoots: c.overshoots,
                restitution_clamped: c.clamped,
                majorant_refreshes: c.refreshes,
                rescales: c.rescales,
                background_collisions: c.background,
                observations: c.observations,
                kicks: c.kicks(scene.n()),
            },
            errors: refs.iter().map(|r| ReferenceError::of(stats, r)).collect(),
            steady_state: Steady::of(stats),
            tail: Tail::of(scene, stats),
            reduced_distribution: crate::analysis::distribution::reduced(scene, stats).map(|r| {
                Reduced {
                    a2: r.a2.0,
                    a2_ci: r.a2.1,
                    tail_law: r.tail.map(|t| TailLaw {
                        equation: t.equation,
                        amplitude: t.amplitude,
                        power: t.power,
                        mu2_from: t.mu2_source,
                    }),
                    file: "reduced.csv",
                }
            }),
            power_tail: crate::analysis::power_tail::measure(scene, stats).map(|t| PowerTail {
                window: t.measured.map(|m| [m.from, m.to]),
                exponent: t.measured.map(|m| m.value),
                exponent_ci: t.measured.map(|m| m.ci),
                extrapolated: t.exponent().map(|e| e.0),
                extrapolated_ci: t.exponent().map(|e| e.1),
                extrapolated_window: t.judged.map(|j| [j.from, j.to]),
                exact: t.exact,
                agrees: t.agrees(),
                pre_asymptotic: t.pre_asymptotic(),
                form: match t.form {
                    gdsmc_theory::maxwell_form::Form::Scattering => "scattering",
                    gdsmc_theory::maxwell_form::Form::Impact => "impact",
                },
                file: "power_tail.csv",
            }),
            thermostat: gdsmc_theory::thermostat::GaussianBalance::of(scene).map(|b| Thermostat {
                zeta: b.zeta,
                cooling_constant: b.kappa,
                steady_temperature: b.steady_temperature(),
                holding_zeta: b.holding_zeta(),
                note: b.describe(),
            }),
            warnings: crate::analysis::warnings::check(scene, stats)
                .into_iter()
                .map(|w| Warning {
                    code: w.code,
                    message: w.message,
                })
                .collect(),
            no_intervals: crate::analysis::warnings::no_intervals(stats),
        }
    }

    /// As JSON, keys sorted at every level.
    #[must_use]
    pub fn to_json(&self) -> serde_json::Value {
        serde_json::to_value(self).expect("a summary serializes")
    }
}

impl ReferenceError {
    /// The error of `stats`'s column against the reference `r`, at the end and at its worst.
    fn of(stats: &RunStats, r: &ReferenceCurve) -> Self {
        let last = stats.times.len() - 1;
        let col = stats.col(r.of).expect("reference of a known column");
        let (mut e_max, mut t_at, mut not_computable) = (f64::NAN, f64::NAN, 0);
        for (ti, &t) in stats.times.iter().enumerate() {
            let exact = (r.curve)(t);
            if !exact.is_finite() {
                not_computable += 1;
                continue;
            }
            let d = (stats.mean(ti, col) - exact).abs();
            let e = if exact != 0.0 { d / exact.abs() } else { d };
            if e_max.is_nan() || e > e_max {
                e_max = e;
                t_at = t;
            }
        }
        let exact_end = (r.curve)(stats.times[last]);
        let scale = if exact_end != 0.0 {
            exact_end.abs()
        } else {
            1.0
        };
        ReferenceError {
            observable: r.of,
            reference: r.name,
            source: r.source,
            e_end: (stats.mean(last, col) - exact_end).abs() / scale,
            conf_end: stats.ci(last, col) / scale,
            e_max,
            not_computable,
            t_of_e_max: t_at,
        }
    }
}

impl Steady {
    /// The steady-state window's averages, when the run has one.
    fn of(stats: &RunStats) -> Option<Self> {
        let st = stats.steady.as_ref()?;
        Some(Steady {
            from: stats.times[st.first],
            points: st.points,
            observables: stats
                .names
                .iter()
                .enumerate()
                .map(|(i, col)| {
                    let (mean, ci) = st.steady_mean_ci(stats, i);
                    (col.to_string(), MeanCi { mean, ci })
                })
                .collect(),
        })
    }
}

impl Tail {
    /// The tail fit of the run's radial histogram, when it has one that can be fitted.
    fn of(scene: &Scene, stats: &RunStats) -> Option<Self> {
        use crate::analysis::tails;
        let crate::run::ShellHistogram { radius, weights: h } = stats.histogram.as_ref()?;
        let f = tails::fit(*radius, h, stats.dimension)?;
        let half = |a: tails::TailFit| HalfFit {
            slope: a.slope,
            slope_ci: a.slope_ci,
            shells: [a.points[0].0, a.points[a.points.len() - 1].0],
        };
        Some(Tail {
            k0: 1,
            slope: f.slope,
            slope_ci: f.slope_ci,
            shells_used: f.points.len(),
            reference_exponent_grw_16: tails::reference_exponent(scene),
            halves: tails::halves(*radius, h, stats.dimension).map(|(a, b)| Halves {
                inner: half(a),
                outer: half(b),
            }),
        })
    }
}
