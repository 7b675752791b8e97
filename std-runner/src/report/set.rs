//! An output set written whole. A run's files are written into a private staging directory
//! beside the target (`.NAME.partial-PID`), prepared before the simulation starts (so an
//! unwritable place is reported before any work), closed by `manifest.json` (every file with
//! its size and FNV-1a checksum, and the run's scene, seed and ensembles) and then swapped in
//! for the previous set in one step: on Linux an atomic exchange of the two directories
//! (`renameat2(RENAME_EXCHANGE)`), elsewhere two renames. A run killed at any moment leaves the
//! previous whole set or the new whole set at the target, never a mix. Every file and the
//! staging directory are flushed to the disk before the swap and the parent directory after
//! it, so a power cut after the swap keeps the new set whole (Unix; see README's data safety).
//! [`verify`] tells a whole set from a broken one.
//!
//! One process at a time writes to a target: [`OutputSet::prepare`] takes the target's
//! [`Claim`] (refused at once, naming the holder, while another process holds it) and records
//! in it the staging directory and a random token before creating the directory with the
//! token in its marker file. The staging directory of a killed run is removed by the next run
//! at that target only when it is proven gdsmc's ([`crate::files::staging::proven`]): a claim
//! file is only a file (anyone may plant one), and a directory it names that is not this
//! place's staging directory, this user's, with the token's marker, is left and named in a
//! warning ([`OutputSet::notes`]).
//!
//! Only what gdsmc wrote is ever replaced ([`check_replaceable`], before the run and again just
//! before the swap): the target must be absent, an empty directory, or a whole gdsmc set that
//! holds nothing its manifest does not list. A user's directory, a regular file or a link at
//! the target is refused, naming it, and left as it is.

use crate::error::Error;
use crate::files::claim::Claim;
use crate::files::staging;
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
    /// Warnings for the user from preparing the set (a staging directory left as it is).
    notes: Vec<String>,
    /// The random token of the staging directory's marker (and its claim's).
    token: String,
    /// The target's claim, held until the set is committed or dropped (after the staging
    /// directory is gone).
    _claim: Claim,
}

/// `.NAME.partial-` for a target `.../NAME`.
fn staging_prefix(target: &Path) -> String {
    let name = target
        .file_name()
        .map_or("out".into(), |n| n.to_string_lossy());
    format!(".{name}.partial-")
}

/// Whether a new set may replace what is at `target`: nothing, an empty directory, or a whole
/// gdsmc output set (its manifest verifies, [`verify`]) holding only the files the manifest
/// lists, each a regular file. Anything else is refused, naming the path and what is there.
pub fn check_replaceable(target: &Path) -> Result<(), Error> {
    let refuse = |message: String| Error::Refused {
        path: target.to_path_buf(),
        message,
    };
    let meta = match std::fs::symlink_metadata(target) {
        Err(e) if e.kind() == std::io::ErrorKind::NotFound => return Ok(()),
        Err(e) => return Err(write_err(target)(e)),
        Ok(m) => m,
    };
    let t = meta.file_type();
    if t.is_symlink() {
        return Err(refuse(
            "is a symbolic link: gdsmc replaces only a directory it wrote, never what a link \
             points to; give the directory itself or a new name as the output directory (--out)"
                .into(),
        ));
    }
    if !t.is_dir() {
        return Err(refuse(
            "exists and is not a directory (a file gdsmc did not write); it is left as it is: \
             choose another output directory (--out)"
                .into(),
        ));
    }
    let mut entries: Vec<(String, bool)> = std::fs::read_dir(target)
        .map_err(write_err(target))?
        .map(|e| {
            e.map(|e| {
                let name = e.file_name().to_string_lossy().into_owned();
                let file = e.file_type().is_ok_and(|t| t.is_file());
                (name, file)
            })
        })
        .collect::<Result<Vec<_>, _>>()
        .map_err(write_err(target))?
        .into_iter()
        // A staging marker a kill left during the swap is gdsmc's, no file of the set.
        .filter(|(n, _)| !staging::is_marker(target, n))
        .collect();
    if entries.is_empty() {
        return Ok(());
    }
    entries.sort();
    let listed = |names: &[(String, bool)]| {
        let shown: Vec<String> = names
            .iter()
            .take(4)
            .map(|(n, file)| if *file { n.clone() } else { format!("{n}/") })
            .collect();
        let more = names.len().saturating_sub(4);
        if more > 0 {
            format!("{} and {more} more", shown.join(", "))
        } else {
            shown.join(", ")
        }
    };
    let keep = "it is left as it is: choose another output directory (--out) or move them away";
    if !entries.iter().any(|(n, _)| n == MANIFEST) {
        return Err(refuse(format!(
            "holds files gdsmc did not write ({}) and no gdsmc {MANIFEST}; gdsmc replaces only \
             an empty directory or an output set of its own; {keep}",
            listed(&entries)
        )));
    }
    let manifest = read_manifest(target).map_err(|why| {
        refuse(format!(
            "is not a whole gdsmc output set ({why}); gdsmc replaces only an empty directory or \
             an output set of its own; {keep}"
        ))
    })?;
    let own: Vec<&str> = manifest.files.iter().map(|(n, _, _)| n.as_str()).collect();
    let foreign: Vec<(String, bool)> = entries
        .into_iter()
        .filter(|(n, file)| !(*file && (n == MANIFEST || own.contains(&n.as_str()))))
        .collect();
    if !foreign.is_empty() {
        return Err(refuse(format!(
            "is a gdsmc output set that also holds what its {MANIFEST} does not list ({}); \
             {keep}",
            listed(&foreign)
        )));
    }
    verify(target).map_err(|why| {
        refuse(format!(
            "is a gdsmc output set changed since gdsmc wrote it ({why}); {keep}"
        ))
    })?;
    Ok(())
}

