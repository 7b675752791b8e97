//! The distribution charts: speed histogram, reduced distribution, Delta(c), G(c) and the
//! marginal distribution.

use super::profile::{Series, Style, profile_svg};
use crate::error::Error;
use crate::report::files::write_atomic;
use crate::run::RunStats;
use plotters::prelude::*;
use std::path::Path;

/// Writes the distribution charts a run has: histogram.svg (speed density, log scale, GRW
/// (31)-(33)), reduced.svg (f~(c) beside phi, log scale), delta.svg (Delta(c) beside
/// S_2(c^2), MS Figures 2, 5, 9), G.svg (G(c), log scale, MS Figures 3, 7, 10) and
/// marginal.svg (BRS Figure 4, log scale).
pub fn write_distribution_charts(
    dir: &Path,
    scene: &str,
    stats: &RunStats,
    reduced: Option<&crate::analysis::distribution::Reduced>,
    marginal: Option<&crate::analysis::distribution::Marginal>,
) -> Result<(), Error> {
    let mut charts: Vec<(&str, Result<String, String>)> = Vec::new();
    if let Some((radius, h)) = &stats.histogram {
        let k = h.len() - 1;
        let pts = (0..k)
            .map(|i| {
                let (lo, hi) = (
                    radius * i as f64 / k as f64,
                    radius * (i + 1) as f64 / k as f64,
                );
                let vol = 4.0 / 3.0 * std::f64::consts::PI * (hi.powi(3) - lo.powi(3));
                (0.5 * (lo + hi), h.mean(i) / vol, h.ci(i) / vol)
            })
            .collect();
        charts.push((
            "histogram.svg",
            profile_svg(
                &format!("{scene}: speed density (GRW (31)-(33)), last observation"),
                "|v|",
                "f(|v|) per unit volume",
                true,
                &[Series {
                    label: "shells, 99.9% bars".into(),
                    points: pts,
                    style: Style::Points,
                    color: BLUE,
                }],
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
            "reduced.svg",
            profile_svg(
                &format!("{scene}: reduced distribution f(c), c = |v - V| / v0"),
                "c",
                "f(c)",
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
            "delta.svg",
            profile_svg(
                &format!(
                    "{scene}: Delta(c) = (f/phi - 1)/a2 (MS (45)), a2 = {:.4}",
                    r.a2.0
                ),
                "c",
                "Delta(c)",
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
            charts.push((
                "G.svg",
                profile_svg(
                    &format!(
                        "{scene}: G(c) = exp(A c^{}) f(c), A = {:.3} ({})",
                        t.power, t.amplitude, t.equation
                    ),
                    "c",
                    "G(c)",
                    true,
                    &[
                        Series {
                            label: "run, 99.9% bars".into(),
                            points: run(&|s| {
                                (
                                    s.g,
                                    if s.f.0 > 0.0 {
                                        s.g * s.f.1 / s.f.0
                                    } else {
                                        0.0
                                    },
                                )
                            }),
                            style: Style::Points,
                            color: BLUE,
                        },
                        Series {
                            label: "phi in place of f (Maxwell-Boltzmann)".into(),
                            points: run(&|s| (s.g_maxwell, 0.0)),
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
            "marginal.svg",
            profile_svg(
                &format!("{scene}: marginal f_1 of v_{} (BRS Figure 4)", m.axis + 1),
                &format!("v_{}", m.axis + 1),
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
    for (file, svg) in charts {
        match svg {
            Ok(svg) => write_atomic(&dir.join(file), svg.as_bytes())?,
            Err(e) => eprintln!("chart {file}: not drawn ({e})"),
        }
    }
    Ok(())
}
