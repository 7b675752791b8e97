//! The exact (no-splitting) loop of weighted particles: GRW Section 3's majorant process with
//! the weighted rate of Rjasanow and Wagner (1996), no drive.
//!
//! The pair `(i, j)` collides at `(1 + kappa) max(g_i, g_j) int B de / n0`
//! ([`super::Transfer::rate_factor`]); it is bounded by `(1 + kappa) g_max B_max / n0` with
//! `B_max` the kernel's bound at `Umax = 2 max |v - V|` (GRW (19)), so candidates come at the
//! total rate `n (n - 1)/2` times that (`n` the particles in use, which changes at every
//! collision: the rate is recomputed at each event, exactly) and a uniform pair is accepted
//! with probability `max(g_i, g_j)/g_max` times the kernel's acceptance (GRW (20)). The bound
//! covers every velocity a collision makes (`Umax` grows to cover it, `g_max` never grows in a
//! collision), so no pair overshoots and the process has no time-step error. When the buffer
//! cannot take a collision's particles, the system is reduced first ([`super::reduce`]) and the
//! bounds are made exact again; every `2 n` candidates they are made exact too.
//!
//! For the Maxwell kernel the weighted process keeps GRW's exact finite-n mean of the
//! temperature: `d/dt E[S2 - |P|^2/n0] = -c E[S2 - |P|^2/n0]`, `S2 = sum g |v|^2`,
//! `P = sum g v`, `c = (1 - alpha^2) int B de / 4`, for every weight transfer (each pair's
//! rate times `gamma` is `g_i g_j int B de / n0`, and `sum_{i<j} g_i g_j |v_i - v_j|^2 =
//! n0 S2 - |P|^2`), and a reduction keeps `S2` and `P`.

use super::particle::{WeightedError, WeightedSystem};
use super::reduce::Reduction;
use super::transfer::{Transfer, collide};
use crate::collision::inelastic;
use crate::engine::collision_map::clamped_coefficient;
use crate::engine::{Counts, EngineError};
use crate::geometry::Geometry;
use crate::kernel::Kernel;
use crate::math::{Real, sqrt};
use crate::restitution::Restitution;
use crate::rng::{Rng, uniform_pair, uniform01};
use crate::sample::standard_exponential;
use crate::vec3::Vec3;

/// A weighted gas's moments now: its weight, flow velocity, temperature about the flow and
/// fourth cumulant, with the particles in use.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct WeightedObservables {
    /// Time.
    pub t: Real,
    /// Particles in use.
    pub particles: usize,
    /// Total weight `sum g` (the run's `n0`: collisions and reductions keep it).
    pub mass: Real,
    /// Flow velocity `sum g v / sum g`.
    pub bulk: Vec3,
    /// Temperature about the flow, `sum g |v - V|^2 / (d sum g)`.
    pub t_bulk: Real,
    /// Fourth cumulant `<c^4> / <c^2>^2 d/(d + 2) - 1` about the flow (MS (3)).
    pub a2: Real,
}

/// The moments of `sys` in dimension `d` at time `t`.
pub fn observe(sys: &WeightedSystem<'_>, d: usize, t: Real) -> WeightedObservables {
    let mass = sys.mass();
    let bulk = (1.0 / mass) * sys.momentum();
    let (mut s2, mut s4) = (0.0, 0.0);
    for p in sys.particles() {
        let c2 = (p.velocity() - bulk).norm2();
        s2 += p.g * c2;
        s4 += p.g * c2 * c2;
    }
    let (m2, m4) = (s2 / mass, s4 / mass);
    let df = d as Real;
    WeightedObservables {
        t,
        particles: sys.len(),
        mass,
        bulk,
        t_bulk: m2 / df,
        a2: m4 / (m2 * m2) * df / (df + 2.0) - 1.0,
    }
}

/// The weighted exact loop for kernel `K`, restitution law `A`, dimension `G` (module docs).
#[derive(Clone, Debug)]
pub struct WeightedNoSplitting<K, A, G> {
    kernel: K,
    law: A,
    transfer: Transfer,
    /// How the particles are reduced when the buffer is full.
    reduction: Reduction,
    /// The total weight.
    n0: Real,
    /// The bounds: `Umax` about `vref`, and the largest weight.
    umax: Real,
    vref: Vec3,
    gmax: Real,
    t: Real,
    /// Candidates until the bounds are made exact again.
    until_refresh: u64,
    counts: Counts,
    reductions: u64,
    dim: core::marker::PhantomData<G>,
}

impl<K: Kernel, A: Restitution, G: Geometry> WeightedNoSplitting<K, A, G> {
    /// Starts at `t0` on `sys` with the weight transfer `transfer` and the reduction
    /// `reduction`.
    pub fn start(
        (kernel, law): (K, A),
        transfer: Transfer,
        reduction: Reduction,
        sys: &WeightedSystem<'_>,
        t0: Real,
    ) -> Result<Self, EngineError> {
        if !t0.is_finite() {
            return Err(EngineError::TimeBackwards);
        }
        let mut s = WeightedNoSplitting {
            kernel,
            law,
            transfer,
            reduction,
            n0: sys.mass(),
            umax: 0.0,
            vref: Vec3::ZERO,
            gmax: 0.0,
            t: t0,
            until_refresh: 0,
            counts: Counts::default(),
            reductions: 0,
            dim: core::marker::PhantomData,
        };
        s.refresh(sys)?;
        Ok(s)
    }

