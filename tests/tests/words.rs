//! One meaning per word a user reads (issue 79): the thermal speed is `v0 = sqrt(2 T/m)`
//! (docs/scenes.md, "Units and conventions"), and `sqrt(T)`, a velocity component's standard
//! deviation, is never called one, nor is a count of speeds written without its unit. The
//! scanner is tested on planted lines first.

use std::fs;
use std::path::{Path, PathBuf};

/// Whether `line` calls `sqrt(T)` a thermal speed or counts thermal speeds with a number.
fn mixes_the_thermal_speed(line: &str) -> bool {
    let l = line.to_lowercase();
    l.match_indices("thermal speed").any(|(i, w)| {
        let after: String = l[i + w.len()..].chars().take(24).collect();
        let before = l[..i].trim_end();
        let counted = before
            .chars()
            .next_back()
            .is_some_and(|c| c.is_ascii_digit());
        let called = after.contains("sqrt(t)") || after.contains("sqrt(t_bulk)");
        counted || called
    })
}

/// Every file a user or a contributor reads for words: the top-level docs, docs/, the scenes,
/// the sources of every crate, the tools and the Python package (not CHANGELOG.md, a history).
fn files() -> Vec<PathBuf> {
    let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("..");
    let mut out = vec![root.join("README.md"), root.join("ARCHITECTURE.md")];
    let mut dirs = vec![
        root.join("docs"),
        root.join("scenes"),
        root.join("tools"),
        root.join("python/gdsmc"),
        root.join("tests/tests"),
    ];
    for c in [
        "core",
        "scene",
        "theory",
        "std-runner",
        "ffi",
        "stats",
        "web",
    ] {
        dirs.push(root.join(c).join("src"));
    }
    while let Some(d) = dirs.pop() {
        for e in fs::read_dir(&d).into_iter().flatten().flatten() {
            let p = e.path();
            if p.is_dir() {
                dirs.push(p);
            } else if p
                .extension()
                .is_some_and(|x| ["md", "rs", "toml", "py"].contains(&x.to_str().unwrap_or("")))
                && p.file_name().is_some_and(|n| n != "words.rs")
            {
                out.push(p);
            }
        }
    }
    out
}

#[test]
fn the_scanner_catches_what_it_must() {
    assert!(mixes_the_thermal_speed(
        "beyond 8 thermal speeds the weight"
    ));
    assert!(mixes_the_thermal_speed(
        "in thermal speeds `sqrt(T)` from the flow"
    ));
    assert!(mixes_the_thermal_speed("a Thermal speed sqrt(T_bulk) wide"));
    assert!(!mixes_the_thermal_speed(
        "the thermal speed sqrt(2 T) = 1.4"
    ));
    assert!(!mixes_the_thermal_speed("beyond 8 sqrt(T), the weight"));
    assert!(!mixes_the_thermal_speed(
        "large against the thermal speed (cooling gases)"
    ));
}

#[test]
fn the_thermal_speed_has_one_meaning() {
    let mut bad = Vec::new();
    let files = files();
    assert!(files.len() > 200, "only {} files found", files.len());
    for f in files {
        let Ok(text) = fs::read_to_string(&f) else {
            continue;
        };
        for (k, line) in text.lines().enumerate() {
            if mixes_the_thermal_speed(line) {
                bad.push(format!("{}:{}: {}", f.display(), k + 1, line.trim()));
            }
        }
    }
    assert!(
        bad.is_empty(),
        "the thermal speed is sqrt(2 T/m); sqrt(T) is a component's spread:\n{}",
        bad.join("\n")
    );
}
