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
use serde::{Deserialize, Serialize};
use std::path::Path;

/// The file's first bytes.
pub const MAGIC: &[u8; 16] = b"GDSMC-ENSEMBLES\n";
/// The layout's version; a reader refuses any other (3: records bound to their run).
pub const FORMAT: u32 = 3;
/// The file extension of shards and journals.
pub const EXTENSION: &str = "gdsmc-ensembles";
/// Event counts per record (the fields of [`gdsmc_core::engine::Counts`]).
const COUNT_WORDS: usize = 9;
/// How long a run waits for another process's lock on its journal before refusing.
const LOCK_WAIT: std::time::Duration = std::time::Duration::from_secs(3);
/// The end record's ensemble field.
const END: u64 = u64::MAX;
/// Most bytes of a header's JSON (the scene's text is in it).
const MAX_HEADER: usize = 16 << 20;
/// Most values per ensemble a header may state: the most a run may have.
const MAX_ROW: usize = crate::run::estimate::MAX_ROW_VALUES;

/// The version a journal records: the package's and the random streams'
/// ([`gdsmc_core::rng::STREAM_VERSION`]), as `0.1.0 (streams v2)`. A journal, shard or rank of
/// another is refused: its ensembles were drawn otherwise.
pub fn version() -> String {
    format!(
        "{} (streams v{})",
        env!("CARGO_PKG_VERSION"),
        gdsmc_core::rng::STREAM_VERSION
    )
}

/// What a journal is of: enough to rebuild the scene and to tell journals of different runs
/// apart.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct Header {
    /// The gdsmc version that wrote it and its stream version ([`version`]: another may draw
    /// other numbers).
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
    /// The identity of the state file the run starts from
    /// ([`crate::run::state::StateReader::identity`]); `None` for a run from the scene's
    /// initial distribution (and in every journal written before it was recorded).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub initial_state: Option<String>,
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
            gdsmc_version: version(),
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
            initial_state: None,
        }
    }

    /// The same header for a run from the state file whose identity is `initial` (none: from
    /// the scene's initial distribution).
    #[must_use]
    pub fn from_state(self, initial: Option<String>) -> Self {
        Header {
            initial_state: initial,
            ..self
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
        let ours = version();
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
        // A run from a state file is bound to it too (a run from the scene keeps the key
        // every earlier journal has).
        let id = match &self.initial_state {
            Some(state) => format!("{id}\nfrom state {state}"),
            None => id,
        };
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
            && self.initial_state == other.initial_state
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
        } else if self.initial_state != other.initial_state {
            let words = |s: &Option<String>| match s {
                Some(id) => format!("the state {id}"),
                None => "the scene's initial distribution".into(),
            };
            format!(
                "a run from {}, not from {}",
                words(&self.initial_state),
                words(&other.initial_state)
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

mod read;
mod record;
mod writer;

pub use read::{Contents, read, read_file};
pub use record::{
    Timing, end_record, ensemble_from_words, ensemble_record, ensemble_words, header_bytes,
};
pub use writer::Writer;

#[cfg(test)]
mod tests;
