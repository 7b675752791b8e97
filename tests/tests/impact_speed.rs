//! The impact-speed law BRS (9)-(10) in the engine: the exact initial cooling rate `dT/dt` at
//! `t = 0` from a Maxwellian (`gdsmc_theory::impact_speed`, derived over the impact parameter)
//! against the engine's, for smooth hard spheres, hard disks and pseudo-Maxwell disks, and for
//! rough hard disks at beta = -0.999 beside the smooth hard disks they become at beta = -1.
//!
//! Each ensemble's rate is measured from its own start (`T(0)` of its draw, so the start's
//! spread cancels) by Richardson's difference `(4 (T(h) - T(0)) - (T(2h) - T(0))) / (2h)`,
//! whose O(h) bias cancels; `h` is 1% of a mean free time, so the O(h^2) rest is ~1e-4 of the
//! rate, far below the intervals (0.5-1% of the rate). The four cases are judged together at
//! 99.9% (Bonferroni over 4), and each shows its power: the rate the printed BRS (10) (`|g .
//! w_hat|`, the law seeing `min(s, 1 - s)`) would give lies at least three joint half-widths
//! away, so the defect fixed here would be caught with certainty (its mean would have to err by
//! two half-widths, over six standard errors). With the absolute value put back in
//! `ImpactSpeed::normal_speed`, the three smooth cases fail (checked when it was fixed).

use gdsmc_core::particles::{Particle, Particles, Spin};
use gdsmc_core::physics::{
    DimensionChoice, DriveChoice, KernelChoice, Physics, RestitutionLaw, RotationChoice,
    SchemeChoice,
};
use gdsmc_core::rng::Streams;
use gdsmc_stats::Sample;
use gdsmc_theory::impact_speed::{Impacts, InitialCooling};

/// `C` with `4 pi gamma C = 1` at `gamma = 1`.
const C: f64 = 1.0 / (4.0 * std::f64::consts::PI);
const BETA0: f64 = 0.3;
const DELTA: f64 = 1.0;
/// Cases judged together.
const CASES: usize = 4;

/// The engine's initial cooling rates of `ph`, one per ensemble (module docs).
fn measured(ph: &Physics, h: f64, ensembles: usize, seed: u64) -> Sample {
    let model = ph.validate().expect("a valid physics");
    let mut streams = Streams::new(seed);
    let mut rates = Vec::with_capacity(ensembles);
    let mut buf = vec![Particle::default(); ph.n];
    let mut spins = vec![Spin::default(); ph.n];
    for _ in 0..ensembles {
        let mut rng = streams.next().expect("streams do not run out");
        let mut p = if model.rotates() {
            Particles::with_spins(&mut buf, &mut spins).expect("equal lengths")
        } else {
            Particles::new(&mut buf).expect("n >= 2")
        };
        let (mut e, o0) = model.launch(&mut p, 0.0, &mut rng).expect("starts");
        let t1 = e.advance_to(&mut p, h, &mut rng).expect("runs").t_raw;
        let t2 = e.advance_to(&mut p, 2.0 * h, &mut rng).expect("runs").t_raw;
        rates.push((4.0 * (t1 - o0.t_raw) - (t2 - o0.t_raw)) / (2.0 * h));
    }
    Sample::of(&rates)
}

fn physics(n: usize, kernel: KernelChoice, dim: DimensionChoice) -> Physics {
    let mut ph = Physics::new(
        n,
        kernel,
        RestitutionLaw::ImpactSpeed {
            beta0: BETA0,
            delta: DELTA,
        },
        DriveChoice::None,
        SchemeChoice::NoSplitting,
    );
    ph.dimension = dim;
    ph
}

fn reference(n: usize, d: usize, lambda: f64, impacts: Impacts) -> InitialCooling {
    InitialCooling {
        n,
        d,
        k: 1.0,
        lambda,
        impacts,
        beta0: BETA0,
        delta: DELTA,
        t0: 1.0,
        rough: None,
    }
}

/// Checks one case against its exact rate (a miss is added to `misses`, so that every case is
/// reported), shows the power against BRS (10) as printed, and returns the sample.
fn check(
    misses: &mut Vec<String>,
    what: &str,
    ph: &Physics,
    exact: &InitialCooling,
    ensembles: usize,
    seed: u64,
) -> Sample {
    let want = exact.rate();
    // h: 5% of a mean free time 1 / (K <|g|^lambda>) (<|g|> ~ 2.3 at T0 = 1).
    let h = 0.05 / if exact.lambda > 0.0 { 2.3 } else { 1.0 };
    let s = measured(ph, h, ensembles, seed);
    let ci = s.joint_ci(CASES);
    if !s.admits(want, CASES) {
        misses.push(format!(
            "{what}: dT/dt(0) = {} +- {ci}, exact {want}",
            s.mean
        ));
    }
    if exact.rough.is_none() {
        let printed = exact.rate_seeing(|x| x.min(1.0 - x));
        assert!(
            (printed - want).abs() >= 3.0 * ci,
            "{what}: no power: BRS (10) as printed gives {printed}, exact {want}, +- {ci}"
        );
    }
    s
}

#[test]
fn the_initial_cooling_rate_under_the_impact_speed_law_is_exact() {
    let hs = KernelChoice::hard_spheres(1.0, C);
    let maxwell = KernelChoice::maxwell(1.0, C);
    let n = 2000;
    let (three, two) = (DimensionChoice::Three, DimensionChoice::Two);
    let mut misses = Vec::new();
    let smooth_cases = [
        ("hard spheres", hs, three, 1.0, Impacts::Spheres),
        ("hard disks", hs, two, 1.0, Impacts::HardDisks),
        ("Maxwell disks", maxwell, two, 0.0, Impacts::IsotropicDisks),
    ];
    let samples: Vec<Sample> = (0u64..)
        .zip(smooth_cases)
        .map(|(k, (what, kernel, dim, lambda, impacts))| {
            let exact = reference(n, dim.d(), lambda, impacts);
            check(
                &mut misses,
                what,
                &physics(n, kernel, dim),
                &exact,
                8000,
                5101 + k,
            )
        })
        .collect();
    let smooth = samples[1];
    // Rough hard disks a hair from smooth (the rough map, which draws the impact itself).
    let (beta, kappa, t_rot) = (-0.999, 0.5, 1.0);
    let mut rough_ph = physics(n, hs, two);
    rough_ph.rotation = Some(RotationChoice {
        beta,
        kappa,
        temperature: t_rot,
        noise: 0.0,
    });
    let mut rough_ref = reference(n, 2, 1.0, Impacts::HardDisks);
    rough_ref.rough = Some((beta, kappa, t_rot));
    let rough = check(
        &mut misses,
        "rough hard disks",
        &rough_ph,
        &rough_ref,
        8000,
        5104,
    );
    // Continuity at beta = -1: the two maps' rates differ by less than a tenth of the
    // difference's standard error in theory, and must agree in the engine.
    let se = rough.se().hypot(smooth.se());
    let gap = rough_ref.rate() - reference(n, 2, 1.0, Impacts::HardDisks).rate();
    assert!(
        gap.abs() < 0.1 * se,
        "beta = -0.999 is not near smooth: {gap} vs {se}"
    );
    let z = rough.z_from(&smooth);
    if z.abs() > gdsmc_stats::joint(CASES + 1, gdsmc_stats::dof(8000)) {
        misses.push(format!(
            "rough at beta = -0.999 {} against smooth {}: z = {z}",
            rough.mean, smooth.mean
        ));
    }
    assert!(misses.is_empty(), "{}", misses.join("\n"));
}
