//! `gdsmc bench`'s work-precision study as the command runs it: each configuration's line
//! printed as it is measured, then the costs compared and written.

use super::work_precision as wp;
use crate::error::Error;
use crate::scene::Scene;

/// What `gdsmc bench work-precision` is asked for besides its scene.
#[derive(Clone, Debug)]
pub struct WorkPrecision {
    /// Independent runs per configuration (each one ensemble, as RW).
    pub runs: u64,
    /// The small ladder ([`wp::default_ladder`]).
    pub quick: bool,
    /// The relative error at which the costs are compared (`None`: RW's 0.01, or with
    /// `quick` the smallest every scheme of the small ladder reaches).
    pub target: Option<f64>,
    /// Worker threads (0: all cores).
    pub threads: usize,
    /// Output directory (default `out/work-precision`).
    pub out: Option<std::path::PathBuf>,
}

/// `gdsmc bench work-precision` as the command runs it: each configuration's line printed as
/// it is measured, then the costs compared at the target error, written to the output
/// directory (CSV and SVG).
pub fn work_precision(sc: &Scene, c: &WorkPrecision) -> Result<(), Error> {
    let WorkPrecision {
        runs,
        quick,
        target,
        threads,
        ref out,
    } = *c;
    let ladder = wp::default_ladder(quick);
    println!(
        "{:<13} {:>7} {:>6} {:>5} {:>12} {:>22} {:>12} {:>12}",
        "scheme", "n", "K", "runs", "cpu s/run", "T mean +- 99.9%", "T exact", "error"
    );
    let points = wp::measure(sc, &ladder, runs, threads, |p| {
        let k = if p.config.dt > 0.0 {
            format!("{}", (8.0 / p.config.dt).round())
        } else {
            "-".into()
        };
        println!(
            "{:<13} {:>7} {:>6} {:>5} {:>12.4e} {:>11.5} +- {:<8.1e} {:>12.5} {:>12.3e}",
            p.config.scheme,
            p.config.n,
            k,
            p.runs,
            p.cpu,
            p.mean.0,
            p.mean.1,
            p.exact_mean,
            p.error
        );
    })?;
    let dir = out
        .clone()
        .unwrap_or_else(|| std::path::PathBuf::from("out").join("work-precision"));
    let target = match (target, quick) {
        (Some(t), _) => t,
        (None, false) => 0.01,
        (None, true) => {
            let t = wp::reachable_target(&points).unwrap_or(0.01);
            println!(
                "\n--quick: costs compared at {:.2}% error, the smallest every scheme of the small ladder reached (RW compare at 1%: the full ladder, or --target)",
                100.0 * t
            );
            t
        }
    };
    let text = wp::write(&dir, sc.name(), &points, target)?;
    print!("\n{text}");
    println!("wrote {}", dir.join("work_precision.svg").display());
    Ok(())
}
