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

use crate::Error;
use crate::scene::Scene;
use gdsmc_core::engine::Frame;
use gdsmc_core::particles::Particles;
use gdsmc_core::vec3::Vec3;
use serde::{Deserialize, Serialize};
use std::fs::File;
use std::io::{Read, Seek, SeekFrom, Write};
use std::path::{Path, PathBuf};
use std::sync::Mutex;

use layout::Layout;
pub use layout::{HEADER_BYTES, MAGIC};

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
fn vectors(it: impl Iterator<Item = Vec3>) -> Vec<u8> {
    it.flat_map(|v| v.to_array())
        .flat_map(f64::to_le_bytes)
        .collect()
}

/// A state file being written: records put as ensembles finish (from any thread) into its
/// partial file beside `path` ([`partial_of`], locked while written), renamed into place by
/// [`StateWriter::finish`]. The partial file's name is fixed, not a process's: a run killed
/// (a job's time limit) leaves one file, which the same command continues (the records of the
/// ensembles its journal holds are kept, [`StateWriter::holds`]) and removes when it ends.
pub struct StateWriter {
    file: Mutex<File>,
    partial: PathBuf,
    path: PathBuf,
    header: StateHeader,
}

/// The partial file of a state being written to `path`: `.NAME.gdsmc-state-partial` beside it.
pub fn partial_of(path: &Path) -> PathBuf {
    let name = path
        .file_name()
        .map_or("state".into(), |n| n.to_string_lossy());
    path.with_file_name(format!(".{name}.gdsmc-state-partial"))
}

/// Record `k`'s values from the open state `file` of layout `layout` and header `h`, its
/// checksum and values checked: the refusal in words.
fn read_record(
    file: &Mutex<File>,
    layout: Layout,
    h: &StateHeader,
    k: u64,
) -> Result<Vec<f64>, String> {
    let payload = h.payload_bytes().ok_or("a record too large to address")? as usize;
    let sum = if layout.summed() {
        layout::SUM_BYTES
    } else {
        0
    };
    let mut bytes = vec![0u8; payload + sum];
    {
        let mut f = file.lock().unwrap_or_else(|e| e.into_inner());
        f.seek(SeekFrom::Start(layout.record_at(k, payload as u64)))
            .and_then(|_| f.read_exact(&mut bytes))
            .map_err(|e| e.to_string())?;
    }
    let (values, stored) = bytes.split_at(payload);
    if sum > 0 && stored != layout::record_sum(k, values) {
        return Err("its bytes do not match its checksum: damaged or edited".into());
    }
    let x: Vec<f64> = values
        .chunks_exact(8)
        .map(|b| f64::from_le_bytes(b.try_into().expect("8 bytes")))
        .collect();
    checks::record(&x, h)?;
    Ok(x)
}

