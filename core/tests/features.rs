//! The engines a build holds (gdsmc-core's cargo features: the families `mixtures`, `rough`,
//! `disks`; each kernel, drive, the impact-speed law and the splitting and time-stepped
//! schemes): each physics starts exactly when its features are built, else the start is
//! refused with `EngineError::NotBuilt` naming the first one missing (in the dispatch's order:
//! family, kernel, drive, law, scheme). CI runs this file with the default features (all), with
//! the firmware's subsets and with none, so both branches are exercised.

use gdsmc_core::engine::EngineError;
use gdsmc_core::particles::{Particle, Particles, Spin};
use gdsmc_core::physics::{
    BackgroundKernel, DimensionChoice, DriveChoice, KernelChoice, Physics, RestitutionLaw,
    RotationChoice, SchemeChoice, SpeciesChoice,
};
use gdsmc_core::rng::stream;

/// Hard spheres or disks, cooling: `mixture` two species, `rough` with rotation.
fn physics(mixture: bool, rough: bool, dim: DimensionChoice) -> Physics {
    let mut ph = Physics::new(
        8,
        KernelChoice::hard_spheres(1.0, 1.0),
        RestitutionLaw::Constant(0.9),
        DriveChoice::None,
        SchemeChoice::NoSplitting,
    );
    ph.dimension = dim;
    if mixture {
        for m in [1.0, 2.0] {
            ph.species.push(SpeciesChoice::new(4, m, 1.0)).unwrap();
        }
    }
    if rough {
        ph.rotation = Some(RotationChoice::uniform(dim, 0.5));
    }
    ph
}

#[test]
fn each_family_starts_exactly_when_built() {
    let (mixtures, rough, disks) = (
        cfg!(feature = "mixtures"),
        cfg!(feature = "rough"),
        cfg!(feature = "disks"),
    );
    let cases = [
        (false, false, DimensionChoice::Three, true, ""),
        (true, false, DimensionChoice::Three, mixtures, "mixtures"),
        (false, true, DimensionChoice::Three, rough, "rough"),
        (false, false, DimensionChoice::Two, disks, "disks"),
        (
            false,
            true,
            DimensionChoice::Two,
            rough && disks,
            "rough` and `disks",
        ),
        (
            true,
            false,
            DimensionChoice::Two,
            mixtures && disks,
            "mixtures` and `disks",
        ),
        (
            true,
            true,
            DimensionChoice::Three,
            mixtures && rough,
            "mixtures` and `rough",
        ),
        (
            true,
            true,
            DimensionChoice::Two,
            mixtures && rough && disks,
            "mixtures`, `rough` and `disks",
        ),
    ];
    // The kernel and the drive are built too (the cases are cooling hard spheres).
    let (hs, cooling) = (cfg!(feature = "hard-spheres"), cfg!(feature = "cooling"));
    for (mixture, spins, dim, built, name) in cases {
        // Validation knows every family, built or not: the rules are the same everywhere.
        let model = physics(mixture, spins, dim).validate().unwrap();
        let mut buf = vec![Particle::default(); 8];
        let mut sp = vec![Spin::default(); 8];
        let mut p = if spins {
            Particles::with_spins(&mut buf, &mut sp).unwrap()
        } else {
            Particles::new(&mut buf).unwrap()
        };
        let mut rng = stream(1, 0);
        match model.launch(&mut p, 0.0, &mut rng) {
            Ok((mut e, _)) => {
                assert!(built && hs && cooling, "{name}: started although not built");
                assert!(e.advance_to(&mut p, 1.0, &mut rng).is_ok());
            }
            Err(e) => {
                let name = match (built, hs) {
                    (false, _) => name,
                    (true, false) => "hard-spheres",
                    (true, true) => "cooling",
                };
                assert!(!(built && hs && cooling), "{name}: {e}");
                assert_eq!(e, EngineError::NotBuilt(name));
                assert!(e.to_string().contains(&format!("cargo feature `{name}`")));
            }
        }
    }
}

