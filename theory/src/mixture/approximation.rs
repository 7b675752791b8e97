//! The Maxwellian approximation of a mixture's species temperatures (Garzó and Dufty 1999).

use gdsmc_core::mixture::pair_index;

/// The Maxwellian approximation of a mixture's species temperatures (Garzó and Dufty 1999):
/// every species' distribution taken as a Maxwellian at its own temperature,
/// zero mean, for the kernel `kappa_st |u|^lambda / N` per pair (exact for Maxwell
/// pseudo-molecules, `lambda = 0`, in the Boltzmann limit). With `theta_s = T_s / m_s` and
/// `sigma^2 = theta_s + theta_t` (the variance per component of `u = v - w`), the collisions
/// change `<|v|^2>_s = 3 theta_s` at
///
/// ```text
/// d(3 theta_s)/dt = sum_t x_t kappa_st M_{2+lambda} sigma^lambda [-2 mu a theta_s + 2 mu^2 a^2 sigma^2]
/// ```
///
/// (`mu = m_t/(m_s + m_t)`, `a = (1 + alpha_st)/2`, `M_k = E|Z|^k` of a standard normal
/// 3-vector: `<|u|^{2+lambda}> = M_{2+lambda} sigma^{2+lambda}` and
/// `<|u|^lambda v.u> = theta_s/sigma^2 <|u|^{2+lambda}>`), and white noise of strength
/// `beta_s` adds `2 beta_s` to `d theta_s/dt` (GRW (18)). For hard spheres the cooling rates
/// `zeta_s = -(dT_s/dt)/T_s` are Garzó and Dufty 1999's Maxwellian (leading Sonine) cooling
/// rates in this normalization; the cooling state is where all `zeta_s` are equal.
#[derive(Clone, Debug, PartialEq)]
pub struct MaxwellianApproximation {
    /// Mole fractions.
    pub fractions: Vec<f64>,
    /// Masses.
    pub masses: Vec<f64>,
    /// `kappa_st = 4 pi gamma C_st` per pair type (order `(0,0), (0,1), .., (1,1), ..`).
    pub kappa: Vec<f64>,
    /// Restitution per pair type.
    pub alpha: Vec<f64>,
    /// Kernel exponent (0 Maxwell, 1 hard spheres).
    pub lambda: f64,
    /// White-noise strength per species (all 0: the cooling state).
    pub beta: Vec<f64>,
}

impl MaxwellianApproximation {
    fn pair(&self, s: usize, t: usize) -> usize {
        pair_index(self.masses.len(), s, t)
    }

    /// `d theta_s / dt` at `theta`.
    pub fn rates(&self, theta: &[f64]) -> Vec<f64> {
        let ns = self.masses.len();
        // M_k = 2^{k/2} Gamma((3 + k)/2) / Gamma(3/2).
        let k = 2.0 + self.lambda;
        let moment = libm::pow(2f64, k / 2.0) * libm::tgamma((3.0 + k) / 2.0) / libm::tgamma(1.5);
        (0..ns)
            .map(|s| {
                let mut d = 0.0;
                for t in 0..ns {
                    let p = self.pair(s, t);
                    let mu = self.masses[t] / (self.masses[s] + self.masses[t]);
                    let a = 0.5 * (1.0 + self.alpha[p]);
                    let sigma2 = theta[s] + theta[t];
                    d += self.fractions[t]
                        * self.kappa[p]
                        * moment
                        * libm::pow(sigma2, self.lambda / 2.0)
                        * (-2.0 * mu * a * theta[s] + 2.0 * mu * mu * a * a * sigma2);
                }
                d / 3.0 + 2.0 * self.beta[s]
            })
            .collect()
    }

    /// The species temperatures over the mixture temperature, `T_s / T` with
    /// `T = sum x_s T_s`, of the cooling state (no drive) or the steady state (white noise):
    /// followed in time from equal temperatures (RK4, the temperature rescaled to 1 after
    /// each step when cooling) until the ratios change by less than 1e-13; `None` if that
    /// takes more than 10^6 steps.
    pub fn steady_ratios(&self) -> Option<Vec<f64>> {
        let ns = self.masses.len();
        let temperature = |theta: &[f64]| -> f64 {
            (0..ns)
                .map(|s| self.fractions[s] * self.masses[s] * theta[s])
                .sum()
        };
        let heating: Vec<f64> = self.beta.iter().map(|b| 2.0 * b).collect();
        crate::steady::relax(
            self.masses.iter().map(|m| 1.0 / m).collect(),
            |theta| self.rates(theta),
            &heating,
            temperature,
            |theta| {
                let t = temperature(theta);
                (0..ns).map(|s| self.masses[s] * theta[s] / t).collect()
            },
        )
    }
}

