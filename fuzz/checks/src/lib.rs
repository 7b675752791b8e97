//! # gdsmc-fuzz-checks: the properties the fuzz targets check
//!
//! One function per fuzz target, taking the fuzzer's bytes. Each panics (a fuzzer crash) when a
//! property fails; everything else returns quietly. The same functions replay the checked-in
//! corpora as plain tests on the stable toolchain (`tests/replay.rs`).
//!
//! - [`collision_maps`]: GRW (3), its MS impact form, BRS (2), the impact-speed law BRS (9)-(10).
//! - [`rough_maps`]: the rough-sphere map and the impact direction (Huthmann and Zippelius
//!   1997).
//! - [`samplers`]: every sampler at extreme parameters: no NaN, no infinity, no endless loop.
//! - [`scene_reader`], [`scene_structured`]: arbitrary bytes and structure-aware TOML: an error
//!   or a valid scene whose physics validates, never a panic.
//! - [`state_reader`]: arbitrary bytes as a state file (`--initial-state`), and valid state files
//!   changed in one byte: a refusal naming the file, or a state within its bounds; a changed
//!   file always refused.
//! - [`c_abi`]: arbitrary configurations, sizes and enumeration integers through the C ABI: a
//!   status code, never a crash (under ASan in the fuzz build).

mod cabi;
mod maps;
mod rough;
mod samplers;
mod scene;
mod state;

pub use cabi::{MOST_KINDS, c_abi};
pub use maps::collision_maps;
pub use rough::rough_maps;
pub use samplers::samplers;
pub use scene::{KEYS, WORDS, scene_reader, scene_structured};
pub use state::state_reader;

use arbitrary::Unstructured;

/// A finite number of magnitude at most `max` drawn from the fuzzer's bytes, or `None` (the
/// input is then outside the property's domain and skipped).
pub(crate) fn bounded(u: &mut Unstructured<'_>, max: f64) -> Option<f64> {
    let x: f64 = u.arbitrary().ok()?;
    (x.is_finite() && x.abs() <= max).then_some(x)
}

/// A number from the fuzzer's bytes, of any magnitude or none (NaN, infinities), with extremes
/// and small integers more likely than uniform bits would make them.
pub(crate) fn wild(u: &mut Unstructured<'_>) -> f64 {
    const SPECIAL: [f64; 14] = [
        0.0,
        -0.0,
        1.0,
        -1.0,
        0.5,
        2.0,
        1e-300,
        5e-324,
        1e300,
        f64::MAX,
        f64::MIN_POSITIVE,
        f64::INFINITY,
        f64::NEG_INFINITY,
        f64::NAN,
    ];
    match u.int_in_range(0u8..=3).unwrap_or(0) {
        0 => SPECIAL[u.choose_index(SPECIAL.len()).unwrap_or(0)],
        1 => u.int_in_range(-1000i32..=1000).unwrap_or(0) as f64 / 8.0,
        _ => u.arbitrary().unwrap_or(0.0),
    }
}
