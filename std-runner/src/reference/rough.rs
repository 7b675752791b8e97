//! The Maxwellian approximation of a rough gas (Huthmann and Zippelius 1997; Luding,
//! Huthmann, McNamara and Zippelius 1998): the rates of `T_tr` and `T_rot` evaluated with
//! independent Maxwellian translational and rim velocities, for the kernel
//! `B = gamma C |g|^lambda` with the impact law of [`gdsmc_core::rough::impact_direction`].
//!
//! Derivation (per unit mass, `g = v1 - v2`, `W = w1 + w2`, `eta = (1 + beta)/2 kappa/(1 + kappa)`,
//! the map of [`gdsmc_core::rough::RoughMap`]): over the impact direction (`E c^2 = 1/2`) and
//! over `W` (independent, isotropic, `E |W x n|^2 = 4 T_rot / kappa`) a collision changes the
//! pair's energies by
//! `E dE_tr = -A |g|^2 / 2 + 4 B T_rot` and `E dE_rot = B |g|^2 / 2 - 4 C T_rot`, with
//! `A = (1 - alpha^2)/4 + eta (1 - eta)`, `B = eta^2 / kappa`, `C = (eta / kappa)(1 - eta / kappa)`
//! (the coefficients of Luding et al. 1998). Collisions happen at `(N/2) 4 pi gamma C |g|^lambda`
//! per unit time, and `T = (2/3) E / N`, so with `M_p = E|g|^p = (4 T_tr)^(p/2)
//! Gamma((3 + p)/2) / Gamma(3/2)`:
//!
//! `dT_tr/dt = (4 pi gamma C / 3) (-A M_(lambda+2) / 2 + 4 B T_rot M_lambda) + 2 beta`,
//! `dT_rot/dt = (4 pi gamma C / 3) (B M_(lambda+2) / 2 - 4 C T_rot M_lambda) + 2 beta_rot`.
//!
//! With `beta = -1` (`eta = 0`) and the Maxwell kernel this is GRW (13)'s
//! `dT/dt = -pi gamma C (1 - alpha^2) T`. For hard spheres the cooling state's ratio
//! `theta = T_rot / T_tr` solves `B theta^2 + (C - A) theta - B = 0` (Huthmann and Zippelius
//! 1997); the elastic perfectly rough gas (`A = B = C`) then has `theta = 1`. For the Maxwell
//! kernel (`M_2 / 2 = 3 T_tr`, `M_0 = 1`) it does not: the rate `|g . n| / |g|` is not the same
//! before and after a collision that moves energy between translation and rotation, so
//! detailed balance and equipartition fail and the approximation's elastic ratio is 3/4.

use ode_solvers::{Dopri5, System, Vector2};

/// The Maxwellian approximation of one rough gas.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct RoughApproximation {
    /// `A`, `B`, `C` of the module docs.
    pub abc: [f64; 3],
    /// `4 pi gamma C / 3`.
    pub k: f64,
    /// The kernel exponent lambda.
    pub lambda: f64,
    /// `2 beta`, `2 beta_rot`: the noise's heating of each part.
    pub heating: [f64; 2],
}

/// `E |g|^p` for `g` Gaussian with variance `2 t` per component.
fn moment(p: f64, t: f64) -> f64 {
    (4.0 * t).powf(p / 2.0) * libm::tgamma((3.0 + p) / 2.0) / libm::tgamma(1.5)
}

impl RoughApproximation {
    /// The approximation for normal and tangential restitution `alpha`, `beta`, reduced moment
    /// of inertia `kappa`, kernel strength `gamma C` and exponent `lambda`, and white noise
    /// `noise_tr`, `noise_rot` on each part.
    pub fn new(
        alpha: f64,
        beta: f64,
        kappa: f64,
        strength: f64,
        lambda: f64,
        noise: [f64; 2],
    ) -> Self {
        let eta = 0.5 * (1.0 + beta) * kappa / (1.0 + kappa);
        RoughApproximation {
            abc: [
                0.25 * (1.0 - alpha * alpha) + eta * (1.0 - eta),
                eta * eta / kappa,
                eta / kappa * (1.0 - eta / kappa),
            ],
            k: 4.0 * std::f64::consts::PI * strength / 3.0,
            lambda,
            heating: [2.0 * noise[0], 2.0 * noise[1]],
        }
    }