impl OutputSet {
    /// Prepares writing a set to `target`: refuses a target gdsmc may not replace
    /// ([`check_replaceable`]), creates its parent and the staging directory, and removes the
    /// staging directories of runs that were killed.
    pub fn prepare(target: &Path) -> Result<Self, Error> {
        check_replaceable(target)?;
        let parent = match target.parent() {
            Some(p) if !p.as_os_str().is_empty() => p.to_path_buf(),
            _ => PathBuf::from("."),
        };
        std::fs::create_dir_all(&parent).map_err(write_err(&parent))?;
        let mut claim = Claim::take(target)?;
        let prefix = staging_prefix(target);
        let mut notes = Vec::new();
        // The staging directory a killed run recorded in its claim is removed only when it is
        // proven gdsmc's; anything else the claim names is left and named.
        if let Some(left) = claim.left_behind()
            && std::fs::symlink_metadata(&left.dir).is_ok()
        {
            match staging::proven(&left.dir, &prefix, left.token.as_deref()) {
                Ok(()) => {
                    staging::remove_marked(&left.dir);
                }
                Err(why) => notes.push(format!(
                    "warning: {} names {} as the staging directory of an earlier run, but {why}: \
                     it is not proven gdsmc's and is left as it is",
                    crate::files::claim::path_of(target).display(),
                    left.dir.display()
                )),
            }
        }
        let prefix = staging_prefix(target);
        let pid = std::process::id();
        // A name nothing has: whatever is at `PID` (a user's directory, or the staging
        // directory of a killed run of another gdsmc) is left as it is.
        let staging = (0..64)
            .map(|k| match k {
                0 => parent.join(format!("{prefix}{pid}")),
                _ => parent.join(format!("{prefix}{pid}-{k}")),
            })
            .find(|p| std::fs::symlink_metadata(p).is_err())
            .ok_or_else(|| {
                write_err(&parent)(std::io::Error::other(
                    "no free name for a staging directory beside the output directory",
                ))
            })?;
        let token = staging::token().map_err(|e| write_err(&staging)(std::io::Error::other(e)))?;
        claim.record_staging(&staging, &token)?;
        std::fs::create_dir(&staging).map_err(write_err(&staging))?;
        let set = OutputSet {
            target: target.to_path_buf(),
            staging,
            committed: false,
            notes,
            token,
            _claim: claim,
        };
        // Created exclusively: the directory is new, so nothing else can be at its name.
        staging::mark(&set.staging, &set.token).map_err(write_err(&set.staging))?;
        Ok(set)
    }

