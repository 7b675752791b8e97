//! The Maxwellian approximation of a rough mixture (Santos, Kremer and Garzó 2010, who give its
//! energy production rates for rough spheres; derived here for the kernel
//! `B = gamma C_st |u|^lambda` with the impact law in `d` = 2 or 3 dimensions, and for the
//! pair map of `gdsmc_core::rough::RoughPair`): every species' velocities and rim velocities
//! taken as independent Maxwellians at its own translational and rotational temperatures
//! `T_s`, `R_s`, zero mean.
//!
//! Derivation. A particle of species `s` (mass `m_s`, inertia `kappa_s`) meets one of species
//! `t` at the rate `x_t S_st |u|^lambda` (`x_t` the mole fraction, `S_st = 4 pi gamma C
//! sigma_st^(d-1)` the pair's strength, `sigma_st = (sigma_s + sigma_t)/2`, `u = v_s - v_t`;
//! the Boltzmann limit), with the impact direction `n` of density `prop. u_hat . n`. With the
//! contact velocity `g = u + W x n` (`W = w_s + w_t`), `g_n = (u . n) n`, `g_t = g - g_n`, the
//! map changes `v_s` by `-a_s g_n - t_s g_t` and `w_s` by `-c_s n x g_t` (`a_s = (1 + alpha)
//! m_t/(m_s + m_t)`, `c_s = (1 + beta)/(1 + kappa_s m_s/mu + kappa_s m_s/(kappa_t m_t))`,
//! `t_s = kappa_s c_s`). The energy changes are `m_s (v_s . dv_s + |dv_s|^2/2)` and
//! `kappa_s m_s (w_s . dw_s + |dw_s|^2/2)`. The changes depend on `v_s` only through `u` and on
//! `w_s` only through `W`, and for Gaussians `E[v_s | u] = l_s u`, `l_s = (T_s/m_s)/s^2`,
//! `s^2 = T_s/m_s + T_t/m_t` (the variance of `u` per component), and `E[w_s | W] =
//! (r_s / v_W) W`, `r_s = R_s/(kappa_s m_s)`, `v_W = r_s + r_t`. Averaged over `W`
//! (`E|W x n|^2 = q v_W`, `q` = 2 for spheres, 1 for disks, whose `W` is normal to the plane)
//! and over `n` (`E (u_hat . n)^2 = p_n`: 1/2 for spheres, 2/3 for disks):
//!
//! ```text
//! E dE_s   = m_s [ (p_n (a_s^2/2 - l_s a_s) + (1 - p_n)(t_s^2/2 - l_s t_s)) |u|^2 + t_s^2 q v_W / 2 ]
//! E dE_s^r = kappa_s m_s [ (1 - p_n) c_s^2/2 |u|^2 + (c_s^2 v_W / 2 - c_s r_s) q ]
//! ```
//!
//! Over `u`, `E|u|^p = M_p = (2 s^2)^(p/2) Gamma((d + p)/2)/Gamma(d/2)`, and with `d_r` = 3
//! (spheres) or 1 (disks) rotational degrees of freedom:
//!
//! ```text
//! dT_s/dt = (2/d)   sum_t x_t S_st E[|u|^lambda dE_s]   + h_s,
//! dR_s/dt = (2/d_r) sum_t x_t S_st E[|u|^lambda dE_s^r] + h_rot,s,
//! ```
//!
//! the last terms the heating of white noise per species (`m_s` times the variance rate of a
//! velocity component, `kappa_s m_s` times a rim-velocity component's). One species is
//! [`super::rough::RoughApproximation`] (`l = r/v_W = 1/2`); `beta = -1` is the smooth
//! mixture's [`super::mixture::MaxwellianApproximation`]; elastic perfectly rough hard spheres
//! or disks at one common temperature do not change it (equilibrium): all three tested below.
//! The cooling state is where every `T_s` and `R_s` cools at one rate.

use gdsmc_core::mixture::pair_index;

