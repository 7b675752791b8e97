//! Scene text to configuration: the command's own scene reader (the `gdsmc-scene` crate), so a
//! scene file means the same to C as to `gdsmc run`. Needs the standard library.

use crate::config::gdsmc_config;
use crate::guard::{check_ptr, guard};
use crate::status::{Failure, fail, gdsmc_status, msg};
use std::ffi::{CStr, c_char};

/// Fills `*out` from a scene in TOML text (the format of the `gdsmc` command's scene files,
/// read and validated by the same code; observation times and ensemble counts are ignored).
/// Every kernel, drive, scheme and restitution law of the command is available. Fails with
/// GDSMC_PARSE_ERROR or GDSMC_INVALID_ARGUMENT and a message naming the line and key; `*out`
/// is untouched then. Only a single-Maxwellian initial distribution can be expressed in
/// gdsmc_config (a mixture is refused with a message). Not in the no_std build.
///
/// # Safety
/// `toml` must be NULL or a NUL-terminated string; `out` NULL or writable for one gdsmc_config.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn gdsmc_config_from_toml(
    toml: *const c_char,
    out: *mut gdsmc_config,
) -> gdsmc_status {
    guard(|| {
        check_ptr(toml, "toml")?;
        check_ptr(out, "out")?;
        // SAFETY: non-null; the caller promises a NUL-terminated string.
        let text = unsafe { CStr::from_ptr(toml) };
        let Ok(text) = text.to_str() else {
            return fail(gdsmc_status::GDSMC_PARSE_ERROR, "scene text is not UTF-8");
        };
        let cfg = from_scene_text(text)?;
        // SAFETY: checked non-null and aligned.
        unsafe { out.write(cfg) };
        Ok(())
    })
}

fn from_scene_text(text: &str) -> Result<gdsmc_config, Failure> {
    let path = std::path::Path::new("<toml>");
    let scene = gdsmc_scene::parse(path, text).map_err(|e| {
        let status = match e {
            gdsmc_scene::Error::Parse { .. } => gdsmc_status::GDSMC_PARSE_ERROR,
            _ => gdsmc_status::GDSMC_INVALID_ARGUMENT,
        };
        Failure(status, msg!("{e}"))
    })?;
    let mut cfg = gdsmc_config::from_physics(scene.physics())?;
    cfg.seed = scene.seed();
    Ok(cfg)
}
