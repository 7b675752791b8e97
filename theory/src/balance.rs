//! The temperature of a smooth one-species gas from its energy balance: Haff's law for the
//! cooling gas (Haff 1983), and its heated forms.
//!
//! A collision of the map GRW (3) changes `|v_1|^2 + |v_2|^2` by `-(1 - alpha^2) c |u|^2 / 2`
//! on average over the scattering: `c = E[(u_hat . n)^2]` over the impact direction, `1/2`
//! for an isotropic `e` (Maxwell and VHS kernels, any `d`) and for hard spheres, `2/3` for hard
//! disks (impact parameter uniform: `crate`'s `geometry` docs). Pairs meet at the total rate
//! `4 pi gamma C |u|^lambda` in both dimensions, so per degree of freedom
//! `dT/dt = -(pi gamma C (1 - alpha^2) c / d) E|u|^(2 + lambda)`. For a Maxwellian,
//! `u ~ N(0, 2T)` in `R^d` and `E|u|^p = (4T)^(p/2) Gamma((d + p)/2) / Gamma(d/2)`:
//! `dT/dt = -kappa T^q`, `q = 1 + lambda/2`, with
//! `kappa = pi gamma C (1 - alpha^2) (c/d) 4^q Gamma((d + 2 + lambda)/2) / Gamma(d/2)`:
//! `(16/3) sqrt(pi) gamma C (1 - alpha^2)` for hard spheres (MS's `xi`), `2 pi^(3/2) gamma C
//! (1 - alpha^2)` for hard disks, `pi gamma C (1 - alpha^2)` for Maxwell particles (GRW (13),
//! exact there). The first Sonine correction of hard particles multiplies it by
//! `1 + 3 a2 / 16` (van Noije and Ernst 1998, any `d`).
//!
//! A drive that heats linearly (`dT/dt = a + b T`, the core's [`Heating`]) adds its rates:
//! `dT/dt = a + b T - kappa T^q`. Without `a` this is a Bernoulli equation, solved in closed
//! form (Haff's law `T = T_0 / (1 + (q - 1) kappa T_0^(q - 1) t)^(1/(q - 1))` for `b = 0`);
//! with it, in `(ln(1 + t), ln T)` by [`super::ode`] so that decades of time keep their
//! resolution. Both are approximations of the Boltzmann equation's `T(t)`: the distribution is
//! not Maxwellian (`a2 != 0`), and a gas started from a Maxwellian reaches its state's `a2`
//! only after some collisions per particle.

use crate::ode;
use gdsmc_core::drive::Heating;
use statrs::function::gamma::gamma;
use std::f64::consts::PI;

/// `E[(u_hat . n)^2]` over the scattering of the map GRW (3) (module docs): `2/3` for hard
/// disks, `1/2` otherwise.
fn impact_factor(d: usize, hard: bool) -> f64 {
    if hard && d == 2 { 2.0 / 3.0 } else { 0.5 }
}

/// The Maxwellian cooling constant `kappa` of `dT/dt = -kappa T^(1 + lambda/2)` (module
/// docs) in dimension `d` for the kernel strength `gamma C`, exponent `lambda` (hard
/// particles: `lambda = 1` with their impact law) and restitution `alpha`.
pub fn cooling_constant(d: usize, hard: bool, gc: f64, lambda: f64, alpha: f64) -> f64 {
    let df = d as f64;
    let q = 1.0 + 0.5 * lambda;
    PI * gc * (1.0 - alpha * alpha) * impact_factor(d, hard) / df
        * libm::pow(4f64, q)
        * gamma((df + 2.0 + lambda) / 2.0)
        / gamma(df / 2.0)
}

/// A particle's collision rate in a Maxwellian gas at temperature `t` (unit mass): pairs meet at
/// `4 pi gamma C |u|^lambda` (module docs), so in the Boltzmann limit a particle collides at
/// `omega = 4 pi gamma C E|u|^lambda`, `E|u|^lambda = (4T)^(lambda/2) Gamma((d + lambda)/2) /
/// Gamma(d/2)`: `4 pi gamma C` for Maxwell particles (exact), `16 sqrt(pi) gamma C sqrt(T)` for
/// hard spheres. Its inverse is the mean free time, the natural time unit of a granular gas.
pub fn collision_rate(d: usize, gc: f64, lambda: f64, t: f64) -> f64 {
    let df = d as f64;
    4.0 * PI * gc * libm::pow(4.0 * t, 0.5 * lambda) * gamma((df + lambda) / 2.0) / gamma(df / 2.0)
}

