//! The Maxwellian approximation of a rough gas (Huthmann and Zippelius 1997; Luding,
//! Huthmann, McNamara and Zippelius 1998): the rates of `T_tr` and `T_rot` evaluated with
//! independent Maxwellian translational and rim velocities, for the kernel
//! `B = gamma C |g|^lambda` with the impact law of [`gdsmc_core::rough::impact_direction`].
//!
//! Derivation (per unit mass, `g = v1 - v2`, `W = w1 + w2`, `eta = (1 + beta)/2 kappa/(1 + kappa)`,
//! the map of [`gdsmc_core::rough::RoughMap`], `c = g_hat . n`): averaged over `W`
//! (independent, isotropic, zero mean) a collision changes the pair's energies by
//!
//! `E dE_tr = -(1 - alpha^2)/4 |g|^2 c^2 - eta (1 - eta) |g|^2 (1 - c^2) + eta^2 E|W x n|^2`,
//! `E dE_rot = (eta^2 / kappa) |g|^2 (1 - c^2) - eta (1 - eta / kappa) E|W x n|^2`.
//!
//! Over the impact law, `E c^2 = p_n`: 1/2 for spheres (density `2c` on the hemisphere), 2/3
//! for disks (impact parameter `b` uniform, `c^2 = 1 - b^2`); `E|W x n|^2 = w T_rot / kappa`
//! with `w` = 4 for spheres (`|W|^2 - (W . n)^2`, `W` of variance `2 T_rot / kappa` per
//! component) and 2 for disks (`W` along z, normal to `n`). With `A = (1 - alpha^2)/4 +
//! eta (1 - eta)`, `B = eta^2 / kappa`, `C = (eta / kappa)(1 - eta / kappa)` (the coefficients
//! of Luding et al. 1998) and the loss `L = p_n (1 - alpha^2)/4 + (1 - p_n) eta (1 - eta)`
//! (`A/2` for spheres):
//! `E dE_tr = -L |g|^2 + w B T_rot` and `E dE_rot = (1 - p_n) B |g|^2 - w C T_rot`.
//! Collisions happen at `(N/2) 4 pi gamma C |g|^lambda` per unit time, and `T_tr = (2/d) E_tr/N`,
//! `T_rot = (2/d_rot) E_rot/N` (`d_rot` = 3 for spheres, 1 for disks), so with
//! `M_p = E|g|^p = (4 T_tr)^(p/2) Gamma((d + p)/2) / Gamma(d/2)`:
//!
//! `dT_tr/dt = (4 pi gamma C / d) (-L M_(lambda+2) + w B T_rot M_lambda) + 2 beta (+ 2 zeta T_tr)`,
//! `dT_rot/dt = (4 pi gamma C / d_rot) ((1 - p_n) B M_(lambda+2) - w C T_rot M_lambda) + 2 beta_rot`.
//!
//! For spheres: `(4 pi gamma C / 3) (-A M_(lambda+2) / 2 + 4 B T_rot M_lambda)` and
//! `(4 pi gamma C / 3) (B M_(lambda+2) / 2 - 4 C T_rot M_lambda)` (Luding et al. 1998).
//! A Gaussian thermostat on translation (MS (12), `dv/dt = zeta (v - V)` between collisions)
//! adds `2 zeta T_tr` to `dT_tr/dt` and leaves the rotation alone.
//! With `beta = -1` (`eta = 0`) and the Maxwell kernel this is GRW (13)'s
//! `dT/dt = -pi gamma C (1 - alpha^2) T` in both dimensions. In the cooling state both parts
//! cool at one rate; `M_(lambda+2) = 2 (d + lambda) T_tr M_lambda` turns that into a quadratic
//! in `theta = T_rot / T_tr` ([`RoughApproximation::cooling_theta`]): for hard spheres
//! `B theta^2 + (C - A) theta - B = 0` (Huthmann and Zippelius 1997), whose elastic perfectly
//! rough root is `theta = 1`. For the Maxwell kernel (`M_2 = 2 d T_tr`, `M_0 = 1`) it is not:
//! the rate `|g . n| / |g|` is not the same before and after a collision that moves energy
//! between translation and rotation, so detailed balance and equipartition fail and the
//! approximation's elastic ratio for spheres is 3/4.

