//! A run of the page: a scene read from its text and the form's keys, advanced a few ensembles
//! at a time ([`gdsmc_runner::run::stepped`]), its statistics, charts and files on demand. Each
//! answer is JSON for the page; each error is the command's words.

use gdsmc_runner::report;
use gdsmc_runner::run::estimate;
use gdsmc_runner::run::journal::{ensemble_from_words, ensemble_words};
use gdsmc_runner::run::stepped::Stepped;
use gdsmc_runner::scene::{Override, merged_text, parse_with};
use gdsmc_theory::curves::{ReferenceCurve, for_scene};
use serde_json::{Value, json};
use std::path::Path;

/// A run in progress.
pub struct Session {
    stepped: Stepped,
    refs: Vec<ReferenceCurve>,
    estimated: f64,
}

/// The command's words for an error: what `gdsmc run` prints after `error: `.
fn words(e: impl std::fmt::Display) -> String {
    format!("error: {e}")
}

impl Session {
    /// The scene `text` (named `name` in messages, as the command names its file) with the
    /// overrides `sets` (`key=value`, one a line, as `--set`), validated and checked against
    /// the command's limits; with what the page shows before the run: the merged scene text
    /// (`gdsmc run` of it alone reproduces the run), its size and its work estimate.
    pub fn prepare(name: &str, text: &str, sets: &str) -> Result<(Session, Value), String> {
        let overrides: Vec<Override> = sets
            .lines()
            .map(str::trim)
            .filter(|l| !l.is_empty())
            .map(Override::set)
            .collect();
        let path = Path::new(name);
        let scene = parse_with(path, text, &overrides).map_err(words)?;
        let merged = merged_text(path, text, &overrides).map_err(words)?;
        let work = estimate::check(&scene, 1, false).map_err(words)?;
        let info = json!({
            "scene": scene.name(),
            "toml": merged,
            "n": scene.n(),
            "ensembles": scene.ensembles(),
            "seed": scene.seed(),
            "times": scene.times().len(),
            "work": work.total(),
            "stream_version": gdsmc_runner::STREAM_VERSION,
        });
        let refs = for_scene(&scene);
        let stepped = Stepped::new(scene).map_err(words)?;
        Ok((
            Session {
                stepped,
                refs,
                estimated: work.total(),
            },
            info,
        ))
    }

    /// Runs the next `k` ensembles; the number finished in all.
    pub fn advance(&mut self, k: u64) -> Result<u64, String> {
        self.stepped.advance(k).map_err(words)
    }

    /// Ensemble `k` run alone, not folded ([`Stepped::run_one`]): its journal words
    /// (`run::journal::ensemble_words`) as little-endian bytes, for the worker that folds.
    pub fn ensemble(&mut self, k: u64) -> Result<Vec<u8>, String> {
        let (row, counts) = self.stepped.run_one(k).map_err(words)?;
        Ok(ensemble_words(&row, &counts)
            .iter()
            .flat_map(|w| w.to_le_bytes())
            .collect())
    }

    /// Folds the next ensemble from the bytes [`Session::ensemble`] gave (run by another
    /// worker); the number folded in all.
    pub fn fold(&mut self, bytes: &[u8]) -> Result<u64, String> {
        let w: Vec<u64> = bytes
            .chunks_exact(8)
            .map(|c| u64::from_le_bytes(c.try_into().expect("8 bytes")))
            .collect();
        let (row, counts) = ensemble_from_words(&w)
            .filter(|_| bytes.len().is_multiple_of(8))
            .ok_or_else(|| words("an ensemble's bytes are cut short"))?;
        self.stepped.push(&row, &counts).map_err(words)
    }

    /// Adds the helper workers' time (wall and CPU seconds, as the page timed them).
    pub fn add_time(&mut self, wall: f64, cpu: f64) {
        self.stepped.add_time(wall, cpu);
    }

    /// The charts of the ensembles so far (every chart the command draws, by stem, as SVG),
    /// with the count finished and asked.
    pub fn charts(&self) -> Value {
        let stats = self.stepped.stats();
        let scene = self.stepped.scene();
        let charts: serde_json::Map<String, Value> = report::all_charts(scene, &stats, &self.refs)
            .into_iter()
            .filter_map(|(stem, c)| c.ok().map(|c| (stem, Value::String(c.svg))))
            .collect();
        json!({
            "done": stats.ensembles,
            "ensembles": scene.ensembles(),
            "charts": charts,
        })
    }

    /// What the command prints and writes for the ensembles finished so far: the summary (its
    /// text and the work line; no files written) and the tables by name (observables.csv,
    /// summary.json, and the histograms the scene asks for).
    pub fn finish(&self) -> Result<Value, String> {
        let stats = self.stepped.stats();
        let scene = self.stepped.scene();
        if stats.ensembles == 0 {
            return Err(words(gdsmc_runner::Error::Interrupted));
        }
        let mut summary = report::summary::text(scene, &stats, &self.refs);
        summary.push_str(&gdsmc_runner::job::work_line(self.estimated, scene, &stats));
        let files: serde_json::Map<String, Value> = report::tables(scene, &stats, &self.refs)
            .map_err(words)?
            .into_iter()
            .map(|(name, bytes)| (name, Value::String(String::from_utf8_lossy(&bytes).into())))
            .collect();
        Ok(json!({
            "done": stats.ensembles,
            "collisions": stats.counts.collisions,
            "summary": summary,
            "files": files,
        }))
    }
}

/// One declared parameter as the page shows it: its key, rule, words, unit, default, example.
fn param(p: &gdsmc_core::declared::ParamSpec) -> Value {
    json!({
        "name": p.name,
        "rule": p.rule.to_string(),
        "words": p.words,
        "unit": p.unit,
        "default": p.default,
        "example": p.example,
    })
}

/// The variants the core declares, for the page's choices (nothing of them written twice): each
/// kernel and drive by its scene word, its words, and its parameters; the restitution laws and
/// schemes by their words.
#[must_use]
pub fn kinds() -> Value {
    use gdsmc_core::physics::{DriveKind, KernelKind, LawKind, SchemeKind};
    let kernels: Vec<Value> = KernelKind::ALL
        .iter()
        .map(|k| json!({"name": k.scene_name(), "doc": k.doc(), "params": k.params().iter().map(param).collect::<Vec<_>>()}))
        .collect();
    let drives: Vec<Value> = DriveKind::ALL
        .iter()
        .map(|k| json!({"name": k.scene_name(), "doc": k.doc(), "params": k.params().map(|ps| ps.iter().map(param).collect::<Vec<_>>())}))
        .collect();
    let laws: Vec<Value> = LawKind::ALL
        .iter()
        .map(|k| json!({"name": k.scene_name(), "doc": k.doc()}))
        .collect();
    let schemes: Vec<Value> = SchemeKind::ALL
        .iter()
        .map(|k| json!({"name": k.scene_name(), "doc": k.doc()}))
        .collect();
    json!({
        "kernels": kernels,
        "drives": drives,
        "laws": laws,
        "schemes": schemes,
        "stream_version": gdsmc_runner::STREAM_VERSION,
        "version": env!("CARGO_PKG_VERSION"),
    })
}
