//! The schemes declared: each scheme's parameters ([`ParamSpec`]: name, rule, words, unit,
//! default), from which the scene's `[scheme]` keys, the validation's refusals and their words
//! follow; a [`SchemeChoice`] is a kind with the values of its parameters.

use super::{DEFAULT_STEP_FACTOR, SchemeChoice, SchemeKind, WEIGHTED_PARAMS};
use crate::declared::{ParamSpec, Rule};
use crate::math::Real;

/// The time step of RW's splittings (RW Algorithms 1-2).
const DT: ParamSpec = ParamSpec {
    name: "dt",
    rule: Rule::Positive,
    words: "the time step of the splitting (RW Algorithms 1-2); every observation time a \
            multiple of it, the run's last time at least one step",
    unit: "time",
    default: None,
    example: 0.25,
};

/// The step of MS's time-stepped scheme (MS Section 3).
const STEP_FACTOR: ParamSpec = ParamSpec {
    name: "step_factor",
    rule: Rule::Positive,
    words: "the time step in mean free paths over the thermal speed, h = step_factor lambda / \
            v0(t) (MS Section 3: 0.01)",
    unit: "1",
    default: Some(DEFAULT_STEP_FACTOR),
    example: DEFAULT_STEP_FACTOR,
};

/// The parameters of the weighted scheme ([`SchemeKind::Weighted`]), in the order of its
/// values: the weight transfer (Rjasanow and Wagner 1996; the tail's, 2001) and the reduction.
#[cfg(feature = "weighted")]
const WEIGHTED: [ParamSpec; WEIGHTED_PARAMS] = [
    ParamSpec {
        name: "kappa",
        rule: Rule::AtLeastZero,
        words: "the core's weight transfer: min(g_i, g_j)/(1 + kappa) moves",
        unit: "1",
        default: Some(0.0),
        example: 0.0,
    },
    ParamSpec {
        name: "tail_kappa",
        rule: Rule::AtLeastZero,
        words: "the transfer of a collision into the tail (at least kappa)",
        unit: "1",
        default: Some(7.0),
        example: 7.0,
    },
    ParamSpec {
        name: "tail_speed",
        rule: Rule::Positive,
        words: "where the tail starts, in units of sqrt(T) about the flow (a velocity component's standard deviation)",
        unit: "1",
        default: Some(3.0),
        example: 3.0,
    },
    ParamSpec {
        name: "capacity",
        rule: Rule::Within {
            lo: 2.0,
            hi: 64.0,
            range: "[2, 64]",
        },
        words: "the particles the buffers hold, times particles.n",
        unit: "1",
        default: Some(4.0),
        example: 4.0,
    },
    ParamSpec {
        name: "target",
        rule: Rule::AboveAtMost {
            lo: 0.0,
            hi: 64.0,
            range: "(0, 64]",
        },
        words: "the particles a reduction aims at, times particles.n",
        unit: "1",
        default: Some(2.0),
        example: 2.0,
    },
    ParamSpec {
        name: "exponent",
        rule: Rule::Within {
            lo: 0.0,
            hi: 1.0,
            range: "[0, 1]",
        },
        words: "shells share the particles as their weight to this power",
        unit: "1",
        default: Some(0.5),
        example: 0.5,
    },
    ParamSpec {
        name: "floor",
        rule: Rule::Within {
            lo: 0.0,
            hi: 0.95,
            range: "[0, 0.95]",
        },
        words: "the share of a reduction's particles given equally to every occupied speed \
                shell, the rest by weight to the exponent",
        unit: "1",
        default: Some(0.0),
        example: 0.25,
    },
    ParamSpec {
        name: "split",
        rule: Rule::AtLeastZero,
        words: "a particle heavier than this times its speed shell's share is split into \
                pieces of the share (0: never)",
        unit: "1",
        default: Some(0.0),
        example: 2.0,
    },
];

impl SchemeKind {
    /// Its parameters, in the order of their values ([`SchemeChoice::values`]).
    #[must_use]
    pub const fn params(self) -> &'static [ParamSpec] {
        match self {
            SchemeKind::NoSplitting => &[],
            SchemeKind::Euler | SchemeKind::Strang => &[DT],
            SchemeKind::TimeStepped => &[STEP_FACTOR],
            // Without the weighted loop the scheme is refused by name (`parts.rs`), and its
            // declarations stay out of the smallest firmware.
            #[cfg(feature = "weighted")]
            SchemeKind::Weighted => &WEIGHTED,
            #[cfg(not(feature = "weighted"))]
            SchemeKind::Weighted => &[],
        }
    }
}

impl SchemeChoice {
    /// The scheme `kind` with the values of its parameters in their order
    /// ([`SchemeKind::params`]; the rest of `values` is ignored); `None` when `values` has
    /// fewer. The values are checked when the physics is validated.
    #[must_use]
    pub fn new(kind: SchemeKind, values: &[Real]) -> Option<Self> {
        let first = || values.first().copied();
        Some(match kind {
            SchemeKind::NoSplitting => SchemeChoice::NoSplitting,
            SchemeKind::Euler => SchemeChoice::Euler(first()?),
            SchemeKind::Strang => SchemeChoice::Strang(first()?),
            SchemeKind::TimeStepped => SchemeChoice::TimeStepped(first()?),
            SchemeKind::Weighted => {
                SchemeChoice::Weighted(values.get(..WEIGHTED_PARAMS)?.try_into().ok()?)
            }
        })
    }

    /// The values of its parameters, in the order of [`SchemeKind::params`].
    #[must_use]
    pub fn values(&self) -> &[Real] {
        match self {
            SchemeChoice::NoSplitting => &[],
            SchemeChoice::Euler(dt) | SchemeChoice::Strang(dt) => core::slice::from_ref(dt),
            SchemeChoice::TimeStepped(f) => core::slice::from_ref(f),
            SchemeChoice::Weighted(v) => v,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Every scheme's declaration holds (unique names, defaults and examples that obey their
    /// rules), and a choice made from a kind's examples gives them back, of that kind.
    #[test]
    fn each_schemes_declaration_round_trips() {
        for &k in SchemeKind::ALL {
            assert_eq!(
                crate::declared::check_specs(k.params(), WEIGHTED_PARAMS),
                Ok(()),
                "{k:?}"
            );
            let values: [Real; WEIGHTED_PARAMS] = crate::declared::examples(k.params());
            let s = SchemeChoice::new(k, &values).expect("its examples make it");
            assert_eq!(s.kind(), k);
            assert_eq!(s.values(), &values[..k.params().len()]);
            if !k.params().is_empty() {
                assert_eq!(SchemeChoice::new(k, &[]), None, "{k:?}");
            }
        }
    }
}
