//! Ensembles: many independent particle systems of one scene, run in parallel.
//!
//! Ensemble `k` uses the seed's Xoshiro256++ generator jumped `k` times. Ensembles are grouped
//! in fixed chunks of [`CHUNK`]; each chunk is accumulated in ensemble order and the chunks are
//! merged in chunk order, so the statistics are bit-identical for any number of threads.
//!
//! The engine is composed at compile time: the core's [`Model::start`] turns the scene's
//! physics into one statically composed event loop per ensemble.

use crate::columns::{COLUMNS, names};
use crate::error::Error;
use crate::scene::Scene;
use crate::stats::Accumulator;
use gdsmc_core::collisional::collisional_moments;
use gdsmc_core::engine::{Counts, EngineError, EventLoop};
use gdsmc_core::histogram::{component_bins, radial_shells_mapped};
use gdsmc_core::moments::Observables;
use gdsmc_core::particles::{Particle, Particles};
use gdsmc_core::physics::{MAX_COMPONENTS, Model};
use gdsmc_core::rng::{Streams, Xoshiro256PlusPlus};
use gdsmc_core::sample::MaxwellianMixture;
use gdsmc_core::vec3::Vec3;
use rayon::prelude::*;
use std::sync::atomic::{AtomicBool, Ordering};
use std::time::{Duration, Instant};

/// Ensembles per chunk: the unit of parallel work and of the fixed merge order (one, so that
/// even a handful of long ensembles spreads over every core).
pub const CHUNK: u64 = 1;
/// Chunks handed to the pool at once (bounds memory; independent of the thread count).
const BATCH: u64 = 256;

/// The initial distribution of a scene as a core sampler (`None` if its physics is invalid).
pub fn initial_sampler(scene: &Scene) -> Option<MaxwellianMixture<MAX_COMPONENTS>> {
    scene.physics.validate().ok().map(|m| m.initial().clone())
}

/// Runs one ensemble of `scene` (whose physics `model` is) from the generator `rng`: the
/// observables at every observation time, row-major (`times x COLUMNS`), and the event counts.
pub fn run_ensemble(
    scene: &Scene,
    model: &Model,
    mut rng: Xoshiro256PlusPlus,
) -> Result<(Vec<f64>, Counts), EngineError> {
    let mut buf = vec![Particle::default(); model.n()];
    let mut p = Particles::new(&mut buf).map_err(|_| EngineError::ParticleCount)?;
    let (engine, obs0) = model.launch(&mut p, 0.0, &mut rng)?;
    observe(scene, engine, obs0, &mut p, &mut rng)
}

