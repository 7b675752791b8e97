//! Charts written as SVG, PNG or PDF: the SVG is drawn once and rendered by resvg (PNG, twice
//! the SVG's pixel size) or converted by svg2pdf (PDF, vector), with the system's fonts
//! (`sans-serif` resolved to the first of DejaVu Sans, Liberation Sans, Noto Sans, Arial
//! found).

use std::sync::OnceLock;

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

/// The parse options with the system's fonts, loaded once.
fn options() -> &'static resvg::usvg::Options<'static> {
    static OPTIONS: OnceLock<resvg::usvg::Options<'static>> = OnceLock::new();
    OPTIONS.get_or_init(|| {
        let mut o = resvg::usvg::Options::default();
        let db = o.fontdb_mut();
        db.load_system_fonts();
        let families: Vec<String> = db
            .faces()
            .flat_map(|f| f.families.iter().map(|(name, _)| name.clone()))
            .collect();
        for want in ["DejaVu Sans", "Liberation Sans", "Noto Sans", "Arial"] {
            if families.iter().any(|f| f == want) {
                db.set_sans_serif_family(want);
                break;
            }
        }
        o
    })
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

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn formats_parse_and_refuse() {
        let f: Formats = "svg,png".parse().unwrap();
        assert!(f.svg && f.png && !f.pdf);
        assert!("pdf".parse::<Formats>().unwrap().pdf);
        assert!("jpg".parse::<Formats>().unwrap_err().contains("jpg"));
        assert!("".parse::<Formats>().is_err());
    }
}
