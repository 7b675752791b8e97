//! Every limit holds (issue 32): a key set twice, a step that takes no step, the work
//! estimate with its heating, outputs that would not fit, and the smaller items of that
//! issue, each refused with words that name it, driven through the `gdsmc` command.

use super::command::{gdsmc, leftovers, ok, refused, root, s, scene, small_run};
use std::process::Command;
use std::time::{Duration, Instant};

/// A `--set` of a key a shorthand flag also sets is refused naming both, never dropped; so is
/// a key given twice by `--set`.
#[test]
fn a_key_set_twice_is_refused() {
    let r = root("twice");
    let out = r.join("o");
    let o = Command::new(env!("CARGO_BIN_EXE_gdsmc"))
        .arg("run")
        .arg(scene("grw-example3"))
        .args(["--n", "64", "--set", "particles.n=nan", "--ensembles", "2"])
        .args(["--out", s(&out)])
        .output()
        .unwrap();
    refused(&o, &["particles.n", "set twice", "--n", "--set"]);
    let o = Command::new(env!("CARGO_BIN_EXE_gdsmc"))
        .arg("run")
        .arg(scene("grw-example3"))
        .args(["--n", "64", "--ensembles", "2", "--set", "run.ensembles=0"])
        .args(["--out", s(&out)])
        .output()
        .unwrap();
    refused(&o, &["run.ensembles", "set twice"]);
    refused(
        &small_run(
            "grw-example3",
            &[
                "--set",
                "collisions.restitution=0.4",
                "--set",
                "collisions.restitution=0.6",
                "--out",
                s(&out),
            ],
        ),
        &["collisions.restitution", "set twice"],
    );
    assert!(!out.exists());
}

/// A splitting step longer than the run (no step would ever be taken) is refused naming
/// `scheme.dt` (the engine's grid rule, `grid_index`, is tested in the core).
#[test]
fn a_step_that_takes_no_step_is_refused() {
    let r = root("dt");
    // rw-steady observes from 8 to 136.
    for dt in ["1e300", "1.7976931348623157e308", "1000"] {
        let set = format!("scheme.dt={dt}");
        refused(
            &small_run(
                "rw-steady",
                &[
                    "--set",
                    "scheme.kind=strang",
                    "--set",
                    &set,
                    "--out",
                    s(&r.join("o")),
                ],
            ),
            &["scheme.dt", "span"],
        );
    }
    assert!(!r.join("o").exists());
}

/// The smaller items: one ensemble says it has no intervals; a shard count above the ensemble
/// count is refused; a duplicated shard's message says "shard" once; a tiny inertia names
/// itself; a failed run leaves no journal or staging directory behind.
#[test]
fn the_smaller_items() {
    let r = root("small");
    let one = r.join("one");
    let o = Command::new(env!("CARGO_BIN_EXE_gdsmc"))
        .arg("run")
        .arg(scene("grw-example3"))
        .args(["--n", "64", "--ensembles", "1", "--out", s(&one)])
        .output()
        .unwrap();
    ok(&o);
    assert!(String::from_utf8_lossy(&o.stdout).contains("note: one ensemble"));
    let summary: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(one.join("summary.json")).unwrap()).unwrap();
    let note = summary["no_intervals"].as_str().unwrap_or("");
    assert!(note.contains("_ci column"), "{summary}");
    // Two ensembles: no such note.
    let two = r.join("two");
    ok(&small_run("grw-example3", &["--out", s(&two)]));
    let summary: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(two.join("summary.json")).unwrap()).unwrap();
    assert!(summary["no_intervals"].is_null(), "{summary}");

    refused(
        &small_run(
            "grw-example3",
            &[
                "--shard",
                "0/18446744073709551615",
                "--out",
                s(&r.join("x")),
            ],
        ),
        &["--shard", "run.ensembles"],
    );
    refused(
        &small_run(
            "grw-example3",
            &["--shard", "2/3", "--out", s(&r.join("x"))],
        ),
        &["3 shards of a run of 2 ensembles"],
    );

    let d = r.join("d");
    for k in ["0/2", "1/2"] {
        ok(&small_run("grw-example3", &["--shard", k, "--out", s(&d)]));
    }
    let f = d.join("grw-example3.shard-0-of-2.gdsmc-ensembles");
    let copy = r.join("copy.gdsmc-ensembles");
    std::fs::copy(&f, &copy).unwrap();
    let o = gdsmc(&["merge", s(&d), s(&copy), "--out", s(&r.join("m"))]);
    refused(&o, &["shard 0/2 given twice"]);
    assert!(!String::from_utf8_lossy(&o.stderr).contains("shard shard"));

    refused(
        &small_run(
            "rough-hcs",
            &["--set", "rotation.inertia=5e-324", "--out", s(&r.join("x"))],
        ),
        &["rotation.inertia", "too small"],
    );

    // An engine failure (the Gaussian thermostat drives the velocities out of f64) leaves
    // nothing behind.
    let fail = r.join("fail");
    std::fs::create_dir(&fail).unwrap();
    let o = small_run(
        "ms-gaussian",
        &[
            "--set",
            "drive.zeta=1e6",
            "--set",
            "observe.collisional_pairs=10",
            "--out",
            s(&fail.join("out")),
        ],
    );
    refused(&o, &["non-finite"]);
    assert!(leftovers(&fail).is_empty(), "{:?}", leftovers(&fail));
    assert!(!fail.join("out").exists());
}

/// The Gaussian thermostat's heating is in the work estimate: at zeta = 3000 (MS's scene,
/// about 10^4 times its own zeta) the collision candidates done are within a factor 3 of the
/// candidates estimated (before: 10^4 times more done than estimated, and zeta = 20000 ran
/// for minutes unrefused); at zeta = 3e6 the run is refused by the work limit up front.
#[test]
fn heating_is_in_the_work_estimate() {
    use gdsmc_runner::run::estimate::estimate;
    let r = root("heating");
    let sets = [
        "drive.zeta=3000",
        "observe.t_end=4",
        "observe.intervals=4",
        "observe.steady_from=1",
        "observe.collisional_pairs=10",
        "particles.n=64",
        "run.ensembles=2",
    ];
    let sets: Vec<String> = sets.iter().map(|x| x.to_string()).collect();
    let sc = gdsmc_runner::scene::load_with_overrides(&scene("ms-gaussian"), &sets).unwrap();
    let e = estimate(&sc);
    let stats = gdsmc_runner::run::run(&sc, 1, &|_| {}).unwrap();
    let done = stats.counts.candidates as f64;
    let ratio = done / e.events;
    assert!(
        (1.0 / 3.0..=3.0).contains(&ratio),
        "candidates done {done:.3e}, estimated {:.3e} (ratio {ratio:.2})",
        e.events
    );
    let o = small_run(
        "ms-gaussian",
        &["--set", "drive.zeta=3e6", "--out", s(&r.join("o"))],
    );
    refused(&o, &["above the limit", "--allow-long"]);
}

/// Observation times whose outputs would not fit are refused up front, naming
/// `observe.intervals`, before any memory is taken for them.
#[test]
fn outputs_that_would_not_fit_are_refused() {
    let r = root("rows");
    let t0 = Instant::now();
    refused(
        &small_run(
            "grw-example3",
            &[
                "--set",
                "observe.intervals=10000000",
                "--out",
                s(&r.join("o")),
            ],
        ),
        &[
            "observe.intervals",
            "values per ensemble",
            "observe fewer times",
        ],
    );
    assert!(t0.elapsed() < Duration::from_secs(60));
    assert!(!r.join("o").exists());
}