fn observe<E: EventLoop>(
    scene: &Scene,
    mut engine: E,
    obs0: Observables,
    p: &mut Particles<'_>,
    rng: &mut Xoshiro256PlusPlus,
) -> Result<(Vec<f64>, Counts), EngineError> {
    let mut out = Vec::with_capacity(scene.times.len() * (COLUMNS.len() + 2) + 1);
    // Diagnostics draw from their own stream, so they never change the trajectory.
    let mut diag = rng.clone();
    diag.long_jump();
    let nt = scene.times.len();
    let mut reduced = vec![0.0; scene.reduced_histogram.map_or(0, |(k, _)| k + 1)];
    let mut reduced_points = 0u32;
    let reduced_from = scene.steady_from.unwrap_or(nt - 1);
    let marginal_len = scene.marginal_histogram.map_or(0, |(_, k, _)| k + 2);
    let (mut marginal_first, mut marginal_last) =
        (vec![0.0; marginal_len], vec![0.0; marginal_len]);
    for (ti, &t) in scene.times.iter().enumerate() {
        let obs = if t == 0.0 {
            obs0
        } else {
            engine.advance_to(p, t, rng)?
        };
        // Bulk velocity and temperature in the stored units, once per observation, for the
        // diagnostics reduced by v0 (exact for a gas stored rescaled, whose physical
        // temperature may have underflowed).
        let wants_reduced = scene.reduced_histogram.is_some() && ti >= reduced_from;
        let stored =
            (wants_reduced || scene.collisional_pairs > 0).then(|| stored_bulk_temperature(p));
        if let (Some((_, c_max)), true, Some((bulk, t_bulk))) =
            (scene.reduced_histogram, wants_reduced, stored)
        {
            // c = (v - V) / v0.
            let inv = 1.0 / (2.0 * t_bulk).sqrt();
            radial_shells_mapped(p, c_max, inv, -inv * bulk, &mut reduced);
            reduced_points += 1;
        }
        if let Some((axis, _, radius)) = scene.marginal_histogram {
            let (scale, offset) = engine.velocity_map();
            if ti == 0 {
                component_bins(p, axis, radius, scale, offset, &mut marginal_first);
            }
            if ti == nt - 1 {
                component_bins(p, axis, radius, scale, offset, &mut marginal_last);
            }
        }
        out.extend(COLUMNS.iter().map(|c| (c.get)(&obs)));
        // The scene allows collisional pairs with a constant restitution law only.
        if let (true, Some((bulk, t_bulk)), Some(alpha)) = (
            scene.collisional_pairs > 0,
            stored,
            scene.physics.restitution.constant(),
        ) {
            // mu2, mu4 are reduced by v0, so the stored units do.
            let (mu2, mu4) =
                collisional_moments(p, bulk, t_bulk, alpha, scene.collisional_pairs, &mut diag);
            out.extend([mu2, mu4]);
        }
    }
    // The histogram of the last observation rides at the end of the row (split off in the job).
    if let Some((k, radius)) = scene.histogram {
        let mut h = vec![0.0; k + 1];
        let (scale, offset) = engine.velocity_map();
        radial_shells_mapped(p, radius, scale, offset, &mut h);
        out.extend(h);
    }
    if reduced_points > 0 {
        out.extend(reduced.iter().map(|x| x / reduced_points as f64));
    }
    out.extend(marginal_first);
    out.extend(marginal_last);
    Ok((out, engine.counts()))
}

/// Bulk velocity and temperature (about it) of the velocities as stored.
fn stored_bulk_temperature(p: &Particles<'_>) -> (Vec3, f64) {
    let n = p.len() as f64;
    let mut v = Vec3::ZERO;
    for q in p.as_slice() {
        v += q.velocity();
    }
    let bulk = (1.0 / n) * v;
    let mut s = 0.0;
    for q in p.as_slice() {
        s += (q.velocity() - bulk).norm2();
    }
    (bulk, s / (3.0 * n))
}

/// Steady-state averages (RW Section 4.2): every observable averaged over the observation
/// times from `first` on, per ensemble; `acc` holds those averages' statistics over ensembles.
#[derive(Clone, Debug)]
pub struct SteadyStats {
    /// Index of the first observation time averaged.
    pub first: usize,
    /// Number of observation times averaged.
    pub points: usize,
    /// Statistics over ensembles of the per-ensemble averages (one entry per column).
    pub acc: Accumulator,
}

impl SteadyStats {
    /// Mean over ensembles of the steady-state average of column `col`, and the half-width of
    /// its 99.9% confidence interval. With one ensemble the interval comes from the spread of
    /// the observation points (RW Section 4.2), widened for their lag-1 autocorrelation.
    pub fn mean_ci(&self, stats: &RunStats, col: usize) -> (f64, f64) {
        if self.acc.count() > 1 {
            return (self.acc.mean(col), self.acc.ci(col));
        }
        let xs: Vec<f64> = (self.first..stats.times.len())
            .map(|ti| stats.mean(ti, col))
            .collect();
        let mut a = Accumulator::new(1);
        for &x in &xs {
            a.push(&[x]);
        }
        // Successive observations of one system are correlated; with the lag-1
        // autocorrelation r (an AR(1) model), the variance of their mean is larger by
        // (1 + r)/(1 - r). Points spaced as RW Section 4.2 spaces them have r near 0.2.
        let m = a.mean(0);
        let var = a.variance(0);
        let r = if xs.len() > 2 && var > 0.0 {
            let cov: f64 =
                xs.windows(2).map(|w| (w[0] - m) * (w[1] - m)).sum::<f64>() / (xs.len() - 1) as f64;
            (cov / var).clamp(0.0, 0.99)
        } else {
            0.0
        };
        (m, a.ci(0) * ((1.0 + r) / (1.0 - r)).sqrt())
    }
}

