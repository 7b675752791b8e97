//! The physics description: every rule is refused with its parameter named, and the one
//! dispatch builds exactly the loop a caller composing the types by hand would run.

use gdsmc_core::drive::{GaussianThermostat, HardSphereBackground, HostMedium, HostMediumParams};
use gdsmc_core::engine::{EventLoop, NoSplitting, Splitting, SplittingOrder, TimeStepped};
use gdsmc_core::kernel::{HardSpheres, Maxwell, Vhs};
use gdsmc_core::particles::{Particle, Particles};
use gdsmc_core::physics::engine::ByKernel;
use gdsmc_core::physics::{
    BackgroundKernel, Component, DriveChoice, Engine, KernelChoice, LawKind, Param, Physics,
    Problem, RestitutionLaw, SchemeChoice, SchemeKind,
};
use gdsmc_core::restitution::{Constant, ImpactSpeed};
use gdsmc_core::rng::seeded;
use gdsmc_core::sample::Maxwellian;
use gdsmc_core::vec3::Vec3;

fn grw3() -> Physics {
    Physics::new(
        16,
        KernelChoice::maxwell(4.0, 0.25 / core::f64::consts::PI),
        RestitutionLaw::Constant(0.5),
        DriveChoice::WhiteNoise(1.0),
        SchemeChoice::NoSplitting,
    )
}

fn refused(p: Physics) -> (Param, Problem) {
    let e = p.validate().unwrap_err();
    (e.param, e.problem)
}

#[test]
fn every_rule_names_its_parameter() {
    let hs = KernelChoice::hard_spheres(1.0, 1.0);
    let cases: Vec<(Physics, Param)> = vec![
        (Physics { n: 1, ..grw3() }, Param::N),
        (
            Physics {
                n: usize::MAX,
                ..grw3()
            },
            Param::N,
        ),
        (
            Physics {
                kernel: KernelChoice::maxwell(0.0, 1.0),
                ..grw3()
            },
            Param::Gamma,
        ),
        (
            Physics {
                kernel: KernelChoice::maxwell(1.0, f64::NAN),
                ..grw3()
            },
            Param::C,
        ),
        // Each positive, the product underflows to 0 (a hostile-input case that once panicked).
        (
            Physics {
                kernel: KernelChoice::maxwell(5e-324, 0.1),
                ..grw3()
            },
            Param::Gamma,
        ),
        (
            Physics {
                kernel: KernelChoice::vhs(1.0, 1.0, 1.5),
                ..grw3()
            },
            Param::Kernel(gdsmc_core::physics::KernelKind::Vhs, 0),
        ),
        (
            Physics {
                restitution: RestitutionLaw::Constant(0.0),
                ..grw3()
            },
            Param::Law(LawKind::Constant, 0),
        ),
        (
            Physics {
                restitution: RestitutionLaw::Constant(1.0 + 1e-12),
                ..grw3()
            },
            Param::Law(LawKind::Constant, 0),
        ),
        (
            Physics {
                restitution: RestitutionLaw::ImpactSpeed {
                    beta0: -0.1,
                    delta: 0.2,
                },
                ..grw3()
            },
            Param::Law(LawKind::ImpactSpeed, 0),
        ),
        (
            Physics {
                restitution: RestitutionLaw::ImpactSpeed {
                    beta0: 0.1,
                    delta: f64::INFINITY,
                },
                ..grw3()
            },
            Param::Law(LawKind::ImpactSpeed, 1),
        ),
        (
            Physics {
                drive: DriveChoice::WhiteNoise(-1.0),
                ..grw3()
            },
            Param::Beta,
        ),
        (
            Physics {
                drive: DriveChoice::declared(gdsmc_core::physics::DriveKind::Gaussian, &[f64::NAN])
                    .unwrap(),
                ..grw3()
            },
            Param::Drive(gdsmc_core::physics::DriveKind::Gaussian, 0),
        ),
        (
            Physics {
                drive: DriveChoice::declared(
                    gdsmc_core::physics::DriveKind::ConstantForce,
                    &[-2.0],
                )
                .unwrap(),
                scheme: SchemeChoice::Euler(0.1),
                ..grw3()
            },
            Param::Drive(gdsmc_core::physics::DriveKind::ConstantForce, 0),
        ),
        (
            Physics {
                drive: DriveChoice::declared(gdsmc_core::physics::DriveKind::ConstantForce, &[1.0])
                    .unwrap(),
                ..grw3()
            },
            Param::Scheme,
        ),
        (
            Physics {
                scheme: SchemeChoice::Strang(0.0),
                ..grw3()
            },
            Param::Step(SchemeKind::Strang, 0),
        ),
        (
            Physics {
                kernel: hs,
                scheme: SchemeChoice::TimeStepped(-1.0),
                ..grw3()
            },
            Param::Step(SchemeKind::TimeStepped, 0),
        ),
    ];
    for (p, param) in cases {
        let (got, problem) = refused(p.clone());
        assert_eq!(got, param, "{p:?}: {problem}");
    }
    let host = |density: f64, mass: f64, temperature: f64, drift: [f64; 3]| Physics {
        drive: DriveChoice::HostMedium {
            kernel: BackgroundKernel::HardSpheres,
            c1: 1.0,
            density,
            mass,
            temperature,
            drift,
        },
        ..grw3()
    };
    assert_eq!(
        refused(host(0.0, 1.0, 1.0, [0.0; 3])).0,
        Param::BackgroundDensity
    );
    assert_eq!(
        refused(host(1.0, -1.0, 1.0, [0.0; 3])).0,
        Param::BackgroundMass
    );
    assert_eq!(
        refused(host(1.0, 1.0, -1.0, [0.0; 3])).0,
        Param::BackgroundTemperature
    );
    assert_eq!(
        refused(host(1.0, 1.0, 1.0, [0.0, f64::NAN, 0.0])).0,
        Param::BackgroundDrift
    );
    let mut p = grw3();
    p.initial.clear();
    assert_eq!(
        refused(p.clone()),
        (Param::Components, Problem::NoComponents)
    );
    p.initial
        .push(Component {
            weight: 0.0,
            ..Component::STANDARD
        })
        .unwrap();
    assert_eq!(
        refused(p.clone()),
        (Param::Components, Problem::AllWeightsZero)
    );
    p.initial
        .push(Component {
            mass: 0.0,
            ..Component::STANDARD
        })
        .unwrap();
    assert_eq!(refused(p).0, Param::Mass(1));
}

