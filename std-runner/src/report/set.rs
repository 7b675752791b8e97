//! An output set written whole. A run's files are written into a private staging directory
//! beside the target (`.NAME.partial-PID`), prepared before the simulation starts (so an
//! unwritable place is reported before any work), closed by `manifest.json` (every file with
//! its size and FNV-1a checksum, and the run's scene, seed and ensembles) and then swapped in
//! for the previous set in one step: on Linux an atomic exchange of the two directories
//! (`renameat2(RENAME_EXCHANGE)`), elsewhere two renames. A run killed at any moment leaves the
//! previous whole set or the new whole set at the target, never a mix; staging directories of
//! killed runs are removed by the next run. [`verify`] tells a whole set from a broken one.

use crate::error::Error;
use std::path::{Path, PathBuf};

/// The file that closes a set.
pub const MANIFEST: &str = "manifest.json";

fn write_err(path: &Path) -> impl Fn(std::io::Error) -> Error + '_ {
    move |source| Error::Write {
        path: path.to_path_buf(),
        source,
    }
}

/// FNV-1a, 64 bits: enough to tell a file from another version of it.
fn fnv1a(bytes: &[u8]) -> u64 {
    let mut h: u64 = 0xcbf2_9ce4_8422_2325;
    for &b in bytes {
        h ^= b as u64;
        h = h.wrapping_mul(0x0100_0000_01b3);
    }
    h
}

/// A set being written; dropped without [`OutputSet::commit`], its staging directory goes.
pub struct OutputSet {
    target: PathBuf,
    staging: PathBuf,
    committed: bool,
}

/// `.NAME.partial-` for a target `.../NAME`.
fn staging_prefix(target: &Path) -> String {
    let name = target
        .file_name()
        .map_or("out".into(), |n| n.to_string_lossy());
    format!(".{name}.partial-")
}

/// Whether process `pid` is alive (Linux: /proc; elsewhere assumed alive, so nothing is
/// removed that might be another run's).
fn alive(pid: u32) -> bool {
    if cfg!(target_os = "linux") {
        Path::new("/proc").join(pid.to_string()).exists()
    } else {
        true
    }
}

impl OutputSet {
    /// Prepares writing a set to `target`: creates its parent and the staging directory, and
    /// removes the staging directories of runs that were killed.
    pub fn prepare(target: &Path) -> Result<Self, Error> {
        let parent = match target.parent() {
            Some(p) if !p.as_os_str().is_empty() => p.to_path_buf(),
            _ => PathBuf::from("."),
        };
        std::fs::create_dir_all(&parent).map_err(write_err(&parent))?;
        let prefix = staging_prefix(target);
        if let Ok(entries) = std::fs::read_dir(&parent) {
            for e in entries.flatten() {
                let name = e.file_name().to_string_lossy().into_owned();
                if let Some(pid) = name.strip_prefix(&prefix).and_then(|p| p.parse().ok())
                    && !alive(pid)
                {
                    let _ = std::fs::remove_dir_all(e.path());
                }
            }
        }
        let staging = parent.join(format!("{prefix}{}", std::process::id()));
        let _ = std::fs::remove_dir_all(&staging);
        std::fs::create_dir(&staging).map_err(write_err(&staging))?;
        Ok(OutputSet {
            target: target.to_path_buf(),
            staging,
            committed: false,
        })
    }

    /// Where the files go until [`OutputSet::commit`].
    pub fn dir(&self) -> &Path {
        &self.staging
    }

    /// Writes the manifest (the files now in the staging directory, and `run`, a JSON object
    /// describing the run) and puts the set in place of the previous one. Returns the names of
    /// the files written (the manifest last).
    pub fn commit(mut self, run: serde_json::Value) -> Result<Vec<String>, Error> {
        let mut files = Vec::new();
        let mut written = Vec::new();
        let mut names: Vec<PathBuf> = std::fs::read_dir(&self.staging)
            .map_err(write_err(&self.staging))?
            .flatten()
            .map(|e| e.path())
            .collect();
        names.sort();
        for p in names {
            let bytes = std::fs::read(&p).map_err(write_err(&p))?;
            written.push(
                p.file_name()
                    .map_or(String::new(), |n| n.to_string_lossy().into_owned()),
            );
            files.push(serde_json::json!({
                "name": p.file_name().map(|n| n.to_string_lossy().into_owned()),
                "bytes": bytes.len(),
                "fnv1a64": format!("{:016x}", fnv1a(&bytes)),
            }));
        }
        let manifest = serde_json::json!({ "run": run, "files": files });
        let path = self.staging.join(MANIFEST);
        let text = serde_json::to_vec_pretty(&manifest).map_err(|e| Error::Write {
            path: path.clone(),
            source: std::io::Error::other(e),
        })?;
        crate::report::files::write_atomic(&path, &text)?;
        self.swap_in()?;
        self.committed = true;
        written.push(MANIFEST.to_string());
        Ok(written)
    }

    /// The staging directory becomes the target; the previous set, if any, is removed.
    fn swap_in(&self) -> Result<(), Error> {
        let (staging, target) = (&self.staging, &self.target);
        if !target.exists() {
            return std::fs::rename(staging, target).map_err(write_err(target));
        }
        #[cfg(target_os = "linux")]
        {
            use rustix::fs::{CWD, RenameFlags, renameat_with};
            // One atomic step: the staging directory now holds the previous set.
            renameat_with(CWD, staging, CWD, target, RenameFlags::EXCHANGE)
                .map_err(|e| write_err(target)(e.into()))?;
            let _ = std::fs::remove_dir_all(staging);
            Ok(())
        }
        #[cfg(not(target_os = "linux"))]
        {
            let old = staging.with_extension("old");
            std::fs::rename(target, &old).map_err(write_err(target))?;
            std::fs::rename(staging, target).map_err(write_err(target))?;
            let _ = std::fs::remove_dir_all(&old);
            Ok(())
        }
    }
}

impl Drop for OutputSet {
    fn drop(&mut self) {
        if !self.committed {
            let _ = std::fs::remove_dir_all(&self.staging);
        }
    }
}

/// Checks that `dir` holds a whole set: a manifest, and every file it lists with its size and
/// checksum. Returns the manifest's `run` object.
pub fn verify(dir: &Path) -> Result<serde_json::Value, String> {
    let text = std::fs::read(dir.join(MANIFEST)).map_err(|e| format!("no manifest: {e}"))?;
    let m: serde_json::Value =
        serde_json::from_slice(&text).map_err(|e| format!("manifest: {e}"))?;
    let files = m["files"].as_array().ok_or("manifest without files")?;
    for f in files {
        let name = f["name"].as_str().ok_or("a file without a name")?;
        let bytes = std::fs::read(dir.join(name)).map_err(|e| format!("{name}: {e}"))?;
        let sum = format!("{:016x}", fnv1a(&bytes));
        if f["bytes"].as_u64() != Some(bytes.len() as u64) || f["fnv1a64"].as_str() != Some(&sum) {
            return Err(format!("{name} is not the file the manifest lists"));
        }
    }
    Ok(m["run"].clone())
}
