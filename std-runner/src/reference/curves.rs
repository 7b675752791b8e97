//! Which reference curves apply to a scene, as extra columns beside the observables.

use crate::reference::exact::{HostMediumMaxwell, MaxwellTemperature};
use crate::run::columns::name;
use crate::run::{initial_sampler, initial_temperature};
use crate::scene::{BackgroundKernel, DriveChoice, DriveKind, KernelKind, Scene, SchemeChoice};

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

/// Per species `k`: the exact finite-n mean of `T_sk` (Maxwell kernel, no drive), the
/// Boltzmann limit of `E T_sk / E T_mix`, and the Maxwellian approximation of the cooling or
/// steady state's ratio.
const SPECIES_REFERENCES: [[&str; 3]; gdsmc_core::mixture::MAX_SPECIES] = [
    ["T_s0_mean_n", "T_s0_ratio_limit", "T_s0_ratio_MA"],
    ["T_s1_mean_n", "T_s1_ratio_limit", "T_s1_ratio_MA"],
    ["T_s2_mean_n", "T_s2_ratio_limit", "T_s2_ratio_MA"],
    ["T_s3_mean_n", "T_s3_ratio_limit", "T_s3_ratio_MA"],
];

/// The Maxwellian approximation of a mixture scene: its mole fractions, masses, the kernel
/// strength `kappa_st = 4 pi gamma C ((d_s + d_t)/2)^2` and the restitution of every pair
/// type, the kernel exponent, and each species' white noise.
fn approximation(scene: &Scene) -> Option<crate::reference::mixture::MaxwellianApproximation> {
    let ph = &scene.physics();
    // Garzó and Dufty's approximation and the exact moments are those of smooth spheres: a
    // rough mixture or a mixture of disks has none of them (yet).
    if ph.rotation.is_some() || ph.dimension != gdsmc_core::physics::DimensionChoice::Three {
        return None;
    }
    // Nor does it know a drive but white noise and the Gaussian thermostat (which scales every
    // species alike): a host medium, the constant force or a Langevin bath move each
    // species' temperature.
    if !matches!(
        ph.drive.kind(),
        DriveKind::None | DriveKind::WhiteNoise | DriveKind::Gaussian
    ) {
        return None;
    }
    let (_, lambda) = ph.kernel.rate_constants();
    let sp = scene.model().species()?;
    let (kappa, alpha) = crate::run::cooling::pair_kernels(ph, sp)?
        .into_iter()
        .unzip();
    let heated = matches!(ph.drive, DriveChoice::WhiteNoise(_));
    Some(crate::reference::mixture::MaxwellianApproximation {
        fractions: (0..sp.len()).map(|s| sp.fraction(s)).collect(),
        masses: ph.species.iter().map(|s| s.mass).collect(),
        kappa,
        alpha,
        lambda,
        beta: ph
            .species
            .iter()
            .map(|s| if heated { s.beta } else { 0.0 })
            .collect(),
    })
}

/// Per species `k` of a rough mixture: the Maxwellian approximation of `theta_sk` in the
/// cooling or steady state (its `T_sk_ratio_MA` is [`SPECIES_REFERENCES`]'s).
const ROUGH_SPECIES_REFERENCES: [&str; gdsmc_core::mixture::MAX_SPECIES] =
    ["theta_s0_MA", "theta_s1_MA", "theta_s2_MA", "theta_s3_MA"];

