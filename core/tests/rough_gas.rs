//! The rough gas's event loop (the exact loop with the rough map, through `Physics`): the elastic
//! perfectly rough gas keeps its energy and relaxes to the equipartition of its finite system,
//! the smooth limit leaves every spin alone, and the spin buffer is required. Statistical
//! checks use fixed seeds and 99.9% intervals (3.2 standard errors).

use crate::common;

use common::check_finite_equipartition;
use gdsmc_core::engine::{EngineError, EventLoop};
use gdsmc_core::particles::{Particle, Particles, ParticlesError, Spin};
use gdsmc_core::physics::{
    Component, DriveChoice, KernelChoice, Physics, RestitutionLaw, RotationChoice, SchemeChoice,
};
use gdsmc_core::rng::Streams;

fn rough(n: usize, alpha: f64, rotation: RotationChoice, drive: DriveChoice) -> Physics {
    let mut ph = Physics::new(
        n,
        KernelChoice::hard_spheres(1.0, 0.25 / core::f64::consts::PI),
        RestitutionLaw::Constant(alpha),
        drive,
        SchemeChoice::NoSplitting,
    );
    ph.rotation = Some(rotation);
    ph
}

#[test]
fn a_rough_gas_needs_one_spin_per_particle() {
    let mut buf = [Particle::default(); 4];
    let mut spins = [Spin::default(); 3];
    assert_eq!(
        Particles::with_spins(&mut buf, &mut spins).unwrap_err(),
        ParticlesError::SpinCount
    );
    let model = rough(4, 0.9, RotationChoice::spheres(0.0), DriveChoice::None)
        .validate()
        .unwrap();
    let mut p = Particles::new(&mut buf).unwrap();
    let mut rng = Streams::new(1).next().unwrap();
    assert_eq!(
        model.launch(&mut p, 0.0, &mut rng).unwrap_err(),
        EngineError::Spins
    );
}

/// Alpha = beta = 1 keeps `sum |v|^2 + kappa |w|^2` to rounding at every collision, and the
/// stationary law is uniform on that energy shell with the total momentum fixed: `3(n - 1)`
/// translational and `3n` rotational degrees of freedom share the energy equally, so
/// `E[T_tr] = (n - 1)/n E[T_rot]` exactly (`T_tr` about the bulk velocity). At n = 8 that is
/// 0.875, far from 1: the test also checks that the same sample refuses `T_tr = T_rot`.
#[test]
fn the_elastic_perfectly_rough_gas_relaxes_to_equipartition_of_its_finite_system() {
    let n = 8;
    let rot = RotationChoice {
        beta: 1.0,
        kappa: 0.4,
        temperature: 0.0, // all the energy starts in translation
        noise: 0.0,
    };
    let model = rough(n, 1.0, rot, DriveChoice::None).validate().unwrap();
    check_finite_equipartition(&model, 20_000, 2024, 0.4, |_| {});
}

/// MS's time-stepped scheme collides rough particles at its own impact direction `s`
/// (`CollisionMap::collide_at_impact`): with alpha = beta = 1 each collision keeps the energy
/// and the momentum, and the collision step's kernel is the exact loop's (`Theta(u . s) (u . s)`
/// over uniform pairs), so the finite system's equipartition holds whatever the step (f = 0.1
/// here), spheres and disks.
#[test]
fn the_time_stepped_elastic_perfectly_rough_gas_relaxes_to_equipartition_too() {
    let n = 8;
    for (dimension, kappa) in [
        (gdsmc_core::physics::DimensionChoice::Three, 0.4),
        (gdsmc_core::physics::DimensionChoice::Two, 0.5),
    ] {
        let rot = RotationChoice {
            beta: 1.0,
            kappa,
            temperature: 0.0,
            noise: 0.0,
        };
        let mut ph = rough(n, 1.0, rot, DriveChoice::None);
        ph.scheme = SchemeChoice::TimeStepped(0.1);
        ph.dimension = dimension;
        let model = ph.validate().unwrap();
        check_finite_equipartition(&model, 8000, 2025, kappa, |_| {});
    }
}

/// Beta = -1 is the smooth gas: no collision touches a spin (the map returns them bit for bit)
/// and the translation cools as the smooth gas's does.
#[test]
fn the_smooth_limit_leaves_every_spin_alone() {
    let n = 200;
    let mut rot = RotationChoice::spheres(-1.0);
    rot.temperature = 3.0;
    let model = rough(n, 0.7, rot, DriveChoice::WhiteNoise(0.5))
        .validate()
        .unwrap();
    let mut rng = Streams::new(7).next().unwrap();
    let mut buf = vec![Particle::default(); n];
    let mut spins = vec![Spin::default(); n];
    let mut p = Particles::with_spins(&mut buf, &mut spins).unwrap();
    let (mut e, _) = model.launch(&mut p, 0.0, &mut rng).unwrap();
    let before: Vec<Spin> = p.spins().to_vec();
    e.advance_to(&mut p, 20.0, &mut rng).unwrap();
    let c = e.counts().collisions;
    assert!(c > 5 * n as u64, "{c} collisions");
    assert_eq!(p.spins(), &before[..]);
}

