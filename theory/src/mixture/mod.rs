//! Exact second moments of an inelastic Maxwell mixture at finite particle number.
//!
//! For Maxwell pseudo-molecules every unordered pair of species `(s, t)` collides at the rate
//! `kappa_st / N` (`kappa_st = int B_st de = 4 pi gamma C_st`, the normalization of GRW
//! Section 3), whatever the velocities. The expected change of the sums
//! `A_s = sum_{i in s} |v_i|^2` and of the products `P_st = Q_s . Q_t` of the species momenta
//! `Q_s = sum_{i in s} v_i` under one collision (the map of `gdsmc_core::mixture::MassRatio`,
//! `e` uniform: `E[D] = a u`, `E|D|^2 = 2 a^2 |u|^2`, `a = (1 + alpha)/2`) is linear in the
//! same quantities, because the pair sums close:
//!
//! ```text
//! sum_{i in s, j in t} v_i . (v_i - v_j) = N_t A_s - P_st,
//! sum_{i in s, j in t} |v_i - v_j|^2     = N_t A_s + N_s A_t - 2 P_st,
//! sum_{i < j in s}     |v_i - v_j|^2     = N_s A_s - P_ss.
//! ```
//!
//! So `X = (A_s, P_st)` has expectations solving a linear system `dX/dt = M X` (derived in
//! the module's code comments; the one-species case is GRW (13) with `beta = 0`), solved here
//! by the matrix exponential. It is exact at every `N`: the process's own expectations, not
//! the Boltzmann limit; dropping the `P` terms (they are `1/N` against the `A` terms) gives the
//! Boltzmann limit, whose temperature ratio `T_1/T_2` tends to the cooling state's.
//!
//! The species temperature about the flow velocity `U = sum_r m_r Q_r / sum_r m_r N_r`
//! (Garzó and Dufty 1999, (6)) is linear in `X` too:
//! `3 N_s T_s / m_s = A_s - 2 sum_r m_r P_sr / M + N_s sum_{r,q} m_r m_q P_rq / M^2`.

use gdsmc_core::mixture::pair_index;
use gdsmc_core::physics::Momentum;

/// An inelastic Maxwell mixture with a Maxwellian start of zero mean.
#[derive(Clone, Debug, PartialEq)]
pub struct MaxwellMixture {
    /// Particles per species.
    pub counts: Vec<usize>,
    /// Masses.
    pub masses: Vec<f64>,
    /// `kappa_st = 4 pi gamma C_st` per pair type in the order `(0,0), (0,1), .., (1,1), ..`.
    pub kappa: Vec<f64>,
    /// Restitution per pair type (same order).
    pub alpha: Vec<f64>,
    /// Initial temperature of each species (velocity variance per component `T_s / m_s`).
    pub temperatures: Vec<f64>,
    /// White-noise strength of each species (GRW (18): every particle's `<|v|^2>` grows by
    /// `6 beta_s` per unit time, so `A_s` and `|Q_s|^2` by `6 beta_s N_s`); empty: none.
    pub beta: Vec<f64>,
    /// How the sample's momentum starts: independent draws, or each species' sample shifted
    /// onto the distribution's mean (zero here), which starts `P_st` at 0 and `A_s` at
    /// `3 (N_s - 1) T_s / m_s`.
    pub momentum: Momentum,
}

impl MaxwellMixture {
    fn species(&self) -> usize {
        self.counts.len()
    }

    /// Index of pair type `(s, t)` in either order.
    fn pair(&self, s: usize, t: usize) -> usize {
        pair_index(self.species(), s, t)
    }

    /// Index of `P_st` in the state vector (after the `S` entries `A_s`).
    fn p(&self, s: usize, t: usize) -> usize {
        self.species() + self.pair(s, t)
    }

    fn dim(&self) -> usize {
        let s = self.species();
        s + s * (s + 1) / 2
    }

