//! What a run leaves behind: observables.csv, histograms.csv, reduced.csv, marginal.csv,
//! summary.json and the charts, each written whole ([`crate::files::write_atomic`]), and the text
//! summary the command prints.

pub mod charts;
pub mod set;
pub mod summary;
pub mod summary_file;
mod verdict;
pub(crate) use verdict::num;

use crate::error::Error;
use crate::files::write_atomic;
use crate::run::RunStats;
use crate::scene::Scene;
use gdsmc_theory::curves::ReferenceCurve;
use std::path::Path;

/// observables.csv: `t`, then `NAME` and `NAME_ci` for every observable, then the reference
/// columns. Numbers are written with full round-trip precision.
pub fn observables_csv(stats: &RunStats, refs: &[ReferenceCurve]) -> Result<Vec<u8>, csv::Error> {
    let mut w = csv::Writer::from_writer(Vec::new());
    let mut header = vec!["t".to_string()];
    for c in &stats.names {
        header.push(c.to_string());
        header.push(format!("{c}_ci"));
    }
    for r in refs {
        header.push(r.name.to_string());
    }
    w.write_record(&header)?;
    for (ti, &t) in stats.times.iter().enumerate() {
        let mut rec = vec![format!("{t:?}")];
        for ci in 0..stats.names.len() {
            rec.push(format!("{:?}", stats.mean(ti, ci)));
            rec.push(format!("{:?}", stats.ci(ti, ci)));
        }
        for r in refs {
            rec.push(format!("{:?}", (r.curve)(t)));
        }
        w.write_record(&rec)?;
    }
    w.into_inner().map_err(|e| e.into_error().into())
}

/// histograms.csv: the radial-shell histogram at the last observation (GRW (31)-(33)):
/// `r_lo, r_hi, f, f_ci` per shell (the weight of the shell, and its 99.9% half-width), and
/// `density` = `f` over the shell volume (a ring's area for disks, `d = 2`); the last shell is
/// `[R, inf)`.
pub fn histograms_csv(
    radius: f64,
    hist: &gdsmc_stats::Accumulator,
    d: usize,
) -> Result<Vec<u8>, csv::Error> {
    let mut w = csv::Writer::from_writer(Vec::new());
    w.write_record(["r_lo", "r_hi", "f", "f_ci", "density"])?;
    let k = hist.len() - 1;
    for i in 0..=k {
        let lo = radius * i as f64 / k as f64;
        let hi = if i == k {
            f64::INFINITY
        } else {
            radius * (i + 1) as f64 / k as f64
        };
        let vol = gdsmc_theory::exact::tail::shell_volume_in(d, lo, hi);
        w.write_record([
            format!("{lo:?}"),
            format!("{hi:?}"),
            format!("{:?}", hist.mean(i)),
            format!("{:?}", hist.ci(i)),
            format!(
                "{:?}",
                if vol.is_finite() {
                    hist.mean(i) / vol
                } else {
                    0.0
                }
            ),
        ])?;
    }
    w.into_inner().map_err(|e| e.into_error().into())
}

