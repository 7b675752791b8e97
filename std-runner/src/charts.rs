//! SVG charts: each observable against time, its 99.9% confidence band shaded, the reference
//! curves dashed. Written next to observables.csv, atomically.

use crate::ensemble::RunStats;
use crate::error::Error;
use crate::output::write_atomic;
use crate::references::ReferenceCurve;
use plotters::prelude::*;
use std::path::Path;

/// The observables drawn, when present.
pub const CHARTED: [&str; 9] = [
    "T",
    "T_bulk",
    "log10_T_bulk",
    "V_norm",
    "a2",
    "a3",
    "crit",
    "mu2",
    "mu4",
];

/// One chart as SVG text.
pub fn chart_svg(
    stats: &RunStats,
    col: usize,
    title: &str,
    refs: &[&ReferenceCurve],
) -> Result<String, String> {
    let name = stats.names[col];
    let mut svg = String::new();
    {
        let root = SVGBackend::with_string(&mut svg, (800, 500)).into_drawing_area();
        root.fill(&WHITE).map_err(|e| e.to_string())?;
        let t = &stats.times;
        let pts: Vec<(f64, f64, f64)> = (0..t.len())
            .map(|i| (t[i], stats.mean(i, col), stats.ci(i, col)))
            .collect();
        let finite = |x: &f64| x.is_finite();
        let mut lo = pts
            .iter()
            .map(|p| p.1 - if p.2.is_finite() { p.2 } else { 0.0 })
            .filter(finite)
            .fold(f64::INFINITY, f64::min);
        let mut hi = pts
            .iter()
            .map(|p| p.1 + if p.2.is_finite() { p.2 } else { 0.0 })
            .filter(finite)
            .fold(f64::NEG_INFINITY, f64::max);
        for r in refs {
            for &x in t {
                let y = (r.curve)(x);
                if y.is_finite() {
                    lo = lo.min(y);
                    hi = hi.max(y);
                }
            }
        }
        if !(lo.is_finite() && hi.is_finite()) {
            return Err("no finite values to draw".into());
        }
        let pad = if hi > lo {
            0.05 * (hi - lo)
        } else {
            0.5 * lo.abs().max(1e-300)
        };
        let (t0, t1) = (t[0], t[t.len() - 1].max(t[0] + 1e-300));
        let mut chart = ChartBuilder::on(&root)
            .caption(title, ("sans-serif", 22))
            .margin(12)
            .x_label_area_size(40)
            .y_label_area_size(80)
            .build_cartesian_2d(t0..t1, (lo - pad)..(hi + pad))
            .map_err(|e| e.to_string())?;
        chart
            .configure_mesh()
            .x_desc("t")
            .y_desc(name)
            .draw()
            .map_err(|e| e.to_string())?;
        let band: Vec<(f64, f64)> = pts
            .iter()
            .map(|p| (p.0, p.1 + p.2))
            .chain(pts.iter().rev().map(|p| (p.0, p.1 - p.2)))
            .filter(|p| p.1.is_finite())
            .collect();
        chart
            .draw_series(std::iter::once(Polygon::new(band, BLUE.mix(0.2).filled())))
            .map_err(|e| e.to_string())?
            .label("99.9% confidence band")
            .legend(|(x, y)| Rectangle::new([(x, y - 5), (x + 20, y + 5)], BLUE.mix(0.2).filled()));
        chart
            .draw_series(LineSeries::new(
                pts.iter().map(|p| (p.0, p.1)),
                BLUE.stroke_width(2),
            ))
            .map_err(|e| e.to_string())?
            .label("ensemble mean")
            .legend(|(x, y)| PathElement::new([(x, y), (x + 20, y)], BLUE.stroke_width(2)));
        let colors = [RED, GREEN, MAGENTA, BLACK];
        for (k, r) in refs.iter().enumerate() {
            let c = colors[k % colors.len()];
            let n = 400;
            let line: Vec<(f64, f64)> = (0..=n)
                .map(|i| t0 + (t1 - t0) * i as f64 / n as f64)
                .map(|x| (x, (r.curve)(x)))
                .collect();
            // Dashes: every other short segment.
            let dashes = line
                .chunks(4)
                .step_by(2)
                .map(|seg| PathElement::new(seg.to_vec(), c.stroke_width(2)));
            chart
                .draw_series(dashes)
                .map_err(|e| e.to_string())?
                .label(format!("{} ({})", r.name, r.source))
                .legend(move |(x, y)| PathElement::new([(x, y), (x + 8, y)], c.stroke_width(2)));
        }
        chart
            .configure_series_labels()
            .background_style(WHITE.mix(0.8))
            .border_style(BLACK)
            .position(SeriesLabelPosition::LowerRight)
            .draw()
            .map_err(|e| e.to_string())?;
        root.present().map_err(|e| e.to_string())?;
    }
    Ok(svg)
}

