//! Which reference curves apply to a scene, as extra columns beside the observables.

use crate::reference::exact::{HostMediumMaxwell, MaxwellTemperature};
use crate::run::initial_sampler;
use crate::scene::{BackgroundKernel, DriveChoice, KernelChoice, Scene, SchemeChoice};

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
    let alpha = scene.physics.restitution.constant()?;
    let KernelChoice::Maxwell { gamma, c } = scene.physics.kernel else {
        return None;
    };
    let t0 = initial_sampler(scene)?.temperature();
    let m = |beta| MaxwellTemperature::new(t0, alpha, beta, gamma, c);
    match scene.physics.drive {
        DriveChoice::None => Some(m(0.0)),
        DriveChoice::WhiteNoise(b) => Some(m(b)),
        DriveChoice::Gaussian(z) => Some(m(0.0).with_gaussian(z)),
        DriveChoice::ConstantForce(_) | DriveChoice::HostMedium { .. } => None,
    }
}

/// The exact BRS (14)-(17) solution, when the scene is a Maxwell gas in a Maxwell host medium.
pub fn host_medium_maxwell(scene: &Scene) -> Option<HostMediumMaxwell> {
    let alpha = scene.physics.restitution.constant()?;
    let KernelChoice::Maxwell { gamma, c } = scene.physics.kernel else {
        return None;
    };
    let DriveChoice::HostMedium {
        kernel: BackgroundKernel::Maxwell,
        c1,
        density,
        mass,
        temperature,
        drift,
    } = scene.physics.drive
    else {
        return None;
    };
    let f0 = initial_sampler(scene)?;
    let u0 = f0.mean();
    Some(HostMediumMaxwell {
        u0: u0.to_array(),
        ub: drift,
        t0: f0.temperature(),
        tb: temperature,
        alpha: mass / (1.0 + mass),
        s: density * c1,
        kn: gamma * c / (density * c1),
        e: alpha,
    })
}

/// The BRS (21), (22) closure models of a hard-sphere gas in a hard-sphere host medium.
pub fn hydro_models(scene: &Scene) -> Option<[crate::reference::hydro::HydroModel; 2]> {
    use crate::reference::hydro::{Closure, HydroModel};
    let KernelChoice::HardSpheres { gamma, c } = scene.physics.kernel else {
        return None;
    };
    let DriveChoice::HostMedium {
        kernel: BackgroundKernel::HardSpheres,
        c1,
        density,
        mass,
        temperature,
        drift,
    } = scene.physics.drive
    else {
        return None;
    };
    let alpha = scene.physics.restitution.constant()?;
    let m = |closure| HydroModel {
        alpha: mass / (1.0 + mass),
        tb: temperature,
        ub: drift,
        k: gamma * c / (density * density * c1),
        beta: (1.0 - alpha) / 2.0,
        s: density * density * c1,
        closure,
    };
    Some([m(Closure::LocalEquilibrium), m(Closure::Grad)])
}

/// Every reference curve that applies to `scene`.
pub fn for_scene(scene: &Scene) -> Vec<ReferenceCurve> {
    let mut out = Vec::new();
    if let (Some(models), Some(f0)) = (hydro_models(scene), initial_sampler(scene)) {
        let t_end = scene.times.last().copied().unwrap_or(1.0);
        for (model, (tn, vn, src)) in models.iter().zip([
            (
                "T_bulk_hydro21",
                "V_y_hydro21",
                "BRS (21), local equilibrium",
            ),
            ("T_bulk_hydro22", "V_y_hydro22", "BRS (22), Grad"),
        ]) {
            match crate::reference::hydro::Trajectory::new(
                model,
                f0.mean().to_array(),
                f0.temperature(),
                t_end,
            ) {
                Ok(tr) => {
                    let tr = std::sync::Arc::new(tr);
                    let tr2 = tr.clone();
                    out.push(ReferenceCurve {
                        name: tn,
                        of: "T_bulk",
                        source: src,
                        curve: Box::new(move |t| tr.temperature(t)),
                    });
                    out.push(ReferenceCurve {
                        name: vn,
                        of: "V_y",
                        source: src,
                        curve: Box::new(move |t| tr2.bulk(t, 1)),
                    });
                }
                Err(e) => eprintln!("{src}: not integrated ({e})"),
            }
        }
    }
    if let Some(h) = host_medium_maxwell(scene) {
        for (k, (name, of)) in [
            ("V_x_exact", "V_x"),
            ("V_y_exact", "V_y"),
            ("V_z_exact", "V_z"),
        ]
        .into_iter()
        .enumerate()
        {
            out.push(ReferenceCurve {
                name,
                of,
                source: "BRS (14)",
                curve: Box::new(move |t| h.bulk(t)[k]),
            });
        }
        out.push(ReferenceCurve {
            name: "T_bulk_exact",
            of: "T_bulk",
            source: "BRS (15)-(17)",
            curve: Box::new(move |t| h.temperature(t)),
        });
    }
    if let (Some(mt), Some(f0)) = (maxwell_temperature(scene), initial_sampler(scene)) {
        let v0 = f0.mean().norm2() / 3.0;
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
        // The exact ensemble mean at this n (and time step): the scheme's whole systematic error,
        // for T_bulk and for the raw T (which adds the random walk of the bulk velocity,
        // `bulk_to_raw`, and the initial drift).
        let n = scene.n();
        let finite: std::sync::Arc<dyn Fn(f64) -> f64 + Send + Sync> = match scene.physics.scheme {
            SchemeChoice::NoSplitting => std::sync::Arc::new(move |t| mt.finite_n_bulk_mean(n, t)),
            SchemeChoice::Euler(dt) => {
                std::sync::Arc::new(move |t| mt.splitting_bulk_mean(n, dt, false, t))
            }
            SchemeChoice::Strang(dt) => {
                std::sync::Arc::new(move |t| mt.splitting_bulk_mean(n, dt, true, t))
            }
            SchemeChoice::TimeStepped(_) => return out,
        };
        let raw = finite.clone();
        out.push(ReferenceCurve {
            name: "T_mean_n",
            of: "T",
            source: "exact ensemble mean at this n and scheme",
            curve: Box::new(move |t| raw(t) + mt.bulk_to_raw(n, t) + v0),
        });
        out.push(ReferenceCurve {
            name: "T_bulk_mean_n",
            of: "T_bulk",
            source: "exact ensemble mean at this n and scheme",
            curve: Box::new(move |t| finite(t)),
        });
    }
    out
}
