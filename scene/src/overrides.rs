//! Command-line overrides of scene values: `--set key.path=value` and the flags that name one
//! key (`--n`, `--ensembles`, `--seed`). They are applied to the scene text and the result is
//! validated as a file is, so a flag gets exactly the file's rules; an override's error names
//! the flag that gave the value.

use crate::error::Error;
use crate::{Scene, parse, read};
use std::path::{Path, PathBuf};

/// One override: where it came from (`--set`, `--n`, ...) and its `key.path=value`.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Override {
    /// The flag that gave it, for error messages.
    pub source: String,
    /// `key.path=value`. Values are TOML (`0.4`, `"hard-spheres"`, `[1.0, 0.0, 0.0]`); a bare
    /// word that is not TOML is taken as a string (`collisions.kernel=vhs`); an empty value
    /// removes the key (`collisions.restitution=`).
    pub assignment: String,
}

impl Override {
    /// `--set key.path=value`.
    pub fn set(assignment: impl Into<String>) -> Self {
        Override {
            source: "--set".into(),
            assignment: assignment.into(),
        }
    }

    /// A flag that sets one key, e.g. `Override::flag("n", "particles.n", 64)` for `--n 64`.
    pub fn flag(flag: &str, key: &str, value: impl std::fmt::Display) -> Self {
        Override {
            source: format!("--{flag}"),
            assignment: format!("{key}={value}"),
        }
    }

    /// The overrides of the flags `--n`, `--ensembles` and `--seed` (and the Python keywords
    /// of the same names), in that order: the keys `particles.n`, `run.ensembles`, `run.seed`,
    /// validated as the file's, errors naming the flag.
    pub fn run_flags(n: Option<i64>, ensembles: Option<i64>, seed: Option<u64>) -> Vec<Self> {
        let mut flags = Vec::new();
        flags.extend(n.map(|n| Override::flag("n", "particles.n", n)));
        flags.extend(ensembles.map(|m| Override::flag("ensembles", "run.ensembles", m)));
        flags.extend(seed.map(|s| Override::flag("seed", "run.seed", s)));
        flags
    }

    /// A keyword argument of the Python binding that sets one key, e.g.
    /// `Override::keyword("ensembles", "run.ensembles", 0)`: its errors name `ensembles=0`, the
    /// caller's words, not a command's flag.
    pub fn keyword(name: &str, key: &str, value: impl std::fmt::Display) -> Self {
        Override {
            source: format!("{name}={value}"),
            assignment: format!("{key}={value}"),
        }
    }

    /// [`Override::run_flags`] as the Python keywords `n=`, `ensembles=` and `seed=`.
    pub fn run_keywords(n: Option<i64>, ensembles: Option<i64>, seed: Option<u64>) -> Vec<Self> {
        let mut words = Vec::new();
        words.extend(n.map(|n| Override::keyword("n", "particles.n", n)));
        words.extend(ensembles.map(|m| Override::keyword("ensembles", "run.ensembles", m)));
        words.extend(seed.map(|s| Override::keyword("seed", "run.seed", s)));
        words
    }

    /// Whether this override and `other` set the same value: the same key, or one a table
    /// holding the other's key.
    pub fn overlaps(&self, other: &Override) -> bool {
        let (a, b) = (self.key(), other.key());
        let nested = |outer: &str, inner: &str| {
            inner.len() > outer.len()
                && inner.starts_with(outer)
                && inner.as_bytes()[outer.len()] == b'.'
        };
        a == b || nested(a, b) || nested(b, a)
    }

    fn key(&self) -> &str {
        self.assignment
            .split_once('=')
            .map_or(self.assignment.as_str(), |(k, _)| k)
            .trim()
    }
}

/// Applies `overrides` to scene text and validates the result. The file is validated first, so
/// its own errors keep their line numbers; an override's error names the override.
pub fn parse_with(path: &Path, text: &str, overrides: &[Override]) -> Result<Scene, Error> {
    let scene = parse(path, text)?;
    if overrides.is_empty() {
        return Ok(scene);
    }
    let merged = merge(path, text, overrides)?;
    parse(Path::new("--set"), &merged).map_err(|e| match e {
        Error::Invalid { key, message, .. } => {
            let source = overrides.iter().rev().find(|o| o.key() == key);
            bad(source, &key, message)
        }
        Error::Parse { message, .. } => {
            let first = message.lines().last().unwrap_or("").trim().to_string();
            // The override that breaks the schema: the first whose prefix of the overrides no
            // longer reads (only on this error path), else the last; named alone, by its source.
            let k = (1..overrides.len())
                .find(|&k| {
                    matches!(
                        parse_with(path, text, &overrides[..k]),
                        Err(Error::Invalid { ref key, ref message, .. })
                            if key == overrides[k - 1].key() && message.starts_with(SCHEMA)
                    )
                })
                .unwrap_or(overrides.len());
            let o = &overrides[k - 1];
            bad(Some(o), o.key(), format!("{SCHEMA}: {first}"))
        }
        other => other,
    })
}

/// The scene text that [`parse_with`] validates: `text` itself without overrides (its comments
/// kept), else the file's keys with the overrides put in, as TOML. `gdsmc run` of it alone is
/// the run of `text` with `overrides` (the browser page offers it for download).
pub fn merged_text(path: &Path, text: &str, overrides: &[Override]) -> Result<String, Error> {
    parse_with(path, text, overrides)?;
    if overrides.is_empty() {
        return Ok(text.to_string());
    }
    merge(path, text, overrides)
}

/// An error of the override `o` (or of `--set`) at `key`.
fn bad(o: Option<&Override>, key: &str, message: String) -> Error {
    Error::Invalid {
        path: PathBuf::from(o.map_or("--set", |o| o.source.as_str())),
        line: 0,
        key: key.to_string(),
        message,
    }
}

