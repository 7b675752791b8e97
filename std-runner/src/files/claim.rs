//! One gdsmc process at a time per output place. A run, merge or sweep that writes an output
//! set at `.../NAME` first takes the claim `.NAME.gdsmc-claim` beside it: an exclusive
//! `flock` on that file, which the kernel releases when the process ends however it ends (a
//! killed run leaves no stale claim), and in it the holder's process id, command line, start
//! time, and the staging directory it creates with that directory's random token. A second
//! process asking for the same place is refused at once, naming the holder.
//!
//! The next process after a killed one reads the staging directory and token the killed one
//! recorded. What a claim file says is not trusted: anyone who can write beside the output
//! directory can plant one. The directory it names is removed only when it is proven gdsmc's
//! ([`super::staging::proven`]: this place's exact staging name, a directory and no link, this
//! user's, holding the marker with the recorded token); anything else is left and named.
//!
//! The claim file is removed when the claim ends (while it is still locked; a process waiting
//! on the removed file sees that it no longer names the place and opens the new one).

use crate::error::Error;
use std::fs::File;
use std::io::{Read, Seek, Write};
use std::path::{Path, PathBuf};

/// The first line of every claim file: what tells gdsmc's claim from a user's file of the
/// same name, which is never written.
const SIGNATURE: &str = "gdsmc claim";

/// Most bytes of a claim file read (a claim is a few lines).
const MOST: u64 = 64 << 10;

/// An exclusive claim on an output place, held until dropped.
#[derive(Debug)]
pub struct Claim {
    path: PathBuf,
    file: File,
    /// The staging directory a killed holder recorded, if one did.
    left: Option<Left>,
}

/// The staging directory a killed holder's claim records, as it says: to be proven before
/// anything is done with it ([`super::staging::proven`]).
#[derive(Debug, Clone, PartialEq)]
pub struct Left {
    /// The directory, beside the output place (the recorded name holds no separator).
    pub dir: PathBuf,
    /// The token recorded with it, as written (checked by the proof).
    pub token: Option<String>,
}

/// A claim file's fields as written (`key value` lines after the signature).
fn field<'a>(text: &'a str, key: &str) -> Option<&'a str> {
    text.lines()
        .skip(1)
        .find_map(|l| l.strip_prefix(key)?.strip_prefix(' '))
}

/// The claim file of the output place `target`: `.NAME.gdsmc-claim` beside it.
pub fn path_of(target: &Path) -> PathBuf {
    let name = target
        .file_name()
        .map_or("out".into(), |n| n.to_string_lossy());
    target.with_file_name(format!(".{name}.gdsmc-claim"))
}

/// Seconds since the Unix epoch now.
fn now() -> u64 {
    std::time::SystemTime::now()
        .duration_since(std::time::UNIX_EPOCH)
        .map_or(0, |d| d.as_secs())
}

/// Whether the open `file` is the file at `path` now (not one removed and replaced).
fn still_at(file: &File, path: &Path) -> std::io::Result<bool> {
    #[cfg(unix)]
    {
        use std::os::unix::fs::MetadataExt;
        let (a, b) = (file.metadata()?, std::fs::symlink_metadata(path));
        Ok(b.is_ok_and(|b| a.dev() == b.dev() && a.ino() == b.ino()))
    }
    #[cfg(not(unix))]
    {
        let _ = (file, path);
        Ok(true)
    }
}

