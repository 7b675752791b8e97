//! Bad scene input gets a clear error naming the file, line and key.

use gdsmc::scene::parse;
use std::path::Path;

const GOOD: &str = r#"
[particles]
n = 64
[collisions]
kernel = "maxwell"
restitution = 0.5
[drive]
kind = "white-noise"
beta = 1.0
[observe]
t_end = 1.0
"#;

fn err(text: &str) -> String {
    parse(Path::new("bad.toml"), text).unwrap_err().to_string()
}

#[test]
fn good_scene_parses_with_defaults() {
    let s = parse(Path::new("good.toml"), GOOD).unwrap();
    assert_eq!(s.n, 64);
    assert_eq!(s.times.len(), 33);
    assert_eq!(s.ensembles, 100);
    assert_eq!(s.name, "good");
}

#[test]
fn restitution_out_of_range_names_line_and_key() {
    let e = err(&GOOD.replace("restitution = 0.5", "restitution = 1.5"));
    assert!(
        e.starts_with("bad.toml:6: `collisions.restitution` must lie in (0, 1]"),
        "{e}"
    );
    let e = err(&GOOD.replace("restitution = 0.5", "restitution = 0.0"));
    assert!(e.contains("bad.toml:6: `collisions.restitution`"), "{e}");
}

#[test]
fn too_few_particles() {
    let e = err(&GOOD.replace("n = 64", "n = 1"));
    assert!(
        e.starts_with("bad.toml:3: `particles.n` must be >= 2"),
        "{e}"
    );
}

#[test]
fn negative_rate() {
    let e = err(&GOOD.replace("beta = 1.0", "beta = -1.0"));
    assert!(
        e.starts_with("bad.toml:9: `drive.beta` must be >= 0"),
        "{e}"
    );
}

#[test]
fn unknown_key_and_wrong_type() {
    let e = err(&GOOD.replace("n = 64", "n = 64\nnn = 3"));
    assert!(
        e.contains("bad.toml") && e.contains("line 4") && e.contains("unknown field `nn`"),
        "{e}"
    );
    let e = err(&GOOD.replace("n = 64", "n = \"many\""));
    assert!(e.contains("line 3") && e.contains("invalid type"), "{e}");
}

#[test]
fn times_out_of_order() {
    let e = err(&GOOD.replace("t_end = 1.0", "t_start = 2.0\nt_end = 1.0"));
    assert!(
        e.contains("bad.toml:12: `observe.t_end` must be later than observe.t_start"),
        "{e}"
    );
}

#[test]
fn kernel_specific_keys() {
    let e = err(&GOOD.replace("kernel = \"maxwell\"", "kernel = \"vhs\""));
    assert!(e.contains("`collisions.lambda` is required"), "{e}");
    let e = err(&GOOD.replace("kernel = \"maxwell\"", "kernel = \"vhs\"\nlambda = 1.5"));
    assert!(
        e.contains("bad.toml:6: `collisions.lambda` must lie in [0, 1]"),
        "{e}"
    );
}
