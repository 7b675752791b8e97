//! `[observe]`, the histogram tables and `[run]`: when to look, what to collect, how many
//! ensembles. These are rules of observing, not physics, and live here.

use super::Ctx;
use crate::error::Error;
use crate::schema::{HistogramSpec, ObserveSpec, RunSpec, SceneFile};
use crate::{Marginal, Shells};
use gdsmc_core::physics::Shown;
use toml::Spanned;

// The rules of observing, each once: the file's validation (with its spans) and the scene's
// setters ([`crate::Scene::set_ensembles`] and the others) both call them.

/// A finite number: what is wrong with `x`, or `None`.
fn finite_problem(x: f64) -> Option<String> {
    (!x.is_finite()).then(|| format!("must be a finite number, got {}", Shown(x)))
}

/// A finite number > 0 (a histogram's radius): what is wrong with `x`, or `None`.
pub(crate) fn positive_problem(x: f64) -> Option<String> {
    finite_problem(x).or_else(|| (x <= 0.0).then(|| format!("must be > 0, got {}", Shown(x))))
}

/// A bin or shell count in 1..=100000: what is wrong with `k`, or `None`.
pub(crate) fn count_problem(k: i64) -> Option<String> {
    (!(1..=100_000).contains(&k)).then(|| format!("must lie in 1..=100000, got {k}"))
}

/// The ensembles of a run (>= 1): what is wrong with `m`, or `None`.
pub(crate) fn ensembles_problem(m: i64) -> Option<String> {
    (m < 1).then(|| format!("must be >= 1, got {m}"))
}

/// The first observation of the steady-state window starting at time `x`: the first of
/// `times` at or after it, which must leave at least two observation times.
pub(crate) fn steady_index(times: &[f64], x: f64) -> Result<usize, String> {
    if let Some(why) = finite_problem(x) {
        return Err(why);
    }
    match times.iter().position(|&t| t >= x - 1e-12 * (1.0 + x.abs())) {
        Some(i) if i + 1 < times.len() => Ok(i),
        _ => Err(format!(
            "must leave at least two observation times at or after it (t_end = {}), got {}",
            Shown(times[times.len() - 1]),
            Shown(x)
        )),
    }
}

/// The observation of a snapshot time `x`: the first observation time at or after it (the rule
/// of `observe.steady_from`), or why there is none.
pub(crate) fn snapshot_index(times: &[f64], x: f64) -> Result<usize, String> {
    if let Some(why) = finite_problem(x) {
        return Err(why);
    }
    times
        .iter()
        .position(|&t| t >= x - 1e-12 * (1.0 + x.abs()))
        .ok_or_else(|| {
            format!(
                "each time must be at most the last observation time t_end = {}, got {}",
                Shown(times[times.len() - 1]),
                Shown(x)
            )
        })
}

/// The snapshot times of `observe.snapshots` (each checked against the observation times).
pub(super) fn snapshots(ctx: &Ctx<'_>, o: &ObserveSpec, times: &[f64]) -> Result<Vec<f64>, Error> {
    let Some(s) = &o.snapshots else {
        return Ok(Vec::new());
    };
    for &x in s.get_ref() {
        if let Err(why) = snapshot_index(times, x) {
            return ctx.invalid(s.span(), "observe.snapshots", why);
        }
    }
    Ok(s.get_ref().clone())
}

fn finite(ctx: &Ctx<'_>, v: &Spanned<f64>, key: &str) -> Result<f64, Error> {
    let x = *v.get_ref();
    match finite_problem(x) {
        None => Ok(x),
        Some(why) => ctx.invalid(v.span(), key, why),
    }
}

fn positive(ctx: &Ctx<'_>, v: &Spanned<f64>, key: &str) -> Result<f64, Error> {
    let x = *v.get_ref();
    match positive_problem(x) {
        None => Ok(x),
        Some(why) => ctx.invalid(v.span(), key, why),
    }
}