/// Writes `NAME.svg` for every charted observable of the run into `dir`.
pub fn write_charts(
    dir: &Path,
    scene: &str,
    stats: &RunStats,
    refs: &[ReferenceCurve],
) -> Result<(), Error> {
    for name in CHARTED {
        let Some(col) = stats.col(name) else { continue };
        let these: Vec<&ReferenceCurve> = refs.iter().filter(|r| r.of == name).collect();
        let title = format!("{scene}: {name}, {} ensembles", stats.ensembles);
        match chart_svg(stats, col, &title, &these) {
            Ok(svg) => write_atomic(&dir.join(format!("{name}.svg")), svg.as_bytes())?,
            Err(e) => eprintln!("chart {name}: not drawn ({e})"),
        }
    }
    if let Some((radius, h)) = &stats.histogram
        && let Some(fit) = crate::tails::fit(*radius, h)
    {
        let all = crate::tails::tail_points(*radius, h);
        match tail_svg(&format!("{scene}: tail (GRW Section 4.3)"), &fit, &all) {
            Ok(svg) => write_atomic(&dir.join("tail.svg"), svg.as_bytes())?,
            Err(e) => eprintln!("tail chart: not drawn ({e})"),
        }
    }
    Ok(())
}

/// The tail plot of GRW Section 4.3 (GRW Figures 7-9): the points `(x_k, y_k)`, the fitted line,
/// and the lines of slope 1, 5/4 and 3/2 through the fit's centre for comparison.
pub fn tail_svg(
    title: &str,
    fit: &crate::tails::TailFit,
    all: &[(usize, f64, f64)],
) -> Result<String, String> {
    let mut svg = String::new();
    {
        let root = SVGBackend::with_string(&mut svg, (800, 500)).into_drawing_area();
        root.fill(&WHITE).map_err(|e| e.to_string())?;
        let (x0, x1) = all.iter().fold((f64::INFINITY, f64::NEG_INFINITY), |a, p| {
            (a.0.min(p.1), a.1.max(p.1))
        });
        let (y0, y1) = all.iter().fold((f64::INFINITY, f64::NEG_INFINITY), |a, p| {
            (a.0.min(p.2), a.1.max(p.2))
        });
        if !(x0 < x1 && y0 < y1) {
            return Err("too few points".into());
        }
        let mut chart = ChartBuilder::on(&root)
            .caption(title, ("sans-serif", 22))
            .margin(12)
            .x_label_area_size(40)
            .y_label_area_size(60)
            .build_cartesian_2d(x0..x1, (y0 - 0.5)..(y1 + 0.5))
            .map_err(|e| e.to_string())?;
        chart
            .configure_mesh()
            .x_desc("x = ln(r_k - r_1)")
            .y_desc("y = ln(ln f_1 - ln f_k)")
            .draw()
            .map_err(|e| e.to_string())?;
        chart
            .draw_series(
                all.iter()
                    .map(|p| Circle::new((p.1, p.2), 3, BLUE.filled())),
            )
            .map_err(|e| e.to_string())?
            .label("shells (GRW (31)-(33))")
            .legend(|(x, y)| Circle::new((x + 10, y), 3, BLUE.filled()));
        let (mx, my) = fit
            .points
            .iter()
            .fold((0.0, 0.0), |a, p| (a.0 + p.1, a.1 + p.2));
        let (mx, my) = (mx / fit.points.len() as f64, my / fit.points.len() as f64);
        let line = |b: f64| vec![(x0, my + b * (x0 - mx)), (x1, my + b * (x1 - mx))];
        chart
            .draw_series(std::iter::once(PathElement::new(
                line(fit.slope),
                RED.stroke_width(2),
            )))
            .map_err(|e| e.to_string())?
            .label(format!(
                "fit: slope {:.3} +- {:.3}",
                fit.slope, fit.slope_ci
            ))
            .legend(|(x, y)| PathElement::new([(x, y), (x + 20, y)], RED.stroke_width(2)));
        for (b, c) in [(1.0, BLACK), (1.25, GREEN), (1.5, MAGENTA)] {
            chart
                .draw_series(std::iter::once(PathElement::new(
                    line(b),
                    c.stroke_width(1),
                )))
                .map_err(|e| e.to_string())?
                .label(format!("slope {b}"))
                .legend(move |(x, y)| PathElement::new([(x, y), (x + 20, y)], c.stroke_width(1)));
        }
        chart
            .configure_series_labels()
            .background_style(WHITE.mix(0.8))
            .border_style(BLACK)
            .position(SeriesLabelPosition::UpperLeft)
            .draw()
            .map_err(|e| e.to_string())?;
        root.present().map_err(|e| e.to_string())?;
    }
    Ok(svg)
}

