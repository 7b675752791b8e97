//! `[drive]` as read: its kind and its keys by type (which keys a kind has is the
//! validation's, `validate/drive.rs`, from the core's declarations).

use super::{BackgroundKind, Vector3};
use gdsmc_core::physics::DriveKind;
use serde::Deserialize;
use toml::Spanned;

/// `[drive]`: its `kind` and the keys that kind reads. Which keys a kind has is known to
/// `validate/drive.rs` (a declared drive's from its declaration in the core,
/// [`gdsmc_core::drive::Declared`]); here every key is read by its type: `kernel` a background
/// kernel, `drift` a velocity, every other key a number.
#[derive(Debug, Clone, Default)]
pub struct DriveSpec {
    /// Which drive (default: none), and where the file says so.
    pub kind: Option<Spanned<DriveKind>>,
    /// Host medium: background kernel (required for `"host-medium"`).
    pub kernel: Option<BackgroundKind>,
    /// Host medium: background drift u^B. Default 0.
    pub drift: Option<Spanned<Vector3>>,
    /// Every numeric key (`beta`, the host medium's `c`, `density`, `mass`, `temperature`, a
    /// declared drive's parameters), by name.
    pub numbers: std::collections::BTreeMap<String, Spanned<f64>>,
}

impl DriveSpec {
    /// Which drive (default: none).
    pub fn kind(&self) -> DriveKind {
        self.kind.as_ref().map_or(DriveKind::None, |k| *k.get_ref())
    }
}

impl<'de> Deserialize<'de> for DriveSpec {
    fn deserialize<D: serde::Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        use serde::de::Error;
        let keys = std::collections::BTreeMap::<String, Spanned<toml::Value>>::deserialize(d)?;
        let mut spec = DriveSpec::default();
        for (key, value) in keys {
            let span = value.span();
            let value = value.into_inner();
            match key.as_str() {
                "kind" => {
                    let kind = super::kind_word(
                        value,
                        "drive kind",
                        DriveKind::ALL.iter().map(|&k| (k.scene_name(), k)),
                    )
                    .map_err(D::Error::custom)?;
                    spec.kind = Some(Spanned::new(span, kind));
                }
                "kernel" => {
                    spec.kernel =
                        Some(BackgroundKind::deserialize(value).map_err(D::Error::custom)?)
                }
                "drift" => {
                    let v = Vector3::deserialize(value).map_err(D::Error::custom)?;
                    spec.drift = Some(Spanned::new(span, v));
                }
                _ => {
                    let x = f64::deserialize(value)
                        .map_err(|e| D::Error::custom(format!("drive.{key}: {e}")))?;
                    spec.numbers.insert(key, Spanned::new(span, x));
                }
            }
        }
        Ok(spec)
    }
}
