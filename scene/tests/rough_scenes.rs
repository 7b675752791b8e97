//! `[rotation]` scenes: the rotation reaches the core's description, each bad value is named by
//! file, line and key, what a rough gas cannot take is refused by key, and `--set rotation.*`
//! overrides.

use gdsmc_scene::{Override, parse, parse_with};
use std::path::Path;

const ROUGH: &str = include_str!("scenes/rough.toml");

use super::{err, refused};

#[test]
fn a_rough_scene_gives_its_rotation() {
    let s = parse(Path::new("r.toml"), ROUGH).unwrap();
    let r = s.physics().rotation.unwrap();
    assert_eq!(
        (r.beta, r.kappa, r.temperature, r.noise),
        (0.25, 0.5, 2.0, 0.0)
    );
    assert!(!s.translation_is_smooth());
    let model = s.physics().validate().unwrap();
    assert_eq!(model.rough_map().unwrap().kappa(), 0.5);
    // Defaults: uniform spheres, T_rot = 1, no noise on rotation.
    let text = ROUGH.replace("inertia = 0.5\ntemperature = 2.0\n", "");
    let r = parse(Path::new("r.toml"), &text)
        .unwrap()
        .physics()
        .rotation
        .unwrap();
    assert_eq!((r.kappa, r.temperature, r.noise), (0.4, 1.0, 0.0));
}

#[test]
fn bad_rotation_values_name_line_and_key() {
    refused(
        &ROUGH.replace(
            "tangential_restitution = 0.25",
            "tangential_restitution = -2.0",
        ),
        "bad.toml:8: `rotation.tangential_restitution` must lie in [-1, 1], got -2",
    );
    refused(
        &ROUGH.replace("inertia = 0.5", "inertia = 0.8"),
        "bad.toml:9: `rotation.inertia` must lie in (0, 2/3], got 0.8",
    );
    refused(
        &ROUGH.replace("temperature = 2.0", "temperature = -2.0"),
        "bad.toml:10: `rotation.temperature` must be >= 0",
    );
    let e = err(&ROUGH.replace("[drive]", "[rotation.x]\n[drive]"));
    assert!(e.contains("unknown field") || e.contains("x"), "{e}");
}

#[test]
fn what_a_rough_gas_cannot_take_is_refused_by_key() {
    // The thermostat acts on translation; rotational noise beside it is refused by its key.
    let thermostat = ROUGH.replace(
        "kind = \"white-noise\"\nbeta = 1.0",
        "kind = \"gaussian\"\nzeta = 0.5",
    );
    assert!(parse(Path::new("ok.toml"), &thermostat).is_ok());
    refused(
        &thermostat.replace("temperature = 2.0", "temperature = 2.0\nnoise = 0.5"),
        "`rotation.noise` takes only no drive or white noise on translation",
    );
    // MS's time-stepped scheme takes rough hard spheres (core/tests/rough_gas.rs).
    let stepped = ROUGH.replace(
        "[observe]\n",
        "[scheme]\nkind = \"time-stepped\"\n[observe]\n",
    );
    assert!(parse(Path::new("ok.toml"), &stepped).is_ok());
    // The collisional cooling is every gas's (gdsmc_core::observe::cooling).
    let pairs = ROUGH.replace("t_end = 1.0", "t_end = 1.0\ncollisional_pairs = 100");
    assert!(parse(Path::new("ok.toml"), &pairs).is_ok());
}

#[test]
fn rough_particles_take_the_impact_speed_law() {
    let s = parse_with(
        Path::new("r.toml"),
        &ROUGH.replace(
            "restitution = 0.9",
            "impact_speed_law = { beta0 = 0.1, delta = 0.2 }",
        ),
        &[],
    )
    .unwrap();
    assert!(s.model().rotates());
    assert!(s.physics().restitution.constant().is_none());
}

#[test]
fn rotation_can_be_overridden() {
    let s = parse_with(
        Path::new("r.toml"),
        ROUGH,
        &[
            Override::set("rotation.tangential_restitution=-1"),
            Override::set("rotation.noise=0.5"),
        ],
    )
    .unwrap();
    let r = s.physics().rotation.unwrap();
    assert_eq!((r.beta, r.noise), (-1.0, 0.5));
    assert!(s.translation_is_smooth());
    let e = parse_with(
        Path::new("r.toml"),
        ROUGH,
        &[Override::set("rotation.inertia=0")],
    )
    .unwrap_err()
    .to_string();
    assert!(
        e.contains("`rotation.inertia` must lie in (0, 2/3], got 0"),
        "{e}"
    );
}

const ROUGH_MIXTURE: &str = include_str!("scenes/rough_mixture.toml");

/// A rough mixture: each species' own rotation where it names one, the rotation's otherwise;
/// the pairs' tangential restitution from the matrix; bad values named by line and key.
#[test]
fn a_rough_mixture_gives_each_species_and_pair_its_rotation() {
    let s = parse(Path::new("r.toml"), ROUGH_MIXTURE).unwrap();
    let ph = s.physics();
    assert_eq!(ph.species[0].inertia, None);
    assert_eq!(ph.species[1].inertia, Some(0.2));
    assert_eq!(ph.species[1].rotation_temperature, Some(3.0));
    assert_eq!(&ph.pair_tangential_restitution[..], &[0.25, 0.5, -0.5]);
    assert!(s.model().rotates());
    refused(
        &ROUGH_MIXTURE.replace("inertia = 0.2", "inertia = 0.9"),
        "bad.toml:9: `species[1].inertia` must lie in (0, 2/3], got 0.9",
    );
    let e = err(&ROUGH_MIXTURE.replace("[[0.25, 0.5], [0.5, -0.5]]", "[[0.25, 2.0], [2.0, -0.5]]"));
    assert!(
        e.starts_with(
            "bad.toml:16: `rotation.pair_tangential_restitution` must lie in [-1, 1], got 2"
        ),
        "{e}"
    );
    refused(
        &ROUGH_MIXTURE.replace("[[0.25, 0.5], [0.5, -0.5]]", "[[0.25, 0.5], [0.4, -0.5]]"),
        "must be symmetric",
    );
    // Without [rotation] a species' rotation is refused at its key.
    let smooth = ROUGH_MIXTURE
        .replace("[rotation]\ntangential_restitution = 0.25\n", "")
        .replace(
            "pair_tangential_restitution = [[0.25, 0.5], [0.5, -0.5]]\n",
            "",
        );
    refused(
        &smooth,
        "bad.toml:9: `species[1].inertia` is only used with rough particles",
    );
}
