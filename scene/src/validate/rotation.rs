//! `[rotation]`: rough particles. The table's values go into the core's
//! [`RotationChoice`] with the keys that hold them; every physical rule (beta's and kappa's
//! ranges, which drives, schemes and laws fit) is the core's
//! ([`gdsmc_core::physics::Physics::validate`]), reported at these keys.

use super::Ctx;
use crate::schema::RotationSpec;
use gdsmc_core::physics::{Param, RotationChoice};

/// The rotation of a scene, if it has a `[rotation]` table.
pub(super) fn rotation(ctx: &mut Ctx<'_>, r: &Option<RotationSpec>) -> Option<RotationChoice> {
    let r = r.as_ref()?;
    ctx.holds(Param::Rotation, "rotation", r.tangential_restitution.span());
    ctx.holds(
        Param::TangentialRestitution,
        "rotation.tangential_restitution",
        r.tangential_restitution.span(),
    );
    ctx.holds(Param::Inertia, "rotation.inertia", r.inertia.span());
    ctx.holds(
        Param::RotationTemperature,
        "rotation.temperature",
        r.temperature.span(),
    );
    ctx.holds(Param::RotationNoise, "rotation.noise", r.noise.span());
    Some(RotationChoice {
        beta: *r.tangential_restitution.get_ref(),
        kappa: *r.inertia.get_ref(),
        temperature: *r.temperature.get_ref(),
        noise: *r.noise.get_ref(),
    })
}
