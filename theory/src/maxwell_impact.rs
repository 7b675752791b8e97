//! The moment equations and tail of the impact form of the inelastic Maxwell model (Ernst and
//! Brito 2002; the core's `MaxwellImpact`): a pair collides at a rate independent of `u` and
//! of the impact direction `n`, uniform on the unit sphere, `u' = u - (1 + alpha)(u . n) n`,
//! and the centre of mass `G = (v + w)/2` is kept.
//!
//! Derivation (unit mass, zero bulk velocity, `mu_p = <|v|^p>`, `x = u_hat . n`,
//! `c = 1 - alpha^2`, `q = 1 + alpha`): `|u'|^2 = |u|^2 (1 - c x^2)`, `<x^2> = 1/d`,
//! `<x^4> = 3/(d (d + 2))`, and `<n_i n_j n_k n_l>` is the isotropic tensor over `d (d + 2)`.
//! With `|v|^4 + |w|^4 = 2 (|G|^2 + |u|^2/4)^2 + 2 (G . u)^2`, the change per collision
//! averaged over `n` is
//!
//! ```text
//! -(c/d) |G|^2 |u|^2 + (1/8)(3 c^2/(d (d + 2)) - 2 c/d) |u|^4 - (4 q/d) (G . u)^2
//!     + 2 q^2 (|u|^2 |G|^2 + 2 (G . u)^2)/(d (d + 2)),
//! ```
//!
//! and over independent isotropic `v, w`: `<|G|^2 |u|^2> = (mu_4 + mu_2^2 (1 - 2/d))/2`,
//! `<(G . u)^2> = (mu_4 - mu_2^2)/2`, `<|u|^4> = 2 mu_4 + 2 mu_2^2 (1 + 2/d)`. In the units of
//! `theory/src/maxwell_cumulant.rs` (`K = 2 pi gamma C_0`):
//!
//! ```text
//! lambda_2 = (1 - alpha^2)/d,
//! lambda_4 = (c + 2 q)/d - (3 c^2/4 + 3 q^2)/(d (d + 2)),
//! b_4      = (2 q - c)/d + (3 c^2/4 - q^2)/d^2,
//! ```
//!
//! which in `d = 2` are the scattering form's (the two models coincide there), give a
//! Maxwellian its `mu_4/mu_2^2 = (d + 2)/d` when elastic, and the cooling state's
//! `a2 = 6 (1 - alpha)^2 / (4 d - 7 + 3 alpha (2 - alpha))` (Santos 2003, Physica A 321, 442).
//!
//! The tail (Ernst and Brito 2002): a fast particle `v` meeting a slow one leaves with
//! `|v| rho_1`, `rho_1^2 = 1 - x^2 (1 + alpha)(3 - alpha)/4`, and gives it `|v| rho_2`,
//! `rho_2^2 = x^2 (1 + alpha)^2 / 4`; `lambda_p = 2 (1 - E_n[rho_1^p + rho_2^p])`, exact at
//! `p = 2` and `4`, and the exponent `s` of `F(c) ~ c^-(d + s)` is the root of
//! `lambda_p = p lambda_2 / 2` above 2.

/// The impact form's `(lambda_2, lambda_4, b_4)` (module docs).
#[must_use]
pub fn coefficients(d: usize, alpha: f64) -> (f64, f64, f64) {
    let (d, c, q) = (d as f64, 1.0 - alpha * alpha, 1.0 + alpha);
    let l2 = c / d;
    let l4 = (c + 2.0 * q) / d - (0.75 * c * c + 3.0 * q * q) / (d * (d + 2.0));
    let b4 = (2.0 * q - c) / d + (0.75 * c * c - q * q) / (d * d);
    (l2, l4, b4)
}

/// The impact form's `lambda_p = 2 (1 - E_n[rho_1^p + rho_2^p])` (module docs), `x = u_hat . n`
/// averaged over a uniform `n` (`crate::maxwell_cumulant::over_directions`).
#[must_use]
pub fn asymptotic_rate(d: usize, alpha: f64, p: f64) -> f64 {
    let (keep, give) = (
        (1.0 + alpha) * (3.0 - alpha) / 4.0,
        (1.0 + alpha).powi(2) / 4.0,
    );
    let mean = crate::maxwell_cumulant::over_directions(d, |x| {
        let r1 = (1.0 - x * x * keep).max(0.0);
        libm::pow(r1, p / 2.0) + libm::pow(x * x * give, p / 2.0)
    });
    2.0 * (1.0 - mean)
}
