//! Reading a journal: its header checked whole, its records up to the first damaged one, and a
//! file read no further than its header allows.

use super::record::{counts_of, record_crc};
use super::{COUNT_WORDS, END, FORMAT, Header, MAGIC, MAX_HEADER, Timing};
use crate::error::Error;
use gdsmc_core::engine::Counts;
use std::io::Read;
use std::path::Path;

/// A journal as read: its header, its valid records in order, and how it ends.
#[derive(Clone, Debug)]
pub struct Contents {
    /// The header.
    pub header: Header,
    /// The ensembles' rows and counts, in order from `header.start`.
    pub rows: Vec<(Vec<f64>, Counts)>,
    /// Bytes up to the end of the last valid ensemble record (where a resumed run appends).
    pub valid_len: u64,
    /// The end record's timing, when the file is complete.
    pub end: Option<Timing>,
    /// Why reading stopped before an end record, when it did (truncation or damage).
    pub damage: Option<String>,
}

fn take<'a>(b: &mut &'a [u8], n: usize) -> Option<&'a [u8]> {
    if b.len() < n {
        return None;
    }
    let (h, t) = b.split_at(n);
    *b = t;
    Some(h)
}

fn u32_of(b: &[u8]) -> u32 {
    u32::from_le_bytes(b.try_into().expect("4 bytes"))
}

fn u64_of(b: &[u8]) -> u64 {
    u64::from_le_bytes(b.try_into().expect("8 bytes"))
}

/// Reads a journal's bytes. A bad magic, format or header is an error (the file is not a
/// journal this version can read); damage after the header stops reading there and is
/// described in [`Contents::damage`].
pub fn read(path: &Path, bytes: &[u8]) -> Result<Contents, Error> {
    let bad = |message: String| Error::Journal {
        path: path.to_path_buf(),
        message,
    };
    let mut b = bytes;
    if take(&mut b, MAGIC.len()) != Some(&MAGIC[..]) {
        return Err(bad(
            "not a gdsmc ensemble file (no GDSMC-ENSEMBLES magic)".into()
        ));
    }
    let head = take(&mut b, 8).ok_or_else(|| bad("truncated in its header".into()))?;
    let format = u32_of(&head[..4]);
    if format != FORMAT {
        return Err(bad(format!(
            "format {format}, this gdsmc reads format {FORMAT}"
        )));
    }
    let len = u32_of(&head[4..]) as usize;
    if len > MAX_HEADER {
        return Err(bad(format!(
            "a header of {len} bytes (at most {MAX_HEADER}): not a gdsmc ensemble file"
        )));
    }
    let json = take(&mut b, len).ok_or_else(|| bad("truncated in its header".into()))?;
    let crc = take(&mut b, 4).ok_or_else(|| bad("truncated in its header".into()))?;
    if crc32fast::hash(json) != u32_of(crc) {
        return Err(bad("damaged header (checksum mismatch)".into()));
    }
    let header: Header =
        serde_json::from_slice(json).map_err(|e| bad(format!("unreadable header: {e}")))?;
    header.check().map_err(bad)?;
    let key = header.key();
    let words = COUNT_WORDS + header.row_len;
    let mut rows = Vec::new();
    let mut valid_len = (bytes.len() - b.len()) as u64;
    let mut end = None;
    let mut damage = None;
    while !b.is_empty() {
        let at = header.start + rows.len() as u64;
        let rec = b;
        let Some(fixed) = take(&mut b, 12) else {
            damage = Some(format!("truncated in the record of ensemble {at}"));
            break;
        };
        let ensemble = u64_of(&fixed[..8]);
        let n = u32_of(&fixed[8..]) as usize;
        let expected = if ensemble == END { 4 } else { words };
        if n != expected {
            damage = Some(format!(
                "damaged at the record of ensemble {at} (length {n}, expected {expected})"
            ));
            break;
        }
        let (Some(body), Some(crc)) = (take(&mut b, 8 * n), take(&mut b, 4)) else {
            damage = Some(format!("truncated in the record of ensemble {at}"));
            break;
        };
        if record_crc(key, &rec[..12 + 8 * n]) != u32_of(crc) {
            damage = Some(format!(
                "damaged at the record of ensemble {at} (checksum mismatch: damaged, or a \
                 record of another run)"
            ));
            break;
        }
        let w: Vec<u64> = body.chunks_exact(8).map(u64_of).collect();
        if ensemble == END {
            if rows.len() as u64 != header.end - header.start {
                damage = Some(format!(
                    "an end record after {} of its {} ensembles",
                    rows.len(),
                    header.end - header.start
                ));
            } else if w[0] != rows.len() as u64 {
                damage = Some(format!(
                    "its end record counts {} ensembles, it holds {}",
                    w[0],
                    rows.len()
                ));
            } else if !b.is_empty() {
                damage = Some("bytes after its end record".into());
            } else {
                end = Some(Timing {
                    wall: f64::from_bits(w[1]),
                    cpu: f64::from_bits(w[2]),
                    threads: w[3],
                });
            }
            break;
        }
        if at == header.end {
            damage = Some(format!(
                "a record after its last ensemble ({}) where its end record belongs",
                header.end - 1
            ));
            break;
        }
        if ensemble != at {
            damage = Some(format!("record of ensemble {ensemble} where {at} belongs"));
            break;
        }
        let counts = counts_of(&w[..COUNT_WORDS]);
        let row = w[COUNT_WORDS..]
            .iter()
            .map(|&x| f64::from_bits(x))
            .collect();
        rows.push((row, counts));
        valid_len = (bytes.len() - b.len()) as u64;
    }
    if end.is_none() && damage.is_none() {
        damage = Some("no end record (the run was interrupted or the file cut short)".into());
    }
    Ok(Contents {
        header,
        rows,
        valid_len,
        end,
        damage,
    })
}