    /// `(dT_tr/dt, dT_rot/dt)` at `(T_tr, T_rot)`.
    pub fn rates(&self, t_tr: f64, t_rot: f64) -> (f64, f64) {
        let [a, b, c] = self.abc;
        let t_tr = t_tr.max(0.0);
        let (m_hi, m_lo) = (moment(self.lambda + 2.0, t_tr), moment(self.lambda, t_tr));
        (
            self.k * (-a * m_hi / 2.0 + 4.0 * b * t_rot * m_lo) + self.heating[0],
            self.k * (b * m_hi / 2.0 - 4.0 * c * t_rot * m_lo) + self.heating[1],
        )
    }

    /// The hard-sphere cooling state's `theta`, the positive root of
    /// `B theta^2 + (C - A) theta - B = 0` (`None` for the smooth gas, `B = 0`).
    pub fn cooling_theta(&self) -> Option<f64> {
        let [a, b, c] = self.abc;
        (b > 0.0).then(|| {
            let d = c - a;
            (-d + (d * d + 4.0 * b * b).sqrt()) / (2.0 * b)
        })
    }

    /// The hard-sphere cooling state's rates `zeta = -(dT/dt)/T` of each part at `T_tr`:
    /// `(zeta_tr, zeta_rot)` (equal in the cooling state).
    pub fn cooling_rates(&self, t_tr: f64) -> Option<(f64, f64)> {
        let theta = self.cooling_theta()?;
        let (d_tr, d_rot) = self.rates(t_tr, theta * t_tr);
        Some((-d_tr / t_tr, -d_rot / (theta * t_tr)))
    }
}

impl System<f64, Vector2<f64>> for RoughApproximation {
    fn system(&self, _x: f64, y: &Vector2<f64>, dy: &mut Vector2<f64>) {
        let (a, b) = self.rates(y[0], y[1]);
        dy[0] = a;
        dy[1] = b;
    }
}

/// The approximation solved in time from `(T_tr, T_rot)` at 0 (Dopri5, tolerances 1e-10 and
/// 1e-12), with linear interpolation between 4000 output steps.
pub struct RoughTrajectory {
    points: Vec<(f64, f64, f64)>,
}

impl RoughTrajectory {
    /// Solves `model` from `t0 = (T_tr, T_rot)` on `[0, t_end]`.
    pub fn new(model: &RoughApproximation, t0: [f64; 2], t_end: f64) -> Result<Self, String> {
        let t_end = t_end.max(1e-12);
        let y0 = Vector2::new(t0[0], t0[1]);
        let mut stepper = Dopri5::new(*model, 0.0, t_end, t_end / 4000.0, y0, 1e-10, 1e-12);
        stepper.integrate().map_err(|e| format!("{e:?}"))?;
        Ok(RoughTrajectory {
            points: stepper
                .x_out()
                .iter()
                .zip(stepper.y_out())
                .map(|(&x, y)| (x, y[0], y[1]))
                .collect(),
        })
    }

