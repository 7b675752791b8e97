//! `[sweep]`: what `gdsmc sweep` varies, in the syntax of `--vary`; read by `sweep_plan`, and
//! checked with the file (a bad table is refused at its line and key by any command).

use gdsmc_scene::vary::Combine;
use gdsmc_scene::{parse, sweep_plan};
use std::path::Path;

const BASE: &str = include_str!("scenes/sweep_base.toml");

#[test]
fn a_sweep_table_gives_its_plan() {
    let text = format!(
        "{BASE}[sweep]\nvary = [\"collisions.restitution=0.5:0.9:3\", \"particles.n=64,128,256\"]\nzip = true\n"
    );
    let plan = sweep_plan(Path::new("s.toml"), &text).unwrap().unwrap();
    assert_eq!(plan.combine, Combine::Zip);
    assert_eq!(plan.vary[0].key, "collisions.restitution");
    assert_eq!(plan.vary[0].values, ["0.5", "0.7", "0.9"]);
    assert_eq!(plan.vary[1].values, ["64", "128", "256"]);
    // The scene itself is the scene as written.
    assert_eq!(parse(Path::new("s.toml"), &text).unwrap().n(), 64);
    assert_eq!(sweep_plan(Path::new("s.toml"), BASE).unwrap(), None);
}

#[test]
fn a_bad_sweep_table_is_refused_at_its_line() {
    for (table, words) in [
        (
            "vary = [\"collisions.restitution=0.5:0.9\"]",
            "sweep.vary[0]",
        ),
        ("vary = [\"a=1,2\", \"b=1,2,3\"]\nzip = true", "one length"),
        ("vary = [\"a=1\", \"a=2\"]", "twice"),
        ("vary = []", "at least one"),
        ("values = [1]", "unknown field"),
    ] {
        let text = format!("{BASE}[sweep]\n{table}\n");
        let e = parse(Path::new("bad.toml"), &text).unwrap_err().to_string();
        assert!(e.contains(words), "{table}: {e}");
        if !words.contains("unknown") {
            assert!(e.starts_with("bad.toml:10:"), "{table}: {e}");
        }
    }
}
