//! The tail chart of GRW Figures 7-9: shell points, the fitted line and reference slopes.

use plotters::prelude::*;

/// The tail plot of GRW Section 4.3 (GRW Figures 7-9): the points `(x_k, y_k)`, the fitted line,
/// and the lines of slope 1, 5/4 and 3/2 through the fit's centre for comparison.
pub fn tail_svg(
    title: &str,
    fit: &crate::analysis::tails::TailFit,
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
