//! Hostile scenes end to end: every shipped scene with each key of the schema overridden by
//! each of a list of hostile values (several thousand mutated scenes, generated here), and
//! every scene file of the scene reader's fuzz corpus, go through the command's path: read,
//! validated, the work estimate's limits, then, when accepted, a run at a size that fits CI
//! (at most 32 particles and 2 ensembles; scenes whose estimate at that size is still above
//! 2e6 units are counted, not run). The classes of issue 18: no panic (any reading, validation, estimate or run), no
//! hang (bounded by the estimate), and no unwarned non-finite output: every column with a
//! non-finite value at some time is named by the run's `non-finite` warning.

use gdsmc_runner::analysis::warnings;
use gdsmc_runner::run::estimate::{check, estimate};
use std::path::{Path, PathBuf};

fn files(dir: &str) -> Vec<PathBuf> {
    let root = PathBuf::from(env!("CARGO_MANIFEST_DIR"))
        .join("..")
        .join(dir);
    let mut files: Vec<PathBuf> = std::fs::read_dir(root)
        .unwrap()
        .map(|e| e.unwrap().path())
        .collect();
    files.sort();
    files
}

/// Every key of the schema.
const KEYS: &[&str] = &[
    "particles.n",
    "particles.initial.temperature",
    "particles.initial.mass",
    "particles.initial.drift",
    "collisions.kernel",
    "collisions.gamma",
    "collisions.c",
    "collisions.lambda",
    "collisions.restitution",
    "drive.kind",
    "drive.beta",
    "drive.zeta",
    "drive.g",
    "drive.density",
    "drive.mass",
    "drive.temperature",
    "scheme.kind",
    "scheme.dt",
    "scheme.step_factor",
    "observe.t_end",
    "observe.t_start",
    "observe.intervals",
    "observe.steady_from",
    "observe.collisional_pairs",
    "run.ensembles",
    "histogram.shells",
    "histogram.radius",
    "rotation.tangential_restitution",
    "rotation.inertia",
    "rotation.temperature",
    "rotation.noise",
    "particles.dimension",
];

/// Hostile values: zero, negative, tiny, huge, special, of the wrong type, too long.
const VALUES: &[&str] = &[
    "0",
    "-1",
    "5e-324",
    "1e-300",
    "1e300",
    "1.7976931348623157e308",
    "nan",
    "inf",
    "0.9",
    "2",
    "7",
    "9223372036854775807",
    "\"vhs\"",
    "\"time-stepped\"",
    "[1, 2, 3, 4]",
    "",
];

#[derive(Default, Debug)]
struct Tally {
    files: usize,
    refused: usize,
    refused_work: usize,
    too_long_for_ci: usize,
    engine_errors: usize,
    ran: usize,
    warned_non_finite: usize,
}

fn one(path: &Path, text: &str, sets: &[String], t: &mut Tally) {
    let Ok(mut s) = gdsmc_runner::scene::parse_with_overrides(path, text, sets) else {
        t.refused += 1;
        return;
    };
    if check(&s, 2, false).is_err() {
        t.refused_work += 1;
        return;
    }
    s.set_n(s.physics().n.min(32))
        .expect("a valid particle count");
    s.set_ensembles(s.ensembles().min(2)).unwrap();
    if estimate(&s).total() > 2e6 {
        t.too_long_for_ci += 1;
        return;
    }
    match gdsmc_runner::run::run(&s, 1, &|_| {}) {
        Err(e) => {
            assert!(!e.to_string().is_empty());
            t.engine_errors += 1;
        }
        Ok(st) => {
            t.ran += 1;
            let w = warnings::check(&s, &st);
            let named = w
                .iter()
                .find(|w| w.code == "non-finite")
                .map(|w| w.message.clone());
            for (c, name) in st.names.iter().enumerate() {
                let bad = (0..st.times.len()).any(|ti| {
                    !st.mean(ti, c).is_finite() || (st.ensembles > 1 && !st.ci(ti, c).is_finite())
                });
                if bad {
                    let m = named.as_deref().unwrap_or("");
                    assert!(
                        m.contains(&format!("{name} from t =")),
                        "{}: {name} is non-finite without a warning naming it\n{text}",
                        path.display()
                    );
                }
            }
            t.warned_non_finite += named.is_some() as usize;
        }
    }
}

#[test]
#[ignore = "long suite: cargo test --workspace --release -- --include-ignored (README, CI)"]
fn mutated_scenes_never_panic_hang_or_hide_a_nan() {
    let mut t = Tally::default();
    let mut cases: Vec<(PathBuf, String, Vec<String>)> = Vec::new();
    for path in files("scenes") {
        let text = std::fs::read_to_string(&path).unwrap();
        for key in KEYS {
            for value in VALUES {
                cases.push((path.clone(), text.clone(), vec![format!("{key}={value}")]));
            }
        }
    }
    for path in files("fuzz/corpus/scene_reader") {
        if let Ok(text) = std::fs::read_to_string(&path) {
            cases.push((path, text, Vec::new()));
        }
    }
    for (path, text, sets) in &cases {
        t.files += 1;
        let r = std::panic::catch_unwind(std::panic::AssertUnwindSafe(|| {
            one(path, text, sets, &mut t)
        }));
        assert!(r.is_ok(), "{} {sets:?} panicked", path.display());
    }
    eprintln!("{t:?}");
    assert!(t.files > 5000, "{t:?}");
    assert!(t.ran > 300, "too few scenes ran to say anything: {t:?}");
}
