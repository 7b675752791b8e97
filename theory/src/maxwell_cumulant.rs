//! The fourth cumulant `a2(t)` of the smooth inelastic Maxwell gas without white noise, exact
//! in the Boltzmann limit (n -> infinity), in `d = 2` and `3`, and its cooling-state value.
//!
//! The model is GRW (1) with the Maxwell kernel `B = gamma C_0` and the collision rule GRW (3),
//! the scattering direction `e` uniform on the unit sphere (circle for disks): the model of
//! Bobylev, Carrillo and Gamba 2000, whose moments close order by order. Derivation (unit
//! mass, zero bulk velocity, `mu_p = <|v|^p>`, `P = v + w`, `u = v - w`, `q = v' - w' =
//! a u + b |u| e` with `a = (1 - alpha)/2`, `b = (1 + alpha)/2`): `|v'|^4 + |w'|^4 =
//! (|P|^2 + |q|^2)^2/8 + (P . q)^2/2`, and over `e`: `E|q|^2 = s |u|^2` (`s = a^2 + b^2`),
//! `E|q|^4 = (s^2 + 4 a^2 b^2 / d) |u|^4`, `E(P . q)^2 = a^2 (P . u)^2 + b^2 |u|^2 |P|^2 / d`.
//! Averaged over independent isotropic `v, w`: `<|P|^2 |u|^2> = 2 mu_4 + 2 mu_2^2 (1 - 2/d)`,
//! `<|u|^4> = 2 mu_4 + 2 mu_2^2 (1 + 2/d)`, `<(P . u)^2> = 2 mu_4 - 2 mu_2^2`. With
//! `K = 2 pi gamma C_0` (the rate that makes `d mu_2/dt = -K lambda_2 mu_2`,
//! `lambda_2 = (1 - alpha^2)/2`, GRW (13)):
//!
//! ```text
//! d mu_4/dt = K (-lambda_4 mu_4 + b_4 mu_2^2),
//! lambda_4 = (1 + alpha)(19 d - 5 - (11 d + 3) alpha + (d + 1) alpha^2 (1 - alpha)) / (16 d),
//! b_4 = (1 + alpha)^2 (d + 2)(5 d - 3 - 2 (d + 1) alpha + (d + 1) alpha^2) / (16 d^2).
//! ```
//!
//! So `r = mu_4 / mu_2^2` relaxes exponentially, `dr/dt = K (b_4 - (lambda_4 - 2 lambda_2) r)`,
//! to `r_inf = b_4 / (lambda_4 - 2 lambda_2)`, and `a2 = d r / (d + 2) - 1`. In the cooling
//! state
//!
//! ```text
//! a2 = 2 (d + 1)(1 - alpha)^2 / (3 d - 5 + (d + 1) alpha (2 - alpha)),
//! ```
//!
//! `2 (1 - alpha)^2 / (1 + 2 alpha - alpha^2)` for spheres and
//! `6 (1 - alpha)^2 / (1 + 6 alpha - 3 alpha^2)` for disks. In `d = 2` the scattering form with
//! `e` uniform is the impact form with the impact direction uniform (the reflection doubles
//! the angle), which is Santos's inelastic Maxwell model (Santos 2003, Physica A 321, 442),
//! and the disks' value is his `6 (1 - alpha)^2 / (4 d - 7 + 3 alpha (2 - alpha))` at `d = 2`;
//! in `d = 3` the two models differ (his collision rate does not weight the impact
//! direction). A Gaussian thermostat (MS (12)) scales every velocity alike, which commutes with
//! collisions whose rate does not depend on `|u|`: it leaves `a2(t)` as it is.
//!
//! The cooling state has a power-law tail `F(c) ~ c^-(d + s)` (Ernst and Brito 2002 for
//! inelastic Maxwell models): a fast particle meeting a slow one
//! leaves with `|v| rho_1` and gives it `|v| rho_2`, `rho_1^2 = A^2 + B^2 + 2 A B cos`,
//! `rho_2^2 = 2 B^2 (1 - cos)`, `A = (3 - alpha)/4`, `B = (1 + alpha)/4`, `cos` the cosine
//! between `v` and `e`; the moment `mu_p` decays at `K lambda_p`, `lambda_p = 2 (1 -
//! E_e[rho_1^p + rho_2^p])` to leading order (exact for `p = 2, 4`: the coefficients above),
//! and the scaled moment of order `p` is finite while `lambda_p > p lambda_2 / 2`. The
//! tail exponent `s` is where they meet (`crate::maxwell_form::Form::tail_exponent`).
//! So `a2` exists for every alpha (`s > 4`), but its
//! estimate from a sample has a finite variance only where `s > 8`, and at finite `n` the
//! tail is cut near `c ~ n^(1/s)`, a deviation of `a2` of order `n^-((s - 4)/s)`, not `1/n`.

