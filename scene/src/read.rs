//! A scene from its text or its file: at most [`MAX_SCENE_BYTES`] read, parsed as TOML and
//! validated ([`parse`], [`load`]), or its `[sweep]` plan ([`sweep_plan`]).

use crate::error::Error;
use crate::schema::SceneFile;
use crate::{Scene, vary};
use std::path::{Path, PathBuf};

/// Most bytes a scene may have: a scene is a few KiB, and the TOML reader's memory grows with
/// its input many times over (50 MB of `=` once took 2.5 GB before the refusal).
pub const MAX_SCENE_BYTES: usize = 1 << 20;

/// The refusal of a scene text or file of `len` bytes or more, above [`MAX_SCENE_BYTES`].
fn too_large(path: &Path, len: usize) -> Error {
    Error::Parse {
        path: path.to_path_buf(),
        message: format!(
            "is {len} bytes or more, above the {} KiB a scene may have (a scene is a few KiB):              is this the scene file?",
            MAX_SCENE_BYTES >> 10
        ),
    }
}

/// Scene text read as TOML into `T`, refused before reading when above [`MAX_SCENE_BYTES`].
pub(crate) fn toml_of<T: serde::de::DeserializeOwned>(path: &Path, text: &str) -> Result<T, Error> {
    if text.len() > MAX_SCENE_BYTES {
        return Err(too_large(path, text.len()));
    }
    toml::from_str(text).map_err(|e| Error::Parse {
        path: PathBuf::from(path),
        message: e.to_string().trim_end().to_string(),
    })
}

/// Parses and validates scene text; `path` names the source in errors.
pub fn parse(path: &Path, text: &str) -> Result<Scene, Error> {
    let file: SceneFile = toml_of(path, text)?;
    file.validate(path, text)
}

/// The `[sweep]` plan of a scene file's text (`None` without the table), checked as the file
/// is: a bad value is named by its key and line.
pub fn sweep_plan(path: &Path, text: &str) -> Result<Option<vary::Plan>, Error> {
    let file: SceneFile = toml_of(path, text)?;
    file.sweep_plan(path, text)
}

/// Reads a scene file: at most [`MAX_SCENE_BYTES`] (a longer file is refused without being
/// read further), UTF-8.
pub fn read(path: &Path) -> Result<String, Error> {
    use std::io::Read;
    let err = |source| Error::Read {
        path: path.to_path_buf(),
        source,
    };
    let mut bytes = Vec::new();
    std::fs::File::open(path)
        .and_then(|f| f.take(MAX_SCENE_BYTES as u64 + 1).read_to_end(&mut bytes))
        .map_err(err)?;
    if bytes.len() > MAX_SCENE_BYTES {
        return Err(too_large(path, bytes.len()));
    }
    String::from_utf8(bytes)
        .map_err(|e| err(std::io::Error::new(std::io::ErrorKind::InvalidData, e)))
}

/// Reads, parses and validates a scene file.
pub fn load(path: &Path) -> Result<Scene, Error> {
    parse(path, &read(path)?)
}
