//! The exact initial cooling rate `dT/dt` at `t = 0` of a gas under the impact-speed law
//! BRS (9)-(10), started from a Maxwellian: the check that the collision maps give the law the
//! true normal impact speed.
//!
//! Derivation (unit mass, `n` particles with independent Maxwellian velocities of temperature
//! `T0`; a rough gas's rim velocities independent Maxwellians of temperature `T_rot`, each
//! component of variance `T_rot / kappa`). A pair collides at `K |g|^lambda / n`, `K = 4 pi
//! gamma C` (GRW (5) with the total pair rate of `crate`'s kernels, both dimensions), so
//! with `T = (2/(d n)) sum |v|^2/2`
//!
//! ```text
//! dT/dt (0) = K (n - 1)/(d n) E[ |g|^lambda dE_tr ],      g = v1 - v2 ~ N(0, 2 T0 I_d),
//! ```
//!
//! exact at every `n` (the expectation over the initial draw). A collision at unit normal `n`
//! with normal share `s = (g_hat . n)^2` changes the pair's translational energy by
//! `dv . g + |dv|^2` with `dv = -eta_n g_n - eta_t g_t` (the rough map's impulse, rough/map.rs;
//! `eta_t = 0` for smooth particles), so on average over the spins
//!
//! ```text
//! E dE_tr = -eta_n (1 - eta_n) s |g|^2 - eta_t (1 - eta_t) (1 - s) |g|^2
//!           + eta_t^2 2 (d - 1) T_rot / kappa,          eta_n = (1 + alpha)/2,
//! ```
//!
//! `alpha = 1 - 2 beta_0 (|g| sqrt(s))^delta` clamped to `[0, 1]` (BRS (9) at the true normal
//! speed `|g . n| = |g| sqrt(s)`). The law of `s` is the impact parameter's: hard spheres
//! (and any kernel in `d = 3`, whose isotropic scattering is the hard-sphere impact law)
//! `s = 1 - b^2` with `b^2` uniform, so `s` uniform on `(0, 1)`; hard disks `b` uniform on
//! `(-1, 1)`, `s = 1 - b^2`; pseudo-Maxwell and VHS disks scatter isotropically, `e` at an angle
//! `theta` uniform from `g_hat`, so `s = sin^2(theta/2)`; a rough disk of any kernel has the
//! hard-disk impact law. Each is written as `s(x)` of one uniform `x` and the double integral
//! over `|g|` and `x` is done by Simpson's rule.

/// How the pair's collision direction is drawn, which sets the law of the normal share
/// `s = (g_hat . n)^2` (module docs).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Impacts {
    /// `s` uniform on (0, 1): every kernel in `d = 3`.
    Spheres,
    /// The impact parameter `b` uniform on (-1, 1), `s = 1 - b^2`: hard disks, and rough disks
    /// of any kernel.
    HardDisks,
    /// The scattering direction uniform on the circle, `s = sin^2(theta / 2)`: smooth Maxwell
    /// and VHS disks.
    IsotropicDisks,
}

impl Impacts {
    /// The normal share `s` at the uniform variable `x` in (0, 1).
    fn share(self, x: f64) -> f64 {
        match self {
            Impacts::Spheres => x,
            Impacts::HardDisks => 1.0 - x * x,
            Impacts::IsotropicDisks => {
                let h = libm::sin(0.5 * std::f64::consts::PI * x);
                h * h
            }
        }
    }
}

/// A gas under the impact-speed law, started from Maxwellians (module docs): what its exact
/// `dT/dt` at `t = 0` depends on.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct InitialCooling {
    /// Particles per system.
    pub n: usize,
    /// The dimension `d`, 2 or 3.
    pub d: usize,
    /// `K = 4 pi gamma C`: the pair rate is `K |g|^lambda / n`.
    pub k: f64,
    /// The kernel's exponent `lambda` (0 Maxwell, 1 hard spheres).
    pub lambda: f64,
    /// The law of the collision direction.
    pub impacts: Impacts,
    /// BRS (9)'s `beta_0`.
    pub beta0: f64,
    /// BRS (9)'s `delta`.
    pub delta: f64,
    /// The start temperature `T0` of the translation.
    pub t0: f64,
    /// Rough particles: `(beta, kappa, T_rot)`, the tangential restitution, the reduced moment
    /// of inertia and the start rotational temperature (`None`: smooth).
    pub rough: Option<(f64, f64, f64)>,
}

impl InitialCooling {
    /// The exact `dT/dt` at `t = 0` (module docs), `T` the translational temperature
    /// `(1/(d n)) sum |v|^2`.
    #[must_use]
    pub fn rate(&self) -> f64 {
        self.rate_seeing(|s| s)
    }

    /// The same with the law given the normal share `seen(s)` in place of the true `s` while
    /// the impulse keeps its direction: what a map that computed the impact speed otherwise
    /// would give (BRS (10) as printed, `|g . w_hat|`, sees `min(s, 1 - s)`), so a test can show
    /// that it tells the two apart.
    #[must_use]
    pub fn rate_seeing(&self, seen: impl Fn(f64) -> f64) -> f64 {
        // Simpson's rule in the reduced speed rho = |g| / sqrt(2 T0) on [0, 14] (the density's
        // tail beyond is below e^-98) and in x on [0, 1]; the test of this module halves the
        // steps: the rate moves by 5e-9 of itself at most, the clamp's kink included.
        self.integral(&seen, 2000, 1000)
    }

