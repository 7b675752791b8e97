//! The distribution charts: speed histogram, reduced distribution, Delta(c), G(c) and the
//! marginal distribution.

use super::frame::Chart;
use super::profile::{Series, Style, profile};
use crate::run::RunStats;
use crate::run::columns::name;
use gdsmc_theory::exact::tail;
use plotters::prelude::*;

/// The distribution charts a run has, `(file stem, chart)`: histogram (speed density, log
/// scale, GRW (31)-(33), with the Maxwellian of the run's temperature), reduced (f~(c) beside
/// phi, log scale), delta (Delta(c) beside S_2(c^2), MS Figures 2, 5, 9), G (G(c) of MS
/// Figures 3, 7, 10 as its ratio to the Maxwellian's, f/phi, log scale) and marginal (BRS
/// Figure 4, log scale). Each title names the chart, `scene` (the run's physics, size and
/// ensembles) below it.
pub fn distribution_charts(
    scene: &str,
    stats: &RunStats,
    reduced: Option<&crate::analysis::distribution::Reduced>,
    marginal: Option<&crate::analysis::distribution::Marginal>,
) -> Vec<(String, Result<Chart, String>)> {
    let mut charts: Vec<(&str, Result<Chart, String>)> = Vec::new();
    if let Some(crate::run::ShellHistogram { radius, weights: h }) = &stats.histogram {
        let k = h.len() - 1;
        // Shell i: [lo, hi) and its volume.
        let shell = |i: usize| {
            let (lo, hi) = (
                radius * i as f64 / k as f64,
                radius * (i + 1) as f64 / k as f64,
            );
            (lo, hi, tail::shell_volume_in(stats.dimension, lo, hi))
        };
        let pts = (0..k)
            .map(|i| {
                let (lo, hi, vol) = shell(i);
                (0.5 * (lo + hi), h.mean(i) / vol, h.ci(i) / vol)
            })
            .collect::<Vec<_>>();
        // The Maxwellian with the run's temperature at the last observation (GRW's T, about
        // zero velocity, as the shells are), averaged over each shell as the histogram is.
        let last = stats.times.len() - 1;
        let temperature = stats.col(name::T).map_or(f64::NAN, |c| stats.mean(last, c));
        let maxwellian = (0..k)
            .map(|i| {
                let (lo, hi, vol) = shell(i);
                let v0 = (2.0 * temperature).sqrt();
                (
                    0.5 * (lo + hi),
                    tail::phi_shell_in(stats.dimension, lo / v0, hi / v0) / vol,
                    0.0,
                )
            })
            .collect::<Vec<_>>();
        charts.push((
            "histogram",
            profile(
                &format!("speed density (GRW (31)-(33)), last observation\n{scene}"),
                "speed |v| (scene units)",
                "density f(|v|) per unit velocity volume",
                true,
                &[
                    Series {
                        label: "shells, 99.9% bars".into(),
                        points: pts,
                        style: Style::Points,
                        color: BLUE,
                    },
                    Series {
                        label: format!(
                            "Maxwellian of the same T = {temperature:.4} (about 0), for comparison"
                        ),
                        points: maxwellian,
                        style: Style::Dashed,
                        color: BLACK,
                    },
                ],
            ),
        ));
    }
    if let Some(r) = reduced {
        let bounded: Vec<_> = r.shells.iter().filter(|s| s.c_hi.is_finite()).collect();
        // Delta(c) is drawn where it is resolved: shells whose weight has a relative
        // half-width below 20% (MS Figures 2, 5, 9 stop near c = 3 for that reason), and
        // S_2 over the same range.
        let ok =
            |s: &crate::analysis::distribution::ReducedShell| s.f.0 > 0.0 && s.f.1 < 0.2 * s.f.0;
        let c_top = bounded
            .iter()
            .filter(|s| ok(s))
            .map(|s| s.c_hi)
            .fold(0.0, f64::max);
        let resolved_delta: Vec<(f64, f64, f64)> = bounded
            .iter()
            .filter(|s| ok(s))
            .map(|s| (0.5 * (s.c_lo + s.c_hi), s.delta.0, s.delta.1))
            .collect();
        let resolved = bounded.iter().take_while(|s| s.c_hi <= c_top).count();
        let mid = |s: &crate::analysis::distribution::ReducedShell| 0.5 * (s.c_lo + s.c_hi);
        let run = |f: &dyn Fn(&crate::analysis::distribution::ReducedShell) -> (f64, f64)| {
            bounded
                .iter()
                .map(|s| {
                    let (y, e) = f(s);
                    (mid(s), y, e)
                })
                .collect::<Vec<_>>()
        };
        let scale = |s: &crate::analysis::distribution::ReducedShell| {
            if s.f.0 > 0.0 { s.density / s.f.0 } else { 0.0 }
        };
        charts.push((
            "reduced",
            profile(
                &format!("reduced distribution f(c), c = |v - V| / v0\n{scene}"),
                "reduced speed c = |v - V| / v0 (dimensionless)",
                "reduced density f(c)",
                true,
                &[
                    Series {
                        label: "run, 99.9% bars".into(),
                        points: run(&|s| (s.density, s.f.1 * scale(s))),
                        style: Style::Points,
                        color: BLUE,
                    },
                    Series {
                        label: "phi(c), Maxwell-Boltzmann".into(),
                        points: run(&|s| (s.phi, 0.0)),
                        style: Style::Dashed,
                        color: BLACK,
                    },
                ],
            ),
        ));
        charts.push((
            "delta",
            profile(
                &format!(
                    "Delta(c) = (f/phi - 1)/a2 (MS (45)), a2 = {:.4}\n{scene}",
                    r.a2.0
                ),
                "reduced speed c = |v - V| / v0 (dimensionless)",
                "deviation from the Maxwellian Delta(c)",
                false,
                &[
                    Series {
                        label: "run, 99.9% bars".into(),
                        points: resolved_delta,
                        style: Style::Points,
                        color: BLUE,
                    },
                    Series {
                        label: "S2(c^2), first Sonine".into(),
                        points: run(&|s| (s.s2, 0.0))[..resolved].to_vec(),
                        style: Style::Dashed,
                        color: BLACK,
                    },
                ],
            ),
        ));
        if let Some(t) = &r.tail {
            // G(c) itself spans many decades (exp(A c^p) against the Gaussian core), which
            // hides the tail's departure; its ratio to the Maxwellian's G is f/phi, 1 for a
            // Maxwellian, the over- or under-population read off directly.
            charts.push((
                "G",
                profile(
                    &format!(
                        "G(c) / G of the Maxwellian = f/phi, G = exp(A c^{}) f, A = {:.3} ({})\n{scene}",
                        t.power, t.amplitude, t.equation
                    ),
                    "reduced speed c = |v - V| / v0 (dimensionless)",
                    "tail ratio G(c) / G_Maxwell(c)",
                    true,
                    &[
                        Series {
                            label: "run, 99.9% bars".into(),
                            points: run(&|s| s.ratio)[..resolved].to_vec(),
                            style: Style::Points,
                            color: BLUE,
                        },
                        Series {
                            label: "Maxwell-Boltzmann: 1".into(),
                            points: run(&|_| (1.0, 0.0))[..resolved].to_vec(),
                            style: Style::Dashed,
                            color: BLACK,
                        },
                    ],
                ),
            ));
        }
    }
    if let Some(m) = marginal {
        let mid = |b: &crate::analysis::distribution::MarginalBin| 0.5 * (b.v_lo + b.v_hi);
        let pts = |f: &dyn Fn(&crate::analysis::distribution::MarginalBin) -> (f64, f64)| {
            m.bins
                .iter()
                .map(|b| {
                    let (y, e) = f(b);
                    (mid(b), y, e)
                })
                .collect::<Vec<_>>()
        };
        charts.push((
            "marginal",
            profile(
                &format!("marginal f_1 of v_{} (BRS Figure 4)\n{scene}", m.axis + 1),
                &format!("velocity component v_{} (scene units)", m.axis + 1),
                "density",
                true,
                &[
                    Series {
                        label: format!("t = {}", m.times.0),
                        points: pts(&|b| b.first),
                        style: Style::Points,
                        color: BLUE,
                    },
                    Series {
                        label: format!("Maxwellian, t = {}", m.times.0),
                        points: pts(&|b| (b.first_maxwell, 0.0)),
                        style: Style::Dashed,
                        color: BLUE,
                    },
                    Series {
                        label: format!("t = {}", m.times.1),
                        points: pts(&|b| b.last),
                        style: Style::Points,
                        color: RED,
                    },
                    Series {
                        label: format!("Maxwellian, t = {}", m.times.1),
                        points: pts(&|b| (b.last_maxwell, 0.0)),
                        style: Style::Dashed,
                        color: RED,
                    },
                ],
            ),
        ));
    }
    charts
        .into_iter()
        .map(|(stem, c)| (stem.to_string(), c))
        .collect()
}
