//! Nothing a user owns is ever deleted or overwritten (issue 32; its limits: `limits.rs`): each
//! test is one way a careless or hostile user could lose data or get a run that lies, driven
//! through the `gdsmc` command as a user would. Every test here failed on the commit before
//! this file (checked; the note of issue 32 lists how each failed).

use super::command::{gdsmc, leftovers, ok, refused, root, s, scene, small_run, tree};
use std::path::PathBuf;
use std::process::Command;
use std::time::{Duration, Instant};
/// A directory holding a user's files (no gdsmc manifest) is refused at `--out` and left byte
/// for byte; so is one that is a gdsmc set with a file added, or changed since it was written.
/// An empty directory and a gdsmc set are replaced as before.
#[test]
fn a_users_directory_is_never_replaced() {
    let r = root("user-dir");
    let precious = r.join("precious");
    std::fs::create_dir_all(precious.join("sub")).unwrap();
    std::fs::write(precious.join("thesis.tex"), "draft\n").unwrap();
    std::fs::write(precious.join("sub/data.csv"), "1,2\n").unwrap();
    let before = tree(&precious);
    let o = small_run("grw-example3", &["--out", s(&precious)]);
    refused(&o, &["precious", "thesis.tex", "did not write"]);
    assert_eq!(tree(&precious), before);
    assert!(leftovers(&r).is_empty(), "{:?}", leftovers(&r));

    // An empty directory is taken; then the set is gdsmc's and is replaced by the next run.
    let out = r.join("out");
    std::fs::create_dir(&out).unwrap();
    ok(&small_run("grw-example3", &["--out", s(&out)]));
    ok(&small_run(
        "grw-example3",
        &["--out", s(&out), "--seed", "2"],
    ));
    // A file the user added to the set, or a file of the set the user changed, keeps it.
    std::fs::write(out.join("notes.txt"), "mine\n").unwrap();
    let before = tree(&out);
    refused(
        &small_run("grw-example3", &["--out", s(&out), "--seed", "3"]),
        &["notes.txt", "does not list"],
    );
    assert_eq!(tree(&out), before);
    std::fs::remove_file(out.join("notes.txt")).unwrap();
    let csv = out.join("observables.csv");
    let mut edited = std::fs::read(&csv).unwrap();
    edited.extend_from_slice(b"# my comment\n");
    std::fs::write(&csv, &edited).unwrap();
    let before = tree(&out);
    refused(
        &small_run("grw-example3", &["--out", s(&out), "--seed", "3"]),
        &["changed since gdsmc wrote it", "observables.csv"],
    );
    assert_eq!(tree(&out), before);
}

/// A regular file or a link at `--out` is refused and left as it is (`run` and `merge`).
#[test]
fn a_file_or_link_at_out_is_refused() {
    let r = root("file-out");
    let victim = r.join("victim.txt");
    std::fs::write(&victim, "hi\n").unwrap();
    refused(
        &small_run("grw-example3", &["--out", s(&victim)]),
        &["victim.txt", "not a directory"],
    );
    assert_eq!(std::fs::read(&victim).unwrap(), b"hi\n");
    let dir = r.join("real");
    std::fs::create_dir(&dir).unwrap();
    std::fs::write(dir.join("keep"), "x").unwrap();
    let link = r.join("link");
    std::os::unix::fs::symlink(&dir, &link).unwrap();
    refused(
        &small_run("grw-example3", &["--out", s(&link)]),
        &["symbolic link"],
    );
    assert_eq!(tree(&dir), vec![("keep".into(), b"x".to_vec())]);
    // merge: shards made, then a file at --out.
    let shards = r.join("shards");
    for k in ["0/2", "1/2"] {
        ok(&small_run(
            "grw-example3",
            &["--shard", k, "--out", s(&shards)],
        ));
    }
    let log = r.join("m.log");
    std::fs::write(&log, "log\n").unwrap();
    refused(
        &gdsmc(&["merge", s(&shards), "--out", s(&log)]),
        &["m.log", "not a directory"],
    );
    assert_eq!(std::fs::read(&log).unwrap(), b"log\n");
    assert!(leftovers(&r).is_empty(), "{:?}", leftovers(&r));
}

/// `merge D --out D` is refused before anything is written, the shards intact.
#[test]
fn merge_never_replaces_its_inputs() {
    let r = root("merge-into-inputs");
    let d = r.join("D");
    for k in ["0/2", "1/2"] {
        ok(&small_run("grw-example3", &["--shard", k, "--out", s(&d)]));
    }
    let before = tree(&d);
    refused(
        &gdsmc(&["merge", s(&d), "--out", s(&d)]),
        &["holds the shard", "merged set would replace it"],
    );
    assert_eq!(tree(&d), before);
    // The shards still merge elsewhere.
    ok(&gdsmc(&["merge", s(&d), "--out", s(&r.join("merged"))]));
}

