//! `[[species]]` scenes: counts from fractions, each bad value named by file, line and key,
//! `--set species[k].key=` overrides.

use gdsmc_scene::parse;
use gdsmc_scene::{Override, parse_with};
use std::path::Path;

const MIX: &str = include_str!("scenes/mixture.toml");

use super::refused;

#[test]
fn a_mixture_scene_gives_its_species_and_pairs() {
    let s = parse(Path::new("mix.toml"), MIX).unwrap();
    let sp = &s.physics().species;
    // 10/3 and 20/3: floors 3 and 6, the larger remainder (2/3) to the second species.
    assert_eq!((sp[0].count, sp[1].count), (3, 7));
    assert_eq!((sp[0].mass, sp[1].mass, sp[1].diameter), (4.0, 1.0, 2.0));
    assert_eq!((sp[0].beta, sp[1].beta), (1.0, 1.0));
    assert_eq!(s.physics().pair_restitution.as_slice(), &[0.9, 0.8, 0.7]);
    assert_eq!(s.species_names(), vec!["heavy", "s1"]);
    let model = s.physics().validate().unwrap();
    assert_eq!(model.species().unwrap().total(), 10);
    let mut s2 = s.clone();
    s2.set_n(1000).expect("a valid particle count");
    assert_eq!(
        (s2.physics().species[0].count, s2.physics().species[1].count),
        (333, 667)
    );
}

#[test]
fn bad_species_values_name_line_and_key() {
    refused(
        &MIX.replace("mass = 4.0", "mass = -4.0"),
        "bad.toml:7: `species[0].mass` must be > 0",
    );
    refused(
        &MIX.replace("fraction = 2.0", "fraction = 0.0"),
        "bad.toml:9: `species[1].fraction` must be a finite number > 0",
    );
    refused(
        &MIX.replace("diameter = 2.0", "diameter = -1.0"),
        "bad.toml:11: `species[1].diameter` must be > 0",
    );
    refused(
        &MIX.replace("[0.8, 0.7]]", "[0.8, 1.7]]"),
        "`collisions.pair_restitution` must lie in (0, 1], got 1.7",
    );
    refused(
        &MIX.replace("[0.8, 0.7]]", "[0.6, 0.7]]"),
        "`collisions.pair_restitution` must be symmetric",
    );
    refused(
        &MIX.replace("[[0.9, 0.8], [0.8, 0.7]]", "[[0.9, 0.8]]"),
        "must be a 2 x 2 matrix",
    );
    refused(
        &MIX.replace("n = 10", "n = 1"),
        "`species[0].fraction` gives no particle at n = 1",
    );
    refused(
        &MIX.replace("beta = 1.0", "beta = -1.0"),
        "`drive.beta` must be >= 0",
    );
    // The constant force (with a stepping scheme): one force per unit mass on every species.
    parse(
        Path::new("mix.toml"),
        &MIX.replace(
            "kind = \"white-noise\"\nbeta = 1.0",
            "kind = \"constant-force\"\ng = 1.0\n[scheme]\nkind = \"time-stepped\"",
        ),
    )
    .expect("mixtures take the constant force");
    // A host medium: every species meets the background with its own mass.
    parse(
        Path::new("mix.toml"),
        &MIX.replace(
            "kind = \"white-noise\"\nbeta = 1.0",
            "kind = \"host-medium\"\nkernel = \"maxwell\"",
        ),
    )
    .expect("mixtures take a host medium");
    // The Gaussian thermostat acts on every species (about the flow velocity).
    let s = parse(
        Path::new("mix.toml"),
        &MIX.replace(
            "kind = \"white-noise\"\nbeta = 1.0",
            "kind = \"gaussian\"\nzeta = 1.0",
        ),
    )
    .unwrap();
    assert!(s.physics().validate().is_ok());
    refused(
        &MIX.replace("pair_restitution", "restitution = 0.5\npair_restitution"),
        "`collisions.restitution` and collisions.pair_restitution exclude each other",
    );
    refused(
        &MIX.replace(
            "[particles]\nn = 10",
            "[particles]\nn = 10\ninitial = { kind = \"maxwellian\", temperature = 2.0 }",
        ),
        "`particles.initial` is not used with [[species]]",
    );
}

#[test]
fn species_can_be_overridden_by_index() {
    let set = |a: &str| Override::set(a);
    let s = parse_with(
        Path::new("mix.toml"),
        MIX,
        &[set("species[1].mass=2.5"), set("species[0].beta=0.5")],
    )
    .unwrap();
    assert_eq!(s.physics().species[1].mass, 2.5);
    assert_eq!(
        (s.physics().species[0].beta, s.physics().species[1].beta),
        (0.5, 1.0)
    );
    let e = parse_with(Path::new("mix.toml"), MIX, &[set("species[2].mass=1")])
        .unwrap_err()
        .to_string();
    assert!(
        e.contains("`species[2]` names no table of the scene"),
        "{e}"
    );
    let e = parse_with(Path::new("mix.toml"), MIX, &[set("species[1].mass=-1")])
        .unwrap_err()
        .to_string();
    assert!(
        e.contains("--set") && e.contains("`species[1].mass` must be > 0"),
        "{e}"
    );
}
