//! GRW (13)-(14): the Maxwell gas's exact temperature under every drive that heats it linearly,
//! and its exact means at finite n (no splitting, Euler and Strang splitting).

use crate::mutation::{Reference, mutated};
use gdsmc_core::drive::Heating;
use gdsmc_core::physics::Momentum;

/// GRW (13)-(14) / RW (24)-(25): the temperature of the heated Maxwell gas, `B = gamma C_0`,
/// `T(t) = T_inf + (T_0 - T_inf) exp(-k t)`, `k = gamma pi C_0 (1 - alpha^2)`,
/// `T_inf = 2 beta / k` (for `beta = 0` the pure exponential cooling). For a gas with a bulk
/// velocity this is the temperature about it (collisions dissipate only the peculiar energy and
/// the kicks are isotropic); GRW's raw temperature adds `|V_0|^2 / 3`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct MaxwellTemperature {
    /// Initial temperature about the bulk velocity.
    pub t0: f64,
    /// Decay rate `k = gamma pi C_0 (1 - alpha^2)`.
    pub k: f64,
    /// How the drive changes the temperature ([`Heating`]: white noise `(2 beta, 0, 0)`, the
    /// Gaussian thermostat `(0, 2 zeta, 0)`, the Langevin thermostat `(2 gamma T_b, -2 gamma,
    /// -2 gamma)`).
    pub heating: Heating,
}

impl MaxwellTemperature {
    /// From the initial temperature and the parameters of GRW (1).
    pub fn new(t0: f64, alpha: f64, beta: f64, gamma: f64, c0: f64) -> Self {
        MaxwellTemperature {
            t0,
            k: gamma * std::f64::consts::PI * c0 * (1.0 - alpha * alpha),
            heating: Heating {
                a: 2.0 * beta,
                b: 0.0,
                p: 0.0,
            },
        }
    }

    /// With the drive's heating `h` instead of white noise (the Maxwell gas's temperature is
    /// exact for every drive that heats linearly, [`Heating`]): `T' = a + (b - k) T`.
    pub fn with_heating(mut self, h: Heating) -> Self {
        self.heating = h;
        self
    }

    /// With a Gaussian thermostat `F = m zeta (v - V)` (MS (12), about the bulk velocity as
    /// the core applies it), which adds `2 zeta T` to `dT/dt`: `T(t) = T_0 exp(-(k - 2 zeta) t)`
    /// (no white noise). Exact at finite `n` for the Maxwell kernel in any dimension: the
    /// scaling of `v - V` commutes with collisions whose rate does not depend on `|u|`.
    pub fn with_gaussian(mut self, zeta: f64) -> Self {
        self.heating.b = 2.0 * zeta;
        self
    }

    /// The net decay rate `k - b` (`k - 2 zeta` with a Gaussian thermostat).
    fn rate(&self) -> f64 {
        self.k - self.heating.b
    }

    /// `T(t)`; for `alpha = 1` (`k = 0`) the limit `T_0 + 2 beta t` (RW, after (25)).
    pub fn at(&self, t: f64) -> f64 {
        // `T' = a - r T`: `Heating::evolve` at rate `-r`, accurate at every rate.
        let x = self.heating.evolve(self.t0, -self.rate(), t);
        mutated(Reference::MaxwellTemperature, x)
    }

    /// `T_inf = 2 beta / k` (GRW (14), RW (25)).
    pub fn stationary(&self) -> f64 {
        self.heating.a / self.rate()
    }

    /// The exact mean over ensembles of the bulk temperature `T_bulk` of an `n`-particle system
    /// started from `n` independent draws of `f_0` (no splitting, Maxwell kernel):
    /// `E T_bulk,n(t) = (1 - 1/n) T(t)`.
    ///
    /// Derivation: with `S = sum |v_i|^2` and `P = sum v_i`, real collisions occur at rate
    /// `2 pi gamma C_0 (n - 1)` on uniform pairs, each changing `S` by
    /// `-(1 - alpha^2)/4 |v_i - v_j|^2` on average over `e`, and
    /// `sum_{i != j} |v_i - v_j|^2 = 2 n S - 2 |P|^2`; kicks add `6 beta` to `E S` per particle
    /// and unit time and `6 n beta` to `E |P|^2`, which collisions keep. So
    /// `d E[S - |P|^2/n] / dt = 6 (n - 1) beta - k E[S - |P|^2/n]`, and `3 n T_bulk = S - |P|^2/n`
    /// starts at `E = 3 (n - 1) T_0`: the ODE of `T(t)` scaled by `(n - 1)/n`.
    pub fn finite_n_bulk_mean(&self, n: usize, t: f64) -> f64 {
        mutated(Reference::FiniteNBulk, (1.0 - 1.0 / n as f64) * self.at(t))
    }