/// Statistics of a finished (or interrupted) run.
#[derive(Clone, Debug)]
pub struct RunStats {
    /// Observation times.
    pub times: Vec<f64>,
    /// Column names (see [`crate::columns::names`]).
    pub names: Vec<&'static str>,
    /// Per (time, column) statistics, row-major `times x names`.
    pub acc: Accumulator,
    /// Event counts summed over ensembles.
    pub counts: Counts,
    /// Ensembles finished.
    pub ensembles: u64,
    /// Wall time.
    pub wall: Duration,
    /// CPU time of the process during the run (all threads).
    pub cpu: Duration,
    /// Threads used.
    pub threads: usize,
    /// Steady-state averages, when the scene asks for them.
    pub steady: Option<SteadyStats>,
    /// The radial-shell histogram at the last observation (radius R, statistics of the K + 1
    /// shell weights over ensembles), when the scene asks for it.
    pub histogram: Option<(f64, Accumulator)>,
    /// The reduced-speed histogram (`c_max`, statistics of the K + 1 shell weights of
    /// `c = |v - V| / v0`, each ensemble's averaged over the steady observations).
    pub reduced: Option<(f64, Accumulator)>,
    /// The marginal histogram (axis 0..=2, R, statistics of the K + 2 weights at the first
    /// and at the last observation).
    pub marginal: Option<(usize, f64, Accumulator, Accumulator)>,
}

impl RunStats {
    /// Mean of column `col` at time index `ti`.
    pub fn mean(&self, ti: usize, col: usize) -> f64 {
        self.acc.mean(ti * self.names.len() + col)
    }
    /// Half-width of the 99.9% confidence interval of column `col` at time index `ti`.
    pub fn ci(&self, ti: usize, col: usize) -> f64 {
        self.acc.ci(ti * self.names.len() + col)
    }
    /// Index of the column `name`.
    pub fn col(&self, name: &str) -> Option<usize> {
        self.names.iter().position(|n| *n == name)
    }
}

struct EnsembleJob<'a> {
    scene: &'a Scene,
    model: &'a Model,
    threads: usize,
    progress: &'a (dyn Fn(u64) + Sync),
    stop: &'a AtomicBool,
}

/// What the parallel part hands back: statistics, steady statistics, histogram statistics,
/// counts, ensembles merged.
type Merged = (Accumulator, Accumulator, Accumulator, Counts, u64);

