//! Trust nothing a file says (issue 77): files a careless or hostile user plants beside an
//! output place, driven through the `gdsmc` command. Run against 03e7324 (before the fix), the
//! planted-claim test failed at its first case: `staging .` removed the whole directory with
//! the user's thesis in it, and the command exited 0 without a word.

use super::command::{gdsmc, leftovers, ok, root, s, small_run, tree};
use super::faults::{holds, long_run, small_sweep, wait_for};
use std::path::Path;

/// The user's files in `dir`: a thesis chapter, a data file, and a directory of the user's
/// that happens to be named like a staging directory of the place `res`.
fn users_files(dir: &Path) {
    std::fs::create_dir_all(dir.join("thesis")).unwrap();
    std::fs::write(dir.join("thesis/ch1.tex"), "\\chapter{One}\n").unwrap();
    std::fs::write(dir.join("data.csv"), "t,T\n0,1\n").unwrap();
    std::fs::create_dir_all(dir.join(".res.partial-77")).unwrap();
    std::fs::write(dir.join(".res.partial-77/keep.txt"), "mine\n").unwrap();
}

/// A claim file as gdsmc writes one (its signature), planted at the place `res` in `dir`,
/// naming `staging` and, when given, a token.
fn plant(dir: &Path, staging: &str, token: Option<&str>) {
    let mut text = format!("gdsmc claim\npid 1\nsince 0\nstaging {staging}\n");
    if let Some(t) = token {
        text.push_str(&format!("token {t}\n"));
    }
    std::fs::write(dir.join(".res.gdsmc-claim"), text).unwrap();
}

/// A planted claim naming `.`, a sibling directory, or a user's directory with a staging
/// name (with and without a token, and with a marker the planter wrote) deletes nothing, in
/// run, merge and sweep alike, and the command names what it left in a warning.
#[test]
fn a_planted_claim_deletes_nothing_in_run_merge_and_sweep() {
    let r = root("planted-claims");
    let shards = r.join("shards");
    for k in ["0/2", "1/2"] {
        ok(&small_run(
            "grw-example3",
            &["--shard", k, "--out", s(&shards)],
        ));
    }
    let token = "0123456789abcdef0123456789abcdef";
    let cases: [(&str, Option<&str>); 5] = [
        (".", None),
        ("thesis", None),
        (".res.partial-77", None),
        (".res.partial-77", Some(token)),
        ("..", None),
    ];
    for command in ["run", "merge", "sweep"] {
        for (k, (staging, tok)) in cases.iter().enumerate() {
            let dir = r.join(format!("{command}-{k}"));
            users_files(&dir);
            // A marker in the user's directory (copied from a staging directory of another
            // run) whose token is not the planted claim's: still left. (One who can write the
            // claim's token into the user's directory can delete the directory anyway.)
            if tok.is_some() {
                std::fs::write(
                    dir.join(".res.partial-77/.gdsmc-staging"),
                    "gdsmc staging\ntoken 00000000000000000000000000000000\n",
                )
                .unwrap();
            }
            let before = tree(&dir);
            plant(&dir, staging, *tok);
            let out = dir.join("res");
            let o = match command {
                "run" => small_run("grw-example3", &["--out", s(&out)]),
                "merge" => gdsmc(&["merge", s(&shards), "--out", s(&out)]),
                _ => small_sweep("collisions.restitution=0.5,0.6", &["--out", s(&out)]),
            };
            ok(&o);
            let after: Vec<_> = tree(&dir)
                .into_iter()
                .filter(|(n, _)| !n.starts_with("res/") && n != "res/")
                .collect();
            assert_eq!(
                after, before,
                "{command} with a claim naming `{staging}` changed the user's files"
            );
            let said = format!(
                "{}{}",
                String::from_utf8_lossy(&o.stdout),
                String::from_utf8_lossy(&o.stderr)
            );
            // A name that is a path (`..`) is not even taken as a directory; every other
            // existing directory the claim names is named in the warning.
            if *staging != ".." {
                assert!(
                    said.contains("warning") && said.contains("not proven gdsmc's"),
                    "{command}, `{staging}`: no warning: {said}"
                );
            }
        }
    }
}

/// The staging directory of a killed run, which its claim names with the token of its
/// marker, is still removed by the next run at the place (the proof holds for gdsmc's own);
/// a killed run's directory whose marker was changed is left and named.
#[test]
fn a_killed_runs_staging_directory_is_proven_and_removed() {
    let r = root("killed-staging");
    let out = r.join("res");
    let child = long_run(&["--out", s(&out)]);
    let marked = || {
        std::fs::read_dir(&r)
            .into_iter()
            .flatten()
            .flatten()
            .map(|e| e.path())
            .find(|p| {
                p.file_name()
                    .is_some_and(|n| n.to_string_lossy().starts_with(".res.partial-"))
                    && p.join(".gdsmc-staging").exists()
            })
    };
    wait_for("the staging marker", || marked().is_some());
    drop(child);
    assert!(holds(&r, ".res.partial-"));
    ok(&small_run("grw-example3", &["--out", s(&out)]));
    assert!(!holds(&r, ".res.partial-"), "{:?}", leftovers(&r));
    assert!(!holds(&r, ".res.gdsmc-claim"), "{:?}", leftovers(&r));

    // Again, but the marker's token is changed after the kill: left, and named.
    let child = long_run(&["--out", s(&out)]);
    wait_for("the staging marker", || marked().is_some());
    drop(child);
    let staging = marked().unwrap();
    std::fs::write(
        staging.join(".gdsmc-staging"),
        "gdsmc staging\ntoken ffffffffffffffffffffffffffffffff\n",
    )
    .unwrap();
    let o = small_run("grw-example3", &["--out", s(&out)]);
    ok(&o);
    let err = String::from_utf8_lossy(&o.stderr);
    assert!(
        staging.exists(),
        "a directory that proves nothing was removed"
    );
    assert!(
        err.contains("does not hold the claim's token") && err.contains(s(&staging)),
        "{err}"
    );
}