#[test]
fn messages_are_the_rules() {
    let msg = |p: Physics| p.validate().unwrap_err().to_string();
    assert_eq!(
        msg(Physics {
            restitution: RestitutionLaw::Constant(1.5),
            ..grw3()
        }),
        "restitution must lie in (0, 1], got 1.5"
    );
    assert_eq!(
        msg(Physics { n: 1, ..grw3() }),
        "n must be >= 2 (a pair is needed to collide), got 1"
    );
    assert_eq!(
        msg(Physics {
            drive: DriveChoice::WhiteNoise(-1.0),
            ..grw3()
        }),
        "beta must be >= 0, got -1"
    );
    assert_eq!(
        msg(Physics {
            drive: DriveChoice::WhiteNoise(f64::INFINITY),
            ..grw3()
        }),
        "beta must be a finite number, got inf"
    );
}

/// Runs an engine for a few observations and returns the trajectory's observables.
fn trajectory<E: EventLoop>(mut e: E, p: &mut Particles<'_>, seed: u64) -> Vec<[f64; 4]> {
    let mut rng = seeded(seed);
    (1..=4)
        .map(|k| {
            let o = e.advance_to(p, 0.5 * k as f64, &mut rng).unwrap();
            [o.t_raw, o.t_bulk, o.v4, e.counts().collisions as f64]
        })
        .collect()
}

