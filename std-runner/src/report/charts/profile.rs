//! Profile charts: series of points with error bars, lines and dashed references against a
//! variable other than time (speed, reduced speed, a velocity component).

use super::frame::{Chart, Entry, Frame, Geometry, LINE_WIDTH, Layer, Swatch, plot_rect};
use plotters::prelude::*;

/// How a series of a profile chart is drawn.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Style {
    /// Points with 99.9% error bars (the run).
    Points,
    /// A solid line.
    Line,
    /// A dashed line (a reference; the k-th dashed series of a chart takes the k-th of
    /// [`DASHES`]).
    Dashed,
}

/// Dash and gap of a chart's dashed series, in order: each its own, so that grey scale tells
/// them apart.
pub const DASHES: [(u32, u32); 4] = [(6, 4), (2, 3), (12, 5), (18, 6)];

/// Each series' dash (`None` for points and solid lines), in order.
fn dashes(series: &[Series]) -> Vec<Option<(u32, u32)>> {
    let mut k = 0;
    series
        .iter()
        .map(|s| {
            (s.style == Style::Dashed).then(|| {
                k += 1;
                DASHES[(k - 1) % DASHES.len()]
            })
        })
        .collect()
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

/// A tick label on an axis spanning `span`: the value to a thousandth of the span's decade,
/// printed shortest (a tick at `0.12000000000000001` reads `0.12`), so 0 where it is zero to
/// within the axis' resolution (a tick computed as `lo + k step` that should be 0 came out
/// `-1.1e-16` and printed `-0.000000000000000111022302463` over its neighbours).
/// Very small and very large values in scientific form (`-6e-8`, not `-0.00000006`), so that
/// no label outgrows its place (`Geometry::ticks`).
pub fn tick(y: f64, span: f64) -> String {
    // To a thousandth of the axis' decade: the digits that tell ticks apart, no more (the
    // axis' rounding noise, `-1.1e-16` for 0 or `-1.20903498483e-16` on an axis of 1e-16,
    // goes).
    let span = span.abs();
    let y = if span > 0.0 && span.is_finite() {
        let q = libm::pow(10.0, libm::floor(libm::log10(span)) - 3.0);
        (y / q).round() * q + 0.0
    } else {
        y
    };
    let rounded: f64 = format!("{y:.11e}").parse().unwrap_or(y);
    if rounded != 0.0 && !(1e-3..1e7).contains(&rounded.abs()) {
        format!("{rounded:e}")
    } else {
        format!("{rounded}")
    }
}

/// A residual panel's points under a profile chart: `(x, (mean - reference) / half-width)`,
/// where the 99.9% interval is the strip between -1 and 1.
pub struct Residuals {
    /// Legend text (what the residual is measured against).
    pub label: String,
    /// The points.
    pub points: Vec<(f64, f64)>,
    /// Colour (the series' it belongs to).
    pub color: RGBColor,
}

/// A chart of several series against one variable, on a linear or logarithmic y axis.
pub fn profile(
    title: &str,
    x_desc: &str,
    y_desc: &str,
    log_y: bool,
    series: &[Series],
) -> Result<Chart, String> {
    profile_with_residuals(title, x_desc, y_desc, (false, log_y), series, &[], "")
}

/// Whether `lo..hi` can be a logarithmic axis: ends that are normal positive numbers with a
/// finite ratio (else the axis's decades never end).
fn log_axis(lo: f64, hi: f64) -> bool {
    lo >= f64::MIN_POSITIVE && hi.is_finite() && (hi / lo).is_finite()
}

/// [`profile`] on logarithmic axes where `(log_x, log_y)` say so, with a residual panel below
/// when `residuals` has points (its y axis named `residual_desc`): each group's residuals in
/// its colour, the strip of the 99.9% interval between the dashed lines at -1 and 1.
pub fn profile_with_residuals(
    title: &str,
    x_desc: &str,
    y_desc: &str,
    (log_x, log_y): (bool, bool),
    series: &[Series],
    residuals: &[Residuals],
    residual_desc: &str,
) -> Result<Chart, String> {
    let keep = |p: &&(f64, f64, f64)| {
        p.0.is_finite() && p.1.is_finite() && (!log_y || p.1 > 0.0) && (!log_x || p.0 > 0.0)
    };
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
                let bar = if s.style == Style::Points && p.2.is_finite() {
                    p.2
                } else {
                    0.0
                };
                y0 = y0.min(if log_y { p.1 } else { p.1 - bar });
                y1 = y1.max(p.1 + bar);
            }
        }
    }
    if !(x0 < x1 && y0 <= y1) {
        return Err("no finite values to draw".into());
    }
    if has_points {
        // Points at the ends of the range keep their error bars off the axes.
        if log_x {
            let f = libm::pow(x1 / x0, 0.02);
            // Unpadded when padding would leave the range of f64 (a range of ~300 decades).
            if log_axis(x0 / f, x1 * f) {
                (x0, x1) = (x0 / f, x1 * f);
            }
        } else {
            let pad = 0.02 * (x1 - x0);
            (x0, x1) = (x0 - pad, x1 + pad);
        }
    }
    let (y_lo, y_hi) = if log_y {
        if log_axis(y0 / 2.0, y1 * 2.0) {
            (y0 / 2.0, y1 * 2.0)
        } else {
            (y0, y1)
        }
    } else {
        let pad = if y1 > y0 {
            0.05 * (y1 - y0)
        } else {
            0.5 * y0.abs().max(1e-300)
        };
        (y0 - pad, y1 + pad)
    };
    // A logarithmic axis needs ends that are normal positive numbers with a finite ratio:
    // else the axis's ticks never end (a range of ~300 decades once spun for minutes).
    for (on, lo, hi, which) in [(log_x, x0, x1, "x"), (log_y, y_lo, y_hi, "y")] {
        if on && !log_axis(lo, hi) {
            return Err(format!(
                "the logarithmic {which} axis would run from {lo:e} to {hi:e}, beyond the range \
                 of f64 a chart can divide into decades"
            ));
        }
    }
    let mut svg = String::new();
    let mut geometry = Geometry::new(title);
    // Every tick label drawn, for the review (`Geometry::ticks`).
    let ticks = std::cell::RefCell::new(Vec::new());
    let note = |label: String| {
        ticks.borrow_mut().push(label.clone());
        label
    };
    let dash = dashes(series);
    let mut entries: Vec<Entry> = series
        .iter()
        .zip(&dash)
        .map(|(s, d)| {
            let sw = match (s.style, d) {
                (Style::Points, _) => Swatch::Point(s.color),
                (Style::Dashed, Some((a, b))) => Swatch::Dashed(s.color, *a, *b),
                _ => Swatch::Line(s.color),
            };
            Entry::new(sw, s.label.clone())
        })
        .collect();
    let residuals: Vec<&Residuals> = residuals
        .iter()
        .filter(|r| r.points.iter().any(|p| p.0.is_finite() && p.1.is_finite()))
        .collect();
    entries.extend(
        residuals
            .iter()
            .map(|r| Entry::new(Swatch::Marker(r.color), r.label.clone())),
    );
    {
        let frame = Frame::new(&mut svg, title, &entries)?;
        let (upper, lower) = if residuals.is_empty() {
            (frame.plot.clone(), None)
        } else {
            let h = frame.plot.dim_in_pixel().1;
            let (a, b) = frame.plot.split_vertically((h as f64 * 0.68) as u32);
            (a, Some(b))
        };
        let x_upper = if lower.is_some() { "" } else { x_desc };
        geometry
            .axes
            .push((x_upper.to_string(), y_desc.to_string()));
        let mut builder = ChartBuilder::on(&upper);
        builder
            .margin(10)
            .x_label_area_size(if lower.is_some() { 20 } else { 40 })
            .y_label_area_size(80);
        macro_rules! draw {
            ($chart:expr) => {{
                let mut chart = $chart;
                let fmt_log = |y: &f64| format!("{y:.0e}");
                let fmt_lin = |y: &f64| note(tick(*y, y_hi - y_lo));
                let fmt: &dyn Fn(&f64) -> String = if log_y { &fmt_log } else { &fmt_lin };
                chart
                    .configure_mesh()
                    .x_desc(x_upper)
                    .y_desc(y_desc)
                    .y_label_formatter(fmt)
                    .x_label_formatter(&|x: &f64| note(tick(*x, x1 - x0)))
                    .draw()
                    .map_err(|e| e.to_string())?;
                let (xr, yr) = chart.plotting_area().get_pixel_range();
                geometry.plots.push(plot_rect(xr, yr));
                for (s, dash) in series.iter().zip(&dash) {
                    let pts: Vec<(f64, f64, f64)> = s.points.iter().filter(keep).copied().collect();
                    let color = s.color;
                    match s.style {
                        Style::Points => {
                            let bars: Vec<(f64, f64, f64)> = pts
                                .iter()
                                .map(|p| {
                                    let e = if p.2.is_finite() { p.2 } else { 0.0 };
                                    let lo = if log_y {
                                        (p.1 - e).max(p.1 * 1e-3).max(y_lo)
                                    } else {
                                        p.1 - e
                                    };
                                    (p.0, lo, (p.1 + e).min(y_hi))
                                })
                                .collect();
                            chart
                                .draw_series(pts.iter().zip(&bars).map(|(p, b)| {
                                    ErrorBar::new_vertical(p.0, b.1, p.1, b.2, color.filled(), 4)
                                }))
                                .map_err(|e| e.to_string())?;
                            for (p, b) in pts.iter().zip(&bars) {
                                geometry.data.push(chart.backend_coord(&(p.0, p.1)));
                                geometry.data.push(chart.backend_coord(&(p.0, b.1)));
                                geometry.data.push(chart.backend_coord(&(p.0, b.2)));
                            }
                        }
                        Style::Line | Style::Dashed => {
                            let xy: Vec<(f64, f64)> = pts
                                .iter()
                                .filter(|p| p.1 >= y_lo && p.1 <= y_hi)
                                .map(|p| (p.0, p.1))
                                .collect();
                            geometry
                                .data
                                .extend(xy.iter().map(|p| chart.backend_coord(p)));
                            geometry.layers.push(Layer::Line {
                                color,
                                dash: *dash,
                                label: s.label.clone(),
                            });
                            if let Some((a, b)) = *dash {
                                chart.draw_series(DashedLineSeries::new(
                                    xy,
                                    a as i32,
                                    b as i32,
                                    color.stroke_width(LINE_WIDTH),
                                ))
                            } else {
                                chart.draw_series(LineSeries::new(
                                    xy,
                                    color.stroke_width(LINE_WIDTH),
                                ))
                            }
                            .map_err(|e| e.to_string())?;
                        }
                    }
                }
            }};
        }
        let (a, b) = (y_lo, y_hi);
        match (log_x, log_y) {
            (false, false) => draw!(
                builder
                    .build_cartesian_2d(x0..x1, a..b)
                    .map_err(|e| e.to_string())?
            ),
            (false, true) => draw!(
                builder
                    .build_cartesian_2d(x0..x1, (a..b).log_scale())
                    .map_err(|e| e.to_string())?
            ),
            (true, false) => draw!(
                builder
                    .build_cartesian_2d((x0..x1).log_scale(), a..b)
                    .map_err(|e| e.to_string())?
            ),
            (true, true) => draw!(
                builder
                    .build_cartesian_2d((x0..x1).log_scale(), (a..b).log_scale())
                    .map_err(|e| e.to_string())?
            ),
        }
        if let Some(lower) = lower {
            let top = residuals
                .iter()
                .flat_map(|r| r.points.iter())
                .filter(|p| p.1.is_finite())
                .map(|p| p.1.abs())
                .fold(1.5, f64::max)
                * 1.1;
            let mut builder = ChartBuilder::on(&lower);
            builder
                .margin(10)
                .x_label_area_size(40)
                .y_label_area_size(80);
            macro_rules! lower {
                ($chart:expr) => {{
                    let mut d = $chart;
                    d.configure_mesh()
                        .x_desc(x_desc)
                        .y_desc(residual_desc)
                        .y_labels(5)
                        .x_label_formatter(&|x: &f64| note(tick(*x, x1 - x0)))
                        .draw()
                        .map_err(|e| e.to_string())?;
                    geometry
                        .axes
                        .push((x_desc.to_string(), residual_desc.to_string()));
                    let (xr, yr) = d.plotting_area().get_pixel_range();
                    geometry.plots.push(plot_rect(xr, yr));
                    for y in [-1.0, 1.0] {
                        d.draw_series(DashedLineSeries::new(
                            [(x0, y), (x1, y)],
                            6,
                            4,
                            RGBColor(120, 120, 120).stroke_width(1),
                        ))
                        .map_err(|e| e.to_string())?;
                    }
                    d.draw_series(std::iter::once(PathElement::new(
                        [(x0, 0.0), (x1, 0.0)],
                        BLACK.stroke_width(1),
                    )))
                    .map_err(|e| e.to_string())?;
                    for r in &residuals {
                        let pts: Vec<(f64, f64)> = r
                            .points
                            .iter()
                            .filter(|p| p.0.is_finite() && p.1.is_finite())
                            .copied()
                            .collect();
                        d.draw_series(pts.iter().map(|p| Circle::new(*p, 3, r.color.filled())))
                            .map_err(|e| e.to_string())?;
                        geometry.data.extend(pts.iter().map(|p| d.backend_coord(p)));
                    }
                }};
            }
            if log_x {
                lower!(
                    builder
                        .build_cartesian_2d((x0..x1).log_scale(), -top..top)
                        .map_err(|e| e.to_string())?
                );
            } else {
                lower!(
                    builder
                        .build_cartesian_2d(x0..x1, -top..top)
                        .map_err(|e| e.to_string())?
                );
            }
        }
        geometry.legend = frame.legend(&entries)?;
        frame.present()?;
    }
    geometry.ticks = ticks.into_inner();
    Ok(Chart { svg, geometry })
}