impl EnsembleJob<'_> {
    fn run(self) -> Result<Merged, Error> {
        let (scene, model) = (self.scene, self.model);
        let ncol = names(scene).len();
        let width = scene.times.len() * ncol;
        let pool = rayon::ThreadPoolBuilder::new()
            .num_threads(self.threads)
            .build()
            .expect("thread pool");
        let first = scene.steady_from.unwrap_or(0);
        let steady_of = |row: &[f64]| -> Vec<f64> {
            let pts = scene.times.len() - first;
            (0..ncol)
                .map(|c| {
                    (first..scene.times.len())
                        .map(|ti| row[ti * ncol + c])
                        .sum::<f64>()
                        / pts as f64
                })
                .collect()
        };
        let hist_len = scene.extra_len();
        let mut total = Accumulator::new(width);
        let mut steady = Accumulator::new(ncol);
        let mut hist = Accumulator::new(hist_len);
        let mut counts = Counts::default();
        let mut streams = Streams::new(scene.seed);
        let m = scene.ensembles;
        let mut start = 0u64;
        while start < m {
            let last = (start + BATCH * CHUNK).min(m);
            let rngs: Vec<Xoshiro256PlusPlus> =
                (&mut streams).take((last - start) as usize).collect();
            // `None`: the chunk was skipped because the run was interrupted.
            type Chunk = Result<Option<(Accumulator, Accumulator, Accumulator, Counts)>, Error>;
            let chunks: Vec<Chunk> = pool.install(|| {
                rngs.par_chunks(CHUNK as usize)
                    .enumerate()
                    .map(|(ci, rs)| {
                        if self.stop.load(Ordering::Relaxed) {
                            return Ok(None);
                        }
                        let mut acc = Accumulator::new(width);
                        let mut st = Accumulator::new(ncol);
                        let mut hi = Accumulator::new(hist_len);
                        let mut cnt = Counts::default();
                        for (k, r) in rs.iter().enumerate() {
                            let e = start + ci as u64 * CHUNK + k as u64;
                            let (row, c) =
                                run_ensemble(scene, model, r.clone()).map_err(|err| {
                                    Error::Engine {
                                        ensemble: e,
                                        message: err.to_string(),
                                    }
                                })?;
                            let (row, h) = row.split_at(width);
                            acc.push(row);
                            st.push(&steady_of(row));
                            hi.push(h);
                            cnt = cnt.add(&c);
                        }
                        (self.progress)(rs.len() as u64);
                        Ok(Some((acc, st, hi, cnt)))
                    })
                    .collect()
            });
            // Merge in ensemble order, and only an unbroken prefix: an interrupted run keeps
            // exactly what a full run with fewer ensembles would have.
            for (ci, ch) in chunks.into_iter().enumerate() {
                match ch? {
                    Some((a, st, h, c)) => {
                        total.merge(&a);
                        steady.merge(&st);
                        hist.merge(&h);
                        counts = counts.add(&c);
                    }
                    None => return Ok((total, steady, hist, counts, start + ci as u64 * CHUNK)),
                }
            }
            start = last;
        }
        Ok((total, steady, hist, counts, m))
    }
}

/// Runs every ensemble of `scene` on `threads` threads (0: all cores); `progress` is called
/// with the number of ensembles each finished chunk adds.
pub fn run(
    scene: &Scene,
    threads: usize,
    progress: &(dyn Fn(u64) + Sync),
) -> Result<RunStats, Error> {
    run_interruptible(scene, threads, progress, &AtomicBool::new(false))
}

/// As [`run`], stopping early when `stop` becomes true (Ctrl-C): ensembles already running
/// finish, and the statistics cover the first `RunStats::ensembles` ensembles, exactly those a
/// run with that many ensembles would give.
pub fn run_interruptible(
    scene: &Scene,
    threads: usize,
    progress: &(dyn Fn(u64) + Sync),
    stop: &AtomicBool,
) -> Result<RunStats, Error> {
    let threads = if threads == 0 {
        rayon::current_num_threads()
    } else {
        threads
    };
    let start = Instant::now();
    let cpu0 = cpu_time::ProcessTime::try_now().ok();
    let model = scene
        .physics
        .validate()
        .map_err(|e| Error::Physics(e.to_string()))?;
    let (acc, st, hist, counts, ensembles) = EnsembleJob {
        scene,
        model: &model,
        threads,
        progress,
        stop,
    }
    .run()?;
    let mut at = 0;
    let mut take = |len: usize| {
        let a = hist.slice(at..at + len);
        at += len;
        a
    };
    let histogram = scene.histogram.map(|(k, radius)| (radius, take(k + 1)));
    let reduced = scene.reduced_histogram.map(|(k, c)| (c, take(k + 1)));
    let marginal = scene
        .marginal_histogram
        .map(|(axis, k, r)| (axis, r, take(k + 2), take(k + 2)));
    let steady = scene.steady_from.map(|first| SteadyStats {
        first,
        points: scene.times.len() - first,
        acc: st,
    });
    Ok(RunStats {
        times: scene.times.clone(),
        names: names(scene),
        acc,
        counts,
        ensembles,
        wall: start.elapsed(),
        cpu: cpu0.map_or(Duration::ZERO, |c| c.elapsed()),
        threads,
        steady,
        histogram,
        reduced,
        marginal,
    })
}
