//! Which reference curves apply to a scene, as extra columns beside the observables.

use crate::reference::exact::{HostMediumMaxwell, MaxwellTemperature};
use crate::run::columns::name;
use crate::run::{initial_sampler, initial_temperature};
use crate::scene::{BackgroundKernel, DriveChoice, DriveKind, KernelKind, Scene, SchemeChoice};

mod mixture;
mod rough;

use mixture::mixture_curves;
use rough::rough_curves;

/// A named reference curve `t -> value` for an observable column.
pub struct ReferenceCurve {
    /// Column name in observables.csv (e.g. `T_exact`).
    pub name: &'static str,
    /// The observable it is the reference of.
    pub of: &'static str,
    /// Paper and equation.
    pub source: &'static str,
    /// What the curve is to a run's means: the verdict judges only [`Kind::MeanAtN`].
    pub kind: Kind,
    /// The curve.
    pub curve: Box<dyn Fn(f64) -> f64 + Send + Sync>,
}

/// What a reference curve is to a run's ensemble means.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Kind {
    /// The exact ensemble mean at the run's n (and scheme): the run's mean must lie within its
    /// interval of it, so the summary's verdict judges it.
    MeanAtN,
    /// An exact solution of the Boltzmann equation (n -> infinity): a mean at finite n lies
    /// `O(1/n)` from it; shown beside the run, not judged.
    Limit,
    /// An approximation (Sonine, Maxwellian approximation, hydrodynamic closure): shown, not
    /// judged.
    Approximation,
}

impl Kind {
    /// The words the summary uses for it.
    pub fn words(self) -> &'static str {
        match self {
            Kind::MeanAtN => "the exact ensemble mean at this n",
            Kind::Limit => "the n -> infinity solution, O(1/n) from a mean at finite n",
            Kind::Approximation => "an approximation",
        }
    }
}

/// `(alpha, gamma, C_0)` of a one-species gas of smooth particles with the Maxwell kernel
/// and a constant restitution: the scenes the Maxwell gas's exact solutions are of.
fn smooth_maxwell(scene: &Scene) -> Option<(f64, f64, f64)> {
    if !scene.physics().species.is_empty() || !scene.translation_is_smooth() {
        return None; // a one-species solution of smooth particles
    }
    let alpha = scene.physics().restitution.constant()?;
    let k = scene.physics().kernel;
    (k.kind() == KernelKind::Maxwell).then(|| (alpha, k.gamma(), k.c()))
}

/// The exact temperature of the Maxwell gas (GRW (13)), when the scene is one.
pub fn maxwell_temperature(scene: &Scene) -> Option<MaxwellTemperature> {
    let (alpha, gamma, c) = smooth_maxwell(scene)?;
    let t0 = initial_temperature(scene);
    // Every drive that heats linearly (the core's declaration: none, white noise, the Gaussian
    // and Langevin thermostats, ...) has it exact.
    let heating = scene.model().heating()?;
    Some(MaxwellTemperature::new(t0, alpha, 0.0, gamma, c).with_heating(heating))
}

/// The exact BRS (14)-(17) solution, when the scene is a Maxwell gas in a Maxwell host medium.
pub fn host_medium_maxwell(scene: &Scene) -> Option<HostMediumMaxwell> {
    let (alpha, gamma, c) = smooth_maxwell(scene)?;
    let DriveChoice::HostMedium {
        kernel: BackgroundKernel::Maxwell,
        c1,
        density,
        mass,
        temperature,
        drift,
    } = scene.physics().drive
    else {
        return None;
    };
    let f0 = initial_sampler(scene);
    let u0 = f0.mean();
    Some(HostMediumMaxwell {
        u0: u0.to_array(),
        ub: drift,
        t0: initial_temperature(scene),
        tb: temperature,
        alpha: mass / (1.0 + mass),
        s: density * c1,
        kn: gamma * c / (density * c1),
        e: alpha,
        d: scene.dimension() as f64,
    })
}