/// A bin or shell count in 1..=100000.
fn count(ctx: &Ctx<'_>, v: &Spanned<i64>, key: &str) -> Result<usize, Error> {
    let k = *v.get_ref();
    match count_problem(k) {
        None => Ok(k as usize),
        Some(why) => ctx.invalid(v.span(), key, why),
    }
}

/// The observation times: `t_start + (t_end - t_start) k / intervals`, `k = 0..=intervals`, or
/// with `spacing = "log"` the start and [`log_times`].
pub(super) fn times(ctx: &Ctx<'_>, o: &ObserveSpec) -> Result<Vec<f64>, Error> {
    let t0 = match &o.t_start {
        Some(s) => {
            let x = finite(ctx, s, "observe.t_start")?;
            if x < 0.0 {
                return ctx.invalid(
                    s.span(),
                    "observe.t_start",
                    format!("must be >= 0, got {}", Shown(x)),
                );
            }
            x
        }
        None => 0.0,
    };
    let t1 = finite(ctx, &o.t_end, "observe.t_end")?;
    if t1 <= t0 {
        return ctx.invalid(
            o.t_end.span(),
            "observe.t_end",
            format!(
                "must be later than observe.t_start = {}, got {}",
                Shown(t0),
                Shown(t1)
            ),
        );
    }
    let k = match &o.intervals {
        Some(s) => {
            let k = *s.get_ref();
            if !(1..=10_000_000).contains(&k) {
                return ctx.invalid(
                    s.span(),
                    "observe.intervals",
                    format!("must lie in 1..=10000000, got {k}"),
                );
            }
            k as usize
        }
        None => 32,
    };
    let span = t1 - t0;
    let log = match &o.spacing {
        None => false,
        Some(sp) => match sp.get_ref().as_str() {
            "linear" => false,
            "log" => true,
            other => {
                return ctx.invalid(
                    sp.span(),
                    "observe.spacing",
                    format!("must be \"linear\" or \"log\", got \"{other}\""),
                );
            }
        },
    };
    // `first` is checked whatever the spacing and used by the log spacing (so that `--set
    // observe.spacing=linear` can switch a log-spaced file back without removing it).
    let first = match &o.first {
        None => span / k as f64,
        Some(f) => {
            let x = positive(ctx, f, "observe.first")?;
            if x >= span {
                return ctx.invalid(
                    f.span(),
                    "observe.first",
                    format!(
                        "must be below t_end - t_start = {}, got {}",
                        Shown(span),
                        Shown(x)
                    ),
                );
            }
            x
        }
    };
    let times = if log {
        log_times(t0, span, first, k)
    } else {
        (0..=k).map(|i| t0 + span * i as f64 / k as f64).collect()
    };
    // The times must be numbers, each later than the one before: a `first` so small that
    // `span / first` overflows (5e-324; 1e-300 with t_end = 1e300) made them NaN, and a span
    // too short for its start in f64 makes two times equal.
    if let Some(i) = times
        .windows(2)
        .position(|w| !(w[1].is_finite() && w[1] > w[0]))
    {
        let (key, at) = match (&o.first, log) {
            (Some(f), true) => ("observe.first", f.span()),
            _ => ("observe.intervals", o.t_end.span()),
        };
        return ctx.invalid(
            at,
            key,
            format!(
                "makes observation time {} equal {}, not a number later than the time before \
                 it ({}): {}",
                i + 1,
                Shown(times[i + 1]),
                Shown(times[i]),
                if log {
                    "choose a larger observe.first (t_end / first must be a finite number)"
                } else {
                    "choose fewer observe.intervals or a longer span"
                }
            ),
        );
    }
    Ok(times)
}