/// The kinetic theory's collision frequency of hard particles, `nu_0 = 4 Omega_d / (sqrt(pi)
/// (d + 2)) n sigma^(d - 1) sqrt(T/m)` (`Omega_d = 2 pi^(d/2) / Gamma(d/2)`; Garzó and Dufty
/// 1999 for spheres, `(16/5) sqrt(pi) n sigma^2 sqrt(T/m)`, and Garzó's d-dimensional form;
/// the shear-viscosity frequency of the Boltzmann equation), in the units of
/// [`collision_rate`]: `4/(d + 2)` of the Maxwellian collision rate at `T` (spheres `4
/// sqrt(pi) n sigma^2 sqrt(T/m)`, 4/5 of it; disks `2 sqrt(pi) n sigma sqrt(T/m)`, all of it).
/// The literature reduces the cooling rate by it: `zeta* = zeta / nu_0 = (d + 2)/(4 d)
/// (1 - alpha^2)(1 + 3 a2/16)` to first Sonine order (5/12 for spheres, 1/2 for disks).
pub fn nu0_hard(d: usize, gc: f64, t: f64) -> f64 {
    4.0 / (d as f64 + 2.0) * collision_rate(d, gc, 1.0, t)
}

/// The first Sonine correction `1 + 3 a2 / 16` of a hard-particle gas's cooling rate (van
/// Noije and Ernst 1998, any `d`).
pub fn sonine_factor(a2: f64) -> f64 {
    1.0 + 3.0 * a2 / 16.0
}

/// `dT/dt = a + b T - kappa T^q` from `T(0) = t0` (module docs).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct EnergyBalance {
    /// The initial temperature (about the bulk velocity).
    pub t0: f64,
    /// The cooling constant ([`cooling_constant`], times [`sonine_factor`] where wanted).
    pub kappa: f64,
    /// The exponent `q = 1 + lambda/2`.
    pub q: f64,
    /// The drive's linear heating (`p`, the bulk velocity's, plays no part in `T`).
    pub heating: Heating,
}

/// The solved balance: closed form without constant heating, else the integrated points.
pub enum Trajectory {
    /// `T^(1 - q)` is linear (`b = 0`) or exponential in `t`: the closed form.
    Closed(EnergyBalance),
    /// `(ln(1 + t), ln T)` points, linear between them.
    Points(Vec<(f64, f64)>),
    /// The Maxwell kernel (`q = 1`): `T' = a + (b - kappa) T`, closed.
    Linear(EnergyBalance),
}

impl EnergyBalance {
    /// The steady temperature where heating and cooling balance (none when nothing balances:
    /// no heating, or `q = 1`).
    pub fn steady(&self) -> Option<f64> {
        let (a, b) = (self.heating.a, self.heating.b);
        if self.q == 1.0 || (a <= 0.0 && b <= 0.0) {
            return None;
        }
        // g(T) = a + b T - kappa T^q changes sign once on (0, inf) for q > 1: bisection.
        let g = |t: f64| a + b * t - self.kappa * libm::pow(t, self.q);
        let (mut lo, mut hi) = (0.0f64, 1.0f64);
        while g(hi) > 0.0 {
            hi *= 2.0;
            if !hi.is_finite() {
                return None;
            }
        }
        for _ in 0..200 {
            let mid = 0.5 * (lo + hi);
            if g(mid) > 0.0 { lo = mid } else { hi = mid }
        }
        Some(0.5 * (lo + hi))
    }

    /// Solves the balance on `[0, t_end]`.
    pub fn solve(&self, t_end: f64) -> Result<Trajectory, String> {
        if !(self.t0 > 0.0 && self.kappa >= 0.0 && self.q >= 1.0) {
            return Err(format!("no balance from T0 = {}", self.t0));
        }
        if self.q == 1.0 {
            return Ok(Trajectory::Linear(*self));
        }
        if self.heating.a == 0.0 {
            return Ok(Trajectory::Closed(*self));
        }
        let (a, b, k, q) = (self.heating.a, self.heating.b, self.kappa, self.q);
        // y = ln T against s = ln(1 + t): dy/ds = (1 + t) (a e^-y + b - kappa e^((q-1) y)).
        let rhs = |s: f64, y: &[f64; 1]| {
            let t1 = libm::exp(s);
            [t1 * (a * libm::exp(-y[0]) + b - k * libm::exp((q - 1.0) * y[0]))]
        };
        let p = ode::solve(
            rhs,
            0.0,
            libm::log1p(t_end.max(1e-12)),
            [libm::log(self.t0)],
            ode::TOLERANCES,
            4000,
        )
        .map_err(|e| e.to_string())?;
        Ok(Trajectory::Points(
            p.into_iter().map(|(s, y)| (s, y[0])).collect(),
        ))
    }
}

