//! One point of a sweep: its scene (the base scene with the point's values and seed, validated
//! as a file is) and, once run, its window averages and references.

use super::vary::Point;
use crate::error::Error;
use crate::run::RunStats;
use crate::scene::{Override, Sourced};
use gdsmc_theory::curves::{Kind, for_scene};

/// A point's validated scene.
#[derive(Clone, Debug)]
pub struct PointScene {
    /// Its place in the sweep (0-based).
    pub index: usize,
    /// The varied keys' values.
    pub values: Point,
    /// The scene: the base scene with the values and the point's seed.
    pub source: Sourced,
}

impl PointScene {
    /// Point `index` of the sweep over `base` with `values`: each value an override named by
    /// the point (its errors say which point and key), and the seed `base seed + index`
    /// unless the sweep varies `run.seed` itself.
    pub fn new(base: &Sourced, index: usize, values: Point) -> Result<Self, Error> {
        let mut source = base.clone();
        for (key, value) in &values {
            source = source.with(Override {
                source: format!("--vary {key} (point {index})"),
                assignment: format!("{key}={value}"),
            })?;
        }
        if !values.iter().any(|(k, _)| k == "run.seed") {
            let seed =
                base.scene
                    .seed()
                    .checked_add(index as u64)
                    .ok_or_else(|| Error::Argument {
                        flag: "run.seed".into(),
                        message: format!(
                            "= {} leaves no room for the sweep's {} point seeds (seed + point)",
                            base.scene.seed(),
                            index + 1
                        ),
                    })?;
            source = source.with(Override {
                source: format!("the seed of sweep point {index}"),
                assignment: format!("run.seed={seed}"),
            })?;
        }
        Ok(PointScene {
            index,
            values,
            source,
        })
    }

    /// Its varied values in words: `key = value, ...`.
    pub fn words(&self) -> String {
        self.values
            .iter()
            .map(|(k, v)| format!("{k} = {v}"))
            .collect::<Vec<_>>()
            .join(", ")
    }
}

/// The observation window a point's averages are over.
#[derive(Clone, Debug, PartialEq)]
pub enum Window {
    /// The steady-state window: its first time and its number of observation times.
    Steady {
        /// First time averaged.
        from: f64,
        /// Observation times averaged.
        points: usize,
    },
    /// The last observation time alone (a scene without a steady window).
    End {
        /// The time.
        t: f64,
    },
}

/// A reference's value at a point: the curve averaged over the point's window.
#[derive(Clone, Debug, PartialEq)]
pub struct ReferenceValue {
    /// Column name (e.g. `a2_sonine`).
    pub name: &'static str,
    /// The observable it is the reference of.
    pub of: &'static str,
    /// What it is to the run's means.
    pub kind: Kind,
    /// Paper and equation.
    pub source: &'static str,
    /// The curve's mean over the window.
    pub value: f64,
}

/// What a finished point gives the sweep.
#[derive(Clone, Debug, PartialEq)]
pub struct PointResult {
    /// Its place in the sweep.
    pub index: usize,
    /// The varied keys' values.
    pub values: Point,
    /// Its seed.
    pub seed: u64,
    /// Its ensembles.
    pub ensembles: u64,
    /// The window of the averages.
    pub window: Window,
    /// Each observable's window mean and the half-width of its 99.9% interval, by column.
    pub observables: Vec<(&'static str, f64, f64)>,
    /// Every reference that applies at the point.
    pub references: Vec<ReferenceValue>,
}

/// The observation window of `scene`'s averages: its steady window, or its last observation
/// time; and the indices of the observation times in it.
pub fn window(scene: &crate::scene::Scene) -> (Window, std::ops::Range<usize>) {
    let times = scene.times();
    let last = times.len() - 1;
    match scene.steady_from() {
        Some(first) => (
            Window::Steady {
                from: times[first],
                points: times.len() - first,
            },
            first..times.len(),
        ),
        None => (Window::End { t: times[last] }, last..last + 1),
    }
}

/// Each reference that applies to `scene`, averaged over its window ([`window`]); with a
/// reduced histogram, the exact root of its power-law tail where one holds (shown, not
/// judged: the root is the asymptote the local slopes reach, from which the measured exponent
/// is extrapolated, analysis/power_tail/).
pub fn references(scene: &crate::scene::Scene) -> Vec<ReferenceValue> {
    use crate::analysis::power_tail as power;
    let (_, span) = window(scene);
    let times = &scene.times()[span];
    let mut all: Vec<ReferenceValue> = for_scene(scene)
        .into_iter()
        .map(|r| ReferenceValue {
            name: r.name,
            of: r.of,
            kind: r.kind,
            source: r.source,
            value: times.iter().map(|&t| (r.curve)(t)).sum::<f64>() / times.len() as f64,
        })
        .collect();
    let exact = power::exact_exponent(scene).filter(|_| scene.reduced_histogram().is_some());
    all.extend(exact.map(|s| ReferenceValue {
        name: power::EXACT,
        of: power::EXPONENT,
        kind: Kind::Limit,
        source: power::exact_source(gdsmc_theory::maxwell_form::Form::of(scene)),
        value: s,
    }));
    all
}

impl PointResult {
    /// The window averages of a finished point's statistics: the steady-state window when
    /// the scene has one (each ensemble's average over it, then the mean over ensembles with
    /// its interval, as summary.json's `steady_state`), else the last observation; and each
    /// reference averaged over the same observation times. With a reduced histogram of a
    /// model with a power-law tail, its extrapolated exponent (`tail_exponent`) beside the exact
    /// root (`tail_exponent_exact`, analysis/power_tail/).
    pub fn of(p: &PointScene, stats: &RunStats) -> Self {
        let last = stats.times.len() - 1;
        let (window, _) = window(&p.source.scene);
        let mut observables: Vec<(&'static str, f64, f64)> = stats
            .names
            .iter()
            .enumerate()
            .map(|(col, &name)| {
                let (mean, ci) = match &stats.steady {
                    Some(st) => st.steady_mean_ci(stats, col),
                    None => (stats.mean(last, col), stats.ci(last, col)),
                };
                (name, mean, ci)
            })
            .collect();
        let references = references(&p.source.scene);
        // The reduced tail's measured exponent where the model has a power-law tail (its
        // exact root is among the references; elsewhere the local slope is no exponent).
        use crate::analysis::power_tail as power;
        let measured = power::measure(&p.source.scene, stats).filter(|t| t.exact.is_some());
        if let Some((v, ci)) = measured.and_then(|t| t.exponent()) {
            observables.push((power::EXPONENT, v, ci));
        }
        PointResult {
            index: p.index,
            values: p.values.clone(),
            seed: p.source.scene.seed(),
            ensembles: stats.ensembles,
            window,
            observables,
            references,
        }
    }
}
