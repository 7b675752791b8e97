//! Errors of scene reading, each naming the file (or command-line flag), line and key.

use std::path::{Path, PathBuf};

/// Why a scene could not be read.
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
}

fn location(path: &Path, line: usize) -> String {
    if line == 0 {
        path.display().to_string()
    } else {
        format!("{}:{line}", path.display())
    }
}
