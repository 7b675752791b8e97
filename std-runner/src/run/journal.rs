//! The ensemble journal: every finished ensemble's row, in ensemble order, in a versioned and
//! checksummed file. It is what a shard hands to `gdsmc merge`, what an MPI rank sends to rank
//! 0, and what an interrupted run resumes from.
//!
//! Layout (all integers little-endian):
//!
//! ```text
//! "GDSMC-ENSEMBLES\n"                      magic, 16 bytes
//! u32 format, u32 L, L bytes of JSON        the header (Header), then u32 CRC-32 of the JSON
//! record*                                   u64 ensemble, u32 words, words x 8 bytes, u32 CRC-32
//! end record                                ensemble = u64::MAX: ensembles, wall, cpu, threads
//! ```
//!
//! A record's words are the ensemble's event counts (9 integers) and its row (observables then
//! histograms, as f64 bits), so a merge folds exactly the values a single run folds. A record's
//! CRC covers its ensemble, length and words and is seeded with the run's key
//! ([`Header::key`]: the CRC-32 of what identifies the run), so a record of another run (another
//! seed, scene, shard or version) spliced in after a valid header fails its check like damage.
//! A file without its end record is a run in progress or one that was killed: its records up to
//! the first incomplete or damaged one are kept, the rest is cut off when the run resumes.
//!
//! The header is checked whole before anything is computed from it (the shard's range against
//! its index, count and ensembles, the row length), and a file is read only when it is a
//! regular file no longer than its header allows ([`read_file`]).

use crate::error::Error;
use crate::scene::Scene;
use gdsmc_core::engine::Counts;
use serde::{Deserialize, Serialize};
use std::io::{Read, Write};
use std::path::Path;

/// The file's first bytes.
pub const MAGIC: &[u8; 16] = b"GDSMC-ENSEMBLES\n";
/// The layout's version; a reader refuses any other (3: records bound to their run).
pub const FORMAT: u32 = 3;
/// The file extension of shards and journals.
pub const EXTENSION: &str = "gdsmc-ensembles";
/// Event counts per record (the fields of [`Counts`]).
const COUNT_WORDS: usize = 9;
/// How long a run waits for another process's lock on its journal before refusing.
const LOCK_WAIT: std::time::Duration = std::time::Duration::from_secs(3);
/// The end record's ensemble field.
const END: u64 = u64::MAX;
/// Most bytes of a header's JSON (the scene's text is in it).
const MAX_HEADER: usize = 16 << 20;
/// Most values per ensemble a header may state: the most a run may have.
const MAX_ROW: usize = crate::run::estimate::MAX_ROW_VALUES;

/// What a journal is of: enough to rebuild the scene and to tell journals of different runs
/// apart.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct Header {
    /// The gdsmc version that wrote it (another version may draw other numbers).
    pub gdsmc_version: String,
    /// The scene file as given on the command line (for messages).
    pub scene_path: String,
    /// The scene file's text.
    pub scene_text: String,
    /// The overrides, as (flag, `key.path=value`), in order.
    pub overrides: Vec<(String, String)>,
    /// The validated scene without its seed and ensemble count (`Debug` text: every value
    /// printed to the last bit), so a changed scene or version is caught.
    pub fingerprint: String,
    /// The run's seed.
    pub seed: u64,
    /// The run's ensembles (all shards together).
    pub ensembles: u64,
    /// `(K, S)`: shard K of S, or `None` for a whole run.
    pub shard: Option<(u64, u64)>,
    /// The ensembles this file holds: `start..end`.
    pub start: u64,
    /// One past the last ensemble this file holds.
    pub end: u64,
    /// Values per ensemble (observables and histograms).
    pub row_len: usize,
}

impl Header {
    /// The header of a run of `source` that holds `range`, as shard `shard` = (K, S) or the
    /// whole run.
    pub fn new(
        source: &crate::scene::Sourced,
        shard: Option<(u64, u64)>,
        range: std::ops::Range<u64>,
    ) -> Self {
        let scene = &source.scene;
        Header {
            gdsmc_version: env!("CARGO_PKG_VERSION").into(),
            scene_path: source.path.display().to_string(),
            scene_text: source.text.clone(),
            overrides: source
                .overrides
                .iter()
                .map(|o| (o.source.clone(), o.assignment.clone()))
                .collect(),
            fingerprint: fingerprint(scene),
            seed: scene.seed(),
            ensembles: scene.ensembles(),
            shard,
            start: range.start,
            end: range.end,
            row_len: crate::run::totals::Totals::row_len_of(scene),
        }
    }