/// The dispatched engine and the hand-composed one, from the same particles and generator.
fn same_as_by_hand<E: EventLoop>(
    physics: Physics,
    by_hand: impl FnOnce(&mut Particles<'_>) -> E,
    is_variant: impl Fn(&Engine) -> bool,
) {
    let model = physics.validate().unwrap();
    let n = physics.n;
    let (mut a, mut b) = (vec![Particle::default(); n], vec![Particle::default(); n]);
    let mut pa = Particles::new(&mut a).unwrap();
    let mut pb = Particles::new(&mut b).unwrap();
    model.initialize(&mut pa, 0.0, &mut seeded(3)).unwrap();
    model.initialize(&mut pb, 0.0, &mut seeded(3)).unwrap();
    let (engine, _) = model.start(&mut pa, 0.0).unwrap();
    assert!(is_variant(&engine), "{engine:?}");
    let hand = by_hand(&mut pb);
    assert_eq!(trajectory(engine, &mut pa, 9), trajectory(hand, &mut pb, 9));
}

#[test]
fn dispatch_builds_the_hand_composed_loop() {
    let p = grw3();
    same_as_by_hand(
        p.clone(),
        |q| {
            let k = Maxwell::new(4.0, 0.25 / core::f64::consts::PI).unwrap();
            let d = gdsmc_core::drive::WhiteNoise::new(1.0).unwrap();
            NoSplitting::start(k, d, Constant::new(0.5).unwrap(), q, 0.0)
                .unwrap()
                .0
        },
        |e| matches!(e, Engine::Smooth(ByKernel::Maxwell(_))),
    );
    let vhs = Physics {
        kernel: KernelChoice::vhs(1.0, 0.1, 0.5),
        scheme: SchemeChoice::Strang(0.25),
        ..p.clone()
    };
    same_as_by_hand(
        vhs,
        |q| {
            let k = Vhs::new(1.0, 0.1, 0.5).unwrap();
            let d = gdsmc_core::drive::WhiteNoise::new(1.0).unwrap();
            let a = Constant::new(0.5).unwrap();
            let (e, _): (Splitting<_, _, _>, _) =
                Splitting::start(k, d, a, SplittingOrder::Strang, 0.25, q, 0.0).unwrap();
            e
        },
        |e| matches!(e, Engine::Smooth(ByKernel::Vhs(_))),
    );
    let ms = Physics {
        kernel: KernelChoice::hard_spheres(1.0, 0.1),
        drive: DriveChoice::declared(gdsmc_core::physics::DriveKind::Gaussian, &[0.25]).unwrap(),
        scheme: SchemeChoice::TimeStepped(0.05),
        ..p.clone()
    };
    same_as_by_hand(
        ms,
        |q| {
            let k = HardSpheres::new(1.0, 0.1).unwrap();
            let d = GaussianThermostat::new(0.25).unwrap();
            let (e, _): (TimeStepped<_, _, _>, _) =
                TimeStepped::start(k, d, Constant::new(0.5).unwrap(), 0.05, q, 0.0).unwrap();
            e
        },
        |e| matches!(e, Engine::Smooth(ByKernel::HardSpheres(_))),
    );
    let brs = Physics {
        kernel: KernelChoice::hard_spheres(1.0, 1.0),
        restitution: RestitutionLaw::ImpactSpeed {
            beta0: 0.2,
            delta: 0.2,
        },
        drive: DriveChoice::HostMedium {
            kernel: BackgroundKernel::HardSpheres,
            c1: 1.0,
            density: 1.0,
            mass: 2.0,
            temperature: 1.0,
            drift: [0.0, 1.0, 0.0],
        },
        ..p
    };
    same_as_by_hand(
        brs,
        |q| {
            let k = HardSpheres::new(1.0, 1.0).unwrap();
            let bg = Maxwellian::new(2.0, 1.0, Vec3::new(0.0, 1.0, 0.0)).unwrap();
            let d = HostMedium::new(
                HostMediumParams::new(bg, 1.0, 1.0).unwrap(),
                HardSphereBackground,
            );
            NoSplitting::start(k, d, ImpactSpeed::new(0.2, 0.2).unwrap(), q, 0.0)
                .unwrap()
                .0
        },
        |e| matches!(e, Engine::Smooth(ByKernel::HardSpheres(_))),
    );
}

#[test]
fn a_buffer_of_the_wrong_size_is_refused() {
    let model = grw3().validate().unwrap();
    let mut buf = vec![Particle::default(); 15];
    let mut p = Particles::new(&mut buf).unwrap();
    assert!(model.launch(&mut p, 0.0, &mut seeded(1)).is_err());
}

/// A splitting step longer than the run is refused by the description's span rule, and the
/// engine's grid refuses every advance such a step would skip (before: `dt = 1e300` to `t = 8`
/// was "on the grid" at step 0 and returned the start's observables as `t = 8`'s).
#[test]
fn a_step_that_takes_no_step_is_refused() {
    use gdsmc_core::engine::{EngineError, grid_index};
    let strang = |dt| SchemeChoice::Strang(dt);
    assert!(strang(8.0).check_span(8.0).is_ok());
    assert!(SchemeChoice::NoSplitting.check_span(1.0).is_ok());
    for dt in [8.000001, 1e300, f64::MAX, f64::INFINITY, f64::NAN] {
        let e = strang(dt).check_span(8.0).unwrap_err();
        assert_eq!(e.param, Param::Step(SchemeKind::Strang, 0), "dt = {dt}");
        assert!(e.to_string().contains("at most the run's span 8"), "{e}");
    }
    // The grid: the start, whole steps to within 1e-9 of a step, nothing else.
    assert_eq!(grid_index(0.0, 0.25, 0.0), Some(0));
    assert_eq!(grid_index(0.0, 0.1, 0.3), Some(3));
    assert_eq!(grid_index(1.0, 0.5, 3.0), Some(4));
    for (dt, t) in [
        (1e300, 8.0),
        (1.0, 1e-12),
        (1.0, 0.4),
        (0.25, 0.3),
        (0.25, -1.0),
        (0.25, f64::NAN),
        (0.25, f64::INFINITY),
        (1e-300, 1e10),
    ] {
        assert_eq!(grid_index(0.0, dt, t), None, "dt = {dt}, t = {t}");
    }
    // The engine applies the same rule: a Strang scheme with dt = 1e300 cannot advance to 8.
    let model = Physics {
        scheme: strang(1e300),
        ..grw3()
    }
    .validate()
    .unwrap();
    let mut buf = [Particle::default(); 16];
    let mut p = Particles::new(&mut buf).unwrap();
    let mut rng = seeded(1);
    let (mut engine, _) = model.launch(&mut p, 0.0, &mut rng).unwrap();
    assert_eq!(
        engine.advance_to(&mut p, 8.0, &mut rng).unwrap_err(),
        EngineError::OffGrid
    );
}

/// A broken invariant of the validated model is its own error, saying it is a bug, not a
/// non-finite velocity the caller could have caused.
#[test]
fn a_broken_invariant_says_it_is_a_bug() {
    use gdsmc_core::engine::EngineError;
    let e = EngineError::Invariant("a hard kernel is hard spheres").to_string();
    assert!(
        e.contains("a hard kernel is hard spheres") && e.contains("a bug in gdsmc"),
        "{e}"
    );
    assert!(!e.contains("non-finite"), "{e}");
}

/// The restitution's rule is checked in one constructor and its words come from one constant:
/// the law, the rough map and the description say the same range.
#[test]
fn alpha_has_one_rule_and_one_wording() {
    use gdsmc_core::restitution::{ALPHA_RANGE, AlphaError, Constant};
    use gdsmc_core::rough::{RoughError, RoughMap};
    for bad in [0.0, -0.5, 1.0 + 1e-12, f64::NAN, f64::INFINITY] {
        let e = Constant::new(bad).unwrap_err();
        assert!(matches!(e, AlphaError(x) if x.to_bits() == bad.to_bits()));
        assert!(e.to_string().contains(ALPHA_RANGE), "{e}");
        assert_eq!(RoughMap::new(bad, 0.0, 0.4).unwrap_err(), RoughError::Alpha);
    }
    assert!(RoughError::Alpha.to_string().contains(ALPHA_RANGE));
    assert_eq!(Constant::new(1.0).unwrap().alpha(), 1.0);
    let msg = Physics {
        restitution: RestitutionLaw::Constant(0.0),
        ..grw3()
    }
    .validate()
    .unwrap_err()
    .to_string();
    assert_eq!(msg, format!("restitution must lie in {ALPHA_RANGE}, got 0"));
}
