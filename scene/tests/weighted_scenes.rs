//! The weighted scheme in a scene (`[scheme] kind = "weighted"`): its keys read by the core's
//! declaration with their defaults, and each rule refused with its words, naming the key and
//! line (the rule against the rest of the physics names `scheme`).

use super::{err, refused};
use gdsmc_core::physics::{SchemeChoice, SchemeKind};
use std::path::Path;

const GOOD: &str = include_str!("scenes/good.toml");

/// The good scene with `[scheme]` weighted and `keys` (one per line, from line 13 on).
fn weighted(keys: &str) -> String {
    format!("{GOOD}[scheme]\nkind = \"weighted\"\n{keys}")
}

#[test]
fn a_weighted_scene_takes_the_declared_defaults() {
    let s = gdsmc_scene::parse(Path::new("w.toml"), &weighted("")).unwrap();
    let defaults: Vec<f64> = (SchemeKind::Weighted.params().iter())
        .map(|p| p.default.expect("every weighted parameter has a default"))
        .collect();
    assert_eq!(
        s.physics().scheme,
        SchemeChoice::Weighted(defaults.try_into().unwrap())
    );
    assert!(s.model().weighted());
    assert_eq!(s.model().capacity(), 4 * 64);
    let s =
        gdsmc_scene::parse(Path::new("w.toml"), &weighted("capacity = 2.5\ntarget = 1")).unwrap();
    assert_eq!(s.model().capacity(), 160);
}

#[test]
fn each_weighted_rule_is_refused_with_its_words() {
    refused(
        &weighted("kappa = -1"),
        "bad.toml:14: `scheme.kappa` must be >= 0",
    );
    refused(
        &weighted("kappa = 2\ntail_kappa = 1"),
        "bad.toml:15: `scheme.tail_kappa` must be at least kappa",
    );
    refused(
        &weighted("tail_speed = 0"),
        "bad.toml:14: `scheme.tail_speed` must be > 0",
    );
    refused(
        &weighted("capacity = 1.5"),
        "bad.toml:14: `scheme.capacity` must lie in [2, 64]",
    );
    refused(
        &weighted("capacity = 3\ntarget = 3"),
        "bad.toml:15: `scheme.target` must be below capacity",
    );
    refused(
        &weighted("exponent = 2"),
        "bad.toml:14: `scheme.exponent` must lie in [0, 1]",
    );
    refused(&weighted("dt = 0.1"), "scheme");
}

#[test]
fn the_weighted_scheme_runs_smooth_particles_of_one_species() {
    let rough = format!(
        "{}[rotation]\ntangential_restitution = 0.25\n",
        weighted("")
    );
    let e = err(&rough);
    assert!(
        e.contains("scheme") && e.contains("smooth particles"),
        "{e}"
    );
    let host = weighted("").replace(
        "kind = \"white-noise\"\nbeta = 1.0",
        "kind = \"host-medium\"\nkernel = \"maxwell\"\nc = 1.0\ndensity = 1.0\nmass = 1.0\ntemperature = 1.0",
    );
    let e = err(&host);
    assert!(e.contains("scheme") && e.contains("host medium"), "{e}");
}