    /// The scene again, from the text and overrides kept (checked against the fingerprint).
    pub fn scene(&self, path: &Path) -> Result<Scene, Error> {
        let overrides: Vec<crate::scene::Override> = self
            .overrides
            .iter()
            .map(|(source, assignment)| crate::scene::Override {
                source: source.clone(),
                assignment: assignment.clone(),
            })
            .collect();
        let ours = env!("CARGO_PKG_VERSION");
        // Written by this gdsmc, the text gives the scene it records; if not, the file was
        // changed after gdsmc wrote it. Written by another, this one may read it differently.
        let why = if self.gdsmc_version == ours {
            "the file was changed after gdsmc wrote it (its scene text does not give the run it \
             records)"
                .to_string()
        } else {
            format!(
                "it was written by gdsmc {}, and this gdsmc ({ours}) reads its scene differently",
                self.gdsmc_version
            )
        };
        let bad = |detail: String| Error::Journal {
            path: path.to_path_buf(),
            message: format!("its scene ({}) {detail}: {why}", self.scene_path),
        };
        let scene =
            crate::scene::parse_with(Path::new(&self.scene_path), &self.scene_text, &overrides)
                .map_err(|e| bad(format!("does not read ({e})")))?;
        if fingerprint(&scene) != self.fingerprint
            || scene.seed() != self.seed
            || scene.ensembles() != self.ensembles
            || crate::run::totals::Totals::row_len_of(&scene) != self.row_len
        {
            return Err(bad("is not the one the file's header records".into()));
        }
        Ok(scene)
    }

    /// The run's key: the CRC-32 of everything [`Header::same_run`] compares, which seeds every
    /// record's CRC, so a record checks only in a file of its own run.
    pub fn key(&self) -> u32 {
        let id = format!(
            "{}\n{}\n{}\n{}\n{:?}\n{}\n{}\n{}",
            self.gdsmc_version,
            self.fingerprint,
            self.seed,
            self.ensembles,
            self.shard,
            self.start,
            self.end,
            self.row_len
        );
        crc32fast::hash(id.as_bytes())
    }

    /// What is wrong with a header read from a file, if anything: a shard's range must be its
    /// index's (`0 <= K < S <= ensembles`), a whole run's all ensembles, the row length
    /// bounded. Checked before any arithmetic on it.
    fn check(&self) -> Result<(), String> {
        if self.start > self.end || self.end > self.ensembles {
            return Err(format!(
                "inconsistent header: ensembles {}..{} of {}",
                self.start, self.end, self.ensembles
            ));
        }
        if self.row_len > MAX_ROW {
            return Err(format!(
                "inconsistent header: {} values per ensemble (at most {MAX_ROW})",
                self.row_len
            ));
        }
        let expected = match self.shard {
            Some((k, s)) => {
                if s == 0 || k >= s || s > self.ensembles {
                    return Err(format!(
                        "inconsistent header: shard {k}/{s} of {} ensembles (a shard K/S needs \
                         0 <= K < S <= ensembles)",
                        self.ensembles
                    ));
                }
                range(k, s, self.ensembles)
            }
            None => 0..self.ensembles,
        };
        if self.start != expected.start || self.end != expected.end {
            return Err(format!(
                "inconsistent header: {} holds ensembles {}..{}, not {}..{}",
                shard_words(self.shard),
                expected.start,
                expected.end,
                self.start,
                self.end
            ));
        }
        Ok(())
    }

    /// Whether a journal with this header holds ensembles of the run `other` describes (the
    /// scene's text and path may differ, e.g. in comments: its values may not).
    pub fn same_run(&self, other: &Header) -> bool {
        self.same_set(other)
            && self.shard == other.shard
            && self.start == other.start
            && self.end == other.end
    }

    /// Whether a file with this header and one with `other` can be shards of one run: the same
    /// everything except which shard each is.
    pub fn same_set(&self, other: &Header) -> bool {
        self.gdsmc_version == other.gdsmc_version
            && self.fingerprint == other.fingerprint
            && self.seed == other.seed
            && self.ensembles == other.ensembles
            && self.shard.map(|s| s.1) == other.shard.map(|s| s.1)
            && self.row_len == other.row_len
    }