/// Starts `ph` (smooth spheres of one species) and checks that it runs exactly when every
/// feature of `needs` (in the dispatch's order) is built, else that the refusal names the first
/// one missing.
fn starts_exactly_when_built(what: &str, ph: Physics, needs: &[(bool, &'static str)]) {
    let model = ph.validate().unwrap_or_else(|e| panic!("{what}: {e}"));
    let mut buf = vec![Particle::default(); ph.n];
    let mut p = Particles::new(&mut buf).unwrap();
    let mut rng = stream(1, 0);
    let missing = needs.iter().find(|(on, _)| !on).map(|&(_, name)| name);
    match (model.launch(&mut p, 0.0, &mut rng), missing) {
        (Ok((mut e, _)), None) => {
            assert!(e.advance_to(&mut p, 0.5, &mut rng).is_ok(), "{what}");
        }
        (Ok(_), Some(name)) => panic!("{what}: started although `{name}` is not built"),
        (Err(e), Some(name)) => {
            assert_eq!(e, EngineError::NotBuilt(name), "{what}");
            assert!(e.to_string().contains(&format!("cargo feature `{name}`")));
        }
        (Err(e), None) => panic!("{what}: {e}"),
    }
}

#[test]
fn each_kernel_drive_law_and_scheme_starts_exactly_when_built() {
    let (maxwell, hard, vhs, cooling) = (
        cfg!(feature = "maxwell"),
        cfg!(feature = "hard-spheres"),
        cfg!(feature = "vhs"),
        cfg!(feature = "cooling"),
    );
    let base = |kernel| {
        Physics::new(
            16,
            kernel,
            RestitutionLaw::Constant(0.9),
            DriveChoice::None,
            SchemeChoice::NoSplitting,
        )
    };
    let mx = KernelChoice::maxwell(1.0, 1.0);
    let hs = KernelChoice::hard_spheres(1.0, 1.0);
    let kernels = [
        ("maxwell", mx, maxwell),
        ("hard-spheres", hs, hard),
        ("vhs", KernelChoice::vhs(1.0, 1.0, 0.5), vhs),
    ];
    for (name, k, on) in kernels {
        starts_exactly_when_built(name, base(k), &[(on, name), (cooling, "cooling")]);
    }
    let host = DriveChoice::HostMedium {
        kernel: BackgroundKernel::HardSpheres,
        c1: 1.0,
        density: 1.0,
        mass: 2.0,
        temperature: 1.0,
        drift: [0.0; 3],
    };
    let drives = [
        ("white-noise", DriveChoice::WhiteNoise(1.0)),
        (
            "gaussian-thermostat",
            DriveChoice::declared(gdsmc_core::physics::DriveKind::Gaussian, &[1.0]).unwrap(),
        ),
        ("host-medium", host),
    ];
    for (name, d) in drives {
        let ph = Physics {
            drive: d,
            ..base(mx)
        };
        starts_exactly_when_built(name, ph, &[(maxwell, "maxwell"), (cfg_drive(name), name)]);
    }
    // The constant force needs a splitting or time-stepped scheme (MS (62)).
    let force = Physics {
        drive: DriveChoice::declared(gdsmc_core::physics::DriveKind::ConstantForce, &[1.0])
            .unwrap(),
        scheme: SchemeChoice::Euler(0.1),
        ..base(mx)
    };
    let split = cfg!(feature = "splitting");
    starts_exactly_when_built(
        "constant force, Euler",
        force,
        &[
            (maxwell, "maxwell"),
            (cfg!(feature = "constant-force"), "constant-force"),
            (split, "splitting"),
        ],
    );
    let impact = Physics {
        restitution: RestitutionLaw::ImpactSpeed {
            beta0: 1.0,
            delta: 0.2,
        },
        ..base(mx)
    };
    starts_exactly_when_built(
        "impact speed",
        impact,
        &[
            (maxwell, "maxwell"),
            (cooling, "cooling"),
            (cfg!(feature = "impact-speed"), "impact-speed"),
        ],
    );
    for scheme in [SchemeChoice::Euler(0.1), SchemeChoice::Strang(0.1)] {
        let ph = Physics { scheme, ..base(mx) };
        starts_exactly_when_built(
            "splitting",
            ph,
            &[
                (maxwell, "maxwell"),
                (cooling, "cooling"),
                (split, "splitting"),
            ],
        );
    }
    let stepped = Physics {
        scheme: SchemeChoice::TimeStepped(0.1),
        ..base(hs)
    };
    starts_exactly_when_built(
        "time-stepped",
        stepped,
        &[
            (hard, "hard-spheres"),
            (cooling, "cooling"),
            (cfg!(feature = "time-stepped"), "time-stepped"),
        ],
    );
    // Bird's form of it for the other kernels.
    let stepped = Physics {
        scheme: SchemeChoice::TimeStepped(0.1),
        ..base(mx)
    };
    starts_exactly_when_built(
        "time-stepped, Maxwell",
        stepped,
        &[
            (maxwell, "maxwell"),
            (cooling, "cooling"),
            (cfg!(feature = "time-stepped"), "time-stepped"),
        ],
    );
}

/// Whether the build holds the drive named by its feature.
fn cfg_drive(name: &str) -> bool {
    match name {
        "white-noise" => cfg!(feature = "white-noise"),
        "gaussian-thermostat" => cfg!(feature = "gaussian-thermostat"),
        "host-medium" => cfg!(feature = "host-medium"),
        _ => unreachable!("{name}"),
    }
}
