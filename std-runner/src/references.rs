//! Which reference curves apply to a scene, as extra columns beside the observables.

use crate::ensemble::initial_sampler;
use crate::reference::MaxwellTemperature;
use crate::scene::{DriveChoice, KernelChoice, Scene, SchemeChoice};

/// A named reference curve `t -> value` for an observable column.
pub struct ReferenceCurve {
    /// Column name in observables.csv (e.g. `T_exact`).
    pub name: &'static str,
    /// The observable it is the reference of.
    pub of: &'static str,
    /// Paper and equation.
    pub source: &'static str,
    /// The curve.
    pub curve: Box<dyn Fn(f64) -> f64 + Send + Sync>,
}

/// The exact temperature of the Maxwell gas (GRW (13)), when the scene is one.
pub fn maxwell_temperature(scene: &Scene) -> Option<MaxwellTemperature> {
    let KernelChoice::Maxwell { gamma, c } = scene.kernel else {
        return None;
    };
    let beta = match scene.drive {
        DriveChoice::None => 0.0,
        DriveChoice::WhiteNoise(b) => b,
    };
    let t0 = initial_sampler(scene).temperature();
    Some(MaxwellTemperature::new(
        t0,
        scene.restitution,
        beta,
        gamma,
        c,
    ))
}

/// Every reference curve that applies to `scene`.
pub fn for_scene(scene: &Scene) -> Vec<ReferenceCurve> {
    let mut out = Vec::new();
    if let Some(mt) = maxwell_temperature(scene) {
        let v0 = initial_sampler(scene).mean().norm2() / 3.0;
        out.push(ReferenceCurve {
            name: "T_exact",
            of: "T",
            source: "GRW (13)-(14)",
            curve: Box::new(move |t| mt.at(t) + v0),
        });
        out.push(ReferenceCurve {
            name: "T_bulk_exact",
            of: "T_bulk",
            source: "GRW (13)-(14)",
            curve: Box::new(move |t| mt.at(t)),
        });
        // The exact ensemble mean at this n (and time step): the scheme's whole systematic error.
        let n = scene.n;
        let finite: Box<dyn Fn(f64) -> f64 + Send + Sync> = match scene.scheme {
            SchemeChoice::NoSplitting => Box::new(move |t| mt.finite_n_bulk_mean(n, t)),
            SchemeChoice::Euler(dt) => Box::new(move |t| mt.splitting_bulk_mean(n, dt, false, t)),
            SchemeChoice::Strang(dt) => Box::new(move |t| mt.splitting_bulk_mean(n, dt, true, t)),
        };
        out.push(ReferenceCurve {
            name: "T_bulk_mean_n",
            of: "T_bulk",
            source: "exact mean at this n and scheme (reference::MaxwellTemperature)",
            curve: finite,
        });
    }
    out
}
