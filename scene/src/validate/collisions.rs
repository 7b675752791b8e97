//! `[collisions]`: the kernel and the restitution law.

use super::Ctx;
use crate::error::Error;
use crate::schema::{CollisionsSpec, ImpactSpeedSpec, KernelKind};
use gdsmc_core::physics::{KernelChoice, Param, RestitutionLaw};

/// The kernel and the restitution law, with the keys that hold their parameters.
pub(super) fn collisions(
    ctx: &mut Ctx<'_>,
    c: &CollisionsSpec,
) -> Result<(KernelChoice, RestitutionLaw), Error> {
    ctx.holds(Param::Gamma, "collisions.gamma", c.gamma.span());
    ctx.holds(Param::C, "collisions.c", c.c.span());
    let (gamma, cc) = (*c.gamma.get_ref(), *c.c.get_ref());
    let kernel = match (c.kernel, &c.lambda) {
        (KernelKind::Maxwell | KernelKind::HardSpheres, Some(l)) => {
            return ctx.invalid(
                l.span(),
                "collisions.lambda",
                "is only used with kernel = \"vhs\"",
            );
        }
        (KernelKind::Maxwell, None) => KernelChoice::Maxwell { gamma, c: cc },
        (KernelKind::HardSpheres, None) => KernelChoice::HardSpheres { gamma, c: cc },
        (KernelKind::Vhs, None) => {
            return ctx.invalid(
                0..0,
                "collisions.lambda",
                "is required with kernel = \"vhs\"",
            );
        }
        (KernelKind::Vhs, Some(l)) => {
            ctx.holds(Param::Lambda, "collisions.lambda", l.span());
            KernelChoice::Vhs {
                gamma,
                c: cc,
                lambda: *l.get_ref(),
            }
        }
    };
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
            ctx.holds(Param::Restitution, "collisions.restitution", r.span());
            RestitutionLaw::Constant(*r.get_ref())
        }
        (None, Some(law)) => {
            let key = "collisions.impact_speed_law";
            ctx.holds(Param::Beta0, format!("{key}.beta0"), law.span());
            ctx.holds(Param::Delta, format!("{key}.delta"), law.span());
            let ImpactSpeedSpec { beta0, delta } = *law.get_ref();
            RestitutionLaw::ImpactSpeed { beta0, delta }
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
    Ok((kernel, law))
}
