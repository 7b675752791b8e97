//! The tail-exponent analysis of GRW Section 4.3: from the radial-shell histogram (GRW
//! (31)-(33)), turned into the density `f_k = weight_k / shell volume_k` (the form
//! `f_k = c exp(-a (r_k - r_k0)^b)` GRW fit is that of a density), the points `x_k = ln(r_k - r_k0)`, `y_k = ln(ln f_k0 - ln f_k)` with
//! `k0 = 1`, whose slope is the exponent `b` of `f ~ exp(-a |v|^b)` (GRW (15)-(16):
//! `b = 1 + lambda/2`). The slope is fitted by least squares over the outer half of the shells
//! whose weight is resolved (mean > 0 and 99.9% half-width below half the mean), with its 99.9%
//! half-width the Student-t quantile (points - 2 degrees of freedom, the 3.2-sigma level) times
//! the regression standard error.

use gdsmc_stats::{Accumulator, level_999, quantile_t};

/// A fitted tail exponent.
#[derive(Clone, Debug, PartialEq)]
pub struct TailFit {
    /// Fitted slope `b`.
    pub slope: f64,
    /// Half-width of its 99.9% interval (regression standard error times the Student-t quantile).
    pub slope_ci: f64,
    /// Fitted intercept `ln a`.
    pub intercept: f64,
    /// The points `(k, x_k, y_k)` used.
    pub points: Vec<(usize, f64, f64)>,
}

/// GRW (16)'s asymptotic tail exponent of the heated gas, `1 + lambda/2`, for the scene's
/// kernel; `None` for a kernel that is not a power law (GRW (16) is of `|u|^lambda`).
pub fn reference_exponent(scene: &crate::scene::Scene) -> Option<f64> {
    let lambda = scene.physics().kernel.exponent()?;
    Some(1.0 + lambda / 2.0)
}

/// The points `(k, x_k, y_k)` of GRW Section 4.3 (k0 = 1, shells k = 2..K, 1-based as GRW),
/// the shells' volumes in `d` dimensions (2: disks).
pub fn tail_points(radius: f64, hist: &Accumulator, d: usize) -> Vec<(usize, f64, f64)> {
    let kk = hist.len().saturating_sub(1);
    if kk < 3 {
        return Vec::new();
    }
    let h = radius / kk as f64;
    let vol = |k: usize| {
        if d == 2 {
            return gdsmc_theory::exact::tail::shell_volume_in(2, (k - 1) as f64 * h, k as f64 * h);
        }
        4.0 / 3.0
            * std::f64::consts::PI
            * h.powi(3)
            * ((k as f64).powi(3) - ((k - 1) as f64).powi(3))
    };
    let f1 = hist.mean(0) / vol(1);
    if f1 <= 0.0 {
        return Vec::new();
    }
    (2..=kk)
        .filter_map(|k| {
            let (f, ci) = (hist.mean(k - 1) / vol(k), hist.ci(k - 1) / vol(k));
            let resolved = f > 0.0 && f < f1 && (ci.is_nan() || ci < 0.5 * f);
            resolved.then(|| {
                (
                    k,
                    libm::log((k - 1) as f64 * h),
                    libm::log(libm::log(f1) - libm::log(f)),
                )
            })
        })
        .collect()
}

/// Least-squares line through the outer half (in `x`) of the tail points, where the
/// asymptotic exponent shows (the inner points still carry the Maxwellian core's exponent 2);
/// `None` with fewer than three points.
pub fn fit(radius: f64, hist: &Accumulator, d: usize) -> Option<TailFit> {
    let all = tail_points(radius, hist, d);
    line(all[all.len() / 2..].to_vec())
}

/// The fit's two halves, inner and outer shells, fitted on their own: if the exponent has
/// reached its asymptote (GRW (16)) they agree; a slope that still changes with the speed
/// beyond both intervals means the fitted exponent is not yet the asymptotic one. `None` with
/// fewer than three points in a half.
pub fn halves(radius: f64, hist: &Accumulator, d: usize) -> Option<(TailFit, TailFit)> {
    let all = tail_points(radius, hist, d);
    let used = &all[all.len() / 2..];
    let mid = used.len() / 2;
    Some((line(used[..mid].to_vec())?, line(used[mid..].to_vec())?))
}

/// The least-squares line through `points` with the 99.9% half-width of its slope.
fn line(points: Vec<(usize, f64, f64)>) -> Option<TailFit> {
    let m = points.len();
    if m < 3 {
        return None;
    }
    let mf = m as f64;
    let (sx, sy) = points
        .iter()
        .fold((0.0, 0.0), |(a, b), p| (a + p.1, b + p.2));
    let (mx, my) = (sx / mf, sy / mf);
    let sxx: f64 = points.iter().map(|p| (p.1 - mx).powi(2)).sum();
    let sxy: f64 = points.iter().map(|p| (p.1 - mx) * (p.2 - my)).sum();
    let slope = sxy / sxx;
    let intercept = my - slope * mx;
    let rss: f64 = points
        .iter()
        .map(|p| (p.2 - intercept - slope * p.1).powi(2))
        .sum();
    let se = (rss / (mf - 2.0) / sxx).sqrt();
    Some(TailFit {
        slope,
        slope_ci: quantile_t(m as u64 - 2, level_999()) * se,
        intercept,
        points,
    })
}
