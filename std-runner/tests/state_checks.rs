//! A state file is checked whole before a run acts on it (issue 77, docs/state.md "The
//! checks"): a flipped bit anywhere is refused by a checksum, naming the record; a header
//! forged with a valid checksum is refused by its fields' bounds (a segment of 10^15 used to
//! hang the set-up, 2^64 - 1 wrapped to another segment's streams, version 2 in a v1 file and
//! a negative time were accepted); records that are not velocities are refused at load naming
//! the file, record and particle (NaN, inf and 1e300 used to fail mid-run, blaming the run); a
//! file of the first format is still read, with a warning. Against 03e7324 every refusal here
//! was an acceptance.

use gdsmc_runner::job::{Job, Quiet};
use gdsmc_runner::run::state::StateReader;
use gdsmc_runner::run::state::layout::{
    HEADER_BYTES, MAGIC, MAGIC_V1, SUM_BYTES, header_sum, record_sum,
};
use gdsmc_runner::scene::{Override, Sourced};
use std::path::{Path, PathBuf};

fn root(name: &str) -> PathBuf {
    let r = PathBuf::from(env!("CARGO_TARGET_TMPDIR"))
        .join("state_checks")
        .join(name);
    let _ = std::fs::remove_dir_all(&r);
    std::fs::create_dir_all(&r).unwrap();
    r
}

/// A scratch directory `name`, and in it the state GRW Example 3 leaves at n = 64, 4 ensembles,
/// run to t = 1 with `sets`: the directory, the state file and its bytes.
fn saved_state(name: &str, sets: &[&str]) -> (PathBuf, PathBuf, Vec<u8>) {
    let r = root(name);
    let saved = r.join("s.state");
    let mut o: Vec<Override> = ["observe.t_end=1"]
        .iter()
        .chain(sets)
        .map(|s| Override::set(*s))
        .collect();
    o.extend(Override::run_flags(Some(64), Some(4), Some(7)));
    let scene = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../scenes/grw-example3.toml");
    Job {
        source: Sourced::read(&scene, o).unwrap(),
        threads: 2,
        allow_long: false,
        shard: None,
        out: Some(r.join("out")),
        fresh: false,
        format: "svg".parse().unwrap(),
        initial_state: None,
        save_state: Some(saved.clone()),
    }
    .run(&Quiet::default())
    .unwrap();
    let bytes = std::fs::read(&saved).unwrap();
    (r, saved, bytes)
}

/// Where the records start in a v2 file.
const DATA: usize = MAGIC.len() + HEADER_BYTES + SUM_BYTES;

/// `bytes` with its header's JSON changed by `edit` and, when `resum`, its checksum made
/// again (a deliberate forgery).
fn forge(bytes: &[u8], edit: impl Fn(&mut serde_json::Value), resum: bool) -> Vec<u8> {
    let mut b = bytes.to_vec();
    let head = &b[MAGIC.len()..MAGIC.len() + HEADER_BYTES];
    let mut h: serde_json::Value = serde_json::from_slice(head.trim_ascii_end()).unwrap();
    edit(&mut h);
    let mut json = serde_json::to_vec(&h).unwrap();
    json.resize(HEADER_BYTES, b' ');
    b[MAGIC.len()..MAGIC.len() + HEADER_BYTES].copy_from_slice(&json);
    if resum {
        let sum = header_sum(&b[..MAGIC.len() + HEADER_BYTES]);
        b[MAGIC.len() + HEADER_BYTES..DATA].copy_from_slice(&sum);
    }
    b
}

/// The refusal of `bytes` written at `path`, as the command words it.
fn refusal(path: &Path, bytes: &[u8]) -> String {
    std::fs::write(path, bytes).unwrap();
    match StateReader::open(path) {
        Ok(_) => panic!("{} was accepted", path.display()),
        Err(e) => e.to_string(),
    }
}

#[test]
fn a_flipped_bit_anywhere_is_refused_naming_the_record() {
    let (r, saved, good) = saved_state("flipped", &[]);
    let h = StateReader::open(&saved).unwrap().header;
    let record = 8 + 24 * h.n + SUM_BYTES;
    let bad = r.join("bad.state");
    // One mantissa bit of ensemble 2's particle 5's velocity y.
    let mut b = good.clone();
    let at = DATA + 2 * record + 8 + (3 * 5 + 1) * 8;
    b[at] ^= 1;
    let e = refusal(&bad, &b);
    assert!(
        e.contains("bad.state") && e.contains("record 2 (ensemble 2") && e.contains("checksum"),
        "{e}"
    );
    // A bit of the header (its JSON), and of the header's checksum.
    for at in [MAGIC.len() + 3, MAGIC.len() + HEADER_BYTES + 1] {
        let mut b = good.clone();
        b[at] ^= 4;
        let e = refusal(&bad, &b);
        assert!(e.contains("header does not match its checksum"), "{e}");
    }
    // Two records swapped: each verifies only at its own place.
    let mut b = good.clone();
    let (r0, r1) = (DATA, DATA + record);
    let first = b[r0..r0 + record].to_vec();
    b.copy_within(r1..r1 + record, r0);
    b[r1..r1 + record].copy_from_slice(&first);
    assert!(refusal(&bad, &b).contains("record 0"));
}

