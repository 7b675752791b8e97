//! A journal's bytes: its header's and its records' ([`super`]'s layout), each record's CRC
//! seeded with its run's key.

use super::{COUNT_WORDS, END, FORMAT, Header, MAGIC};
use gdsmc_core::engine::Counts;

fn counts_words(c: &Counts) -> [u64; COUNT_WORDS] {
    // Destructured, so a new field of Counts fails to compile here until it is journaled.
    let Counts {
        candidates,
        collisions,
        fictitious,
        overshoots,
        observations,
        clamped,
        refreshes,
        rescales,
        background,
    } = *c;
    [
        candidates,
        collisions,
        fictitious,
        overshoots,
        observations,
        clamped,
        refreshes,
        rescales,
        background,
    ]
}

pub(super) fn counts_of(w: &[u64]) -> Counts {
    Counts {
        candidates: w[0],
        collisions: w[1],
        fictitious: w[2],
        overshoots: w[3],
        observations: w[4],
        clamped: w[5],
        refreshes: w[6],
        rescales: w[7],
        background: w[8],
    }
}

/// The bytes before the first record.
pub fn header_bytes(h: &Header) -> Vec<u8> {
    let json = serde_json::to_vec(h).expect("a header serializes");
    let mut out = Vec::with_capacity(json.len() + 28);
    out.extend_from_slice(MAGIC);
    out.extend_from_slice(&FORMAT.to_le_bytes());
    out.extend_from_slice(&(json.len() as u32).to_le_bytes());
    out.extend_from_slice(&json);
    out.extend_from_slice(&crc32fast::hash(&json).to_le_bytes());
    out
}

/// A record's CRC: CRC-32 of its bytes, seeded with the run's key ([`Header::key`]).
pub(super) fn record_crc(key: u32, bytes: &[u8]) -> u32 {
    let mut h = crc32fast::Hasher::new_with_initial(key);
    h.update(bytes);
    h.finalize()
}

fn record_bytes(key: u32, ensemble: u64, words: &[u64]) -> Vec<u8> {
    let mut out = Vec::with_capacity(16 + 8 * words.len());
    out.extend_from_slice(&ensemble.to_le_bytes());
    out.extend_from_slice(&(words.len() as u32).to_le_bytes());
    for w in words {
        out.extend_from_slice(&w.to_le_bytes());
    }
    let crc = record_crc(key, &out);
    out.extend_from_slice(&crc.to_le_bytes());
    out
}

/// One ensemble's record in a file of the run whose key is `key` ([`Header::key`]).
pub fn ensemble_record(key: u32, ensemble: u64, row: &[f64], counts: &Counts) -> Vec<u8> {
    record_bytes(key, ensemble, &ensemble_words(row, counts))
}

/// A finished ensemble as a record holds it: its counts, then its row's bits (the browser's
/// workers hand ensembles to the one that folds them this way).
pub fn ensemble_words(row: &[f64], counts: &Counts) -> Vec<u64> {
    counts_words(counts)
        .into_iter()
        .chain(row.iter().map(|x| x.to_bits()))
        .collect()
}

/// The row and counts of [`ensemble_words`] (`None`: fewer words than the counts take).
pub fn ensemble_from_words(words: &[u64]) -> Option<(Vec<f64>, Counts)> {
    let (counts, row) = (words.get(..COUNT_WORDS)?, &words[COUNT_WORDS..]);
    Some((
        row.iter().map(|&x| f64::from_bits(x)).collect(),
        counts_of(counts),
    ))
}

/// How the ensembles of a finished file were run.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Timing {
    /// Wall seconds.
    pub wall: f64,
    /// CPU seconds (all threads).
    pub cpu: f64,
    /// Worker threads.
    pub threads: u64,
}

/// The end record: the file (of the run whose key is `key`) is complete with `ensembles`
/// records.
pub fn end_record(key: u32, ensembles: u64, t: Timing) -> Vec<u8> {
    record_bytes(
        key,
        END,
        &[ensembles, t.wall.to_bits(), t.cpu.to_bits(), t.threads],
    )
}
