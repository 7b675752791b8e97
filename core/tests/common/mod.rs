//! Shared statistics for the core's tests.
#![allow(dead_code)]

/// Kolmogorov-Smirnov statistic of `xs` (sorted in place) against the CDF `cdf`.
pub fn ks_statistic(xs: &mut [f64], cdf: impl Fn(f64) -> f64) -> f64 {
    xs.sort_by(|a, b| a.partial_cmp(b).unwrap());
    let n = xs.len() as f64;
    let mut d: f64 = 0.0;
    for (i, &x) in xs.iter().enumerate() {
        let f = cdf(x);
        d = d.max((i as f64 + 1.0) / n - f).max(f - i as f64 / n);
    }
    d
}

/// Critical value of the KS statistic at level 99.9% for `n` samples (asymptotic:
/// sqrt(-ln(0.0005)/2) / sqrt(n) = 1.9495 / sqrt(n)).
pub fn ks_critical_999(n: usize) -> f64 {
    1.9495 / (n as f64).sqrt()
}

/// Standard normal CDF.
pub fn normal_cdf(x: f64) -> f64 {
    0.5 * (1.0 + libm::erf(x / std::f64::consts::SQRT_2))
}

/// Mean and the half-width of its 99.9% confidence interval (lambda = 3.2) of a sample.
pub fn mean_ci(xs: &[f64]) -> (f64, f64) {
    let n = xs.len() as f64;
    let m = xs.iter().sum::<f64>() / n;
    let var = xs.iter().map(|x| (x - m) * (x - m)).sum::<f64>() / (n - 1.0);
    (m, 3.2 * (var / n).sqrt())
}

/// Proptest strategies shared by the collision-map tests.
pub mod strategies {
    use gdsmc_core::vec3::Vec3;
    use proptest::prelude::*;

    /// A vector with components in `(-r, r)`.
    pub fn vec3(r: f64) -> impl Strategy<Value = Vec3> {
        (-r..r, -r..r, -r..r).prop_map(|(x, y, z)| Vec3::new(x, y, z))
    }

    /// A unit vector, uniform on the sphere.
    pub fn unit() -> impl Strategy<Value = Vec3> {
        (-1.0f64..1.0, 0.0..std::f64::consts::TAU).prop_map(|(z, phi)| {
            let r = (1.0 - z * z).sqrt();
            Vec3::new(r * phi.cos(), r * phi.sin(), z)
        })
    }

    /// A restitution coefficient in (0, 1], with 1 often.
    pub fn alpha() -> impl Strategy<Value = f64> {
        prop_oneof![Just(1.0), 1e-6f64..=1.0]
    }
}