#[test]
fn a_forged_header_is_refused_by_its_bounds() {
    let (r, _, good) = saved_state("forged", &[]);
    let bad = r.join("bad.state");
    // Not re-summed: the checksum tells it.
    let b = forge(
        &good,
        |h| h["segment"] = 1_000_000_000_000_000u64.into(),
        false,
    );
    assert!(refusal(&bad, &b).contains("checksum"));
    // Re-summed: the bounds tell it, at once (the set-up used to take forever).
    let t0 = std::time::Instant::now();
    for (edit, words) in [
        (
            Box::new(|h: &mut serde_json::Value| h["segment"] = 1_000_000_000_000_000u64.into())
                as Box<dyn Fn(&mut serde_json::Value)>,
            "segment 1000000000000000 is past the most",
        ),
        (
            Box::new(|h: &mut serde_json::Value| h["segment"] = u64::MAX.into()),
            "segment 18446744073709551615 is past the most",
        ),
        (
            Box::new(|h: &mut serde_json::Value| h["version"] = 1.into()),
            "says format version 1 but the file is version 2",
        ),
        (
            Box::new(|h: &mut serde_json::Value| h["time"] = (-1.0).into()),
            "time -1 is not a time a run reaches",
        ),
        (
            Box::new(|h: &mut serde_json::Value| h["dimension"] = 4.into()),
            "dimension 4 is neither 2 nor 3",
        ),
        (
            Box::new(|h: &mut serde_json::Value| h["species"] = serde_json::json!([10, 20])),
            "species counts [10, 20] do not add up to its 64 particles",
        ),
        (
            Box::new(|h: &mut serde_json::Value| h["ensembles"] = u64::MAX.into()),
            "more than a file can hold",
        ),
        (
            Box::new(|h: &mut serde_json::Value| h["n"] = 65.into()),
            "cut short or damaged",
        ),
    ] {
        let e = refusal(&bad, &forge(&good, edit, true));
        assert!(e.contains(words) && e.contains("bad.state"), "{e}");
    }
    assert!(
        t0.elapsed().as_secs() < 60,
        "the refusals took {:?}",
        t0.elapsed()
    );
}

/// A record whose checksum was made again over a value that is no velocity (NaN, inf, 1e300,
/// a z component in a gas of disks, a negative collision count): refused at load naming the
/// record and the particle.
#[test]
fn records_that_are_not_velocities_are_refused_at_load() {
    let (r, saved, good) = saved_state("values", &["particles.dimension=2"]);
    let h = StateReader::open(&saved).unwrap().header;
    let payload = 8 + 24 * h.n;
    let record = payload + SUM_BYTES;
    let bad = r.join("bad.state");
    // Record 3, value `j` (0: s; 1 + 3 i + c: particle i's component c) set to `x`.
    let with = |j: usize, x: f64| {
        let mut b = good.clone();
        let start = DATA + 3 * record;
        b[start + 8 * j..start + 8 * j + 8].copy_from_slice(&x.to_le_bytes());
        let sum = record_sum(3, &b[start..start + payload]);
        b[start + payload..start + record].copy_from_slice(&sum);
        b
    };
    for (j, x, words) in [
        (1 + 3 * 7, f64::NAN, "particle 7's velocity x is NaN"),
        (
            1 + 3 * 7 + 1,
            f64::INFINITY,
            "particle 7's velocity y is inf",
        ),
        (1 + 3 * 9, 1e300, "particle 9's velocity x is 1e300"),
        (
            1 + 3 * 9 + 2,
            0.5,
            "particle 9's velocity z is 0.5 in a gas of dimension 2",
        ),
        (0, -1.0, "collisions per particle -1 are not a count"),
    ] {
        let e = refusal(&bad, &with(j, x));
        assert!(
            e.contains("record 3 (ensemble 3") && e.contains(words),
            "{e}"
        );
    }
}

/// A file of the first format (no checksums) is still read, with a warning saying its bytes
/// are not verified, and a run continues from it to what the v2 file gives.
#[test]
fn a_first_format_file_is_read_with_a_warning() {
    let (r, saved, good) = saved_state("v1", &[]);
    let v2 = StateReader::open(&saved).unwrap();
    assert!(v2.notes.is_empty());
    let payload = 8 + 24 * v2.header.n;
    // The v1 bytes: its magic, version 1, no header sum, no record sums.
    let mut b = forge(&good, |h| h["version"] = 1.into(), false);
    b[..MAGIC.len()].copy_from_slice(MAGIC_V1);
    let mut v1 = b[..MAGIC.len() + HEADER_BYTES].to_vec();
    for k in 0..v2.header.ensembles as usize {
        let start = DATA + k * (payload + SUM_BYTES);
        v1.extend_from_slice(&b[start..start + payload]);
    }
    let old = r.join("old.state");
    std::fs::write(&old, &v1).unwrap();
    let read = StateReader::open(&old).unwrap();
    assert!(
        read.notes[0].contains("format v001, which has no checksums"),
        "{:?}",
        read.notes
    );
    for k in 0..v2.header.ensembles {
        assert_eq!(read.record(k).unwrap(), v2.record(k).unwrap());
    }
    // A NaN in a v1 file is still refused by its value.
    let mut nan = v1.clone();
    let at = MAGIC.len() + HEADER_BYTES + payload + 8;
    nan[at..at + 8].copy_from_slice(&f64::NAN.to_le_bytes());
    assert!(refusal(&r.join("nan.state"), &nan).contains("record 1 (ensemble 1"));
}