impl Claim {
    /// Takes the claim on the output place `target` (whose parent must exist), or refuses at
    /// once, naming the process that holds it. A file at the claim's place that is not a
    /// claim of gdsmc's is refused and left as it is.
    pub fn take(target: &Path) -> Result<Claim, Error> {
        let path = path_of(target);
        let werr = |source| Error::Write {
            path: path.clone(),
            source,
        };
        for _ in 0..16 {
            let mut file = super::open_own(&path)?;
            match file.try_lock() {
                Ok(()) => {}
                Err(std::fs::TryLockError::WouldBlock) => {
                    let text = read_head(&mut file).unwrap_or_default();
                    return Err(Error::Refused {
                        path: target.to_path_buf(),
                        message: holder_words(&text),
                    });
                }
                Err(std::fs::TryLockError::Error(e)) => return Err(werr(e)),
            }
            // The holder before us may have removed the file as it ended: then this lock is
            // on a file no longer at the place, and the place's file is opened again.
            if !still_at(&file, &path).map_err(werr)? {
                continue;
            }
            let text = read_head(&mut file).map_err(werr)?;
            if !text.is_empty() && !text.starts_with(SIGNATURE) {
                return Err(Error::Refused {
                    path: path.clone(),
                    message: "exists and is not a gdsmc claim: gdsmc does not write over it; \
                              move it away or choose another output directory (--out)"
                        .into(),
                });
            }
            let left = field(&text, "staging")
                .filter(|s| !s.is_empty() && !s.contains(['/', '\\']) && *s != "..")
                .and_then(|s| {
                    Some(Left {
                        dir: target.parent()?.join(s),
                        token: field(&text, "token").map(str::to_string),
                    })
                });
            // The new claim keeps naming the directory left behind (with its token) until this
            // process has removed it and records its own: a kill in between must not leave a
            // staging directory no claim names.
            let keep = left.as_ref().and_then(|l| {
                Some((
                    l.dir.file_name()?.to_string_lossy().into_owned(),
                    l.token.clone()?,
                ))
            });
            let mut claim = Claim { path, file, left };
            claim.write(keep)?;
            return Ok(claim);
        }
        Err(werr(std::io::Error::other(
            "the claim file kept being replaced by other processes",
        )))
    }

    /// The staging directory a killed holder of this place recorded, as its claim says, if
    /// it says one: not yet proven gdsmc's.
    pub fn left_behind(&self) -> Option<&Left> {
        self.left.as_ref()
    }

    /// Records the staging directory this process creates for the place (its file name,
    /// beside the target) and its random `token`, before creating it.
    pub fn record_staging(&mut self, staging: &Path, token: &str) -> Result<(), Error> {
        self.write(
            staging
                .file_name()
                .map(|n| (n.to_string_lossy().into_owned(), token.to_string())),
        )
    }

    /// Writes the claim's fields: this process, its command, its start, and the staging
    /// directory and its token when given.
    fn write(&mut self, staging: Option<(String, String)>) -> Result<(), Error> {
        let command: Vec<String> = std::env::args().collect();
        let mut text = format!(
            "{SIGNATURE}\npid {}\ncommand {}\nsince {}\n",
            std::process::id(),
            command.join(" ").replace('\n', " "),
            now()
        );
        if let Some((s, token)) = staging {
            text.push_str(&format!("staging {s}\ntoken {token}\n"));
        }
        let path = self.path.clone();
        let werr = |source| Error::Write {
            path: path.clone(),
            source,
        };
        // Written over the old text in place and cut after, never cut first: a kill between
        // an emptying `set_len(0)` and the write left an empty claim, and the staging
        // directory it had named no claim named any more (seen once in CI's kill test). At
        // every instant the file is the old text, or the new one, or the new one followed by
        // the old one's tail, whose fields come after the new ones (`field` takes the first).
        self.file.rewind().map_err(&werr)?;
        self.file.write_all(text.as_bytes()).map_err(&werr)?;
        self.file.set_len(text.len() as u64).map_err(&werr)?;
        // The staging name must be on disk before the directory is: else a crash could
        // leave a directory no claim names.
        self.file.sync_data().map_err(werr)
    }
}

impl Drop for Claim {
    fn drop(&mut self) {
        // Removed while still locked (the lock goes with the file handle, after this).
        let _ = std::fs::remove_file(&self.path);
    }
}

/// The process holding an `flock` on the open `file`, from `/proc/locks` (Linux; `None`
/// elsewhere or when it cannot be told): for the message refusing a second writer of a
/// journal.
pub fn flock_holder(file: &File) -> Option<u32> {
    #[cfg(target_os = "linux")]
    {
        use std::os::unix::fs::MetadataExt;
        let m = file.metadata().ok()?;
        let dev = m.dev();
        let want = format!(
            "{:02x}:{:02x}:{}",
            rustix::fs::major(dev),
            rustix::fs::minor(dev),
            m.ino()
        );
        let locks = std::fs::read_to_string("/proc/locks").ok()?;
        locks.lines().find_map(|l| {
            let f: Vec<&str> = l.split_whitespace().collect();
            // `1: FLOCK  ADVISORY  WRITE 1234 fd:01:5678 0 EOF`
            (f.get(1) == Some(&"FLOCK") && f.get(5) == Some(&want.as_str()))
                .then(|| f.get(4)?.parse().ok())
                .flatten()
        })
    }
    #[cfg(not(target_os = "linux"))]
    {
        let _ = file;
        None
    }
}

