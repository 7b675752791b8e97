//! Radial-shell histograms of the speed, GRW (31)-(33): shells `r_k = k R / K`, `k = 1..K`;
//! `f_1` counts `|v| < r_1`, `f_k` counts `r_{k-1} <= |v| < r_k`, `f_{K+1}` counts `|v| >= R`,
//! each with the particle weight `g = 1/n` (weighted particles: `g_i / sum g`).

use crate::engine::Frame;
use crate::math::{Real, sqrt};
use crate::particles::{Particle, Particles};

/// Each particle in use with its share of the histogram: `1/n`, or for weighted particles its
/// weight over the total.
fn shares<'b>(p: &'b Particles<'_>) -> impl Iterator<Item = (&'b Particle, Real)> {
    let (weighted, g) = if p.is_weighted() {
        (true, 1.0 / p.mass())
    } else {
        (false, 1.0 / p.len() as Real)
    };
    (p.as_slice().iter().enumerate())
        .map(move |(i, q)| (q, if weighted { p.weight(i) * g } else { g }))
}

/// Adds the shell weights of `p` to `out` (`K + 1` entries, the last one for `|v| >= R`),
/// for shells of width `radius / (out.len() - 1)`. Returns `false` (adding nothing) when `out`
/// has fewer than two entries or `radius` is not finite and positive.
pub fn radial_shells(p: &Particles<'_>, radius: Real, out: &mut [Real]) -> bool {
    radial_shells_mapped(p, radius, Frame::IDENTITY, out)
}

/// As [`radial_shells`], for the velocities `frame.physical(v)` (a system stored rescaled, a
/// cooling gas: [`crate::engine::NoSplitting::velocity_map`]; or any affine map, e.g. to
/// reduced velocities).
pub fn radial_shells_mapped(
    p: &Particles<'_>,
    radius: Real,
    frame: Frame,
    out: &mut [Real],
) -> bool {
    let k = out.len().saturating_sub(1);
    if k == 0 || !(radius.is_finite() && radius > 0.0) {
        return false;
    }
    let per = k as Real / radius;
    let identity = frame.is_identity();
    for (q, g) in shares(p) {
        let v = if identity {
            q.velocity()
        } else {
            frame.physical(q.velocity())
        };
        let r = sqrt(v.norm2());
        let i = if r >= radius {
            k
        } else {
            ((r * per) as usize).min(k - 1)
        };
        out[i] += g;
    }
    true
}

/// Adds the weights of the marginal histogram of velocity component `axis` (0, 1 or 2) of the
/// velocities `frame.physical(v)` to `out`: `K = out.len() - 2` bins of width `2R / K`
/// over `[-R, R)`, then `out[K]` for components below `-R` and `out[K + 1]` for those at or
/// above `R`; particle weight `1/n`. It estimates BRS's integrated distribution
/// `f_1(t, v_1) = int f(t, v) dv_2 dv_3` (BRS Figure 4). Returns `false` (adding nothing) when
/// `out` has fewer than three entries, `axis > 2` or `radius` is not finite and positive.
pub fn component_bins(
    p: &Particles<'_>,
    axis: usize,
    radius: Real,
    frame: Frame,
    out: &mut [Real],
) -> bool {
    let k = out.len().saturating_sub(2);
    if k == 0 || axis > 2 || !(radius.is_finite() && radius > 0.0) {
        return false;
    }
    let per = k as Real / (2.0 * radius);
    for (q, g) in shares(p) {
        let v = frame.physical(q.velocity()).to_array()[axis];
        let i = if v < -radius {
            k
        } else if v >= radius {
            k + 1
        } else {
            (((v + radius) * per) as usize).min(k - 1)
        };
        out[i] += g;
    }
    true
}