/// A link planted at the journal's place (`.NAME.run.gdsmc-ensembles` beside the output, in a
/// shared directory anyone could plant it) is not followed: its target is unchanged and the
/// run is refused. A user's own file there, a FIFO, are refused too, never overwritten or
/// blocked on.
#[test]
fn the_journal_never_writes_through_a_link_or_over_a_users_file() {
    let r = root("journal-link");
    let target = r.join("target.txt");
    std::fs::write(&target, "secret\n").unwrap();
    std::os::unix::fs::symlink(&target, r.join(".sym.run.gdsmc-ensembles")).unwrap();
    refused(
        &small_run("grw-example3", &["--out", s(&r.join("sym"))]),
        &[".sym.run.gdsmc-ensembles", "symbolic link"],
    );
    assert_eq!(std::fs::read(&target).unwrap(), b"secret\n");
    assert!(!r.join("sym").exists());

    let mine = r.join(".mine.run.gdsmc-ensembles");
    std::fs::write(&mine, "my notes, not a journal\n").unwrap();
    refused(
        &small_run("grw-example3", &["--out", s(&r.join("mine"))]),
        &[".mine.run.gdsmc-ensembles", "not a gdsmc ensemble journal"],
    );
    assert_eq!(std::fs::read(&mine).unwrap(), b"my notes, not a journal\n");

    let fifo = r.join(".fifo.run.gdsmc-ensembles");
    assert!(
        Command::new("mkfifo")
            .arg(&fifo)
            .status()
            .unwrap()
            .success()
    );
    let t0 = Instant::now();
    refused(
        &small_run("grw-example3", &["--out", s(&r.join("fifo"))]),
        &["not a regular file"],
    );
    assert!(t0.elapsed() < Duration::from_secs(60));
}

/// The bytes of an ensemble file up to the end of its header (magic, format, length, JSON,
/// CRC), and the header's JSON.
pub(crate) fn split_header(b: &[u8]) -> (usize, serde_json::Value) {
    let len = u32::from_le_bytes(b[20..24].try_into().unwrap()) as usize;
    let json = serde_json::from_slice(&b[24..24 + len]).unwrap();
    (24 + len + 4, json)
}

/// An ensemble file with `json` as its header (a valid checksum) and `rest` after it.
pub(crate) fn with_header(b: &[u8], json: &serde_json::Value, rest: &[u8]) -> Vec<u8> {
    let text = serde_json::to_vec(json).unwrap();
    let mut out = b[..20].to_vec();
    out.extend_from_slice(&(text.len() as u32).to_le_bytes());
    out.extend_from_slice(&text);
    out.extend_from_slice(&crc32fast::hash(&text).to_le_bytes());
    out.extend_from_slice(rest);
    out
}

/// A shard whose records are another run's (same scene, another seed) after a valid header is
/// refused, naming the file; so is a journal's on resume (its records are run again).
#[test]
fn records_of_another_run_are_refused() {
    let r = root("spliced");
    let a = r.join("a");
    let b = r.join("b");
    for k in ["0/2", "1/2"] {
        ok(&small_run("grw-example3", &["--shard", k, "--out", s(&a)]));
        ok(&small_run(
            "grw-example3",
            &["--shard", k, "--out", s(&b), "--seed", "2"],
        ));
    }
    let name = "grw-example3.shard-0-of-2.gdsmc-ensembles";
    let fa = std::fs::read(a.join(name)).unwrap();
    let fb = std::fs::read(b.join(name)).unwrap();
    let (ha, _) = split_header(&fa);
    let (hb, _) = split_header(&fb);
    let mut spliced = fa[..ha].to_vec();
    spliced.extend_from_slice(&fb[hb..]);
    std::fs::write(a.join(name), &spliced).unwrap();
    refused(
        &gdsmc(&["merge", s(&a), "--out", s(&r.join("m"))]),
        &[name, "another run"],
    );
    assert!(!r.join("m").exists());
}