    /// `(T_tr, T_rot)` at `t`.
    pub fn at(&self, t: f64) -> (f64, f64) {
        let (i, f) = crate::reference::hydro::bracket(&self.points, |q| q.0, t);
        let (a, b) = (&self.points[i - 1], &self.points[i]);
        (a.1 + f * (b.1 - a.1), a.2 + f * (b.2 - a.2))
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use gdsmc_core::rng::seeded;
    use gdsmc_core::rough::{RoughMap, impact_direction};
    use gdsmc_core::sample::standard_normal3;

    /// The closed forms against a Monte Carlo of the core's map itself: Gaussian `v1, v2`
    /// (variance `T_tr`), `w1, w2` (variance `T_rot / kappa`), the impact direction, weights
    /// `|g|^lambda`. 400,000 draws; each mean within 3.2 standard errors, 8 checks
    /// (Bonferroni: 3.2 -> 3.9).
    #[test]
    fn the_rates_are_the_maps_mean_energy_changes() {
        let mut rng = seeded(11);
        for (alpha, beta, kappa, lambda) in [
            (0.9, 0.0, 0.4, 1.0),
            (0.7, 0.6, 0.5, 1.0),
            (0.8, -0.4, 0.4, 0.0),
            (1.0, 1.0, 0.4, 0.0),
        ] {
            let (t_tr, t_rot): (f64, f64) = (1.3, 0.7);
            let map = RoughMap::new(alpha, beta, kappa).unwrap();
            let ma = RoughApproximation::new(alpha, beta, kappa, 1.0, lambda, [0.0; 2]);
            let draws = 400_000;
            let (mut s_tr, mut s_rot) = (Vec::new(), Vec::new());
            for _ in 0..draws {
                let v1 = t_tr.sqrt() * standard_normal3(&mut rng);
                let v2 = t_tr.sqrt() * standard_normal3(&mut rng);
                let w1 = (t_rot / kappa).sqrt() * standard_normal3(&mut rng);
                let w2 = (t_rot / kappa).sqrt() * standard_normal3(&mut rng);
                let g = v1 - v2;
                let n = impact_direction(g, &mut rng);
                let (a1, b1, a2, b2) = map.collide(v1, w1, v2, w2, n);
                let de_tr = 0.5 * (a1.norm2() + a2.norm2() - v1.norm2() - v2.norm2());
                let de_rot = 0.5 * kappa * (b1.norm2() + b2.norm2() - w1.norm2() - w2.norm2());
                let w = g.norm().powf(lambda);
                s_tr.push(w * de_tr);
                s_rot.push(w * de_rot);
            }
            // dT/dt = (4 pi gamma C / 3) E[|g|^lambda dE] (module docs), gamma C = 1.
            let (d_tr, d_rot) = ma.rates(t_tr, t_rot);
            for (s, d) in [(s_tr, d_tr), (s_rot, d_rot)] {
                let n = s.len() as f64;
                let m = s.iter().sum::<f64>() / n;
                let sd = (s.iter().map(|x| (x - m) * (x - m)).sum::<f64>() / (n - 1.0)).sqrt();
                let got = ma.k * m;
                let h = 3.9 * ma.k * sd / n.sqrt();
                assert!(
                    (got - d).abs() <= h,
                    "alpha {alpha} beta {beta} kappa {kappa} lambda {lambda}: {got} vs {d} +- {h}"
                );
            }
        }
    }

    #[test]
    fn the_smooth_maxwell_gas_is_grw_13() {
        let ma = RoughApproximation::new(0.5, -1.0, 0.4, 1.0, 0.0, [0.0; 2]);
        let (d_tr, d_rot) = ma.rates(2.0, 5.0);
        let k = std::f64::consts::PI * (1.0 - 0.25);
        assert!((d_tr + k * 2.0).abs() < 1e-12, "{d_tr}");
        assert_eq!(d_rot, 0.0);
        assert_eq!(ma.cooling_theta(), None);
    }

    #[test]
    fn the_elastic_perfectly_rough_hard_spheres_equipartition() {
        let ma = RoughApproximation::new(1.0, 1.0, 0.4, 1.0, 1.0, [0.0; 2]);
        assert!((ma.cooling_theta().unwrap() - 1.0).abs() < 1e-12);
        let (a, b) = ma.rates(1.0, 1.0);
        assert!(a.abs() < 1e-12 && b.abs() < 1e-12);
    }
}
