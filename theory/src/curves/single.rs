//! The curves of a one-species gas's exact solutions and closures: GRW (13)-(14) (in the
//! Boltzmann limit and at finite n), the Maxwell gas's `a2(t)`, BRS (14)-(17) and the BRS (21),
//! (22) closures. Each is a builder of [`super::registry`], called where its declaration holds.

use super::{
    Kind, ReferenceCurve, host_medium_maxwell, hydro_models, maxwell_cumulant, maxwell_temperature,
};
use crate::columns::name;
use crate::initial::initial_sampler;
use gdsmc_scene::{Scene, SchemeChoice};
use std::sync::Arc;

/// The Boltzmann limit of the Maxwell gas's `a2(t)` (`a2_exact`).
pub(super) fn a2_exact(scene: &Scene) -> Vec<ReferenceCurve> {
    let source = match crate::maxwell_form::Form::of(scene) {
        crate::maxwell_form::Form::Scattering => {
            "the inelastic Maxwell gas's moment equations in GRW (3)'s scattering form, e uniform (Bobylev, Carrillo and Gamba 2000; Santos 2003 for d = 2), a2(t) in the Boltzmann limit; derived in theory/src/maxwell_cumulant.rs"
        }
        crate::maxwell_form::Form::Impact => {
            "the inelastic Maxwell model's moment equations in Ernst and Brito's impact form, n uniform (Santos 2003's cooling state), a2(t) in the Boltzmann limit; derived in theory/src/maxwell_impact.rs"
        }
    };
    maxwell_cumulant(scene)
        .map(|m| ReferenceCurve {
            name: "a2_exact",
            of: name::A2,
            source,
            kind: Kind::Limit,
            curve: Box::new(move |t| m.at(t)),
        })
        .into_iter()
        .collect()
}

/// The BRS (21), (22) closures' `T_bulk` and `V_y` of a gas in a hard-sphere host medium.
pub(super) fn brs_hydro(scene: &Scene) -> Vec<ReferenceCurve> {
    let mut out = Vec::new();
    let (Some(models), f0) = (hydro_models(scene), initial_sampler(scene)) else {
        return out;
    };
    let t_end = scene.times().last().copied().unwrap_or(1.0);
    for (model, (tn, vn, src)) in models.iter().zip([
        (
            "T_bulk_hydro21",
            "V_y_hydro21",
            "BRS (21), local equilibrium",
        ),
        ("T_bulk_hydro22", "V_y_hydro22", "BRS (22), Grad"),
    ]) {
        match crate::hydro::Trajectory::new(model, f0.mean().to_array(), f0.temperature(), t_end) {
            Ok(tr) => {
                let tr = Arc::new(tr);
                let tr2 = tr.clone();
                out.push(ReferenceCurve {
                    name: tn,
                    of: name::T_BULK,
                    source: src,
                    kind: Kind::Approximation,
                    curve: Box::new(move |t| tr.temperature(t)),
                });
                out.push(ReferenceCurve {
                    name: vn,
                    of: name::V_Y,
                    source: src,
                    kind: Kind::Approximation,
                    curve: Box::new(move |t| tr2.bulk(t, 1)),
                });
            }
            Err(e) => eprintln!("{src}: not integrated ({e})"),
        }
    }
    out
}

/// BRS (14): the exact bulk velocity in a Maxwell host medium (`V_x_exact` ...), the mean at
/// any n (collisions among the grains keep it).
pub(super) fn brs_bulk(scene: &Scene) -> Vec<ReferenceCurve> {
    let Some(h) = host_medium_maxwell(scene) else {
        return Vec::new();
    };
    [
        ("V_x_exact", name::V_X),
        ("V_y_exact", name::V_Y),
        ("V_z_exact", name::V_Z),
    ]
    .into_iter()
    .enumerate()
    .map(|(k, (name, of))| ReferenceCurve {
        name,
        of,
        source: "BRS (14)",
        kind: Kind::MeanAtN,
        curve: Box::new(move |t| h.bulk(t)[k]),
    })
    .collect()
}

