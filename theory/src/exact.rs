//! Exact reference solutions, each with its paper and equation.

pub use crate::maxwell_temperature::MaxwellTemperature;
use crate::mutation::{Reference, mutated};

/// BRS (14)-(17): the exact bulk velocity and temperature of a Maxwell-kernel granular gas in
/// a Maxwellian host medium (`B_1 = C_1`, `B_2 = C_2`, constant restitution `e`, unit grain mass,
/// grain density `rho = 1`). BRS writes them in the time `rho^B C_1 t`; here `t` is the
/// simulation's own time, so every rate carries the factor `s = rho^B C_1`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct HostMediumMaxwell {
    /// Initial bulk velocity `u_0`.
    pub u0: [f64; 3],
    /// Background drift `u^B`.
    pub ub: [f64; 3],
    /// Initial temperature (about the bulk velocity).
    pub t0: f64,
    /// Background temperature `T^B`.
    pub tb: f64,
    /// Mass ratio `alpha = m^B / (1 + m^B)` (BRS (3)).
    pub alpha: f64,
    /// `s = rho^B C_1`.
    pub s: f64,
    /// `Kn = C_2 / (rho^B C_1)` (BRS (12) with `rho = 1`).
    pub kn: f64,
    /// Restitution coefficient `e`.
    pub e: f64,
    /// The dimension `d` (3: BRS's spheres; 2: disks, whose kernels keep the total rates and
    /// isotropic scattering, so only the flow energy `A` is shared over `d` components).
    pub d: f64,
}

impl HostMediumMaxwell {
    /// The bulk velocity BRS (14): `u^B + (u_0 - u^B) exp(-4 pi alpha s t)`.
    pub fn bulk(&self, t: f64) -> [f64; 3] {
        let f = libm::exp(-4.0 * std::f64::consts::PI * self.alpha * self.s * t);
        std::array::from_fn(|k| self.ub[k] + (self.u0[k] - self.ub[k]) * f)
    }

    /// `A, B, C, D` of BRS (17) (`A = 8/3 pi alpha^2 |u_0 - u^B|^2` for spheres: the energy of
    /// the relative flow, turned into heat and shared over the `d` components, so `8/d` in
    /// general; B, C and D are per component and hold in any `d`).
    pub fn coefficients(&self) -> (f64, f64, f64, f64) {
        let pi = std::f64::consts::PI;
        let a = self.alpha;
        let du2: f64 = (0..3).map(|k| (self.u0[k] - self.ub[k]).powi(2)).sum();
        (
            8.0 / self.d * pi * a * a * du2,
            8.0 * pi * a,
            8.0 * pi * a * (1.0 - a) + pi * self.kn * (1.0 - self.e * self.e),
            8.0 * pi * a * (1.0 - a) * self.tb,
        )
    }

    /// The temperature BRS (15) (or (16) when `B = C`).
    pub fn temperature(&self, t: f64) -> f64 {
        let (a, b, c, d) = self.coefficients();
        let x = self.s * t;
        let temperature = if (b - c).abs() < 1e-12 * b.abs().max(c.abs()) {
            self.t0 * libm::exp(-b * x)
                + d / b * (1.0 - libm::exp(-b * x))
                + a * x * libm::exp(-b * x)
        } else {
            self.t0 * libm::exp(-c * x)
                + d / c * (1.0 - libm::exp(-c * x))
                + a / (c - b) * (libm::exp(-b * x) - libm::exp(-c * x))
        };
        mutated(Reference::HostMediumTemperature, temperature)
    }

    /// The equilibrium temperature BRS (18), `T* = D / C`.
    pub fn equilibrium(&self) -> f64 {
        let (_, _, c, d) = self.coefficients();
        d / c
    }

