//! `collisions.diameter` and `collisions.density`: the rate constant of hard particles from
//! what a researcher measures. The kernels keep the total pair rate `4 pi gamma C |u|` in
//! both dimensions ([`gdsmc_core::geometry`]): hard spheres of diameter `sigma` at number
//! density `n` meet at `4 pi gamma C = pi sigma^2 n`, hard disks at areal density `n` at
//! `4 pi gamma C = 2 sigma n` (the cross-section of disks is the length `2 sigma`). So a
//! particle collides at the kinetic theory's Maxwellian rate, `4 sqrt(pi) n sigma^2 sqrt(T/m)`
//! (spheres) or `2 sqrt(pi) n sigma sqrt(T/m)` (disks), and the summary says what was derived.
//! A mixture gives `density` alone: its species' diameters already scale each pair's `C`
//! (`((d_s + d_t)/2)^2` for spheres, `(d_s + d_t)/2` for disks).

use super::Ctx;
use crate::error::Error;
use crate::schema::CollisionsSpec;
use gdsmc_core::physics::{DimensionChoice, Param};
use toml::Spanned;

/// The two keys, in the order a summary names them.
pub const KEYS: [&str; 2] = ["diameter", "density"];

/// `gamma C` and the words that say how it was derived.
pub(super) struct Derived {
    /// The kernel's strength `gamma C` (`gamma = 1`, `C` = this).
    pub strength: f64,
    /// What was derived, from which keys, for the summary.
    pub words: String,
}

/// A positive, finite number at `collisions.KEY`, or `None` when the key is absent.
fn positive(ctx: &Ctx<'_>, c: &CollisionsSpec, key: &str) -> Result<Option<f64>, Error> {
    let Some(v) = c.numbers.get(key) else {
        return Ok(None);
    };
    let x = *v.get_ref();
    if !(x.is_finite() && x > 0.0) {
        return ctx.invalid(
            v.span(),
            &format!("collisions.{key}"),
            format!("must be a finite number > 0, got {x}"),
        );
    }
    Ok(Some(x))
}

fn span(c: &CollisionsSpec, key: &str) -> std::ops::Range<usize> {
    c.numbers.get(key).map_or(0..0, Spanned::span)
}

/// The strength derived from `diameter` and `density`, or `None` when neither is given
/// (`gamma` and `c` then hold it). Refused: on a kernel that is not hard (its rate is not a
/// cross-section's), beside `gamma` or `c`, one of the two alone for one species, and a
/// `diameter` beside `[[species]]`.
pub(super) fn derived(
    ctx: &mut Ctx<'_>,
    c: &CollisionsSpec,
    dimension: DimensionChoice,
    mixture: bool,
) -> Result<Option<Derived>, Error> {
    let (sigma, n) = (positive(ctx, c, "diameter")?, positive(ctx, c, "density")?);
    let Some(first) = KEYS.iter().find(|k| c.numbers.contains_key(**k)) else {
        return Ok(None);
    };
    let at = span(c, first);
    let key = format!("collisions.{first}");
    let kind = *c.kernel.get_ref();
    if !kind.hard() {
        return ctx.invalid(
            at,
            &key,
            format!(
                "sets the collision rate of hard particles (kernel = \"hard-spheres\"); \
                 kernel = \"{}\" takes gamma and c",
                kind.scene_name()
            ),
        );
    }
    for (given, what) in [(c.gamma.span(), "gamma"), (c.c.span(), "c")] {
        if given != (0..0) {
            return ctx.invalid(
                given,
                &format!("collisions.{what}"),
                "and collisions.diameter/density exclude each other (they set gamma C)",
            );
        }
    }
    let d3 = dimension == DimensionChoice::Three;
    let (what, strength) = match (mixture, sigma, n) {
        (false, Some(s), Some(n)) if d3 => (
            format!(
                "hard spheres of diameter {s} at number density {n}: 4 pi gamma C = pi sigma^2 n"
            ),
            s * s * n / 4.0,
        ),
        (false, Some(s), Some(n)) => (
            format!("hard disks of diameter {s} at areal density {n}: 4 pi gamma C = 2 sigma n"),
            s * n / (2.0 * std::f64::consts::PI),
        ),
        (true, None, Some(n)) if d3 => (
            format!(
                "a mixture at number density {n}: 4 pi gamma C = pi n, each pair's C times ((d_s + d_t)/2)^2"
            ),
            n / 4.0,
        ),
        (true, None, Some(n)) => (
            format!(
                "a mixture of disks at areal density {n}: 4 pi gamma C = 2 n, each pair's C times (d_s + d_t)/2"
            ),
            n / (2.0 * std::f64::consts::PI),
        ),
        (true, Some(_), _) => {
            return ctx.invalid(
                span(c, "diameter"),
                "collisions.diameter",
                "is each species' own with [[species]] (species.diameter); give collisions.density alone",
            );
        }
        (_, _, None) => {
            return ctx.invalid(
                at,
                "collisions.density",
                "is required with collisions.diameter",
            );
        }
        (false, None, Some(_)) => {
            return ctx.invalid(
                at,
                "collisions.diameter",
                "is required with collisions.density",
            );
        }
    };
    // A strength the core refuses names the keys it came from.
    ctx.holds(Param::Gamma, key.clone(), at.clone());
    ctx.holds(Param::C, key, at);
    Ok(Some(Derived {
        strength,
        words: format!("gamma C = {strength} (gamma = 1) from collisions.diameter/density, {what}"),
    }))
}
