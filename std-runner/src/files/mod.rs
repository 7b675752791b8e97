//! Files written and read safely. gdsmc never writes through a symbolic link, never replaces a
//! file it did not write, and reads only regular files:
//! - [`write_atomic`] writes to a fresh temporary name beside the target (created exclusively,
//!   so neither an existing file nor a planted link is ever opened) and renames it into place:
//!   an interrupted run never leaves a half-written file where a good one was;
//! - [`write_own`] does the same for a file in a place the user chose, refusing to replace a
//!   file that is not gdsmc's (`gdsmc reproduce --out`'s report.md, `gdsmc bench`'s files);
//! - [`open_own`] opens (or creates) a file gdsmc keeps writing, a journal, without following
//!   a link and only when it is a regular file;
//! - [`open_regular`] opens a file to read (a shard given on the command line, a link to one
//!   included), refusing a FIFO, device or directory by its type before reading a byte, so
//!   that nothing blocks or reads for ever;
//! - [`claim::Claim`] holds an output place for one process at a time (a lock the kernel
//!   releases when the process dies), and records the staging directory it creates, the only
//!   kind of directory gdsmc ever removes;
//! - [`sync_dir`] makes a rename in a directory durable (a power cut after it keeps it).

pub mod claim;
pub mod staging;

use crate::error::Error;
use std::fs::File;
use std::io::Write;
use std::path::{Path, PathBuf};
use std::sync::atomic::{AtomicU64, Ordering};

/// Distinguishes the temporary names of one process.
static TEMPORARIES: AtomicU64 = AtomicU64::new(0);

pub(crate) fn write_err(path: &Path) -> impl Fn(std::io::Error) -> Error + '_ {
    move |source| Error::Write {
        path: path.to_path_buf(),
        source,
    }
}

/// `.NAME.partial-PID-K` beside `path`, created exclusively (`O_CREAT | O_EXCL`: never an
/// existing file, never through a link): the file and its name.
pub(crate) fn create_temporary(path: &Path) -> Result<(File, PathBuf), Error> {
    let name = path
        .file_name()
        .map_or("out".into(), |n| n.to_string_lossy());
    for _ in 0..64 {
        let k = TEMPORARIES.fetch_add(1, Ordering::Relaxed);
        let tmp = path.with_file_name(format!(".{name}.partial-{}-{k}", std::process::id()));
        match std::fs::OpenOptions::new()
            .write(true)
            .create_new(true)
            .open(&tmp)
        {
            Ok(f) => return Ok((f, tmp)),
            Err(e) if e.kind() == std::io::ErrorKind::AlreadyExists => continue,
            Err(e) if e.kind() == std::io::ErrorKind::NotFound => {
                // The directory itself is gone (removed while the run went): said so, and not
                // made again.
                let dir = path.parent().unwrap_or(Path::new("."));
                return Err(write_err(dir)(std::io::Error::new(
                    e.kind(),
                    "the directory is gone (removed while gdsmc was writing into it); \
                     nothing was written",
                )));
            }
            Err(e) => return Err(write_err(path)(e)),
        }
    }
    Err(write_err(path)(std::io::Error::other(
        "no free temporary name beside it",
    )))
}

/// Writes `bytes` to `path` atomically: a fresh temporary file beside it (see the module
/// docs), flushed, then renamed into place. A link at `path` is replaced, its target never
/// written.
pub fn write_atomic(path: &Path, bytes: &[u8]) -> Result<(), Error> {
    let (mut f, tmp) = create_temporary(path)?;
    let written = f
        .write_all(bytes)
        .and_then(|()| f.sync_all())
        .and_then(|()| {
            drop(f);
            std::fs::rename(&tmp, path)
        });
    if let Err(e) = written {
        let _ = std::fs::remove_file(&tmp);
        return Err(write_err(path)(e));
    }
    Ok(())
}

/// Flushes the directory `dir` to the disk (its entries: a file created or renamed in it), where
/// the platform offers it (Unix: `fsync` of the directory); elsewhere a no-op.
pub fn sync_dir(dir: &Path) -> Result<(), Error> {
    #[cfg(unix)]
    {
        let dir = if dir.as_os_str().is_empty() {
            Path::new(".")
        } else {
            dir
        };
        File::open(dir)
            .and_then(|d| d.sync_all())
            .map_err(write_err(dir))
    }
    #[cfg(not(unix))]
    {
        let _ = dir;
        Ok(())
    }
}

/// Flushes the regular file at `path` to the disk.
pub fn sync_file(path: &Path) -> Result<(), Error> {
    open_regular(path)
        .and_then(|f| f.sync_all())
        .map_err(write_err(path))
}