    /// The exact ensemble mean of GRW's raw temperature `(1/3n) sum |v|^2` of an `n`-particle
    /// system, for an initial distribution with zero mean: `E T_n(t) = E T_bulk,n(t) + E|P|^2/(3n^2)`
    /// with `E |P(t)|^2 = 3 n T_0 + 6 n beta t`, that is
    /// `T(t) + (1/n) [T_0 (1 - e^{-kt}) + 2 beta (t - (1 - e^{-kt}) / k)]`: an `O(1/n)` bias,
    /// which is why GRW/RW's error tables fall by a factor 4 per fourfold `n`.
    pub fn finite_n_raw_mean(&self, n: usize, t: f64) -> f64 {
        self.finite_n_bulk_mean(n, t) + self.bulk_to_raw(n, t)
    }

    /// `E |P(t)|^2 / (3 n^2) = (T_0 + 2 beta t) / n`: what the raw temperature's mean adds to
    /// the bulk one (zero-mean start; collisions keep `P`, and so does the Gaussian thermostat,
    /// which scales the peculiar velocity `v - V` (MS (61)); kicks make it a random walk).
    /// The same in any dimension: `E |P|^2 = d n T_0 + 2 d n beta t` over `d n^2`. In general
    /// `U = E|P|^2/(d n)` obeys `U' = a + p U` ([`Heating`]; the Langevin bath's drag makes `P`
    /// decay), and this is `U(t)/n`.
    pub fn bulk_to_raw(&self, n: usize, t: f64) -> f64 {
        self.bulk_to_raw_from(Momentum::Drawn, n, t)
    }

    /// [`Self::bulk_to_raw`] for a sample whose momentum starts as `momentum` says: drawn,
    /// `U(0) = T_0`; exact ([`Momentum::Exact`], the sample's mean velocity is the
    /// distribution's), `U(0) = 0`, so that only the kicks' random walk is left,
    /// `U(t) = 2 beta t` for white noise (`U' = a + p U` from 0). The shift does not change
    /// `T_bulk`, so [`Self::finite_n_bulk_mean`] holds for both starts.
    pub fn bulk_to_raw_from(&self, momentum: Momentum, n: usize, t: f64) -> f64 {
        let u0 = match momentum {
            Momentum::Drawn => self.t0,
            Momentum::Exact => 0.0,
        };
        // `U' = a + p U`, accurate at every rate.
        let u = self.heating.evolve(u0, self.heating.p, t);
        mutated(Reference::BulkToRaw, u / n as f64)
    }

    /// The factor `e^{p t}` by which the drive carries the square of an initial drift
    /// ([`Heating`]: 1 but for a drag on the whole velocity).
    pub fn drift_factor(&self, t: f64) -> f64 {
        libm::exp(self.heating.p * t)
    }

    /// The exact ensemble mean of `T_bulk` of the splitting schemes (RW Algorithms 1 and 2)
    /// with time step `dt` at the grid time `t = m dt`, `n` particles.
    ///
    /// With `X = E[S - |P|^2/n] = 3 n E T_bulk`: a collision step of length `h` multiplies `X` by
    /// `exp(-k h)` (the collision process alone, as in `finite_n_bulk_mean`), a kicking step of
    /// length `dt` adds `6 (n - 1) beta dt`. Euler: `X' = a X + b`, `a = exp(-k dt)`,
    /// `b = 6 (n - 1) beta dt`; Strang: `X' = a X + exp(-k dt / 2) b`. So
    /// `X_m = a^m X_0 + b' (1 - a^m) / (1 - a)`, `X_0 = 3 (n - 1) T_0`. The stationary values are
    /// `(1 - 1/n) 2 beta dt / (1 - e^{-k dt})` (Euler: first order in dt) and
    /// `(1 - 1/n) (2 beta / k) (k dt / 2) / sinh(k dt / 2)` (Strang: second order), which give
    /// RW Tables 3 and 4.
    pub fn splitting_bulk_mean(&self, n: usize, dt: f64, strang: bool, t: f64) -> f64 {
        let m = (t / dt).round();
        let nf = n as f64;
        let x0 = 3.0 * (nf - 1.0) * self.t0;
        // The kicking step: `X -> e^{b dt} X + 3 (n - 1) (a/b)(e^{b dt} - 1)` (`a dt` for
        // `b = 0`); the scaling `e^{b dt}` is folded into the step's factor below.
        // (`6 (n - 1) (a/2) dt` for `b = 0`: RW's white noise, `a = 2 beta`, as written there.)
        let (ha, hb) = (self.heating.a, self.heating.b);
        let added = 3.0 * (nf - 1.0) * ha * Heating::growth(hb, dt);
        let b = added
            * if strang {
                libm::exp(-0.5 * self.k * dt)
            } else {
                1.0
            };
        // `a = e^x` per step; the sum of `a^j` for `j < m`, `(a^m - 1)/(a - 1)`, as a ratio of
        // `expm1`s: no cancellation where the rate is tiny.
        let x = -self.rate() * dt;
        let am = libm::exp(m * x);
        let geometric = if x == 0.0 {
            m
        } else {
            libm::expm1(m * x) / libm::expm1(x)
        };
        mutated(
            Reference::SplittingBulk,
            (am * x0 + b * geometric) / (3.0 * nf),
        )
    }
}
