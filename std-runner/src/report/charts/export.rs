//! Charts written as SVG, PNG or PDF: the SVG is drawn once and rendered by resvg (PNG, twice
//! the SVG's pixel size) or converted by svg2pdf (PDF, vector), with the system's fonts
//! (`sans-serif` resolved to the first of DejaVu Sans, Liberation Sans, Noto Sans, Arial
//! found). The renderers are the `render` feature (off by default: they are more crates than the rest of
//! the build): without it gdsmc writes
//! SVG only and refuses `png` and `pdf` where the formats are parsed ([`NO_RENDER`]).

/// Why PNG and PDF are refused by a build without the `render` feature.
pub const NO_RENDER: &str = "PNG and PDF charts need the `render` feature, which this gdsmc \
was built without (build it with `cargo build --release -p gdsmc --features render`); SVG needs \
nothing";

/// The formats a chart is written in.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Formats {
    /// `NAME.svg`.
    pub svg: bool,
    /// `NAME.png`.
    pub png: bool,
    /// `NAME.pdf`.
    pub pdf: bool,
}

impl Default for Formats {
    /// SVG only.
    fn default() -> Self {
        Formats {
            svg: true,
            png: false,
            pdf: false,
        }
    }
}

impl std::str::FromStr for Formats {
    type Err = String;
    /// A comma-separated list of `svg`, `png`, `pdf` (at least one).
    fn from_str(s: &str) -> Result<Self, String> {
        let mut f = Formats {
            svg: false,
            png: false,
            pdf: false,
        };
        for part in s.split(',').map(str::trim).filter(|p| !p.is_empty()) {
            match part {
                "svg" => f.svg = true,
                "png" | "pdf" if !cfg!(feature = "render") => {
                    return Err(format!("chart format `{part}`: {NO_RENDER}"));
                }
                "png" => f.png = true,
                "pdf" => f.pdf = true,
                other => {
                    return Err(format!(
                        "unknown chart format `{other}`: use svg, png, pdf or a comma-separated list"
                    ));
                }
            }
        }
        if !(f.svg || f.png || f.pdf) {
            return Err(
                "no chart format given: use svg, png, pdf or a comma-separated list".into(),
            );
        }
        Ok(f)
    }
}

#[cfg(feature = "render")]
pub use render::{have_fonts, pdf, png};

#[cfg(not(feature = "render"))]
pub use unrendered::{have_fonts, pdf, png};

/// PNG and PDF by resvg and svg2pdf.
#[cfg(feature = "render")]
mod render {
    use std::sync::OnceLock;

    use resvg::usvg::fontdb::{Database, Source};

    /// The parse options with the system's fonts, loaded once.
    fn options() -> &'static resvg::usvg::Options<'static> {
        static OPTIONS: OnceLock<resvg::usvg::Options<'static>> = OnceLock::new();
        OPTIONS.get_or_init(|| {
            let mut o = resvg::usvg::Options::default();
            *o.fontdb_mut() = fonts();
            o
        })
    }

    /// The sans-serif family: the first of these the system has, its files read into memory
    /// (a database of the system's font files opens and maps a file for every glyph it
    /// shapes: 877 000 opens for the charts of the shipped scenes, three quarters of their
    /// PNG time in the kernel). Without any of them, every system font, from its files.
    fn fonts() -> Database {
        let mut system = Database::new();
        system.load_system_fonts();
        for want in ["DejaVu Sans", "Liberation Sans", "Noto Sans", "Arial"] {
            let mut files: Vec<&std::path::Path> = system
                .faces()
                .filter(|f| f.families.iter().any(|(name, _)| name == want))
                .filter_map(|f| match &f.source {
                    Source::File(path) => Some(path.as_path()),
                    _ => None,
                })
                .collect();
            files.sort();
            files.dedup();
            let mut db = Database::new();
            for bytes in files.into_iter().filter_map(|f| std::fs::read(f).ok()) {
                db.load_font_data(bytes);
            }
            if !db.is_empty() {
                db.set_sans_serif_family(want);
                return db;
            }
        }
        system
    }

    /// Whether any font was found (without one, text is left out of PNG and PDF).
    pub fn have_fonts() -> bool {
        !options().fontdb.is_empty()
    }

