//! `[scheme]`: which scheme, its step, and (a rule of observing) that the observation times lie
//! on a splitting scheme's grid.

use super::Ctx;
use crate::error::Error;
use crate::schema::{SchemeKind, SchemeSpec};
use gdsmc_core::physics::{Param, SchemeChoice};

pub use gdsmc_core::physics::DEFAULT_STEP_FACTOR;

/// The scheme, with the keys that hold its parameters.
pub(super) fn scheme(ctx: &mut Ctx<'_>, sch: &SchemeSpec) -> Result<SchemeChoice, Error> {
    ctx.holds(Param::Scheme, "scheme.kind", 0..0);
    if sch.kind != SchemeKind::TimeStepped
        && let Some(f) = &sch.step_factor
    {
        return ctx.invalid(
            f.span(),
            "scheme.step_factor",
            "is only used with kind = \"time-stepped\"",
        );
    }
    Ok(match (sch.kind, &sch.dt) {
        (SchemeKind::NoSplitting | SchemeKind::TimeStepped, Some(d)) => {
            return ctx.invalid(
                d.span(),
                "scheme.dt",
                "is only used with kind = \"euler\" or \"strang\"",
            );
        }
        (SchemeKind::NoSplitting, None) => SchemeChoice::NoSplitting,
        (SchemeKind::TimeStepped, None) => match &sch.step_factor {
            Some(f) => {
                ctx.holds(Param::StepFactor, "scheme.step_factor", f.span());
                SchemeChoice::TimeStepped(*f.get_ref())
            }
            None => SchemeChoice::TimeStepped(DEFAULT_STEP_FACTOR),
        },
        (_, None) => {
            return ctx.invalid(
                0..0,
                "scheme.dt",
                "is required with kind = \"euler\" or \"strang\"",
            );
        }
        (kind, Some(d)) => {
            ctx.holds(Param::Dt, "scheme.dt", d.span());
            if kind == SchemeKind::Euler {
                SchemeChoice::Euler(*d.get_ref())
            } else {
                SchemeChoice::Strang(*d.get_ref())
            }
        }
    })
}

/// A splitting scheme observes only on its grid: every observation time a multiple of `dt`.
pub(super) fn on_grid(
    ctx: &Ctx<'_>,
    sch: &SchemeSpec,
    scheme: SchemeChoice,
    times: &[f64],
) -> Result<(), Error> {
    let at = sch.dt.as_ref().map_or(0..0, |d| d.span());
    match grid_problem(scheme, times) {
        Some(message) => ctx.invalid(at, "scheme.dt", message),
        None => Ok(()),
    }
}

/// The rule of `scheme.dt` against the observation times (a splitting scheme observes only on
/// its grid, [`gdsmc_core::engine::grid_index`]): what is wrong, or `None`.
pub(crate) fn grid_problem(scheme: SchemeChoice, times: &[f64]) -> Option<String> {
    let (SchemeChoice::Euler(dt) | SchemeChoice::Strang(dt)) = scheme else {
        return None;
    };
    // The run starts at 0 (the engine is launched there) and ends at its last time.
    let t_end = times.last().copied().unwrap_or(0.0);
    if let Err(e) = scheme.check_span(t_end) {
        return Some(e.problem.to_string());
    }
    let t = *times
        .iter()
        .find(|&&t| gdsmc_core::engine::grid_index(0.0, dt, t).is_none())?;
    Some(if t / dt >= u64::MAX as f64 {
        format!("= {dt} is too small: reaching t = {t} would take more than 2^64 steps")
    } else {
        format!("must divide every observation time; {t} is not a multiple of {dt}")
    })
}
