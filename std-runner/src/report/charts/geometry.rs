//! Where a chart put things, and the objections a referee would raise about it
//! ([`Geometry::objections`]): overlapping boxes, a band over the lines, a line grey scale
//! loses, two lines grey scale cannot tell apart, an axis without its words.

use plotters::prelude::*;

/// Width of every drawn line, pixels.
pub const LINE_WIDTH: u32 = 2;

/// The least height in pixels a confidence band must reach to be drawn: a line's width plus
/// two pixels on each side, so that it shows beyond the line it surrounds (a thinner band
/// would be a swatch in the legend for something the reader cannot see).
pub const MIN_BAND_PX: f64 = (LINE_WIDTH + 4) as f64;
/// Largest relative luminance of a line on the white canvas (pure green's is 0.72: it
/// vanishes in grey scale and in print).
pub const MAX_LINE_LUMINANCE: f64 = 0.6;
/// Longest tick label, characters: what the 80 px beside an axis hold, and what a tick between
/// its neighbours on the x axis can take without overprinting them.
pub const MAX_TICK_CHARS: usize = 10;
/// Smallest luminance difference that tells two lines of the same dash apart in grey scale.
pub const MIN_LUMINANCE_STEP: f64 = 0.3;

/// A rectangle in pixels, `(left, top)` to `(right, bottom)`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Rect {
    /// Left edge.
    pub left: i32,
    /// Top edge.
    pub top: i32,
    /// Right edge.
    pub right: i32,
    /// Bottom edge.
    pub bottom: i32,
}

impl Rect {
    /// Whether two rectangles share any pixel.
    pub fn overlaps(&self, o: &Rect) -> bool {
        self.left < o.right && o.left < self.right && self.top < o.bottom && o.top < self.bottom
    }

    /// Whether `(x, y)` lies inside (edges included).
    pub fn contains(&self, (x, y): (i32, i32)) -> bool {
        x >= self.left && x <= self.right && y >= self.top && y <= self.bottom
    }
}

/// One drawn layer of the first panel, in drawing order.
#[derive(Clone, Debug, PartialEq)]
pub enum Layer {
    /// The translucent confidence band.
    Band,
    /// A line: its colour, its dash and gap (`None`: solid) and its legend text.
    Line {
        /// Colour.
        color: RGBColor,
        /// Dash and gap, pixels; `None` for a solid line.
        dash: Option<(u32, u32)>,
        /// What it is.
        label: String,
    },
}

/// Relative luminance of a colour (ITU-R BT.709 weights on the 0-1 channels): what a line
/// keeps in grey scale.
pub fn luminance(c: RGBColor) -> f64 {
    (0.2126 * c.0 as f64 + 0.7152 * c.1 as f64 + 0.0722 * c.2 as f64) / 255.0
}

/// The width of an axis description per character, pixels: an upper estimate of the mean
/// advance of plotters' default description font (measured on the rendered charts: about 4.7).
pub const AXIS_CHAR_PX: f64 = 5.5;

/// The estimated length of an axis description in pixels ([`AXIS_CHAR_PX`]).
pub fn label_px(label: &str) -> f64 {
    label.chars().count() as f64 * AXIS_CHAR_PX
}

/// `full` when it fits in `px` pixels, else `short` (the symbol and unit without the words).
pub fn fit_label(full: String, short: &str, px: i32) -> String {
    if label_px(&full) <= px as f64 {
        full
    } else {
        short.to_string()
    }
}

/// Where a chart put things: for the checks that a reviewer's eye would make.
#[derive(Clone, Debug, PartialEq)]
pub struct Geometry {
    /// The title.
    pub title: String,
    /// The plotting areas (one per panel), pixels.
    pub plots: Vec<Rect>,
    /// Each panel's axis labels, `(x, y)` (an empty x label: the panel below carries it).
    pub axes: Vec<(String, String)>,
    /// The first panel's band and lines in drawing order.
    pub layers: Vec<Layer>,
    /// The legend's box, pixels.
    pub legend: Rect,
    /// The drawn data, in pixels (every point, band corner and error-bar end), to check it
    /// lies in the plotting areas.
    pub data: Vec<(i32, i32)>,
    /// The tallest extent of the confidence band in pixels, when a band is drawn.
    pub band_px: Option<f64>,
    /// Every tick label drawn on the axes.
    pub ticks: Vec<String>,
}

