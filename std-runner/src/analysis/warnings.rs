//! Warnings: where a run's own diagnostics say its numbers cannot be trusted as they stand.
//! Each names the diagnostic that fired, the size of the expected error and what to do; the
//! stability study in docs/stability.md lists them with the failures they reveal.

use crate::run::RunStats;
use crate::run::columns::name;
use crate::scene::{DriveChoice, Scene, SchemeChoice};

/// Expected relative errors above this fire the step-size warnings.
pub const STEP_ERROR: f64 = 0.01;
/// Truncated-kernel events above this fraction of candidates fire the majorant warning.
pub const OVERSHOOT_FRACTION: f64 = 1e-5;
/// Clamped restitution coefficients above this fraction of collisions fire a warning.
pub const CLAMPED_FRACTION: f64 = 1e-4;
/// Peculiar speeds below this fraction of the bulk speed lose digits in stored velocities.
pub const PRECISION_RATIO: f64 = 1e-6;

/// One warning.
#[derive(Clone, Debug, PartialEq)]
pub struct Warning {
    /// Short code: `non-finite`, `unsteady`, `tail-not-asymptotic`, `splitting-step`, `time-step`, `majorant`,
    /// `restitution-clamped`, `precision`.
    pub code: &'static str,
    /// What fired, how large the error is expected to be, and what to do.
    pub message: String,
}

/// What a run of one ensemble has no interval for, in words (`None` for two or more): every
/// `_ci` column of observables.csv is NaN (a confidence interval needs the spread of two
/// ensembles: it is undefined, not zero), while a steady-state average still has one, from
/// the spread of its observation times (RW Section 4.2). Not a warning: RW's steady runs are
/// single systems by design.
pub fn no_intervals(stats: &RunStats) -> Option<String> {
    (stats.ensembles == 1).then(|| {
        let steady = if stats.steady.is_some() {
            " The steady-state averages have intervals from the spread of their observation \
             times (RW Section 4.2)."
        } else {
            ""
        };
        format!(
            "one ensemble: every _ci column of observables.csv is NaN, since a confidence \
             interval needs the spread of at least two ensembles (it is undefined, not zero); \
             run with --ensembles 2 or more for intervals.{steady}"
        )
    })
}

/// The energy relaxation rate `k = nu (1 - alpha^2) / 4` from the run's collision frequency
/// per particle `nu = 2 N_coll / (n M t_end)` (for the Maxwell gas exactly GRW (13)'s
/// `gamma pi C0 (1 - alpha^2)`; for other kernels the mean over the run).
fn relaxation_rate(scene: &Scene, stats: &RunStats) -> Option<f64> {
    // Every run starts at t = 0, whatever its first observation time.
    let t_end = *stats.times.last()?;
    if t_end <= 0.0 || stats.ensembles == 0 {
        return None;
    }
    let nu =
        2.0 * stats.counts.collisions as f64 / (scene.n() as f64 * stats.ensembles as f64 * t_end);
    let a = crate::run::estimate::typical_alpha(scene);
    Some(nu * (1.0 - a * a) / 4.0)
}

/// Columns whose mean or half-width is not finite, each with the first time it is not: no
/// silent NaN. (A ratio such as a2 is undefined once T_bulk is 0; a moment overflows when the
/// velocities leave the range of f64.)
fn non_finite(stats: &RunStats) -> Option<Warning> {
    let mut found = Vec::new();
    for (c, name) in stats.names.iter().enumerate() {
        // One ensemble has no half-width (by design, not a silent NaN).
        let ci_defined = stats.ensembles > 1;
        let first = (0..stats.times.len()).find(|&ti| {
            !stats.mean(ti, c).is_finite() || (ci_defined && !stats.ci(ti, c).is_finite())
        });
        if let Some(ti) = first {
            found.push(format!("{name} from t = {}", stats.times[ti]));
        }
    }
    (!found.is_empty()).then(|| Warning {
        code: "non-finite",
        message: format!(
            "non-finite values in observables.csv: {}. A ratio (a2, a3, crit, c3/c1) is undefined where T_bulk is 0 or underflowed; a moment is infinite where the velocities left the range of f64.",
            found.join(", ")
        ),
    })
}

