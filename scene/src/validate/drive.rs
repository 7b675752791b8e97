//! `[drive]`: which drive, and only the keys that drive uses. A drive declared by its type
//! ([`gdsmc_core::drive::Declared`]) has the keys its declaration names, with their defaults;
//! none, white noise and the host medium are written out here.

use super::Ctx;
use crate::error::Error;
use crate::schema::{BackgroundKind, DriveSpec};
use gdsmc_core::physics::MAX_DRIVE_PARAMS;
use gdsmc_core::physics::{BackgroundKernel, DriveChoice, DriveKind, DriveParams, Param};
use toml::Spanned;

/// The keys of the host medium's table besides `kind`.
const HOST_KEYS: [&str; 6] = ["kernel", "c", "density", "mass", "temperature", "drift"];

/// The keys `kind` reads besides `kind` itself.
pub fn keys_of(kind: DriveKind) -> Vec<&'static str> {
    match kind {
        DriveKind::None => vec![],
        DriveKind::WhiteNoise => vec!["beta"],
        DriveKind::HostMedium => HOST_KEYS.to_vec(),
        declared => declared
            .params()
            .map_or_else(Vec::new, |ps| ps.iter().map(|p| p.name).collect()),
    }
}

/// A required number of the drive: its value, recorded as holding `param`.
fn required(ctx: &mut Ctx<'_>, d: &DriveSpec, key: &str, param: Param) -> Result<f64, Error> {
    match d.numbers.get(key) {
        Some(v) => {
            ctx.holds(param, format!("drive.{key}"), v.span());
            Ok(*v.get_ref())
        }
        None => ctx.invalid(
            kind_span(d),
            &format!("drive.{key}"),
            format!("is required with kind = \"{}\"", d.kind().scene_name()),
        ),
    }
}

/// A number of the drive with a default, recorded as holding `param`.
fn or_default(ctx: &mut Ctx<'_>, d: &DriveSpec, key: &str, param: Param, default: f64) -> f64 {
    let v = d
        .numbers
        .get(key)
        .cloned()
        .unwrap_or_else(|| Spanned::new(0..0, default));
    ctx.holds(param, format!("drive.{key}"), v.span());
    *v.get_ref()
}

/// Where the file names the drive's kind (0..0 when it does not).
fn kind_span(d: &DriveSpec) -> std::ops::Range<usize> {
    d.kind.as_ref().map_or(0..0, Spanned::span)
}

/// The drive, with the keys that hold its parameters.
pub(super) fn drive(ctx: &mut Ctx<'_>, d: &DriveSpec) -> Result<DriveChoice, Error> {
    let kind = d.kind();
    let keys = keys_of(kind);
    let written = d
        .numbers
        .iter()
        .map(|(k, v)| (k.as_str(), v.span()))
        .chain(d.kernel.map(|_| ("kernel", 0..0)))
        .chain(d.drift.as_ref().map(|v| ("drift", v.span())));
    for (key, span) in written {
        if !keys.contains(&key) {
            let has = if keys.is_empty() {
                "it has no other key".to_string()
            } else {
                format!("its keys: {}", keys.join(", "))
            };
            return ctx.invalid(
                span,
                &format!("drive.{key}"),
                format!("is not a key of kind = \"{}\" ({has})", kind.scene_name()),
            );
        }
    }
    Ok(match kind {
        DriveKind::None => DriveChoice::None,
        DriveKind::WhiteNoise => DriveChoice::WhiteNoise(required(ctx, d, "beta", Param::Beta)?),
        DriveKind::HostMedium => {
            let Some(kernel) = d.kernel else {
                return ctx.invalid(
                    kind_span(d),
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
                c1: or_default(ctx, d, "c", Param::BackgroundC, 1.0),
                density: or_default(ctx, d, "density", Param::BackgroundDensity, 1.0),
                mass: or_default(ctx, d, "mass", Param::BackgroundMass, 1.0),
                temperature: or_default(ctx, d, "temperature", Param::BackgroundTemperature, 1.0),
                drift: drift.map_or([0.0; 3], |s| s.get_ref().0),
            }
        }
        declared => {
            let specs = declared.params().unwrap_or(&[]);
            let mut values = [0.0; MAX_DRIVE_PARAMS];
            for (i, p) in specs.iter().enumerate() {
                let param = Param::Drive(declared, i);
                values[i] = match p.default {
                    Some(x) => or_default(ctx, d, p.name, param, x),
                    None => required(ctx, d, p.name, param)?,
                };
            }
            let params = DriveParams::new(declared, &values[..specs.len()])
                .expect("a declared drive takes one value per parameter");
            DriveChoice::Declared(params)
        }
    })
}
