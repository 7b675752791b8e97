//! The hydrodynamic closures of BRS for hard spheres in a hard-sphere host medium (constant
//! restitution), integrated by the adaptive, error-controlled Dormand-Prince 5(4) method
//! ([`super::ode`]): the local-equilibrium closure BRS (21) and the Grad-type closure
//! BRS (22), for the bulk velocity `u` and temperature `T` of unit-mass grains.
//!
//! BRS writes them in the time `(rho^B / rho) rho^B C_1 t` with `rho = 1` here, so every right
//! side carries the factor `s = (rho^B)^2 C_1`; `K = (rho / rho^B)^2 C_2 / C_1` (BRS (23)) and
//! `beta = (1 - e)/2` (BRS (5)).

use super::ode;

/// Which closure.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Closure {
    /// BRS (21): local equilibrium.
    LocalEquilibrium,
    /// BRS (22): Grad-type.
    Grad,
}

/// The parameters of BRS (21)-(22).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct HydroModel {
    /// Mass ratio `alpha = m^B / (1 + m^B)` (BRS (3)).
    pub alpha: f64,
    /// Background temperature `T^B`.
    pub tb: f64,
    /// Background drift `u^B`.
    pub ub: [f64; 3],
    /// `K` of BRS (23).
    pub k: f64,
    /// Inelasticity `beta = (1 - e)/2`.
    pub beta: f64,
    /// Time factor `s = (rho^B)^2 C_1`.
    pub s: f64,
    /// The closure.
    pub closure: Closure,
}

impl HydroModel {
    /// `(du/dt, dT/dt)` at `u`, `T` (grain mass m = 1).
    pub fn rates(&self, u: [f64; 3], t: f64) -> ([f64; 3], f64) {
        let pi = std::f64::consts::PI;
        let a = self.alpha;
        let w: [f64; 3] = std::array::from_fn(|k| u[k] - self.ub[k]);
        let w2 = w[0] * w[0] + w[1] * w[1] + w[2] * w[2];
        let inel = self.k * self.beta * (1.0 - self.beta);
        let (du, dt) = match self.closure {
            Closure::LocalEquilibrium => {
                let d = (1.0 - a) * self.tb + a * t;
                let root = (a / d).sqrt();
                let f = -a * 16.0 / 3.0 * (2.0 * pi).sqrt() * root * (w2 / 5.0 + 2.0 * d / a);
                let dt = a * 8.0 / 3.0
                    * (2.0 * pi).sqrt()
                    * root
                    * ((a + a * t / (3.0 * d)) * w2 * w2 / 5.0
                        + 4.0 * d / a * (a - a * t / (3.0 * d)) * w2
                        + 8.0 * (d / a) * (d / a) * (a - a * t / d))
                    - 64.0 / 3.0 * pi.sqrt() * inel * libm::pow(t, 1.5);
                (f, dt)
            }
            Closure::Grad => {
                let g = a.sqrt() * pi.sqrt() * (2.0 * self.tb).sqrt();
                let f = -32.0 / 3.0 * g;
                let x = w2 / self.tb + 3.0 * (t - self.tb) / self.tb;
                let dt = -64.0 / 3.0 * g * ((1.0 - a) * (t - self.tb) - a * w2 / 3.0)
                    - 4.0 / 3.0
                        * pi.sqrt()
                        * inel
                        * (x * x / 3.0 + 8.0 * (3.0 * t - self.tb) / self.tb)
                        * libm::pow(self.tb, 1.5);
                (f, dt)
            }
        };
        (std::array::from_fn(|k| self.s * du * w[k]), self.s * dt)
    }

    /// Integrates from `u0`, `t0` at time 0 to `t_end` with relative and absolute tolerances
    /// 1e-10 and 1e-12, returning the solution on `steps + 1` equally spaced times.
    pub fn solve(
        &self,
        u0: [f64; 3],
        t0: f64,
        t_end: f64,
        steps: usize,
    ) -> Result<Vec<(f64, [f64; 3], f64)>, String> {
        let rhs = |_: f64, y: &[f64; 4]| {
            let (du, dt) = self.rates([y[0], y[1], y[2]], y[3]);
            [du[0], du[1], du[2], dt]
        };
        let y0 = [u0[0], u0[1], u0[2], t0];
        Ok(ode::solve(rhs, 0.0, t_end, y0, ode::TOLERANCES, steps)
            .map_err(|e| e.to_string())?
            .into_iter()
            .map(|(x, y)| (x, [y[0], y[1], y[2]], y[3]))
            .collect())
    }
}

/// Where `t` falls in the dense output `p` (times by `x`, increasing, at least two points):
/// `(i, f)` with `t` at the fraction `f` in [0, 1] of the way from point `i - 1` to point `i`
/// (clamped at the ends), for linear interpolation.
pub fn bracket<T>(p: &[T], x: impl Fn(&T) -> f64, t: f64) -> (usize, f64) {
    let i = p.partition_point(|q| x(q) <= t).clamp(1, p.len() - 1);
    let (a, b) = (x(&p[i - 1]), x(&p[i]));
    let f = if b > a {
        ((t - a) / (b - a)).clamp(0.0, 1.0)
    } else {
        0.0
    };
    (i, f)
}

/// A solved closure as a function of time (linear interpolation on the dense output).
pub struct Trajectory {
    points: Vec<(f64, [f64; 3], f64)>,
}

impl Trajectory {
    /// Solves `model` from `u0`, `t0` on `[0, t_end]` with 4000 output steps.
    pub fn new(model: &HydroModel, u0: [f64; 3], t0: f64, t_end: f64) -> Result<Self, String> {
        Ok(Trajectory {
            points: model.solve(u0, t0, t_end.max(1e-12), 4000)?,
        })
    }

    fn at(&self, t: f64) -> ([f64; 3], f64) {
        let (i, f) = bracket(&self.points, |q| q.0, t);
        let (a, b) = (&self.points[i - 1], &self.points[i]);
        (
            std::array::from_fn(|k| a.1[k] + f * (b.1[k] - a.1[k])),
            a.2 + f * (b.2 - a.2),
        )
    }

    /// Temperature at `t`.
    pub fn temperature(&self, t: f64) -> f64 {
        self.at(t).1
    }

    /// Bulk velocity component `k` at `t`.
    pub fn bulk(&self, t: f64, k: usize) -> f64 {
        self.at(t).0[k]
    }
}
