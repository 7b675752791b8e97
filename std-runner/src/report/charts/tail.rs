//! The tail chart of GRW Figures 7-9: shell points, the fitted line and reference slopes.

use super::frame::{Chart, Entry, Frame, Geometry, LINE_WIDTH, Layer, Swatch, plot_rect};
use plotters::prelude::*;

/// The axes of GRW (31)-(33): shell radius and density on double-logarithmic scales.
const X_LABEL: &str = "shell distance x = ln(r_k - r_1)";
const Y_LABEL: &str = "density decay y = ln(ln f_1 - ln f_k)";

/// The tail plot of GRW Section 4.3 (GRW Figures 7-9): the points `(x_k, y_k)`, the fitted
/// line, and the lines of slope 1, 5/4 and 3/2 (GRW (16): Maxwell, VHS 1/2, hard spheres)
/// through the fit's centre for comparison.
pub fn tail(
    title: &str,
    fit: &crate::analysis::tails::TailFit,
    all: &[(usize, f64, f64)],
) -> Result<Chart, String> {
    let (x0, x1) = all.iter().fold((f64::INFINITY, f64::NEG_INFINITY), |a, p| {
        (a.0.min(p.1), a.1.max(p.1))
    });
    let (y0, y1) = all.iter().fold((f64::INFINITY, f64::NEG_INFINITY), |a, p| {
        (a.0.min(p.2), a.1.max(p.2))
    });
    if !(x0 < x1 && y0 < y1) {
        return Err("too few points".into());
    }
    let (lo, hi) = (y0 - 0.5, y1 + 0.5);
    let mut svg = String::new();
    let mut geometry = Geometry::new(title);
    let slopes = [
        (1.0, BLACK, 2, 3),
        (1.25, RGBColor(0, 120, 0), 6, 4),
        (1.5, MAGENTA, 14, 5),
    ];
    let mut entries = vec![
        Entry::new(Swatch::Point(BLUE), "shells (GRW (31)-(33))"),
        Entry::new(
            Swatch::Line(RED),
            format!(
                "fit over the outer half: slope {:.3} +- {:.3}",
                fit.slope, fit.slope_ci
            ),
        ),
    ];
    for (b, c, dash, gap) in slopes {
        entries.push(Entry::new(
            Swatch::Dashed(c, dash as u32, gap as u32),
            format!("slope {b} (GRW (16))"),
        ));
    }
    {
        let frame = Frame::new(&mut svg, title, &entries)?;
        let mut chart = ChartBuilder::on(&frame.plot)
            .margin(10)
            .x_label_area_size(40)
            .y_label_area_size(60)
            .build_cartesian_2d(x0..x1, lo..hi)
            .map_err(|e| e.to_string())?;
        chart
            .configure_mesh()
            .x_desc(X_LABEL)
            .y_desc(Y_LABEL)
            .draw()
            .map_err(|e| e.to_string())?;
        geometry.axes.push((X_LABEL.into(), Y_LABEL.into()));
        let (xr, yr) = chart.plotting_area().get_pixel_range();
        geometry.plots.push(plot_rect(xr, yr));
        chart
            .draw_series(
                all.iter()
                    .map(|p| Circle::new((p.1, p.2), 3, BLUE.filled())),
            )
            .map_err(|e| e.to_string())?;
        geometry
            .data
            .extend(all.iter().map(|p| chart.backend_coord(&(p.1, p.2))));
        let (mx, my) = fit
            .points
            .iter()
            .fold((0.0, 0.0), |a, p| (a.0 + p.1, a.1 + p.2));
        let (mx, my) = (mx / fit.points.len() as f64, my / fit.points.len() as f64);
        // Each line clipped to the plotting area.
        let line = |b: f64| -> Vec<(f64, f64)> {
            (0..=200)
                .map(|i| x0 + (x1 - x0) * i as f64 / 200.0)
                .map(|x| (x, my + b * (x - mx)))
                .filter(|p| p.1 >= lo && p.1 <= hi)
                .collect()
        };
        chart
            .draw_series(LineSeries::new(
                line(fit.slope),
                RED.stroke_width(LINE_WIDTH),
            ))
            .map_err(|e| e.to_string())?;
        geometry.layers.push(Layer::Line {
            color: RED,
            dash: None,
            label: entries[1].text.clone(),
        });
        for (b, c, dash, gap) in slopes {
            chart
                .draw_series(DashedLineSeries::new(
                    line(b),
                    dash,
                    gap,
                    c.stroke_width(LINE_WIDTH),
                ))
                .map_err(|e| e.to_string())?;
            geometry.layers.push(Layer::Line {
                color: c,
                dash: Some((dash as u32, gap as u32)),
                label: format!("slope {b}"),
            });
        }
        geometry.legend = frame.legend(&entries)?;
        frame.present()?;
    }
    Ok(Chart { svg, geometry })
}
