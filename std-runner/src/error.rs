//! Errors of the runner, each naming what is wrong (file, line, key or argument).

use std::path::PathBuf;

/// Everything that can stop a run.
#[derive(Debug, thiserror::Error)]
pub enum Error {
    /// The scene file could not be read.
    #[error("{path}: cannot read scene file: {source}")]
    Read {
        /// The file.
        path: PathBuf,
        /// The I/O error.
        source: std::io::Error,
    },
    /// The scene file is not valid TOML or does not match the schema (unknown key, wrong type).
    #[error("{path}: {message}")]
    Parse {
        /// The file.
        path: PathBuf,
        /// The parser's message, with line and column.
        message: String,
    },
    /// A value is out of its domain.
    #[error("{}: `{key}` {message}", location(path, *line))]
    Invalid {
        /// The file (or `--flag` for command-line values).
        path: PathBuf,
        /// 1-based line of the value (0 when it came from the command line).
        line: usize,
        /// Dotted key path.
        key: String,
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
    /// The run was interrupted (Ctrl-C); what was finished has been written.
    #[error("interrupted")]
    Interrupted,
    /// `gdsmc reproduce`: figures that do not agree with the paper's.
    #[error("{} figure(s) disagree with the paper: {}", .0.len(), .0.join("; "))]
    Disagrees(Vec<String>),
    /// An output file could not be written.
    #[error("{path}: cannot write: {source}")]
    Write {
        /// The file.
        path: PathBuf,
        /// The I/O error.
        source: std::io::Error,
    },
}

fn location(path: &std::path::Path, line: usize) -> String {
    if line == 0 {
        path.display().to_string()
    } else {
        format!("{}:{line}", path.display())
    }
}