    /// Warnings from preparing the set, for the user (a directory a claim named that was not
    /// proven gdsmc's, left as it is).
    pub fn notes(&self) -> &[String] {
        &self.notes
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
            .filter(|e| e.file_name() != staging::MARKER)
            .map(|e| e.path())
            .collect();
        names.sort();
        for p in names {
            let bytes = std::fs::read(&p).map_err(write_err(&p))?;
            // On the disk before the set is swapped in: a power cut after the swap must find
            // whole files.
            crate::files::sync_file(&p)?;
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
        crate::files::write_atomic(&path, &text)?;
        crate::files::sync_dir(&self.staging)?;
        self.swap_in()?;
        self.committed = true;
        written.push(MANIFEST.to_string());
        Ok(written)
    }

    /// The staging directory becomes the target; the previous set, if any, is removed (checked
    /// again: something may have been put there while the run ran).
    fn swap_in(&self) -> Result<(), Error> {
        let (staging, target) = (&self.staging, &self.target);
        check_replaceable(target)?;
        let parent = staging.parent().unwrap_or(Path::new("."));
        // The new set's marker goes once the set is in place (a kill before leaves it there,
        // recognized as gdsmc's: `staging::is_marker`).
        let unmark = || {
            let _ = std::fs::remove_file(target.join(staging::MARKER));
        };
        if std::fs::symlink_metadata(target).is_err() {
            std::fs::rename(staging, target).map_err(write_err(target))?;
            unmark();
            return crate::files::sync_dir(parent);
        }
        // The previous set carries this run's token to the staging name, so that a kill before
        // it is removed leaves a directory the next run proves gdsmc's and removes.
        if staging::is_marker(target, staging::MARKER) {
            // An earlier run's, left by a kill during its swap.
            let _ = std::fs::remove_file(target.join(staging::MARKER));
        }
        staging::mark(target, &self.token).map_err(write_err(target))?;
        #[cfg(target_os = "linux")]
        {
            use rustix::fs::{CWD, RenameFlags, renameat_with};
            // One atomic step: the staging directory now holds the previous set.
            renameat_with(CWD, staging, CWD, target, RenameFlags::EXCHANGE)
                .map_err(|e| write_err(target)(e.into()))?;
            unmark();
            crate::files::sync_dir(parent)?;
            staging::remove_marked(staging);
            Ok(())
        }
        #[cfg(not(target_os = "linux"))]
        {
            let old = staging.with_extension("old");
            std::fs::rename(target, &old).map_err(write_err(target))?;
            std::fs::rename(staging, target).map_err(write_err(target))?;
            unmark();
            crate::files::sync_dir(parent)?;
            let _ = std::fs::remove_dir_all(&old);
            Ok(())
        }
    }
}

impl Drop for OutputSet {
    fn drop(&mut self) {
        if !self.committed {
            staging::remove_marked(&self.staging);
        }
    }
}

/// A manifest as read: the run object and every file with its size and checksum.
struct Manifest {
    run: serde_json::Value,
    files: Vec<(String, u64, String)>,
}

/// Reads `dir`'s manifest; a file name that is not a plain name (a path) is refused.
fn read_manifest(dir: &Path) -> Result<Manifest, String> {
    let path = dir.join(MANIFEST);
    let f = crate::files::open_regular(&path).map_err(|e| format!("{MANIFEST}: {e}"))?;
    let mut text = Vec::new();
    std::io::Read::read_to_end(&mut std::io::Read::take(f, 16 << 20), &mut text)
        .map_err(|e| format!("{MANIFEST}: {e}"))?;
    let m: serde_json::Value =
        serde_json::from_slice(&text).map_err(|e| format!("{MANIFEST}: {e}"))?;
    let list = m["files"]
        .as_array()
        .ok_or(format!("{MANIFEST} without files"))?;
    let mut files = Vec::with_capacity(list.len());
    for f in list {
        let name = f["name"].as_str().ok_or("a file without a name")?;
        if name.is_empty() || name.contains(['/', '\\']) || name == "." || name == ".." {
            return Err(format!("{MANIFEST} lists `{name}`, not a file name"));
        }
        let bytes = f["bytes"].as_u64().ok_or("a file without a size")?;
        let sum = f["fnv1a64"].as_str().ok_or("a file without a checksum")?;
        files.push((name.to_string(), bytes, sum.to_string()));
    }
    Ok(Manifest {
        run: m["run"].clone(),
        files,
    })
}

/// Checks that `dir` holds a whole set: a manifest, and every file it lists with its size and
/// checksum. Returns the manifest's `run` object.
pub fn verify(dir: &Path) -> Result<serde_json::Value, String> {
    let m = read_manifest(dir)?;
    for (name, len, sum) in &m.files {
        let path = dir.join(name);
        let f = crate::files::open_regular(&path).map_err(|e| format!("{name}: {e}"))?;
        if f.metadata().map_err(|e| format!("{name}: {e}"))?.len() != *len {
            return Err(format!("{name} is not the file the manifest lists"));
        }
        let mut bytes = Vec::new();
        std::io::Read::read_to_end(&mut std::io::Read::take(f, *len), &mut bytes)
            .map_err(|e| format!("{name}: {e}"))?;
        if bytes.len() as u64 != *len || format!("{:016x}", fnv1a(&bytes)) != *sum {
            return Err(format!("{name} is not the file the manifest lists"));
        }
    }
    Ok(m.run)
}