/// The BRS (21), (22) closure models of a hard-sphere gas in a hard-sphere host medium.
pub fn hydro_models(scene: &Scene) -> Option<[crate::reference::hydro::HydroModel; 2]> {
    if !scene.physics().species.is_empty() || !scene.translation_is_smooth() {
        return None; // a one-species solution
    }
    if scene.dimension() != 3 {
        return None; // BRS (21)-(22)'s coefficients are the spheres' integrals
    }
    use crate::reference::hydro::{Closure, HydroModel};
    let k = scene.physics().kernel;
    if k.kind() != KernelKind::HardSpheres {
        return None;
    }
    let (gamma, c) = (k.gamma(), k.c());
    let DriveChoice::HostMedium {
        kernel: BackgroundKernel::HardSpheres,
        c1,
        density,
        mass,
        temperature,
        drift,
    } = scene.physics().drive
    else {
        return None;
    };
    let alpha = scene.physics().restitution.constant()?;
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

/// The first-Sonine `a2` of the cooling state of smooth hard spheres or disks (van Noije and
/// Ernst 1998; MS (5) for `d = 3`), when the scene is one.
pub fn sonine_cooling_a2(scene: &Scene) -> Option<f64> {
    if !scene.physics().species.is_empty() || !scene.translation_is_smooth() {
        return None;
    }
    let alpha = scene.physics().restitution.constant()?;
    let hard = scene.physics().kernel.kind() == KernelKind::HardSpheres;
    (hard && matches!(scene.physics().drive, DriveChoice::None))
        .then(|| crate::reference::exact::sonine::a2_cooling_in(scene.dimension() as f64, alpha))
}

/// The Boltzmann limit of `a2(t)` of the smooth one-species Maxwell gas without white noise
/// (`reference/maxwell_cumulant.rs`), cooling or under the Gaussian thermostat (which leaves
/// it as it is), when the scene is one; not for MS's time-stepped scheme, whose collisions
/// are not the Maxwell process's.
pub fn maxwell_cumulant(
    scene: &Scene,
) -> Option<crate::reference::maxwell_cumulant::MaxwellCumulant> {
    use crate::reference::maxwell_cumulant::{MaxwellCumulant, moment_ratio};
    let (alpha, gamma, c) = smooth_maxwell(scene)?;
    if !matches!(
        scene.physics().drive.kind(),
        DriveKind::None | DriveKind::Gaussian
    ) || matches!(scene.physics().scheme, SchemeChoice::TimeStepped(_))
    {
        return None;
    }
    let d = scene.dimension();
    let r0 = moment_ratio(&initial_sampler(scene), d);
    Some(MaxwellCumulant::new(d, alpha, gamma, c, r0))
}

/// Every reference curve that applies to `scene`.
pub fn for_scene(scene: &Scene) -> Vec<ReferenceCurve> {
    if !scene.physics().species.is_empty() {
        return mixture_curves(scene);
    }
    let mut out = rough_curves(scene);
    if let Some(a2) = sonine_cooling_a2(scene) {
        out.push(ReferenceCurve {
            name: "a2_sonine",
            of: name::A2,
            source: "van Noije and Ernst 1998, first Sonine approximation of the cooling state in d dimensions (MS (5) for d = 3); an approximation, reached once the gas has relaxed",
            kind: Kind::Approximation,
            curve: Box::new(move |_| a2),
        });
    }
    if let Some(m) = maxwell_cumulant(scene) {
        out.push(ReferenceCurve {
            name: "a2_exact",
            of: name::A2,
            source: "the inelastic Maxwell gas's moment equations (Bobylev, Carrillo and Gamba 2000; Santos 2003 for d = 2), a2(t) in the Boltzmann limit; derived in reference/maxwell_cumulant.rs",
            kind: Kind::Limit,
            curve: Box::new(move |t| m.at(t)),
        });
    }
    if let (Some(models), f0) = (hydro_models(scene), initial_sampler(scene)) {
        let t_end = scene.times().last().copied().unwrap_or(1.0);
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
    }
    if let Some(h) = host_medium_maxwell(scene) {
        for (k, (name, of)) in [
            ("V_x_exact", name::V_X),
            ("V_y_exact", name::V_Y),
            ("V_z_exact", name::V_Z),
        ]
        .into_iter()
        .enumerate()
        {
            out.push(ReferenceCurve {
                name,
                of,
                source: "BRS (14)",
                kind: Kind::MeanAtN,
                curve: Box::new(move |t| h.bulk(t)[k]),
            });
        }
        out.push(ReferenceCurve {
            name: "T_bulk_exact",
            of: name::T_BULK,
            source: "BRS (15)-(17)",
            kind: Kind::Limit,
            curve: Box::new(move |t| h.temperature(t)),
        });
    }
    if let (Some(mt), f0) = (maxwell_temperature(scene), initial_sampler(scene)) {
        // GRW (13)-(14) hold per degree of freedom in any dimension (the derivation in
        // `exact.rs` counts d components; disks keep it with d = 2).
        let v0 = f0.mean().norm2() / scene.dimension() as f64;
        out.push(ReferenceCurve {
            name: "T_exact",
            of: name::T,
            source: "GRW (13)-(14)",
            kind: Kind::Limit,
            curve: Box::new(move |t| mt.at(t) + v0 * mt.drift_factor(t)),
        });
        out.push(ReferenceCurve {
            name: "T_bulk_exact",
            of: name::T_BULK,
            source: "GRW (13)-(14)",
            kind: Kind::Limit,
            curve: Box::new(move |t| mt.at(t)),
        });
        // The exact ensemble mean at this n (and time step): the scheme's whole systematic error,
        // for T_bulk and for the raw T (which adds the random walk of the bulk velocity,
        // `bulk_to_raw`, and the initial drift).
        let n = scene.n();
        let finite: std::sync::Arc<dyn Fn(f64) -> f64 + Send + Sync> = match scene.physics().scheme
        {
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
            of: name::T,
            source: "exact ensemble mean at this n and scheme",
            kind: Kind::MeanAtN,
            curve: Box::new(move |t| raw(t) + mt.bulk_to_raw(n, t) + v0 * mt.drift_factor(t)),
        });
        out.push(ReferenceCurve {
            name: "T_bulk_mean_n",
            of: name::T_BULK,
            source: "exact ensemble mean at this n and scheme",
            kind: Kind::MeanAtN,
            curve: Box::new(move |t| finite(t)),
        });
    }
    out
}