    /// The generator `M` of `dX/dt = M X` (`large_n`: the Boltzmann limit, `P` terms dropped).
    fn generator(&self, large_n: bool) -> Vec<Vec<f64>> {
        let ns = self.species();
        let d = self.dim();
        let n: f64 = self.counts.iter().sum::<usize>() as f64;
        let cnt: Vec<f64> = self.counts.iter().map(|&c| c as f64).collect();
        let mut m = vec![vec![0.0; d]; d];
        let keep_p = if large_n { 0.0 } else { 1.0 };
        // mu(s, t) = m_t / (m_s + m_t): the share of D the s partner takes.
        let mu = |s: usize, t: usize| self.masses[t] / (self.masses[s] + self.masses[t]);
        for s in 0..ns {
            // dA_s/dt.
            let ss = self.pair(s, s);
            let (k, a) = (self.kappa[ss] / n, 0.5 * (1.0 + self.alpha[ss]));
            // Same-species pairs: -a (1 - a) (N_s A_s - P_ss).
            m[s][s] += -k * a * (1.0 - a) * cnt[s];
            m[s][self.p(s, s)] += k * a * (1.0 - a) * keep_p;
            for t in (0..ns).filter(|&t| t != s) {
                let st = self.pair(s, t);
                let (k, a, mt) = (self.kappa[st] / n, 0.5 * (1.0 + self.alpha[st]), mu(s, t));
                // -2 mu a (N_t A_s - P_st) + 2 mu^2 a^2 (N_t A_s + N_s A_t - 2 P_st).
                m[s][s] += k * (-2.0 * mt * a * cnt[t] + 2.0 * mt * mt * a * a * cnt[t]);
                m[s][t] += k * 2.0 * mt * mt * a * a * cnt[s];
                m[s][self.p(s, t)] += k * (2.0 * mt * a - 4.0 * mt * mt * a * a) * keep_p;
            }
        }
        if large_n {
            return m;
        }
        // dP_st/dt, s <= t. The drift of Q_s is sum_{r != s} -(kappa_sr/N) mu(s,r) a_sr
        // (N_r Q_s - N_s Q_r); P_st gains drift(Q_s).Q_t + Q_s.drift(Q_t) + E[dQ_s . dQ_t].
        for s in 0..ns {
            for t in s..ns {
                let row = self.p(s, t);
                for (x, y) in [(s, t), (t, s)] {
                    // drift(Q_x) . Q_y
                    for r in (0..ns).filter(|&r| r != x) {
                        let xr = self.pair(x, r);
                        let c = -(self.kappa[xr] / n) * mu(x, r) * 0.5 * (1.0 + self.alpha[xr]);
                        m[row][self.p(x, y)] += c * cnt[r];
                        m[row][self.p(r, y)] -= c * cnt[x];
                    }
                }
                if s != t {
                    // Pairs (i in s, j in t): dQ_s . dQ_t = -mu_s mu_t |D|^2, E = -2 mu_s mu_t a^2 |u|^2.
                    let st = self.pair(s, t);
                    let (k, a) = (self.kappa[st] / n, 0.5 * (1.0 + self.alpha[st]));
                    let c = -2.0 * mu(s, t) * mu(t, s) * a * a * k;
                    m[row][s] += c * cnt[t];
                    m[row][t] += c * cnt[s];
                    m[row][row] += -2.0 * c;
                } else {
                    // |dQ_s|^2 over pairs (i in s, j in r != s): 2 mu(s,r)^2 a^2 |u|^2.
                    for r in (0..ns).filter(|&r| r != s) {
                        let sr = self.pair(s, r);
                        let (k, a) = (self.kappa[sr] / n, 0.5 * (1.0 + self.alpha[sr]));
                        let c = 2.0 * mu(s, r) * mu(s, r) * a * a * k;
                        m[row][s] += c * cnt[r];
                        m[row][r] += c * cnt[s];
                        m[row][self.p(s, r)] += -2.0 * c;
                    }
                }
            }
        }
        m
    }

    /// The expected state `X(0)`: drawn, `E A_s = E |Q_s|^2 = 3 N_s T_s / m_s`, `E P_st = 0`
    /// (`s != t`); exact momentum, `Q_s = 0`, so `P_st = 0` and `E A_s = 3 (N_s - 1) T_s / m_s`
    /// (the sum of squares about the sample's mean).
    fn initial(&self) -> Vec<f64> {
        let mut x = vec![0.0; self.dim()];
        for s in 0..self.species() {
            let per = 3.0 * self.temperatures[s] / self.masses[s];
            let n = self.counts[s] as f64;
            match self.momentum {
                Momentum::Drawn => {
                    x[s] = n * per;
                    x[self.p(s, s)] = n * per;
                }
                Momentum::Exact => x[s] = (n - 1.0) * per,
            }
        }
        x
    }

    /// The expected species temperatures `E[T_s](t)` about the flow velocity, at finite `N`
    /// (exact) or in the Boltzmann limit (`large_n`, where the flow velocity vanishes).
    pub fn temperatures_at(&self, t: f64, large_n: bool) -> Vec<f64> {
        // The white noise makes the system affine, dX/dt = M X + b: carried as a constant
        // last component of the state.
        let d = self.dim();
        let mut m = self.generator(large_n);
        for row in &mut m {
            row.push(0.0);
        }
        m.push(vec![0.0; d + 1]);
        for (row, rate) in self.noise(large_n).into_iter().enumerate() {
            m[row][d] += rate;
        }
        let mut x0 = self.initial();
        x0.push(1.0);
        let x = apply(&expm(&m, t), &x0);
        self.temperatures_of(&x, large_n)
    }