use super::ode;

/// The Maxwellian approximation of one rough gas.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct RoughApproximation {
    /// `A`, `B`, `C` of the module docs.
    pub abc: [f64; 3],
    /// The translational loss `L` of the module docs (`A/2` for spheres).
    pub loss: f64,
    /// The pair rate constant `4 pi gamma C`.
    pub rate: f64,
    /// The kernel exponent lambda.
    pub lambda: f64,
    /// `2 beta`, `2 beta_rot`: the noise's heating of each part.
    pub heating: [f64; 2],
    /// `zeta` of a Gaussian thermostat on translation (MS (12): it adds `2 zeta T_tr` to
    /// `dT_tr/dt`); 0 without one.
    pub thermostat: f64,
    /// The dimension `d` (3: spheres, 2: disks).
    pub d: usize,
}

/// `E |g|^p` for `g` Gaussian in `d` dimensions with variance `2 t` per component.
fn moment(p: f64, t: f64, d: usize) -> f64 {
    let d = d as f64;
    libm::pow(4.0 * t, p / 2.0) * libm::tgamma((d + p) / 2.0) / libm::tgamma(d / 2.0)
}

impl RoughApproximation {
    /// The approximation for rough spheres with normal and tangential restitution `alpha`,
    /// `beta`, reduced moment of inertia `kappa`, kernel strength `gamma C` and exponent
    /// `lambda`, and white noise `noise_tr`, `noise_rot` on each part.
    pub fn new(
        alpha: f64,
        beta: f64,
        kappa: f64,
        strength: f64,
        lambda: f64,
        noise: [f64; 2],
    ) -> Self {
        Self::in_dimension(3, alpha, beta, kappa, strength, lambda, noise)
    }

    /// As [`RoughApproximation::new`] in dimension `d` (3: spheres, 2: disks).
    pub fn in_dimension(
        d: usize,
        alpha: f64,
        beta: f64,
        kappa: f64,
        strength: f64,
        lambda: f64,
        noise: [f64; 2],
    ) -> Self {
        let eta = 0.5 * (1.0 + beta) * kappa / (1.0 + kappa);
        let (a_n, a_t) = (0.25 * (1.0 - alpha * alpha), eta * (1.0 - eta));
        let p_n = Self::normal_share(d);
        RoughApproximation {
            abc: [
                a_n + a_t,
                eta * eta / kappa,
                eta / kappa * (1.0 - eta / kappa),
            ],
            loss: p_n * a_n + (1.0 - p_n) * a_t,
            rate: 4.0 * std::f64::consts::PI * strength,
            lambda,
            heating: [2.0 * noise[0], 2.0 * noise[1]],
            thermostat: 0.0,
            d,
        }
    }

    /// `p_n = E c^2` over the impact law: 1/2 for spheres, 2/3 for disks.
    fn normal_share(d: usize) -> f64 {
        if d == 2 { 2.0 / 3.0 } else { 0.5 }
    }

    /// `w = E|W x n|^2 kappa / T_rot`: 4 for spheres, 2 for disks.
    fn spin_share(&self) -> f64 {
        if self.d == 2 { 2.0 } else { 4.0 }
    }

    /// Rotational degrees of freedom: 3 for spheres, 1 for disks.
    fn d_rot(&self) -> f64 {
        if self.d == 2 { 1.0 } else { 3.0 }
    }

    /// `4 pi gamma C / d` and `4 pi gamma C / d_rot`: what multiplies `E[|g|^lambda dE]` in
    /// `dT_tr/dt` and `dT_rot/dt`.
    pub fn factors(&self) -> (f64, f64) {
        (self.rate / self.d as f64, self.rate / self.d_rot())
    }