/// The files of a run besides the charts, by name, as bytes: observables.csv, summary.json,
/// and histograms.csv, reduced.csv (with power_tail.csv), marginal.csv when the scene asks for
/// them. The command
/// writes them ([`write_all`]); the Python package hands them over as they are.
pub fn tables(
    scene: &Scene,
    stats: &RunStats,
    refs: &[ReferenceCurve],
) -> Result<Vec<(String, Vec<u8>)>, Error> {
    let csv_err = |name: &str, e: csv::Error| Error::Write {
        path: name.into(),
        source: std::io::Error::other(e.to_string()),
    };
    let mut out = vec![(
        "observables.csv".to_string(),
        observables_csv(stats, refs).map_err(|e| csv_err("observables.csv", e))?,
    )];
    let json = serde_json::to_vec_pretty(&summary_file::Summary::of(scene, stats, refs).to_json())
        .expect("json");
    out.push(("summary.json".into(), json));
    if let Some(crate::run::ShellHistogram { radius, weights: h }) = &stats.histogram {
        let bytes = histograms_csv(*radius, h, stats.dimension)
            .map_err(|e| csv_err("histograms.csv", e))?;
        out.push(("histograms.csv".into(), bytes));
    }
    if let Some(r) = crate::analysis::distribution::reduced(scene, stats) {
        let bytes = reduced_csv(&r).map_err(|e| csv_err("reduced.csv", e))?;
        out.push(("reduced.csv".into(), bytes));
    }
    if let Some(t) = crate::analysis::power_tail::measure(scene, stats) {
        let bytes = power_tail_csv(&t).map_err(|e| csv_err("power_tail.csv", e))?;
        out.push(("power_tail.csv".into(), bytes));
    }
    if let Some(m) = crate::analysis::distribution::marginal(stats) {
        let bytes = marginal_csv(&m).map_err(|e| csv_err("marginal.csv", e))?;
        out.push(("marginal.csv".into(), bytes));
    }
    Ok(out)
}

/// Writes the [`tables`] and the charts (in `formats`) into `dir`, which must exist (a
/// staging directory removed while the run went is an error, not made again).
pub fn write_all(
    dir: &Path,
    scene: &Scene,
    stats: &RunStats,
    refs: &[ReferenceCurve],
    formats: charts::Formats,
) -> Result<(), Error> {
    for (name, bytes) in tables(scene, stats, refs)? {
        write_atomic(&dir.join(name), &bytes)?;
    }
    charts::write(dir, &all_charts(scene, stats, refs), formats)?;
    Ok(())
}

/// Every chart of a run, by stem, as SVG (or why it is not drawn): those [`write_all`] writes,
/// and the browser page shows.
pub fn all_charts(
    scene: &Scene,
    stats: &RunStats,
    refs: &[ReferenceCurve],
) -> Vec<(String, Result<charts::Chart, String>)> {
    let reduced = crate::analysis::distribution::reduced(scene, stats);
    let marginal = crate::analysis::distribution::marginal(stats);
    let power = crate::analysis::power_tail::measure(scene, stats);
    let title = charts::title(scene, stats.ensembles);
    charts::all(
        &title,
        stats,
        (scene.time_axis(), scene.species_names()),
        refs,
        reduced.as_ref(),
        marginal.as_ref(),
        power.as_ref(),
    )
}

/// Writes a run's whole output set into the prepared `set` ([`write_all`]) and commits it with
/// its manifest (scene, seed, n, ensembles, version). Returns the files written.
pub fn commit_run(
    set: set::OutputSet,
    scene: &Scene,
    stats: &RunStats,
    refs: &[ReferenceCurve],
    formats: charts::Formats,
) -> Result<Vec<String>, Error> {
    write_all(set.dir(), scene, stats, refs, formats)?;
    set.commit(serde_json::json!({
        "scene": scene.name(),
        "seed": scene.seed(),
        "n": scene.n(),
        "ensembles": stats.ensembles,
        "gdsmc_version": env!("CARGO_PKG_VERSION"),
        "stream_version": gdsmc_core::rng::STREAM_VERSION,
    }))
}