/// The most bytes a file with this header can hold: the header, every ensemble's record and
/// the end record (`None` when that does not fit a `u64`).
fn most_bytes(header_len: u64, h: &Header) -> Option<u64> {
    let record = 16 + 8 * (COUNT_WORDS as u64 + h.row_len as u64);
    (h.end - h.start)
        .checked_mul(record)?
        .checked_add(header_len)?
        .checked_add(16 + 8 * 4)
}

/// Reads an ensemble file's bytes from an open file: the header first, checked, then at most
/// the bytes its header allows (a longer file is refused before it is read whole).
pub(super) fn read_bounded(path: &Path, mut f: impl std::io::Read) -> Result<Vec<u8>, Error> {
    let bad = |message: String| Error::Journal {
        path: path.to_path_buf(),
        message,
    };
    let io = |e: std::io::Error| bad(format!("cannot read: {e}"));
    let mut bytes = Vec::new();
    (&mut f)
        .take(MAGIC.len() as u64 + 8)
        .read_to_end(&mut bytes)
        .map_err(io)?;
    if bytes.len() < MAGIC.len() + 8 {
        return Ok(bytes); // too short for a header: read() names it
    }
    let len = (u32_of(&bytes[MAGIC.len() + 4..]) as usize).min(MAX_HEADER + 1);
    (&mut f)
        .take(len as u64 + 4)
        .read_to_end(&mut bytes)
        .map_err(io)?;
    // A bad header is read()'s to name; only a good one bounds the rest.
    let header = read(path, &bytes)?.header;
    let most = most_bytes(bytes.len() as u64, &header)
        .ok_or_else(|| bad("inconsistent header: its size overflows".into()))?;
    f.take(most - bytes.len() as u64 + 1)
        .read_to_end(&mut bytes)
        .map_err(io)?;
    if bytes.len() as u64 > most {
        return Err(bad(format!(
            "longer than its header allows ({} ensembles of {} values: at most {most} bytes)",
            header.end - header.start,
            header.row_len
        )));
    }
    Ok(bytes)
}

/// Reads an ensemble file (a shard given to merge): only a regular file (a FIFO, device or
/// directory is refused by its type), and no longer than its header allows.
pub fn read_file(path: &Path) -> Result<Vec<u8>, Error> {
    let f = crate::files::open_regular(path).map_err(|e| Error::Journal {
        path: path.to_path_buf(),
        message: format!("cannot read: {e}"),
    })?;
    read_bounded(path, f)
}

/// Whether `bytes` can be the start of an ensemble file: empty, or beginning with (a prefix
/// of) the magic. Anything else at a journal's place is not gdsmc's to overwrite.
pub(super) fn is_own(bytes: &[u8]) -> bool {
    let n = bytes.len().min(MAGIC.len());
    bytes[..n] == MAGIC[..n]
}
