//! Scene tests, one test binary: each file of this directory is a module here (one link of
//! the engine instead of one per file: the test build is faster and its binaries a fraction
//! of the disk). Run one file's tests with `cargo test --release -p gdsmc-scene --test all FILE::`.

mod docs_examples;
mod kinds;
mod mixture_scenes;
mod rough_scenes;
mod scene_errors;
mod size;
mod sweep_table;
mod weighted_scenes;

/// The error of parsing the scene `text` as `bad.toml`.
fn err(text: &str) -> String {
    gdsmc_scene::parse(std::path::Path::new("bad.toml"), text)
        .unwrap_err()
        .to_string()
}

/// Asserts that the scene `text` is refused with an error containing `words` (the file, line
/// and key where they are part of `words`).
#[track_caller]
fn refused(text: &str, words: &str) {
    let e = err(text);
    assert!(e.contains(words), "expected {words:?} in: {e}");
}