    fn tree(svg: &str) -> Result<resvg::usvg::Tree, String> {
        resvg::usvg::Tree::from_str(svg, options()).map_err(|e| e.to_string())
    }

    /// The chart as a PNG at twice the SVG's pixel size.
    pub fn png(svg: &str) -> Result<Vec<u8>, String> {
        let t = tree(svg)?;
        let size = t.size().to_int_size();
        let (w, h) = (size.width() * 2, size.height() * 2);
        let mut pix = resvg::tiny_skia::Pixmap::new(w, h).ok_or("empty chart")?;
        resvg::render(
            &t,
            resvg::tiny_skia::Transform::from_scale(2.0, 2.0),
            &mut pix.as_mut(),
        );
        pix.encode_png().map_err(|e| e.to_string())
    }

    /// The chart as a one-page PDF.
    pub fn pdf(svg: &str) -> Result<Vec<u8>, String> {
        let t = tree(svg)?;
        svg2pdf::to_pdf(
            &t,
            svg2pdf::ConversionOptions::default(),
            svg2pdf::PageOptions::default(),
        )
        .map_err(|e| e.to_string())
    }
}

/// A build without the renderers: PNG and PDF are errors ([`super::NO_RENDER`]).
#[cfg(not(feature = "render"))]
mod unrendered {
    use super::NO_RENDER;

    /// True: nothing is rendered, so no font is missing.
    pub fn have_fonts() -> bool {
        true
    }

    /// An error: this build has no PNG renderer.
    pub fn png(_svg: &str) -> Result<Vec<u8>, String> {
        Err(NO_RENDER.into())
    }

    /// An error: this build has no PDF converter.
    pub fn pdf(_svg: &str) -> Result<Vec<u8>, String> {
        Err(NO_RENDER.into())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn formats_parse_and_refuse() {
        assert!("jpg".parse::<Formats>().unwrap_err().contains("jpg"));
        if cfg!(feature = "render") {
            let f: Formats = "svg,png".parse().unwrap();
            assert!(f.svg && f.png && !f.pdf);
            assert!("pdf".parse::<Formats>().unwrap().pdf);
        } else {
            let e = "svg,png".parse::<Formats>().unwrap_err();
            assert!(e.contains("`png`") && e.contains("render"), "{e}");
            assert!("svg".parse::<Formats>().unwrap().svg);
        }
        assert!("".parse::<Formats>().is_err());
    }

    /// A small chart with text, a line and a filled band.
    const SVG: &str = r##"<svg xmlns="http://www.w3.org/2000/svg" width="120" height="80">
<rect x="10" y="30" width="100" height="20" fill="#3060c0" fill-opacity="0.3"/>
<line x1="10" y1="40" x2="110" y2="40" stroke="#000" stroke-width="2"/>
<text x="10" y="20" font-family="sans-serif" font-size="12">T(t)</text></svg>"##;

    /// PNG at twice the SVG's pixel size (its IHDR's width and height), with the line drawn
    /// (not one colour throughout); a complete PDF. CI runs this in the stage
    /// that builds `render`.
    #[cfg(feature = "render")]
    #[test]
    fn png_and_pdf_are_rendered() {
        let png = png(SVG).unwrap();
        assert_eq!(&png[..8], b"\x89PNG\r\n\x1a\n");
        let be = |i: usize| u32::from_be_bytes(png[i..i + 4].try_into().unwrap());
        assert_eq!((be(16), be(20)), (240, 160), "IHDR size");
        assert!(
            png.len() > 300,
            "an empty picture compresses to less: {}",
            png.len()
        );
        let pdf = pdf(SVG).unwrap();
        assert!(pdf.starts_with(b"%PDF-"), "{:?}", &pdf[..8]);
        let tail = String::from_utf8_lossy(&pdf[pdf.len().saturating_sub(64)..]).to_string();
        assert!(tail.contains("%%EOF"), "{tail}");
        assert!(
            have_fonts(),
            "no system font: the PNG and PDF would have no text"
        );
    }

    /// Without the renderers PNG and PDF are refused by name.
    #[cfg(not(feature = "render"))]
    #[test]
    fn png_and_pdf_are_refused_without_render() {
        for e in [png(SVG).unwrap_err(), pdf(SVG).unwrap_err()] {
            assert!(
                e.contains("`render` feature") && e.contains("--features render"),
                "{e}"
            );
        }
    }
}