use gdsmc_core::drive::Heating;
use gdsmc_core::sample::MaxwellianMixture;

/// The coefficients `(lambda_2, lambda_4, b_4)` of the module's moment equations.
#[must_use]
pub fn coefficients(d: usize, alpha: f64) -> (f64, f64, f64) {
    let (d, a) = (d as f64, alpha);
    let l2 = (1.0 - a * a) / 2.0;
    let l4 = (1.0 + a) * (19.0 * d - 5.0 - (11.0 * d + 3.0) * a + (d + 1.0) * a * a * (1.0 - a))
        / (16.0 * d);
    let b4 =
        (1.0 + a).powi(2) * (d + 2.0) * (5.0 * d - 3.0 - 2.0 * (d + 1.0) * a + (d + 1.0) * a * a)
            / (16.0 * d * d);
    (l2, l4, b4)
}

/// The cooling-state `a2` of the module: `2 (d + 1)(1 - alpha)^2 / (3 d - 5 + (d + 1) alpha
/// (2 - alpha))`.
#[must_use]
pub fn cooling_state_a2(d: usize, alpha: f64) -> f64 {
    let df = d as f64;
    2.0 * (df + 1.0) * (1.0 - alpha).powi(2) / (3.0 * df - 5.0 + (df + 1.0) * alpha * (2.0 - alpha))
}

/// `lambda_p = 2 (1 - E_e[rho_1^p + rho_2^p])` of the module docs.
#[must_use]
pub fn asymptotic_rate(d: usize, alpha: f64, p: f64) -> f64 {
    let (a, b) = ((3.0 - alpha) / 4.0, (1.0 + alpha) / 4.0);
    let mean = over_directions(d, |cos| {
        let r1 = a * a + b * b + 2.0 * a * b * cos;
        let r2 = (2.0 * b * b * (1.0 - cos)).max(0.0);
        libm::pow(r1, p / 2.0) + libm::pow(r2, p / 2.0)
    });
    2.0 * (1.0 - mean)
}

/// The mean of `f(cos)` over a direction uniform on the unit sphere (`d = 3`: the cosine to a
/// fixed axis uniform on `[-1, 1]`) or circle (`d = 2`: the angle uniform), by the midpoint
/// rule on 20,000 cells.
pub(crate) fn over_directions(d: usize, f: impl Fn(f64) -> f64) -> f64 {
    const CELLS: usize = 20_000;
    let mut sum = 0.0;
    for i in 0..CELLS {
        let x = (i as f64 + 0.5) / CELLS as f64;
        let cos = if d == 2 {
            libm::cos(std::f64::consts::PI * x)
        } else {
            2.0 * x - 1.0
        };
        sum += f(cos);
    }
    sum / CELLS as f64
}

