//! `[particles]`: the count and the initial distribution (a Maxwellian or a mixture).

use super::Ctx;
use crate::error::Error;
use crate::schema::{InitialKind, ParticlesSpec, one};
use gdsmc_core::physics::{Component, DimensionChoice, MAX_COMPONENTS, Momentum, Param};
use toml::Spanned;

type Initial = heapless::Vec<Component, MAX_COMPONENTS>;

fn span_of<T>(v: &Option<Spanned<T>>) -> std::ops::Range<usize> {
    v.as_ref().map_or(0..0, |s| s.span())
}

/// The dimension of `[particles]` (`dimension = 2` or `3`; absent: 3), recorded at its key.
pub(super) fn dimension(ctx: &mut Ctx<'_>, spec: &ParticlesSpec) -> Result<DimensionChoice, Error> {
    let Some(d) = &spec.dimension else {
        return Ok(DimensionChoice::Three);
    };
    ctx.holds(Param::Dimension, "particles.dimension", d.span());
    match *d.get_ref() {
        3 => Ok(DimensionChoice::Three),
        2 => Ok(DimensionChoice::Two),
        other => ctx.invalid(
            d.span(),
            "particles.dimension",
            format!("must be 2 (disks) or 3 (spheres), got {other}"),
        ),
    }
}

/// How the sample's momentum starts (`momentum = "drawn"` or `"exact"`; absent: drawn).
pub(super) fn momentum(ctx: &Ctx<'_>, spec: &ParticlesSpec) -> Result<Momentum, Error> {
    let Some(m) = &spec.momentum else {
        return Ok(Momentum::Drawn);
    };
    match Momentum::ALL
        .iter()
        .find(|k| k.scene_name() == m.get_ref().as_str())
    {
        Some(&k) => Ok(k),
        None => {
            let words: Vec<_> = Momentum::ALL.iter().map(|k| k.scene_name()).collect();
            ctx.invalid(
                m.span(),
                "particles.momentum",
                format!(
                    "unknown momentum `{}`, expected one of `{}`",
                    m.get_ref(),
                    words.join("`, `")
                ),
            )
        }
    }
}

/// The particle count and the initial components, with the keys that hold them.
pub(super) fn particles(
    ctx: &mut Ctx<'_>,
    spec: &ParticlesSpec,
) -> Result<(usize, Initial), Error> {
    ctx.holds(Param::N, "particles.n", spec.n.span());
    let ini = &spec.initial;
    let mut initial = Initial::new();
    match ini.kind {
        InitialKind::Maxwellian => {
            if let Some(c) = &ini.components {
                return ctx.invalid(
                    c.span(),
                    "particles.initial.components",
                    "is only used with kind = \"mixture\"",
                );
            }
            let key = "particles.initial";
            ctx.holds(Param::Mass(0), format!("{key}.mass"), span_of(&ini.mass));
            ctx.holds(
                Param::Temperature(0),
                format!("{key}.temperature"),
                span_of(&ini.temperature),
            );
            ctx.holds(Param::Drift(0), format!("{key}.drift"), span_of(&ini.drift));
            let _ = initial.push(Component {
                weight: 1.0,
                mass: *ini.mass.clone().unwrap_or_else(one).get_ref(),
                temperature: *ini.temperature.clone().unwrap_or_else(one).get_ref(),
                drift: ini.drift.as_ref().map_or([0.0; 3], |d| d.get_ref().0),
            });
        }
        InitialKind::Mixture => {
            for (key, span) in [
                ("mass", ini.mass.as_ref().map(|s| s.span())),
                ("temperature", ini.temperature.as_ref().map(|s| s.span())),
                ("drift", ini.drift.as_ref().map(|s| s.span())),
            ] {
                if let Some(span) = span {
                    return ctx.invalid(
                        span,
                        &format!("particles.initial.{key}"),
                        "belongs in each of `components` for kind = \"mixture\"",
                    );
                }
            }
            let Some(components) = &ini.components else {
                return ctx.invalid(
                    0..0,
                    "particles.initial.components",
                    "is required with kind = \"mixture\"",
                );
            };
            ctx.holds(
                Param::Components,
                "particles.initial.components",
                components.span(),
            );
            if components.get_ref().len() > MAX_COMPONENTS {
                return ctx.invalid(
                    components.span(),
                    "particles.initial.components",
                    format!(
                        "holds {} components; at most {MAX_COMPONENTS} are supported",
                        components.get_ref().len()
                    ),
                );
            }
            for (k, c) in components.get_ref().iter().enumerate() {
                let key = format!("particles.initial.components[{k}]");
                ctx.holds(Param::Weight(k), format!("{key}.weight"), c.weight.span());
                ctx.holds(Param::Mass(k), format!("{key}.mass"), c.mass.span());
                ctx.holds(
                    Param::Temperature(k),
                    format!("{key}.temperature"),
                    c.temperature.span(),
                );
                ctx.holds(Param::Drift(k), format!("{key}.drift"), span_of(&c.drift));
                let _ = initial.push(Component {
                    weight: *c.weight.get_ref(),
                    mass: *c.mass.get_ref(),
                    temperature: *c.temperature.get_ref(),
                    drift: c.drift.as_ref().map_or([0.0; 3], |d| d.get_ref().0),
                });
            }
        }
    }
    Ok((*spec.n.get_ref(), initial))
}