/// The claim's text, at most [`MOST`] bytes, from its start.
fn read_head(file: &mut File) -> std::io::Result<String> {
    file.rewind()?;
    let mut bytes = Vec::new();
    file.take(MOST).read_to_end(&mut bytes)?;
    Ok(String::from_utf8_lossy(&bytes).into_owned())
}

/// Who holds a place, in words, from its claim's text.
fn holder_words(text: &str) -> String {
    let pid = field(text, "pid").unwrap_or("?");
    let command = field(text, "command").unwrap_or("gdsmc");
    let age = field(text, "since")
        .and_then(|s| s.parse::<u64>().ok())
        .map(|s| format!(", running for {} s", now().saturating_sub(s)))
        .unwrap_or_default();
    format!(
        "another gdsmc process is writing here: process {pid} (`{command}`{age}); wait for it \
         to finish, or choose another output directory (--out)"
    )
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A fresh directory for one test.
    fn scratch(name: &str) -> PathBuf {
        let d = std::env::temp_dir().join(format!("gdsmc-claim-{}-{name}", std::process::id()));
        let _ = std::fs::remove_dir_all(&d);
        std::fs::create_dir_all(&d).unwrap();
        d
    }

    #[test]
    fn a_second_claim_is_refused_naming_the_holder_and_taken_once_released() {
        let dir = scratch("second");
        let target = dir.join("res");
        let first = Claim::take(&target).unwrap();
        let e = Claim::take(&target).unwrap_err().to_string();
        assert!(
            e.contains(&format!("process {}", std::process::id())),
            "{e}"
        );
        drop(first);
        assert!(
            !path_of(&target).exists(),
            "the claim file goes with the claim"
        );
        let again = Claim::take(&target).unwrap();
        assert!(again.left_behind().is_none());
        // The lock's holder is told from /proc/locks (Linux).
        #[cfg(target_os = "linux")]
        assert_eq!(flock_holder(&again.file), Some(std::process::id()));
    }

    #[test]
    fn a_users_file_at_the_claims_place_is_refused_and_kept() {
        let dir = scratch("users");
        let target = dir.join("res");
        std::fs::write(path_of(&target), "notes\n").unwrap();
        let e = Claim::take(&target).unwrap_err().to_string();
        assert!(e.contains("not a gdsmc claim"), "{e}");
        assert_eq!(std::fs::read(path_of(&target)).unwrap(), b"notes\n");
    }

    #[test]
    fn the_staging_directory_a_dead_holder_recorded_is_reported() {
        let dir = scratch("dead");
        let target = dir.join("res");
        std::fs::write(
            path_of(&target),
            format!("{SIGNATURE}\npid 1\nstaging .res.partial-7\n"),
        )
        .unwrap();
        let c = Claim::take(&target).unwrap();
        let left = c.left_behind().unwrap();
        assert_eq!(left.dir, dir.join(".res.partial-7"));
        assert_eq!(left.token, None);
        drop(c);
        // With its token, the new claim keeps naming it until the new holder records its own
        // (a kill in between must not orphan it).
        let token = "0123456789abcdef0123456789abcdef";
        std::fs::write(
            path_of(&target),
            format!("{SIGNATURE}\npid 1\nstaging .res.partial-7\ntoken {token}\n"),
        )
        .unwrap();
        let mut c = Claim::take(&target).unwrap();
        let text = std::fs::read_to_string(path_of(&target)).unwrap();
        assert!(
            text.contains(&format!("staging .res.partial-7\ntoken {token}\n")),
            "{text}"
        );
        assert!(
            text.contains(&format!("pid {}", std::process::id())),
            "{text}"
        );
        c.record_staging(
            &dir.join(".res.partial-8"),
            "ffffffffffffffffffffffffffffffff",
        )
        .unwrap();
        let text = std::fs::read_to_string(path_of(&target)).unwrap();
        assert!(text.contains("staging .res.partial-8\n") && !text.contains("partial-7"));
        // A recorded name that is a path is not followed.
        drop(c);
        std::fs::write(
            path_of(&target),
            format!("{SIGNATURE}\npid 1\nstaging ../x\n"),
        )
        .unwrap();
        assert!(Claim::take(&target).unwrap().left_behind().is_none());
    }
}