/// How a series of a profile chart is drawn.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Style {
    /// Points with 99.9% error bars (the run).
    Points,
    /// A solid line.
    Line,
    /// A dashed line (a reference).
    Dashed,
}

/// One series of a profile chart: `(x, y, half-width)` points.
pub struct Series {
    /// Legend text.
    pub label: String,
    /// The points; non-finite and (on a log axis) non-positive values are left out.
    pub points: Vec<(f64, f64, f64)>,
    /// How to draw it.
    pub style: Style,
    /// Colour.
    pub color: RGBColor,
}

/// A chart of several series against one variable, on a linear or logarithmic y axis.
pub fn profile_svg(
    title: &str,
    x_desc: &str,
    y_desc: &str,
    log_y: bool,
    series: &[Series],
) -> Result<String, String> {
    let keep = |p: &&(f64, f64, f64)| p.0.is_finite() && p.1.is_finite() && (!log_y || p.1 > 0.0);
    let (mut x0, mut x1, mut y0, mut y1) = (
        f64::INFINITY,
        f64::NEG_INFINITY,
        f64::INFINITY,
        f64::NEG_INFINITY,
    );
    // The run's points set the y range when there are any (references are clipped to it).
    let has_points = series.iter().any(|s| s.style == Style::Points);
    for s in series {
        for p in s.points.iter().filter(keep) {
            x0 = x0.min(p.0);
            x1 = x1.max(p.0);
            if s.style == Style::Points || !has_points {
                y0 = y0.min(p.1);
                y1 = y1.max(p.1);
            }
        }
    }
    if !(x0 < x1 && y0 <= y1) {
        return Err("no finite values to draw".into());
    }
    let (y_lo, y_hi) = if log_y {
        (y0 / 2.0, y1 * 2.0)
    } else {
        let pad = if y1 > y0 {
            0.05 * (y1 - y0)
        } else {
            0.5 * y0.abs().max(1e-300)
        };
        (y0 - pad, y1 + pad)
    };
    let mut svg = String::new();
    {
        let root = SVGBackend::with_string(&mut svg, (800, 500)).into_drawing_area();
        root.fill(&WHITE).map_err(|e| e.to_string())?;
        let mut builder = ChartBuilder::on(&root);
        builder
            .caption(title, ("sans-serif", 20))
            .margin(12)
            .x_label_area_size(40)
            .y_label_area_size(70);
        macro_rules! draw {
            ($chart:expr) => {{
                let mut chart = $chart;
                let fmt_log = |y: &f64| format!("{y:.0e}");
                let fmt_lin = |y: &f64| format!("{y}");
                let fmt: &dyn Fn(&f64) -> String = if log_y { &fmt_log } else { &fmt_lin };
                chart
                    .configure_mesh()
                    .x_desc(x_desc)
                    .y_desc(y_desc)
                    .y_label_formatter(fmt)
                    .draw()
                    .map_err(|e| e.to_string())?;
                for s in series {
                    let pts: Vec<(f64, f64, f64)> = s.points.iter().filter(keep).copied().collect();
                    let color = s.color;
                    match s.style {
                        Style::Points => {
                            chart
                                .draw_series(pts.iter().map(|p| {
                                    let lo = if log_y {
                                        (p.1 - p.2).max(p.1 * 1e-3)
                                    } else {
                                        p.1 - p.2
                                    };
                                    ErrorBar::new_vertical(
                                        p.0,
                                        lo,
                                        p.1,
                                        p.1 + p.2,
                                        color.filled(),
                                        4,
                                    )
                                }))
                                .map_err(|e| e.to_string())?
                                .label(s.label.clone())
                                .legend(move |(x, y)| Circle::new((x + 10, y), 3, color.filled()));
                        }
                        Style::Line | Style::Dashed => {
                            let xy: Vec<(f64, f64)> = pts
                                .iter()
                                .filter(|p| p.1 >= y_lo && p.1 <= y_hi)
                                .map(|p| (p.0, p.1))
                                .collect();
                            let dashed = s.style == Style::Dashed;
                            if dashed {
                                chart.draw_series(DashedLineSeries::new(
                                    xy,
                                    6,
                                    4,
                                    color.stroke_width(2),
                                ))
                            } else {
                                chart.draw_series(LineSeries::new(xy, color.stroke_width(2)))
                            }
                            .map_err(|e| e.to_string())?
                            .label(s.label.clone())
                            .legend(move |(x, y)| {
                                PathElement::new([(x, y), (x + 20, y)], color.stroke_width(2))
                            });
                        }
                    }
                }
                chart
                    .configure_series_labels()
                    .background_style(WHITE.mix(0.8))
                    .border_style(BLACK)
                    .position(SeriesLabelPosition::UpperRight)
                    .draw()
                    .map_err(|e| e.to_string())?;
            }};
        }
        if log_y {
            let (a, b) = (y_lo, y_hi);
            draw!(
                builder
                    .build_cartesian_2d(x0..x1, (a..b).log_scale())
                    .map_err(|e| e.to_string())?
            );
        } else {
            draw!(
                builder
                    .build_cartesian_2d(x0..x1, y_lo..y_hi)
                    .map_err(|e| e.to_string())?
            );
        }
        root.present().map_err(|e| e.to_string())?;
    }
    Ok(svg)
}

