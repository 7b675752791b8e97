//! Scene tests, one test binary: each file of this directory is a module here (one link of
//! the engine instead of one per file: the test build is faster and its binaries a fraction
//! of the disk). Run one file's tests with `cargo test --release -p gdsmc-scene --test all FILE::`.

mod docs_examples;
mod kinds;
mod mixture_scenes;
mod rough_scenes;
mod scene_errors;
mod sweep_table;
