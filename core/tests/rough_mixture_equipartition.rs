//! The elastic perfectly rough mixture keeps its energy to rounding and relaxes to the
//! equipartition of its finite system over every species' translational and rotational
//! degrees of freedom, under the exact and the time-stepped scheme (99.9% intervals, 3.2
//! standard errors; the same sample must refuse the naive equipartition, so the check can
//! fail), spheres and disks.

use crate::common::mean_ci;
use gdsmc_core::engine::EventLoop;
use gdsmc_core::math::PI;
use gdsmc_core::particles::{Particle, Particles, Spin};
use gdsmc_core::physics::{
    DimensionChoice, DriveChoice, KernelChoice, Physics, RestitutionLaw, RotationChoice,
    SchemeChoice, SpeciesChoice,
};
use gdsmc_core::rng::Streams;

/// The elastic perfectly rough mixture of `dimension` through `Physics`: species of masses 1
/// and 4 (four particles each) and inertia 0.4 and 0.2 (the second species' own), all energy
/// in translation at the start.
fn elastic_rough_mixture(dimension: DimensionChoice) -> Physics {
    let mut ph = Physics::new(
        8,
        KernelChoice::hard_spheres(1.0, c1()),
        RestitutionLaw::Constant(1.0),
        DriveChoice::None,
        SchemeChoice::NoSplitting,
    );
    let light = SpeciesChoice::new(4, 1.0, 1.0);
    let heavy = SpeciesChoice {
        inertia: Some(0.2),
        ..SpeciesChoice::new(4, 4.0, 1.0)
    };
    ph.species.extend([light, heavy]);
    ph.rotation = Some(RotationChoice {
        beta: 1.0,
        kappa: 0.4,
        temperature: 0.0,
        noise: 0.0,
    });
    ph.dimension = dimension;
    ph
}

pub(super) fn c1() -> f64 {
    0.25 / PI
}

/// The elastic perfectly rough mixture keeps `sum m (|v|^2 + kappa |w|^2)` to rounding, and
/// its stationary law is uniform on that energy shell with the total momentum fixed. In the
/// mass-weighted coordinates `sqrt(m) v`, `sqrt(m kappa) w` the momentum fixes one direction
/// per velocity axis, `(sqrt(m_i))_i / sqrt(M)`, `M = sum m_i`; every other direction carries
/// the same mean energy `T`. So `E[m_i |v_i - U|^2] = d (1 - m_i/M) T` and
/// `E[m_i kappa_i |w_i|^2] = d_rot T`: species `s`'s `E[T_s] = (1 - m_s/M) E[T_rot,s]`. At
/// masses 1 and 4 (`M = 20`) the factors are 0.95 and 0.8; the same sample must refuse
/// `E[T_s] = E[T_rot,s]` for the heavy species.
fn check_mixture_equipartition(
    dimension: DimensionChoice,
    scheme: SchemeChoice,
    ensembles: usize,
    seed: u64,
) {
    let model = Physics {
        scheme,
        ..elastic_rough_mixture(dimension)
    }
    .validate()
    .unwrap();
    let (masses, kappa) = ([1.0, 4.0], [0.4, 0.2]);
    let total_mass = 4.0 * (masses[0] + masses[1]);
    let energy = |p: &Particles<'_>| {
        (0..8)
            .map(|i| {
                let s = i / 4;
                masses[s] * (p.velocity(i).norm2() + kappa[s] * p.spin(i).norm2())
            })
            .sum::<f64>()
    };
    let mut finite = [Vec::new(), Vec::new()];
    let mut naive = Vec::new();
    let mut streams = Streams::new(seed);
    let mut collisions = 0;
    for _ in 0..ensembles {
        let mut rng = streams.next().unwrap();
        let mut buf = vec![Particle::default(); 8];
        let mut spins = vec![Spin::default(); 8];
        let mut p = Particles::with_spins(&mut buf, &mut spins).unwrap();
        let (mut e, _) = model.launch(&mut p, 0.0, &mut rng).unwrap();
        let e0 = energy(&p);
        e.advance_to(&mut p, 60.0, &mut rng).unwrap();
        let e1 = energy(&p);
        assert!((e1 - e0).abs() <= 1e-12 * e0, "energy {e0} -> {e1}");
        collisions += e.counts().collisions;
        let m = e.species(&p).unwrap();
        for s in 0..2 {
            let t_rot = m.rotational_temperature(s).unwrap();
            let factor = 1.0 - masses[s] / total_mass;
            finite[s].push(m.temperature(s) - factor * t_rot);
            if s == 1 {
                naive.push(m.temperature(s) - t_rot);
            }
        }
    }
    let per = collisions as f64 / (ensembles * 8) as f64;
    assert!(per > 20.0, "{per} collisions per particle");
    // Two species checked together (Bonferroni, `joint(2, ..)`).
    for (s, d) in finite.iter().enumerate() {
        let sample = gdsmc_stats::Sample::of(d);
        let (m, h) = (sample.mean, sample.joint_ci(2));
        assert!(
            m.abs() <= h,
            "species {s}: E[T_s - (1 - m_s/M) T_rot,s] = {m} +- {h}"
        );
    }
    let (m, h) = mean_ci(&naive);
    assert!(m.abs() > h, "the test cannot tell 0.8 from 1: {m} +- {h}");
}

#[test]
fn the_elastic_perfectly_rough_mixture_relaxes_to_equipartition_of_its_finite_system() {
    check_mixture_equipartition(DimensionChoice::Three, SchemeChoice::NoSplitting, 6000, 31);
}

/// The same under the time-stepped scheme (`MixtureTimeStepped`): each candidate's collision
/// keeps the energy shell's uniform law, so a whole number of them per step does too; the
/// step adds no error to an elastic gas with no drive.
#[test]
#[ignore = "long suite: cargo test --workspace --release -- --include-ignored (README, CI)"]
fn the_elastic_perfectly_rough_mixture_relaxes_to_equipartition_when_time_stepped() {
    let stepped = SchemeChoice::TimeStepped(0.05);
    check_mixture_equipartition(DimensionChoice::Three, stepped, 6000, 33);
    check_mixture_equipartition(DimensionChoice::Two, stepped, 6000, 34);
}

#[test]
fn elastic_perfectly_rough_disk_mixtures_relax_to_equipartition_too() {
    check_mixture_equipartition(DimensionChoice::Two, SchemeChoice::NoSplitting, 6000, 32);
}