impl Geometry {
    /// Nothing placed yet, under `title`.
    pub fn new(title: &str) -> Self {
        Geometry {
            title: title.to_string(),
            plots: Vec::new(),
            axes: Vec::new(),
            layers: Vec::new(),
            legend: Rect {
                left: 0,
                top: 0,
                right: 0,
                bottom: 0,
            },
            data: Vec::new(),
            band_px: None,
            ticks: Vec::new(),
        }
    }

    /// What a referee would object to, one sentence each (empty: none): the legend over a
    /// plotting area, data outside the plotting areas, a band drawn where it is no taller
    /// than a line or drawn under a line (the lines then hide it), a line too light to see in
    /// grey scale (luminance above [`MAX_LINE_LUMINANCE`]), two lines of the same dash that
    /// grey scale cannot tell apart (luminances closer than [`MIN_LUMINANCE_STEP`]), an axis
    /// label longer than its panel (so it overprints its neighbour's), a solid line drawn over
    /// a dashed one (hiding it where they meet), an axis label that is only a symbol (no word
    /// of four letters or more), a tick label longer than [`MAX_TICK_CHARS`].
    pub fn objections(&self) -> Vec<String> {
        let mut out = Vec::new();
        if self.plots.is_empty() {
            out.push("no plotting area".to_string());
        }
        for p in &self.plots {
            if self.legend.overlaps(p) {
                out.push(format!(
                    "the legend {:?} covers the plot {p:?}",
                    self.legend
                ));
            }
        }
        if let Some(d) = self
            .data
            .iter()
            .find(|&&d| !self.plots.iter().any(|p| p.contains(d)))
        {
            out.push(format!("data at {d:?} outside the plotting areas"));
        }
        if let Some(t) = self
            .ticks
            .iter()
            .find(|t| t.chars().count() > MAX_TICK_CHARS)
        {
            out.push(format!(
                "the tick label \"{t}\" is longer than {MAX_TICK_CHARS} characters: it overprints \
                 its neighbours"
            ));
        }
        if let Some(px) = self.band_px
            && px < MIN_BAND_PX
        {
            out.push(format!(
                "a band of {px:.1} px drawn under a {LINE_WIDTH} px line (at least {MIN_BAND_PX} \
                 px shows beyond it)"
            ));
        }
        if let Some(band) = self.layers.iter().position(|l| *l == Layer::Band)
            && let Some(Layer::Line { label, .. }) = self.layers[band..]
                .iter()
                .find(|l| matches!(l, Layer::Line { .. }))
        {
            out.push(format!(
                "the band is drawn under the line \"{label}\", which hides it"
            ));
        }
        // A solid line drawn after a dashed one covers it where they meet (a reference equal
        // to the mean vanishes under it): the dashed lines go over the solid ones.
        let lines_in_order: Vec<(&Option<(u32, u32)>, &str)> = self
            .layers
            .iter()
            .filter_map(|l| match l {
                Layer::Line { dash, label, .. } => Some((dash, label.as_str())),
                Layer::Band => None,
            })
            .collect();
        for (i, (dash, label)) in lines_in_order.iter().enumerate() {
            if dash.is_none()
                && let Some((_, under)) = lines_in_order[..i].iter().find(|(d, _)| d.is_some())
            {
                out.push(format!(
                    "the solid line \"{label}\" is drawn over the dashed \"{under}\", hiding it \
                     where they meet"
                ));
            }
        }
        type Drawn<'a> = (RGBColor, Option<(u32, u32)>, &'a str);
        let lines: Vec<Drawn<'_>> = self
            .layers
            .iter()
            .filter_map(|l| match l {
                Layer::Line { color, dash, label } => Some((*color, *dash, label.as_str())),
                Layer::Band => None,
            })
            .collect();
        for (i, a) in lines.iter().enumerate() {
            if luminance(a.0) > MAX_LINE_LUMINANCE {
                out.push(format!(
                    "the line \"{}\" is too light for grey scale (luminance {:.2})",
                    a.2,
                    luminance(a.0)
                ));
            }
            for b in &lines[i + 1..] {
                if a.1 == b.1 && (luminance(a.0) - luminance(b.0)).abs() < MIN_LUMINANCE_STEP {
                    out.push(format!(
                        "the lines \"{}\" and \"{}\" look the same in grey scale",
                        a.2, b.2
                    ));
                }
            }
        }
        // A vertical y description is centred on its panel: longer than the panel, it runs
        // into the next panel's (or off the chart); an x description likewise across.
        for ((x, y), p) in self.axes.iter().zip(&self.plots) {
            for (label, room, side) in [
                (y, p.bottom - p.top, "height"),
                (x, p.right - p.left, "width"),
            ] {
                if label_px(label) > room as f64 {
                    out.push(format!(
                        "the axis label \"{label}\" ({:.0} px) is longer than its panel's {side} \
                         ({room} px): it runs into its neighbour",
                        label_px(label)
                    ));
                }
            }
        }
        for (x, y) in &self.axes {
            for label in [x, y] {
                let named = label
                    .split(|c: char| !c.is_ascii_alphabetic())
                    .any(|w| w.len() >= 4);
                if !label.is_empty() && !named {
                    out.push(format!("the axis label \"{label}\" is only a symbol"));
                }
            }
        }
        out
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A chart as the T chart was drawn before the objections existed: band first and the
    /// lines over it, a bright green reference, bare symbols on the axes.
    fn yesterdays_t_chart() -> Geometry {
        let plot = Rect {
            left: 100,
            top: 50,
            right: 700,
            bottom: 400,
        };
        let line = |color, dash, label: &str| Layer::Line {
            color,
            dash,
            label: label.into(),
        };
        Geometry {
            title: "grw-example3, n = 1024, 1000 ensembles: T".into(),
            plots: vec![plot],
            axes: vec![("t".into(), crate::run::columns::name::T.into())],
            layers: vec![
                Layer::Band,
                line(BLUE, None, "mean"),
                line(RED, Some((12, 5)), "T_exact"),
                line(GREEN, Some((4, 4)), "T_mean_n"),
            ],
            legend: Rect {
                left: 710,
                top: 50,
                right: 970,
                bottom: 300,
            },
            data: vec![(150, 200)],
            band_px: Some(4.0),
            ticks: vec!["0.5".into(), "1".into()],
        }
    }

