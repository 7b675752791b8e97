//! The cooling or heated steady state of a system of temperature rates, followed in time: the
//! one search behind the Maxwellian approximations of mixtures ([`super::mixture`],
//! [`super::rough_mixture`]).

/// Follows `dx/dt = rates(x)` from `x` (RK4, each step a twentieth of the fastest collisional
/// relaxation time `|(rates - heating)/x|`: the collisions' part alone stays finite at a heated
/// steady state, where the whole rate vanishes) until `ratios(x)` changes by less than 1e-13
/// in a step, and returns those ratios; `None` after 10^6 steps. Without heating (all 0) the
/// state cools: after each step `x` is divided by `scale(x)` (the mixture's temperature), so
/// the ratios of the cooling state are found at temperature 1.
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
        let fastest = x
            .iter()
            .zip(&k1)
            .zip(heating)
            .map(|((a, b), q)| ((b - q) / a).abs())
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