#[cfg(test)]
mod tests {
    use super::super::MaxwellMixture;
    use super::*;

    /// For Maxwell pseudo-molecules the approximation is exact in the Boltzmann limit: its
    /// cooling-state ratio equals the exact second moments' at long times.
    #[test]
    fn maxwell_kernel_matches_the_exact_boltzmann_limit() {
        let exact = MaxwellMixture {
            counts: vec![400, 600],
            masses: vec![1.0, 4.0],
            kappa: vec![1.0, 1.5, 0.5],
            alpha: vec![0.9, 0.6, 0.8],
            temperatures: vec![1.0, 2.0],
            beta: vec![],
            momentum: gdsmc_core::physics::Momentum::Drawn,
        };
        let t = exact.temperatures_at(200.0, true);
        let approx = MaxwellianApproximation {
            fractions: vec![0.4, 0.6],
            masses: vec![1.0, 4.0],
            kappa: vec![1.0, 1.5, 0.5],
            alpha: vec![0.9, 0.6, 0.8],
            lambda: 0.0,
            beta: vec![0.0, 0.0],
        }
        .steady_ratios()
        .unwrap();
        let r_exact = t[0] / t[1];
        let r = approx[0] / approx[1];
        assert!((r - r_exact).abs() < 1e-9 * r_exact, "{r} vs {r_exact}");
    }

    /// Equal species share the temperature (equipartition), hard spheres or not.
    #[test]
    fn equal_species_have_equal_temperatures() {
        let a = MaxwellianApproximation {
            fractions: vec![0.3, 0.7],
            masses: vec![2.0, 2.0],
            kappa: vec![1.0; 3],
            alpha: vec![0.8; 3],
            lambda: 1.0,
            beta: vec![0.0, 0.0],
        }
        .steady_ratios()
        .unwrap();
        assert!(
            (a[0] - 1.0).abs() < 1e-12 && (a[1] - 1.0).abs() < 1e-12,
            "{a:?}"
        );
    }

    /// Hard spheres, equal sizes and fractions, alpha = 0.8 for every pair: the heavier
    /// species is the hotter (Garzó and Dufty 1999's finding), and equal masses share it.
    #[test]
    fn heavier_species_is_hotter() {
        let ratio = |m1: f64| {
            let r = MaxwellianApproximation {
                fractions: vec![0.5, 0.5],
                masses: vec![m1, 1.0],
                kappa: vec![1.0; 3],
                alpha: vec![0.8; 3],
                lambda: 1.0,
                beta: vec![0.0, 0.0],
            }
            .steady_ratios()
            .unwrap();
            r[0] / r[1]
        };
        assert!(
            ratio(4.0) > 1.0 && ratio(0.25) < 1.0,
            "{} {}",
            ratio(4.0),
            ratio(0.25)
        );
        assert!((ratio(1.0) - 1.0).abs() < 1e-12);
    }

    /// The heated steady state is where the rates vanish: the ratios against small fixed
    /// Euler steps followed to rest (independent of the adaptive step, which once grew
    /// without bound there and returned a state that was not steady).
    #[test]
    fn the_heated_steady_state_is_where_the_rates_vanish() {
        let a = MaxwellianApproximation {
            fractions: vec![0.5, 0.5],
            masses: vec![2.0, 1.0],
            kappa: vec![4.0, 3.6, 3.2],
            alpha: vec![0.8; 3],
            lambda: 1.0,
            beta: vec![1.0, 1.0],
        };
        let r = a.steady_ratios().unwrap();
        let mut theta = vec![0.5, 1.0];
        for _ in 0..200_000 {
            let k = a.rates(&theta);
            theta.iter_mut().zip(&k).for_each(|(x, d)| *x += 1e-3 * d);
        }
        assert!(a.rates(&theta).iter().all(|d| d.abs() < 1e-10));
        let t: Vec<f64> = (0..2).map(|s| a.masses[s] * theta[s]).collect();
        let mean = 0.5 * (t[0] + t[1]);
        for s in 0..2 {
            assert!((r[s] - t[s] / mean).abs() < 1e-9, "{r:?} vs {t:?}");
        }
    }
}