impl Trajectory {
    /// `T(t)`.
    pub fn at(&self, t: f64) -> f64 {
        match self {
            Trajectory::Linear(e) => e.heating.evolve(e.t0, e.heating.b - e.kappa, t),
            Trajectory::Closed(e) => {
                // u = T^(1 - q): u' = r kappa - r b u (r = q - 1), so
                // u = u0 e^(-r b t) + r kappa (1 - e^(-r b t))/(r b), the second term through
                // `Heating::growth`: never `kappa/b` minus itself (at b = 2e-300, a Gaussian
                // thermostat's zeta = 1e-300, that cancelled to u = 0 and T = inf).
                let (b, k, r) = (e.heating.b, e.kappa, e.q - 1.0);
                let u0 = libm::pow(e.t0, -r);
                let u = u0 * libm::exp(-r * b * t) + r * k * Heating::growth(-r * b, t);
                libm::pow(u, -1.0 / r)
            }
            Trajectory::Points(p) => {
                let s = libm::log1p(t);
                let (i, f) = crate::hydro::bracket(p, |q| q.0, s);
                libm::exp(p[i - 1].1 + f * (p[i].1 - p[i - 1].1))
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A scene's `collisions.diameter` and `density` give the kinetic theory's collision
    /// frequency of hard particles at a Maxwellian: `4 sqrt(pi) n sigma^2 sqrt(T/m)` for spheres
    /// (Chapman and Cowling), `2 sqrt(pi) n sigma sqrt(T/m)` for disks (the 2D cross-section
    /// `2 sigma` times `<|u|> = sqrt(pi T/m)`), written here from those formulas, not from the
    /// scene crate's.
    #[test]
    fn a_scenes_diameter_and_density_give_the_kinetic_theorys_collision_frequency() {
        let (sigma, n, t) = (0.7, 1.9, 2.5);
        for d in [3usize, 2] {
            let text = format!(
                "[particles]\nn = 64\ndimension = {d}\n[collisions]\nkernel = \"hard-spheres\"\n\
                 diameter = {sigma}\ndensity = {n}\nrestitution = 0.9\n[drive]\nkind = \"none\"\n\
                 [observe]\nt_end = 1.0\nintervals = 1\n"
            );
            let scene = gdsmc_scene::parse(std::path::Path::new("s.toml"), &text).unwrap();
            let gc = scene.physics().kernel.strength();
            let omega = collision_rate(d, gc, 1.0, t);
            let kinetic = match d {
                3 => 4.0 * PI.sqrt() * n * sigma * sigma * t.sqrt(),
                _ => 2.0 * PI.sqrt() * n * sigma * t.sqrt(),
            };
            assert!(
                (omega / kinetic - 1.0).abs() < 1e-14,
                "d = {d}: {omega} against {kinetic}"
            );
        }
    }

    fn cooling(kappa: f64, q: f64, a: f64, b: f64) -> EnergyBalance {
        EnergyBalance {
            t0: 1.0,
            kappa,
            q,
            heating: Heating { a, b, p: 0.0 },
        }
    }

    /// Without constant heating the closed form is the balance integrated numerically, at a
    /// heating rate of either sign, at none, and at `b = 2e-300` (a Gaussian thermostat's
    /// `zeta = 1e-300`), where the old form `kappa/b + (u0 - kappa/b) e^(-r b t)` cancelled to
    /// `T = inf`; there it is Haff's law (`b = 0`) to rounding. Tolerance: the integrator's
    /// (1e-10 relative per step) over a few hundred steps, so 1e-7.
    #[test]
    fn the_closed_form_is_the_integrated_balance_at_every_rate() {
        for b in [0.3, -0.2, 0.0, 2e-300] {
            let e = cooling(0.7, 1.5, 0.0, b);
            let Ok(Trajectory::Closed(_)) = e.solve(10.0) else {
                panic!("no constant heating: the closed form");
            };
            let closed = e.solve(10.0).unwrap();
            let f = |_: f64, y: &[f64; 1]| [b * y[0] - 0.7 * libm::pow(y[0], 1.5)];
            let points = ode::solve(f, 0.0, 10.0, [1.0], ode::TOLERANCES, 20).unwrap();
            for (t, y) in points {
                let got = closed.at(t);
                assert!(
                    (got - y[0]).abs() <= 1e-7 * y[0],
                    "b = {b}, t = {t}: {got} vs {}",
                    y[0]
                );
            }
        }
        let tiny = cooling(0.7, 1.5, 0.0, 2e-300).solve(10.0).unwrap();
        let haff = cooling(0.7, 1.5, 0.0, 0.0).solve(10.0).unwrap();
        for t in [0.0, 1.0, 10.0] {
            assert!(
                (tiny.at(t) - haff.at(t)).abs() <= 1e-15 * haff.at(t),
                "t = {t}"
            );
        }
    }

    #[test]
    fn the_cooling_constants_are_the_known_ones() {
        let (gc, al) = (0.3, 0.6);
        let loss = 1.0 - al * al;
        let close = |x: f64, y: f64| (x - y).abs() <= 1e-13 * y;
        // Hard spheres: MS's xi = (16/3) sqrt(pi) gamma C (1 - alpha^2).
        let hs = cooling_constant(3, true, gc, 1.0, al);
        assert!(close(hs, 16.0 / 3.0 * PI.sqrt() * gc * loss), "{hs}");
        // Hard disks: 2 pi^(3/2) gamma C (1 - alpha^2).
        let hd = cooling_constant(2, true, gc, 1.0, al);
        assert!(close(hd, 2.0 * libm::pow(PI, 1.5) * gc * loss), "{hd}");
        // Maxwell particles in d = 2 and 3: GRW (13)'s pi gamma C (1 - alpha^2).
        for d in [2, 3] {
            let m = cooling_constant(d, false, gc, 0.0, al);
            assert!(close(m, PI * gc * loss), "{d}: {m}");
        }
        // VHS with lambda = 1 and isotropic scattering in d = 3 is the hard-sphere rate.
        assert!(close(cooling_constant(3, false, gc, 1.0, al), hs));
    }

    #[test]
    fn the_collision_rates_are_the_known_ones() {
        let close = |x: f64, y: f64| (x - y).abs() <= 1e-13 * y;
        for d in [2, 3] {
            assert!(
                close(collision_rate(d, 0.3, 0.0, 7.0), 4.0 * PI * 0.3),
                "{d}"
            );
        }
        let hs = collision_rate(3, 0.3, 1.0, 2.0);
        assert!(close(hs, 16.0 * PI.sqrt() * 0.3 * 2f64.sqrt()), "{hs}");
        // Disks: E|u| = sqrt(4T) Gamma(3/2) = sqrt(pi T).
        let hd = collision_rate(2, 0.3, 1.0, 2.0);
        assert!(close(hd, 4.0 * PI * 0.3 * (PI * 2.0).sqrt()), "{hd}");
    }

    #[test]
    fn haffs_law_and_the_heated_balance() {
        // Haff: T = 1 / (1 + kappa t / 2)^2 for q = 3/2.
        let e = cooling(0.8, 1.5, 0.0, 0.0);
        let tr = e.solve(100.0).unwrap();
        for t in [0.0f64, 0.5, 7.0, 100.0] {
            let haff = 1.0 / (1.0 + 0.4 * t).powi(2);
            assert!((tr.at(t) - haff).abs() <= 1e-13 * haff, "{t}");
        }
        assert_eq!(e.steady(), None);
        // A Gaussian thermostat (b > 0) balances at (b / kappa)^(1/(q-1)), reached in closed form.
        let g = cooling(0.8, 1.5, 0.0, 0.4);
        let ts = g.steady().unwrap();
        assert!((ts - 0.25).abs() < 1e-12, "{ts}");
        assert!((g.solve(1e3).unwrap().at(1e3) - ts).abs() < 1e-9);
        // White noise: the integrated curve relaxes to the root of a = kappa T^q, and agrees
        // with a fine explicit Euler integration at an early time.
        let w = cooling(0.8, 1.5, 2.0, 0.0);
        let ts = w.steady().unwrap();
        assert!((ts - libm::pow(2.0f64 / 0.8, 2.0 / 3.0)).abs() < 1e-12);
        let tr = w.solve(200.0).unwrap();
        assert!((tr.at(200.0) - ts).abs() < 1e-8 * ts);
        let (mut t, mut x, h) = (0.0, 1.0f64, 1e-6);
        while t < 0.5 - 1e-12 {
            x += h * (2.0 - 0.8 * libm::pow(x, 1.5));
            t += h;
        }
        assert!((tr.at(0.5) - x).abs() < 1e-5, "{} vs {x}", tr.at(0.5));
        // The Maxwell kernel (q = 1) is linear: GRW (13).
        let m = cooling(0.75, 1.0, 2.0, 0.0);
        let tm = m.solve(5.0).unwrap().at(5.0);
        let exact = 8.0 / 3.0 + (1.0 - 8.0 / 3.0) * libm::exp(-0.75f64 * 5.0);
        assert!((tm - exact).abs() < 1e-12);
    }
}
