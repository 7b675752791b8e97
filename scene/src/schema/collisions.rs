//! `[collisions]` as read: the kernel, its constants and its own keys by type (which keys a
//! kernel has is the core's declaration, [`gdsmc_core::kernel::Declared`], checked by
//! `validate/collisions.rs`), and the restitution law.

use gdsmc_core::physics::KernelKind;
use serde::Deserialize;
use toml::Spanned;

/// `[collisions]`.
#[derive(Debug, Clone)]
pub struct CollisionsSpec {
    /// The kernel, and where the file says so.
    pub kernel: Spanned<KernelKind>,
    /// Collision-rate constant gamma of GRW (1) (> 0). Default 1.
    pub gamma: Spanned<f64>,
    /// Kernel constant C_lambda (> 0). Default 1/(4 pi).
    pub c: Spanned<f64>,
    /// Restitution coefficient alpha in (0, 1] (a constant law).
    pub restitution: Option<Spanned<f64>>,
    /// The impact-speed law BRS (9)-(10) instead of a constant: `{ beta0 = ..., delta = ... }`,
    /// its numbers by name (which keys it has is the core's declaration,
    /// [`gdsmc_core::physics::LawKind::params`]), each with the table's place.
    pub impact_speed_law: Option<Spanned<std::collections::BTreeMap<String, Spanned<f64>>>>,
    /// A mixture's restitution per species pair: a symmetric `S x S` matrix (default: the
    /// constant `restitution` for every pair).
    pub pair_restitution: Option<Spanned<Vec<Vec<f64>>>>,
    /// Every other key, a number: the kernel's own parameters (VHS's `lambda`), by name.
    pub numbers: std::collections::BTreeMap<String, Spanned<f64>>,
}

impl<'de> Deserialize<'de> for CollisionsSpec {
    fn deserialize<D: serde::Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        use serde::de::Error;
        let keys = std::collections::BTreeMap::<String, Spanned<toml::Value>>::deserialize(d)?;
        let mut kernel = None;
        let mut spec = CollisionsSpec {
            kernel: Spanned::new(0..0, KernelKind::Maxwell),
            gamma: super::one(),
            c: Spanned::new(0..0, 1.0 / (4.0 * std::f64::consts::PI)),
            restitution: None,
            impact_speed_law: None,
            pair_restitution: None,
            numbers: Default::default(),
        };
        let number = |key: &str, value: toml::Value| {
            f64::deserialize(value).map_err(|e| D::Error::custom(format!("collisions.{key}: {e}")))
        };
        for (key, value) in keys {
            let span = value.span();
            let value = value.into_inner();
            match key.as_str() {
                "kernel" => {
                    let kind = super::kind_word(
                        value,
                        "kernel",
                        KernelKind::ALL.iter().map(|&k| (k.scene_name(), k)),
                    )
                    .map_err(D::Error::custom)?;
                    kernel = Some(Spanned::new(span, kind));
                }
                "gamma" => spec.gamma = Spanned::new(span, number(&key, value)?),
                "c" => spec.c = Spanned::new(span, number(&key, value)?),
                "restitution" => spec.restitution = Some(Spanned::new(span, number(&key, value)?)),
                "impact_speed_law" => {
                    let law = std::collections::BTreeMap::<String, f64>::deserialize(value)
                        .map_err(|e| {
                            D::Error::custom(format!("collisions.impact_speed_law: {e}"))
                        })?;
                    let law = law
                        .into_iter()
                        .map(|(k, x)| (k, Spanned::new(span.clone(), x)))
                        .collect();
                    spec.impact_speed_law = Some(Spanned::new(span, law));
                }
                "pair_restitution" => {
                    let m = Vec::<Vec<f64>>::deserialize(value).map_err(|e| {
                        D::Error::custom(format!("collisions.pair_restitution: {e}"))
                    })?;
                    spec.pair_restitution = Some(Spanned::new(span, m));
                }
                _ => {
                    let x = number(&key, value)?;
                    spec.numbers.insert(key, Spanned::new(span, x));
                }
            }
        }
        spec.kernel = kernel.ok_or_else(|| D::Error::missing_field("kernel"))?;
        Ok(spec)
    }
}
