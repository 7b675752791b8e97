//! The state being written (`--save-state`, the snapshots): its locked partial file at a fixed
//! name, a record per ensemble as it finishes, renamed into place when the run ends
//! (docs/state.md, "Stopped and continued").

use super::layout;
use super::reader::read_record;
use super::{StateHeader, vectors};
use crate::Error;
use gdsmc_core::engine::Frame;
use gdsmc_core::particles::Particles;
use std::fs::File;
use std::io::{Read, Seek, SeekFrom, Write};
use std::path::{Path, PathBuf};
use std::sync::Mutex;

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

impl StateWriter {
    /// Starts the state of `header.ensembles` ensembles at `path`: refused when a file is
    /// there that gdsmc did not write (a state file is its own: it starts with [`super::MAGIC`]), when
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

/// Refuses a `--save-state` path that is one of the run's own files: its journal `journal`
/// (the finished run removes it: the state would go with it), its claim, or a place inside
/// its output directory `dir` (the new output set replaces that directory).
pub fn check_place(path: &Path, dir: &Path, journal: &Path) -> Result<(), Error> {
    // Where a path is: its parent made absolute and free of links (when it exists), and its
    // name.
    let place = |p: &Path| -> Option<PathBuf> {
        let parent = match p.parent() {
            Some(d) if !d.as_os_str().is_empty() => d,
            _ => Path::new("."),
        };
        Some(std::fs::canonicalize(parent).ok()?.join(p.file_name()?))
    };
    let refuse = |what: &str| Error::Argument {
        flag: "--save-state".into(),
        message: format!(
            "{} is {what}, which gdsmc removes or replaces: choose a file of its own",
            path.display()
        ),
    };
    let Some(state) = place(path) else {
        return Ok(());
    };
    if place(journal).is_some_and(|j| j == state) {
        return Err(refuse("the run's own journal"));
    }
    if place(&crate::files::claim::path_of(dir)).is_some_and(|c| c == state) {
        return Err(refuse("the run's claim on its output directory"));
    }
    if place(dir).is_some_and(|d| state.starts_with(&d)) {
        return Err(refuse("inside the run's output directory"));
    }
    Ok(())
}
