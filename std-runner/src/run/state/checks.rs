//! What a state file must hold before a run acts on it (docs/state.md, "The checks"): every
//! header field within its bounds and consistent with the others, and every record's values
//! ones a run can start from. The file's checksums ([`super::layout`]) tell damage; these tell
//! a file that is whole but says what no gdsmc run could have written (a forged or mistaken
//! header, a velocity that is not a number).

use super::StateHeader;
use super::layout::Layout;
use gdsmc_core::physics::Shown;

/// The most segments a state may follow. A continuation's streams are the seed's jumped
/// `2 (segment + 1)` long jumps per ensemble (module docs of [`super`]); at this bound that is
/// about 20 000 jumps, milliseconds per ensemble, where a forged `segment` of 10^15 took
/// forever and 2^64 - 1 wrapped to another segment's streams.
pub const MAX_SEGMENT: u64 = 10_000;

/// The largest magnitude of a stored velocity component: the sixth power of every velocity (the
/// run's highest moment, `a3`) stays below f64's largest number. No gas of any scene comes
/// near it; a value past it is damage or forgery.
pub const MAX_COMPONENT: f64 = 1e50;

/// Checks the header `h` read from a file of layout `layout`: the refusal in words.
pub fn header(h: &StateHeader, layout: Layout) -> Result<(), String> {
    if h.version != layout.version {
        return Err(format!(
            "its header says format version {} but the file is version {}",
            h.version, layout.version
        ));
    }
    if h.scene.is_empty() {
        return Err("its header names no scene".into());
    }
    if h.segment > MAX_SEGMENT {
        return Err(format!(
            "its header's segment {} is past the most this gdsmc continues ({MAX_SEGMENT}): a \
             forged or damaged header",
            h.segment
        ));
    }
    if !(h.time.is_finite() && h.time >= 0.0) {
        return Err(format!(
            "its header's time {} is not a time a run reaches (finite, at or after 0)",
            Shown(h.time)
        ));
    }
    if h.n == 0 {
        return Err("its header holds no particles (n = 0)".into());
    }
    if !matches!(h.dimension, 2 | 3) {
        return Err(format!(
            "its header's dimension {} is neither 2 nor 3",
            h.dimension
        ));
    }
    if h.ensembles == 0 {
        return Err("its header holds no ensembles".into());
    }
    if !h.species.is_empty()
        && (h.species.contains(&0)
            || h.species.iter().try_fold(0usize, |a, &c| a.checked_add(c)) != Some(h.n))
    {
        return Err(format!(
            "its header's species counts {:?} do not add up to its {} particles",
            h.species, h.n
        ));
    }
    let hex = h.origin.len() == 16 && h.origin.bytes().all(|b| b.is_ascii_hexdigit());
    if !(hex || h.origin == "none") {
        return Err(format!(
            "its header's origin `{}` is neither a process's hash nor \"none\"",
            gdsmc_scene::cut_lines(&h.origin, 40)
        ));
    }
    Ok(())
}

/// Checks record `k`'s values `x` (its collisions per particle, then `3 n` velocity
/// components, then for rough particles `3 n` rim-velocity components) against the header `h`:
/// the refusal in words, naming the particle and component.
pub fn record(x: &[f64], h: &StateHeader) -> Result<(), String> {
    let s = x[0];
    if !(s.is_finite() && s >= 0.0) {
        return Err(format!(
            "its collisions per particle {} are not a count (finite, at or above 0)",
            Shown(s)
        ));
    }
    let n = h.n;
    for (j, &v) in x[1..].iter().enumerate() {
        let (rim, i, c) = (j >= 3 * n, (j % (3 * n)) / 3, j % 3);
        let what = || {
            format!(
                "particle {i}'s {} {}",
                if rim { "rim velocity" } else { "velocity" },
                ["x", "y", "z"][c]
            )
        };
        if !(v.is_finite() && v.abs() <= MAX_COMPONENT) {
            return Err(format!(
                "{} is {}, not a velocity a run can start from (finite, at most {MAX_COMPONENT:e} \
                 in magnitude)",
                what(),
                Shown(v)
            ));
        }
        if h.dimension == 2 && !rim && c == 2 && v != 0.0 {
            return Err(format!(
                "{} is {} in a gas of dimension 2 (it is 0 in every file gdsmc writes)",
                what(),
                Shown(v)
            ));
        }
    }
    Ok(())
}