    /// The exact mean over ensembles of the bulk temperature `T_bulk,n = Q / (d n)`,
    /// `Q = sum |v_i - V|^2`, of an `n`-grain system started from `n` independent draws of
    /// `f_0` (mean `u_0`, temperature `T_0`): BRS (15) at finite `n`. At `t = 0` it is
    /// `(1 - 1/n) T_0`; as `n -> infinity` it tends to [`Self::temperature`].
    ///
    /// Derivation (Maxwell kernels: every collision rate is independent of the velocities, so
    /// second moments close). With `w_i = v_i - u^B`, `R = sum |w_i|^2`, `W = sum w_i`,
    /// `Q = R - |W|^2 / n`, and `x = s t`:
    /// - a grain's background collisions (BRS (2)-(4)) move its mean `E w_i` at rate
    ///   `4 pi alpha` towards 0 (BRS (14)) and its `E |w_i|^2` at rate `b = 8 pi alpha
    ///   (1 - alpha)` towards `d T^B` (the single-grain form of BRS (15)-(17): the flow term
    ///   `A` is the part of `|w|^2` carried by the mean); they act on each grain alone, so a
    ///   product `E w_i . w_j` (`i != j`) decays at `2 x 4 pi alpha`. Summed:
    ///   `dE R/dx = -b (E R - n d T^B)` and
    ///   `dE|W|^2/dx = -b (E R - n d T^B) - 8 pi alpha (E|W|^2 - E R)`;
    /// - grain-grain collisions keep `W` and, per unit time, take `k E Q` from `E R`,
    ///   `k = pi C_2 (1 - e^2) = s pi Kn (1 - e^2)` (as for the heated gas,
    ///   [`MaxwellTemperature::finite_n_bulk_mean`]).
    ///
    /// So `X = E R`, `Y = E |W|^2` obey the linear system
    /// `dX/dt = -(s b + k) X + (k / n) Y + s b n d T^B`,
    /// `dY/dt = 8 pi alpha^2 s X - 8 pi alpha s Y + s b n d T^B`,
    /// from `X_0 = n (d T_0 + |u_0 - u^B|^2)`, `Y_0 = n d T_0 + n^2 |u_0 - u^B|^2`, solved here
    /// in closed form (two real eigenvalues: the off-diagonal terms are positive), and
    /// `E T_bulk,n = (X - Y / n) / (d n)`. Letting `n -> infinity` with `Y / n^2 -> |u - u^B|^2`
    /// gives BRS (15) back, `A`, `B`, `C`, `D` of BRS (17) included.
    pub fn finite_n_bulk_mean(&self, n: usize, t: f64) -> f64 {
        let pi = std::f64::consts::PI;
        let (a, s, d, nf) = (self.alpha, self.s, self.d, n as f64);
        let b = 8.0 * pi * a * (1.0 - a);
        let k = s * pi * self.kn * (1.0 - self.e * self.e);
        let flow: f64 = (0..3).map(|c| (self.u0[c] - self.ub[c]).powi(2)).sum();
        // d/dt (X, Y) = M (X, Y) + f.
        let m = [
            [-(s * b + k), k / nf],
            [8.0 * pi * a * a * s, -8.0 * pi * a * s],
        ];
        let f = s * b * nf * d * self.tb;
        let det = m[0][0] * m[1][1] - m[0][1] * m[1][0];
        // The fixed point M u* = -(f, f).
        let star = [
            (-f * m[1][1] + f * m[0][1]) / det,
            (-f * m[0][0] + f * m[1][0]) / det,
        ];
        let start = [nf * (d * self.t0 + flow), nf * d * self.t0 + nf * nf * flow];
        let dev = [start[0] - star[0], start[1] - star[1]];
        // exp(M t) by its eigenvalues l1 > l2: (e^{l1 t} (M - l2) - e^{l2 t} (M - l1)) / (l1 - l2).
        let half_trace = 0.5 * (m[0][0] + m[1][1]);
        let root = (half_trace * half_trace - det).max(0.0).sqrt();
        let (l1, l2) = (half_trace + root, half_trace - root);
        let (e1, e2) = (libm::exp(l1 * t), libm::exp(l2 * t));
        let apply = |row: usize| -> f64 {
            let mut out = 0.0;
            for (col, dv) in dev.iter().enumerate() {
                let id = if row == col { 1.0 } else { 0.0 };
                let entry = if root > 1e-12 * half_trace.abs() {
                    (e1 * (m[row][col] - l2 * id) - e2 * (m[row][col] - l1 * id)) / (l1 - l2)
                } else {
                    e1 * (id + (m[row][col] - l1 * id) * t)
                };
                out += entry * dv;
            }
            out
        };
        let (x, y) = (star[0] + apply(0), star[1] + apply(1));
        mutated(Reference::HostMediumFiniteN, (x - y / nf) / (d * nf))
    }
}

/// The Sonine estimates of the fourth cumulant `a2(alpha)` of MS: in `d` dimensions where MS
/// give them so (`_in`), for `d = 3` otherwise.
pub mod sonine {
    const D: f64 = 3.0;

    /// MS (5): the homogeneous cooling state and the Gaussian thermostat (van Noije, Ernst).
    pub fn a2_cooling_5(a: f64) -> f64 {
        a2_cooling_in(D, a)
    }