/// The Maxwellian approximation of a rough mixture (module docs).
#[derive(Clone, Debug, PartialEq)]
pub struct RoughMixtureApproximation {
    /// The dimension `d` (3: spheres, 2: disks).
    pub d: usize,
    /// Mole fractions `x_s`.
    pub fractions: Vec<f64>,
    /// Masses `m_s`.
    pub masses: Vec<f64>,
    /// Reduced moments of inertia `kappa_s`.
    pub inertia: Vec<f64>,
    /// `S_st = 4 pi gamma C sigma_st^(d-1)` per pair type (order `(0,0), (0,1), .., (1,1), ..`).
    pub strength: Vec<f64>,
    /// Normal restitution per pair type.
    pub alpha: Vec<f64>,
    /// Tangential restitution per pair type.
    pub beta: Vec<f64>,
    /// Kernel exponent (0 Maxwell, 1 hard spheres).
    pub lambda: f64,
    /// `dT_s/dt` from white noise on translation per species (all 0 with no drive).
    pub heating: Vec<f64>,
    /// `dR_s/dt` from white noise on rotation per species.
    pub heating_rot: Vec<f64>,
}

/// `E|u|^p` for `u` Gaussian in `d` dimensions with variance `s2` per component.
fn moment(p: f64, s2: f64, d: usize) -> f64 {
    let d = d as f64;
    libm::pow(2.0 * s2, p / 2.0) * libm::tgamma((d + p) / 2.0) / libm::tgamma(d / 2.0)
}

impl RoughMixtureApproximation {
    fn species(&self) -> usize {
        self.masses.len()
    }

    /// `(p_n, q, d_r)` of the module docs.
    fn geometry(&self) -> (f64, f64, f64) {
        if self.d == 2 {
            (2.0 / 3.0, 1.0, 1.0)
        } else {
            (0.5, 2.0, 3.0)
        }
    }

    /// `(dT_s/dt, dR_s/dt)` per species at translational temperatures `tr` and rotational
    /// ones `rot` (module docs).
    pub fn rates(&self, tr: &[f64], rot: &[f64]) -> (Vec<f64>, Vec<f64>) {
        let ns = self.species();
        let (p_n, q, d_r) = self.geometry();
        let lam = self.lambda;
        let mut d_tr = vec![0.0; ns];
        let mut d_rot = vec![0.0; ns];
        for s in 0..ns {
            let (m_s, k_s) = (self.masses[s], self.inertia[s]);
            for t in 0..ns {
                let p = pair_index(ns, s, t);
                let (m_t, k_t) = (self.masses[t], self.inertia[t]);
                let mu = m_s * m_t / (m_s + m_t);
                let a = (1.0 + self.alpha[p]) * m_t / (m_s + m_t);
                let (i_s, i_t) = (k_s * m_s, k_t * m_t);
                let c = (1.0 + self.beta[p]) / (1.0 + i_s / mu + i_s / i_t);
                let ts = k_s * c;
                let s2 = tr[s] / m_s + tr[t] / m_t;
                let l = (tr[s] / m_s) / s2;
                let r_s = rot[s] / i_s;
                let v_w = r_s + rot[t] / i_t;
                let (m_hi, m_lo) = (moment(lam + 2.0, s2, self.d), moment(lam, s2, self.d));
                let w = self.fractions[t] * self.strength[p];
                let e_tr = (p_n * (0.5 * a * a - l * a) + (1.0 - p_n) * (0.5 * ts * ts - l * ts))
                    * m_hi
                    + 0.5 * ts * ts * q * v_w * m_lo;
                let e_rot =
                    (1.0 - p_n) * 0.5 * c * c * m_hi + (0.5 * c * c * v_w - c * r_s) * q * m_lo;
                d_tr[s] += w * m_s * e_tr;
                d_rot[s] += w * i_s * e_rot;
            }
            d_tr[s] = 2.0 / self.d as f64 * d_tr[s] + self.heating[s];
            d_rot[s] = 2.0 / d_r * d_rot[s] + self.heating_rot[s];
        }
        (d_tr, d_rot)
    }

