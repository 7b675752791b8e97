//! A sweep's verdict: each observable that has an exact ensemble mean at the run's n (a
//! reference of kind [`Kind::MeanAtN`]) against it at every point together. Each point's mean
//! must lie within its 99.9% half-width widened for the family of points (Bonferroni:
//! `gdsmc_stats::level::family(k, dof)`), so the sweep as a whole misses at most 0.1% of the
//! time when the engine is right; a point outside is named.

use super::point::PointResult;
use gdsmc_stats::level::{dof, family};
use gdsmc_theory::curves::Kind;

/// One observable's joint check over the points.
#[derive(Clone, Debug, PartialEq)]
pub struct Check {
    /// The observable.
    pub of: &'static str,
    /// Its exact mean at n.
    pub reference: &'static str,
    /// Points checked.
    pub points: usize,
    /// The largest `|mean - exact| / (half-width x family factor)` over them (<= 1: inside).
    pub worst: f64,
    /// The points outside.
    pub outside: Vec<usize>,
}

/// Every joint check the points allow (none when no exact mean at n applies, or a point has
/// fewer than two ensembles).
pub fn checks(results: &[PointResult]) -> Vec<Check> {
    let mut pairs: Vec<(&'static str, &'static str)> = Vec::new();
    for r in results {
        for e in r.references.iter().filter(|e| e.kind == Kind::MeanAtN) {
            if !pairs.contains(&(e.of, e.name)) {
                pairs.push((e.of, e.name));
            }
        }
    }
    pairs
        .into_iter()
        .filter_map(|(of, name)| {
            let found: Vec<(usize, f64, f64, u64)> = results
                .iter()
                .filter_map(|r| {
                    let o = r.observables.iter().find(|o| o.0 == of)?;
                    let e = r.references.iter().find(|e| e.name == name)?;
                    Some((r.index, (o.1 - e.value).abs(), o.2, r.ensembles))
                })
                .filter(|c| c.1.is_finite() && c.2.is_finite() && c.2 > 0.0)
                .collect();
            if found.is_empty() || found.iter().any(|c| c.3 < 2) {
                return None;
            }
            let k = found.len();
            let scores: Vec<(usize, f64)> = found
                .iter()
                .map(|&(i, diff, ci, m)| (i, diff / (ci * family(k, dof(m)))))
                .collect();
            Some(Check {
                of,
                reference: name,
                points: k,
                worst: scores.iter().map(|s| s.1).fold(0.0, f64::max),
                outside: scores.iter().filter(|s| s.1 > 1.0).map(|s| s.0).collect(),
            })
        })
        .collect()
}

/// The verdict's lines for the terminal.
pub fn text(checks: &[Check]) -> String {
    checks
        .iter()
        .map(|c| {
            let result = if c.outside.is_empty() {
                "all inside".to_string()
            } else {
                let pts: Vec<String> = c.outside.iter().map(usize::to_string).collect();
                format!("OUTSIDE at point {}", pts.join(", "))
            };
            format!(
                "verdict    {} against {} at {} points together (99.9% for the family): {result}, largest |mean - exact| {:.2} of its widened half-width\n",
                c.of, c.reference, c.points, c.worst
            )
        })
        .collect()
}
