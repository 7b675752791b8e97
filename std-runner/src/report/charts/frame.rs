//! What every chart shares: the canvas with its title, the plotting area on the left and the
//! legend in a column of its own on the right (so it never covers data), legend swatches
//! drawn in the same style as their series, and the geometry a test can check.

use plotters::coord::Shift;
use plotters::prelude::*;

/// Canvas width and height in pixels.
pub const SIZE: (u32, u32) = (980, 560);
/// Width of the legend column.
pub const LEGEND_WIDTH: u32 = 270;
/// Height of the title band.
const TITLE_HEIGHT: u32 = 40;
/// Width of every drawn line, pixels.
pub const LINE_WIDTH: u32 = 2;
/// Characters per legend line before it wraps.
const LEGEND_CHARS: usize = 32;

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

/// Where a chart put things: for the checks that a reviewer's eye would make.
#[derive(Clone, Debug, PartialEq)]
pub struct Geometry {
    /// The title.
    pub title: String,
    /// The plotting areas (one per panel), pixels.
    pub plots: Vec<Rect>,
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

/// The canvas split into title, plotting area and legend column.
pub struct Frame<'a> {
    /// The plotting area (left).
    pub plot: DrawingArea<SVGBackend<'a>, Shift>,
    legend: DrawingArea<SVGBackend<'a>, Shift>,
    root: DrawingArea<SVGBackend<'a>, Shift>,
}

impl<'a> Frame<'a> {
    /// A white canvas with `title` on top, into `svg`.
    pub fn new(svg: &'a mut String, title: &str) -> Result<Self, String> {
        let root = SVGBackend::with_string(svg, SIZE).into_drawing_area();
        root.fill(&WHITE).map_err(|e| e.to_string())?;
        let (head, body) = root.split_vertically(TITLE_HEIGHT);
        head.draw(&Text::new(
            title.to_string(),
            (12, 10),
            ("sans-serif", 20).into_font(),
        ))
        .map_err(|e| e.to_string())?;
        let (plot, legend) = body.split_horizontally(SIZE.0 - LEGEND_WIDTH);
        Ok(Frame { plot, legend, root })
    }

    /// Draws the legend in its column and returns its box in canvas pixels.
    pub fn legend(&self, entries: &[Entry]) -> Result<Rect, String> {
        let (x0, y0) = (12, 16);
        let line_h = 18;
        let mut y = y0;
        let a = &self.legend;
        for e in entries {
            let lines = wrap(&e.text, LEGEND_CHARS);
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
                        c.mix(0.25).filled(),
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
                    (x0 + 36, y + k as i32 * line_h),
                    ("sans-serif", 14).into_font(),
                ))
                .map_err(|e| e.to_string())?;
            }
            y += lines.len().max(1) as i32 * line_h + 8;
        }
        let (ox, oy) = self.legend_origin();
        let r = Rect {
            left: ox + x0 - 6,
            top: oy + y0 - 6,
            right: ox + LEGEND_WIDTH as i32 - 4,
            bottom: oy + y,
        };
        self.root
            .draw(&Rectangle::new(
                [(r.left, r.top), (r.right, r.bottom)],
                BLACK.stroke_width(1),
            ))
            .map_err(|e| e.to_string())?;
        Ok(r)
    }

    /// The legend column's top-left corner on the canvas.
    fn legend_origin(&self) -> (i32, i32) {
        (SIZE.0 as i32 - LEGEND_WIDTH as i32, TITLE_HEIGHT as i32)
    }

    /// Finishes the document.
    pub fn present(self) -> Result<(), String> {
        self.root.present().map_err(|e| e.to_string())
    }
}

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
