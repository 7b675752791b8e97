//! Every column name is spelled once, in the theory crate's `columns.rs` (`columns::name`, which
//! the runner's `run/columns.rs` table reads): no other source file of the theory, the runner,
//! its tests, the validation crate or the Python extension writes a base or
//! rough column's name as a string literal (a JSON key, followed by `:`, is a field of
//! summary.json, not a column). The scanner is tested to find one.

use gdsmc_runner::run::columns::{COLLISIONAL, COLUMNS, ROUGH_COLUMNS};
use std::path::{Path, PathBuf};

fn names() -> Vec<&'static str> {
    COLUMNS
        .iter()
        .map(|c| c.name)
        .chain(COLLISIONAL)
        .chain(ROUGH_COLUMNS)
        .collect()
}

/// The column names `text` writes as string literals (not JSON keys).
fn literals(text: &str, names: &[&str]) -> Vec<String> {
    let mut found = Vec::new();
    for name in names {
        let quoted = format!("\"{name}\"");
        let mut from = 0;
        while let Some(i) = text[from..].find(&quoted) {
            let at = from + i;
            let after = text[at + quoted.len()..].trim_start();
            let before = text[..at].chars().last();
            let key = after.starts_with(':') && !after.starts_with("::");
            if !key && before != Some('"') && before != Some('\\') {
                found.push(format!("{name} at byte {at}"));
            }
            from = at + quoted.len();
        }
    }
    found
}

fn rust_files(dir: &Path, out: &mut Vec<PathBuf>) {
    for e in std::fs::read_dir(dir).unwrap().flatten() {
        let p = e.path();
        if p.is_dir() {
            rust_files(&p, out);
        } else if p.extension().is_some_and(|x| x == "rs") {
            out.push(p);
        }
    }
}

#[test]
fn the_scanner_finds_a_column_literal_and_passes_a_json_key() {
    let n = names();
    assert_eq!(literals("stats.col(\"T_bulk\")", &n).len(), 1);
    assert_eq!(literals("[\"theta\", name::A2]", &n).len(), 1);
    assert!(literals("json!({ \"a2\": x })", &n).is_empty());
    assert!(literals("stats.col(name::T_BULK)", &n).is_empty());
}

#[test]
fn no_column_name_is_written_outside_the_column_table() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("..");
    let mut files = Vec::new();
    for dir in [
        "theory/src",
        "std-runner/src",
        "std-runner/tests",
        "tests/src",
        "tests/tests",
        "python/src",
    ] {
        rust_files(&root.join(dir), &mut files);
    }
    let n = names();
    let mut bad = Vec::new();
    for f in files {
        if f.ends_with("theory/src/columns.rs") || f.ends_with("tests/column_names.rs") {
            continue;
        }
        let text = std::fs::read_to_string(&f).unwrap();
        for hit in literals(&text, &n) {
            bad.push(format!("{}: {hit}", f.display()));
        }
    }
    assert!(bad.is_empty(), "column names outside columns.rs: {bad:#?}");
}
