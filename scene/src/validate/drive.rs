//! `[drive]`: which drive, and only the keys that drive uses.

use super::Ctx;
use crate::error::Error;
use crate::schema::{BackgroundKind, DriveKind, DriveSpec, one};
use gdsmc_core::physics::{BackgroundKernel, DriveChoice, Param};
use toml::Spanned;

/// A required drive key: its value, recorded as holding `param`.
fn required(
    ctx: &mut Ctx<'_>,
    v: &Option<Spanned<f64>>,
    param: Param,
    key: &str,
    kind: &str,
) -> Result<f64, Error> {
    match v {
        Some(v) => {
            ctx.holds(param, format!("drive.{key}"), v.span());
            Ok(*v.get_ref())
        }
        None => ctx.invalid(
            0..0,
            &format!("drive.{key}"),
            format!("is required with kind = \"{kind}\""),
        ),
    }
}

/// A host-medium key with default 1, recorded as holding `param`.
fn or_one(ctx: &mut Ctx<'_>, v: &Option<Spanned<f64>>, param: Param, key: &str) -> f64 {
    let v = v.clone().unwrap_or_else(one);
    ctx.holds(param, format!("drive.{key}"), v.span());
    *v.get_ref()
}

/// The drive, with the keys that hold its parameters.
pub(super) fn drive(ctx: &mut Ctx<'_>, d: &DriveSpec) -> Result<DriveChoice, Error> {
    let host_keys = [
        ("kernel", d.kernel.is_some()),
        ("c", d.c.is_some()),
        ("density", d.density.is_some()),
        ("mass", d.mass.is_some()),
        ("temperature", d.temperature.is_some()),
        ("drift", d.drift.is_some()),
    ];
    if d.kind != DriveKind::HostMedium
        && let Some((k, _)) = host_keys.iter().find(|(_, set)| *set)
    {
        return ctx.invalid(
            0..0,
            &format!("drive.{k}"),
            "is only used with kind = \"host-medium\"",
        );
    }
    for (key, kind, v, name) in [
        ("beta", DriveKind::WhiteNoise, &d.beta, "white-noise"),
        ("zeta", DriveKind::Gaussian, &d.zeta, "gaussian"),
        ("g", DriveKind::ConstantForce, &d.g, "constant-force"),
    ] {
        if d.kind != kind
            && let Some(b) = v
        {
            return ctx.invalid(
                b.span(),
                &format!("drive.{key}"),
                format!("is only used with kind = \"{name}\""),
            );
        }
    }
    Ok(match d.kind {
        DriveKind::None => DriveChoice::None,
        DriveKind::WhiteNoise => {
            DriveChoice::WhiteNoise(required(ctx, &d.beta, Param::Beta, "beta", "white-noise")?)
        }
        DriveKind::Gaussian => {
            DriveChoice::Gaussian(required(ctx, &d.zeta, Param::Zeta, "zeta", "gaussian")?)
        }
        DriveKind::ConstantForce => {
            DriveChoice::ConstantForce(required(ctx, &d.g, Param::G, "g", "constant-force")?)
        }
        DriveKind::HostMedium => {
            let Some(kernel) = d.kernel else {
                return ctx.invalid(
                    0..0,
                    "drive.kernel",
                    "is required with kind = \"host-medium\" (\"maxwell\" or \"hard-spheres\")",
                );
            };
            let drift = d.drift.as_ref();
            ctx.holds(
                Param::BackgroundDrift,
                "drive.drift",
                drift.map_or(0..0, |s| s.span()),
            );
            DriveChoice::HostMedium {
                kernel: match kernel {
                    BackgroundKind::Maxwell => BackgroundKernel::Maxwell,
                    BackgroundKind::HardSpheres => BackgroundKernel::HardSpheres,
                },
                c1: or_one(ctx, &d.c, Param::BackgroundC, "c"),
                density: or_one(ctx, &d.density, Param::BackgroundDensity, "density"),
                mass: or_one(ctx, &d.mass, Param::BackgroundMass, "mass"),
                temperature: or_one(
                    ctx,
                    &d.temperature,
                    Param::BackgroundTemperature,
                    "temperature",
                ),
                drift: drift.map_or([0.0; 3], |s| s.get_ref().0),
            }
        }
    })
}