/// BRS (15)-(17): the temperature in a Maxwell host medium (`T_bulk_exact`).
pub(super) fn brs_temperature(scene: &Scene) -> Vec<ReferenceCurve> {
    host_medium_maxwell(scene)
        .map(|h| ReferenceCurve {
            name: "T_bulk_exact",
            of: name::T_BULK,
            source: "BRS (15)-(17)",
            kind: Kind::Limit,
            curve: Box::new(move |t| h.temperature(t)),
        })
        .into_iter()
        .collect()
}

/// The squared initial drift per degree of freedom, which the raw `T` carries.
fn drift(scene: &Scene) -> f64 {
    initial_sampler(scene).mean().norm2() / scene.dimension() as f64
}

/// GRW (13)-(14) in the Boltzmann limit: `T_exact` (raw, with the drift) and `T_bulk_exact`.
pub(super) fn grw_limit(scene: &Scene) -> Vec<ReferenceCurve> {
    let Some(mt) = maxwell_temperature(scene) else {
        return Vec::new();
    };
    // GRW (13)-(14) hold per degree of freedom in any dimension (the derivation in
    // `exact.rs` counts d components; disks keep it with d = 2).
    let v0 = drift(scene);
    let source = match crate::maxwell_form::Form::of(scene) {
        crate::maxwell_form::Form::Scattering => "GRW (13)-(14)",
        crate::maxwell_form::Form::Impact => {
            "GRW (13)-(14)'s law at the impact form's rate 2 pi gamma C (1 - alpha^2)/d (Ernst and Brito's model, theory/src/maxwell_impact.rs)"
        }
    };
    vec![
        ReferenceCurve {
            name: "T_exact",
            of: name::T,
            source,
            kind: Kind::Limit,
            curve: Box::new(move |t| mt.at(t) + v0 * mt.drift_factor(t)),
        },
        ReferenceCurve {
            name: "T_bulk_exact",
            of: name::T_BULK,
            source,
            kind: Kind::Limit,
            curve: Box::new(move |t| mt.at(t)),
        },
    ]
}

/// GRW (13)-(14)'s exact ensemble means at this n (and time step): the scheme's whole
/// systematic error, for `T_bulk` and for the raw `T` (which adds the random walk of the bulk
/// velocity, `bulk_to_raw_from` the scene's start of momentum, and the initial drift). None for MS's time-stepped scheme, whose
/// collisions are not the Maxwell process's, nor for weighted particles under a drive that
/// heats them by itself.
pub(super) fn grw_mean_at_n(scene: &Scene) -> Vec<ReferenceCurve> {
    let Some(mt) = maxwell_temperature(scene) else {
        return Vec::new();
    };
    let (n, v0, momentum) = (scene.n(), drift(scene), scene.physics().momentum);
    let finite: Arc<dyn Fn(f64) -> f64 + Send + Sync> = match scene.physics().scheme {
        SchemeChoice::NoSplitting => Arc::new(move |t| mt.finite_n_bulk_mean(n, t)),
        SchemeChoice::Euler(dt) => Arc::new(move |t| mt.splitting_bulk_mean(n, dt, false, t)),
        SchemeChoice::Strang(dt) => Arc::new(move |t| mt.splitting_bulk_mean(n, dt, true, t)),
        // Weighted particles keep GRW's mean of T_bulk where the drive adds no heat of its own
        // (`a = 0`: cooling, the Gaussian thermostat); white noise's depends on the weights
        // (docs/weighted.md: sum g^2 / n0^2 in place of 1/n), so only the limit stands then.
        SchemeChoice::Weighted(_) if mt.heating.a == 0.0 => {
            Arc::new(move |t| mt.finite_n_bulk_mean(n, t))
        }
        SchemeChoice::TimeStepped(_) | SchemeChoice::Weighted(_) => return Vec::new(),
    };
    let raw = finite.clone();
    vec![
        ReferenceCurve {
            name: "T_mean_n",
            of: name::T,
            source: "exact ensemble mean at this n and scheme",
            kind: Kind::MeanAtN,
            curve: Box::new(move |t| {
                raw(t) + mt.bulk_to_raw_from(momentum, n, t) + v0 * mt.drift_factor(t)
            }),
        },
        ReferenceCurve {
            name: "T_bulk_mean_n",
            of: name::T_BULK,
            source: "exact ensemble mean at this n and scheme",
            kind: Kind::MeanAtN,
            curve: Box::new(move |t| finite(t)),
        },
    ]
}
