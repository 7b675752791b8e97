//! Each observable against time: the ensemble mean, the reference curves dashed over it (each
//! its own dash and a colour dark enough for grey scale), and its 99.9% confidence band drawn
//! last, translucent, where it is wider than the line (so no line hides it); when a reference
//! applies, a residual panel below: `(mean - reference) / half-width`, where the 99.9%
//! interval is the strip between -1 and 1 whatever the band's size on the upper panel.

use super::frame::{
    BAND_ALPHA, Chart, Entry, Frame, Geometry, LINE_WIDTH, Layer, Swatch, plot_rect,
};
use super::geometry::{MIN_BAND_PX, fit_label};
use crate::run::RunStats;
use crate::run::columns::name::S;
use crate::run::columns::{COLLISIONS_LABEL, TIME_LABEL, axis_label_in};
use crate::scene::TimeAxis;
use gdsmc_theory::curves::{Kind, ReferenceCurve};
use plotters::prelude::*;

/// Colours and dashes of the reference curves, in order: each dash its own, each colour's
/// luminance at most 0.36 (readable in grey scale and in print).
const REF_STYLES: [(RGBColor, u32, u32); 4] = [
    (RGBColor(190, 30, 30), 12, 5),
    (BLACK, 3, 3),
    (RGBColor(120, 40, 160), 18, 6),
    (RGBColor(90, 90, 90), 6, 3),
];

/// The legend's words for the band, drawn or too thin to draw.
const BAND_TEXT: &str = "99.9% confidence band of the mean";
const THIN_BAND_TEXT: &str = "99.9% band: thinner than the line (see the residuals)";

/// The reference the residual panel measures against: the exact ensemble mean at this n when
/// there is one (it is what the mean estimates), else a Boltzmann limit, else the first
/// approximation (the registry lists the better of a reference's curves first).
fn residual_reference<'a>(refs: &[&'a ReferenceCurve]) -> Option<&'a ReferenceCurve> {
    [Kind::MeanAtN, Kind::Limit, Kind::Approximation]
        .iter()
        .find_map(|k| refs.iter().find(|r| r.kind == *k))
        .copied()
}

/// Whether the observation times call for a log time axis: their steps grow tenfold or more
/// from the first to the last (`observe.spacing = "log"`), so a linear axis would squeeze the
/// early decades into a sliver.
pub fn log_time(t: &[f64]) -> bool {
    let positive: Vec<f64> = t.iter().copied().filter(|&x| x > 0.0).collect();
    match positive.as_slice() {
        [a, b, .., y, z] => (z - y) > 10.0 * (b - a) && z / a >= 100.0,
        _ => false,
    }
}

/// Whether values in `[lo, hi]` call for a log axis: all positive over three decades or more.
pub fn log_values(lo: f64, hi: f64) -> bool {
    lo > 0.0 && hi.is_finite() && hi / lo >= 1e3
}

/// An axis, linear or decimal-logarithmic: where a value is drawn and how a tick is labelled.
#[derive(Clone, Copy)]
struct Scale {
    log: bool,
}

impl Scale {
    /// The drawn coordinate of `v` (NaN for a value a log axis cannot show).
    fn at(self, v: f64) -> f64 {
        if !self.log {
            v
        } else if v > 0.0 {
            libm::log10(v)
        } else {
            f64::NAN
        }
    }

    /// The value a drawn coordinate stands for, as a tick label.
    fn label(self, c: f64) -> String {
        if !self.log {
            // `+ 0.0`: a tick at -1e-16 rounds to -0, printed "-0".
            return format!("{}", (c * 1e6).round() / 1e6 + 0.0);
        }
        // Decades only: a tick between them stays a grid line without words.
        if (c - c.round()).abs() < 1e-9 {
            format!("1e{}", c.round())
        } else {
            String::new()
        }
    }

    /// An axis description with the scale named when it is logarithmic.
    fn describe(self, label: &str) -> String {
        if self.log && !label.is_empty() {
            format!("{label} (log scale)")
        } else {
            label.to_string()
        }
    }
}

