//! `[sweep]`: the keys `gdsmc sweep` varies, each `KEY=VALUES` checked by the `--vary` rules
//! ([`crate::vary`]) at the table's line, and the points they make (a grid, or zipped lists of
//! one length). Each point's scene is validated by the sweep, before anything runs.

use super::Ctx;
use crate::error::Error;
use crate::schema::SweepSpec;
use crate::vary::{Combine, Plan, Vary, points};

/// The sweep plan of the file, if it has a `[sweep]` table.
pub(crate) fn sweep(ctx: &Ctx<'_>, spec: &Option<SweepSpec>) -> Result<Option<Plan>, Error> {
    let Some(s) = spec else {
        return Ok(None);
    };
    let span = s.vary.span();
    let vary = s
        .vary
        .get_ref()
        .iter()
        .enumerate()
        .map(|(i, v)| {
            Vary::parse(v).map_err(|m| ctx.error(span.clone(), &format!("sweep.vary[{i}]"), m))
        })
        .collect::<Result<Vec<_>, _>>()?;
    let combine = if s.zip { Combine::Zip } else { Combine::Grid };
    points(&vary, combine).map_err(|m| ctx.error(span.clone(), "sweep.vary", m))?;
    Ok(Some(Plan { vary, combine }))
}