    /// `(dT_tr/dt, dT_rot/dt)` at `(T_tr, T_rot)`.
    pub fn rates(&self, t_tr: f64, t_rot: f64) -> (f64, f64) {
        let [_, b, c] = self.abc;
        let (w, p_t) = (self.spin_share(), 1.0 - Self::normal_share(self.d));
        let (k_tr, k_rot) = self.factors();
        let t_tr = t_tr.max(0.0);
        let m_hi = moment(self.lambda + 2.0, t_tr, self.d);
        let m_lo = moment(self.lambda, t_tr, self.d);
        (
            k_tr * (-self.loss * m_hi + w * b * t_rot * m_lo)
                + self.heating[0]
                + 2.0 * self.thermostat * t_tr,
            k_rot * (p_t * b * m_hi - w * c * t_rot * m_lo) + self.heating[1],
        )
    }

    /// The cooling state's `theta` (module docs): with `r = M_(lambda+2) / (T_tr M_lambda) =
    /// 2 (d + lambda)`, the positive root of
    /// `(w B / d) theta^2 + (w C / d_rot - L r / d) theta - (1 - p_n) B r / d_rot = 0`
    /// (hard spheres: `B theta^2 + (C - A) theta - B = 0`); `None` for the smooth gas, `B = 0`.
    pub fn cooling_theta(&self) -> Option<f64> {
        let [_, b, c] = self.abc;
        let (w, p_t) = (self.spin_share(), 1.0 - Self::normal_share(self.d));
        let (d, d_rot) = (self.d as f64, self.d_rot());
        let r = 2.0 * (d + self.lambda);
        let qa = w * b / d;
        let qb = w * c / d_rot - self.loss * r / d;
        let qc = -p_t * b * r / d_rot;
        (b > 0.0).then(|| (-qb + (qb * qb - 4.0 * qa * qc).sqrt()) / (2.0 * qa))
    }

    /// The hard-sphere cooling state's rates `zeta = -(dT/dt)/T` of each part at `T_tr`:
    /// `(zeta_tr, zeta_rot)` (equal in the cooling state).
    pub fn cooling_rates(&self, t_tr: f64) -> Option<(f64, f64)> {
        let theta = self.cooling_theta()?;
        let (d_tr, d_rot) = self.rates(t_tr, theta * t_tr);
        Some((-d_tr / t_tr, -d_rot / (theta * t_tr)))
    }
}

/// The approximation in scale-free variables against log time: `u = ln T_tr`,
/// `theta = T_rot / T_tr` as functions of `s = ln(1 + t)`, so that a cooling gas's decades
/// (Haff's law: `T ~ t^-2`) are as many steps as its first unit of time and no tolerance is
/// absolute in `T`: `du/ds = (1 + t) T_tr'/T_tr`, `dtheta/ds = (1 + t)(T_rot' - theta
/// T_tr')/T_tr`.
#[derive(Clone, Copy)]
struct ScaleFree(RoughApproximation);

impl ScaleFree {
    /// `(du/ds, dtheta/ds)` at `s`, `y = (u, theta)`.
    fn rates(&self, s: f64, y: &[f64; 2]) -> [f64; 2] {
        let t_tr = libm::exp(y[0]);
        let (a, b) = self.0.rates(t_tr, y[1] * t_tr);
        let dt_ds = libm::exp(s);
        [dt_ds * a / t_tr, dt_ds * (b - y[1] * a) / t_tr]
    }
}

/// The approximation solved in time from `(T_tr, T_rot)` at 0 ([`ode::solve`], tolerances
/// [`ode::TOLERANCES`]): in the scale-free variables of `ScaleFree` when `T_tr > 0` at the start (4000
/// output steps even in log time, `ln T_tr` and `theta` interpolated linearly in it), else
/// in `(T_tr, T_rot)` themselves (4000 even steps in time).
pub struct RoughTrajectory {
    /// `(s, u, theta)` points (scale-free), or `(t, T_tr, T_rot)`.
    points: Vec<(f64, f64, f64)>,
    scale_free: bool,
}