/// The Maxwellian approximation of a rough mixture scene (`reference/rough_mixture.rs`),
/// from the validated model: mole fractions, masses, each pair's law (alpha, beta, the
/// partners' kappa) and cross section, the kernel, each species' white noise.
pub fn rough_mixture_approximation(
    scene: &Scene,
) -> Option<crate::reference::rough_mixture::RoughMixtureApproximation> {
    // The thermostat on translation alone moves the cooling state's theta, and a host medium
    // or the constant force every temperature: the approximation (noise and collisions) follows neither, so it
    // draws nothing there.
    if !matches!(
        scene.physics().drive.kind(),
        DriveKind::None | DriveKind::WhiteNoise
    ) {
        return None;
    }
    // The approximation takes each pair's constant alpha; under the impact-speed law alpha
    // follows each collision's impact speed, which it does not: no curve.
    scene.physics().restitution.constant()?;
    let model = scene.model();
    let (sp, laws, sections) = (
        model.species()?,
        model.rough_pair_laws()?,
        model.pair_cross_sections()?,
    );
    let (strength, lambda) = scene.physics().kernel.rate_constants();
    let ns = sp.len();
    let masses: Vec<f64> = (0..ns).map(|s| sp.mass(s)).collect();
    let inertia: Vec<f64> = (0..ns)
        .map(|s| laws[gdsmc_core::mixture::pair_index(ns, s, s)].inertia().0)
        .collect();
    let noises = model.rough_noises();
    let heat = |f: &dyn Fn(&gdsmc_core::rough::RoughNoise, usize) -> f64| -> Vec<f64> {
        (0..ns)
            .map(|s| noises.map_or(0.0, |n| f(&n[s], s)))
            .collect()
    };
    Some(crate::reference::rough_mixture::RoughMixtureApproximation {
        d: scene.dimension(),
        fractions: (0..ns).map(|s| sp.fraction(s)).collect(),
        heating: heat(&|n, s| masses[s] * n.heating_tr()),
        heating_rot: heat(&|n, s| inertia[s] * masses[s] * n.rim_rate()),
        masses,
        inertia,
        strength: sections
            .iter()
            .map(|f| 4.0 * std::f64::consts::PI * strength * f)
            .collect(),
        alpha: laws.iter().map(|l| l.alpha()).collect(),
        beta: laws.iter().map(|l| l.beta()).collect(),
        lambda,
    })
}

/// A rough mixture's curves: each species' `T_sk_ratio_MA` and `theta_sk_MA` of the cooling
/// or steady state.
fn rough_mixture_curves(scene: &Scene) -> Vec<ReferenceCurve> {
    let Some(ma) = rough_mixture_approximation(scene) else {
        return Vec::new();
    };
    let src =
        "Maxwellian approximation of the cooling (or steady) state (Santos, Kremer and Garzó 2010)";
    let (cols, rough) = (
        crate::run::columns::SPECIES_COLUMNS,
        crate::run::columns::ROUGH_SPECIES_COLUMNS,
    );
    let Some((ratios, theta)) = ma.steady() else {
        eprintln!("{src}: not converged");
        return Vec::new();
    };
    let mut out = Vec::new();
    for s in 0..ratios.len() {
        let (r, th) = (ratios[s], theta[s]);
        out.push(ReferenceCurve {
            name: SPECIES_REFERENCES[s][2],
            of: cols[s][1],
            source: src,
            kind: Kind::Approximation,
            curve: Box::new(move |_| r),
        });
        out.push(ReferenceCurve {
            name: ROUGH_SPECIES_REFERENCES[s],
            of: rough[s][1],
            source: src,
            kind: Kind::Approximation,
            curve: Box::new(move |_| th),
        });
    }
    out
}

/// The reference curves of a mixture scene.
fn mixture_curves(scene: &Scene) -> Vec<ReferenceCurve> {
    use crate::reference::mixture::MaxwellMixture;
    if scene.physics().rotation.is_some() {
        return rough_mixture_curves(scene);
    }
    let mut out = Vec::new();
    let Some(ma) = approximation(scene) else {
        return out;
    };
    let ph = &scene.physics();
    let species = ph.species.len();
    let Some(approx) = ma.steady_ratios() else {
        eprintln!("Garzó and Dufty's Maxwellian approximation: not converged");
        return out;
    };
    let cols = crate::run::columns::SPECIES_COLUMNS;
    for s in 0..species {
        let r = approx[s];
        out.push(ReferenceCurve {
            name: SPECIES_REFERENCES[s][2],
            of: cols[s][1],
            source: "Garzó and Dufty 1999, Maxwellian approximation of the cooling (or steady) state",
            kind: Kind::Approximation,
            curve: Box::new(move |_| r),
        });
    }
    // The exact moments know no thermostat.
    if ma.lambda == 0.0 && matches!(ph.drive, DriveChoice::None | DriveChoice::WhiteNoise(_)) {
        let fractions = ma.fractions.clone();
        let exact = std::sync::Arc::new(MaxwellMixture {
            counts: ph.species.iter().map(|s| s.count).collect(),
            masses: ma.masses,
            kappa: ma.kappa,
            alpha: ma.alpha,
            temperatures: ph.species.iter().map(|s| s.temperature).collect(),
            beta: ma.beta.clone(),
        });
        // The exact mean at this n of the scheme run: the splittings' own recursions.
        let split = match ph.scheme {
            SchemeChoice::Euler(dt) => Some((dt, false)),
            SchemeChoice::Strang(dt) => Some((dt, true)),
            _ => None,
        };
        let at_n = move |e: &MaxwellMixture, t: f64| match split {
            Some((dt, strang)) => e.splitting_temperatures_at(t, dt, strang),
            None => e.temperatures_at(t, false),
        };
        for s in 0..species {
            let e = exact.clone();
            out.push(ReferenceCurve {
                name: SPECIES_REFERENCES[s][0],
                of: cols[s][0],
                source: "exact ensemble mean at this n (closed second moments of the Maxwell mixture)",
                kind: Kind::MeanAtN,
                curve: Box::new(move |t| at_n(&e, t)[s]),
            });
            let (e, x) = (exact.clone(), fractions.clone());
            out.push(ReferenceCurve {
                name: SPECIES_REFERENCES[s][1],
                of: cols[s][1],
                source: "Boltzmann limit of the exact moments, E T_s / E T_mix",
                kind: Kind::Limit,
                curve: Box::new(move |t| {
                    let ts = e.temperatures_at(t, true);
                    let mix: f64 = ts.iter().zip(&x).map(|(a, b)| a * b).sum();
                    ts[s] / mix
                }),
            });
        }
        let (e, x) = (exact, fractions);
        out.push(ReferenceCurve {
            name: "T_mix_mean_n",
            of: crate::run::columns::MIXTURE_TEMPERATURE,
            source: "exact ensemble mean at this n (closed second moments of the Maxwell mixture)",
            kind: Kind::MeanAtN,
            curve: Box::new(move |t| {
                let ts = at_n(&e, t);
                ts.iter().zip(&x).map(|(a, b)| a * b).sum()
            }),
        });
    }
    out
}