#[cfg(test)]
mod tick_tests {
    use super::*;

    /// A tick that should be zero prints 0 (it printed `-0.000000000000000111022302463`, the
    /// chart of docs' sweeps through zero), the rest as before; a profile through zero has no
    /// tick label the review objects to.
    #[test]
    fn a_tick_at_zero_reads_zero() {
        assert_eq!(tick(-1.1102230246251565e-16, 0.8), "0");
        assert_eq!(tick(0.12000000000000001, 1.0), "0.12");
        assert_eq!(tick(-0.2, 0.8), "-0.2");
        assert_eq!(tick(-6e-8, 1e-7), "-6e-8");
        assert_eq!(tick(2.5e7, 1e7), "2.5e7");
        assert_eq!(tick(-1.20903498483e-16, 3e-16), "-1.209e-16");
        assert_eq!(tick(0.30000000000000004, 2.0), "0.3");
        let s = Series {
            label: crate::run::columns::name::A2.into(),
            points: (0..9)
                .map(|k| (k as f64 * 0.1, -0.4 + k as f64 * 0.1, 0.01))
                .collect(),
            style: Style::Points,
            color: BLUE,
        };
        let chart = profile("t", "restitution alpha", "fourth cumulant a2", false, &[s]).unwrap();
        assert!(
            chart.geometry.ticks.iter().any(|t| t == "0"),
            "{:?}",
            chart.geometry.ticks
        );
        assert_eq!(chart.geometry.objections(), Vec::<String>::new());
    }
}