    /// MS (5) in `d` dimensions, as van Noije and Ernst (1998) give it for hard spheres
    /// (`d = 3`) and disks (`d = 2`): `16 (1 - a)(1 - 2a^2) / (9 + 24d - a(41 - 8d) +
    /// 30 (1 - a) a^2)`.
    pub fn a2_cooling_in(d: f64, a: f64) -> f64 {
        16.0 * (1.0 - a) * (1.0 - 2.0 * a * a)
            / (9.0 + 24.0 * d - a * (41.0 - 8.0 * d) + 30.0 * (1.0 - a) * a * a)
    }
    /// MS (10): the stochastic (white-noise) thermostat.
    pub fn a2_white_noise_10(a: f64) -> f64 {
        a2_white_noise_10_in(D, a)
    }
    /// MS (10) in `d` dimensions (MS write it for any `d`; van Noije and Ernst 1998).
    pub fn a2_white_noise_10_in(d: f64, a: f64) -> f64 {
        16.0 * (1.0 - a) * (1.0 - 2.0 * a * a)
            / (73.0 + 56.0 * d - 3.0 * a * (35.0 + 8.0 * d) + 30.0 * (1.0 - a) * a * a)
    }
    /// MS (32): the stochastic thermostat, the other linearization.
    pub fn a2_white_noise_32(a: f64) -> f64 {
        a2_white_noise_32_in(D, a)
    }
    /// MS (32) in `d` dimensions.
    pub fn a2_white_noise_32_in(d: f64, a: f64) -> f64 {
        4.0 * (1.0 - a) * (1.0 - 2.0 * a * a)
            / (19.0 + 14.0 * d - 3.0 * a * (9.0 + 2.0 * d) + 6.0 * (1.0 - a) * a * a)
    }
    /// MS (40): the Gaussian thermostat, better than (5) for alpha < 0.5.
    pub fn a2_gaussian_40(a: f64) -> f64 {
        a2_gaussian_40_in(D, a)
    }
    /// MS (40) in `d` dimensions.
    pub fn a2_gaussian_40_in(d: f64, a: f64) -> f64 {
        16.0 * (1.0 - a) * (1.0 - 2.0 * a * a)
            / (25.0 + 24.0 * d - a * (57.0 - 8.0 * d) - 2.0 * (1.0 - a) * a * a)
    }
    /// MS (50): the constant-force thermostat (about 20% too small in magnitude, MS).
    pub fn a2_constant_force_50(a: f64) -> f64 {
        a2_constant_force_50_in(D, a)
    }
    /// MS (50) in `d` dimensions.
    pub fn a2_constant_force_50_in(d: f64, a: f64) -> f64 {
        -16.0 * (1.0 - a) * (1.0 + 2.0 * a * a)
            / (63.0 + 40.0 * d - a * (95.0 + 8.0 * d) + 30.0 * (1.0 - a) * a * a)
    }
    /// MS (76): the constant-force thermostat, improved.
    pub fn a2_constant_force_76(a: f64) -> f64 {
        -240.0 * (1.0 - a) * (1.0 + 2.0 * a * a) / (1957.0 - 1125.0 * a + 390.0 * (1.0 - a) * a * a)
    }
    /// `mu_2^(0) = pi^{(d-1)/2} / (sqrt(2) Gamma(d/2)) (1 - alpha^2) = sqrt(2 pi)(1 - alpha^2)`,
    /// MS (27).
    pub fn mu2_maxwellian(a: f64) -> f64 {
        use crate::mutation::{Reference, mutated};
        mutated(
            Reference::MaxwellianMoments,
            (2.0 * std::f64::consts::PI).sqrt() * (1.0 - a * a),
        )
    }
    /// `mu_4^(0) = (d + 3/2 + alpha^2) mu_2^(0)`, MS (29).
    pub fn mu4_maxwellian(a: f64) -> f64 {
        (D + 1.5 + a * a) * mu2_maxwellian(a)
    }
}

/// The high-energy tails of MS Section 2 (hard spheres, `d = 3`) and the reference shapes
/// against which MS plot the reduced distribution: the Maxwellian shells and the Sonine
/// polynomial `S_2`.
pub mod tail {
    use std::f64::consts::PI;

    /// `beta_1` of MS (A.7) for `d = 3`: `pi Gamma(1) / Gamma(2) = pi`.
    pub const BETA_1: f64 = PI;

    /// MS (36), white noise: `f(c) ~ K exp(-A c^{3/2})`, `A = (2/3) (2 d beta_1 / mu_2)^{1/2}`.
    pub fn a_white_noise_36(mu2: f64) -> f64 {
        2.0 / 3.0 * (6.0 * BETA_1 / mu2).sqrt()
    }

    /// MS (42), Gaussian thermostat (and the cooling state): `f(c) ~ K exp(-A c)`,
    /// `A = d beta_1 / mu_2`.
    pub fn a_gaussian_42(mu2: f64) -> f64 {
        3.0 * BETA_1 / mu2
    }

    /// MS (52), constant force: `f(c) ~ K exp(-A' c^2)`, `A' = beta_1 <c> / mu_2` (MS find the
    /// fitted amplitude below this, MS (54)).
    pub fn a_constant_force_52(mu2: f64, c_mean: f64) -> f64 {
        BETA_1 * c_mean / mu2
    }

