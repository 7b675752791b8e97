//! `sweep`: a parameter study (the command's `gdsmc sweep`) run in memory with the GIL
//! released, Ctrl-C stopping it after the running point's ensembles; the results come back as
//! the command's sweep.csv and sweep.json.

use crate::result::polled;
use crate::scene::Scene;
use crate::to_py;
use gdsmc_runner::scene as sc;
use gdsmc_runner::sweep::{Sweep, table};
use pyo3::prelude::*;
use std::sync::atomic::AtomicBool;

/// What the sweep's watcher sees: the poller's stop flag and progress counter.
struct Polled<'a> {
    stop: &'a AtomicBool,
    advance: &'a (dyn Fn(u64) + Sync),
}

impl gdsmc_runner::job::Watch for Polled<'_> {
    fn begin(&self, _: u64) {}
    fn advance(&self, k: u64) {
        (self.advance)(k);
    }
    fn end(&self) {}
    fn stop(&self) -> &AtomicBool {
        self.stop
    }
    fn note(&self, _: &str) {}
}

/// Sweeps `scene` over `vary` (`KEY=VALUES` strings in the command's syntax; empty: the
/// scene's `[sweep]` table), a grid or `zip`ped, with `n`, `ensembles` and `seed` overriding
/// the base scene's keys. Every point is validated and the summed work checked first; `total`,
/// when given, is then called with the ensembles of all points (a progress bar's end). Returns
/// sweep.csv and sweep.json of the finished points, the number of points asked for, and
/// whether Ctrl-C stopped the sweep.
#[pyfunction]
#[pyo3(signature = (scene, vary, zip = false, n = None, ensembles = None, seed = None, threads = 0, progress = None, allow_long = false, total = None))]
#[allow(clippy::too_many_arguments)]
pub fn sweep(
    py: Python<'_>,
    scene: &Scene,
    vary: Vec<String>,
    zip: bool,
    n: Option<i64>,
    ensembles: Option<i64>,
    seed: Option<u64>,
    threads: usize,
    progress: Option<Bound<'_, PyAny>>,
    allow_long: bool,
    total: Option<Bound<'_, PyAny>>,
) -> PyResult<(String, String, usize, bool)> {
    let mut s = scene.clone();
    for o in sc::Override::run_keywords(n, ensembles, seed) {
        s = s.with(o)?;
    }
    let plan = gdsmc_runner::sweep::plan(&s.source, &vary, zip).map_err(to_py)?;
    let sw = Sweep {
        source: s.source.clone(),
        vary: plan.vary,
        combine: plan.combine,
        threads,
        allow_long,
        out: None,
        fresh: false,
        format: Default::default(),
        shard: None,
    };
    let points = sw.checked_points().map_err(to_py)?;
    // The progress bar's total: every point's ensembles, known once the points are checked.
    if let Some(t) = &total {
        let ensembles: u64 = points.iter().map(|p| p.source.scene.ensembles()).sum();
        t.call1((ensembles,))?;
    }
    let (ran, interrupted) = polled(py, progress.as_ref(), |stop, advance| {
        sw.run_points(&points, None, &Polled { stop, advance })
    })?;
    let results = ran.map_err(to_py)?.results;
    let csv = table::csv(&sw.vary, &results).map_err(|e| {
        to_py(gdsmc_runner::Error::Argument {
            flag: "sweep.csv".into(),
            message: e.to_string(),
        })
    })?;
    let complete = results.len() == points.len();
    let json = table::json(s.scene().name(), &sw.vary, sw.combine, complete, &results);
    Ok((
        String::from_utf8_lossy(&csv).into_owned(),
        json.to_string(),
        points.len(),
        interrupted,
    ))
}