/// The start `t0`, then `k` times evenly spaced in `log(t - t0)` from `t0 + first` to
/// `t0 + span` (the last exactly `t0 + span`; one time for `k = 1`).
pub fn log_times(t0: f64, span: f64, first: f64, k: usize) -> Vec<f64> {
    let mut out = vec![t0];
    if k == 1 {
        out.push(t0 + span);
        return out;
    }
    let ratio = libm::log(span / first);
    out.extend((0..k).map(|i| {
        if i + 1 == k {
            t0 + span
        } else {
            t0 + first * libm::exp(ratio * i as f64 / (k - 1) as f64)
        }
    }));
    out
}

/// The first steady-state observation (if asked), the collisional pairs per observation and
/// the time charts' axis.
pub(super) fn observe(
    ctx: &Ctx<'_>,
    o: &ObserveSpec,
    times: &[f64],
) -> Result<(Option<usize>, u64, crate::TimeAxis), Error> {
    let steady_from = match &o.steady_from {
        None => None,
        Some(sf) => match steady_index(times, *sf.get_ref()) {
            Ok(i) => Some(i),
            Err(why) => return ctx.invalid(sf.span(), "observe.steady_from", why),
        },
    };
    let pairs = match &o.collisional_pairs {
        None => 0,
        Some(k) if *k.get_ref() >= 0 => *k.get_ref() as u64,
        Some(k) => {
            return ctx.invalid(
                k.span(),
                "observe.collisional_pairs",
                format!("must be >= 0, got {}", k.get_ref()),
            );
        }
    };
    let axis = match &o.time_axis {
        None => crate::TimeAxis::Time,
        Some(a) => match a.get_ref().as_str() {
            "time" => crate::TimeAxis::Time,
            "collisions" => crate::TimeAxis::Collisions,
            other => {
                return ctx.invalid(
                    a.span(),
                    "observe.time_axis",
                    format!("must be \"time\" or \"collisions\", got \"{other}\""),
                );
            }
        },
    };
    Ok((steady_from, pairs, axis))
}

/// What the histogram tables ask for: the radial shells, the reduced shells and the marginal
/// bins.
pub(super) type Histograms = (Option<Shells>, Option<Shells>, Option<Marginal>);

/// The histogram tables.
pub(super) fn histograms(ctx: &Ctx<'_>, f: &SceneFile) -> Result<Histograms, Error> {
    let shells = |h: &Option<HistogramSpec>, table: &str| -> Result<_, Error> {
        let Some(h) = h else { return Ok(None) };
        let k = count(ctx, &h.shells, &format!("{table}.shells"))?;
        Ok(Some(Shells {
            shells: k,
            radius: positive(ctx, &h.radius, &format!("{table}.radius"))?,
        }))
    };
    let histogram = shells(&f.histogram, "histogram")?;
    let reduced = shells(&f.reduced_histogram, "reduced_histogram")?;
    let marginal = match &f.marginal_histogram {
        None => None,
        Some(h) => {
            let axis = *h.axis.get_ref();
            if !(1..=3).contains(&axis) {
                return ctx.invalid(
                    h.axis.span(),
                    "marginal_histogram.axis",
                    format!("must be 1, 2 or 3 (the velocity component), got {axis}"),
                );
            }
            let k = count(ctx, &h.bins, "marginal_histogram.bins")?;
            let r = positive(ctx, &h.radius, "marginal_histogram.radius")?;
            Some(Marginal {
                axis: axis as usize - 1,
                bins: k,
                radius: r,
            })
        }
    };
    Ok((histogram, reduced, marginal))
}

/// `[run]`: the number of ensembles (>= 1) and the seed (>= 0).
pub(super) fn run(ctx: &Ctx<'_>, r: &RunSpec) -> Result<(u64, u64), Error> {
    let m = *r.ensembles.get_ref();
    if let Some(why) = ensembles_problem(m) {
        return ctx.invalid(r.ensembles.span(), "run.ensembles", why);
    }
    let seed = *r.seed.get_ref();
    if seed < 0 {
        return ctx.invalid(
            r.seed.span(),
            "run.seed",
            format!("must be >= 0, got {seed}"),
        );
    }
    Ok((m as u64, seed as u64))
}