impl RoughTrajectory {
    /// Solves `model` from `t0 = (T_tr, T_rot)` on `[0, t_end]`.
    pub fn new(model: &RoughApproximation, t0: [f64; 2], t_end: f64) -> Result<Self, String> {
        let t_end = t_end.max(1e-12);
        let collect = |p: Vec<(f64, [f64; 2])>| -> Vec<(f64, f64, f64)> {
            p.into_iter().map(|(x, y)| (x, y[0], y[1])).collect()
        };
        if t0[0] > 0.0 {
            let y0 = [libm::log(t0[0]), t0[1] / t0[0]];
            let scale_free = ScaleFree(*model);
            let rhs = |s: f64, y: &[f64; 2]| scale_free.rates(s, y);
            let p = ode::solve(rhs, 0.0, libm::log1p(t_end), y0, ode::TOLERANCES, 4000)
                .map_err(|e| e.to_string())?;
            return Ok(RoughTrajectory {
                points: collect(p),
                scale_free: true,
            });
        }
        let rhs = |_: f64, y: &[f64; 2]| {
            let (a, b) = model.rates(y[0], y[1]);
            [a, b]
        };
        let p =
            ode::solve(rhs, 0.0, t_end, t0, ode::TOLERANCES, 4000).map_err(|e| e.to_string())?;
        Ok(RoughTrajectory {
            points: collect(p),
            scale_free: false,
        })
    }