    /// The objections catch each fault of the old T chart, one at a time, and none is left
    /// once all are mended: the check can fail, and passes only a readable chart.
    #[test]
    fn objections_name_each_fault_and_pass_a_mended_chart() {
        let old = yesterdays_t_chart();
        let found = old.objections().join("\n");
        assert!(found.contains("drawn under the line \"mean\""), "{found}");
        assert!(found.contains("\"T_mean_n\" is too light"), "{found}");
        assert!(found.contains("\"t\" is only a symbol"), "{found}");
        assert!(found.contains("\"T\" is only a symbol"), "{found}");
        let mut g = old.clone();
        g.band_px = Some(MIN_BAND_PX + 2.0);
        g.layers.rotate_left(1);
        g.layers[2] = Layer::Line {
            color: BLACK,
            dash: Some((3, 3)),
            label: "T_mean_n".into(),
        };
        g.axes = vec![(
            "time t (scene units)".into(),
            "temperature T (scene units)".into(),
        )];
        assert_eq!(g.objections(), Vec::<String>::new());
        // Each further fault alone is caught.
        let mut covered = g.clone();
        covered.legend.left = 600;
        assert!(covered.objections()[0].contains("covers the plot"));
        let mut outside = g.clone();
        outside.data.push((50, 50));
        assert!(outside.objections()[0].contains("outside the plotting areas"));
        let mut thin = g.clone();
        thin.band_px = Some(LINE_WIDTH as f64);
        assert!(thin.objections()[0].contains("drawn under a 2 px line"));
        let mut hidden = g.clone();
        hidden.layers.swap(0, 1);
        assert!(hidden.objections()[0].contains("drawn over the dashed \"T_exact\""));
        let mut zero = g.clone();
        zero.ticks.push("-0.000000000000000111022302463".into());
        assert!(zero.objections()[0].contains("overprints its neighbours"));
        let mut long = g.clone();
        long.axes[0].1 = "a temperature label much longer than the panel is tall ".repeat(2);
        assert!(long.objections()[0].contains("longer than its panel's height"));
        let mut twins = g.clone();
        twins.layers[1] = Layer::Line {
            color: RGBColor(60, 60, 60),
            dash: Some((3, 3)),
            label: "T_exact".into(),
        };
        assert!(twins.objections()[0].contains("look the same in grey scale"));
    }

    #[test]
    fn rectangles_overlap_only_when_they_share_pixels() {
        let a = Rect {
            left: 0,
            top: 0,
            right: 10,
            bottom: 10,
        };
        let b = Rect {
            left: 10,
            top: 0,
            right: 20,
            bottom: 10,
        };
        assert!(!a.overlaps(&b));
        let c = Rect { left: 9, ..b };
        assert!(a.overlaps(&c));
    }
}
