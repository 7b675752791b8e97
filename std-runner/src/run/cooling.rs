//! The cooling rates of a mixture's species, `zeta_s = -(dT_s/dt)/T_s` from the collisions,
//! estimated at an observation from random pairs (Garzó and Dufty 1999 define them; here they
//! are measured, not approximated).
//!
//! A collision of particle `i` (species `s`) with `j` (species `t`) changes
//! `|v_i - U|^2` by, on average over the uniform direction `e` (the map of
//! `gdsmc_core::mixture::MassRatio`, `E[D] = a u`, `E|D|^2 = 2 a^2 |u|^2`):
//!
//! ```text
//! g_st(i, j) = -2 mu_t a (v_i - U) . u + 2 mu_t^2 a^2 |u|^2,    u = v_i - v_j, a = (1 + alpha_st)/2,
//! ```
//!
//! and the pair collides at `int B_st de / N` (GRW Section 3), so
//! `dT_s/dt = m_s / (3 N_s N) sum_t sum_{i in s, j in t, j != i} int B_st de g_st(i, j)`:
//! exact given the velocities; the double sum is estimated from `K` uniform pairs per species
//! pair (so its expectation over the pairs is the exact rate). The flow velocity `U` is kept by
//! collisions, so the rate of `T_s` about it is the collisions' alone.

use gdsmc_core::mixture::Species;
use gdsmc_core::particles::Particles;
use gdsmc_core::rng::{Rng, uniform_index};
use gdsmc_core::vec3::Vec3;
use gdsmc_theory::pairs::pair_kernels;

/// The collision data of one pair type.
#[derive(Clone, Copy, Debug)]
struct Pair {
    /// `4 pi gamma C ((d_s + d_t)/2)^2`: `int B de = strength |u|^lambda`.
    strength: f64,
    /// `(1 + alpha_st)/2`.
    a: f64,
}

/// A mixture's collision data for the cooling-rate estimate.
#[derive(Clone, Debug)]
pub struct CoolingRates {
    species: Species,
    lambda: f64,
    pairs: Vec<Pair>,
}

impl CoolingRates {
    /// The kernel's exponent: a rate of velocities stored rescaled by `scale` is
    /// `scale^lambda` times the stored one.
    pub fn lambda(&self) -> f64 {
        self.lambda
    }

    /// The rates of a mixture scene (`None` for one species).
    pub fn new(scene: &crate::scene::Scene) -> Option<Self> {
        let ph = scene.physics();
        let species = *scene.model().species()?;
        // The estimate's rates are `strength |u|^lambda`: a power-law kernel's.
        let lambda = ph.kernel.exponent()?;
        let pairs = pair_kernels(ph, &species)?
            .into_iter()
            .map(|(strength, alpha)| Pair {
                strength,
                a: 0.5 * (1.0 + alpha),
            })
            .collect();
        Some(CoolingRates {
            species,
            lambda,
            pairs,
        })
    }

    /// `(T_s, dT_s/dt)` of every species from the velocities of `p` (all at one time), with
    /// `samples` random pairs per species pair drawn from `rng`; in the units of `p`'s
    /// velocities for a kernel `|u|^lambda` (a gas stored rescaled by `scale` has physical
    /// rates `scale^lambda` times these).
    pub fn rates<R: Rng + ?Sized>(
        &self,
        p: &Particles<'_>,
        samples: u64,
        rng: &mut R,
    ) -> Vec<(f64, f64)> {
        let sp = &self.species;
        let n = sp.total() as f64;
        let (mut flow, mut mass) = (Vec3::ZERO, 0.0);
        for s in 0..sp.len() {
            for i in sp.range(s) {
                flow += sp.mass(s) * p.velocity(i);
            }
            mass += sp.mass(s) * sp.count(s) as f64;
        }
        let u_flow = (1.0 / mass) * flow;
        (0..sp.len())
            .map(|s| {
                let ns = sp.count(s);
                let t_s = sp.mass(s) / (3.0 * ns as f64)
                    * sp.range(s)
                        .map(|i| (p.velocity(i) - u_flow).norm2())
                        .sum::<f64>();
                let mut sum = 0.0;
                for t in 0..sp.len() {
                    let others = if s == t { ns - 1 } else { sp.count(t) };
                    if others == 0 || samples == 0 {
                        continue;
                    }
                    let pair = self.pairs[sp.pair_index(s, t)];
                    let mu = sp.mass(t) / (sp.mass(s) + sp.mass(t));
                    let mut g = 0.0;
                    for _ in 0..samples {
                        let a = uniform_index(rng, ns);
                        let i = sp.offset(s) + a;
                        let j = if s == t {
                            let mut b = uniform_index(rng, ns - 1);
                            if b >= a {
                                b += 1;
                            }
                            sp.offset(s) + b
                        } else {
                            sp.offset(t) + uniform_index(rng, others)
                        };
                        let u = p.velocity(i) - p.velocity(j);
                        let u2 = u.norm2();
                        let rate = pair.strength * libm::pow(u2.sqrt(), self.lambda);
                        g += rate
                            * (-2.0 * mu * pair.a * (p.velocity(i) - u_flow).dot(u)
                                + 2.0 * mu * mu * pair.a * pair.a * u2);
                    }
                    sum += ns as f64 * others as f64 * g / samples as f64;
                }
                (t_s, sp.mass(s) / (3.0 * ns as f64 * n) * sum)
            })
            .collect()
    }
}