/// power_tail.csv: the reduced tail's local slopes
/// ([`crate::analysis::power_tail`]), a row per window `[from, to = 2 from]`: `beyond,
/// beyond_ci` (`P(c >= to)` and its 99.9% half-width), `slope, slope_ci`, `resolved` (1 when
/// `P(c >= to)` is resolved), `measured` (1 on the window whose slope is the measured
/// exponent), `extrapolated, extrapolated_ci` (`s(x) + (s(x) - s(x/2))/3` from this window's
/// slope and that of `[from/2, from]`, empty where `from/2` is no edge), `judged` (1 on the
/// window whose extrapolation is judged), `exact` (the exact exponent, empty without one).
pub fn power_tail_csv(t: &crate::analysis::power_tail::PowerTail) -> Result<Vec<u8>, csv::Error> {
    let mut w = csv::Writer::from_writer(Vec::new());
    w.write_record([
        "from",
        "to",
        "beyond",
        "beyond_ci",
        "slope",
        "slope_ci",
        "resolved",
        "measured",
        "extrapolated",
        "extrapolated_ci",
        "judged",
        "exact",
    ])?;
    let exact = t.exact.map_or(String::new(), |s| format!("{s:?}"));
    for sl in &t.slopes {
        let measured = t.measured.is_some_and(|m| m.from == sl.from);
        let judged = t.judged.is_some_and(|m| m.from == sl.from);
        let (e, e_ci) = sl
            .extrapolated
            .map_or((String::new(), String::new()), |(v, ci)| {
                (format!("{v:?}"), format!("{ci:?}"))
            });
        w.write_record([
            format!("{:?}", sl.from),
            format!("{:?}", sl.to),
            format!("{:?}", sl.beyond.0),
            format!("{:?}", sl.beyond.1),
            format!("{:?}", sl.value),
            format!("{:?}", sl.ci),
            u8::from(sl.resolved).to_string(),
            u8::from(measured).to_string(),
            e,
            e_ci,
            u8::from(judged).to_string(),
            exact.clone(),
        ])?;
    }
    w.into_inner().map_err(|e| e.into_error().into())
}

/// reduced.csv: MS's reduced distribution per shell of `c = |v - V| / v0`: `c_lo, c_hi, f,
/// f_ci` (shell weight), `density` (f~(c)), `phi` (the Maxwellian, shell-averaged), `ratio,
/// ratio_ci` (f/phi), `delta, delta_ci` (MS (45)), `s2` (S_2(c^2)), `G, G_maxwell` (MS (69),
/// (71) or (77); empty without a tail law).
pub fn reduced_csv(r: &crate::analysis::distribution::Reduced) -> Result<Vec<u8>, csv::Error> {
    let mut w = csv::Writer::from_writer(Vec::new());
    w.write_record([
        "c_lo",
        "c_hi",
        "f",
        "f_ci",
        "density",
        "phi",
        "ratio",
        "ratio_ci",
        "delta",
        "delta_ci",
        "s2",
        "G",
        "G_maxwell",
    ])?;
    let g = |x: f64| {
        if x.is_nan() {
            String::new()
        } else {
            format!("{x:?}")
        }
    };
    for sh in &r.shells {
        w.write_record([
            format!("{:?}", sh.c_lo),
            format!("{:?}", sh.c_hi),
            format!("{:?}", sh.f.0),
            format!("{:?}", sh.f.1),
            format!("{:?}", sh.density),
            format!("{:?}", sh.phi),
            format!("{:?}", sh.ratio.0),
            format!("{:?}", sh.ratio.1),
            format!("{:?}", sh.delta.0),
            format!("{:?}", sh.delta.1),
            format!("{:?}", sh.s2),
            g(sh.g),
            g(sh.g_maxwell),
        ])?;
    }
    w.into_inner().map_err(|e| e.into_error().into())
}

/// marginal.csv: the marginal density of one velocity component (BRS Figure 4) per bin,
/// `v_lo, v_hi, first, first_ci, first_maxwell, last, last_ci, last_maxwell` (densities at the
/// first and last observation, each beside the Maxwellian with that time's bulk velocity
/// and temperature).
pub fn marginal_csv(m: &crate::analysis::distribution::Marginal) -> Result<Vec<u8>, csv::Error> {
    let mut w = csv::Writer::from_writer(Vec::new());
    w.write_record([
        "v_lo",
        "v_hi",
        "first",
        "first_ci",
        "first_maxwell",
        "last",
        "last_ci",
        "last_maxwell",
    ])?;
    for b in &m.bins {
        w.write_record(
            [
                b.v_lo,
                b.v_hi,
                b.first.0,
                b.first.1,
                b.first_maxwell,
                b.last.0,
                b.last.1,
                b.last_maxwell,
            ]
            .map(|x| format!("{x:?}")),
        )?;
    }
    w.into_inner().map_err(|e| e.into_error().into())
}
