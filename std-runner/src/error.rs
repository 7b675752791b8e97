//! Errors of the runner, each naming what is wrong (file, line, key or argument).

use std::path::PathBuf;

/// Everything that can stop a run.
#[derive(Debug, thiserror::Error)]
pub enum Error {
    /// A scene could not be read, parsed or validated (file, line and key named).
    #[error(transparent)]
    Scene(#[from] gdsmc_scene::Error),
    /// A physics description built in code (not from a scene file) is invalid.
    #[error("{0}")]
    Physics(String),
    /// A command-line argument is out of its domain.
    #[error("{flag}: {message}")]
    Argument {
        /// The flag or argument.
        flag: String,
        /// What is wrong.
        message: String,
    },
    /// The engine stopped (non-finite state).
    #[error("ensemble {ensemble}: {message}")]
    Engine {
        /// Ensemble index.
        ensemble: u64,
        /// The engine's message.
        message: String,
    },
    /// Memory for a run's buffers could not be had (refused by the allocator, not aborted).
    #[error("{what}: {bytes} bytes cannot be allocated")]
    OutOfMemory {
        /// What the memory was for, with the key that sizes it.
        what: String,
        /// The bytes asked for.
        bytes: usize,
    },
    /// A sweep's point failed while it ran (its index and varied values named).
    #[error("point {index} of the sweep ({values}): {source}")]
    Point {
        /// The point's index.
        index: usize,
        /// Its varied keys' values, `key = value, ...`.
        values: String,
        /// What went wrong.
        source: Box<Error>,
    },
    /// The run was interrupted (Ctrl-C); what was finished has been written.
    #[error("interrupted")]
    Interrupted,
    /// `gdsmc reproduce`: figures of ours that lie outside an exact value's range, or that
    /// disagree with the paper's where nothing exact decides.
    #[error("{} figure(s) disagree: {}", .0.len(), .0.join("; "))]
    Disagrees(Vec<String>),
    /// An ensemble file (journal or shard) is unreadable, damaged or of another run.
    #[error("{path}: {message}")]
    Journal {
        /// The file.
        path: PathBuf,
        /// What is wrong with it.
        message: String,
    },
    /// `gdsmc merge`: the shards given do not make one run (missing, duplicated, of several runs).
    #[error("{0}")]
    Shards(String),
    /// gdsmc will not write here: the place holds what gdsmc did not write (a user's
    /// directory or file, a link), or what it asks for would not fit.
    #[error("{path}: {message}")]
    Refused {
        /// The place.
        path: PathBuf,
        /// Why, and what to do instead.
        message: String,
    },
    /// An output file could not be written.
    #[error("{path}: cannot write: {source}")]
    Write {
        /// The file.
        path: PathBuf,
        /// The I/O error.
        source: std::io::Error,
    },
}