    /// The expected species temperatures of RW's splittings (RW Algorithms 1, 2) with step `dt`
    /// at the grid time `t = m dt`, at finite `N`: a collision step of length `h` multiplies
    /// `E X` by `exp(M h)` (the collisions alone, as in [`Self::temperatures_at`]), and a kick
    /// of `dt` adds `b dt` whatever the state (white noise adds `6 beta_s N_s dt` to `E A_s` and
    /// `E |Q_s|^2`, nothing to the cross products). Euler: `X' = e^{M dt} X + b dt`; Strang:
    /// `X' = e^{M dt/2} (e^{M dt/2} X + b dt)`.
    pub fn splitting_temperatures_at(&self, t: f64, dt: f64, strang: bool) -> Vec<f64> {
        let m = self.generator(false);
        let steps = (t / dt).round() as usize;
        let kick: Vec<f64> = self.noise(false).iter().map(|b| b * dt).collect();
        let add = |x: Vec<f64>| -> Vec<f64> { x.iter().zip(&kick).map(|(a, b)| a + b).collect() };
        let mut x = self.initial();
        if strang {
            let half = expm(&m, 0.5 * dt);
            for _ in 0..steps {
                x = apply(&half, &add(apply(&half, &x)));
            }
        } else {
            let full = expm(&m, dt);
            for _ in 0..steps {
                x = add(apply(&full, &x));
            }
        }
        self.temperatures_of(&x, false)
    }

    /// `b` of `dX/dt = M X + b`: the white noise's growth of each state entry per unit time.
    fn noise(&self, large_n: bool) -> Vec<f64> {
        let mut b = vec![0.0; self.dim()];
        for (s, &beta) in self.beta.iter().enumerate() {
            let rate = 6.0 * beta * self.counts[s] as f64;
            b[s] += rate;
            if !large_n {
                b[self.p(s, s)] += rate;
            }
        }
        b
    }

    /// The species temperatures about the flow velocity of the expected state `x` (module
    /// docs; `large_n`: the flow velocity's terms dropped).
    fn temperatures_of(&self, x: &[f64], large_n: bool) -> Vec<f64> {
        let ns = self.species();
        let total: f64 = (0..ns)
            .map(|r| self.masses[r] * self.counts[r] as f64)
            .sum();
        (0..ns)
            .map(|s| {
                let ns_f = self.counts[s] as f64;
                let mut sum = x[s];
                if !large_n {
                    for r in 0..ns {
                        sum -= 2.0 * self.masses[r] * x[self.p(s, r)] / total;
                        for q in 0..ns {
                            sum += ns_f * self.masses[r] * self.masses[q] * x[self.p(r, q)]
                                / (total * total);
                        }
                    }
                }
                self.masses[s] * sum / (3.0 * ns_f)
            })
            .collect()
    }
}

fn apply(m: &[Vec<f64>], x: &[f64]) -> Vec<f64> {
    m.iter()
        .map(|row| row.iter().zip(x).map(|(a, b)| a * b).sum())
        .collect()
}

fn matmul(a: &[Vec<f64>], b: &[Vec<f64>]) -> Vec<Vec<f64>> {
    let d = a.len();
    (0..d)
        .map(|i| {
            (0..d)
                .map(|j| (0..d).map(|k| a[i][k] * b[k][j]).sum())
                .collect()
        })
        .collect()
}

/// `exp(M t)` by scaling and squaring with a Taylor series (the norm scaled below 1/2, 24
/// terms: truncation far below double rounding).
fn expm(m: &[Vec<f64>], t: f64) -> Vec<Vec<f64>> {
    let d = m.len();
    let norm = m
        .iter()
        .map(|r| r.iter().map(|x| x.abs()).sum::<f64>())
        .fold(0.0, f64::max)
        * t.abs();
    let squarings = if norm > 0.5 {
        libm::log2(norm / 0.5).ceil() as u32
    } else {
        0
    };
    let h = t / f64::from(2u32).powi(squarings as i32);
    let a: Vec<Vec<f64>> = m
        .iter()
        .map(|r| r.iter().map(|x| x * h).collect())
        .collect();
    let identity: Vec<Vec<f64>> = (0..d)
        .map(|i| (0..d).map(|j| if i == j { 1.0 } else { 0.0 }).collect())
        .collect();
    let mut result = identity.clone();
    let mut term = identity;
    for k in 1..=24 {
        term = matmul(&term, &a);
        for (row, trow) in result.iter_mut().zip(&term) {
            for (x, y) in row.iter_mut().zip(trow) {
                *x += y / factorial(k);
            }
        }
    }
    for _ in 0..squarings {
        result = matmul(&result, &result);
    }
    result
}

fn factorial(k: u32) -> f64 {
    (1..=k).map(f64::from).product()
}

mod approximation;

pub use approximation::MaxwellianApproximation;

#[cfg(test)]
mod tests;