/// The file's keys with the overrides put in, as TOML (not yet validated).
fn merge(path: &Path, text: &str, overrides: &[Override]) -> Result<String, Error> {
    // A key given twice (`--n 64 --set particles.n=nan`, or a table and a key in it) would have
    // the later value replace the earlier before either is checked: refused, naming both.
    for (i, a) in overrides.iter().enumerate() {
        for b in &overrides[..i] {
            if a.overlaps(b) {
                return Err(bad(
                    Some(a),
                    a.key(),
                    format!(
                        "is set twice ({} {} and {} {}): give each key once",
                        b.source, b.assignment, a.source, a.assignment
                    ),
                ));
            }
        }
    }
    let mut doc: toml::Table = crate::toml_of(path, text)?;
    for o in overrides {
        // A line break would let one value carry further keys (`0.5\nfoo = 1`), which the
        // TOML reader below would take as a second assignment and drop.
        if o.assignment.contains(['\n', '\r']) {
            return Err(bad(
                Some(o),
                o.key(),
                "must be one line: the value holds a line break".into(),
            ));
        }
        let Some((key, raw)) = o.assignment.split_once('=') else {
            return Err(bad(
                Some(o),
                &o.assignment,
                "must have the form key.path=value".into(),
            ));
        };
        let key = key.trim();
        // An empty value removes the key (`--set collisions.restitution=`).
        let remove = raw.trim().is_empty();
        let value = match toml::from_str::<toml::Table>(&format!("v = {raw}")) {
            Ok(mut t) => t.remove("v"),
            Err(_) => None,
        }
        .unwrap_or_else(|| toml::Value::String(raw.trim().to_string()));
        let parts: Vec<&str> = key.split('.').collect();
        if parts.iter().any(|p| p.is_empty()) {
            return Err(bad(Some(o), key, "is not a dotted key path".into()));
        }
        let mut table = &mut doc;
        for part in &parts[..parts.len() - 1] {
            // `species[1]`: a table of an array of tables (`[[species]]`), which must exist.
            if let Some((name, index)) = indexed(part) {
                let element = match table.get_mut(name) {
                    Some(toml::Value::Array(a)) => a.get_mut(index),
                    _ => None,
                };
                table = match element {
                    Some(toml::Value::Table(t)) => t,
                    _ => {
                        return Err(bad(
                            Some(o),
                            key,
                            format!("`{part}` names no table of the scene"),
                        ));
                    }
                };
                continue;
            }
            let entry = table
                .entry(part.to_string())
                .or_insert_with(|| toml::Value::Table(toml::Table::new()));
            table = match entry {
                toml::Value::Table(t) => t,
                _ => {
                    return Err(bad(
                        Some(o),
                        key,
                        format!("`{part}` is a value, not a table"),
                    ));
                }
            };
        }
        if remove {
            table.remove(parts[parts.len() - 1]);
        } else {
            table.insert(parts[parts.len() - 1].to_string(), value);
        }
    }
    toml::to_string(&doc).map_err(|e| Error::Parse {
        path: path.to_path_buf(),
        message: e.to_string(),
    })
}

/// The words of an override that the scene schema does not read.
const SCHEMA: &str = "does not fit the scene schema";

/// `name[k]` as `(name, k)`.
fn indexed(part: &str) -> Option<(&str, usize)> {
    let (name, rest) = part.split_once('[')?;
    let index = rest.strip_suffix(']')?.parse().ok()?;
    Some((name, index))
}

/// [`parse_with`] for `--set` assignments.
pub fn parse_with_overrides(path: &Path, text: &str, sets: &[String]) -> Result<Scene, Error> {
    let overrides: Vec<Override> = sets.iter().map(Override::set).collect();
    parse_with(path, text, &overrides)
}

/// Reads a scene file and applies overrides.
pub fn load_with(path: &Path, overrides: &[Override]) -> Result<Scene, Error> {
    parse_with(path, &read(path)?, overrides)
}

/// Reads a scene file and applies `--set` assignments.
pub fn load_with_overrides(path: &Path, sets: &[String]) -> Result<Scene, Error> {
    load_with(path, &sets.iter().map(Override::set).collect::<Vec<_>>())
}

/// A validated scene with what it was made from: the file's path and text (read once) and the
/// overrides applied to it. A run's journal records these, so that a continued run or a merge
/// rebuilds the same scene; the command and the Python package both start from one.
#[derive(Clone, Debug)]
pub struct Sourced {
    /// The scene file (or the name standing for it in messages).
    pub path: PathBuf,
    /// The file's text, without the overrides.
    pub text: String,
    /// The overrides, in the order given.
    pub overrides: Vec<Override>,
    /// The validated scene: `text` with `overrides`.
    pub scene: Scene,
}

impl Sourced {
    /// Validates `text` (named `path` in messages) with `overrides`.
    pub fn parse(path: &Path, text: String, overrides: Vec<Override>) -> Result<Self, Error> {
        let scene = parse_with(path, &text, &overrides)?;
        Ok(Sourced {
            path: path.to_path_buf(),
            text,
            overrides,
            scene,
        })
    }

    /// Reads the scene file at `path` once and validates it with `overrides`.
    pub fn read(path: &Path, overrides: Vec<Override>) -> Result<Self, Error> {
        Sourced::parse(path, read(path)?, overrides)
    }

    /// This scene with one more override, validated. An earlier override of the same key (or
    /// of a table holding it) is replaced, so no key is ever given twice.
    pub fn with(&self, o: Override) -> Result<Self, Error> {
        let mut overrides = self.overrides.clone();
        overrides.retain(|e| !e.overlaps(&o));
        overrides.push(o);
        Sourced::parse(&self.path, self.text.clone(), overrides)
    }
}
