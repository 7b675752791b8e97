//! A run's particle state: saved at its last observation (`gdsmc run --save-state FILE`) and
//! read to continue it (`--initial-state FILE`). docs/state.md describes the format; it is
//! versioned, checksummed ([`layout`]: format 2; format 1, without checksums, is read with a
//! warning) and nothing of it is acted on before it is checked: the header's checksum, every
//! header field's bounds ([`checks::header`]), the size the header implies, and every record's
//! checksum and values ([`checks::record`]), each refusal naming the file and the record.
//!
//! The records: one per ensemble in ensemble order: its collisions per particle so far (`s`,
//! one little-endian f64), its `n` physical velocities (`3 n` little-endian f64, particle
//! `i`'s `x, y, z` at `3 i`), then for rough particles its `n` rim velocities likewise, then
//! (format 2) its checksum. Velocities are physical (a cooling gas stored rescaled is written
//! in the scene's units).
//!
//! A continuation starts ensemble `k` at the state's time from record `k`, with the seed's
//! stream of ensemble `k` long-jumped `2 (segment + 1)` times (Xoshiro256++'s long jump: 2^192
//! draws; a run's ensembles and their diagnostics use the first two of these blocks), so no
//! segment repeats another's random numbers: a continuation is a pure function of the scene,
//! the seed and the state file. The segment is at most [`checks::MAX_SEGMENT`], so the jumps
//! are bounded. It is not bit for bit one longer run: the engine starts again at the state's
//! time (its majorant from the velocities, GRW step 1).

pub mod checks;
pub mod layout;
mod reader;
mod writer;

use crate::Error;
use crate::scene::Scene;
use gdsmc_core::vec3::Vec3;
use serde::{Deserialize, Serialize};
use std::path::Path;

use layout::Layout;
pub use layout::{HEADER_BYTES, MAGIC};
pub use reader::StateReader;
pub use writer::{StateWriter, check_place, partial_of};

/// What a state file holds, as its JSON header says.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct StateHeader {
    /// The format's version ([`layout::VERSION`] when written; 1 in files of the first
    /// format).
    pub version: u32,
    /// The scene's name.
    pub scene: String,
    /// The run's seed.
    pub seed: u64,
    /// The segment that wrote it: 0 for a run from the scene's initial distribution, one more
    /// for each continuation.
    pub segment: u64,
    /// The time of the state (the run's last observation).
    pub time: f64,
    /// Particles per ensemble.
    pub n: usize,
    /// The dimension of velocity space.
    pub dimension: usize,
    /// Ensembles (records).
    pub ensembles: u64,
    /// Whether each record holds rim velocities (rough particles).
    pub spins: bool,
    /// A mixture's particles per species, in the order of the records' particles (empty: one
    /// species).
    pub species: Vec<usize>,
    /// The process the records are samples of ([`origin`] of the scene that ran from t = 0,
    /// kept by continuations of the same physics; `"none"` once other physics continued it):
    /// the references of a scene of that origin hold for a continuation.
    pub origin: String,
    /// The gdsmc version that wrote it.
    pub gdsmc_version: String,
}

impl StateHeader {
    /// The header of the state `scene`'s run leaves: its last observation, `ensembles`
    /// records, after `segment`, continuing `from` (none: from the scene's initial
    /// distribution).
    pub fn of(scene: &Scene, ensembles: u64, from: Option<&StateHeader>) -> Self {
        let own = origin(scene);
        let (segment, origin) = match from {
            None => (0, own),
            Some(h) if h.origin == own => (h.segment + 1, own),
            Some(h) => (h.segment + 1, "none".to_string()),
        };
        StateHeader {
            version: layout::VERSION,
            scene: scene.name().to_string(),
            seed: scene.seed(),
            segment,
            time: *scene
                .times()
                .last()
                .expect("a scene observes at least once"),
            n: scene.n(),
            dimension: scene.dimension(),
            ensembles,
            spins: scene.physics().rotation.is_some(),
            species: scene.physics().species.iter().map(|s| s.count).collect(),
            origin,
            gdsmc_version: env!("CARGO_PKG_VERSION").to_string(),
        }
    }