    /// `(T_tr, T_rot)` at `t`.
    pub fn at(&self, t: f64) -> (f64, f64) {
        let x = if self.scale_free { libm::log1p(t) } else { t };
        let (i, f) = crate::hydro::bracket(&self.points, |q| q.0, x);
        let (a, b) = (&self.points[i - 1], &self.points[i]);
        let (p, q) = (a.1 + f * (b.1 - a.1), a.2 + f * (b.2 - a.2));
        if self.scale_free {
            let t_tr = libm::exp(p);
            (t_tr, q * t_tr)
        } else {
            (p, q)
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use gdsmc_core::geometry::{Disks, Geometry, Spheres};
    use gdsmc_core::rng::seeded;
    use gdsmc_core::rough::RoughMap;

    /// The closed forms against a Monte Carlo of the core's map itself: Gaussian `v1, v2`
    /// (variance `T_tr` per component), `w1, w2` (variance `T_rot / kappa` per degree of
    /// freedom), the impact direction of the dimension, weights `|g|^lambda`. 400,000 draws;
    /// each mean within its 99.9% interval, the 8 checks of a dimension held together
    /// (Bonferroni, `gdsmc_stats::joint`).
    fn rates_match_the_map<G: Geometry>(seed: u64, kappas: [f64; 2]) {
        const CHECKS: usize = 8;
        let mut rng = seeded(seed);
        let d = G::CHOICE.d();
        for (alpha, beta, kappa, lambda) in [
            (0.9, 0.0, kappas[0], 1.0),
            (0.7, 0.6, kappas[1], 1.0),
            (0.8, -0.4, kappas[0], 0.0),
            (1.0, 1.0, kappas[0], 0.0),
        ] {
            let (t_tr, t_rot): (f64, f64) = (1.3, 0.7);
            let map = if d == 2 {
                RoughMap::for_disks(alpha, beta, kappa).unwrap()
            } else {
                RoughMap::new(alpha, beta, kappa).unwrap()
            };
            let ma = RoughApproximation::in_dimension(d, alpha, beta, kappa, 1.0, lambda, [0.0; 2]);
            let draws = 400_000;
            let (mut s_tr, mut s_rot) = (Vec::new(), Vec::new());
            for _ in 0..draws {
                let v1 = t_tr.sqrt() * G::normal(&mut rng);
                let v2 = t_tr.sqrt() * G::normal(&mut rng);
                let w1 = (t_rot / kappa).sqrt() * G::spin_normal(&mut rng);
                let w2 = (t_rot / kappa).sqrt() * G::spin_normal(&mut rng);
                let g = v1 - v2;
                let n = G::impact(g, &mut rng);
                let (a1, b1, a2, b2) = map.collide(v1, w1, v2, w2, n);
                let de_tr = 0.5 * (a1.norm2() + a2.norm2() - v1.norm2() - v2.norm2());
                let de_rot = 0.5 * kappa * (b1.norm2() + b2.norm2() - w1.norm2() - w2.norm2());
                let w = libm::pow(g.norm(), lambda);
                s_tr.push(w * de_tr);
                s_rot.push(w * de_rot);
            }
            // dT/dt = (4 pi gamma C / d) E[|g|^lambda dE] (module docs), gamma C = 1.
            let (d_tr, d_rot) = ma.rates(t_tr, t_rot);
            let (k_tr, k_rot) = ma.factors();
            for (s, dt, k) in [(s_tr, d_tr, k_tr), (s_rot, d_rot, k_rot)] {
                let sample = gdsmc_stats::Sample::of(&s);
                let got = k * sample.mean;
                let h = k * sample.joint_ci(CHECKS);
                assert!(
                    (got - dt).abs() <= h,
                    "d {d} alpha {alpha} beta {beta} kappa {kappa} lambda {lambda}: {got} vs {dt} +- {h}"
                );
            }
        }
    }

    #[test]
    fn the_rates_are_the_maps_mean_energy_changes() {
        rates_match_the_map::<Spheres>(11, [0.4, 0.5]);
    }

    #[test]
    fn the_disk_rates_are_the_maps_mean_energy_changes() {
        rates_match_the_map::<Disks>(12, [0.5, 0.9]);
    }

    /// The cooling-state theta is where both parts cool at one rate, for each dimension and
    /// kernel exponent (the quadratic against the rates themselves).
    /// A cooling gas solved over nine decades of time keeps its temperatures positive and
    /// theta at the closed-form cooling value (relative 1e-6) once it has settled, and Haff's
    /// law `T ~ t^-2` (issue 35: the solution in `(T_tr, T_rot)` with an absolute tolerance
    /// and even steps gave theta = -2.2 at t = 4e9 for the elastic perfectly rough spheres).
    #[test]
    fn a_cooling_trajectory_keeps_the_cooling_theta_over_nine_decades() {
        for beta in [1.0, 0.0, -0.5] {
            let m =
                RoughApproximation::new(0.9, beta, 0.4, 1.0 / std::f64::consts::PI, 1.0, [0.0; 2]);
            let theta = m.cooling_theta().unwrap();
            let tr = RoughTrajectory::new(&m, [1.0, 1.0], 4e9).unwrap();
            for t in [2e9, 3e9, 4e9] {
                let (a, b) = tr.at(t);
                assert!(a > 0.0 && b > 0.0, "beta {beta}, t {t}: ({a}, {b})");
                assert!(
                    ((b / a) / theta - 1.0).abs() < 1e-6,
                    "beta {beta}, t {t}: theta {} against {theta}",
                    b / a
                );
            }
            let (t1, t2) = (tr.at(2e9).0, tr.at(4e9).0);
            assert!(
                (libm::log2(t1 / t2) - 2.0).abs() < 1e-4,
                "Haff: {t1} -> {t2}"
            );
        }
    }

    #[test]
    fn the_cooling_theta_equalizes_the_rates() {
        for d in [2, 3] {
            for lambda in [0.0, 0.5, 1.0] {
                let ma = RoughApproximation::in_dimension(d, 0.8, 0.3, 0.45, 1.0, lambda, [0.0; 2]);
                let theta = ma.cooling_theta().unwrap();
                let (a, b) = ma.rates(1.0, theta);
                assert!(
                    (a - b / theta).abs() < 1e-12,
                    "d {d} lambda {lambda}: {a} vs {}",
                    b / theta
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
