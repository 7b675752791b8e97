//! Drives declared by their type (rand_distr's model: the parameters, their rules and the
//! rules' words beside the constructor). A declared drive names once, in its own file, its
//! parameters ([`ParamSpec`]: name, rule, words, unit), how it is built from their values, how
//! it acts in each dimension and on each mass ([`Declared::place`]), the words of a chart's
//! title, the rate at which it heats the temperature when that rate is linear (the exact
//! Maxwell-gas references follow from it) and the bound a run's work estimate takes; its row in
//! the drive table (`physics/kinds.rs`) gives its scene word, C code and cargo feature. The
//! scene's `[drive]` keys, the C ABI's `drive_params`, the validation's errors, the engine's
//! drive level, the dispatch and the runner's words, references and estimate are derived from
//! these declarations.

use super::Drive;
pub use crate::declared::{ParamSpec, Rule};
use crate::geometry::Geometry;
use crate::math::{Real, exp, exp_m1};

/// Most parameters a declared drive has (the C ABI's `drive_params`).
pub const MAX_DRIVE_PARAMS: usize = 4;

/// What a run's work estimate takes from a drive: the temperature at the start, the run's
/// last time and Haff's law of the kernel there (`dT/dt = -zeta0 (T/T0)^s T` from the
/// collisions alone).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct WorkInput {
    /// The temperature at the start.
    pub t0: Real,
    /// The run's last time.
    pub t_end: Real,
    /// Haff's exponent `s = lambda/2`.
    pub s: Real,
    /// The collisional cooling rate at `t0`.
    pub zeta0: Real,
}

/// A drive that changes the temperature linearly (unit-mass particles, `d` components, `n` of
/// them; `S = sum |v_i|^2`, `P = sum v_i`, `X = E[S - |P|^2/n] = d n E T_bulk`,
/// `U = E|P|^2/(d n)`): the drive alone gives `dX/dt = d (n - 1) a + b X` and
/// `dU/dt = a + p U`. White noise (GRW (18)): `(2 beta, 0, 0)`; the Gaussian thermostat, which
/// scales `v - V` and keeps `P` (MS (12)): `(0, 2 zeta, 0)`; the Langevin thermostat:
/// `(2 gamma T_b, -2 gamma, -2 gamma)`. With the Maxwell kernel the collisions take `k X` from
/// `X` (`k = pi gamma C_0 (1 - alpha^2)`, GRW (13)) and keep `P`, so `E T_bulk = (1 - 1/n) T(t)`
/// with `T' = a + (b - k) T`, and the raw temperature adds `U/n`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Heating {
    /// The rate that does not depend on the temperature.
    pub a: Real,
    /// The rate per unit of the temperature about the bulk velocity.
    pub b: Real,
    /// The rate per unit of the bulk velocity's square, `|P|^2/(d n)`.
    pub p: Real,
}

impl Heating {
    /// `y(t)` of `y' = a + rate y`, `y(0) = y0`, in closed form: `y0 e^(rate t) + a
    /// growth(rate, t)`, accurate at every rate ([`Heating::growth`]: a rate of `1e-300` gives
    /// `y0 + a t`, where `a/rate (1 - e^(-rate t))` cancelled to `y0`, issue 78).
    #[must_use]
    pub fn evolve(&self, y0: Real, rate: Real, t: Real) -> Real {
        // `y0 e^x` directly: `y0 + y0 (e^x - 1)` cancels where the gas decays far (x = -38).
        y0 * exp(rate * t) + self.a * Self::growth(rate, t)
    }

    /// `(e^(rate t) - 1)/rate` (`t` at rate 0), computed as `t (e^x - 1)/x` with `x = rate t`:
    /// never a division by a rate that cancelled or underflowed, and exact to rounding where
    /// `x` is tiny (its Taylor series to `x^2`, whose remainder `x^3/24` is below `1e-24` there).
    #[must_use]
    pub fn growth(rate: Real, t: Real) -> Real {
        let x = rate * t;
        let g = if x == 0.0 {
            1.0
        } else if x.abs() < 1e-8 {
            1.0 + x / 2.0 + x * x / 6.0
        } else {
            exp_m1(x) / x
        };
        t * g
    }
}

/// A drive declared by its type.
pub trait Declared: Drive + PartialEq + 'static {
    /// Its parameters, in the order of their values (the C ABI's `drive_params`).
    const PARAMS: &'static [ParamSpec];
    /// Its name in a chart's title ("Langevin thermostat"); the title adds the parameters.
    const TITLE: &'static str;
    /// Why no exact (no-splitting) scheme exists for it, when none does: the scheme must then
    /// be Euler, Strang or time-stepped.
    const STEPPED_ONLY: Option<&'static str> = None;

    /// The drive as a loop of dimension `G` takes it.
    type In<G: Geometry>: Drive;

    /// The drive of these values, each of which obeys its rule; `Err(i)` when parameter `i`
    /// makes it overflow anyway.
    fn from_values(values: &[Real]) -> Result<Self, usize>;

    /// The drive acting on a grain of mass `mass` (a mixture's species; one species: 1) in
    /// dimension `G`; `None` when that mass makes it overflow.
    fn place<G: Geometry>(self, mass: Real) -> Option<Self::In<G>>;

    /// How the drive alone changes the temperature, when it does so linearly ([`Heating`]):
    /// then the Maxwell gas's temperature is exact with it. `None`: not linear.
    fn heating(&self) -> Option<Heating> {
        None
    }

    /// The largest temperature a run can reach and the time over which it collides at the
    /// start's rate (a run's work estimate, an order of magnitude). Default, from
    /// [`Declared::heating`]: the drive alone, with no collision to cool it, and the run's span.
    fn work(&self, w: WorkInput) -> (Real, Real) {
        let heated = match self.heating() {
            Some(h) => h.evolve(w.t0, h.b, w.t_end),
            None => w.t0,
        };
        (w.t0.max(heated), w.t_end)
    }
}

#[cfg(test)]
mod tests {
    use super::Heating;

    /// `growth` and `evolve` at rates where the plain closed form cancels or overflows: a rate
    /// of 1e-300 (and a subnormal one) gives `y0 + a t` to rounding (the plain `a/r (1 - e^(-r
    /// t))` gave `y0`); ordinary rates agree with the plain form to a few ulps.
    #[test]
    fn the_closed_form_holds_at_every_rate() {
        let h = Heating {
            a: 2.0,
            b: 0.0,
            p: 0.0,
        };
        for rate in [0.0, 1e-300, -1e-300, 5e-324, 1e-12] {
            let y = h.evolve(1.0, rate, 8.0);
            assert!((y - 17.0).abs() <= 17.0 * 1e-10, "rate {rate}: {y}");
        }
        for rate in [-0.5, 0.3, -7.0] {
            let plain = libm::exp(rate * 8.0) + 2.0 / rate * libm::expm1(rate * 8.0);
            let y = h.evolve(1.0, rate, 8.0);
            assert!(
                (y - plain).abs() <= 8.0 * f64::EPSILON * plain.abs(),
                "{rate}: {y} {plain}"
            );
        }
        assert_eq!(Heating::growth(0.0, 3.0), 3.0);
        // A far decay keeps its digits: e^-38 relative to rounding (1 + (e^-38 - 1) did not).
        let cooling = Heating {
            a: 0.0,
            b: 0.0,
            p: 0.0,
        };
        let y = cooling.evolve(1.0, -0.19, 200.0);
        let exact = libm::exp(-38.0);
        assert!(
            (y - exact).abs() <= 4.0 * f64::EPSILON * exact,
            "{y} {exact}"
        );
    }
}