    /// The same header for a state at observation time `time` (a velocity snapshot,
    /// `observe.snapshots`): a continuation of it starts there.
    #[must_use]
    pub fn at(self, time: f64) -> Self {
        StateHeader { time, ..self }
    }

    /// The bytes of a record's values (without its checksum).
    fn payload_bytes(&self) -> Option<u64> {
        let per = if self.spins { 2 } else { 1 };
        (self.n as u64).checked_mul(3 * 8 * per)?.checked_add(8)
    }

    /// The layout of this header's format version (a written header: the current one).
    fn layout(&self) -> Layout {
        Layout::of(self.version).unwrap_or(Layout {
            version: layout::VERSION,
        })
    }

    /// The file's size in bytes, `None` when a (forged) header's numbers overflow.
    fn file_bytes(&self) -> Option<u64> {
        self.layout()
            .file_bytes(self.ensembles, self.payload_bytes()?)
    }

    /// The magic, the padded JSON and the header's checksum (a written header: the current
    /// format).
    fn bytes(&self) -> Vec<u8> {
        let mut b = MAGIC.to_vec();
        let json = serde_json::to_vec(self).expect("a header serializes");
        assert!(json.len() <= HEADER_BYTES, "a state header fits its bytes");
        b.extend(json);
        b.resize(MAGIC.len() + HEADER_BYTES, b' ');
        let sum = layout::header_sum(&b);
        b.extend(sum);
        b
    }
}

/// The identity of the process a scene runs from t = 0: its physics (particles, kernel, law,
/// drive, scheme, the initial distribution) as the FNV-1a hash of their `Debug` text, in hex.
/// Seeds, ensembles and observation times are not part of it: they do not change the process.
pub fn origin(scene: &Scene) -> String {
    let text = format!("{:?}", scene.physics());
    let hash = text.bytes().fold(0xcbf2_9ce4_8422_2325_u64, |h, b| {
        (h ^ u64::from(b)).wrapping_mul(0x0000_0100_0000_01b3)
    });
    format!("{hash:016x}")
}

/// The generator of ensemble `k` of a segment after `segment` (module docs): ensemble `k`'s
/// stream long-jumped `2 (segment + 1)` times.
pub fn continued(
    mut rng: gdsmc_core::rng::Xoshiro256PlusPlus,
    segment: u64,
) -> gdsmc_core::rng::Xoshiro256PlusPlus {
    for _ in 0..2 * (segment + 1) {
        rng.long_jump();
    }
    rng
}

/// Little-endian f64s of `3 len` components from `f` (velocities or rim velocities).
pub(super) fn vectors(it: impl Iterator<Item = Vec3>) -> Vec<u8> {
    it.flat_map(|v| v.to_array())
        .flat_map(f64::to_le_bytes)
        .collect()
}

/// The file name of a run's snapshot `j` (its `j`-th of [`Scene::snapshots`]) in the output
/// directory: `snapshot-J.state`.
pub fn snapshot_name(j: usize) -> String {
    format!("snapshot-{j}.state")
}

/// The writers of `scene`'s velocity snapshots ([`Scene::snapshots`]) in `dir` (a staging
/// directory of the output set: they are committed with it), of a run of `ensembles`
/// ensembles continuing `from` (none: from the scene's initial distribution).
pub fn snapshot_writers(
    scene: &Scene,
    dir: &Path,
    ensembles: u64,
    from: Option<&StateHeader>,
) -> Result<Vec<StateWriter>, Error> {
    let times = scene.times();
    (scene.snapshots().iter().enumerate())
        .map(|(j, &ti)| {
            let header = StateHeader::of(scene, ensembles, from).at(times[ti]);
            StateWriter::create(&dir.join(snapshot_name(j)), header)
        })
        .collect()
}

/// Finishes every writer of `writers` with the first `ensembles` records when the run kept
/// any (`Some`), else drops their files.
pub fn finish_all(writers: Vec<StateWriter>, ensembles: Option<u64>) -> Result<(), Error> {
    let mut first = Ok(());
    for w in writers {
        match ensembles {
            Some(m) if m > 0 && first.is_ok() => first = w.finish(m),
            _ => w.abandon(),
        }
    }
    first
}
