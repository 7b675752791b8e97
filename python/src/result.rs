//! `run` and `RunResult`: a scene's ensembles run with the GIL released, Ctrl-C (a
//! KeyboardInterrupt) stopping them the way the command's Ctrl-C does, and the results as the
//! command's tables; `reproduce`: the papers' tables.

use crate::scene::Scene;
use crate::to_py;
use gdsmc_runner::report;
use gdsmc_runner::run::state::{StateHeader, StateReader, StateWriter};
use gdsmc_runner::run::{self as runner, RunStats};
use gdsmc_runner::scene as sc;
use gdsmc_theory::curves::for_scene;
use pyo3::prelude::*;
use std::path::PathBuf;
use std::sync::atomic::{AtomicBool, AtomicU64, Ordering};
use std::time::Duration;

/// The statistics of a finished (or interrupted) run and its scene.
#[pyclass(frozen, module = "gdsmc._gdsmc")]
pub struct RunResult {
    scene: Scene,
    stats: RunStats,
    /// Every ensemble's observables (`times x columns` each), when asked.
    samples: Option<Vec<Vec<f64>>>,
    /// Whether the scene's references hold (not for a state of other physics).
    references: bool,
    /// The velocity snapshots (`observe.snapshots`), when the scene takes any.
    snapshots: Option<crate::state::Snapshots>,
}

impl RunResult {
    /// The references the run's tables and summary carry.
    fn refs(&self) -> Vec<gdsmc_theory::curves::ReferenceCurve> {
        if self.references {
            for_scene(self.scene.scene())
        } else {
            Vec::new()
        }
    }
}

/// Every ensemble's observables as Python gets them: little-endian f64 bytes, their shape
/// `(ensembles, times, columns)` and the column names.
type Samples<'py> = (
    Bound<'py, pyo3::types::PyBytes>,
    (usize, usize, usize),
    Vec<String>,
);

/// How often the waiting thread looks for Ctrl-C and reports progress.
const POLL: Duration = Duration::from_millis(50);

/// Runs `body` on its own thread with the GIL released, polling for Ctrl-C (a
/// KeyboardInterrupt sets the stop flag `body` is given: the running ensembles finish, the rest
/// are skipped) and calling `progress` with the ensembles finished since its last call (the
/// `advance` `body` is given counts them; a raising callback stops the body and its error is
/// raised once the body has returned). Returns the body's value and whether Ctrl-C stopped it.
pub(crate) fn polled<T: Send>(
    py: Python<'_>,
    progress: Option<&Bound<'_, PyAny>>,
    body: impl FnOnce(&AtomicBool, &(dyn Fn(u64) + Sync)) -> T + Send,
) -> PyResult<(T, bool)> {
    let stop = AtomicBool::new(false);
    let done = AtomicU64::new(0);
    let mut reported = 0;
    let mut interrupted = false;
    let mut failed: Option<PyErr> = None;
    let value = std::thread::scope(|scope| {
        let job = scope.spawn(|| {
            body(&stop, &|k| {
                done.fetch_add(k, Ordering::Relaxed);
            })
        });
        while !job.is_finished() {
            py.detach(|| std::thread::sleep(POLL));
            if !interrupted && py.check_signals().is_err() {
                interrupted = true;
                stop.store(true, Ordering::SeqCst);
            }
            let now = done.load(Ordering::Relaxed);
            if let Some(p) = progress
                && now > reported
                && !interrupted
                && failed.is_none()
            {
                match p.call1((now - reported,)) {
                    Ok(_) => reported = now,
                    Err(e) => {
                        failed = Some(e);
                        stop.store(true, Ordering::SeqCst);
                    }
                }
            }
        }
        py.detach(|| job.join())
            .expect("the run thread does not panic")
    });
    if let Some(e) = failed {
        return Err(e);
    }
    let now = done.load(Ordering::Relaxed);
    if let Some(p) = progress
        && !interrupted
        && now > reported
    {
        p.call1((now - reported,))?;
    }
    Ok((value, interrupted))
}

