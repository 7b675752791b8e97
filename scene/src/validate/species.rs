//! `[[species]]` and `collisions.pair_restitution`: a granular mixture. The file's own rules
//! (fractions, the matrix's shape and symmetry, which keys go together) are checked here; the
//! physical rules (masses, temperatures, diameters, restitution, beta) by the core's
//! [`gdsmc_core::physics::Physics::validate`], reported at the keys recorded here.

use super::Ctx;
use crate::error::Error;
use crate::schema::{InitialKind, SceneFile};
use gdsmc_core::physics::DriveKind;
use gdsmc_core::physics::{MAX_PAIRS, MAX_SPECIES, Param, Shown, SpeciesChoice};
use toml::Spanned;

/// The species and the per-pair restitution of a scene.
pub(crate) struct Mixture {
    /// The species (empty: one species).
    pub species: heapless::Vec<SpeciesChoice, MAX_SPECIES>,
    /// Per pair type (empty: the constant restitution for every pair).
    pub pair_restitution: heapless::Vec<f64, MAX_PAIRS>,
    /// Rough mixtures: the tangential restitution per pair type (empty: the rotation's).
    pub pair_tangential_restitution: heapless::Vec<f64, MAX_PAIRS>,
    /// The species' labels.
    pub names: Vec<String>,
    /// The species' mole fractions as written.
    pub fractions: Vec<f64>,
}

/// Particles per species: `x_s n` rounded by largest remainders (ties to the first species),
/// so the counts add up to `n` exactly.
pub fn counts(fractions: &[f64], n: usize) -> Vec<usize> {
    let total: f64 = fractions.iter().sum();
    let exact: Vec<f64> = fractions.iter().map(|x| x / total * n as f64).collect();
    let mut counts: Vec<usize> = exact.iter().map(|x| x.floor() as usize).collect();
    let mut left = n.saturating_sub(counts.iter().sum());
    let mut order: Vec<usize> = (0..fractions.len()).collect();
    order.sort_by(|&a, &b| {
        let (ra, rb) = (exact[a] - exact[a].floor(), exact[b] - exact[b].floor());
        rb.partial_cmp(&ra)
            .unwrap_or(std::cmp::Ordering::Equal)
            .then(a.cmp(&b))
    });
    for &s in order.iter().cycle() {
        if left == 0 {
            break;
        }
        counts[s] += 1;
        left -= 1;
    }
    counts
}