    /// The cooling state (no noise) or the steady state (white noise) from equal
    /// temperatures: `(T_s / T, theta_s = R_s / T_s)` per species, `T = sum x_s T_s`. Followed
    /// in time (RK4, a twentieth of the collisions' fastest relaxation time per step; all
    /// temperatures divided by `T` after each step when cooling) until no ratio changes by more
    /// than 1e-13. `None` if that takes more than 10^6 steps.
    pub fn steady(&self) -> Option<(Vec<f64>, Vec<f64>)> {
        let ns = self.species();
        let temperature = |x: &[f64]| -> f64 { (0..ns).map(|s| self.fractions[s] * x[s]).sum() };
        let heating: Vec<f64> = self
            .heating
            .iter()
            .chain(&self.heating_rot)
            .copied()
            .collect();
        let last = super::steady::relax(
            vec![1.0; 2 * ns],
            |x| {
                let (a, b) = self.rates(&x[..ns], &x[ns..]);
                a.into_iter().chain(b).collect()
            },
            &heating,
            temperature,
            |x| {
                let t = temperature(x);
                (0..ns)
                    .map(|s| x[s] / t)
                    .chain((0..ns).map(|s| x[ns + s] / x[s]))
                    .collect()
            },
        )?;
        let (t, theta) = last.split_at(ns);
        Some((t.to_vec(), theta.to_vec()))
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::mixture::MaxwellianApproximation;
    use crate::rough::RoughApproximation;
    use gdsmc_core::geometry::{Disks, Geometry, Spheres};
    use gdsmc_core::mixture::PairLaw;
    use gdsmc_core::rng::seeded;
    use gdsmc_core::rough::RoughPairLaw;

    /// The rates are the core map's mean energy changes: unequal Maxwellians of each part
    /// (masses 1 and 3, inertias and temperatures all different), the impact direction of
    /// `G`, weight `|u|^lambda`; per species and part the mean of `E[|u|^lambda dE]` (400,000
    /// draws) against the module docs' formula (the rates per unit strength, one species
    /// `t` of mole fraction 1 as partner). 4 checks per parameter set, 3 sets, per
    /// dimension: held together at 99.9% (Bonferroni over 12, `gdsmc_stats::joint`).
    fn rates_match_the_pair_map<G: Geometry>(seed: u64, kappas: [f64; 2]) {
        let mut rng = seeded(seed);
        let d = G::CHOICE.d();
        let (m, k) = ([1.0, 3.0], kappas);
        let (tr, rot) = ([1.3, 0.6], [0.7, 1.1]);
        for (alpha, beta, lambda) in [(0.9, 0.0, 1.0), (0.7, 0.6, 1.0), (0.8, -0.4, 0.0)] {
            let law = if d == 2 {
                RoughPairLaw::for_disks(alpha, beta, k[0], k[1])
            } else {
                RoughPairLaw::new(alpha, beta, k[0], k[1])
            }
            .unwrap();
            let map = law.between(m[0], m[1]);
            // Species 0 against partners of species 1 and the other way round: the pair type
            // (0, 1) seen from each side, every other pair type absent (strength 0).
            let ma = RoughMixtureApproximation {
                d,
                fractions: vec![1.0, 1.0],
                masses: m.to_vec(),
                inertia: k.to_vec(),
                strength: vec![0.0, 1.0, 0.0],
                alpha: vec![alpha; 3],
                beta: vec![beta; 3],
                lambda,
                heating: vec![0.0; 2],
                heating_rot: vec![0.0; 2],
            };
            let draws = 400_000;
            let mut sums: Vec<Vec<f64>> = (0..4).map(|_| Vec::with_capacity(draws)).collect();
            for _ in 0..draws {
                let v1 = (tr[0] / m[0]).sqrt() * G::normal(&mut rng);
                let v2 = (tr[1] / m[1]).sqrt() * G::normal(&mut rng);
                let w1 = (rot[0] / (k[0] * m[0])).sqrt() * G::spin_normal(&mut rng);
                let w2 = (rot[1] / (k[1] * m[1])).sqrt() * G::spin_normal(&mut rng);
                let u = v1 - v2;
                let n = G::impact(u, &mut rng);
                let (a1, b1, a2, b2) = map.collide(v1, w1, v2, w2, n);
                let w = libm::pow(u.norm(), lambda);
                let de = [
                    0.5 * m[0] * (a1.norm2() - v1.norm2()),
                    0.5 * m[1] * (a2.norm2() - v2.norm2()),
                    0.5 * k[0] * m[0] * (b1.norm2() - w1.norm2()),
                    0.5 * k[1] * m[1] * (b2.norm2() - w2.norm2()),
                ];
                for (acc, x) in sums.iter_mut().zip(de) {
                    acc.push(w * x);
                }
            }
            let (d_tr, d_rot) = ma.rates(&tr, &rot);
            let d_r = if d == 2 { 1.0 } else { 3.0 };
            let want = [
                d_tr[0] * d as f64 / 2.0,
                d_tr[1] * d as f64 / 2.0,
                d_rot[0] * d_r / 2.0,
                d_rot[1] * d_r / 2.0,
            ];
            for (i, (s, want)) in sums.iter().zip(want).enumerate() {
                // Four parts in each of the three cases, held together (Bonferroni).
                let sample = gdsmc_stats::Sample::of(s);
                let (mean, h) = (sample.mean, sample.joint_ci(12));
                assert!(
                    (mean - want).abs() <= h,
                    "d {d} alpha {alpha} beta {beta} lambda {lambda} part {i}: {mean} vs {want} +- {h}"
                );
            }
        }
    }

    #[test]
    fn the_rates_are_the_pair_maps_mean_energy_changes() {
        rates_match_the_pair_map::<Spheres>(21, [0.4, 0.15]);
    }

    #[test]
    fn the_disk_rates_are_the_pair_maps_mean_energy_changes() {
        rates_match_the_pair_map::<Disks>(22, [0.5, 0.95]);
    }

    fn two(d: usize, alpha: f64, beta: f64, lambda: f64) -> RoughMixtureApproximation {
        RoughMixtureApproximation {
            d,
            fractions: vec![0.3, 0.7],
            masses: vec![1.0, 3.5],
            inertia: vec![0.4, if d == 2 { 0.9 } else { 0.2 }],
            strength: vec![1.0, 1.7, 2.3],
            alpha: vec![alpha, 0.8 * alpha, alpha],
            beta: vec![beta, beta, beta],
            lambda,
            heating: vec![0.0; 2],
            heating_rot: vec![0.0; 2],
        }
    }

    /// Elastic perfectly rough hard particles at one common temperature are in equilibrium:
    /// every rate vanishes (to rounding), in both dimensions, for unequal masses, inertias and
    /// strengths. A slip in any coefficient of the module docs breaks it; so does an unequal
    /// temperature (checked, so the test can fail).
    #[test]
    fn elastic_perfectly_rough_hard_particles_at_one_temperature_are_in_equilibrium() {
        for d in [2, 3] {
            let mut ma = two(d, 1.0, 1.0, 1.0);
            ma.alpha = vec![1.0; 3];
            let (a, b) = ma.rates(&[1.3, 1.3], &[1.3, 1.3]);
            for r in a.iter().chain(&b) {
                assert!(r.abs() < 1e-13, "d = {d}: {a:?} {b:?}");
            }
            let (a, _) = ma.rates(&[1.3, 1.3], &[1.0, 1.3]);
            assert!(a.iter().any(|r| r.abs() > 1e-3), "d = {d}: {a:?}");
        }
    }

    /// One species is the one-species approximation (its rates per unit strength), spheres and
    /// disks, any kernel exponent.
    #[test]
    fn one_species_is_the_rough_gas_approximation() {
        for (d, kappa) in [(3, 0.4), (2, 0.7)] {
            for lambda in [0.0, 0.5, 1.0] {
                let (alpha, beta, strength) = (0.8, 0.3, 0.6);
                let one = RoughApproximation::in_dimension(
                    d,
                    alpha,
                    beta,
                    kappa,
                    strength,
                    lambda,
                    [0.0, 0.0],
                );
                let mix = RoughMixtureApproximation {
                    d,
                    fractions: vec![1.0],
                    masses: vec![1.0],
                    inertia: vec![kappa],
                    strength: vec![4.0 * std::f64::consts::PI * strength],
                    alpha: vec![alpha],
                    beta: vec![beta],
                    lambda,
                    heating: vec![0.0],
                    heating_rot: vec![0.0],
                };
                let (t, r) = (1.7, 0.6);
                let (a, b) = mix.rates(&[t], &[r]);
                let (x, y) = one.rates(t, r);
                assert!((a[0] - x).abs() < 1e-12 * x.abs(), "{a:?} vs {x}");
                assert!((b[0] - y).abs() < 1e-12 * y.abs(), "{b:?} vs {y}");
            }
        }
    }

    /// `beta = -1` is the smooth mixture's approximation (spheres), whatever the rotation:
    /// `dT_s/dt = m_s d theta_s/dt`, and the rotation is left alone.
    #[test]
    fn beta_minus_one_is_the_smooth_mixture_approximation() {
        for lambda in [0.0, 1.0] {
            let ma = two(3, 0.7, -1.0, lambda);
            let smooth = MaxwellianApproximation {
                fractions: ma.fractions.clone(),
                masses: ma.masses.clone(),
                kappa: ma.strength.clone(),
                alpha: ma.alpha.clone(),
                lambda,
                beta: vec![0.0; 2],
            };
            let tr = [1.2, 0.7];
            let (a, b) = ma.rates(&tr, &[3.0, 0.1]);
            let theta: Vec<f64> = (0..2).map(|s| tr[s] / ma.masses[s]).collect();
            let r = smooth.rates(&theta);
            for s in 0..2 {
                let want = ma.masses[s] * r[s];
                assert!((a[s] - want).abs() < 1e-12 * want.abs(), "{a:?} vs {r:?}");
                assert_eq!(b[s], 0.0);
            }
        }
    }

    /// The cooling state of equal species is the one-species cooling state, and every part
    /// cools at one rate there.
    #[test]
    fn the_cooling_state_cools_every_part_at_one_rate() {
        let ma = two(3, 0.9, 0.0, 1.0);
        let (t, theta) = ma.steady().unwrap();
        let tr: Vec<f64> = t.clone();
        let rot: Vec<f64> = (0..2).map(|s| theta[s] * t[s]).collect();
        let (a, b) = ma.rates(&tr, &rot);
        let zeta: Vec<f64> = (0..2)
            .map(|s| a[s] / tr[s])
            .chain((0..2).map(|s| b[s] / rot[s]))
            .collect();
        for z in &zeta {
            assert!((z - zeta[0]).abs() < 1e-9 * zeta[0].abs(), "{zeta:?}");
        }
        let mut eq = two(3, 0.9, 0.0, 1.0);
        eq.masses = vec![2.0, 2.0];
        eq.inertia = vec![0.4, 0.4];
        eq.strength = vec![1.0, 1.0, 1.0];
        eq.alpha = vec![0.9; 3];
        let (t, theta) = eq.steady().unwrap();
        let one = RoughApproximation::new(0.9, 0.0, 0.4, 1.0, 1.0, [0.0, 0.0])
            .cooling_theta()
            .unwrap();
        for s in 0..2 {
            assert!((t[s] - 1.0).abs() < 1e-10, "{t:?}");
            assert!((theta[s] - one).abs() < 1e-9, "{theta:?} vs {one}");
        }
    }

    /// The heated steady state (white noise on translation and rotation) is where the rates
    /// vanish: against small fixed Euler steps followed to rest.
    #[test]
    fn the_heated_steady_state_is_where_the_rates_vanish() {
        for d in [2, 3] {
            let mut ma = two(d, 0.8, 0.3, 1.0);
            ma.heating = vec![4.0, 2.0];
            ma.heating_rot = vec![0.0, 1.0];
            let (r, theta) = ma.steady().unwrap();
            let (mut tr, mut rot) = (vec![1.0; 2], vec![1.0; 2]);
            for _ in 0..200_000 {
                let (a, b) = ma.rates(&tr, &rot);
                for s in 0..2 {
                    tr[s] += 1e-3 * a[s];
                    rot[s] += 1e-3 * b[s];
                }
            }
            let (a, b) = ma.rates(&tr, &rot);
            assert!(a.iter().chain(&b).all(|x| x.abs() < 1e-10), "{a:?} {b:?}");
            let mean = 0.3 * tr[0] + 0.7 * tr[1];
            for s in 0..2 {
                assert!((r[s] - tr[s] / mean).abs() < 1e-9, "{r:?} vs {tr:?}");
                assert!((theta[s] - rot[s] / tr[s]).abs() < 1e-9, "{theta:?}");
            }
        }
    }

    /// Elastic perfectly rough hard species (alpha = beta = 1) neither cool nor heat: their
    /// state is equilibrium, every ratio 1 (it was NaN: the steps grew without bound as the
    /// rates vanished). (Softer kernels have no equipartition: docs/rough.md.)
    #[test]
    fn the_elastic_perfectly_rough_mixture_is_at_equipartition() {
        for (d, lambda) in [(2, 1.0), (3, 1.0)] {
            let mut ma = two(d, 1.0, 1.0, lambda);
            ma.alpha = vec![1.0; 3];
            let (t, theta) = ma.steady().unwrap();
            for v in t.iter().chain(&theta) {
                assert!((v - 1.0).abs() < 1e-9, "d = {d}: {t:?} {theta:?}");
            }
        }
    }
}
