//! `[scheme]` as read: the scheme and its own keys by type (which keys a scheme has is the
//! core's declaration, [`SchemeKind::params`], checked by `validate/scheme.rs`).

use gdsmc_core::physics::SchemeKind;
use serde::Deserialize;
use std::collections::BTreeMap;
use toml::Spanned;

/// `[scheme]`.
#[derive(Debug, Clone)]
pub struct SchemeSpec {
    /// Which scheme (default the exact no-splitting scheme), and where the file says so.
    pub kind: Spanned<SchemeKind>,
    /// Every other key, a number: the scheme's parameters (a splitting's `dt`, the
    /// time-stepped scheme's `step_factor`), by name.
    pub numbers: BTreeMap<String, Spanned<f64>>,
}

impl Default for SchemeSpec {
    fn default() -> Self {
        SchemeSpec {
            kind: Spanned::new(0..0, SchemeKind::NoSplitting),
            numbers: BTreeMap::new(),
        }
    }
}

impl<'de> Deserialize<'de> for SchemeSpec {
    fn deserialize<D: serde::Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        use serde::de::Error;
        let keys = BTreeMap::<String, Spanned<toml::Value>>::deserialize(d)?;
        let mut spec = SchemeSpec::default();
        for (key, value) in keys {
            let span = value.span();
            let value = value.into_inner();
            if key == "kind" {
                let kind = super::kind_word(
                    value,
                    "scheme",
                    SchemeKind::ALL.iter().map(|&k| (k.scene_name(), k)),
                )
                .map_err(D::Error::custom)?;
                spec.kind = Spanned::new(span, kind);
            } else {
                let x = f64::deserialize(value)
                    .map_err(|e| D::Error::custom(format!("scheme.{key}: {e}")))?;
                spec.numbers.insert(key, Spanned::new(span, x));
            }
        }
        Ok(spec)
    }
}
