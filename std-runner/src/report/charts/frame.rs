//! What every chart shares: the canvas with its title, the plotting area over the full width
//! and the legend in a band of its own below it (so it never covers data), legend swatches
//! drawn in the same style as their series, and the geometry a test can check with the
//! objections a referee would raise ([`Geometry::objections`]).

pub use super::geometry::{
    Geometry, LINE_WIDTH, Layer, MAX_LINE_LUMINANCE, MIN_LUMINANCE_STEP, Rect, luminance,
};
use plotters::coord::Shift;
use plotters::prelude::*;

/// Canvas width in pixels.
pub const WIDTH: u32 = 980;
/// Height of the plotting area (all panels, with their axis labels), pixels.
pub const PLOT_HEIGHT: u32 = 500;
/// Height of one title line; the title band holds as many as the title has.
const TITLE_LINE: u32 = 24;
/// Legend entries per row.
const LEGEND_COLUMNS: usize = 2;
/// Characters per legend line before it wraps (a column is about half the canvas).
const LEGEND_CHARS: usize = 56;
/// Legend text line height and the gap after each row, pixels.
const LEGEND_LINE: i32 = 17;
const LEGEND_GAP: i32 = 5;
/// Margin above and below the legend's entries, pixels.
const LEGEND_PAD: i32 = 8;

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
}
