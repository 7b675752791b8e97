//! What a finished (or stopped) sweep writes and prints: sweep.csv, sweep.md, sweep.json and
//! the charts as one output set, the terminal's table and its notes.

use super::point::{PointResult, PointScene};
use super::spec::Sweep;
use super::table;
use crate::error::Error;
use crate::report::set::OutputSet;
use crate::run::columns::name;
use std::fmt::Write as _;

/// The points' ensembles in words: `N ensembles each`, or their range when `run.ensembles`
/// varies.
pub(super) fn ensembles_words(points: &[PointScene]) -> String {
    let e = points.iter().map(|p| p.source.scene.ensembles());
    match (e.clone().min(), e.max()) {
        (Some(a), Some(b)) if a == b => format!("{a} ensembles each"),
        (Some(a), Some(b)) => format!("{a} to {b} ensembles (run.ensembles varies)"),
        _ => "no points".into(),
    }
}

/// A note for every finished point of one ensemble: its intervals are NaN (undefined, not
/// zero) and the verdict leaves it out.
pub(super) fn one_ensemble_notes(results: &[PointResult]) -> Vec<String> {
    let ones: Vec<String> = results
        .iter()
        .filter(|r| r.ensembles == 1)
        .map(|r| r.index.to_string())
        .collect();
    if ones.is_empty() {
        return Vec::new();
    }
    vec![format!(
        "note: point{} {} {} one ensemble: {} _ci columns of sweep.csv (and intervals of \
         sweep.json) are NaN, since an interval needs the spread of at least two ensembles (it is \
         undefined, not zero), and the verdict leaves {} out; run.ensembles = 2 or more gives \
         intervals",
        if ones.len() > 1 { "s" } else { "" },
        ones.join(", "),
        if ones.len() > 1 { "have" } else { "has" },
        if ones.len() > 1 { "their" } else { "its" },
        if ones.len() > 1 { "them" } else { "it" },
    )]
}
/// Writes sweep.csv, sweep.json and the charts into the prepared set and puts it in place.
pub(super) fn write(
    set: OutputSet,
    sweep: &Sweep,
    complete: bool,
    results: &[PointResult],
    charts: &[(String, Result<crate::report::charts::Chart, String>)],
) -> Result<Vec<String>, Error> {
    let (base, vary) = (&sweep.source, &sweep.vary);
    crate::report::charts::write(set.dir(), charts, sweep.format)?;
    let path = set.dir().join("sweep.csv");
    let bytes = table::csv(vary, results).map_err(|e| Error::Write {
        path: path.clone(),
        source: std::io::Error::other(e),
    })?;
    crate::files::write_atomic(&path, &bytes)?;
    let path = set.dir().join("sweep.md");
    crate::files::write_atomic(
        &path,
        table::markdown(base.scene.name(), vary, results).as_bytes(),
    )?;
    let path = set.dir().join("sweep.json");
    let j = table::json(base.scene.name(), vary, sweep.combine, complete, results);
    let mut text = serde_json::to_vec_pretty(&j).map_err(|e| Error::Write {
        path: path.clone(),
        source: std::io::Error::other(e),
    })?;
    text.push(b'\n');
    crate::files::write_atomic(&path, &text)?;
    set.commit(serde_json::json!({
        "sweep": base.scene.name(),
        "points": results.len(),
        "gdsmc_version": env!("CARGO_PKG_VERSION"),
        "stream_version": gdsmc_core::rng::STREAM_VERSION,
    }))
}

/// The observables a sweep is about: those that have a reference at some point (what the
/// study compares), else `T` and `a2`.
fn studied(results: &[PointResult]) -> Vec<&'static str> {
    let mut with_refs: Vec<&'static str> = Vec::new();
    for p in results {
        for o in &p.observables {
            if p.references.iter().any(|r| r.of == o.0) && !with_refs.contains(&o.0) {
                with_refs.push(o.0);
            }
        }
    }
    if with_refs.is_empty() {
        vec![name::T, name::A2]
    } else {
        with_refs
    }
}

/// The terminal's table: per point the varied values and the studied observables' window
/// means with their intervals ([`studied`]), each beside its first reference.
pub(super) fn summary(results: &[PointResult]) -> String {
    let mut out = String::new();
    let names = studied(results);
    for p in results {
        let values: Vec<String> = p.values.iter().map(|(k, v)| format!("{k} = {v}")).collect();
        let shown: Vec<String> = names
            .iter()
            .filter_map(|n| p.observables.iter().find(|o| o.0 == *n))
            .map(|(name, mean, ci)| {
                let r = p.references.iter().find(|r| r.of == *name);
                // The summary's figures: a cooling gas's T_bulk of 1e-10 printed 0.00000.
                let num = crate::report::num;
                match r {
                    Some(r) => format!(
                        "{name} = {} ± {ci:.2e} ({} {})",
                        num(*mean),
                        r.name,
                        num(r.value)
                    ),
                    None => format!("{name} = {} ± {ci:.2e}", num(*mean)),
                }
            })
            .collect();
        let _ = writeln!(
            out,
            "point {:>3}  {}  {}",
            p.index,
            values.join(", "),
            shown.join(", ")
        );
    }
    out
}
