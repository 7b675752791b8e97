//! The cooling or heated steady state of a system of temperature rates, followed in time: the
//! one search behind the Maxwellian approximations of mixtures ([`super::mixture`],
//! [`super::rough_mixture`]).

/// Follows `dx/dt = rates(x)` from `x` (RK4, each step a twentieth of the fastest collisional
/// time: of `|(rates - heating)/x|`, the collisions' part alone, which stays finite at a heated
/// steady state where the whole rate vanishes, and of each component's own relaxation rate
/// `|d rate_i / d x_i|`, which stays finite where a system that neither cools nor is heated, an
/// elastic perfectly rough one, comes to rest at equipartition and every rate vanishes) until
/// `ratios(x)` changes by less than 1e-13 in a step, and returns those ratios; `None` after
/// 10^6 steps or when a value is not finite (a reference is a number or is absent). Without
/// heating (all 0) the state cools: after each step `x` is divided by `scale(x)` (the
/// mixture's temperature), so the ratios of the cooling state are found at temperature 1.
pub fn relax(
    mut x: Vec<f64>,
    rates: impl Fn(&[f64]) -> Vec<f64>,
    heating: &[f64],
    scale: impl Fn(&[f64]) -> f64,
    ratios: impl Fn(&[f64]) -> Vec<f64>,
) -> Option<Vec<f64>> {
    let heated = heating.iter().any(|&h| h > 0.0);
    let add = |x: &[f64], k: &[f64], f: f64| -> Vec<f64> {
        x.iter().zip(k).map(|(a, b)| a + f * b).collect()
    };
    let mut last = ratios(&x);
    for _ in 0..1_000_000 {
        let k1 = rates(&x);
        let own = (0..x.len()).map(|i| {
            // The diagonal of the Jacobian, by a forward difference of a millionth of x_i.
            let dx = 1e-6 * x[i];
            let mut y = x.clone();
            y[i] += dx;
            ((rates(&y)[i] - k1[i]) / dx).abs()
        });
        let fastest = x
            .iter()
            .zip(&k1)
            .zip(heating)
            .map(|((a, b), q)| ((b - q) / a).abs())
            .chain(own)
            .fold(1e-300, f64::max);
        let h = 0.05 / fastest;
        let k2 = rates(&add(&x, &k1, h / 2.0));
        let k3 = rates(&add(&x, &k2, h / 2.0));
        let k4 = rates(&add(&x, &k3, h));
        for i in 0..x.len() {
            x[i] += h / 6.0 * (k1[i] + 2.0 * k2[i] + 2.0 * k3[i] + k4[i]);
        }
        if !heated {
            let t = scale(&x);
            x.iter_mut().for_each(|v| *v /= t);
        }
        let now = ratios(&x);
        if now.iter().any(|v| !v.is_finite()) {
            return None;
        }
        let change = now
            .iter()
            .zip(&last)
            .map(|(a, b)| (a - b).abs())
            .fold(0.0, f64::max);
        last = now;
        if change < 1e-13 {
            return Some(last);
        }
    }
    None
}

#[cfg(test)]
mod tests {
    use super::relax;

    /// A system that neither cools nor is heated relaxes to rest, where every rate vanishes:
    /// two parts exchanging energy at rate 1 from 2 and 1/2 come to equal temperatures. The
    /// steps were once set by the vanishing rates alone and grew until the state was NaN,
    /// which the convergence test (a maximum that skips NaN) took for converged.
    #[test]
    fn a_conservative_system_comes_to_rest() {
        let r = relax(
            vec![2.0, 0.5],
            |x| vec![x[1] - x[0], x[0] - x[1]],
            &[0.0, 0.0],
            |_| 1.0,
            |x| vec![x[0] / x[1]],
        )
        .expect("converges");
        assert!((r[0] - 1.0).abs() < 1e-9, "{r:?}");
    }
}
