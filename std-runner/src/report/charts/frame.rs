//! What every chart shares: the canvas with its title, the plotting area over the full width
//! and the legend in a band of its own below it (so it never covers data), legend swatches
//! drawn in the same style as their series, and the geometry a test can check with the
//! objections a referee would raise ([`Geometry::objections`]).

use plotters::coord::Shift;
use plotters::prelude::*;

/// Canvas width in pixels.
pub const WIDTH: u32 = 980;
/// Height of the plotting area (all panels, with their axis labels), pixels.
pub const PLOT_HEIGHT: u32 = 500;
/// Height of one title line; the title band holds as many as the title has.
const TITLE_LINE: u32 = 24;
/// Width of every drawn line, pixels.
pub const LINE_WIDTH: u32 = 2;
/// Legend entries per row.
const LEGEND_COLUMNS: usize = 2;
/// Characters per legend line before it wraps (a column is about half the canvas).
const LEGEND_CHARS: usize = 56;
/// Legend text line height and the gap after each row, pixels.
const LEGEND_LINE: i32 = 17;
const LEGEND_GAP: i32 = 5;
/// Margin above and below the legend's entries, pixels.
const LEGEND_PAD: i32 = 8;
/// Largest relative luminance of a line on the white canvas (pure green's is 0.72: it
/// vanishes in grey scale and in print).
pub const MAX_LINE_LUMINANCE: f64 = 0.6;
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
        }
    }

    /// What a referee would object to, one sentence each (empty: none): the legend over a
    /// plotting area, data outside the plotting areas, a band drawn where it is no taller
    /// than a line or drawn under a line (the lines then hide it), a line too light to see in
    /// grey scale (luminance above [`MAX_LINE_LUMINANCE`]), two lines of the same dash that
    /// grey scale cannot tell apart (luminances closer than [`MIN_LUMINANCE_STEP`]), an axis
    /// label that is only a symbol (no word of four letters or more).
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
        if let Some(px) = self.band_px
            && px <= LINE_WIDTH as f64
        {
            out.push(format!(
                "a band of {px:.1} px drawn under a {LINE_WIDTH} px line"
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

/// A chart: its SVG text and where it put things.
#[derive(Clone, Debug, PartialEq)]
pub struct Chart {
    /// The SVG document.
    pub svg: String,
    /// Its geometry.
    pub geometry: Geometry,
}

/// How a legend entry's swatch is drawn: as its series is.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Swatch {
    /// A solid line.
    Line(RGBColor),
    /// A dashed line with this dash and gap, pixels.
    Dashed(RGBColor, u32, u32),
    /// A filled band, translucent.
    Band(RGBColor),
    /// A point with an error bar.
    Point(RGBColor),
    /// A point alone.
    Marker(RGBColor),
    /// Text only (a note).
    None,
}

/// One legend entry.
#[derive(Clone, Debug, PartialEq)]
pub struct Entry {
    /// Its swatch.
    pub swatch: Swatch,
    /// Its text (wrapped to the column).
    pub text: String,
}

impl Entry {
    /// An entry.
    pub fn new(swatch: Swatch, text: impl Into<String>) -> Self {
        Entry {
            swatch,
            text: text.into(),
        }
    }
}

/// Where each legend entry goes: `(column, top offset, wrapped lines)`, and the height of
/// all of them (entries fill rows of [`LEGEND_COLUMNS`], each row as tall as its tallest).
fn legend_layout(entries: &[Entry]) -> (Vec<(usize, i32, Vec<String>)>, i32) {
    let mut out = Vec::new();
    let mut y = LEGEND_PAD;
    for row in entries.chunks(LEGEND_COLUMNS) {
        let mut tallest = 1;
        for (col, e) in row.iter().enumerate() {
            let lines = wrap(&e.text, LEGEND_CHARS);
            tallest = tallest.max(lines.len());
            out.push((col, y, lines));
        }
        y += tallest as i32 * LEGEND_LINE + LEGEND_GAP;
    }
    (out, y + LEGEND_PAD - LEGEND_GAP)
}

/// The canvas split into title, plotting area and the legend band below it.
pub struct Frame<'a> {
    /// The plotting area (full width, below the title).
    pub plot: DrawingArea<SVGBackend<'a>, Shift>,
    root: DrawingArea<SVGBackend<'a>, Shift>,
    /// Top of the legend band on the canvas.
    legend_top: i32,
    /// Height reserved for the legend.
    legend_height: i32,
}

impl<'a> Frame<'a> {
    /// A white canvas with `title` on top (a line each, the first larger), into `svg`, its
    /// legend band sized for `entries` (the texts the chart will list: [`Frame::legend`]
    /// draws the final ones, whose swatches may differ).
    pub fn new(svg: &'a mut String, title: &str, entries: &[Entry]) -> Result<Self, String> {
        let (_, legend_height) = legend_layout(entries);
        let lines: Vec<&str> = title.lines().collect();
        let title_height = 12 + TITLE_LINE * lines.len().max(1) as u32;
        let height = title_height + PLOT_HEIGHT + legend_height as u32;
        let root = SVGBackend::with_string(svg, (WIDTH, height)).into_drawing_area();
        root.fill(&WHITE).map_err(|e| e.to_string())?;
        let (head, body) = root.split_vertically(title_height);
        for (k, line) in lines.iter().enumerate() {
            let size = if k == 0 { 18 } else { 15 };
            head.draw(&Text::new(
                line.to_string(),
                (12, 9 + (k as u32 * TITLE_LINE) as i32),
                ("sans-serif", size).into_font(),
            ))
            .map_err(|e| e.to_string())?;
        }
        let (plot, _) = body.split_vertically(PLOT_HEIGHT);
        Ok(Frame {
            plot,
            root,
            legend_top: (title_height + PLOT_HEIGHT) as i32,
            legend_height,
        })
    }

    /// Draws the legend in its band and returns its box in canvas pixels.
    pub fn legend(&self, entries: &[Entry]) -> Result<Rect, String> {
        let (layout, height) = legend_layout(entries);
        let column = (WIDTH as i32 - 24) / LEGEND_COLUMNS as i32;
        let a = &self.root;
        for (e, (col, y, lines)) in entries.iter().zip(&layout) {
            let x0 = 18 + *col as i32 * column;
            let y = self.legend_top + y;
            let mid = y + 8;
            match e.swatch {
                Swatch::Line(c) => {
                    a.draw(&PathElement::new(
                        [(x0, mid), (x0 + 28, mid)],
                        c.stroke_width(LINE_WIDTH),
                    ))
                    .map_err(|e| e.to_string())?;
                }
                Swatch::Dashed(c, dash, gap) => {
                    let mut x = x0;
                    while x < x0 + 28 {
                        let end = (x + dash as i32).min(x0 + 28);
                        a.draw(&PathElement::new(
                            [(x, mid), (end, mid)],
                            c.stroke_width(LINE_WIDTH),
                        ))
                        .map_err(|e| e.to_string())?;
                        x += (dash + gap) as i32;
                    }
                }
                Swatch::Band(c) => {
                    a.draw(&Rectangle::new(
                        [(x0, mid - 6), (x0 + 28, mid + 6)],
                        c.mix(BAND_ALPHA).filled(),
                    ))
                    .map_err(|e| e.to_string())?;
                }
                Swatch::Point(c) => {
                    a.draw(&Circle::new((x0 + 14, mid), 3, c.filled()))
                        .map_err(|e| e.to_string())?;
                    a.draw(&PathElement::new(
                        [(x0 + 14, mid - 7), (x0 + 14, mid + 7)],
                        c.stroke_width(1),
                    ))
                    .map_err(|e| e.to_string())?;
                }
                Swatch::Marker(c) => {
                    a.draw(&Circle::new((x0 + 14, mid), 3, c.filled()))
                        .map_err(|e| e.to_string())?;
                }
                Swatch::None => {}
            }
            for (k, l) in lines.iter().enumerate() {
                a.draw(&Text::new(
                    l.clone(),
                    (x0 + 36, y + k as i32 * LEGEND_LINE),
                    ("sans-serif", 14).into_font(),
                ))
                .map_err(|e| e.to_string())?;
            }
        }
        let r = Rect {
            left: 8,
            top: self.legend_top + 2,
            right: WIDTH as i32 - 8,
            bottom: self.legend_top + height.max(self.legend_height) - 2,
        };
        a.draw(&Rectangle::new(
            [(r.left, r.top), (r.right, r.bottom)],
            RGBColor(160, 160, 160).stroke_width(1),
        ))
        .map_err(|e| e.to_string())?;
        Ok(r)
    }

    /// Finishes the document.
    pub fn present(self) -> Result<(), String> {
        self.root.present().map_err(|e| e.to_string())
    }
}

/// Opacity of a confidence band (drawn over the lines: they show through it).
pub const BAND_ALPHA: f64 = 0.3;

/// The plotting area of a chart on the canvas, from its pixel ranges.
pub fn plot_rect(x: std::ops::Range<i32>, y: std::ops::Range<i32>) -> Rect {
    Rect {
        left: x.start.min(x.end),
        top: y.start.min(y.end),
        right: x.start.max(x.end),
        bottom: y.start.max(y.end),
    }
}

/// `text` broken into lines of at most `width` characters at spaces (a longer word stands
/// alone).
pub fn wrap(text: &str, width: usize) -> Vec<String> {
    let mut lines: Vec<String> = Vec::new();
    let mut cur = String::new();
    for w in text.split_whitespace() {
        if !cur.is_empty() && cur.chars().count() + 1 + w.chars().count() > width {
            lines.push(std::mem::take(&mut cur));
        }
        if !cur.is_empty() {
            cur.push(' ');
        }
        cur.push_str(w);
    }
    if !cur.is_empty() {
        lines.push(cur);
    }
    lines
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn wraps_at_spaces() {
        assert_eq!(
            wrap("99.9% confidence band of the ensemble mean", 16),
            ["99.9% confidence", "band of the", "ensemble mean"]
        );
        assert_eq!(wrap("", 10), Vec::<String>::new());
    }

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
        let mut twins = g.clone();
        twins.layers[1] = Layer::Line {
            color: RGBColor(60, 60, 60),
            dash: Some((3, 3)),
            label: "T_exact".into(),
        };
        assert!(twins.objections()[0].contains("look the same in grey scale"));
    }

    #[test]
    fn legend_rows_are_as_tall_as_their_tallest_entry() {
        let e = |t: &str| Entry::new(Swatch::None, t);
        let long = "a legend text long enough to wrap onto a second line of the legend's column";
        let (layout, height) = legend_layout(&[e("one"), e(long), e("three")]);
        assert_eq!(layout.iter().map(|l| l.0).collect::<Vec<_>>(), [0, 1, 0]);
        assert_eq!(layout[1].2.len(), 2);
        assert_eq!(layout[2].1, LEGEND_PAD + 2 * LEGEND_LINE + LEGEND_GAP);
        assert_eq!(height, layout[2].1 + LEGEND_LINE + LEGEND_PAD);
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
