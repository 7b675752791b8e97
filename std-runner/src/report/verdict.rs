//! The verdict that ends a run's summary: each observable against the reference that applies
//! at this n, judged with its 99.9% interval jointly over the observation times (Bonferroni),
//! the other references named as what they are, and a reference that is not computable at
//! these parameters flagged, never judged.

use crate::run::RunStats;
use gdsmc_stats::{joint, multiplier};
use gdsmc_theory::curves::{Kind, ReferenceCurve};
use std::fmt::Write;

/// The verdict that ends the summary: each observable against the reference that applies at
/// this n ([`Kind::MeanAtN`]): how many observation times lie within their own 99.9% interval,
/// and whether every time does jointly (Bonferroni over the times, so that a sound run passes
/// with probability 99.9% however many times it observes); then the other references, named
/// as what they are (a limit or an approximation is shown, not judged).
pub(super) fn verdict(s: &mut String, stats: &RunStats, refs: &[ReferenceCurve]) {
    let nt = stats.times.len();
    if refs.is_empty() || nt == 0 || stats.ensembles < 2 {
        return;
    }
    let _ = writeln!(
        s,
        "
verdict    each mean against the reference that applies at this n, at all {nt} observation times"
    );
    // The joint interval: the Student-t quantile of the family over the per-time one.
    let widen = joint(nt, stats.ensembles - 1) / multiplier(stats.ensembles);
    // The times where a reference is not a number: its closed form left the range of f64 at
    // these parameters (a rate that cancels or overflows). Flagged, never judged or shown as a
    // number (issue 78).
    let not_computable = |r: &ReferenceCurve| -> Vec<f64> {
        (stats.times.iter().copied())
            .filter(|&t| !(r.curve)(t).is_finite())
            .collect()
    };
    let at = |times: &[f64]| {
        let shown: Vec<String> = times.iter().take(3).map(|t| num(*t)).collect();
        format!(
            "{}{}",
            shown.join(", "),
            if times.len() > 3 { ", ..." } else { "" }
        )
    };
    for r in refs.iter().filter(|r| r.kind == Kind::MeanAtN) {
        let Some(col) = stats.col(r.of) else { continue };
        let flagged = not_computable(r);
        if !flagged.is_empty() {
            let _ = writeln!(
                s,
                "  {:<8} NOT JUDGED: {} ({}) is not computable here (at t = {}, {} of {nt} times: its \
                 closed form leaves the range of f64 at these parameters)",
                r.of,
                r.name,
                r.source,
                at(&flagged),
                flagged.len()
            );
            continue;
        }
        let (mut inside, mut off) = (0, Vec::new());
        for (ti, &t) in stats.times.iter().enumerate() {
            let (m, ci, e) = (stats.mean(ti, col), stats.ci(ti, col), (r.curve)(t));
            // A time without spread (a deterministic start) is judged to rounding.
            let (d, rounding) = ((m - e).abs(), 8.0 * f64::EPSILON * e.abs());
            if d <= ci + rounding {
                inside += 1;
            }
            // NaN (a mean or a reference that is not a number) is off too.
            if d.is_nan() || d > widen * ci + rounding {
                off.push(t);
            }
        }
        let source = if r.source.contains("at this n") {
            r.source.to_string()
        } else {
            format!("{}; exact at this n", r.source)
        };
        if off.is_empty() {
            let _ = writeln!(
                s,
                "  {:<8} agrees with {} ({source}): {inside} of {nt} times within their 99.9% interval, all {nt} within the joint one (Bonferroni)",
                r.of, r.name,
            );
        } else {
            let times: Vec<String> = off.iter().take(6).map(|t| num(*t)).collect();
            let _ = writeln!(
                s,
                "  {:<8} DISAGREES with {} ({source}): outside the joint 99.9% interval at t = {}{} ({} of {nt} times; {inside} of {nt} within their own interval)",
                r.of,
                r.name,
                times.join(", "),
                if off.len() > 6 { ", ..." } else { "" },
                off.len()
            );
        }
    }
    if refs.iter().all(|r| r.kind != Kind::MeanAtN) {
        let _ = writeln!(
            s,
            "  no reference is the exact mean at this n: nothing is judged"
        );
    }
    for r in refs.iter().filter(|r| r.kind != Kind::MeanAtN) {
        let flagged = not_computable(r);
        if !flagged.is_empty() {
            let _ = writeln!(
                s,
                "  not computable here: {} ({}) at t = {} ({} of {nt} times: its closed form leaves \
                 the range of f64 at these parameters; the column holds NaN there)",
                r.name,
                r.source,
                at(&flagged),
                flagged.len()
            );
        }
    }
    for kind in [Kind::Limit, Kind::Approximation] {
        // Grouped by source: `T_exact, T_bulk_exact (GRW (13)-(14))`.
        let mut groups: Vec<(&str, Vec<&str>)> = Vec::new();
        // A reference not computable at any time is flagged above, not listed as shown.
        let shown = |r: &&ReferenceCurve| r.kind == kind && not_computable(r).len() < nt;
        for r in refs.iter().filter(shown) {
            match groups.iter_mut().find(|(src, _)| *src == r.source) {
                Some((_, names)) if !names.contains(&r.name) => names.push(r.name),
                Some(_) => {}
                None => groups.push((r.source, vec![r.name])),
            }
        }
        if !groups.is_empty() {
            let list: Vec<String> = groups
                .iter()
                .map(|(src, names)| format!("{} ({src})", names.join(", ")))
                .collect();
            let _ = writeln!(
                s,
                "  shown, not judged ({}): {}",
                kind.words(),
                list.join("; ")
            );
        }
    }
}

/// A figure of the summary: six decimals where that keeps six significant digits' worth
/// (`1e-3 <= |x| < 1e7`, or 0), scientific notation otherwise (a cooling gas's `T = 3e-12`
/// would print as 0.000000).
pub(crate) fn num(x: f64) -> String {
    if x == 0.0 || (x.abs() >= 1e-3 && x.abs() < 1e7) || !x.is_finite() {
        format!("{x:.6}")
    } else {
        format!("{x:.6e}")
    }
}