/// Writes the distribution charts a run has: histogram.svg (speed density, log scale, GRW
/// (31)-(33)), reduced.svg (f~(c) beside phi, log scale), delta.svg (Delta(c) beside
/// S_2(c^2), MS Figures 2, 5, 9), G.svg (G(c), log scale, MS Figures 3, 7, 10) and
/// marginal.svg (BRS Figure 4, log scale).
pub fn write_distribution_charts(
    dir: &Path,
    scene: &str,
    stats: &RunStats,
    reduced: Option<&crate::distribution::Reduced>,
    marginal: Option<&crate::distribution::Marginal>,
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
        let ok = |s: &crate::distribution::ReducedShell| s.f.0 > 0.0 && s.f.1 < 0.2 * s.f.0;
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
        let mid = |s: &crate::distribution::ReducedShell| 0.5 * (s.c_lo + s.c_hi);
        let run = |f: &dyn Fn(&crate::distribution::ReducedShell) -> (f64, f64)| {
            bounded
                .iter()
                .map(|s| {
                    let (y, e) = f(s);
                    (mid(s), y, e)
                })
                .collect::<Vec<_>>()
        };
        let scale = |s: &crate::distribution::ReducedShell| {
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
        let mid = |b: &crate::distribution::MarginalBin| 0.5 * (b.v_lo + b.v_hi);
        let pts = |f: &dyn Fn(&crate::distribution::MarginalBin) -> (f64, f64)| {
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
