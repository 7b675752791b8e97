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
            "is {len} bytes or more, above the {} KiB a scene may have (a scene is a few KiB): \
             is this the scene file?",
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
        message: cut_lines(e.to_string().trim_end(), MAX_LINE_CHARS),
    })
}

/// Most characters of one line of a message: the parser quotes the scene's line and the key
/// it does not know, and a 1 MB line was echoed three times over (3 MB of standard error).
pub const MAX_LINE_CHARS: usize = 160;

/// `text` with every line longer than `most` characters cut there, saying how much was left
/// out.
pub fn cut_lines(text: &str, most: usize) -> String {
    let cut = |line: &str| match line.char_indices().nth(most) {
        None => line.to_string(),
        Some((at, _)) => format!(
            "{}... ({} more characters)",
            &line[..at],
            line[at..].chars().count()
        ),
    };
    text.lines().map(cut).collect::<Vec<_>>().join("\n")
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
    // Only a regular file (a link to one included): a FIFO would block the open itself, and a
    // device or directory is no scene. Told by its type before it is opened, and again of
    // what was opened.
    let regular = |m: std::fs::Metadata| {
        if m.is_file() {
            Ok(())
        } else {
            Err(std::io::Error::new(
                std::io::ErrorKind::InvalidInput,
                "not a regular file (a FIFO, device or directory): a scene is a TOML file",
            ))
        }
    };
    std::fs::metadata(path).and_then(regular).map_err(err)?;
    let mut bytes = Vec::new();
    std::fs::File::open(path)
        .and_then(|f| {
            regular(f.metadata()?)?;
            f.take(MAX_SCENE_BYTES as u64 + 1).read_to_end(&mut bytes)
        })
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