/// Runs `scene` (with `n`, `ensembles`, `seed` overriding its keys, validated as the command's
/// flags are) on `threads` threads (0: all cores). Returns the result and whether a
/// KeyboardInterrupt stopped it early (the result then covers the ensembles finished, exactly
/// those of a shorter run). `progress(k)` is called with the ensembles finished since its last
/// call. With `samples` the result keeps every ensemble's observables
/// ([`RunResult::samples`]); `initial_state` and `save_state` are the command's
/// `--initial-state` and `--save-state` (docs/state.md); the scene's velocity snapshots
/// (`observe.snapshots`) are written into a directory that lives as long as the result
/// ([`RunResult::snapshot_files`]).
#[pyfunction]
#[pyo3(signature = (scene, n = None, ensembles = None, seed = None, threads = 0, progress = None, allow_long = false, samples = false, initial_state = None, save_state = None))]
#[allow(clippy::too_many_arguments)]
pub fn run(
    py: Python<'_>,
    scene: &Scene,
    n: Option<i64>,
    ensembles: Option<i64>,
    seed: Option<u64>,
    threads: usize,
    progress: Option<Bound<'_, PyAny>>,
    allow_long: bool,
    samples: bool,
    initial_state: Option<std::path::PathBuf>,
    save_state: Option<std::path::PathBuf>,
) -> PyResult<(RunResult, bool)> {
    let mut s = scene.clone();
    for o in sc::Override::run_keywords(n, ensembles, seed) {
        s = s.with(o)?;
    }
    runner::estimate::check(s.scene(), threads, allow_long).map_err(to_py)?;
    // The state files are checked before anything runs (as the command's flags are).
    let initial = initial_state
        .as_deref()
        .map(StateReader::open)
        .transpose()
        .map_err(to_py)?;
    if let Some(r) = &initial {
        r.check(s.scene()).map_err(to_py)?;
        crate::warn_all(py, &r.notes)?;
    }
    let save = save_state
        .as_deref()
        .map(|p| {
            let header = StateHeader::of(
                s.scene(),
                s.scene().ensembles(),
                initial.as_ref().map(|r| &r.header),
            );
            StateWriter::create(p, header)
        })
        .transpose()
        .map_err(to_py)?;
    let from = initial.as_ref().map(|r| &r.header);
    let (snapshots, writers) =
        match crate::state::Snapshots::create(s.scene(), s.scene().ensembles(), from)
            .map_err(to_py)?
        {
            Some((d, w)) => (Some(d), w),
            None => (None, Vec::new()),
        };
    let io = runner::StateIo {
        initial: initial.as_ref(),
        save: save.as_ref(),
        snapshots: &writers,
    };
    let mut kept = Vec::new();
    let (stats, interrupted) = polled(py, progress.as_ref(), |stop, advance| {
        let keep = samples.then_some(&mut kept);
        runner::run_in_memory(s.scene(), threads, (advance, stop), io, keep)
    })?;
    let kept_ensembles = stats.as_ref().ok().map(|st| st.ensembles);
    runner::state::finish_all(writers, kept_ensembles).map_err(to_py)?;
    let stats = match (stats, save) {
        (Ok(st), Some(w)) if st.ensembles > 0 => {
            w.finish(st.ensembles).map_err(to_py)?;
            st
        }
        (st, w) => {
            if let Some(w) = w {
                w.abandon();
            }
            st.map_err(to_py)?
        }
    };
    // The references hold for a continuation of the scene's own process only (docs/state.md).
    let references = initial.as_ref().is_none_or(|r| r.continues(s.scene()));
    let result = RunResult {
        scene: s,
        stats,
        samples: samples.then_some(kept),
        references,
        snapshots,
    };
    Ok((result, interrupted))
}

#[pymethods]
impl RunResult {
    /// The scene that ran (with the overrides of the call).
    #[getter]
    fn scene(&self) -> Scene {
        self.scene.clone()
    }

    /// Ensembles in the statistics.
    #[getter]
    fn ensembles(&self) -> u64 {
        self.stats.ensembles
    }

    /// Wall seconds of the run.
    #[getter]
    fn wall(&self) -> f64 {
        self.stats.wall.as_secs_f64()
    }

    /// CPU seconds of the run (all threads).
    #[getter]
    fn cpu(&self) -> f64 {
        self.stats.cpu.as_secs_f64()
    }