/// `a2(t)` of the module from a start with `mu_4 / mu_2^2 = r_0`, under a drive that heats
/// linearly ([`Heating`] `(a, b)`: `T' = a + (b - k) T`): the white noise's kicks (`a = 2 beta`)
/// act on the peculiar velocity as the generator `(a/2) Laplacian`, a thermostat's scaling
/// (`b`: the Gaussian's `2 zeta`, the Langevin's `-2 gamma` with `a = 2 gamma T_b`) as `(b/2) c
/// . grad`, so in units of the temperature (`mu_2 = d T`, `mu_4 = m^2 <|c|^4>`)
///
/// ```text
/// mu_2' = d a - k mu_2,                                 k = K lambda_2 - b,
/// mu_4' = -A mu_4 + K b_4 mu_2^2 + 2 (d + 2) a mu_2,    A = K lambda_4 - 2 b,
/// ```
///
/// (`Laplacian |c|^4 = 4 (d + 2) |c|^2`, `c . grad |c|^4 = 4 |c|^4`). With `mu_2 = m + D
/// e^(-k t)` (`m = d a / k`) the forcing is a sum of `e^(-r t)`, `r = 0, k, 2 k`, each with the
/// particular solution `F e^(-r t) / (A - r)`: `A - 2 k = K (lambda_4 - 2 lambda_2) > 0`
/// always, `A - k = K (lambda_4 - lambda_2) - b > 0` for every drive that heats with `a > 0`
/// (`b <= 0`). Without kicks (`a = 0`) this is the cooling state's solution, which a
/// Gaussian thermostat leaves as it is. The white-noise-heated gas's steady value is
/// `a2 = d b_4 / ((d + 2) lambda_4) + 2 lambda_2 / lambda_4 - 1` (0.0870 for GRW Example 3:
/// alpha = 1/2, d = 3).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct MaxwellCumulant {
    d: f64,
    /// `mu_2(t) = m + D e^(-k t)`: `(m, D, k)`.
    mu2: (f64, f64, f64),
    /// `mu_4(t) = sum c e^(-r t)`: `(c, r)`.
    mu4: [(f64, f64); 4],
}

impl MaxwellCumulant {
    /// For the kernel `B = gamma C_0`, restitution `alpha`, dimension `d` and the start's
    /// `mu_4 / mu_2^2` (about the bulk velocity), with no kicks (cooling, or the Gaussian
    /// thermostat).
    #[must_use]
    pub fn new(d: usize, alpha: f64, gamma: f64, c0: f64, r0: f64) -> Self {
        let none = Heating {
            a: 0.0,
            b: 0.0,
            p: 0.0,
        };
        let c = coefficients(d, alpha);
        Self::heated(d, c, (gamma, c0), (1.0, r0), none).expect("no kicks: no resonance")
    }

    /// As [`Self::new`] for a model of moment coefficients `(lambda_2, lambda_4, b_4)` (this
    /// module's [`coefficients`], or the impact form's, `crate::maxwell_form::Form`), from the
    /// temperature `t0` about the bulk velocity and `r0`, under the drive's heating `h` (type
    /// docs); `None` where the solution has no steady state to relax to (`a > 0` with
    /// `k <= 0`) or a forcing rate meets `A`.
    #[must_use]
    pub fn heated(
        d: usize,
        (l2, l4, b4): (f64, f64, f64),
        (gamma, c0): (f64, f64),
        (t0, r0): (f64, f64),
        h: Heating,
    ) -> Option<Self> {
        let df = d as f64;
        let kk = 2.0 * std::f64::consts::PI * gamma * c0;
        let (k, a4) = (kk * l2 - h.b, kk * l4 - 2.0 * h.b);
        let mu2_0 = df * t0;
        let (m, delta) = match h.a {
            0.0 => (0.0, mu2_0),
            a if k > 0.0 => (df * a / k, mu2_0 - df * a / k),
            _ => return None,
        };
        let s = 2.0 * (df + 2.0) * h.a;
        let forcing = [
            (kk * b4 * m * m + s * m, 0.0),
            (2.0 * kk * b4 * m * delta + s * delta, k),
            (kk * b4 * delta * delta, 2.0 * k),
        ];
        let mut mu4 = [(0.0, 0.0); 4];
        let mut rest = r0 * mu2_0 * mu2_0;
        for (slot, (f, r)) in mu4.iter_mut().zip(forcing) {
            if f != 0.0 {
                if a4 - r == 0.0 || !(a4 - r).is_finite() {
                    return None;
                }
                *slot = (f / (a4 - r), r);
                rest -= f / (a4 - r);
            }
        }
        mu4[3] = (rest, a4);
        Some(MaxwellCumulant {
            d: df,
            mu2: (m, delta, k),
            mu4,
        })
    }