/// The mixture of `file` (n particles), with the keys that hold its parameters.
pub(super) fn mixture(ctx: &mut Ctx<'_>, file: &SceneFile, n: usize) -> Result<Mixture, Error> {
    let mut out = Mixture {
        species: heapless::Vec::new(),
        pair_restitution: heapless::Vec::new(),
        pair_tangential_restitution: heapless::Vec::new(),
        names: Vec::new(),
        fractions: Vec::new(),
    };
    let pairs = &file.collisions.pair_restitution;
    let tangential = file
        .rotation
        .as_ref()
        .and_then(|r| r.pair_tangential_restitution.as_ref());
    let Some(list) = &file.species else {
        if let Some(m) = pairs {
            return ctx.invalid(
                m.span(),
                "collisions.pair_restitution",
                "is only used with [[species]]",
            );
        }
        if let Some(m) = tangential {
            return ctx.invalid(
                m.span(),
                "rotation.pair_tangential_restitution",
                "is only used with [[species]]",
            );
        }
        return Ok(out);
    };
    let span = list.span();
    let list = list.get_ref();
    if list.is_empty() || list.len() > MAX_SPECIES {
        return ctx.invalid(
            span,
            "species",
            format!("must hold 1 to {MAX_SPECIES} species, got {}", list.len()),
        );
    }
    let ini = &file.particles.initial;
    if ini.kind != InitialKind::Maxwellian
        || ini.mass.is_some()
        || ini.temperature.is_some()
        || ini.drift.is_some()
        || ini.components.is_some()
    {
        return ctx.invalid(
            span,
            "particles.initial",
            "is not used with [[species]]: each species starts from a Maxwellian at its own \
             `temperature`",
        );
    }
    let mut fractions = Vec::new();
    for (k, s) in list.iter().enumerate() {
        let x = *s.fraction.get_ref();
        if !(x.is_finite() && x > 0.0) {
            return ctx.invalid(
                s.fraction.span(),
                &format!("species[{k}].fraction"),
                format!("must be a finite number > 0, got {}", Shown(x)),
            );
        }
        fractions.push(x);
    }
    let counts = counts(&fractions, n);
    out.fractions = fractions;
    let drive_beta = file.drive.numbers.get("beta").map_or(0.0, |b| *b.get_ref());
    for (k, s) in list.iter().enumerate() {
        if counts[k] == 0 {
            return ctx.invalid(
                s.fraction.span(),
                &format!("species[{k}].fraction"),
                format!("gives no particle at n = {n}: raise `particles.n` or the fraction"),
            );
        }
        let key = |name: &str| format!("species[{k}].{name}");
        ctx.holds(Param::SpeciesCount(k), key("fraction"), s.fraction.span());
        ctx.holds(Param::SpeciesMass(k), key("mass"), s.mass.span());
        ctx.holds(
            Param::SpeciesTemperature(k),
            key("temperature"),
            s.temperature.span(),
        );
        ctx.holds(
            Param::SpeciesDiameter(k),
            key("diameter"),
            s.diameter.span(),
        );
        let beta = match &s.beta {
            Some(b) if file.drive.kind() != DriveKind::WhiteNoise => {
                return ctx.invalid(
                    b.span(),
                    &key("beta"),
                    "is only used with drive.kind = \"white-noise\"",
                );
            }
            Some(b) => {
                ctx.holds(Param::SpeciesBeta(k), key("beta"), b.span());
                *b.get_ref()
            }
            None => {
                let span = file.drive.numbers.get("beta").map_or(0..0, |b| b.span());
                ctx.holds(Param::SpeciesBeta(k), "drive.beta", span);
                drive_beta
            }
        };
        let mut rotation = |value: &Option<Spanned<f64>>, param: Param, name: &str| {
            value.as_ref().map(|v| {
                ctx.holds(param, key(name), v.span());
                *v.get_ref()
            })
        };
        let inertia = rotation(&s.inertia, Param::SpeciesInertia(k), "inertia");
        let rotation_temperature = rotation(
            &s.rotation_temperature,
            Param::SpeciesRotationTemperature(k),
            "rotation_temperature",
        );
        let rotation_noise = rotation(
            &s.rotation_noise,
            Param::SpeciesRotationNoise(k),
            "rotation_noise",
        );
        let _ = out.species.push(SpeciesChoice {
            count: counts[k],
            mass: *s.mass.get_ref(),
            temperature: *s.temperature.get_ref(),
            diameter: *s.diameter.get_ref(),
            beta,
            inertia,
            rotation_temperature,
            rotation_noise,
        });
        out.names
            .push(s.name.clone().unwrap_or_else(|| format!("s{k}")));
    }
    for (k, a) in out.names.iter().enumerate() {
        if out.names[..k].contains(a)
            || a.is_empty()
            || !a
                .chars()
                .all(|c| c.is_ascii_alphanumeric() || c == '-' || c == '_')
        {
            return ctx.invalid(
                span.clone(),
                &format!("species[{k}].name"),
                format!("must be unique and made of letters, digits, '-' and '_', got {a:?}"),
            );
        }
    }
    if let Some(m) = pairs {
        out.pair_restitution = matrix(
            ctx,
            m,
            list.len(),
            "collisions.pair_restitution",
            Param::PairRestitution,
        )?;
    }
    if let Some(m) = tangential {
        out.pair_tangential_restitution = matrix(
            ctx,
            m,
            list.len(),
            "rotation.pair_tangential_restitution",
            Param::PairTangentialRestitution,
        )?;
    }
    Ok(out)
}

/// A symmetric `s x s` matrix of per-pair values at `key`, as the upper triangle in pair order
/// (`(0,0), (0,1), .., (1,1), ..`), each entry recorded as held by `key` for `param`.
fn matrix(
    ctx: &mut Ctx<'_>,
    m: &Spanned<Vec<Vec<f64>>>,
    s: usize,
    key: &str,
    param: fn(usize, usize) -> Param,
) -> Result<heapless::Vec<f64, MAX_PAIRS>, Error> {
    let rows = m.get_ref();
    if rows.len() != s || rows.iter().any(|r| r.len() != s) {
        return ctx.invalid(
            m.span(),
            key,
            format!("must be a {s} x {s} matrix (one row per species)"),
        );
    }
    let mut out = heapless::Vec::new();
    for (a, row) in rows.iter().enumerate() {
        for (b, &x) in row.iter().enumerate().skip(a) {
            if x != rows[b][a] {
                return ctx.invalid(
                    m.span(),
                    key,
                    format!(
                        "must be symmetric: row {a} column {b} is {}, row {b} column {a} is {}",
                        Shown(x),
                        Shown(rows[b][a])
                    ),
                );
            }
            ctx.holds(param(a, b), key, m.span());
            // At most MAX_SPECIES rows: the triangle fits.
            let _ = out.push(x);
        }
    }
    Ok(out)
}
