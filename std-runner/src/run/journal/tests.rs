//! The journal's round trip, and every truncation, flipped bit and forged header of a file.

use super::read::read_bounded;
use super::*;
use gdsmc_core::engine::Counts;

fn header() -> Header {
    Header {
        gdsmc_version: "test".into(),
        scene_path: "s.toml".into(),
        scene_text: "name = \"s\"".into(),
        overrides: vec![("--n".into(), "particles.n=8".into())],
        fingerprint: "fp".into(),
        seed: 3,
        ensembles: 6,
        shard: Some((1, 2)),
        start: 3,
        end: 6,
        row_len: 3,
        initial_state: None,
    }
}

fn rows() -> Vec<(Vec<f64>, Counts)> {
    (0..3)
        .map(|i| {
            let c = Counts {
                candidates: 10 + i,
                collisions: 7 + i,
                fictitious: 3,
                overshoots: i,
                observations: 4,
                clamped: 0,
                refreshes: 1,
                rescales: 2,
                background: 100 + i,
            };
            (vec![i as f64 + 0.1, -1e-300, f64::MAX], c)
        })
        .collect()
}

fn file() -> (Vec<u8>, usize) {
    let mut b = header_bytes(&header());
    let head = b.len();
    for (k, (row, c)) in rows().iter().enumerate() {
        b.extend(ensemble_record(header().key(), 3 + k as u64, row, c));
    }
    let t = Timing {
        wall: 1.5,
        cpu: 2.5,
        threads: 2,
    };
    b.extend(end_record(header().key(), 3, t));
    (b, head)
}

/// Written and read back: the same header, rows (to the bit), counts and timing.
#[test]
fn round_trip() {
    let (b, _) = file();
    let c = read(Path::new("x"), &b).unwrap();
    assert_eq!(c.header, header());
    assert_eq!(c.rows, rows());
    assert_eq!(c.end.unwrap().threads, 2);
    assert!(c.damage.is_none());
    assert_eq!(c.valid_len as usize, b.len() - 48);
}

/// Cut at every byte: never a panic; past the header, the rows read are exactly the
/// records that are whole, and the damage is named; within the header, an error.
#[test]
fn every_truncation_keeps_the_whole_records() {
    let (b, head) = file();
    let rec = (b.len() - head - 48) / 3;
    for len in 0..b.len() {
        match read(Path::new("x"), &b[..len]) {
            Err(_) => assert!(len < head, "cut at {len}, past the header, refused"),
            Ok(c) => {
                assert!(len >= head);
                let whole = ((len - head) / rec).min(3);
                assert_eq!(c.rows, rows()[..whole], "cut at {len}");
                assert_eq!(c.valid_len as usize, head + whole * rec);
                assert!(c.end.is_none() && c.damage.is_some(), "cut at {len}");
            }
        }
    }
}

/// Records beyond the header's range are refused, not folded.
#[test]
fn no_record_beyond_the_range() {
    let mut b = header_bytes(&header());
    for (k, (row, c)) in rows().iter().chain(rows().iter()).enumerate() {
        b.extend(ensemble_record(header().key(), 3 + k as u64, row, c));
    }
    let c = read(Path::new("x"), &b).unwrap();
    assert_eq!(c.rows.len(), 3);
    assert!(c.damage.unwrap().contains("after its last ensemble"));
}

/// Every single bit flipped after the header: the records before the damaged one are kept,
/// that one and all after it are not, and the file is never taken as complete (CRC-32
/// detects every single-bit error).
#[test]
fn every_flipped_bit_is_caught() {
    let (b, head) = file();
    let rec = (b.len() - head - 48) / 3;
    for at in head..b.len() {
        for bit in 0..8 {
            let mut d = b.clone();
            d[at] ^= 1 << bit;
            let c = read(Path::new("x"), &d).unwrap();
            let before = ((at - head) / rec).min(3);
            assert_eq!(c.rows, rows()[..before], "bit {bit} of byte {at}");
            assert!(
                c.end.is_none() && c.damage.is_some(),
                "bit {bit} of byte {at}"
            );
        }
    }
    for at in 0..head {
        let mut d = b.clone();
        d[at] ^= 0x04;
        assert!(read(Path::new("x"), &d).is_err(), "header byte {at}");
    }
}

/// Every field of a valid header set to each of a list of hostile values, with a valid
/// checksum: never a panic, and a header that breaks the layout's rules is refused as
/// inconsistent before anything is computed from it.
#[test]
fn every_forged_header_is_read_without_a_panic() {
    let h = header();
    let values: [serde_json::Value; 9] = [
        serde_json::json!(0),
        serde_json::json!(1),
        serde_json::json!(7),
        serde_json::json!(u32::MAX),
        serde_json::json!(u64::MAX),
        serde_json::json!([0, 0]),
        serde_json::json!([5, 2]),
        serde_json::json!([0, u64::MAX]),
        serde_json::json!(null),
    ];
    let mut refused = 0;
    for field in ["ensembles", "shard", "start", "end", "row_len"] {
        for v in &values {
            let mut j = serde_json::to_value(&h).unwrap();
            j[field] = v.clone();
            let Ok(forged) = serde_json::from_value::<Header>(j) else {
                continue; // not a header at all: the reader's JSON error
            };
            let mut b = header_bytes(&forged);
            b.extend(ensemble_record(
                forged.key(),
                3,
                &[1.0, 2.0],
                &Counts::default(),
            ));
            match read(Path::new("x"), &b) {
                Err(e) => {
                    assert!(e.to_string().contains("inconsistent header"), "{e}");
                    refused += 1;
                }
                Ok(c) => assert!(forged.check().is_ok() && c.end.is_none()),
            }
            let _ = read_bounded(Path::new("x"), &b[..]);
        }
    }
    assert!(refused >= 20, "only {refused} forgeries refused");
}
