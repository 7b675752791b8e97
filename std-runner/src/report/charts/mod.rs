//! SVG charts: each observable against time, its 99.9% confidence band shaded, the reference
//! curves dashed. Written next to observables.csv, atomically.

pub mod distribution;
pub mod profile;
pub mod tail;
pub mod time;

pub use distribution::write_distribution_charts;
pub use profile::{Series, Style, profile_svg};
pub use tail::tail_svg;
pub use time::{CHARTED, chart_svg, write_charts};
