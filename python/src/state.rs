//! State files in Python: `read_state` (any state file: `--save-state`, `save_state=`, a
//! velocity snapshot; docs/state.md) and the snapshots of a run from Python, written into a
//! directory of their own that lives as long as the result.

use crate::to_py;
use gdsmc_runner::run::state::{StateHeader, StateReader, StateWriter, snapshot_writers};
use gdsmc_runner::scene::Scene;
use pyo3::prelude::*;
use std::path::PathBuf;
use std::sync::atomic::{AtomicU64, Ordering};

/// A state file as Python gets it: its JSON header, every record's f64s as little-endian
/// bytes, and their shape `(ensembles, values per record)`.
pub type StateBytes<'py> = (String, Bound<'py, pyo3::types::PyBytes>, (usize, usize));

/// Reads the state file `path` whole (checked as `--initial-state` is): its header, and its
/// records (each: collisions per particle, `3 n` velocity components, then for rough
/// particles `3 n` rim-velocity components).
#[pyfunction]
pub fn read_state(py: Python<'_>, path: PathBuf) -> PyResult<StateBytes<'_>> {
    let r = StateReader::open(&path).map_err(to_py)?;
    crate::warn_all(py, &r.notes)?;
    let header = serde_json::to_string(&r.header).expect("a header serializes");
    let mut bytes = Vec::new();
    let mut width = 0;
    for k in 0..r.header.ensembles {
        let x = r.record(k).map_err(to_py)?;
        width = x.len();
        bytes.extend(x.iter().flat_map(|v| v.to_le_bytes()));
    }
    let shape = (r.header.ensembles as usize, width);
    Ok((header, pyo3::types::PyBytes::new(py, &bytes), shape))
}

/// The velocity snapshots of a run from Python: a directory of its own under the system's
/// temporary directory, removed with the result.
pub struct Snapshots {
    dir: PathBuf,
    /// Each snapshot's time and file.
    pub files: Vec<(f64, PathBuf)>,
}

/// Tells one process's snapshot directories apart.
static NEXT: AtomicU64 = AtomicU64::new(0);

impl Snapshots {
    /// The directory and the writers of `scene`'s snapshots (`None` when it takes none) for a
    /// run of `ensembles` continuing `from`.
    pub fn create(
        scene: &Scene,
        ensembles: u64,
        from: Option<&StateHeader>,
    ) -> Result<Option<(Self, Vec<StateWriter>)>, gdsmc_runner::Error> {
        if scene.snapshots().is_empty() {
            return Ok(None);
        }
        let dir = std::env::temp_dir().join(format!(
            "gdsmc-snapshots-{}-{}",
            std::process::id(),
            NEXT.fetch_add(1, Ordering::Relaxed)
        ));
        std::fs::create_dir(&dir).map_err(|source| gdsmc_runner::Error::Write {
            path: dir.clone(),
            source,
        })?;
        let snapshots = Snapshots {
            files: (scene.snapshots().iter().enumerate())
                .map(|(j, &ti)| {
                    let name = gdsmc_runner::run::state::snapshot_name(j);
                    (scene.times()[ti], dir.join(name))
                })
                .collect(),
            dir,
        };
        let writers = snapshot_writers(scene, &snapshots.dir, ensembles, from)?;
        Ok(Some((snapshots, writers)))
    }
}

impl Drop for Snapshots {
    /// Removes the directory this process created, and what it wrote there.
    fn drop(&mut self) {
        for (_, f) in &self.files {
            let _ = std::fs::remove_file(f);
        }
        let _ = std::fs::remove_dir(&self.dir);
    }
}
