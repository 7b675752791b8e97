//! `references`: a scene's references without a run (issue 78), computed by the theory crate
//! as `gdsmc run` computes its reference columns, so the values equal the command's to the bit.

use crate::scene::Scene;
use gdsmc_runner::scene as sc;
use gdsmc_theory::curves::{Kind, for_scene};
use pyo3::prelude::*;

/// One reference as Python gets it: its column name, the observable it is of, its paper and
/// equation, its kind ("mean_at_n", "limit", "approximation") and its values at the times.
type Curve = (String, String, String, &'static str, Vec<f64>);

/// The references of `scene` (with `n` overriding `particles.n`, as `run`'s keyword does) at
/// `times` (default: the scene's observation times): the times and every reference that holds.
#[pyfunction]
#[pyo3(signature = (scene, times = None, n = None))]
pub fn references(
    scene: &Scene,
    times: Option<Vec<f64>>,
    n: Option<i64>,
) -> PyResult<(Vec<f64>, Vec<Curve>)> {
    let mut s = scene.clone();
    for o in sc::Override::run_keywords(n, None, None) {
        s = s.with(o)?;
    }
    let mut scene = s.scene().clone();
    if let Some(t) = times {
        scene.set_times(t).map_err(|e| {
            crate::SceneError::new_err(e.to_string().replace("observe.times", "times"))
        })?;
    }
    let times = scene.times().to_vec();
    let curves = for_scene(&scene)
        .into_iter()
        .map(|r| {
            let kind = match r.kind {
                Kind::MeanAtN => "mean_at_n",
                Kind::Limit => "limit",
                Kind::Approximation => "approximation",
            };
            let values = times.iter().map(|&t| (r.curve)(t)).collect();
            (
                r.name.to_string(),
                r.of.to_string(),
                r.source.to_string(),
                kind,
                values,
            )
        })
        .collect();
    Ok((times, curves))
}
