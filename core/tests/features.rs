//! The engine families a build holds (gdsmc-core's cargo features `mixtures`, `rough`,
//! `disks`): each family starts exactly when its features are built, else the start is refused
//! with `EngineError::NotBuilt` naming them; smooth spheres of one species always start. CI
//! runs this file with the default features (all) and with the firmware's subset (`rough`
//! alone), so both branches are exercised.

use gdsmc_core::engine::{EngineError, EventLoop};
use gdsmc_core::particles::{Particle, Particles, Spin};
use gdsmc_core::physics::{
    DimensionChoice, DriveChoice, KernelChoice, Physics, RestitutionLaw, RotationChoice,
    SchemeChoice, SpeciesChoice,
};
use gdsmc_core::rng::stream;

/// Hard spheres or disks, cooling: `mixture` two species, `rough` with rotation.
fn physics(mixture: bool, rough: bool, dim: DimensionChoice) -> Physics {
    let mut ph = Physics::new(
        8,
        KernelChoice::HardSpheres { gamma: 1.0, c: 1.0 },
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
                assert!(built, "{name}: started although not built");
                assert!(e.advance_to(&mut p, 1.0, &mut rng).is_ok());
            }
            Err(e) => {
                assert!(!built, "{name}: {e}");
                assert_eq!(e, EngineError::NotBuilt(name));
                assert!(e.to_string().contains(&format!("cargo feature `{name}`")));
            }
        }
    }
}
