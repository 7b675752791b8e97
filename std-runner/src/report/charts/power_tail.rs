//! The reduced tail's local slopes (analysis/power_tail/): `s(x)` over each window `[x, 2x]`
//! resolved with every nearer one, with its 99.9% bars, and the exact root where one holds.

use super::frame::Chart;
use super::profile::{Series, Style, profile};
use crate::analysis::power_tail::PowerTail;
use plotters::prelude::*;

/// The chart `power_tail`: the local slopes against the window's start `x`, the exact root as
/// a dashed line; an error when no window is resolved.
pub fn power_tail(scene: &str, t: &PowerTail) -> Result<Chart, String> {
    let shown: Vec<(f64, f64, f64)> = crate::analysis::power_tail::resolved(&t.slopes)
        .iter()
        .map(|s| (s.from, s.value, s.ci))
        .collect();
    let (Some(first), Some(last)) = (shown.first(), shown.last()) else {
        return Err("no window resolved".into());
    };
    let mut series = vec![Series {
        label: "local slope ln(P(c >= x)/P(c >= 2x))/ln 2, 99.9% bars".into(),
        points: shown.clone(),
        style: Style::Points,
        color: BLUE,
    }];
    if let Some(s) = t.exact {
        series.push(Series {
            label: format!("exact s = {s:.4} (GRW (3)'s scattering form, e uniform)"),
            points: vec![(first.0, s, 0.0), (last.0, s, 0.0)],
            style: Style::Dashed,
            color: BLACK,
        });
    }
    profile(
        &format!("local slope of the reduced tail P(c >= x) (s for a power law x^-s)\n{scene}"),
        "window start x = c (the window is [x, 2x]; c = |v - V| / v0)",
        "local slope s(x) (dimensionless)",
        false,
        &series,
    )
}