/// Whether `path` may be replaced by a file of gdsmc's: it is absent, or it is a regular file
/// (not a link) whose first 64 KiB hold `signature`, the text every version of that file
/// holds. Otherwise the refusal names the file.
pub fn check_own(path: &Path, signature: &str) -> Result<(), Error> {
    let refuse = |message: &str| Error::Refused {
        path: path.to_path_buf(),
        message: message.to_string(),
    };
    let meta = match std::fs::symlink_metadata(path) {
        Err(e) if e.kind() == std::io::ErrorKind::NotFound => return Ok(()),
        Err(e) => return Err(write_err(path)(e)),
        Ok(m) => m,
    };
    if !meta.file_type().is_file() {
        return Err(refuse(
            "exists and is not a regular file (a link, directory, FIFO or device): gdsmc \
             replaces only files it wrote; choose another output directory",
        ));
    }
    let mut head = Vec::new();
    let f = open_regular(path).map_err(write_err(path))?;
    std::io::Read::read_to_end(&mut std::io::Read::take(f, 64 << 10), &mut head)
        .map_err(write_err(path))?;
    if !head
        .windows(signature.len())
        .any(|w| w == signature.as_bytes())
    {
        return Err(refuse(
            "exists and was not written by gdsmc: it is left as it is; choose another output \
             directory or move it away",
        ));
    }
    Ok(())
}

/// [`write_atomic`] into a place the user chose: refused when a file is at `path` that is not
/// gdsmc's ([`check_own`] with `signature`, which `bytes` must hold).
pub fn write_own(path: &Path, bytes: &[u8], signature: &str) -> Result<(), Error> {
    debug_assert!(
        bytes
            .windows(signature.len())
            .any(|w| w == signature.as_bytes())
    );
    check_own(path, signature)?;
    write_atomic(path, bytes)
}

/// Open flags that keep an open from following a final link or blocking on a FIFO.
#[cfg(target_os = "linux")]
fn guarded(o: &mut std::fs::OpenOptions, follow: bool) {
    use rustix::fs::OFlags;
    use std::os::unix::fs::OpenOptionsExt;
    let mut flags = OFlags::NONBLOCK;
    if !follow {
        flags |= OFlags::NOFOLLOW;
    }
    o.custom_flags(flags.bits() as i32);
}

/// Elsewhere: a link is refused by its metadata before the open.
#[cfg(not(target_os = "linux"))]
fn guarded(_: &mut std::fs::OpenOptions, _: bool) {}

/// Why an open file is refused, when it is not a regular file.
fn not_regular(f: &File) -> std::io::Result<Option<&'static str>> {
    let t = f.metadata()?.file_type();
    Ok(if t.is_file() {
        None
    } else if t.is_dir() {
        Some("is a directory, not a file")
    } else {
        Some(
            "is not a regular file (a FIFO, socket or device): gdsmc reads and writes only regular files",
        )
    })
}

/// Opens `path` to read and write, creating it when absent, without following a link at
/// `path` and only when it is a regular file (a link, FIFO, device or directory is refused
/// without blocking, and left as it is). For the files gdsmc keeps writing: journals.
pub fn open_own(path: &Path) -> Result<File, Error> {
    let refuse = |message: &str| Error::Refused {
        path: path.to_path_buf(),
        message: message.to_string(),
    };
    const LINK: &str = "is a symbolic link: gdsmc does not write through one (its target may \
                        be anyone's file); remove the link or choose another output place";
    #[cfg(not(target_os = "linux"))]
    if std::fs::symlink_metadata(path).is_ok_and(|m| m.file_type().is_symlink()) {
        return Err(refuse(LINK));
    }
    let mut o = std::fs::OpenOptions::new();
    o.read(true).write(true).create(true).truncate(false);
    guarded(&mut o, false);
    let f = o.open(path).map_err(|e| {
        // ELOOP: the last component is a link (O_NOFOLLOW).
        #[cfg(target_os = "linux")]
        if e.raw_os_error() == Some(rustix::io::Errno::LOOP.raw_os_error()) {
            return refuse(LINK);
        }
        write_err(path)(e)
    })?;
    match not_regular(&f).map_err(write_err(path))? {
        None => Ok(f),
        Some(why) => Err(refuse(why)),
    }
}

/// Opens an existing file to read, following links (a user may link a shard), only when it is
/// a regular file: a FIFO, device or directory is refused by its type without blocking.
pub fn open_regular(path: &Path) -> std::io::Result<File> {
    let mut o = std::fs::OpenOptions::new();
    o.read(true);
    guarded(&mut o, true);
    let f = o.open(path)?;
    match not_regular(&f)? {
        None => Ok(f),
        Some(why) => Err(std::io::Error::other(why)),
    }
}
