//! `[drive]`: which drive, and only the keys that drive uses. A drive declared by its type
//! ([`gdsmc_core::drive::Declared`]) has the keys its declaration names, with their defaults;
//! none, white noise and the host medium are written out here.

use super::Ctx;
use super::declared::Table;
use crate::error::Error;
use crate::schema::{BackgroundKind, DriveSpec};
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

/// Where the file names the drive's kind (0..0 when it does not).
fn kind_span(d: &DriveSpec) -> std::ops::Range<usize> {
    d.kind.as_ref().map_or(0..0, Spanned::span)
}

/// The drive, with the keys that hold its parameters.
pub(super) fn drive(ctx: &mut Ctx<'_>, d: &DriveSpec) -> Result<DriveChoice, Error> {
    let kind = d.kind();
    let table = Table {
        name: "drive",
        numbers: &d.numbers,
        kind_span: kind_span(d),
        kind_words: format!("kind = \"{}\"", kind.scene_name()),
    };
    let others = d
        .kernel
        .map(|_| ("kernel", 0..0))
        .into_iter()
        .chain(d.drift.as_ref().map(|v| ("drift", v.span())));
    table.only(ctx, &keys_of(kind), others, &table.kind_words)?;
    Ok(match kind {
        DriveKind::None => DriveChoice::None,
        DriveKind::WhiteNoise => {
            DriveChoice::WhiteNoise(table.required(ctx, "beta", Param::Beta)?)
        }
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
                c1: table.or_default(ctx, "c", Param::BackgroundC, 1.0),
                density: table.or_default(ctx, "density", Param::BackgroundDensity, 1.0),
                mass: table.or_default(ctx, "mass", Param::BackgroundMass, 1.0),
                temperature: table.or_default(
                    ctx,
                    "temperature",
                    Param::BackgroundTemperature,
                    1.0,
                ),
                drift: drift.map_or([0.0; 3], |s| s.get_ref().0),
            }
        }
        declared => {
            let specs = declared.params().unwrap_or(&[]);
            let values = table.declared(ctx, specs, |i| Param::Drive(declared, i))?;
            let params = DriveParams::new(declared, &values)
                .expect("a declared drive takes one value per parameter");
            DriveChoice::Declared(params)
        }
    })
}