    fn integral(&self, seen: &impl Fn(f64) -> f64, nr: usize, nx: usize) -> f64 {
        let scale = (2.0 * self.t0).sqrt();
        let (eta_t, spin_var) = match self.rough {
            None => (0.0, 0.0),
            Some((beta, kappa, t_rot)) => (
                0.5 * (1.0 + beta) * kappa / (1.0 + kappa),
                2.0 * (self.d as f64 - 1.0) * t_rot / kappa,
            ),
        };
        let alpha = |speed: f64| {
            if self.beta0 == 0.0 {
                1.0
            } else {
                (1.0 - 2.0 * self.beta0 * libm::pow(speed, self.delta)).clamp(0.0, 1.0)
            }
        };
        // The mean energy change at relative speed r over the law of s.
        let over_x = |r: f64| {
            simpson(nx, 0.0, 1.0, |x| {
                let s = self.impacts.share(x);
                let a = alpha(r * seen(s).max(0.0).sqrt());
                let eta_n = 0.5 * (1.0 + a);
                -eta_n * (1.0 - eta_n) * s * r * r - eta_t * (1.0 - eta_t) * (1.0 - s) * r * r
                    + eta_t * eta_t * spin_var
            })
        };
        // The density of rho = |g| / sqrt(2 T0): chi with d degrees of freedom.
        let density = |rho: f64| match self.d {
            2 => rho * libm::exp(-0.5 * rho * rho),
            _ => (2.0 / std::f64::consts::PI).sqrt() * rho * rho * libm::exp(-0.5 * rho * rho),
        };
        let mean = simpson(nr, 0.0, 14.0, |rho| {
            let r = scale * rho;
            density(rho) * libm::pow(r, self.lambda) * over_x(r)
        });
        let (n, d) = (self.n as f64, self.d as f64);
        self.k * (n - 1.0) / (d * n) * mean
    }
}

/// Simpson's rule for `f` on `[a, b]` with `m` (even) intervals.
fn simpson(m: usize, a: f64, b: f64, f: impl Fn(f64) -> f64) -> f64 {
    let h = (b - a) / m as f64;
    let mut sum = f(a) + f(b);
    for i in 1..m {
        sum += if i % 2 == 1 { 4.0 } else { 2.0 } * f(a + i as f64 * h);
    }
    sum * h / 3.0
}

#[cfg(test)]
mod tests {
    use super::*;

    fn base(impacts: Impacts, d: usize) -> InitialCooling {
        InitialCooling {
            n: 2,
            d,
            k: 1.0,
            lambda: 1.0,
            impacts,
            beta0: 0.0,
            delta: 0.0,
            t0: 1.0,
            rough: None,
        }
    }

    /// A constant coefficient has the closed form `-K (n-1)/(d n) (1 - alpha^2)/4 E[s]
    /// <|g|^(2 + lambda)>`: `E[s]` is 1/2 on spheres and isotropic disks, 2/3 for hard disks;
    /// `<|g|^3> = 8 sqrt(2/pi) (2 T0)^(3/2)` in d = 3 and `3 sqrt(pi/2) (2 T0)^(3/2)` in d = 2.
    #[test]
    fn a_constant_coefficient_has_its_closed_form() {
        let g3 = |d: usize| {
            let c = libm::pow(2f64, 1.5);
            if d == 3 {
                8.0 * (2.0 / std::f64::consts::PI).sqrt() * c
            } else {
                3.0 * (std::f64::consts::PI / 2.0).sqrt() * c
            }
        };
        for (impacts, d, es) in [
            (Impacts::Spheres, 3, 0.5),
            (Impacts::HardDisks, 2, 2.0 / 3.0),
            (Impacts::IsotropicDisks, 2, 0.5),
        ] {
            let mut c = base(impacts, d);
            c.beta0 = 0.2; // alpha = 0.6 with delta = 0
            let want = -(0.5 / d as f64) * (1.0 - 0.36) / 4.0 * es * g3(d);
            let got = c.rate();
            assert!(
                (got - want).abs() < 1e-9 * want.abs(),
                "{impacts:?}: {got} vs {want}"
            );
        }
    }

    /// Halving both steps changes the rate by less than 2e-8 of itself (measured: 5e-9 at most,
    /// the clamp's kink limiting Simpson's order), with a clamp inside
    /// the range (beta0 = 0.3, delta = 1: alpha = 0 above |g . n| = 5/3).
    #[test]
    fn the_quadrature_has_converged() {
        for impacts in [
            Impacts::Spheres,
            Impacts::HardDisks,
            Impacts::IsotropicDisks,
        ] {
            let mut c = base(impacts, if impacts == Impacts::Spheres { 3 } else { 2 });
            (c.beta0, c.delta, c.rough) = (0.3, 1.0, Some((0.2, 0.4, 1.0)));
            let id = |s: f64| s;
            let (a, b) = (c.integral(&id, 2000, 1000), c.integral(&id, 4000, 2000));
            assert!((a - b).abs() < 2e-8 * a.abs(), "{impacts:?}: {a} vs {b}");
        }
    }
}