/// One observable's chart (column `col`) with the reference curves `refs`, against time or
/// collisions per particle (`axis`), a mixture's species called by their names (`species`).
pub fn chart(
    stats: &RunStats,
    (axis, species): (TimeAxis, &[String]),
    col: usize,
    title: &str,
    refs: &[&ReferenceCurve],
) -> Result<Chart, String> {
    let name = stats.names[col];
    // The abscissa of each observation: its time, or the mean collisions per particle there.
    let by_collisions = axis == TimeAxis::Collisions;
    let s_col = stats.names.iter().position(|&n| n == S);
    let abscissa: Vec<f64> = match (by_collisions, s_col) {
        (true, Some(sc)) => (0..stats.times.len()).map(|i| stats.mean(i, sc)).collect(),
        _ => stats.times.clone(),
    };
    let by_collisions = by_collisions && s_col.is_some();
    let x_words = if by_collisions {
        COLLISIONS_LABEL
    } else {
        TIME_LABEL
    };
    let xs = Scale {
        log: log_time(&abscissa),
    };
    // `(x, mean, half-width, t)` of each observation with a finite mean (a log axis shows the
    // positive abscissae).
    let pts: Vec<(f64, f64, f64, f64)> = (0..abscissa.len())
        .map(|i| {
            let (x, t) = (abscissa[i], stats.times[i]);
            (x, stats.mean(i, col), stats.ci(i, col), t)
        })
        .filter(|p| p.1.is_finite() && (!xs.log || p.0 > 0.0))
        .collect();
    let t: Vec<f64> = pts.iter().map(|p| p.3).collect();
    if pts.is_empty() {
        return Err("no finite values to draw".into());
    }
    let ci = |p: &(f64, f64, f64, f64)| if p.2.is_finite() { p.2 } else { 0.0 };
    let mut lo = pts
        .iter()
        .map(|p| p.1 - ci(p))
        .fold(f64::INFINITY, f64::min);
    let mut hi = pts
        .iter()
        .map(|p| p.1 + ci(p))
        .fold(f64::NEG_INFINITY, f64::max);
    for r in refs {
        for &x in &t {
            let y = (r.curve)(x);
            if y.is_finite() {
                lo = lo.min(y);
                hi = hi.max(y);
            }
        }
    }
    // A log value axis where the means and the references span three decades or more (the
    // band's lower edge may reach 0: it is cut a decade below the lowest line).
    let lines = pts.iter().map(|p| p.1).chain(refs.iter().flat_map(|r| {
        t.iter()
            .map(|&x| (r.curve)(x))
            .filter(|y| y.is_finite())
            .collect::<Vec<_>>()
    }));
    let (line_lo, line_hi) = lines.fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), y| {
        (a.min(y), b.max(y))
    });
    let ys = Scale {
        log: log_values(line_lo, line_hi),
    };
    let (lo, hi) = if ys.log {
        (ys.at(lo.max(line_lo / 10.0)), ys.at(hi))
    } else {
        (lo, hi)
    };
    let pad = if hi > lo {
        0.05 * (hi - lo)
    } else {
        0.5 * lo.abs().max(1e-300)
    };
    let (x_first, x_last) = (pts[0].0, pts[pts.len() - 1].0);
    let (t0, t1) = (xs.at(x_first), xs.at(x_last).max(xs.at(x_first) + 1e-300));
    // The drawn point of a time and a value, and a value clamped into the axis.
    let y_floor = lo - pad;
    let at = |x: f64, y: f64| (xs.at(x), ys.at(y).max(y_floor));
    let residual = residual_reference(refs).and_then(|r| {
        let rs: Vec<(f64, f64)> = pts
            .iter()
            .filter(|p| p.2.is_finite() && p.2 > 0.0)
            .map(|p| (xs.at(p.0), (p.1 - (r.curve)(p.3)) / p.2))
            .filter(|p| p.1.is_finite())
            .collect();
        (!rs.is_empty()).then_some((r, rs))
    });

    let mean_text = format!("mean of {} ensembles", stats.ensembles);
    let residual_text = residual.as_ref().map(|(r, _)| {
        format!(
            "residual (lower panel): (mean - {}) / 99.9% half-width; within +-1: inside the interval",
            r.name
        )
    });
    let ref_texts: Vec<String> = refs
        .iter()
        .map(|r| format!("{} ({})", r.name, r.source))
        .collect();
    // The legend band is sized for the longer of the band's two texts.
    let mut sizing = vec![
        Entry::new(Swatch::None, mean_text.clone()),
        Entry::new(Swatch::None, THIN_BAND_TEXT),
    ];
    sizing.extend(
        ref_texts
            .iter()
            .map(|t| Entry::new(Swatch::None, t.clone())),
    );
    sizing.extend(
        residual_text
            .iter()
            .map(|t| Entry::new(Swatch::None, t.clone())),
    );

    let mut svg = String::new();
    let mut geometry = Geometry::new(title);
    let mut entries = vec![Entry::new(Swatch::Line(BLUE), mean_text.clone())];
    let y_label = axis_label_in(name, species);
    {
        let frame = Frame::new(&mut svg, title, &sizing)?;
        let (upper, lower) = if residual.is_some() {
            let h = frame.plot.dim_in_pixel().1;
            let (a, b) = frame.plot.split_vertically((h as f64 * 0.68) as u32);
            (a, Some(b))
        } else {
            (frame.plot.clone(), None)
        };
        let mut c = ChartBuilder::on(&upper)
            .margin(10)
            .x_label_area_size(if lower.is_some() { 20 } else { 40 })
            .y_label_area_size(80)
            .build_cartesian_2d(t0..t1, (lo - pad)..(hi + pad))
            .map_err(|e| e.to_string())?;
        let (xr, yr) = c.plotting_area().get_pixel_range();
        // The full words when they fit the panel's height, else the symbol and unit.
        let short = y_label
            .rfind('(')
            .map_or(name.to_string(), |i| format!("{name} {}", &y_label[i..]));
        let y_label = fit_label(
            ys.describe(&y_label),
            &ys.describe(&short),
            yr.end - yr.start,
        );
        let mut mesh = c.configure_mesh();
        mesh.y_desc(y_label.as_str());
        let x_label = xs.describe(if lower.is_none() { x_words } else { "" });
        let (xf, yf) = (move |v: &f64| xs.label(*v), move |v: &f64| ys.label(*v));
        mesh.x_desc(x_label.as_str())
            .x_label_formatter(&xf)
            .y_label_formatter(&yf);
        mesh.draw().map_err(|e| e.to_string())?;
        geometry.axes.push((x_label.to_string(), y_label.clone()));
        geometry.plots.push(plot_rect(xr, yr.clone()));
        // The mean first, then the references dashed over it (one that coincides with the
        // mean shows through its gaps), then the band over all: translucent, it shows the
        // lines through it and no line hides it.
        c.draw_series(LineSeries::new(
            pts.iter().map(|p| at(p.0, p.1)),
            BLUE.stroke_width(LINE_WIDTH),
        ))
        .map_err(|e| e.to_string())?;
        geometry.layers.push(Layer::Line {
            color: BLUE,
            dash: None,
            label: mean_text,
        });
        geometry
            .data
            .extend(pts.iter().map(|p| c.backend_coord(&at(p.0, p.1))));
        let mut ref_entries = Vec::new();
        for (k, r) in refs.iter().enumerate() {
            let (color, dash, gap) = REF_STYLES[k % REF_STYLES.len()];
            // Evenly spaced on a time axis (the curve is a function of time); through the
            // observations on a collisions axis (their mean s is where each time lies).
            let line: Vec<(f64, f64)> = if by_collisions {
                pts.iter()
                    .map(|p| (xs.at(p.0), ys.at((r.curve)(p.3))))
                    .filter(|p| p.1.is_finite())
                    .collect()
            } else {
                let n = 400;
                let time = |c: f64| if xs.log { libm::pow(10f64, c) } else { c };
                (0..=n)
                    .map(|i| t0 + (t1 - t0) * i as f64 / n as f64)
                    .map(|c| (c, ys.at((r.curve)(time(c)))))
                    .filter(|p| p.1.is_finite())
                    .collect()
            };
            c.draw_series(DashedLineSeries::new(
                line,
                dash as i32,
                gap as i32,
                color.stroke_width(LINE_WIDTH),
            ))
            .map_err(|e| e.to_string())?;
            geometry.layers.push(Layer::Line {
                color,
                dash: Some((dash, gap)),
                label: ref_texts[k].clone(),
            });
            ref_entries.push(Entry::new(
                Swatch::Dashed(color, dash, gap),
                ref_texts[k].clone(),
            ));
        }
        // The band is drawn where it can be seen: its tallest extent in pixels above the
        // line's width.
        let px_per_unit = (yr.end - yr.start) as f64 / (hi + pad - (lo - pad));
        let band_px = pts
            .iter()
            .map(|p| (at(p.0, p.1 + ci(p)).1 - at(p.0, p.1 - ci(p)).1) * px_per_unit)
            .fold(0.0, f64::max);
        if band_px >= MIN_BAND_PX {
            let band: Vec<(f64, f64)> = pts
                .iter()
                .map(|p| at(p.0, p.1 + ci(p)))
                .chain(pts.iter().rev().map(|p| at(p.0, p.1 - ci(p))))
                .collect();
            geometry
                .data
                .extend(band.iter().map(|p| c.backend_coord(p)));
            c.draw_series(std::iter::once(Polygon::new(
                band,
                BLUE.mix(BAND_ALPHA).filled(),
            )))
            .map_err(|e| e.to_string())?;
            geometry.band_px = Some(band_px);
            geometry.layers.push(Layer::Band);
            entries.push(Entry::new(Swatch::Band(BLUE), BAND_TEXT));
        } else {
            entries.push(Entry::new(Swatch::None, THIN_BAND_TEXT));
        }
        entries.extend(ref_entries);
        if let (Some(lower), Some((_, rs))) = (lower, &residual) {
            let top = rs.iter().map(|p| p.1.abs()).fold(1.5, f64::max) * 1.1;
            let mut d = ChartBuilder::on(&lower)
                .margin(10)
                .x_label_area_size(40)
                .y_label_area_size(80)
                .build_cartesian_2d(t0..t1, -top..top)
                .map_err(|e| e.to_string())?;
            // The legend says what the residual is; the panel is too short for the words.
            let y_label = "residual".to_string();
            let x_label = xs.describe(x_words);
            let xf = move |v: &f64| xs.label(*v);
            d.configure_mesh()
                .x_desc(x_label.as_str())
                .x_label_formatter(&xf)
                .y_desc(y_label.as_str())
                .y_labels(5)
                .draw()
                .map_err(|e| e.to_string())?;
            geometry.axes.push((x_label, y_label));
            let (xr, yr) = d.plotting_area().get_pixel_range();
            geometry.plots.push(plot_rect(xr, yr));
            for y in [-1.0, 1.0] {
                d.draw_series(DashedLineSeries::new(
                    [(t0, y), (t1, y)],
                    6,
                    4,
                    RGBColor(120, 120, 120).stroke_width(1),
                ))
                .map_err(|e| e.to_string())?;
            }
            d.draw_series(std::iter::once(PathElement::new(
                [(t0, 0.0), (t1, 0.0)],
                BLACK.stroke_width(1),
            )))
            .map_err(|e| e.to_string())?;
            d.draw_series(rs.iter().map(|p| Circle::new(*p, 3, BLUE.filled())))
                .map_err(|e| e.to_string())?;
            geometry.data.extend(rs.iter().map(|p| d.backend_coord(p)));
            if let Some(t) = residual_text {
                entries.push(Entry::new(Swatch::Marker(BLUE), t));
            }
        }
        geometry.legend = frame.legend(&entries)?;
        frame.present()?;
    }
    Ok(Chart { svg, geometry })
}

/// Every observable's chart (but `V_z` for disks), `(file stem, chart)`, in the order of the columns; `title`
/// (the physics, size, ensembles) heads each, the observable names its y axis.
pub fn charts(
    title: &str,
    stats: &RunStats,
    labels: (TimeAxis, &[String]),
    refs: &[ReferenceCurve],
) -> Vec<(String, Result<Chart, String>)> {
    let mut out = Vec::new();
    for (col, &name) in stats.names.iter().enumerate() {
        // Disks move in the plane: V_z is 0 by construction, a chart of nothing.
        if stats.dimension == 2 && name == crate::run::columns::name::V_Z {
            continue;
        }
        let these: Vec<&ReferenceCurve> = refs.iter().filter(|r| r.of == name).collect();
        out.push((name.to_string(), chart(stats, labels, col, title, &these)));
    }
    out
}