impl StateWriter {
    /// Starts the state of `header.ensembles` ensembles at `path`: refused when a file is
    /// there that gdsmc did not write (a state file is its own: it starts with [`MAGIC`]), when
    /// its directory does not exist, or while another process writes the same state. A
    /// partial file of this same state (its header's bytes this one's: the same scene, seed,
    /// segment, time and size) is continued, its records kept for [`StateWriter::holds`];
    /// any other partial file of gdsmc's at that name is started anew.
    pub fn create(path: &Path, header: StateHeader) -> Result<Self, Error> {
        crate::files::check_own(path, "GDSMC-STATE")?;
        // A directory that is not there is said so (not "removed while gdsmc was writing").
        let dir = match path.parent() {
            Some(d) if !d.as_os_str().is_empty() => d,
            _ => Path::new("."),
        };
        if !dir.is_dir() {
            return Err(Error::Refused {
                path: dir.to_path_buf(),
                message: format!(
                    "{}, so the state file {} cannot be written there: create the directory \
                     first",
                    if dir.exists() {
                        "is not a directory"
                    } else {
                        "does not exist"
                    },
                    path.display()
                ),
            });
        }
        let partial = partial_of(path);
        let werr = crate::files::write_err(&partial);
        crate::files::check_own(&partial, "GDSMC-STATE")?;
        let mut file = crate::files::open_own(&partial)?;
        match file.try_lock() {
            Ok(()) => {}
            Err(std::fs::TryLockError::WouldBlock) => {
                let who = crate::files::claim::flock_holder(&file)
                    .map_or(String::new(), |pid| format!(" (process {pid})"));
                return Err(Error::Refused {
                    path: path.to_path_buf(),
                    message: format!(
                        "another gdsmc process{who} is writing this state file: wait for it, \
                         or choose another --save-state"
                    ),
                });
            }
            Err(std::fs::TryLockError::Error(e)) => return Err(werr(e)),
        }
        let size = header
            .file_bytes()
            .ok_or_else(|| werr(std::io::Error::other("a state too large to address")))?;
        let head = header.bytes();
        let mut have = Vec::new();
        (&mut file)
            .take(head.len() as u64)
            .read_to_end(&mut have)
            .map_err(&werr)?;
        let same = have == head && file.metadata().map_err(&werr)?.len() == size;
        if !same {
            file.set_len(0)
                .and_then(|()| file.rewind())
                .and_then(|()| file.write_all(&head))
                .and_then(|()| file.set_len(size))
                .map_err(&werr)?;
        }
        Ok(StateWriter {
            file: Mutex::new(file),
            partial: partial.clone(),
            path: path.to_path_buf(),
            header,
        })
    }

    /// The file the state goes to when the run ends.
    pub fn path(&self) -> &Path {
        &self.path
    }

    /// Whether the partial file holds ensemble `k`'s record whole (its checksum and values
    /// check): the record a run killed after journaling ensemble `k` wrote before it.
    pub fn holds(&self, k: u64) -> bool {
        read_record(&self.file, self.header.layout(), &self.header, k).is_ok()
    }

    /// Writes ensemble `k`'s particles `p` (stored velocities mapped by `frame` to physical
    /// ones) and its collisions per particle so far, `s`.
    pub fn put(&self, k: u64, p: &Particles<'_>, frame: Frame, s: f64) -> Result<(), Error> {
        let n = p.len();
        let mut bytes = s.to_le_bytes().to_vec();
        bytes.extend(vectors(
            (0..n).map(|i| frame.offset + frame.scale * p.velocity(i)),
        ));
        if self.header.spins {
            bytes.extend(vectors((0..n).map(|i| frame.scale * p.spin(i))));
        }
        let sum = layout::record_sum(k, &bytes);
        bytes.extend(sum);
        let at = self
            .header
            .layout()
            .record_at(k, bytes.len() as u64 - layout::SUM_BYTES as u64);
        let mut f = self.file.lock().unwrap_or_else(|e| e.into_inner());
        f.seek(SeekFrom::Start(at))
            .and_then(|_| f.write_all(&bytes))
            .map_err(crate::files::write_err(&self.partial))
    }

    /// Finishes the file with the first `ensembles` records (those of the statistics) and
    /// renames it into place.
    pub fn finish(self, ensembles: u64) -> Result<(), Error> {
        let header = StateHeader {
            ensembles,
            ..self.header
        };
        let size = header.file_bytes().unwrap_or(0);
        let mut f = self.file.into_inner().unwrap_or_else(|e| e.into_inner());
        let done = f
            .seek(SeekFrom::Start(0))
            .and_then(|_| f.write_all(&header.bytes()))
            .and_then(|()| f.set_len(size))
            .and_then(|()| f.sync_all())
            .and_then(|()| std::fs::rename(&self.partial, &self.path));
        if let Err(e) = done {
            let _ = std::fs::remove_file(&self.partial);
            return Err(crate::files::write_err(&self.path)(e));
        }
        Ok(())
    }

