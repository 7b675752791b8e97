//! Each observable against time: the reference curves dashed (each its own dash and a
//! colour dark enough for grey scale), the ensemble mean, and its 99.9% confidence band drawn
//! last, translucent, where it is wider than the line (so no line hides it); when a reference
//! applies, a residual panel below: `(mean - reference) / half-width`, where the 99.9%
//! interval is the strip between -1 and 1 whatever the band's size on the upper panel.

use super::frame::{
    BAND_ALPHA, Chart, Entry, Frame, Geometry, LINE_WIDTH, Layer, Swatch, plot_rect,
};
use crate::reference::curves::ReferenceCurve;
use crate::run::RunStats;
use crate::run::columns::{TIME_LABEL, axis_label};
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
/// there is one (it is what the mean estimates), else the first.
fn residual_reference<'a>(refs: &[&'a ReferenceCurve]) -> Option<&'a ReferenceCurve> {
    refs.iter()
        .find(|r| r.name.ends_with("_mean_n"))
        .or(refs.first())
        .copied()
}

/// One observable's chart (column `col`) with the reference curves `refs`.
pub fn chart(
    stats: &RunStats,
    col: usize,
    title: &str,
    refs: &[&ReferenceCurve],
) -> Result<Chart, String> {
    let name = stats.names[col];
    let t = &stats.times;
    let pts: Vec<(f64, f64, f64)> = (0..t.len())
        .map(|i| (t[i], stats.mean(i, col), stats.ci(i, col)))
        .filter(|p| p.1.is_finite())
        .collect();
    if pts.is_empty() {
        return Err("no finite values to draw".into());
    }
    let ci = |p: &(f64, f64, f64)| if p.2.is_finite() { p.2 } else { 0.0 };
    let mut lo = pts
        .iter()
        .map(|p| p.1 - ci(p))
        .fold(f64::INFINITY, f64::min);
    let mut hi = pts
        .iter()
        .map(|p| p.1 + ci(p))
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
    let pad = if hi > lo {
        0.05 * (hi - lo)
    } else {
        0.5 * lo.abs().max(1e-300)
    };
    let (t0, t1) = (t[0], t[t.len() - 1].max(t[0] + 1e-300));
    let residual = residual_reference(refs).and_then(|r| {
        let rs: Vec<(f64, f64)> = pts
            .iter()
            .filter(|p| p.2.is_finite() && p.2 > 0.0)
            .map(|p| (p.0, (p.1 - (r.curve)(p.0)) / p.2))
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
    let y_label = axis_label(name);
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
        let mut mesh = c.configure_mesh();
        mesh.y_desc(y_label.as_str());
        let x_label = if lower.is_none() { TIME_LABEL } else { "" };
        mesh.x_desc(x_label);
        mesh.draw().map_err(|e| e.to_string())?;
        geometry.axes.push((x_label.to_string(), y_label.clone()));
        let (xr, yr) = c.plotting_area().get_pixel_range();
        geometry.plots.push(plot_rect(xr, yr.clone()));
        // The references first, then the mean, then the band over both: translucent, it
        // shows the lines through it and no line hides it.
        let mut ref_entries = Vec::new();
        for (k, r) in refs.iter().enumerate() {
            let (color, dash, gap) = REF_STYLES[k % REF_STYLES.len()];
            let n = 400;
            let line: Vec<(f64, f64)> = (0..=n)
                .map(|i| t0 + (t1 - t0) * i as f64 / n as f64)
                .map(|x| (x, (r.curve)(x)))
                .filter(|p| p.1.is_finite())
                .collect();
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
        c.draw_series(LineSeries::new(
            pts.iter().map(|p| (p.0, p.1)),
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
            .extend(pts.iter().map(|p| c.backend_coord(&(p.0, p.1))));
        // The band is drawn where it can be seen: its tallest extent in pixels above the
        // line's width.
        let px_per_unit = (yr.end - yr.start) as f64 / (hi + pad - (lo - pad));
        let band_px = pts
            .iter()
            .map(|p| 2.0 * ci(p) * px_per_unit)
            .fold(0.0, f64::max);
        if band_px > (LINE_WIDTH + 1) as f64 {
            let band: Vec<(f64, f64)> = pts
                .iter()
                .map(|p| (p.0, p.1 + ci(p)))
                .chain(pts.iter().rev().map(|p| (p.0, p.1 - ci(p))))
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
        if let (Some(lower), Some((r, rs))) = (lower, &residual) {
            let top = rs.iter().map(|p| p.1.abs()).fold(1.5, f64::max) * 1.1;
            let mut d = ChartBuilder::on(&lower)
                .margin(10)
                .x_label_area_size(40)
                .y_label_area_size(80)
                .build_cartesian_2d(t0..t1, -top..top)
                .map_err(|e| e.to_string())?;
            let y_label = format!("({name} - {}) / half-width", r.name);
            d.configure_mesh()
                .x_desc(TIME_LABEL)
                .y_desc(y_label.as_str())
                .y_labels(5)
                .draw()
                .map_err(|e| e.to_string())?;
            geometry.axes.push((TIME_LABEL.to_string(), y_label));
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

/// Every observable's chart, `(file stem, chart)`, in the order of the columns; `title`
/// (the physics, size, ensembles) heads each, the observable names its y axis.
pub fn charts(
    title: &str,
    stats: &RunStats,
    refs: &[ReferenceCurve],
) -> Vec<(String, Result<Chart, String>)> {
    let mut out = Vec::new();
    for (col, &name) in stats.names.iter().enumerate() {
        let these: Vec<&ReferenceCurve> = refs.iter().filter(|r| r.of == name).collect();
        out.push((name.to_string(), chart(stats, col, title, &these)));
    }
    out
}
