//! Every duration the README states is measured, not written: the README's timing block is the
//! one `tools/timings.py` wrote into docs/timings.md (with the machine, its load and the
//! commit), and no other file a user reads for "how long" (README.md, ARCHITECTURE.md, the
//! Python and firmware READMEs, docs/*.md, `gdsmc --help`) states a duration by hand. The
//! measurement records (docs/timings.md, docs/speed.md, docs/tails-full.md,
//! docs/reproduce-full.md, docs/work-precision.md: each the output of a stated command on a
//! stated machine) and the histories (CHANGELOG.md, fuzz/README.md's table of findings) are
//! not scanned.

use std::fs;
use std::path::{Path, PathBuf};

const BEGIN: &str = "<!-- timings -->";
const END: &str = "<!-- /timings -->";

/// Records of measurements, each made by the command it names on the machine it states.
const RECORDS: [&str; 6] = [
    "ci.md",
    "timings.md",
    "speed.md",
    "tails-full.md",
    "reproduce-full.md",
    "work-precision.md",
];

/// Durations that are settings, not claims: the fuzz stage's time budget per target.
const SETTINGS: [&str; 2] = ["each target for 20 seconds", "those 20 seconds"];

fn root() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .parent()
        .expect("tests/ has a parent")
        .to_path_buf()
}

fn block(text: &str) -> Option<&str> {
    let i = text.find(BEGIN)? + BEGIN.len();
    let j = text[i..].find(END)? + i;
    Some(text[i..j].trim())
}

/// The durations written in `text`: a number (digits, or one to ten in words) followed by a
/// unit of time (`s`, `min`, `minutes`, `seconds`, `hours`, ...), a number glued to its unit
/// (`15s`, `3min`), or "about a second/minute/hour". Returns (line, phrase).
fn durations(text: &str) -> Vec<(usize, String)> {
    const UNITS: [&str; 10] = [
        "s", "sec", "secs", "second", "seconds", "min", "mins", "minute", "minutes", "hours",
    ];
    const WORDS: [&str; 10] = [
        "one", "two", "three", "four", "five", "six", "seven", "eight", "nine", "ten",
    ];
    let is_number = |w: &str| {
        !w.is_empty()
            && w.chars().all(|c| c.is_ascii_digit() || c == '.')
            && w.chars().any(|c| c.is_ascii_digit())
    };
    let mut out = Vec::new();
    for (k, line) in text.lines().enumerate() {
        if SETTINGS.iter().any(|s| line.contains(s)) {
            continue;
        }
        let words: Vec<&str> = line
            .split(|c: char| c.is_whitespace() || "()[],;:`*".contains(c))
            .filter(|w| !w.is_empty())
            .map(|w| w.trim_end_matches(['.', '!', '?']))
            .collect();
        for (i, w) in words.iter().enumerate() {
            let next = words.get(i + 1).copied().unwrap_or("");
            let glued = UNITS
                .iter()
                .any(|u| w.strip_suffix(u).is_some_and(is_number));
            let counted = (is_number(w) || WORDS.contains(&w.to_lowercase().as_str()))
                && UNITS.contains(&next);
            let about_a = w.eq_ignore_ascii_case("about")
                && next == "a"
                && words
                    .get(i + 2)
                    .is_some_and(|u| ["second", "minute", "hour"].contains(u));
            if glued || counted || about_a {
                out.push((k + 1, format!("{w} {next}")));
            }
        }
    }
    out
}

#[test]
fn the_scanner_finds_hand_written_durations() {
    let found = |t: &str| !durations(t).is_empty();
    assert!(found(
        "The first build takes about three minutes on two cores"
    ));
    assert!(found("measured: 3 min 1 s for the release build"));
    assert!(found("Regenerate (15 s on 2 cores):"));
    assert!(found("in about a second"));
    assert!(found("(30s; scenes/x.toml)"));
    assert!(found("the tests about 2.5 minutes after it"));
    assert!(!found(
        "a second nalgebra; n = 16 s-waves; 4 cores; --seconds S"
    ));
    assert!(!found("runs each target for 20 seconds under ASan"));
}

#[test]
fn the_readme_block_is_the_measured_one() {
    // The measuring run itself (tools/timings.py runs the test command on a clone whose block
    // is the previous one, or none) cannot hold its own result yet.
    if std::env::var_os("GDSMC_TIMINGS_RUN").is_some() {
        eprintln!("timings block not checked: tools/timings.py is measuring");
        return;
    }
    let r = root();
    let readme = fs::read_to_string(r.join("README.md")).expect("README.md");
    let timings = fs::read_to_string(r.join("docs/timings.md"))
        .expect("docs/timings.md: run `python3 tools/timings.py`");
    let ours = block(&readme).expect("README.md has the timings block");
    let theirs = block(&timings).expect("docs/timings.md has the README's block");
    assert!(
        !ours.is_empty(),
        "README's timings block is empty: run tools/timings.py"
    );
    assert_eq!(
        ours, theirs,
        "README's timings block is not docs/timings.md's: run tools/timings.py"
    );
    for key in [
        "first-command",
        "quick-start-run",
        "test-build",
        "tests",
        "build-with-renderers",
        "long-suite",
        "python-install",
        "reproduce-quick",
    ] {
        assert!(
            timings.contains(&format!("(`{key}`)")),
            "docs/timings.md has no `{key}` row"
        );
    }
    assert!(timings.contains("- Machine: ") && timings.contains("load before"));
}

#[test]
fn no_duration_is_written_by_hand() {
    let r = root();
    let mut files = vec![
        r.join("README.md"),
        r.join("ARCHITECTURE.md"),
        r.join("python/README.md"),
        r.join("embedded/README.md"),
    ];
    for e in fs::read_dir(r.join("docs")).expect("docs/") {
        let p = e.expect("entry").path();
        let name = p.file_name().and_then(|n| n.to_str()).unwrap_or("");
        if name.ends_with(".md") && !RECORDS.contains(&name) {
            files.push(p);
        }
    }
    let mut found = Vec::new();
    for f in &files {
        let Ok(mut text) = fs::read_to_string(f) else {
            continue;
        };
        if let (Some(i), Some(j)) = (text.find(BEGIN), text.find(END)) {
            text.replace_range(i..j, "");
        }
        for (line, phrase) in durations(&text) {
            found.push(format!("{}:{line}: {phrase}", f.display()));
        }
    }
    // `gdsmc --help`: the doc comments of the command line.
    let main = fs::read_to_string(r.join("std-runner/src/main.rs")).expect("main.rs");
    let help: String = main
        .lines()
        .map(|l| {
            if l.trim_start().starts_with("///") {
                l
            } else {
                ""
            }
        })
        .collect::<Vec<_>>()
        .join("\n");
    for (line, phrase) in durations(&help) {
        found.push(format!("std-runner/src/main.rs:{line}: {phrase}"));
    }
    assert!(
        found.is_empty(),
        "durations written by hand (measure them with tools/timings.py, or remove them):\n{}",
        found.join("\n")
    );
}
