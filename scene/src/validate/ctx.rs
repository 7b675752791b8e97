//! Where a file's values are: spans turned into lines, physics parameters into the keys that
//! hold them, so that every refusal names file, line and key.

use crate::error::Error;
use gdsmc_core::physics::{Param, PhysicsError};
use std::ops::Range;
use std::path::Path;

/// Where the values of a file are: turns spans into lines and parameters into keys.
pub(crate) struct Ctx<'a> {
    path: &'a Path,
    text: &'a str,
    keys: Vec<(Param, String, Range<usize>)>,
}

impl<'a> Ctx<'a> {
    pub(crate) fn new(path: &'a Path, text: &'a str) -> Self {
        Ctx {
            path,
            text,
            keys: Vec::new(),
        }
    }

    fn line(&self, span: &Range<usize>) -> usize {
        if *span == (0..0) {
            return 0;
        }
        self.text[..span.start.min(self.text.len())]
            .bytes()
            .filter(|&b| b == b'\n')
            .count()
            + 1
    }

    /// The error for the value at `span` of `key`.
    pub(crate) fn error(&self, span: Range<usize>, key: &str, message: impl Into<String>) -> Error {
        Error::Invalid {
            path: self.path.to_path_buf(),
            line: self.line(&span),
            key: key.to_string(),
            message: message.into(),
        }
    }

    /// [`Ctx::error`] as a `Result`.
    pub(crate) fn invalid<T>(
        &self,
        span: Range<usize>,
        key: &str,
        message: impl Into<String>,
    ) -> Result<T, Error> {
        Err(self.error(span, key, message))
    }

    /// Records that `key` (at `span`) holds the physics parameter `param`.
    pub(crate) fn holds(&mut self, param: Param, key: impl Into<String>, span: Range<usize>) {
        self.keys.push((param, key.into(), span));
    }

    /// Which key holds which physics parameter, as the scene keeps it.
    pub(crate) fn keys(&self) -> Vec<(Param, String)> {
        self.keys.iter().map(|(p, k, _)| (*p, k.clone())).collect()
    }

    /// The core's verdict on a parameter, at the key and line that hold it.
    pub(crate) fn physics_error(&self, e: PhysicsError) -> Error {
        match self.keys.iter().find(|(p, _, _)| *p == e.param) {
            Some((_, key, span)) => self.error(span.clone(), key, e.problem.to_string()),
            None => self.error(0..0, &e.param.to_string(), e.problem.to_string()),
        }
    }
}