    /// What differs from `other`, in words (the first difference found), for the message that
    /// says why a journal was not continued or a shard not merged.
    pub fn difference(&self, other: &Header) -> String {
        if self.gdsmc_version != other.gdsmc_version {
            format!(
                "written by gdsmc {}, this is {}",
                self.gdsmc_version, other.gdsmc_version
            )
        } else if self.fingerprint != other.fingerprint {
            format!(
                "another scene ({} with overrides [{}])",
                self.scene_path,
                self.overrides
                    .iter()
                    .map(|(_, a)| a.as_str())
                    .collect::<Vec<_>>()
                    .join(", ")
            )
        } else if self.seed != other.seed {
            format!("seed {}, not {}", self.seed, other.seed)
        } else if self.ensembles != other.ensembles {
            format!(
                "{} ensembles in all, not {}",
                self.ensembles, other.ensembles
            )
        } else if self.shard.map(|s| s.1) != other.shard.map(|s| s.1) {
            format!(
                "{}, not {}",
                shard_words(self.shard),
                shard_words(other.shard)
            )
        } else {
            format!(
                "ensembles {}..{} ({}), not {}..{} ({})",
                self.start,
                self.end,
                shard_words(self.shard),
                other.start,
                other.end,
                shard_words(other.shard)
            )
        }
    }
}

/// "shard K/S" or "a whole run".
pub fn shard_words(shard: Option<(u64, u64)>) -> String {
    match shard {
        Some((k, s)) => format!("shard {k}/{s}"),
        None => "a whole run".into(),
    }
}

/// The ensembles of shard `k` of `s` in a run of `m`: `[k m / s, (k + 1) m / s)` (sizes differ
/// by at most one; every ensemble in exactly one shard).
pub fn range(k: u64, s: u64, m: u64) -> std::ops::Range<u64> {
    let at = |k: u64| (k as u128 * m as u128 / s as u128) as u64;
    at(k)..at(k + 1)
}

/// The file name of shard `k` of `s` of the scene `name`.
pub fn file_name(name: &str, k: u64, s: u64) -> String {
    let w = s.to_string().len();
    format!("{name}.shard-{k:0w$}-of-{s}.{EXTENSION}")
}

/// Which journal of an output place a file is: what keeps the journals of different commands
/// writing near one another apart (a run's `--out res.point-0` and point 0 of a sweep's
/// `--out res` once shared a name).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Of {
    /// A whole run (`gdsmc run`).
    Run,
    /// Shard `(K, S)` of a run, as an MPI rank runs it.
    Rank(u64, u64),
    /// Point `k` of a sweep, whole.
    Point(usize),
    /// Shard `(c, C)` of point `k` of a sweep (`gdsmc sweep --shard` with more tasks than
    /// points).
    PointShard(usize, u64, u64),
}

impl Of {
    /// The tag in the file name: no dot in it, so that the name `.NAME.TAG.gdsmc-ensembles`
    /// gives back NAME and TAG, and no two (place, journal) pairs share a file.
    pub fn tag(self) -> String {
        let padded = |k: u64, s: u64| {
            let w = s.to_string().len();
            format!("{k:0w$}-of-{s}")
        };
        match self {
            Of::Run => "run".into(),
            Of::Rank(k, s) => format!("rank-{}", padded(k, s)),
            Of::Point(k) => format!("point-{k}"),
            Of::PointShard(k, c, n) => format!("point-{k}-shard-{}", padded(c, n)),
        }
    }
}

/// The journal `of` the output place `dir`, hidden beside it: `.NAME.TAG.gdsmc-ensembles`
/// ([`Of::tag`]).
pub fn beside(dir: &Path, of: Of) -> std::path::PathBuf {
    let name = dir
        .file_name()
        .map_or("out".into(), |n| n.to_string_lossy().into_owned());
    let parent = dir
        .parent()
        .filter(|p| !p.as_os_str().is_empty())
        .map_or_else(|| std::path::PathBuf::from("."), Path::to_path_buf);
    parent.join(format!(".{name}.{}.{EXTENSION}", of.tag()))
}

/// The `Debug` text of `scene` with its seed and ensemble count cleared
/// ([`Scene::fingerprint`]).
pub fn fingerprint(scene: &Scene) -> String {
    scene.fingerprint()
}

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