/// The temperature columns a steady-state window is checked on.
const STEADY_CHECKED: [&str; 2] = [name::T, name::T_BULK];

/// The columns a steady-state window must hold steady: the temperatures, for a cooling
/// one-species gas a2, for a cooling rough gas theta (a rough mixture: each species' theta and
/// temperature ratio), or for a mixture its species' temperature ratios (a cooling mixture's temperature keeps falling while its
/// ratios settle: Garzó and Dufty 1999's cooling state).
fn steady_checked(scene: &Scene) -> Vec<&'static str> {
    let species = scene.physics().species.len();
    if scene.physics().rotation.is_some() {
        // A cooling rough gas's temperatures keep falling while theta settles (Luding et al.
        // 1998); a heated one's settle themselves. A rough mixture: each species' ratios
        // (T_sk / T_mix and theta_sk) when cooling, its temperatures when heated.
        let heated = !scene.physics().cools_freely();
        let (tr, rot) = (
            &crate::run::columns::SPECIES_COLUMNS[..species],
            &crate::run::columns::ROUGH_SPECIES_COLUMNS[..species],
        );
        return match (species > 0, heated) {
            (false, true) => vec![name::T_BULK, name::T_ROT],
            (false, false) => vec![name::THETA],
            (true, true) => tr
                .iter()
                .map(|c| c[0])
                .chain(rot.iter().map(|c| c[0]))
                .collect(),
            (true, false) => tr
                .iter()
                .map(|c| c[1])
                .chain(rot.iter().map(|c| c[1]))
                .collect(),
        };
    }
    if species == 0 {
        // A cooling one-species gas's temperature keeps falling (Haff's law) while its shape,
        // a2, settles into the cooling state.
        if matches!(scene.physics().drive, DriveChoice::None) {
            return vec![name::A2];
        }
        return STEADY_CHECKED.to_vec();
    }
    crate::run::columns::SPECIES_COLUMNS[..species]
        .iter()
        .map(|c| c[1])
        .collect()
}

/// The mean of the per-time means over `range` and a bound on its 99.9% half-width: the mean
/// of the per-time half-widths (the standard deviation of a mean is at most the mean of the
/// standard deviations, whatever the correlation between times).
fn window_mean(stats: &RunStats, col: usize, range: std::ops::Range<usize>) -> (f64, f64) {
    let k = range.len() as f64;
    let (mut m, mut h) = (0.0, 0.0);
    for ti in range {
        m += stats.mean(ti, col);
        h += stats.ci(ti, col);
    }
    (m / k, h / k)
}

/// A steady-state window that is not steady: the temperature averaged over the window's
/// first half and over its second half differ by more than the sum of their half-widths (each
/// bounded from above, so a steady gas fires this less often than one run in a thousand per
/// column). The averages then mix a transient into the steady state.
fn unsteady(scene: &Scene, stats: &RunStats) -> Option<Warning> {
    let st = stats.steady.as_ref()?;
    let nt = stats.times.len();
    if stats.ensembles < 2 || st.points < 4 {
        return None;
    }
    let half = st.points / 2;
    let mut found = Vec::new();
    for name in steady_checked(scene) {
        let Some(col) = stats.col(name) else { continue };
        let (ma, ha) = window_mean(stats, col, st.first..st.first + half);
        let (mb, hb) = window_mean(stats, col, nt - half..nt);
        if (mb - ma).abs() > ha + hb {
            found.push(format!(
                "{name} averages {ma:.6} (+- {ha:.1e}) over its first half and {mb:.6} (+- {hb:.1e}) over its second, a change of {:+.2}%",
                100.0 * (mb - ma) / ma.abs()
            ));
        }
    }
    (!found.is_empty()).then(|| Warning {
        code: "unsteady",
        message: format!(
            "the steady-state window t >= {} is not steady: {}, beyond both 99.9% intervals. Its averages mix a transient into the steady state; start the window later (observe.steady_from) or run longer (observe.t_end).",
            stats.times[st.first],
            found.join("; ")
        ),
    })
}

