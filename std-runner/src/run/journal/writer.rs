//! A journal being written: locked for one process, never through a link or over what gdsmc
//! did not write, a record flushed as each ensemble finishes.

use super::read::{is_own, read_bounded};
use super::{Header, LOCK_WAIT, MAGIC, header_bytes};
use crate::error::Error;
use std::io::{Read, Write};
use std::path::Path;

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

    /// Keeps the first `len` bytes (what [`super::read`] found valid) and appends after them.
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