/// A rough gas cooled far enough to be stored rescaled (the one loop's velocity frame) still
/// reports `<|v|^6>`, summed from the physical velocities: it was NaN when the rough gas had a
/// loop of its own (the frame rebuilds `v6` only from a raw sum, not from central moments).
#[test]
fn a_rescaled_rough_gas_reports_its_sixth_moment() {
    let n = 64;
    let model = rough(n, 0.3, RotationChoice::spheres(0.0), DriveChoice::None)
        .validate()
        .unwrap();
    let mut rng = Streams::new(11).next().unwrap();
    let mut buf = vec![Particle::default(); n];
    let mut spins = vec![Spin::default(); n];
    let mut p = Particles::with_spins(&mut buf, &mut spins).unwrap();
    let (mut e, _) = model.launch(&mut p, 0.0, &mut rng).unwrap();
    let obs = e.advance_to(&mut p, 1e9, &mut rng).unwrap();
    assert!(e.counts().rescales > 0, "{:?}", e.counts());
    let frame = e.velocity_map();
    assert!(frame.offset != gdsmc_core::vec3::Vec3::ZERO, "{frame:?}");
    let direct = p
        .as_slice()
        .iter()
        .map(|q| frame.physical(q.velocity()).norm2().powi(3))
        .sum::<f64>()
        / n as f64;
    assert!(obs.v6.is_finite(), "{obs:?}");
    // The same sum in the same order: equal to the last bit.
    assert_eq!(obs.v6, direct);
    let r = e.rough(&p).unwrap();
    assert!(r.t_rot.is_finite() && r.t_rot > 0.0, "{r:?}");
}

/// A rough gas refuses what it cannot run, naming the parameter.
#[test]
fn rough_refusals_name_their_parameter() {
    let cases: [(Physics, &str); 5] = [
        (
            rough(4, 0.9, RotationChoice::spheres(1.5), DriveChoice::None),
            "tangential_restitution must lie in [-1, 1], got 1.5",
        ),
        (
            rough(
                4,
                0.9,
                RotationChoice {
                    kappa: 0.7,
                    ..RotationChoice::spheres(0.0)
                },
                DriveChoice::None,
            ),
            "inertia must lie in (0, 2/3], got 0.7",
        ),
        (
            rough(
                4,
                0.9,
                RotationChoice {
                    temperature: -1.0,
                    ..RotationChoice::spheres(0.0)
                },
                DriveChoice::None,
            ),
            "rotation_temperature must be >= 0, got -1",
        ),
        (
            rough(
                4,
                0.9,
                RotationChoice {
                    noise: -1.0,
                    ..RotationChoice::spheres(0.0)
                },
                DriveChoice::None,
            ),
            "rotation_noise must be >= 0, got -1",
        ),
        (
            rough(
                4,
                0.9,
                RotationChoice {
                    noise: 0.5,
                    ..RotationChoice::spheres(0.0)
                },
                DriveChoice::declared(gdsmc_core::physics::DriveKind::Gaussian, &[1.0]).unwrap(),
            ),
            "rotation_noise takes only no drive or white noise on translation beside it (the \
             thermostats and the host medium are not combined with rotational noise)",
        ),
    ];
    // The thermostat alone acts on translation: a rough gas takes it.
    assert!(
        rough(
            4,
            0.9,
            RotationChoice::spheres(0.0),
            DriveChoice::declared(gdsmc_core::physics::DriveKind::Gaussian, &[1.0]).unwrap()
        )
        .validate()
        .is_ok()
    );
    for (ph, msg) in cases {
        assert_eq!(ph.validate().unwrap_err().to_string(), msg);
    }
    let mut ph = rough(4, 0.9, RotationChoice::spheres(0.0), DriveChoice::None);
    ph.initial[0] = Component::STANDARD;
    ph.scheme = SchemeChoice::Euler(0.1);
    assert!(ph.validate().is_ok(), "rough particles take the splittings");
    ph.scheme = SchemeChoice::TimeStepped(0.01);
    assert!(
        ph.validate().is_ok(),
        "rough hard spheres take MS's time-stepped scheme"
    );
}
