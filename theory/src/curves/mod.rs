//! The reference curves of a scene, as extra columns beside the observables: each reference
//! declared once in [`registry`] with the physics it holds for; here the curve type and the
//! exact solutions' parameters read from a scene.

use crate::exact::{HostMediumMaxwell, MaxwellTemperature};
use crate::initial::{initial_sampler, initial_temperature};
use crate::maxwell_form::Form;
use gdsmc_scene::{BackgroundKernel, DriveChoice, Scene};

mod cooling;
pub mod holds;
mod mixture;
pub mod registry;
mod rough;
mod single;
mod sonine;

pub use registry::for_scene;

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
    // A kernel that does not depend on the speed (the Maxwell kernel, or VHS at lambda = 0):
    // `B = gamma C` (GRW (2)), whose moment equations close.
    let k = scene.physics().kernel;
    (k.exponent() == Some(0.0)).then(|| (alpha, k.gamma(), k.c()))
}

/// The exact temperature of the Maxwell gas (GRW (13)), when the scene is one.
pub fn maxwell_temperature(scene: &Scene) -> Option<MaxwellTemperature> {
    let (alpha, gamma, c) = smooth_maxwell(scene)?;
    let t0 = initial_temperature(scene);
    // Every drive that heats linearly (the core's declaration: none, white noise, the Gaussian
    // and Langevin thermostats, ...) has it exact.
    let heating = scene.model().heating()?;
    // The energy's decay rate `2 pi gamma C lambda_2` of the model's form (GRW (13): the
    // scattering form's `lambda_2 = (1 - alpha^2)/2`; the impact form's `(1 - alpha^2)/d`).
    let l2 = Form::of(scene).lambda2(scene.dimension(), alpha);
    Some(MaxwellTemperature {
        k: 2.0 * std::f64::consts::PI * gamma * c * l2,
        ..MaxwellTemperature::new(t0, alpha, 0.0, gamma, c).with_heating(heating)
    })
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
pub fn hydro_models(scene: &Scene) -> Option<[crate::hydro::HydroModel; 2]> {
    if !scene.physics().species.is_empty() || !scene.translation_is_smooth() {
        return None; // a one-species solution
    }
    if scene.dimension() != 3 {
        return None; // BRS (21)-(22)'s coefficients are the spheres' integrals
    }
    use crate::hydro::{Closure, HydroModel};
    let k = scene.physics().kernel;
    if !k.kind().hard() {
        return None; // the closures' integrals are hard spheres'
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

/// The Boltzmann limit of `a2(t)` of the smooth one-species Maxwell gas
/// (`theory/src/maxwell_cumulant.rs`) under every drive that heats linearly: cooling, white
/// noise, the Gaussian thermostat (which leaves it as cooling has it) and the Langevin
/// thermostat, when the scene is one; not for MS's time-stepped scheme, whose collisions are
/// not the Maxwell process's.
pub fn maxwell_cumulant(scene: &Scene) -> Option<crate::maxwell_cumulant::MaxwellCumulant> {
    use crate::maxwell_cumulant::{MaxwellCumulant, moment_ratio};
    let (alpha, gamma, c) = smooth_maxwell(scene)?;
    if !holds::Schemes::Boltzmann.holds(scene.physics().scheme.kind()) {
        return None;
    }
    let heating = scene.model().heating()?;
    let d = scene.dimension();
    let r0 = moment_ratio(&initial_sampler(scene), d);
    let t0 = initial_temperature(scene);
    let coefficients = Form::of(scene).coefficients(d, alpha);
    MaxwellCumulant::heated(d, coefficients, (gamma, c), (t0, r0), heating)
}
