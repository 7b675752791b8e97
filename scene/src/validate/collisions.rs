//! `[collisions]`: the kernel (`gamma`, `c` and the keys its declaration names,
//! [`gdsmc_core::kernel::Declared`]) and the restitution law.

use super::Ctx;
use super::declared::Table;
use crate::error::Error;
use crate::schema::CollisionsSpec;
use gdsmc_core::physics::{DimensionChoice, KernelChoice, LawKind, Param, RestitutionLaw};

/// The keys of `[collisions]` with every kernel (a kernel's own follow them; `diameter` and
/// `density` are for hard particles, `super::size`).
pub const COMMON_KEYS: [&str; 8] = [
    "kernel",
    "gamma",
    "c",
    "diameter",
    "density",
    "restitution",
    "impact_speed_law",
    "pair_restitution",
];

/// The kernel and the restitution law, with the keys that hold their parameters, and the
/// words of a strength derived from `diameter` and `density` (`super::size`).
pub(super) fn collisions(
    ctx: &mut Ctx<'_>,
    c: &CollisionsSpec,
    dimension: DimensionChoice,
    mixture: bool,
) -> Result<(KernelChoice, RestitutionLaw, Option<String>), Error> {
    ctx.holds(Param::Gamma, "collisions.gamma", c.gamma.span());
    ctx.holds(Param::C, "collisions.c", c.c.span());
    let derived = super::size::derived(ctx, c, dimension, mixture)?;
    let kind = *c.kernel.get_ref();
    let table = Table {
        name: "collisions",
        numbers: &c.numbers,
        kind_span: c.kernel.span(),
        kind_words: format!("kernel = \"{}\"", kind.scene_name()),
    };
    let specs = kind.params();
    let keys: Vec<&str> = COMMON_KEYS
        .iter()
        .copied()
        .chain(specs.iter().map(|p| p.name))
        .collect();
    let whose = format!("[collisions] with {}", table.kind_words);
    table.only(ctx, &keys, std::iter::empty(), &whose)?;
    let values = table.declared(ctx, specs, |i| Param::Kernel(kind, i))?;
    let (gamma, cc) = match &derived {
        Some(d) => (1.0, d.strength),
        None => (*c.gamma.get_ref(), *c.c.get_ref()),
    };
    let kernel = KernelChoice::new(kind, gamma, cc, &values)
        .expect("a kernel takes one value per parameter");
    if let (Some(r), Some(_)) = (&c.restitution, &c.pair_restitution) {
        return ctx.invalid(
            r.span(),
            "collisions.restitution",
            "and collisions.pair_restitution exclude each other",
        );
    }
    let law = match (&c.restitution, &c.impact_speed_law) {
        // Every pair's coefficient is given (checked against the species by species.rs).
        (None, None) if c.pair_restitution.is_some() => RestitutionLaw::Constant(1.0),
        (Some(r), None) => {
            ctx.holds(
                Param::Law(LawKind::Constant, 0),
                "collisions.restitution",
                r.span(),
            );
            RestitutionLaw::Constant(*r.get_ref())
        }
        (None, Some(law)) => {
            // Its keys are its declaration's (`LawKind::params`).
            let kind = LawKind::ImpactSpeed;
            let table = Table {
                name: "collisions.impact_speed_law",
                numbers: law.get_ref(),
                kind_span: law.span(),
                kind_words: "collisions.impact_speed_law".into(),
            };
            let keys: Vec<&str> = kind.params().iter().map(|p| p.name).collect();
            table.only(
                ctx,
                &keys,
                std::iter::empty(),
                "collisions.impact_speed_law",
            )?;
            let values = table.declared(ctx, kind.params(), |i| Param::Law(kind, i))?;
            RestitutionLaw::new(kind, &values).expect("one value per declared parameter")
        }
        (Some(r), Some(_)) => {
            return ctx.invalid(
                r.span(),
                "collisions.restitution",
                "and collisions.impact_speed_law exclude each other",
            );
        }
        (None, None) => {
            return ctx.invalid(
                0..0,
                "collisions.restitution",
                format!(
                    "is required (a coefficient in {}), or give collisions.impact_speed_law",
                    gdsmc_core::restitution::ALPHA_RANGE
                ),
            );
        }
    };
    Ok((kernel, law, derived.map(|d| d.words)))
}