/// The Maxwellian approximation of a rough gas (`reference/rough.rs`), when the scene is one.
pub fn rough_approximation(scene: &Scene) -> Option<crate::reference::rough::RoughApproximation> {
    let r = scene.physics().rotation?;
    let alpha = scene.physics().restitution.constant()?;
    let (strength, lambda) = scene.physics().kernel.rate_constants();
    // The constant force's work depends on `E|v - V|` (MS (14)), which the approximation
    // does not follow, nor does it a host medium's encounters: no curve (they heat otherwise
    // than linearly).
    // A drive that heats the translation linearly (the core's declaration, `Heating`) is
    // `dT/dt = a + b T` in the approximation's equations: white noise `2 beta`, a thermostat
    // `2 zeta T`, a Langevin bath both.
    let h = scene.model().heating()?;
    let (beta, zeta) = (h.a / 2.0, h.b / 2.0);
    let mut ma = crate::reference::rough::RoughApproximation::in_dimension(
        scene.dimension(),
        alpha,
        r.beta,
        r.kappa,
        strength,
        lambda,
        [beta, r.noise],
    );
    ma.thermostat = zeta;
    Some(ma)
}

/// A rough gas's Maxwellian-approximation curves: `T_bulk_MA` (the translational temperature),
/// `T_rot_MA` and `theta_MA`, solved from the scene's start.
fn rough_curves(scene: &Scene) -> Vec<ReferenceCurve> {
    let (Some(ma), Some(r)) = (rough_approximation(scene), scene.physics().rotation) else {
        return Vec::new();
    };
    let t_end = scene.times().last().copied().unwrap_or(1.0);
    let src = "Maxwellian approximation (Huthmann and Zippelius 1997)";
    match crate::reference::rough::RoughTrajectory::new(
        &ma,
        [initial_temperature(scene), r.temperature],
        t_end,
    ) {
        Ok(tr) => {
            let tr = std::sync::Arc::new(tr);
            let (a, b, c) = (tr.clone(), tr.clone(), tr);
            vec![
                ReferenceCurve {
                    name: "T_bulk_MA",
                    of: name::T_BULK,
                    source: src,
                    kind: Kind::Approximation,
                    curve: Box::new(move |t| a.at(t).0),
                },
                ReferenceCurve {
                    name: "T_rot_MA",
                    of: name::T_ROT,
                    source: src,
                    kind: Kind::Approximation,
                    curve: Box::new(move |t| b.at(t).1),
                },
                ReferenceCurve {
                    name: "theta_MA",
                    of: name::THETA,
                    source: src,
                    kind: Kind::Approximation,
                    curve: Box::new(move |t| {
                        let (x, y) = c.at(t);
                        y / x
                    }),
                },
            ]
        }
        Err(e) => {
            eprintln!("{src}: not integrated ({e})");
            Vec::new()
        }
    }
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