    /// `a2(t) = d mu_4 / ((d + 2) mu_2^2) - 1` (type docs); without kicks as the ratio
    /// `sum c e^(-(r - 2 k) t) / D^2`, which stays finite while both moments underflow.
    #[must_use]
    pub fn at(&self, t: f64) -> f64 {
        let (m, delta, k) = self.mu2;
        let r = if m == 0.0 {
            let sum: f64 = (self.mu4.iter())
                .filter(|(c, _)| *c != 0.0)
                .map(|(c, r)| c * libm::exp(-(r - 2.0 * k) * t))
                .sum();
            sum / (delta * delta)
        } else {
            let mu2 = m + delta * libm::exp(-k * t);
            let sum: f64 = (self.mu4.iter()).map(|(c, r)| c * libm::exp(-r * t)).sum();
            sum / (mu2 * mu2)
        };
        self.d * r / (self.d + 2.0) - 1.0
    }
}

/// `mu_4 / mu_2^2` about the mean velocity of a mixture of Maxwellians in `d` dimensions:
/// each component (weight `w`, drift `m` from the mean, variance `s = T/m_k` per component)
/// gives `E|c|^2 = |m|^2 + d s` and `E|c|^4 = |m|^4 + 2 (d + 2) s |m|^2 + d (d + 2) s^2`.
#[must_use]
pub fn moment_ratio<const CAP: usize>(f0: &MaxwellianMixture<CAP>, d: usize) -> f64 {
    let (mean, df) = (f0.mean(), d as f64);
    let total: f64 = f0.components().iter().map(|(w, _)| w).sum();
    let (mut m2, mut m4) = (0.0, 0.0);
    for (w, c) in f0.components() {
        let (m, s) = ((c.drift() - mean).norm2(), c.temperature() / c.mass());
        let p = w / total;
        m2 += p * (m + df * s);
        m4 += p * (m * m + 2.0 * (df + 2.0) * s * m + df * (df + 2.0) * s * s);
    }
    m4 / (m2 * m2)
}

#[cfg(test)]
mod tests {
    use super::*;
    use gdsmc_core::collision::inelastic::inelastic;
    use gdsmc_core::geometry::{Disks, Geometry, Spheres};
    use gdsmc_core::kernel::Maxwell;
    use gdsmc_core::rng::seeded;

    /// The moment equation against a Monte Carlo of the core's own collision map and
    /// scattering direction: `v, w` independent isotropic scale mixtures of Gaussians (scale
    /// 0.5 or 1.5 in equal shares, so `a2 = 0.64`, far from a Maxwellian), 400,000 pairs;
    /// `E[|v'|^4 + |w'|^4 - |v|^4 - |w|^4] = -lambda_4 mu_4 + b_4 mu_2^2` and the energy's
    /// `-lambda_2 mu_2` within their 99.9% intervals, the 8 checks of a dimension held
    /// together (Bonferroni).
    fn moments_match_the_map<G: Geometry>(seed: u64) {
        const CHECKS: usize = 8;
        let mut rng = seeded(seed);
        let d = G::CHOICE.d();
        let df = d as f64;
        let scales: [f64; 2] = [0.5, 1.5];
        let mean = |p: i32| scales.iter().map(|s| s.powi(p)).sum::<f64>() / 2.0;
        let (mu2, mu4) = (df * mean(2), df * (df + 2.0) * mean(4));
        for alpha in [0.1, 0.5, 0.8, 1.0] {
            let (l2, l4, b4) = coefficients(d, alpha);
            let (mut s2, mut s4) = (Vec::new(), Vec::new());
            for i in 0..400_000 {
                // The scales in a balanced cycle (stratified: the interval is conservative).
                let v = scales[i % 2] * G::normal(&mut rng);
                let w = scales[(i / 2) % 2] * G::normal(&mut rng);
                let e = G::scattering::<Maxwell, _>(v - w, &mut rng);
                let (a, b) = inelastic(v, w, e, alpha);
                s2.push(a.norm2() + b.norm2() - v.norm2() - w.norm2());
                s4.push(
                    a.norm2().powi(2) + b.norm2().powi(2) - v.norm2().powi(2) - w.norm2().powi(2),
                );
            }
            for (s, want) in [(s2, -l2 * mu2), (s4, -l4 * mu4 + b4 * mu2 * mu2)] {
                let sample = gdsmc_stats::Sample::of(&s);
                let h = sample.joint_ci(CHECKS);
                assert!(
                    (sample.mean - want).abs() <= h,
                    "d {d} alpha {alpha}: {} vs {want} +- {h}",
                    sample.mean
                );
            }
        }
    }

