//! Each observable against time, its 99.9% confidence band shaded, the reference curves
//! dashed.

use super::tail::tail_svg;
use crate::error::Error;
use crate::reference::curves::ReferenceCurve;
use crate::report::files::write_atomic;
use crate::run::RunStats;
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
        && let Some(fit) = crate::analysis::tails::fit(*radius, h)
    {
        let all = crate::analysis::tails::tail_points(*radius, h);
        match tail_svg(&format!("{scene}: tail (GRW Section 4.3)"), &fit, &all) {
            Ok(svg) => write_atomic(&dir.join("tail.svg"), svg.as_bytes())?,
            Err(e) => eprintln!("tail chart: not drawn ({e})"),
        }
    }
    Ok(())
}