    /// The bounds made exact: `vref` the flow, `Umax = 2 max |v - vref|`, `g_max`.
    fn refresh(&mut self, sys: &WeightedSystem<'_>) -> Result<(), EngineError> {
        let vref = (1.0 / sys.mass()) * sys.momentum();
        let (mut c2, mut g) = (0.0, 0.0);
        for p in sys.particles() {
            let x = (p.velocity() - vref).norm2();
            c2 = if x > c2 { x } else { c2 };
            g = if p.g > g { p.g } else { g };
        }
        if !(c2.is_finite() && g.is_finite()) {
            return Err(EngineError::NonFinite(
                "a weighted particle's velocity or weight",
            ));
        }
        self.vref = vref;
        self.umax = 2.0 * sqrt(c2);
        self.gmax = g;
        self.until_refresh = 2 * sys.len() as u64;
        Ok(())
    }

    /// Current time.
    pub fn time(&self) -> Real {
        self.t
    }

    /// Event counts so far.
    pub fn counts(&self) -> Counts {
        self.counts
    }

    /// Reductions so far.
    pub fn reductions(&self) -> u64 {
        self.reductions
    }

    /// Runs to `t_end` (not before the current time) and returns the moments there.
    pub fn advance_to<R: Rng + ?Sized>(
        &mut self,
        sys: &mut WeightedSystem<'_>,
        t_end: Real,
        rng: &mut R,
    ) -> Result<WeightedObservables, EngineError> {
        if !t_end.is_finite() || t_end < self.t {
            return Err(EngineError::TimeBackwards);
        }
        loop {
            let n = sys.len();
            let pairs = 0.5 * n as Real * (n - 1) as Real;
            let rate = pairs
                * self.transfer.rate_factor(self.gmax, self.gmax)
                * self.kernel.b_max(self.umax)
                / self.n0;
            if rate.is_nan() {
                return Err(EngineError::NonFinite("the weighted majorant's rate"));
            }
            if rate <= 0.0 {
                // No pair can collide (every velocity equal, and the kernel's bound at
                // Umax = 0 is 0): nothing happens until t_end.
                break;
            }
            let next = self.t + standard_exponential(rng) / rate;
            if next >= t_end {
                break;
            }
            self.t = next;
            self.event(sys, rng)?;
        }
        self.t = t_end;
        self.counts.observations += 1;
        Ok(observe(sys, G::CHOICE.d(), t_end))
    }

    /// One candidate at the current time: the acceptance, the collision, a reduction first
    /// when the buffer is full.
    fn event<R: Rng + ?Sized>(
        &mut self,
        sys: &mut WeightedSystem<'_>,
        rng: &mut R,
    ) -> Result<(), EngineError> {
        self.counts.candidates += 1;
        if sys.len() + 2 > sys.capacity() {
            self.reduction.apply(sys, 2, G::CHOICE, rng);
            self.reductions += 1;
            self.refresh(sys)?;
            // The bounds changed: this candidate was drawn at the old rate, which bounds the
            // new one only if it did not grow; it is counted as fictitious and the next is
            // drawn at the new rate.
            self.counts.fictitious += 1;
            return Ok(());
        }
        let (i, j) = uniform_pair(rng, sys.len());
        let (pi, pj) = (sys.particles()[i], sys.particles()[j]);
        let (vi, vj) = (pi.velocity(), pj.velocity());
        let u = vi - vj;
        let heavier = if pi.g > pj.g { pi.g } else { pj.g };
        let accept = heavier / self.gmax * self.kernel.acceptance(u.norm(), self.umax);
        if uniform01(rng) >= accept {
            self.counts.fictitious += 1;
        } else {
            let e = G::scattering::<K, R>(u, rng);
            let alpha = clamped_coefficient(&self.law, u, e, &mut self.counts);
            let (a, b) = inelastic(vi, vj, e, alpha);
            collide(sys, (i, j), (a, b), &self.transfer).map_err(|e| match e {
                WeightedError::Full => EngineError::Invariant("a reduction makes room first"),
                _ => EngineError::Invariant("a collision keeps every weight > 0"),
            })?;
            self.counts.collisions += 1;
            // Cover the new velocities: no pair overshoots the bound.
            for v in [a, b] {
                let c = 2.0 * (v - self.vref).norm();
                if c > self.umax {
                    self.umax = c;
                }
            }
        }
        self.until_refresh = self.until_refresh.saturating_sub(1);
        if self.until_refresh == 0 {
            self.counts.refreshes += 1;
            self.refresh(sys)?;
        }
        Ok(())
    }
}