    #[test]
    fn the_moment_equation_is_the_maps_for_spheres() {
        moments_match_the_map::<Spheres>(21);
    }

    #[test]
    fn the_moment_equation_is_the_maps_for_disks() {
        moments_match_the_map::<Disks>(22);
    }

    /// The tail's rate is the moment equation's at `p = 2` and `4` (two routes to
    /// `lambda_4`); the exponents the docs quote (docs/disks.md: `s > 8`, a finite variance
    /// of the a2 estimate, from alpha = 0.5 in d = 3 and from 0.6 in d = 2; `s` near 4.5 and
    /// 5.2 at alpha = 0.1); elastic: no tail.
    #[test]
    fn the_tail_exponent() {
        for d in [2, 3] {
            for alpha in [0.1, 0.5, 0.9] {
                let (l2, l4, _) = coefficients(d, alpha);
                assert!(
                    (asymptotic_rate(d, alpha, 2.0) - l2).abs() < 1e-7,
                    "{d} {alpha}"
                );
                assert!(
                    (asymptotic_rate(d, alpha, 4.0) - l4).abs() < 1e-7,
                    "{d} {alpha}"
                );
            }
        }
        let s = |d, a| crate::maxwell_form::Form::Scattering.tail_exponent(d, a);
        assert!(s(3, 0.4) < 8.0 && s(3, 0.5) > 8.0);
        assert!(s(2, 0.5) < 8.0 && s(2, 0.6) > 8.0);
        assert!((s(2, 0.1) - 4.544).abs() < 1e-3 && (s(3, 0.1) - 5.154).abs() < 1e-3);
        assert!(s(3, 1.0).is_infinite());
    }

    /// The closed form is the relaxed solution; a Maxwellian stays one when elastic; the
    /// disks' value is Santos's d-dimensional formula at d = 2.
    #[test]
    fn the_cooling_state_is_the_limit_of_the_solution() {
        for d in [2, 3] {
            for alpha in [0.0, 0.1, 0.5, 0.9, 1.0] {
                let m = MaxwellCumulant::new(d, alpha, 1.0, 1.0 / std::f64::consts::PI, 1.0);
                let want = cooling_state_a2(d, alpha);
                assert!(
                    (m.at(1e6) - want).abs() <= 1e-12 * (1.0 + want),
                    "{d} {alpha}: {} vs {want}, {m:?}",
                    m.at(1e6)
                );
                let maxwellian = (d as f64 + 2.0) / d as f64;
                let m = MaxwellCumulant::new(d, 1.0, 1.0, 1.0, maxwellian);
                assert!(m.at(3.0).abs() < 1e-14);
            }
        }
        for alpha in [0.1_f64, 0.5, 0.9] {
            let santos = 6.0 * (1.0 - alpha).powi(2) / (1.0 + 3.0 * alpha * (2.0 - alpha));
            assert!((cooling_state_a2(2, alpha) - santos).abs() < 1e-14);
        }
    }

