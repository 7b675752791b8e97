//! What a variant declared by its type says of each of its parameters (rand_distr's model: the
//! parameter, its rule and the rule's words beside the constructor): its name, its [`Rule`],
//! its words, its unit, its default and an example value. Drives
//! ([`crate::drive::Declared`]) and kernels ([`crate::kernel::Declared`]) declare their
//! parameters so; every front end (scene keys, the C ABI's parameter arrays, the validation's
//! errors, the fuzzers, the documentation) is derived from these declarations.

use crate::math::Real;

/// The rule a declared parameter's value obeys. Its refusal is the physics error every front
/// end prints (`drive.friction must be > 0, got -1`, `collisions.lambda must lie in [0, 1],
/// got 2`).
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Rule {
    /// Any finite number.
    Finite,
    /// A finite number `>= 0`.
    AtLeastZero,
    /// A finite number `> 0`.
    Positive,
    /// A number in the closed interval `[lo, hi]`, written `range` (`"[0, 1]"`).
    Within {
        /// The least value.
        lo: Real,
        /// The greatest value.
        hi: Real,
        /// The interval as text.
        range: &'static str,
    },
    /// A number in the half-open interval `(lo, hi]`, written `range` (`"(0, 1]"`).
    AboveAtMost {
        /// The bound the value must exceed.
        lo: Real,
        /// The greatest value.
        hi: Real,
        /// The interval as text.
        range: &'static str,
    },
}

impl Rule {
    /// Whether `x` obeys the rule.
    #[must_use]
    pub fn holds(self, x: Real) -> bool {
        x.is_finite()
            && match self {
                Rule::Finite => true,
                Rule::AtLeastZero => x >= 0.0,
                Rule::Positive => x > 0.0,
                Rule::Within { lo, hi, .. } => lo <= x && x <= hi,
                Rule::AboveAtMost { lo, hi, .. } => lo < x && x <= hi,
            }
    }
}

/// The rule in words, as a scene's documentation and the C header state it ("a finite number
/// > 0", "a number in [0, 1]").
impl core::fmt::Display for Rule {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        match self {
            Rule::Finite => f.write_str("a finite number"),
            Rule::AtLeastZero => f.write_str("a finite number >= 0"),
            Rule::Positive => f.write_str("a finite number > 0"),
            Rule::Within { range, .. } | Rule::AboveAtMost { range, .. } => {
                write!(f, "a number in {range}")
            }
        }
    }
}

/// A parameter of a variant declared by its type.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ParamSpec {
    /// Its name: the scene key (under `[drive]` for a drive, `[collisions]` for a kernel), the
    /// name in errors and in titles.
    pub name: &'static str,
    /// The rule its value obeys.
    pub rule: Rule,
    /// What it is, in words (documentation, the C header's comments).
    pub words: &'static str,
    /// Its unit, in the scene's units (`"1/time"`, `"temperature"`, `"1"`).
    pub unit: &'static str,
    /// Its value when the scene leaves it out (`None`: required).
    pub default: Option<Real>,
    /// A typical value that obeys the rule: the combination matrix, the fuzzers and the
    /// documentation's examples run the variant with it.
    pub example: Real,
}

/// The values of `params` taken from `values` in their order, the rest of the `N` places 0;
/// `None` when `values` has fewer than `params` (the rest of `values` is ignored).
#[must_use]
pub fn fill<const N: usize>(params: &[ParamSpec], values: &[Real]) -> Option<[Real; N]> {
    let given = values.get(..params.len())?;
    let mut all = [0.0; N];
    all.get_mut(..given.len())?.copy_from_slice(given);
    Some(all)
}

/// Each parameter's example value ([`ParamSpec::example`]) in its place, the rest 0.
#[must_use]
pub fn examples<const N: usize>(params: &[ParamSpec]) -> [Real; N] {
    let mut all = [0.0; N];
    for (v, p) in all.iter_mut().zip(params) {
        *v = p.example;
    }
    all
}

/// The value of the parameter named `name` among `params`, whose values are `values`.
#[must_use]
pub fn named(params: &[ParamSpec], values: &[Real], name: &str) -> Option<Real> {
    let i = params.iter().position(|p| p.name == name)?;
    values.get(i).copied()
}

/// A title's list of declared parameters, ` (friction = 0.5, temperature = 2)`; nothing when
/// there are none.
pub fn write_params(
    f: &mut core::fmt::Formatter<'_>,
    specs: &[ParamSpec],
    values: &[Real],
) -> core::fmt::Result {
    for (i, (p, v)) in specs.iter().zip(values).enumerate() {
        let sep = if i == 0 { " (" } else { ", " };
        write!(f, "{sep}{} = {v}", p.name)?;
    }
    if values.is_empty() {
        Ok(())
    } else {
        f.write_str(")")
    }
}

/// Checks a table of declared parameters: at most `max`, named uniquely, defaults and examples
/// that obey their rules. `Err` names the first parameter that breaks this.
pub fn check_specs(params: &[ParamSpec], max: usize) -> Result<(), &'static str> {
    if params.len() > max {
        return Err("more parameters than its array holds");
    }
    for (i, p) in params.iter().enumerate() {
        if params[..i].iter().any(|q| q.name == p.name) {
            return Err(p.name);
        }
        if !p.default.is_none_or(|d| p.rule.holds(d)) || !p.rule.holds(p.example) {
            return Err(p.name);
        }
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    const UNIT: Rule = Rule::Within {
        lo: 0.0,
        hi: 1.0,
        range: "[0, 1]",
    };

    /// Each rule refuses what its words exclude, and every rule refuses what is not finite.
    #[test]
    fn rules_hold_as_worded() {
        let alpha = Rule::AboveAtMost {
            lo: 0.0,
            hi: 1.0,
            range: "(0, 1]",
        };
        for r in [Rule::Finite, Rule::AtLeastZero, Rule::Positive, UNIT, alpha] {
            assert!(!r.holds(Real::NAN) && !r.holds(Real::INFINITY), "{r:?}");
            assert!(r.holds(1.0), "{r:?}");
        }
        assert!(Rule::Finite.holds(-1.0) && !Rule::AtLeastZero.holds(-1.0));
        assert!(Rule::AtLeastZero.holds(0.0) && !Rule::Positive.holds(0.0));
        assert!(UNIT.holds(0.0) && !UNIT.holds(1.0 + 1e-12) && !UNIT.holds(-1e-300));
        assert!(!alpha.holds(0.0) && alpha.holds(1e-300) && !alpha.holds(1.0 + 1e-12));
        let mut words = heapless::String::<32>::new();
        core::fmt::Write::write_fmt(&mut words, format_args!("{alpha}")).unwrap();
        assert_eq!(words.as_str(), "a number in (0, 1]");
    }

    /// A table with a repeated name, or an example its rule refuses, is refused.
    #[test]
    fn bad_tables_are_refused() {
        let p = ParamSpec {
            name: "x",
            rule: UNIT,
            words: "",
            unit: "1",
            default: None,
            example: 0.5,
        };
        assert_eq!(check_specs(&[p], 1), Ok(()));
        assert_eq!(check_specs(&[p, p], 4), Err("x"));
        assert!(check_specs(&[p, p], 1).is_err());
        let bad = ParamSpec { example: 2.0, ..p };
        assert_eq!(check_specs(&[bad], 1), Err("x"));
        let bad = ParamSpec {
            default: Some(-1.0),
            ..p
        };
        assert_eq!(check_specs(&[bad], 1), Err("x"));
    }
}