/// A whole run's journal whose records are another run's (seed 2's, after seed 1's header) is
/// not continued from them: the run says it cut the journal after its last good record, runs
/// those ensembles, and writes exactly what a fresh run writes.
#[test]
fn a_spliced_journal_is_not_continued() {
    use gdsmc_runner::run::journal::{Header, ensemble_record, header_bytes};
    use gdsmc_runner::scene::{Override, Sourced};
    let r = root("spliced-journal");
    let path = scene("grw-example3");
    let header = |seed: u64| {
        let o = Override::run_flags(Some(64), Some(2), Some(seed));
        Header::new(&Sourced::read(&path, o).unwrap(), None, 0..2)
    };
    let (mine, theirs) = (header(1), header(2));
    let mut b = header_bytes(&mine);
    let row = vec![1.0; mine.row_len];
    b.extend(ensemble_record(
        theirs.key(),
        0,
        &row,
        &gdsmc_core::engine::Counts::default(),
    ));
    std::fs::write(r.join(".o.run.gdsmc-ensembles"), &b).unwrap();
    let o = small_run("grw-example3", &["--seed", "1", "--out", s(&r.join("o"))]);
    ok(&o);
    let err = String::from_utf8_lossy(&o.stderr);
    assert!(err.contains("another run"), "{err}");
    ok(&small_run(
        "grw-example3",
        &["--seed", "1", "--out", s(&r.join("fresh"))],
    ));
    assert_eq!(
        std::fs::read(r.join("o/observables.csv")).unwrap(),
        std::fs::read(r.join("fresh/observables.csv")).unwrap()
    );
}

/// Forged headers with valid checksums (`"shard": [0, 0]`, K >= S, a range not the shard's, a
/// huge row) are refused naming the file, never a panic; a FIFO, a device and a directory
/// given as shards are refused by their type; a shard longer than its header allows is refused
/// before it is read whole.
#[test]
fn forged_and_strange_shards_are_refused_without_a_panic() {
    let r = root("forged");
    let d = r.join("d");
    for k in ["0/2", "1/2"] {
        ok(&small_run("grw-example3", &["--shard", k, "--out", s(&d)]));
    }
    let good = d.join("grw-example3.shard-0-of-2.gdsmc-ensembles");
    let other = d.join("grw-example3.shard-1-of-2.gdsmc-ensembles");
    let bytes = std::fs::read(&good).unwrap();
    let (h, json) = split_header(&bytes);
    let forge = |name: &str, edit: &dyn Fn(&mut serde_json::Value)| -> PathBuf {
        let mut j = json.clone();
        edit(&mut j);
        let p = r.join(name);
        std::fs::write(&p, with_header(&bytes, &j, &bytes[h..])).unwrap();
        p
    };
    let cases = [
        forge("zero.gdsmc-ensembles", &|j| {
            j["shard"] = serde_json::json!([0, 0])
        }),
        forge("k-above.gdsmc-ensembles", &|j| {
            j["shard"] = serde_json::json!([5, 2])
        }),
        forge("many.gdsmc-ensembles", &|j| {
            j["shard"] = serde_json::json!([0, u64::MAX])
        }),
        forge("range.gdsmc-ensembles", &|j| {
            j["end"] = serde_json::json!(2)
        }),
        forge("row.gdsmc-ensembles", &|j| {
            j["row_len"] = serde_json::json!(usize::MAX)
        }),
    ];
    for p in &cases {
        refused(
            &gdsmc(&["merge", s(p), s(&other), "--out", s(&r.join("m"))]),
            &[
                p.file_name().unwrap().to_str().unwrap(),
                "inconsistent header",
            ],
        );
    }
    // Longer than its header allows: a copy with a megabyte appended.
    let long = r.join("long.gdsmc-ensembles");
    let mut b = bytes.clone();
    b.resize(bytes.len() + (1 << 20), 0);
    std::fs::write(&long, &b).unwrap();
    refused(
        &gdsmc(&["merge", s(&long), s(&other), "--out", s(&r.join("m"))]),
        &["long.gdsmc-ensembles", "longer than its header allows"],
    );
    // A FIFO (named as a shard, in a directory given to merge), /dev/zero and a directory.
    let fifo_dir = r.join("fifo");
    std::fs::create_dir(&fifo_dir).unwrap();
    std::fs::copy(&other, fifo_dir.join("b.gdsmc-ensembles")).unwrap();
    assert!(
        Command::new("mkfifo")
            .arg(fifo_dir.join("a.gdsmc-ensembles"))
            .status()
            .unwrap()
            .success()
    );
    let t0 = Instant::now();
    refused(
        &gdsmc(&["merge", s(&fifo_dir), "--out", s(&r.join("m"))]),
        &["a.gdsmc-ensembles", "not a regular file"],
    );
    refused(
        &gdsmc(&["merge", "/dev/zero", s(&other), "--out", s(&r.join("m"))]),
        &["/dev/zero", "not a regular file"],
    );
    assert!(t0.elapsed() < Duration::from_secs(60));
    assert!(!r.join("m").exists());
}
