//! A mixture in a host medium (BRS's background, each species meeting it with its own mass in
//! BRS (3)'s ratio, `HostMediumParams::for_grain`).
//!
//! Elastic grains in an elastic background have an exact stationary state: every grain
//! Maxwellian at the background's temperature `T^B` about its drift, independently (the
//! background's encounters keep that law by detailed balance, the grains' elastic collisions
//! keep the product of Maxwellians of one temperature). Each species' temperature about the
//! sample's flow velocity `U` then has `E[T_s] = (1 - m_s/M) T^B` (`M` the total mass: `U` is
//! the mass-weighted mean of the grains themselves), and a rough species' rotational
//! temperature `E[T_rot,s] = T^B` (perfectly rough grains hand the translation's temperature
//! to the rotation). Checked from a start at `T = 1` far from `T^B = 2`, at 99.9% jointly
//! (Bonferroni over the checks); a grain of the wrong mass would settle at `T^B m_s / m`, and
//! the same sample must refuse `E[T_s] = T^B` for the heavy species, so the check can fail.

use gdsmc_core::engine::EventLoop;
use gdsmc_core::math::PI;
use gdsmc_core::particles::{Particle, Particles, Spin};
use gdsmc_core::physics::{
    BackgroundKernel, DimensionChoice, DriveChoice, KernelChoice, Physics, RestitutionLaw,
    RotationChoice, SchemeChoice, SpeciesChoice,
};
use gdsmc_core::rng::Streams;
use gdsmc_stats::Sample;

const TB: f64 = 2.0;
const MASSES: [f64; 2] = [1.0, 4.0];

/// Four grains of mass 1 and four of mass 4, elastic, hard spheres, in a background of
/// `kernel` at `T^B = 2` drifting along x; rough (perfectly, beta = 1) when `rough`.
fn in_bath(kernel: BackgroundKernel, rough: bool, dimension: DimensionChoice) -> Physics {
    let mut ph = Physics::new(
        8,
        KernelChoice::hard_spheres(1.0, 0.25 / PI),
        RestitutionLaw::Constant(1.0),
        DriveChoice::HostMedium {
            kernel,
            c1: 0.25 / PI,
            density: 1.0,
            mass: 1.0,
            temperature: TB,
            drift: [0.3, 0.0, 0.0],
        },
        SchemeChoice::NoSplitting,
    );
    ph.species.extend([
        SpeciesChoice::new(4, MASSES[0], 1.0),
        SpeciesChoice::new(4, MASSES[1], 1.0),
    ]);
    if rough {
        ph.rotation = Some(RotationChoice {
            beta: 1.0,
            kappa: 0.4,
            temperature: 1.0,
            noise: 0.0,
        });
    }
    ph.dimension = dimension;
    ph
}

/// `ensembles` systems of `ph` run to t = 40; the checks of the module docs.
fn check_bath_equilibrium(ph: Physics, ensembles: usize, seed: u64) {
    let rough = ph.rotation.is_some();
    let model = ph.validate().unwrap();
    let total_mass = 4.0 * (MASSES[0] + MASSES[1]);
    let (mut tr, mut rot) = ([Vec::new(), Vec::new()], [Vec::new(), Vec::new()]);
    let mut streams = Streams::new(seed);
    let mut background = 0;
    for _ in 0..ensembles {
        let mut rng = streams.next().unwrap();
        let mut buf = vec![Particle::default(); 8];
        let mut spins = vec![Spin::default(); 8];
        let mut p = if rough {
            Particles::with_spins(&mut buf, &mut spins).unwrap()
        } else {
            Particles::new(&mut buf).unwrap()
        };
        let (mut e, _) = model.launch(&mut p, 0.0, &mut rng).unwrap();
        e.advance_to(&mut p, 40.0, &mut rng).unwrap();
        background += e.counts().background;
        let m = e.species(&p).unwrap();
        for s in 0..2 {
            tr[s].push(m.temperature(s));
            if rough {
                rot[s].push(m.rotational_temperature(s).unwrap());
            }
        }
    }
    assert!(
        background as f64 / (ensembles * 8) as f64 > 20.0,
        "{background} background events"
    );
    let checks = if rough { 4 } else { 2 };
    for s in 0..2 {
        let sample = Sample::of(&tr[s]);
        let (m, h) = (sample.mean, sample.joint_ci(checks));
        let exact = (1.0 - MASSES[s] / total_mass) * TB;
        assert!(
            (m - exact).abs() <= h,
            "species {s}: E[T_s] = {m} +- {h}, exact {exact}"
        );
        if rough {
            let sample = Sample::of(&rot[s]);
            let (m, h) = (sample.mean, sample.joint_ci(checks));
            assert!(
                (m - TB).abs() <= h,
                "species {s}: E[T_rot,s] = {m} +- {h}, exact {TB}"
            );
        }
    }
    let heavy = Sample::of(&tr[1]);
    assert!(
        (heavy.mean - TB).abs() > heavy.ci(),
        "the test cannot tell (1 - m/M) T^B from T^B: {} +- {}",
        heavy.mean,
        heavy.ci()
    );
}

#[test]
fn an_elastic_mixture_takes_the_background_temperature_species_by_species() {
    for (k, kernel) in [BackgroundKernel::Maxwell, BackgroundKernel::HardSpheres]
        .into_iter()
        .enumerate()
    {
        check_bath_equilibrium(
            in_bath(kernel, false, DimensionChoice::Three),
            4000,
            41 + k as u64,
        );
    }
    check_bath_equilibrium(
        in_bath(BackgroundKernel::Maxwell, false, DimensionChoice::Two),
        4000,
        43,
    );
}

#[test]
fn an_elastic_perfectly_rough_mixture_takes_it_in_rotation_too() {
    check_bath_equilibrium(
        in_bath(BackgroundKernel::Maxwell, true, DimensionChoice::Three),
        4000,
        44,
    );
    check_bath_equilibrium(
        in_bath(BackgroundKernel::HardSpheres, true, DimensionChoice::Two),
        4000,
        45,
    );
}