    /// Writes the state of the first `ensembles` records (an interrupted run's: those of its
    /// statistics) to the target through a temporary file, and keeps the partial file for the
    /// run's continuation.
    pub fn save_prefix(&self, ensembles: u64) -> Result<(), Error> {
        let header = StateHeader {
            ensembles,
            ..self.header.clone()
        };
        let layout = self.header.layout();
        let payload = self.header.payload_bytes().unwrap_or(0);
        let (mut out, tmp) = crate::files::create_temporary(&self.path)?;
        let mut f = self.file.lock().unwrap_or_else(|e| e.into_inner());
        let copy = |f: &mut File, out: &mut File| -> std::io::Result<()> {
            out.write_all(&header.bytes())?;
            f.seek(SeekFrom::Start(layout.data_start()))?;
            let records = ensembles * layout.record_bytes(payload).unwrap_or(0);
            std::io::copy(&mut f.take(records), out)?;
            out.sync_all()
        };
        let done = copy(&mut f, &mut out).and_then(|()| {
            drop(out);
            std::fs::rename(&tmp, &self.path)
        });
        if let Err(e) = done {
            let _ = std::fs::remove_file(&tmp);
            return Err(crate::files::write_err(&self.path)(e));
        }
        Ok(())
    }

    /// Drops the partial file (nothing of it is to be continued).
    pub fn abandon(self) {
        let _ = std::fs::remove_file(&self.partial);
    }
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

/// A state file opened to continue from, checked whole before anything acts on it (module
/// docs).
pub struct StateReader {
    file: Mutex<File>,
    path: PathBuf,
    layout: Layout,
    /// What it holds.
    pub header: StateHeader,
    /// Warnings for the user (a file of the first format, whose bytes carry no checksums).
    pub notes: Vec<String>,
    /// What tells this state from another: the CRC-32 of its header and every record's values,
    /// and its size, in hex. A run's journal records it, so that a journal of a run from
    /// another state is not continued.
    pub identity: String,
}

impl StateReader {
    /// Opens and checks `path`: its magic and version, its header's checksum and fields, its
    /// size, and every record's checksum and values. The refusal names the file and, for a
    /// record, the ensemble and its byte offset.
    pub fn open(path: &Path) -> Result<Self, Error> {
        let bad = |why: String| Error::Argument {
            flag: "--initial-state".into(),
            message: format!("{}: {why}", path.display()),
        };
        let mut file = crate::files::open_regular(path).map_err(|e| bad(e.to_string()))?;
        let mut head = vec![0u8; MAGIC.len() + HEADER_BYTES];
        file.read_exact(&mut head)
            .map_err(|_| bad("too short to be a gdsmc state file".into()))?;
        let layout = Layout::of_magic(&head[..MAGIC.len()]).ok_or_else(|| {
            bad(if head.starts_with(b"GDSMC-STATE") {
                "a gdsmc state file of another format version (this gdsmc reads v001 and v002)"
                    .into()
            } else {
                "not a gdsmc state file (it does not start with GDSMC-STATE)".into()
            })
        })?;
        let mut notes = Vec::new();
        if layout.summed() {
            let mut sum = [0u8; layout::SUM_BYTES];
            file.read_exact(&mut sum)
                .map_err(|_| bad("too short to be a gdsmc state file".into()))?;
            if sum != layout::header_sum(&head) {
                return Err(bad(
                    "its header does not match its checksum: damaged or edited".into(),
                ));
            }
        } else {
            notes.push(format!(
                "warning: {} is a state file of format v001, which has no checksums: its bytes \
                 are checked for sense, not for damage (a run with --save-state writes v002)",
                path.display()
            ));
        }
        let header: StateHeader = serde_json::from_slice(head[MAGIC.len()..].trim_ascii_end())
            .map_err(|e| bad(format!("its header is not readable: {e}")))?;
        checks::header(&header, layout).map_err(&bad)?;
        let size = file.metadata().map_err(|e| bad(e.to_string()))?.len();
        let want = header.file_bytes();
        if want != Some(size) {
            return Err(bad(format!(
                "holds {size} bytes, but its header ({} ensembles of {} particles) makes {}: \
                 cut short or damaged",
                header.ensembles,
                header.n,
                want.map_or("more than a file can hold".into(), |w| w.to_string())
            )));
        }
        let mut reader = StateReader {
            file: Mutex::new(file),
            path: path.to_path_buf(),
            layout,
            header,
            notes,
            identity: String::new(),
        };
        // Every record, before any run starts from one (a damaged record must not be found
        // mid-run, blaming the run).
        let mut id = crc32fast::Hasher::new();
        id.update(&head);
        for k in 0..reader.header.ensembles {
            for x in reader.record(k)? {
                id.update(&x.to_le_bytes());
            }
        }
        reader.identity = format!("{:08x}-{size}", id.finalize());
        Ok(reader)
    }