    /// The Sonine polynomial `S_2(x) = x^2/2 - 5x/2 + 15/8` (`d = 3`), MS (24)-(25); MS plot
    /// `Delta(c)` against `S_2(c^2)`.
    pub fn sonine_s2(x: f64) -> f64 {
        sonine_s2_in(3, x)
    }

    /// The Sonine polynomial of `d` dimensions, `S_2(x) = x^2/2 - (d + 2) x/2 + d (d + 2)/8`
    /// (MS (24) with `d/2 - 1` for `1/2`; disks: `x^2/2 - 2 x + 1`).
    pub fn sonine_s2_in(d: usize, x: f64) -> f64 {
        let d = d as f64;
        0.5 * x * x - 0.5 * (d + 2.0) * x + d * (d + 2.0) / 8.0
    }

    /// `phi(c) = pi^{-3/2} exp(-c^2)`, the reduced Maxwellian of MS.
    pub fn phi(c: f64) -> f64 {
        libm::exp(-c * c) / libm::pow(PI, 1.5)
    }

    /// The volume of the spherical shell `a <= |v| < b`, `(4/3) pi (b^3 - a^3)`.
    pub fn shell_volume(a: f64, b: f64) -> f64 {
        4.0 / 3.0 * PI * (b.powi(3) - a.powi(3))
    }

    /// The volume of the shell `a <= |v| < b` in `d` dimensions: [`shell_volume`] for 3, the
    /// ring's area `pi (b^2 - a^2)` for 2 (disks).
    pub fn shell_volume_in(d: usize, a: f64, b: f64) -> f64 {
        if d == 2 {
            PI * (b * b - a * a)
        } else {
            shell_volume(a, b)
        }
    }

    /// The weight of the reduced Maxwellian of `d` dimensions in the shell `a <= |c| < b`:
    /// [`phi_shell`] for 3, `exp(-a^2) - exp(-b^2)` for 2 (density `exp(-c^2)/pi`).
    pub fn phi_shell_in(d: usize, a: f64, b: f64) -> f64 {
        if d == 2 {
            libm::exp(-a * a) - libm::exp(-b * b)
        } else {
            phi_shell(a, b)
        }
    }

    /// The weight of `phi` in the shell `a <= |c| < b`: `F(b) - F(a)`,
    /// `F(c) = erf(c) - 2 c exp(-c^2) / sqrt(pi)` (exact; `b` may be infinite).
    pub fn phi_shell(a: f64, b: f64) -> f64 {
        let f = |c: f64| {
            if c.is_infinite() {
                1.0
            } else {
                libm::erf(c) - 2.0 * c * libm::exp(-c * c) / PI.sqrt()
            }
        };
        f(b) - f(a)
    }

    /// The weight of the normal law of mean `u` and variance `t` (a Maxwellian's velocity
    /// component, unit mass) in `[a, b)`.
    pub fn normal_bin(u: f64, t: f64, a: f64, b: f64) -> f64 {
        let s = (2.0 * t).sqrt();
        0.5 * (libm::erf((b - u) / s) - libm::erf((a - u) / s))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// BRS Example 1's parameters (u_0 = (1, 0, 0) about a resting host medium).
    fn example1() -> HostMediumMaxwell {
        HostMediumMaxwell {
            u0: [1.0, 0.0, 0.0],
            ub: [0.0; 3],
            t0: 1.0,
            tb: 0.5,
            alpha: 0.5,
            s: 0.1,
            kn: 2.0,
            e: 0.5,
            d: 3.0,
        }
    }

    /// The finite-n mean starts at (1 - 1/n) T_0 and tends to BRS (15) as n grows: at n = 1e9
    /// within 1e-8 relative at every time (the O(1/n) terms are 1e-9).
    #[test]
    fn finite_n_mean_starts_low_and_tends_to_brs_15() {
        let h = example1();
        for n in [4usize, 16, 1024] {
            let t0 = h.finite_n_bulk_mean(n, 0.0);
            assert!((t0 - (1.0 - 1.0 / n as f64) * h.t0).abs() < 1e-12, "{t0}");
        }
        for i in 0..=40 {
            let t = 0.5 * i as f64;
            let (big, limit) = (h.finite_n_bulk_mean(1_000_000_000, t), h.temperature(t));
            assert!(
                (big / limit - 1.0).abs() < 1e-8,
                "t = {t}: {big} against {limit}"
            );
        }
        // The equilibrium at finite n lies below BRS (18)'s, by O(1/n).
        let eq4 = h.finite_n_bulk_mean(4, 1e4);
        assert!(
            eq4 < h.equilibrium() && eq4 > 0.5 * h.equilibrium(),
            "{eq4}"
        );
    }
}
