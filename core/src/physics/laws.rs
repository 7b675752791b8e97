//! The restitution laws declared: each law's parameters ([`ParamSpec`]: name, rule, words,
//! unit), from which the scene's keys (`collisions.restitution`, the keys of
//! `collisions.impact_speed_law`), the validation's refusals and their words follow; a
//! [`RestitutionLaw`] is a kind with the values of its parameters.

use super::{LawKind, RestitutionLaw};
use crate::declared::{ParamSpec, Rule};
use crate::math::Real;
use crate::restitution::ALPHA_RANGE;

/// Most parameters a law has.
pub const MAX_LAW_PARAMS: usize = 2;

/// The constant coefficient of GRW (3).
const RESTITUTION: ParamSpec = ParamSpec {
    name: "restitution",
    rule: Rule::AboveAtMost {
        lo: 0.0,
        hi: 1.0,
        range: ALPHA_RANGE,
    },
    words: "the restitution coefficient alpha of every collision (GRW (3); 1: elastic)",
    unit: "1",
    default: None,
    example: 0.8,
};

/// `beta_0` of BRS (9)-(10).
const BETA0: ParamSpec = ParamSpec {
    name: "beta0",
    rule: Rule::AtLeastZero,
    words: "beta_0 of the impact-speed law 1 - e = 2 beta0 |g . n|^delta (BRS (9)-(10))",
    unit: "1/speed^delta",
    default: None,
    example: 0.1,
};

/// `delta` of BRS (9)-(10).
const DELTA: ParamSpec = ParamSpec {
    name: "delta",
    rule: Rule::AtLeastZero,
    words: "the exponent delta of the impact-speed law (BRS (9)-(10); 1/5: viscoelastic spheres)",
    unit: "1",
    default: None,
    example: 0.2,
};

impl LawKind {
    /// Its parameters, in the order of their values ([`RestitutionLaw::values`]): the constant
    /// law's one is its scene key itself, the impact-speed law's are the keys of its table.
    #[must_use]
    pub const fn params(self) -> &'static [ParamSpec] {
        match self {
            LawKind::Constant => &[RESTITUTION],
            LawKind::ImpactSpeed => &[BETA0, DELTA],
        }
    }
}

impl RestitutionLaw {
    /// The law `kind` with the values of its parameters in their order ([`LawKind::params`];
    /// the rest of `values` is ignored); `None` when `values` has fewer. The values are checked
    /// when the physics is validated.
    #[must_use]
    pub fn new(kind: LawKind, values: &[Real]) -> Option<Self> {
        Some(match kind {
            LawKind::Constant => RestitutionLaw::Constant(*values.first()?),
            LawKind::ImpactSpeed => RestitutionLaw::ImpactSpeed {
                beta0: *values.first()?,
                delta: *values.get(1)?,
            },
        })
    }

    /// The values of its parameters in the order of [`LawKind::params`], the rest of the
    /// array 0.
    #[must_use]
    pub fn values(&self) -> [Real; MAX_LAW_PARAMS] {
        match *self {
            RestitutionLaw::Constant(alpha) => [alpha, 0.0],
            RestitutionLaw::ImpactSpeed { beta0, delta } => [beta0, delta],
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Every law's declaration holds, and a law made from a kind's examples gives them back, of
    /// that kind.
    #[test]
    fn each_laws_declaration_round_trips() {
        for &k in LawKind::ALL {
            let params = k.params();
            assert_eq!(
                crate::declared::check_specs(params, MAX_LAW_PARAMS),
                Ok(()),
                "{k:?}"
            );
            let values: [Real; MAX_LAW_PARAMS] = crate::declared::examples(params);
            let law = RestitutionLaw::new(k, &values).expect("its examples make it");
            assert_eq!(law.kind(), k);
            assert_eq!(law.values(), values);
            assert_eq!(
                RestitutionLaw::new(k, &values[..params.len() - 1]),
                None,
                "{k:?}"
            );
        }
    }
}
