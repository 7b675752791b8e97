//! The keys of a table whose variant declares its parameters by its type (a drive's
//! [`gdsmc_core::drive::Declared`], a kernel's [`gdsmc_core::kernel::Declared`], a scheme's
//! [`gdsmc_core::physics::SchemeKind::params`]): each number
//! read under its declared name with its default, recorded as holding its parameter, and every
//! key the variant does not have refused with the keys it has.

use super::Ctx;
use crate::error::Error;
use gdsmc_core::declared::ParamSpec;
use gdsmc_core::physics::Param;
use std::collections::BTreeMap;
use std::ops::Range;
use toml::Spanned;

/// A table's numbers and the variant it names.
pub(super) struct Table<'a> {
    /// The table's name (`drive`, `collisions`).
    pub name: &'static str,
    /// Its numeric keys, by name.
    pub numbers: &'a BTreeMap<String, Spanned<f64>>,
    /// Where the file names the variant (0..0 when it does not).
    pub kind_span: Range<usize>,
    /// The variant as the file names it: `kind = "langevin"`, `kernel = "vhs"`.
    pub kind_words: String,
}

impl Table<'_> {
    /// A required number: its value, recorded as holding `param`.
    pub fn required(&self, ctx: &mut Ctx<'_>, key: &str, param: Param) -> Result<f64, Error> {
        match self.numbers.get(key) {
            Some(v) => {
                ctx.holds(param, format!("{}.{key}", self.name), v.span());
                Ok(*v.get_ref())
            }
            None => ctx.invalid(
                self.kind_span.clone(),
                &format!("{}.{key}", self.name),
                format!("is required with {}", self.kind_words),
            ),
        }
    }

    /// A number with a default, recorded as holding `param`.
    pub fn or_default(&self, ctx: &mut Ctx<'_>, key: &str, param: Param, default: f64) -> f64 {
        let v = self
            .numbers
            .get(key)
            .cloned()
            .unwrap_or_else(|| Spanned::new(0..0, default));
        ctx.holds(param, format!("{}.{key}", self.name), v.span());
        *v.get_ref()
    }

    /// The values of the declared parameters `specs` in their order, parameter `i` named
    /// `param(i)`; what a spec leaves out is required unless it has a default.
    pub fn declared(
        &self,
        ctx: &mut Ctx<'_>,
        specs: &[ParamSpec],
        param: impl Fn(usize) -> Param,
    ) -> Result<Vec<f64>, Error> {
        let mut values = Vec::with_capacity(specs.len());
        for (i, p) in specs.iter().enumerate() {
            values.push(match p.default {
                Some(x) => self.or_default(ctx, p.name, param(i), x),
                None => self.required(ctx, p.name, param(i))?,
            });
        }
        Ok(values)
    }

    /// Refuses the first of the numbers and the `others` written that is not one of `keys`,
    /// naming the keys the table has with this variant (`whose`: `kind = "langevin"`,
    /// `[collisions] with kernel = "vhs"`).
    pub fn only(
        &self,
        ctx: &Ctx<'_>,
        keys: &[&str],
        others: impl Iterator<Item = (&'static str, Range<usize>)>,
        whose: &str,
    ) -> Result<(), Error> {
        let numbers = self.numbers.iter().map(|(k, v)| (k.as_str(), v.span()));
        let others = others.map(|(k, span): (&str, _)| (k, span));
        for (key, span) in numbers.chain(others) {
            if !keys.contains(&key) {
                let has = if keys.is_empty() {
                    "it has no other key".to_string()
                } else {
                    format!("its keys: {}", keys.join(", "))
                };
                return ctx.invalid(
                    span,
                    &format!("{}.{key}", self.name),
                    format!("is not a key of {whose} ({has})"),
                );
            }
        }
        Ok(())
    }
}
