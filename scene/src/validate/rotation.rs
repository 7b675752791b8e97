//! `[rotation]`: rough particles. The table's values go into the core's
//! [`RotationChoice`] with the keys that hold them; every physical rule (beta's and kappa's
//! ranges, which drives, schemes and laws fit) is the core's
//! ([`gdsmc_core::physics::Physics::validate`]), reported at these keys.

use super::Ctx;
use crate::schema::RotationSpec;
use gdsmc_core::physics::{DimensionChoice, Param, RotationChoice};

/// The rotation of a scene, if it has a `[rotation]` table; an absent `inertia` is the core's
/// default for the dimension (uniform spheres or disks).
pub(super) fn rotation(
    ctx: &mut Ctx<'_>,
    r: &Option<RotationSpec>,
    dimension: DimensionChoice,
) -> Option<RotationChoice> {
    let r = r.as_ref()?;
    let defaults = RotationChoice::uniform(dimension, *r.tangential_restitution.get_ref());
    ctx.holds(Param::Rotation, "rotation", r.tangential_restitution.span());
    ctx.holds(
        Param::TangentialRestitution,
        "rotation.tangential_restitution",
        r.tangential_restitution.span(),
    );
    let inertia_span = r.inertia.as_ref().map_or(0..0, |k| k.span());
    ctx.holds(Param::Inertia, "rotation.inertia", inertia_span);
    ctx.holds(
        Param::RotationTemperature,
        "rotation.temperature",
        r.temperature.span(),
    );
    ctx.holds(Param::RotationNoise, "rotation.noise", r.noise.span());
    Some(RotationChoice {
        beta: *r.tangential_restitution.get_ref(),
        kappa: r.inertia.as_ref().map_or(defaults.kappa, |k| *k.get_ref()),
        temperature: *r.temperature.get_ref(),
        noise: *r.noise.get_ref(),
    })
}