    /// The files `gdsmc run` writes besides the charts, as text: observables.csv,
    /// summary.json, and histograms.csv, reduced.csv (with power_tail.csv), marginal.csv when
    /// the scene has them.
    fn tables(&self) -> PyResult<Vec<(String, String)>> {
        let refs = self.refs();
        let files = report::tables(self.scene.scene(), &self.stats, &refs).map_err(to_py)?;
        Ok(files
            .into_iter()
            .map(|(name, bytes)| (name, String::from_utf8_lossy(&bytes).into_owned()))
            .collect())
    }

    /// Every ensemble's observables when the run kept them (`samples=True`): the values as
    /// little-endian f64 bytes, ensemble-major then time then column, with the shape
    /// `(ensembles, times, columns)` and the column names; `None` otherwise.
    fn samples<'py>(&self, py: Python<'py>) -> Option<Samples<'py>> {
        let rows = self.samples.as_ref()?;
        let bytes: Vec<u8> = rows
            .iter()
            .flatten()
            .flat_map(|x| x.to_le_bytes())
            .collect();
        let shape = (rows.len(), self.stats.times.len(), self.stats.names.len());
        let names = self.stats.names.iter().map(|n| n.to_string()).collect();
        Some((pyo3::types::PyBytes::new(py, &bytes), shape, names))
    }

    /// Each velocity snapshot's time and state file (read with `read_state`); empty when the
    /// scene takes none. The files go with the result.
    fn snapshot_files(&self) -> Vec<(f64, PathBuf)> {
        self.snapshots
            .as_ref()
            .map_or_else(Vec::new, |s| s.files.clone())
    }

    /// The summary the command prints.
    fn summary_text(&self) -> String {
        let refs = self.refs();
        report::summary::text(self.scene.scene(), &self.stats, &refs)
    }

    /// Writes the command's whole output set (tables, summary.json, charts in `formats`:
    /// "svg", "png", "pdf", comma-separated; png and pdf with the `render` feature) into
    /// `dir`, replacing the previous set in one step. Returns the files written.
    #[pyo3(signature = (dir, formats = "svg"))]
    fn write(
        &self,
        py: Python<'_>,
        dir: std::path::PathBuf,
        formats: &str,
    ) -> PyResult<Vec<String>> {
        let formats: report::charts::Formats = formats
            .parse()
            .map_err(|e: String| pyo3::exceptions::PyValueError::new_err(e))?;
        let (notes, written) = py
            .detach(|| {
                let set = report::set::OutputSet::prepare(&dir)?;
                let notes = set.notes().to_vec();
                let written =
                    report::commit_run(set, self.scene.scene(), &self.stats, &self.refs(), formats);
                Ok::<_, gdsmc_runner::Error>((notes, written))
            })
            .map_err(to_py)?;
        // A directory an earlier run's claim named but that is not proven gdsmc's: left, and
        // said as a Python warning.
        crate::warn_all(py, &notes)?;
        written.map_err(to_py)
    }

    fn __repr__(&self) -> String {
        format!(
            "RunResult({:?}: n={}, {} ensembles, {:.2} s)",
            self.scene.scene().name(),
            self.scene.scene().n(),
            self.stats.ensembles,
            self.stats.wall.as_secs_f64()
        )
    }
}

/// Runs the papers' tables (`names`: e.g. ["grw-table1"]; empty: all) and returns the
/// markdown report, one text block per table, and the disagreements of ours (empty when the
/// run passes).
#[pyfunction]
#[pyo3(signature = (names, quick = true, threads = 0, seed = 1))]
pub fn reproduce(
    py: Python<'_>,
    names: Vec<String>,
    quick: bool,
    threads: usize,
    seed: u64,
) -> PyResult<(String, Vec<String>, Vec<String>)> {
    use gdsmc_runner::reproduce as rp;
    let opts = rp::Options {
        quick,
        threads,
        seed,
    };
    let start = std::time::Instant::now();
    let tables = py
        .detach(|| rp::run(&names, &opts, |_| {}))
        .map_err(to_py)?;
    let md = rp::markdown(&tables, &opts, start.elapsed().as_secs_f64());
    let texts = tables.iter().map(rp::text).collect();
    let bad = rp::failures(&tables);
    Ok((md, texts, bad))
}
