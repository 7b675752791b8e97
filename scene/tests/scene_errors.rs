//! Bad scene input gets a clear error naming the file, line and key.

use gdsmc_scene::parse;
use std::path::Path;

const GOOD: &str = include_str!("scenes/good.toml");

use super::{err, refused};

#[test]
fn good_scene_parses_with_defaults() {
    let s = parse(Path::new("good.toml"), GOOD).unwrap();
    assert_eq!(s.n(), 64);
    assert_eq!(s.times().len(), 33);
    assert_eq!(s.ensembles(), 100);
    assert_eq!(s.name(), "good");
}

#[test]
fn restitution_out_of_range_names_line_and_key() {
    refused(
        &GOOD.replace("restitution = 0.5", "restitution = 1.5"),
        "bad.toml:6: `collisions.restitution` must lie in (0, 1]",
    );
    refused(
        &GOOD.replace("restitution = 0.5", "restitution = 0.0"),
        "bad.toml:6: `collisions.restitution`",
    );
}

#[test]
fn too_few_particles() {
    refused(
        &GOOD.replace("n = 64", "n = 1"),
        "bad.toml:3: `particles.n` must be >= 2",
    );
}

#[test]
fn negative_rate() {
    refused(
        &GOOD.replace("beta = 1.0", "beta = -1.0"),
        "bad.toml:9: `drive.beta` must be >= 0",
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
fn a_velocity_has_three_components() {
    let text = GOOD.replace(
        "n = 64",
        "n = 64\n[particles.initial]\ndrift = [1.0, 2.0, 3.0, 4.0]",
    );
    let e = err(&text);
    assert!(
        e.contains("bad.toml")
            && e.contains("line 5")
            && e.contains("invalid length 4, expected an array of 3 numbers"),
        "{e}"
    );
}

#[test]
fn times_out_of_order() {
    refused(
        &GOOD.replace("t_end = 1.0", "t_start = 2.0\nt_end = 1.0"),
        "bad.toml:12: `observe.t_end` must be later than observe.t_start",
    );
}

#[test]
fn histogram_tables_are_validated() {
    refused(
        &format!("{GOOD}[marginal_histogram]\naxis = 4\nbins = 10\nradius = 3.0\n"),
        "bad.toml:13: `marginal_histogram.axis` must be 1, 2 or 3",
    );
    refused(
        &format!("{GOOD}[reduced_histogram]\nshells = 0\nradius = 3.0\n"),
        "bad.toml:13: `reduced_histogram.shells` must lie in 1..=100000, got 0",
    );
    refused(
        &format!("{GOOD}[reduced_histogram]\nshells = 10\nradius = -1.0\n"),
        "bad.toml:14: `reduced_histogram.radius`",
    );
    refused(
        &format!("{GOOD}[marginal_histogram]\nbins = 10\nradius = 3.0\nbin = 2\n"),
        "unknown field `bin`",
    );
}

#[test]
fn kernel_specific_keys() {
    refused(
        &GOOD.replace("kernel = \"maxwell\"", "kernel = \"vhs\""),
        "`collisions.lambda` is required",
    );
    refused(
        &GOOD.replace("kernel = \"maxwell\"", "kernel = \"vhs\"\nlambda = 1.5"),
        "bad.toml:6: `collisions.lambda` must lie in [0, 1]",
    );
}

mod overrides {
    use gdsmc_scene::{SchemeChoice, parse_with_overrides};
    use std::path::Path;

    fn with(sets: &[&str]) -> Result<gdsmc_scene::Scene, String> {
        let sets: Vec<String> = sets.iter().map(|s| s.to_string()).collect();
        parse_with_overrides(Path::new("bad.toml"), super::GOOD, &sets).map_err(|e| e.to_string())
    }

    #[test]
    fn set_reaches_nested_keys_and_new_tables() {
        let s = with(&[
            "collisions.restitution=0.4",
            "particles.n=10",
            "scheme.kind=strang",
            "scheme.dt=0.125",
            "observe.intervals=8",
        ])
        .unwrap();
        assert_eq!(
            s.physics().restitution,
            gdsmc_scene::RestitutionLaw::Constant(0.4)
        );
        assert_eq!(s.n(), 10);
        assert_eq!(s.physics().scheme, SchemeChoice::Strang(0.125));
        let s = with(&["collisions.kernel=vhs", "collisions.lambda=0.5"]).unwrap();
        assert!(s.physics().kernel.get("lambda") == Some(0.5));
    }

    #[test]
    fn set_is_validated_like_the_file() {
        let e = with(&["collisions.restitution=1.5"]).unwrap_err();
        assert_eq!(
            e,
            "--set: `collisions.restitution` must lie in (0, 1], got 1.5"
        );
        let e = with(&["particles.m=3"]).unwrap_err();
        assert!(
            e.starts_with("--set: `particles.m` does not fit the scene schema")
                && e.contains("unknown field `m`"),
            "{e}"
        );
        // The bad one of several is named alone, by its own source.
        let e = with(&["collisions.restitution=0.4", "particles.m=3"]).unwrap_err();
        assert!(
            e.starts_with("--set: `particles.m` does not fit the scene schema"),
            "{e}"
        );
        let e = with(&["collisions.restitution=1.5", "particles.m=3"]).unwrap_err();
        assert!(
            e.starts_with("--set: `particles.m` does not fit the scene schema"),
            "{e}"
        );
        let e = with(&["particles.m=3", "collisions.restitution=0.4"]).unwrap_err();
        assert!(
            e.starts_with("--set: `particles.m` does not fit the scene schema"),
            "{e}"
        );
        let e = with(&["particles.n"]).unwrap_err();
        assert!(e.contains("must have the form key.path=value"), "{e}");
        let e = with(&["particles.n.x=3"]).unwrap_err();
        assert!(e.contains("`n` is a value, not a table"), "{e}");
        let e = with(&["scheme.kind=euler"]).unwrap_err();
        assert!(e.contains("`scheme.dt` is required"), "{e}");
        let e = with(&["scheme.kind=euler", "scheme.dt=0.3"]).unwrap_err();
        assert!(
            e.contains("`scheme.dt` must divide every observation time"),
            "{e}"
        );
    }

    /// Nothing the user wrote is dropped: a value with a line break (which would smuggle in a
    /// second key) and a velocity with more or fewer than three elements are refused.
    #[test]
    fn nothing_written_is_dropped() {
        let e = with(&["collisions.restitution=0.5\nfoo = 1"]).unwrap_err();
        assert_eq!(
            e,
            "--set: `collisions.restitution` must be one line: the value holds a line break"
        );
        let e = with(&["drive.kind=host-medium", "drive.drift=[0, 0, 0, 4]"]).unwrap_err();
        assert!(
            e.contains("invalid length 4, expected an array of 3 numbers"),
            "{e}"
        );
        let e = with(&["particles.initial.drift=[1.0, 2.0]"]).unwrap_err();
        assert!(
            e.contains("invalid length 2, expected an array of 3 numbers"),
            "{e}"
        );
        let s = with(&["particles.initial.drift=[1.0, 2.0, 3.0]"]).unwrap();
        assert_eq!(s.physics().initial[0].drift, [1.0, 2.0, 3.0]);
    }

    #[test]
    fn file_errors_keep_their_lines_even_with_overrides() {
        let bad = super::GOOD.replace("n = 64", "n = 1");
        let e = parse_with_overrides(Path::new("bad.toml"), &bad, &["particles.n=10".into()])
            .unwrap_err()
            .to_string();
        assert!(e.starts_with("bad.toml:3: `particles.n`"), "{e}");
    }
}

/// `--n`, `--ensembles` and `--seed` are overrides of their keys: the file's rules, with the
/// flag named in the error.
#[test]
fn flags_are_validated_like_the_file() {
    use gdsmc_scene::{Override, parse_with};
    let with = |o: Override| parse_with(Path::new("good.toml"), GOOD, &[o]);
    let e = with(Override::flag("n", "particles.n", 1))
        .unwrap_err()
        .to_string();
    assert_eq!(
        e,
        "--n: `particles.n` must be >= 2 (a pair is needed to collide), got 1"
    );
    let e = with(Override::flag("ensembles", "run.ensembles", 0))
        .unwrap_err()
        .to_string();
    assert_eq!(e, "--ensembles: `run.ensembles` must be >= 1, got 0");
    let e = with(Override::flag("n", "particles.n", -3))
        .unwrap_err()
        .to_string();
    assert!(
        e.starts_with("--n: `particles.n` does not fit the scene schema"),
        "{e}"
    );
    let s = with(Override::flag("seed", "run.seed", 42)).unwrap();
    assert_eq!((s.seed(), s.n()), (42, 64));
}

/// A physics changed in code after the file was read is validated again, by the same rules as
/// the file's (the core's validation, the scheme's grid), naming the key; a refused change
/// leaves the scene and its model as they were.
#[test]
fn a_changed_physics_is_validated_again() {
    use gdsmc_scene::{RestitutionLaw, SchemeChoice};
    let mut s = parse(Path::new("good.toml"), GOOD).unwrap();
    let before = s.clone();
    let e = s
        .with_physics(|ph| ph.restitution = RestitutionLaw::Constant(1.5))
        .unwrap_err()
        .to_string();
    assert!(
        e.contains("`collisions.restitution` must lie in (0, 1]"),
        "{e}"
    );
    assert_eq!(s, before);
    // The observation times are multiples of 1/32: dt = 0.3 does not divide them.
    let e = s
        .with_physics(|ph| ph.scheme = SchemeChoice::Strang(0.3))
        .unwrap_err()
        .to_string();
    assert!(
        e.contains("`scheme.dt` must divide every observation time"),
        "{e}"
    );
    assert_eq!(s, before);
    let e = s.set_n(1).unwrap_err().to_string();
    assert!(
        e.starts_with("scene good: `particles.n` must be >= 2"),
        "{e}"
    );
    // An accepted change reaches the model the runs start from.
    s.with_physics(|ph| ph.scheme = SchemeChoice::Strang(1.0 / 32.0))
        .unwrap();
    s.set_n(100).unwrap();
    assert_eq!(s.model().n(), 100);
    assert_eq!(s.physics().scheme, SchemeChoice::Strang(1.0 / 32.0));
}

/// `Scene::set_times` keeps the steady-state window's start time (the index follows it into the
/// new times) and drops the window when fewer than two new times lie in it.
#[test]
fn set_times_keeps_the_steady_windows_start_time() {
    let text = std::fs::read_to_string(
        Path::new(env!("CARGO_MANIFEST_DIR")).join("../scenes/brs-example4.toml"),
    )
    .unwrap();
    let mut s = parse(Path::new("brs-example4.toml"), &text).unwrap();
    let start = s.times()[s.steady_from().unwrap()];
    assert_eq!(start, 0.5);
    s.set_times(vec![0.0, 0.25, 0.75, 1.0, 2.0]).unwrap();
    assert_eq!(
        s.steady_from(),
        Some(2),
        "the first new time at or after t = 0.5"
    );
    s.set_times(vec![0.0, 0.1, 0.2, 0.8]).unwrap();
    assert_eq!(s.steady_from(), None, "one time in the window is no window");
}

#[test]
fn log_spacing_gives_decades_at_equal_resolution() {
    let text = GOOD.replace(
        "t_end = 1.0",
        "t_end = 1000.0\nintervals = 4\nspacing = \"log\"\nfirst = 1.0",
    );
    let s = parse(Path::new("log.toml"), &text).unwrap();
    let t = s.times();
    assert_eq!(t.len(), 5);
    assert_eq!((t[0], t[4]), (0.0, 1000.0));
    for (k, want) in [(1, 1.0), (2, 10.0), (3, 100.0)] {
        assert!((t[k] - want).abs() < 1e-12 * want, "{t:?}");
    }
    // The default first observation is the linear grid's.
    let text = GOOD.replace(
        "t_end = 1.0",
        "t_end = 8.0\nintervals = 8\nspacing = \"log\"",
    );
    let t = parse(Path::new("log.toml"), &text)
        .unwrap()
        .times()
        .to_vec();
    assert_eq!((t[1], t[8]), (1.0, 8.0));
    assert!(t.windows(2).all(|w| w[1] > w[0]), "{t:?}");
}

#[test]
fn spacing_and_first_are_checked() {
    refused(
        &GOOD.replace("t_end = 1.0", "t_end = 1.0\nspacing = \"logarithmic\""),
        "bad.toml:12: `observe.spacing` must be \"linear\" or \"log\", got \"logarithmic\"",
    );
    // `first` is checked under either spacing, and a linear grid ignores it.
    refused(
        &GOOD.replace("t_end = 1.0", "t_end = 1.0\nfirst = -0.1"),
        "bad.toml:12: `observe.first` must be > 0, got -0.1",
    );
    let linear = GOOD.replace("t_end = 1.0", "t_end = 1.0\nintervals = 4\nfirst = 0.1");
    let t = parse(Path::new("l.toml"), &linear)
        .unwrap()
        .times()
        .to_vec();
    assert_eq!(t, [0.0, 0.25, 0.5, 0.75, 1.0]);
    refused(
        &GOOD.replace("t_end = 1.0", "t_end = 1.0\nspacing = \"log\"\nfirst = 2.0"),
        "bad.toml:13: `observe.first` must be below t_end - t_start = 1, got 2",
    );
    refused(
        &GOOD.replace("t_end = 1.0", "t_end = 1.0\nspacing = \"log\"\nfirst = 0.0"),
        "bad.toml:13: `observe.first` must be > 0, got 0",
    );
}

/// The merged text (what the browser page offers for download) is the scene the overrides
/// make: read alone it validates to the same scene, and without overrides it is the file's own
/// text; an override the rules refuse is refused there too, with the same words.
#[test]
fn the_merged_text_is_the_overridden_scene() {
    use gdsmc_scene::{Override, merged_text, parse_with};
    let sets = [
        Override::set("particles.n=128"),
        Override::set("collisions.restitution=0.7"),
        Override::flag("seed", "run.seed", 9),
    ];
    let path = Path::new("good.toml");
    let merged = merged_text(path, GOOD, &sets).unwrap();
    let direct = parse_with(path, GOOD, &sets).unwrap();
    let alone = parse(Path::new("merged.toml"), &merged).unwrap();
    assert_eq!(alone.n(), 128);
    assert_eq!(alone.seed(), 9);
    assert_eq!(
        format!("{:?}", alone.physics()),
        format!("{:?}", direct.physics())
    );
    assert_eq!(alone.times(), direct.times());
    assert_eq!(merged_text(path, GOOD, &[]).unwrap(), GOOD);
    let bad = [Override::set("particles.n=1")];
    assert_eq!(
        merged_text(path, GOOD, &bad).unwrap_err().to_string(),
        parse_with(path, GOOD, &bad).unwrap_err().to_string()
    );
}