    /// Whether `scene` may continue from this state: the same particles (count, dimension,
    /// rotation, species), no more ensembles than it holds, and every observation time at
    /// or after its time. The refusal names the key to change.
    pub fn check(&self, scene: &Scene) -> Result<(), Error> {
        let h = &self.header;
        let bad = |key: &str, why: String| Error::Argument {
            flag: "--initial-state".into(),
            message: format!("{}: {key} {why}", self.path.display()),
        };
        let species: Vec<usize> = scene.physics().species.iter().map(|s| s.count).collect();
        if scene.n() != h.n {
            return Err(bad(
                "particles.n",
                format!("is {} but the state holds {} particles", scene.n(), h.n),
            ));
        }
        if scene.dimension() != h.dimension {
            return Err(bad(
                "particles.dimension",
                format!(
                    "is {} but the state's is {}",
                    scene.dimension(),
                    h.dimension
                ),
            ));
        }
        if scene.physics().rotation.is_some() != h.spins {
            return Err(bad(
                "[rotation]",
                format!(
                    "does not match the state's particles ({})",
                    if h.spins { "rough" } else { "smooth" }
                ),
            ));
        }
        if species != h.species {
            return Err(bad(
                "[[species]]",
                format!("count {species:?} particles, the state {:?}", h.species),
            ));
        }
        if scene.ensembles() > h.ensembles {
            return Err(bad(
                "run.ensembles",
                format!(
                    "is {} but the state holds {}",
                    scene.ensembles(),
                    h.ensembles
                ),
            ));
        }
        let first = scene.times()[0];
        if first < h.time {
            return Err(bad(
                "observe.t_start",
                format!(
                    "is {first} but the state is at t = {}: observe from its time on \
                     (--set observe.t_start={} and a later observe.t_end)",
                    h.time, h.time
                ),
            ));
        }
        Ok(())
    }

    /// Whether the references of `scene` (solved from its initial distribution at t = 0) hold
    /// for a run of it from this state: the state is a sample of `scene`'s own process.
    pub fn continues(&self, scene: &Scene) -> bool {
        self.header.origin == origin(scene)
    }

    /// Ensemble `k`'s record as f64s: its collisions per particle so far, then `3 n`
    /// velocity components, then (rough particles) `3 n` rim-velocity components; its checksum
    /// and values checked (again: the file may have changed since it was opened).
    pub fn record(&self, k: u64) -> Result<Vec<f64>, Error> {
        read_record(&self.file, self.layout, &self.header, k).map_err(|why| {
            let payload = self.header.payload_bytes().unwrap_or(0);
            Error::Argument {
                flag: "--initial-state".into(),
                message: format!(
                    "{}: record {k} (ensemble {k}, at byte {}): {why}",
                    self.path.display(),
                    self.layout.record_at(k, payload)
                ),
            }
        })
    }

    /// Sets `p` to ensemble `k`'s particles; returns its collisions per particle so far.
    pub fn get(&self, k: u64, p: &mut Particles<'_>) -> Result<f64, Error> {
        let (n, spins) = (self.header.n, self.header.spins);
        let x = self.record(k)?;
        let v = |j: usize| Vec3::new(x[1 + 3 * j], x[2 + 3 * j], x[3 + 3 * j]);
        for i in 0..n {
            p.set_velocity(i, v(i));
            if spins {
                p.set_spin(i, v(n + i));
            }
        }
        Ok(x[0])
    }
}