/// A tail exponent that has not reached its asymptote: the inner and the outer half of the
/// fitted shells give slopes that differ beyond both 99.9% intervals (the exponent still
/// changes with the speed), or, for the white-noise heated gas, the fitted exponent misses
/// GRW (16)'s `1 + lambda/2` beyond its interval (the interval is the fit's noise only, not the
/// distance from the asymptote).
fn tail_not_asymptotic(scene: &Scene, stats: &RunStats) -> Option<Warning> {
    use crate::analysis::tails::{TailFit, fit, halves};
    let crate::run::ShellHistogram { radius, weights: h } = stats.histogram.as_ref()?;
    let all = fit(*radius, h, stats.dimension)?;
    let (inner, outer) = halves(*radius, h, stats.dimension)?;
    let drifts = (outer.slope - inner.slope).abs() > inner.slope_ci + outer.slope_ci;
    let reference = crate::analysis::tails::reference_exponent(scene);
    let heated = scene.translation_is_smooth()
        && matches!(scene.physics().drive, DriveChoice::WhiteNoise(b) if b > 0.0)
        && matches!(scene.physics().restitution, crate::scene::RestitutionLaw::Constant(a) if a < 1.0);
    let misses = heated && reference.is_some_and(|r| (all.slope - r).abs() > all.slope_ci);
    if !(drifts || misses) {
        return None;
    }
    let span = |f: &TailFit| {
        let k = |i: usize| f.points.get(i).map_or(0, |p| p.0);
        format!(
            "{:.3} +- {:.3} over shells {}-{}",
            f.slope,
            f.slope_ci,
            k(0),
            k(f.points.len() - 1)
        )
    };
    let what = if drifts {
        "still changes with the speed".to_string()
    } else {
        format!(
            "{:.3} +- {:.3} misses GRW (16)'s asymptote {} for the heated gas",
            all.slope,
            all.slope_ci,
            reference.unwrap_or(f64::NAN)
        )
    };
    // GRW Examples 6-8 sample n = 1e7 particles in 100 ensembles.
    let samples = scene.n() as f64 * stats.ensembles as f64;
    let remedy = if samples < 1e9 {
        "Farther shells need more particles and ensembles (GRW Examples 6-8: n = 1e7, 100 ensembles; docs/tails-full.md has those runs)."
    } else {
        "This run has GRW's samples (n x ensembles >= 1e9), and at that size the exponent is still on its way (docs/tails-full.md); farther shells need weighted particles (GRW's Conclusions) rather than more of the same."
    };
    Some(Warning {
        code: "tail-not-asymptotic",
        message: format!(
            "the tail exponent {what}: {}, then {}. The fitted exponent is not the asymptotic one of GRW (16) (|v| -> infinity); its interval is the fit's noise, not the distance from the asymptote. {remedy}",
            span(&inner),
            span(&outer)
        ),
    })
}