fn counts_of(w: &[u64]) -> Counts {
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
fn record_crc(key: u32, bytes: &[u8]) -> u32 {
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
    let words: Vec<u64> = counts_words(counts)
        .into_iter()
        .chain(row.iter().map(|x| x.to_bits()))
        .collect();
    record_bytes(key, ensemble, &words)
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
fn read_bounded(path: &Path, mut f: impl std::io::Read) -> Result<Vec<u8>, Error> {
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
fn is_own(bytes: &[u8]) -> bool {
    let n = bytes.len().min(MAGIC.len());
    bytes[..n] == MAGIC[..n]
}

/// A journal file being written: records appended as ensembles finish in order, flushed after
/// each, so a run killed at any moment leaves every finished ensemble readable.
pub struct Writer {
    path: std::path::PathBuf,
    file: std::fs::File,
}

impl Writer {
    /// Opens (or creates) the journal at `path` for this process alone (an exclusive lock,
    /// held until the writer is dropped: two runs into one output place would interleave
    /// their records) and returns what it holds, or why that cannot be continued. A file that
    /// is not gdsmc's (another's file, a link, a FIFO) is refused and left as it is.
    #[allow(clippy::type_complexity)]
    pub fn open(path: &Path) -> Result<(Self, Result<Vec<u8>, String>), Error> {
        let werr = |source| Error::Write {
            path: path.to_path_buf(),
            source,
        };
        // Never through a link (one planted at the journal's place would have its target
        // overwritten), only a regular file.
        let mut file = crate::files::open_own(path)?;
        // A process that was just killed (e.g. the ranks of an mpirun ended by a signal) can
        // hold the lock for a moment longer: wait up to LOCK_WAIT before giving up.
        let asked = std::time::Instant::now();
        loop {
            match file.try_lock() {
                Ok(()) => break,
                Err(std::fs::TryLockError::WouldBlock) if asked.elapsed() < LOCK_WAIT => {
                    std::thread::sleep(std::time::Duration::from_millis(50));
                }
                Err(std::fs::TryLockError::WouldBlock) => {
                    let who = crate::files::claim::flock_holder(&file)
                        .map_or(String::new(), |pid| format!(" (process {pid})"));
                    return Err(Error::Journal {
                        path: path.to_path_buf(),
                        message: format!(
                            "another gdsmc process{who} is writing this journal (the same run \
                             into the same output place): wait for it, or choose another --out"
                        ),
                    });
                }
                Err(std::fs::TryLockError::Error(e)) => return Err(werr(e)),
            }
        }
        let mut head = Vec::new();
        (&mut file)
            .take(MAGIC.len() as u64)
            .read_to_end(&mut head)
            .map_err(werr)?;
        if !is_own(&head) {
            return Err(Error::Journal {
                path: path.to_path_buf(),
                message: "is not a gdsmc ensemble journal (no GDSMC-ENSEMBLES magic), and gdsmc \
                          does not overwrite what it did not write: move it away or choose \
                          another --out"
                    .into(),
            });
        }
        std::io::Seek::rewind(&mut file).map_err(werr)?;
        // A gdsmc file that cannot be continued (another format, a header that does not hold,
        // longer than its header allows) is the caller's to start anew.
        let bytes = read_bounded(path, &mut file).map_err(|e| e.to_string());
        Ok((
            Writer {
                path: path.to_path_buf(),
                file,
            },
            bytes,
        ))
    }

    /// Starts the journal anew with `header` (whatever it held is dropped).
    pub fn restart(&mut self, header: &Header) -> Result<(), Error> {
        self.keep(0)?;
        self.append(&header_bytes(header))
    }

    /// Keeps the first `len` bytes (what [`read`] found valid) and appends after them.
    pub fn keep(&mut self, len: u64) -> Result<(), Error> {
        let werr = |source| Error::Write {
            path: self.path.clone(),
            source,
        };
        self.file.set_len(len).map_err(werr)?;
        std::io::Seek::seek(&mut self.file, std::io::SeekFrom::Start(len)).map_err(werr)?;
        Ok(())
    }

    /// Appends bytes (a record).
    pub fn append(&mut self, bytes: &[u8]) -> Result<(), Error> {
        self.file.write_all(bytes).map_err(|source| Error::Write {
            path: self.path.clone(),
            source,
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

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
}
