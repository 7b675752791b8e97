//! The state a run continues from (`--initial-state`, Python's `read_state`): opened and
//! checked whole before anything acts on it (docs/state.md, "The checks").

use super::layout::{self, HEADER_BYTES, Layout, MAGIC};
use super::{StateHeader, checks, origin};
use crate::Error;
use crate::scene::Scene;
use gdsmc_core::particles::Particles;
use gdsmc_core::vec3::Vec3;
use std::fs::File;
use std::io::{Read, Seek, SeekFrom};
use std::path::{Path, PathBuf};
use std::sync::Mutex;

/// Record `k`'s values from the open state `file` of layout `layout` and header `h`, its
/// checksum and values checked: the refusal in words.
pub(super) fn read_record(
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
