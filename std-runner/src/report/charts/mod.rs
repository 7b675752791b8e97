//! Charts: each observable against time (its 99.9% band, the references dashed, a residual
//! panel), the distribution and tail charts, all with the legend in a band below the data
//! (`frame.rs`), written as SVG, PNG or PDF (`export.rs`) next to observables.csv, atomically.

pub mod distribution;
pub mod export;
pub mod frame;
pub mod geometry;
pub mod power_tail;
pub mod profile;
pub mod tail;
pub mod time;

pub use distribution::distribution_charts;
pub use export::Formats;
pub use frame::Chart;
pub use power_tail::power_tail;
pub use profile::{Residuals, Series, Style, profile, profile_with_residuals};
pub use tail::tail;

use crate::error::Error;
use crate::files::write_atomic;
use crate::run::RunStats;
use gdsmc_theory::curves::ReferenceCurve;
use std::path::Path;

/// Every chart of a run, `(file stem, chart)`: one per observable, the tail plot when there is
/// a histogram, the distribution charts; the time charts against `axis`, a mixture's species
/// called by their names (`species`). `title` (the physics, n, ensembles: [`title`]) heads each.
pub fn all(
    title: &str,
    stats: &RunStats,
    (axis, species): (crate::scene::TimeAxis, &[String]),
    refs: &[ReferenceCurve],
    reduced: Option<&crate::analysis::distribution::Reduced>,
    marginal: Option<&crate::analysis::distribution::Marginal>,
    power: Option<&crate::analysis::power_tail::PowerTail>,
) -> Vec<(String, Result<Chart, String>)> {
    let mut out = time::charts(title, stats, (axis, species), refs);
    if let Some(crate::run::ShellHistogram { radius, weights: h }) = &stats.histogram
        && let Some(fit) = crate::analysis::tails::fit(*radius, h, stats.dimension)
    {
        let points = crate::analysis::tails::tail_points(*radius, h, stats.dimension);
        out.push((
            "tail".into(),
            tail(&format!("{title}: tail (GRW Section 4.3)"), &fit, &points),
        ));
    }
    out.extend(distribution_charts(title, stats, reduced, marginal));
    if let Some(t) = power {
        out.push(("power_tail".into(), power_tail(title, t)));
    }
    out
}

/// The title every chart of a run carries: the physics in words (particles, kernel,
/// restitution, drive; not the file's name), particles and ensembles, e.g. "Smooth spheres,
/// Maxwell kernel, alpha = 0.5, white noise (beta = 1), n = 1024, 1000 ensembles".
pub fn title(scene: &crate::scene::Scene, ensembles: u64) -> String {
    use gdsmc_core::physics::{DriveChoice, RestitutionLaw};
    let ph = scene.physics();
    let shape = if scene.is_disks() { "disks" } else { "spheres" };
    let (surface, capital) = if ph.rotation.is_some() {
        ("rough", "Rough")
    } else {
        ("smooth", "Smooth")
    };
    let particles = match ph.species.len() {
        0 | 1 => format!("{capital} {shape}"),
        2 => format!("Binary mixture of {surface} {shape}"),
        k => format!("Mixture of {k} species of {surface} {shape}"),
    };
    // Weighted particles (the scheme that changes what a particle is) are named with them.
    let particles = if scene.model().weighted() {
        format!("{particles} (weighted particles)")
    } else {
        particles
    };
    let kernel = ph.kernel.to_string();
    let law = match (ph.restitution, ph.pair_restitution.is_empty()) {
        (RestitutionLaw::Constant(a), true) => format!("alpha = {a}"),
        (RestitutionLaw::Constant(_), false) => "alpha per pair".to_string(),
        (RestitutionLaw::ImpactSpeed { .. }, _) => "impact-speed alpha (BRS (9))".to_string(),
    };
    // The core's words for the drive (a declared drive's from its declaration), but a
    // mixture's white noise, whose strengths are each species' own.
    let drive = match ph.drive {
        DriveChoice::WhiteNoise(_) if !ph.species.is_empty() => "white noise".to_string(),
        d => d.to_string(),
    };
    format!(
        "{particles}, {kernel}, {law}, {drive}, n = {}, {ensembles} ensembles",
        scene.n()
    )
}

/// Writes every chart of a run into `dir` in the chosen formats; returns the files written.
pub fn write(
    dir: &Path,
    charts: &[(String, Result<Chart, String>)],
    formats: Formats,
) -> Result<Vec<String>, Error> {
    let mut written = Vec::new();
    if (formats.png || formats.pdf) && !export::have_fonts() {
        eprintln!(
            "charts: no system fonts found; PNG and PDF charts have no text (install fonts-dejavu-core)"
        );
    }
    for (stem, chart) in charts {
        let chart = match chart {
            Ok(c) => c,
            Err(e) => {
                eprintln!("chart {stem}: not drawn ({e})");
                continue;
            }
        };
        let mut put = |ext: &str, bytes: Result<Vec<u8>, String>| -> Result<(), Error> {
            match bytes {
                Ok(b) => {
                    let name = format!("{stem}.{ext}");
                    write_atomic(&dir.join(&name), &b)?;
                    written.push(name);
                }
                Err(e) => eprintln!("chart {stem}.{ext}: not written ({e})"),
            }
            Ok(())
        };
        if formats.svg {
            put("svg", Ok(chart.svg.clone().into_bytes()))?;
        }
        if formats.png {
            put("png", export::png(&chart.svg))?;
        }
        if formats.pdf {
            put("pdf", export::pdf(&chart.svg))?;
        }
    }
    Ok(written)
}