/// Every warning of a finished run.
pub fn check(scene: &Scene, stats: &RunStats) -> Vec<Warning> {
    let mut w: Vec<Warning> = Vec::new();
    w.extend(non_finite(stats));
    w.extend(unsteady(scene, stats));
    w.extend(tail_not_asymptotic(scene, stats));
    let c = stats.counts;
    // Splitting schemes: the stationary temperature of the Maxwell gas is off by exactly
    // k dt / 2 (Euler) and (k dt)^2 / 24 (Strang) to leading order (reference.rs,
    // splitting_bulk_mean; RW Tables 2-4 and 6).
    if let (SchemeChoice::Euler(dt) | SchemeChoice::Strang(dt), Some(k)) =
        (scene.physics().scheme, relaxation_rate(scene, stats))
    {
        let euler = matches!(scene.physics().scheme, SchemeChoice::Euler(_));
        let err = if euler {
            k * dt / 2.0
        } else {
            (k * dt).powi(2) / 24.0
        };
        if err > STEP_ERROR {
            w.push(Warning {
                code: "splitting-step",
                message: format!(
                    "{} splitting with dt = {dt}: k dt = {:.3} (k = {k:.3}, the energy relaxation rate from the collision counts), so the temperature is expected off by about {:.1}% ({}; exact for the Maxwell gas, RW Tables 2-6). Use a smaller scheme.dt or the exact no-splitting scheme.",
                    if euler { "Euler" } else { "Strang" },
                    k * dt,
                    100.0 * err,
                    if euler { "k dt / 2" } else { "(k dt)^2 / 24" },
                ),
            });
        }
    }
    // The MS time-stepped scheme decouples drive and collisions over h = f lambda / v0, an
    // Euler-like splitting with k h = (1 - alpha^2) f / 4 per mean free time.
    if let SchemeChoice::TimeStepped(f) = scene.physics().scheme {
        let a = crate::run::estimate::typical_alpha(scene);
        let err = (1.0 - a * a) * f / 8.0;
        if err > STEP_ERROR {
            w.push(Warning {
                code: "time-step",
                message: format!(
                    "time-stepped scheme with step_factor = {f}: the step is {f} mean free times, an Euler-like splitting error of about {:.1}% ((1 - alpha^2) f / 8). MS use 0.01.",
                    100.0 * err
                ),
            });
        }
    }
    if c.candidates > 0 && c.overshoots as f64 > OVERSHOOT_FRACTION * c.candidates as f64 {
        w.push(Warning {
            code: "majorant",
            message: format!(
                "{} of {} candidate pairs had a collision rate above the majorant that generated them (Umax of the no-splitting scheme, omega_max of the time-stepped scheme): the kernel was truncated there (RW (19)), which underweights the fastest pairs. Start from a larger majorant (time-stepped: a smaller scheme.step_factor or a start nearer the steady temperature).",
                c.overshoots, c.candidates
            ),
        });
    }
    if c.collisions > 0 && c.clamped as f64 > CLAMPED_FRACTION * c.collisions as f64 {
        w.push(Warning {
            code: "restitution-clamped",
            message: format!(
                "{} of {} collisions had a restitution coefficient outside [0, 1] from the impact-speed law (BRS (9)-(10)), clamped: the law does not hold at these impact speeds; reduce beta0 or delta.",
                c.clamped, c.collisions
            ),
        });
    }
    // Stored velocities keep about 16 digits of v = V + c; when |c| << |V| the peculiar
    // velocities, and with them T_bulk, a2, a3 and crit, lose digits. The exact schemes (no
    // splitting, on equal or weighted particles) without drive store a cooling gas rescaled
    // about V and keep every digit.
    let rescaled = matches!(
        scene.physics().scheme,
        SchemeChoice::NoSplitting | SchemeChoice::Weighted(_)
    ) && scene.physics().drive == DriveChoice::None;
    let (Some(tb), Some(vn), false) = (stats.col(name::T_BULK), stats.col(name::V_NORM), rescaled)
    else {
        return w;
    };
    for (ti, &t) in stats.times.iter().enumerate() {
        let (temp, v) = (stats.mean(ti, tb), stats.mean(ti, vn));
        let lost =
            !temp.is_finite() || temp <= 0.0 || (v > 0.0 && temp.sqrt() < PRECISION_RATIO * v);
        if lost {
            w.push(Warning {
                code: "precision",
                message: format!(
                    "at t = {t}: T_bulk = {temp:.3e} beside a bulk speed {v:.3e}: the peculiar velocities are below {PRECISION_RATIO:e} of the stored velocities (or underflowed), so T_bulk, a2, a3 and crit have lost digits from here on. The exact schemes (no-splitting, weighted) rescale a cooling gas (exact over any number of decades); the splitting schemes do not."
                ),
            });
            break;
        }
    }
    w
}