    /// The heated solution solves its moment equations (type docs of [`MaxwellCumulant`]):
    /// `mu_2` and `mu_4` rebuilt from `a2(t)` and the exact temperature satisfy `mu_4' = -A
    /// mu_4 + K b_4 mu_2^2 + 2 (d + 2) a mu_2` to the accuracy of a central difference, for
    /// white noise (GRW Example 3, and a start far from a Maxwellian) and the Langevin
    /// thermostat in d = 2 and 3; a solution without the kicks' term `2 (d + 2) a mu_2` would
    /// miss it by that term. The white-noise steady value is the closed form; the Gaussian
    /// thermostat's is the cooling one; kicks with a scaling that outheats the collisions (no
    /// steady state) are refused.
    #[test]
    fn the_heated_solution_solves_its_moment_equations() {
        use crate::maxwell_temperature::MaxwellTemperature;
        let (gamma, c0, alpha) = (4.0, 1.0 / (4.0 * std::f64::consts::PI), 0.5);
        let kk = 2.0 * std::f64::consts::PI * gamma * c0;
        for d in [2usize, 3] {
            let df = d as f64;
            let (l2, l4, b4) = coefficients(d, alpha);
            for (h, t0, r0) in [
                (
                    Heating {
                        a: 2.0,
                        b: 0.0,
                        p: 0.0,
                    },
                    1.0,
                    (df + 2.0) / df,
                ),
                (
                    Heating {
                        a: 2.0,
                        b: 0.0,
                        p: 0.0,
                    },
                    5.0,
                    3.0,
                ),
                (
                    Heating {
                        a: 0.6,
                        b: -0.4,
                        p: -0.4,
                    },
                    0.5,
                    2.0,
                ),
            ] {
                let m =
                    MaxwellCumulant::heated(d, coefficients(d, alpha), (gamma, c0), (t0, r0), h)
                        .unwrap();
                let temp = MaxwellTemperature::new(t0, alpha, 0.0, gamma, c0).with_heating(h);
                let mu2 = |t: f64| df * temp.at(t);
                let mu4 = |t: f64| (m.at(t) + 1.0) * (df + 2.0) / df * mu2(t) * mu2(t);
                for t in [0.3, 1.0, 2.5, 6.0] {
                    let step = 1e-4;
                    let lhs = (mu4(t + step) - mu4(t - step)) / (2.0 * step);
                    let kicks = 2.0 * (df + 2.0) * h.a * mu2(t);
                    let rhs = -(kk * l4 - 2.0 * h.b) * mu4(t) + kk * b4 * mu2(t).powi(2) + kicks;
                    let tol = 1e-6 * mu4(t);
                    assert!((lhs - rhs).abs() < tol, "d {d} {h:?} t {t}: {lhs} vs {rhs}");
                    assert!(kicks.abs() > 100.0 * tol);
                }
                if h.b == 0.0 {
                    let steady = df * b4 / ((df + 2.0) * l4) + 2.0 * l2 / l4 - 1.0;
                    assert!((m.at(200.0) - steady).abs() < 1e-12, "{d}");
                }
            }
            let gauss = Heating {
                a: 0.0,
                b: 0.3,
                p: 0.0,
            };
            let g =
                MaxwellCumulant::heated(d, coefficients(d, alpha), (gamma, c0), (2.0, 1.7), gauss)
                    .unwrap();
            let cooling = MaxwellCumulant::new(d, alpha, gamma, c0, 1.7);
            assert!((g.at(1.5) - cooling.at(1.5)).abs() < 1e-12);
        }
        // GRW Example 3 in d = 3: 0.0870.
        let (l2, l4, b4) = coefficients(3, 0.5);
        assert!((3.0 * b4 / (5.0 * l4) + 2.0 * l2 / l4 - 1.0 - 0.086957).abs() < 1e-6);
        // Kicks with a scaling that outheats the collisions (k <= 0): no steady state.
        let runaway = Heating {
            a: 1.0,
            b: 2.0 * kk * l2,
            p: 0.0,
        };
        assert!(
            MaxwellCumulant::heated(3, coefficients(3, 0.5), (gamma, c0), (1.0, 1.0), runaway)
                .is_none()
        );
    }
}
