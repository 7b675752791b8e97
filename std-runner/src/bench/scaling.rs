//! `gdsmc bench scaling SCENE`: the same run on 1 and on `k` threads; the speed-up, and a
//! check that the statistics are bit-identical (a run is a pure function of scene and seed).

use super::line::ScalingLine;
use crate::error::Error;
use crate::run;
use crate::scene::Scene;

/// Wall seconds on one thread and on `threads` threads, and whether the results agree bit for
/// bit.
pub fn measure(scene: &Scene, threads: usize) -> Result<ScalingLine, Error> {
    let one = run::run(scene, 1, &|_| {})?;
    let many = run::run(scene, threads, &|_| {})?;
    Ok(ScalingLine {
        scene: scene.name().to_string(),
        ensembles: scene.ensembles(),
        one_s: one.wall.as_secs_f64(),
        threads,
        many_s: many.wall.as_secs_f64(),
        bit_identical: one.acc == many.acc && one.counts == many.counts,
    })
}
