//! A mixture's reference curves: per species the exact finite-n means of the Maxwell mixture,
//! the Boltzmann limit of the temperature ratios, and the Maxwellian approximations of the
//! smooth and the rough mixture.

use super::{Kind, ReferenceCurve};
use crate::mixture::MaxwellMixture;
use gdsmc_scene::{DriveChoice, Scene, SchemeChoice};
use std::sync::Arc;

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
fn approximation(scene: &Scene) -> Option<crate::mixture::MaxwellianApproximation> {
    let ph = &scene.physics();
    // Garzó and Dufty's approximation and the exact moments are those of smooth spheres: a
    // rough mixture or a mixture of disks has none of them (yet).
    if ph.rotation.is_some() || ph.dimension != gdsmc_core::physics::DimensionChoice::Three {
        return None;
    }
    // Nor does it know a drive but white noise and one that only rescales (the registry's
    // declarations say which of them each reference takes: a host medium, the constant force
    // or a Langevin bath move each species' temperature their own way).
    let (_, lambda) = ph.kernel.power_law()?;
    let sp = scene.model().species()?;
    let (kappa, alpha) = crate::pairs::pair_kernels(ph, sp)?.into_iter().unzip();
    let heated = matches!(ph.drive, DriveChoice::WhiteNoise(_));
    Some(crate::mixture::MaxwellianApproximation {
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

/// The Maxwellian approximation of a rough mixture scene (`theory/src/rough_mixture.rs`),
/// from the validated model: mole fractions, masses, each pair's law (alpha, beta, the
/// partners' kappa) and cross section, the kernel, each species' white noise.
pub fn rough_mixture_approximation(
    scene: &Scene,
) -> Option<crate::rough_mixture::RoughMixtureApproximation> {
    // The approximation follows noise and collisions alone: the registry declares it for no
    // drive and white noise (a thermostat on translation alone moves the cooling state's theta,
    // and a host medium or the constant force every temperature).
    // The approximation takes each pair's constant alpha; under the impact-speed law alpha
    // follows each collision's impact speed, which it does not: no curve.
    scene.physics().restitution.constant()?;
    let model = scene.model();
    let (sp, laws, sections) = (
        model.species()?,
        model.rough_pair_laws()?,
        model.pair_cross_sections()?,
    );
    let (strength, lambda) = scene.physics().kernel.power_law()?;
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
    Some(crate::rough_mixture::RoughMixtureApproximation {
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
pub(super) fn rough_mixture_curves(scene: &Scene) -> Vec<ReferenceCurve> {
    let Some(ma) = rough_mixture_approximation(scene) else {
        return Vec::new();
    };
    let src =
        "Maxwellian approximation of the cooling (or steady) state (Santos, Kremer and Garzó 2010)";
    let (cols, rough) = (
        crate::columns::SPECIES_COLUMNS,
        crate::columns::ROUGH_SPECIES_COLUMNS,
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

/// Garzó and Dufty 1999's Maxwellian approximation of each species' `T_sk / T_mix` in the
/// cooling (or steady) state (`T_sk_ratio_MA`).
pub(super) fn garzo_dufty_curves(scene: &Scene) -> Vec<ReferenceCurve> {
    let Some(ma) = approximation(scene) else {
        return Vec::new();
    };
    let Some(approx) = ma.steady_ratios() else {
        eprintln!("Garzó and Dufty's Maxwellian approximation: not converged");
        return Vec::new();
    };
    let cols = crate::columns::SPECIES_COLUMNS;
    (0..scene.physics().species.len())
        .map(|s| {
            let r = approx[s];
            ReferenceCurve {
                name: SPECIES_REFERENCES[s][2],
                of: cols[s][1],
                source: "Garzó and Dufty 1999, Maxwellian approximation of the cooling (or steady) state",
                kind: Kind::Approximation,
                curve: Box::new(move |_| r),
            }
        })
        .collect()
}

/// The closed second moments of the Maxwell mixture (`theory/src/mixture`) and its mole
/// fractions, for a scene the approximation's reading of holds for.
fn maxwell_mixture(scene: &Scene) -> Option<(Arc<MaxwellMixture>, Vec<f64>)> {
    let ma = approximation(scene)?;
    let ph = &scene.physics();
    let fractions = ma.fractions.clone();
    let exact = Arc::new(MaxwellMixture {
        counts: ph.species.iter().map(|s| s.count).collect(),
        masses: ma.masses,
        kappa: ma.kappa,
        alpha: ma.alpha,
        temperatures: ph.species.iter().map(|s| s.temperature).collect(),
        beta: ma.beta,
        momentum: ph.momentum,
    });
    Some((exact, fractions))
}

/// The exact ensemble means at this n of each species' `T_sk` and of `T_mix` (the no-splitting
/// process's, or the splittings' own recursions).
pub(super) fn maxwell_mixture_means(scene: &Scene) -> Vec<ReferenceCurve> {
    let Some((exact, fractions)) = maxwell_mixture(scene) else {
        return Vec::new();
    };
    let split = match scene.physics().scheme {
        SchemeChoice::Euler(dt) => Some((dt, false)),
        SchemeChoice::Strang(dt) => Some((dt, true)),
        SchemeChoice::NoSplitting => None,
        // MS's collisions are not the Maxwell process's; the weighted scheme runs no mixture.
        SchemeChoice::TimeStepped(_) | SchemeChoice::Weighted(_) => return Vec::new(),
    };
    let at_n = move |e: &MaxwellMixture, t: f64| match split {
        Some((dt, strang)) => e.splitting_temperatures_at(t, dt, strang),
        None => e.temperatures_at(t, false),
    };
    let cols = crate::columns::SPECIES_COLUMNS;
    let source = "exact ensemble mean at this n (closed second moments of the Maxwell mixture)";
    let mut out: Vec<ReferenceCurve> = (0..scene.physics().species.len())
        .map(|s| {
            let e = exact.clone();
            ReferenceCurve {
                name: SPECIES_REFERENCES[s][0],
                of: cols[s][0],
                source,
                kind: Kind::MeanAtN,
                curve: Box::new(move |t| at_n(&e, t)[s]),
            }
        })
        .collect();
    out.push(ReferenceCurve {
        name: "T_mix_mean_n",
        of: crate::columns::MIXTURE_TEMPERATURE,
        source,
        kind: Kind::MeanAtN,
        curve: Box::new(move |t| {
            let ts = at_n(&exact, t);
            ts.iter().zip(&fractions).map(|(a, b)| a * b).sum()
        }),
    });
    out
}

/// The Boltzmann limit of each species' `E T_sk / E T_mix` from the exact moments.
pub(super) fn maxwell_mixture_limits(scene: &Scene) -> Vec<ReferenceCurve> {
    let Some((exact, fractions)) = maxwell_mixture(scene) else {
        return Vec::new();
    };
    let cols = crate::columns::SPECIES_COLUMNS;
    (0..scene.physics().species.len())
        .map(|s| {
            let (e, x) = (exact.clone(), fractions.clone());
            ReferenceCurve {
                name: SPECIES_REFERENCES[s][1],
                of: cols[s][1],
                source: "Boltzmann limit of the exact moments, E T_s / E T_mix",
                kind: Kind::Limit,
                curve: Box::new(move |t| {
                    let ts = e.temperatures_at(t, true);
                    let mix: f64 = ts.iter().zip(&x).map(|(a, b)| a * b).sum();
                    ts[s] / mix
                }),
            }
        })
        .collect()
}
