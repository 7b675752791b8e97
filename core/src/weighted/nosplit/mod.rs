//! The exact (no-splitting) loop of weighted particles: GRW Section 3's majorant process with
//! the weighted rate of Rjasanow and Wagner (1996), with a drive between collisions.
//!
//! The pair `(i, j)` collides at `(1 + kappa) max(g_i, g_j) int B de / n0`
//! ([`super::Transfer::rate_factor`]); it is bounded by `(1 + kappa) g_max B_max / n0` with
//! `B_max` the kernel's bound at `Umax = 2 max |v - V|` (GRW (19)), so candidates come at the
//! total rate `n (n - 1)/2` times that (`n` the particles in use, which changes at every
//! collision: the rate is recomputed at each event, exactly) and a uniform pair is accepted
//! with probability `max(g_i, g_j)/g_max` times the kernel's acceptance (GRW (20)). A transfer
//! whose `kappa` depends on the outcome ([`Transfer::with_tail`]) bounds with its largest,
//! and thins an outcome by `(1 + kappa(outcome))/(1 + kappa_max)` once it is drawn; its
//! scale `sqrt(T)` is from the temperature about `vref` at the last refresh of the bounds. With no
//! drive the bound covers every velocity a collision makes (`Umax` grows to cover it, `g_max`
//! never grows in a collision), so no pair overshoots and the process has no time-step error.
//! When after a collision the buffer could not take the next one's particles, the system is
//! reduced at once ([`mod@super::reduce`]) and the bounds are made exact again (the next waiting
//! time is then drawn at the new rate); every `2 n` candidates they are made exact too.
//!
//! A drive acts as in the equal-weight loop ([`crate::engine::NoSplitting`]): each partner is
//! kicked lazily from its last-kick time (the record's, as for equal weights: GRW (18), steps
//! 2.5-2.6) before the pair is tested,
//! new particles start at the collision's time, and every particle is kicked to the time of an
//! observation, a reduction or a refresh of the bounds (so a reduction groups velocities of one
//! time). The weights are untouched by a drive, which acts on each particle alone (a drive that
//! couples the particles, [`Drive::COUPLES`], is refused). For the Maxwell kernel nothing
//! depends on `Umax` and the process stays exact; for the others `Umax` grows to cover every
//! kicked velocity, and a pair whose relative speed passed the `Umax` that drew its waiting
//! time is truncated there (RW (19), [`Counts::overshoots`]), as in GRW's algorithm.
//!
//! For the Maxwell kernel the weighted process keeps GRW's exact finite-n mean of the
//! temperature: `d/dt E[S2 - |P|^2/n0] = -c E[S2 - |P|^2/n0]`, `S2 = sum g |v|^2`,
//! `P = sum g v`, `c = (1 - alpha^2) int B de / 4`, for every weight transfer (each pair's
//! rate times `gamma` is `g_i g_j int B de / n0`, and `sum_{i<j} g_i g_j |v_i - v_j|^2 =
//! n0 S2 - |P|^2`), and a reduction keeps `S2` and `P`; a drive whose heating is linear adds
//! its own term, each particle's alone, as GRW (13) has it.

mod report;
mod split;

use super::moments::{momentum, observables};
use super::reduce::Reduction;
use super::transfer::{Transfer, collide_with};
use super::windows::{Allocation, Windows};
use crate::collision::inelastic;
use crate::drive::Drive;
use crate::engine::collision_map::clamped_coefficient;
use crate::engine::frame::{RESCALE_BELOW, rescale_due};
use crate::engine::{Counts, EngineError, Frame};
use crate::geometry::Geometry;
use crate::kernel::Kernel;
use crate::math::{Real, sqrt};
use crate::moments::Observables;
use crate::particles::{Particles, ParticlesError};
use crate::restitution::Restitution;
use crate::rng::{Rng, uniform_pair, uniform01};
use crate::sample::standard_exponential;
use crate::vec3::Vec3;

/// A pair whose lighter partner weighs less than this (a particle of the start weighs 1)
/// moves it whole (`kappa = 0`, at its rate: the outcome thinned by `1/(1 + kappa_max)`), so
/// no lineage of ever lighter remainders is left at one velocity: a light particle of a
/// cooling hard-sphere gas at a few sqrt(T), halved by every collision it had
/// (`kappa = 1`), fell to 1e-170 and below, collided ever more often for its speed, and its
/// weight underflowed to 0 (a non-finite mean followed). Far below any weight that counts:
/// `n0` sums to 16 digits.
pub const LIGHTEST: Real = 1e-12;

/// The weighted exact loop for kernel `K`, restitution law `A`, drive `D`, dimension `G`
/// (module docs).
#[derive(Clone, Debug)]
pub struct WeightedNoSplitting<K, A, D, G> {
    kernel: K,
    law: A,
    drive: D,
    transfer: Transfer,
    /// How the particles are reduced when the buffer is full.
    reduction: Reduction,
    /// The total weight.
    n0: Real,
    /// The bounds: `Umax` about `vref`, and the largest weight.
    umax: Real,
    vref: Vec3,
    /// The temperature about `vref` at the last refresh (a tail's scale `sqrt(T)`).
    tref: Real,
    gmax: Real,
    t: Real,
    /// Candidates until the bounds are made exact again.
    until_refresh: u64,
    /// The particles in use when the loop last stopped (for [`Self::work_rate`]).
    len: usize,
    /// The weight the collisions moved, both partners' (`2 gamma` each).
    moved: Real,
    /// Stored velocities to physical ones (a cooling gas stored rescaled, as the equal-weight
    /// loop's: [`crate::engine::frame`]).
    frame: Frame,
    counts: Counts,
    reductions: u64,
    /// A particle heavier than this times its shell's share is split (0: never;
    /// [`super::windows`]).
    split: Real,
    /// The windows of the last refresh (with an allocated reduction and `split > 0`).
    windows: Option<Windows>,
    /// The copies the splits made.
    splits: u64,
    dim: core::marker::PhantomData<G>,
}

impl<K: Kernel, A: Restitution, D: Drive, G: Geometry> WeightedNoSplitting<K, A, D, G> {
    /// Starts at `t0` on the weighted particles `sys` ([`Particles::weighted`]; every last-kick
    /// time set to `t0`) with the weight transfer `transfer` and the reduction `reduction`. A
    /// drive that couples the particles is refused.
    pub fn start(
        (kernel, law, drive): (K, A, D),
        transfer: Transfer,
        reduction: Reduction,
        sys: &mut Particles<'_>,
        t0: Real,
    ) -> Result<Self, EngineError> {
        if !t0.is_finite() {
            return Err(EngineError::TimeBackwards);
        }
        if !sys.is_weighted() {
            return Err(EngineError::Invariant(
                "the weighted loop runs weighted particles",
            ));
        }
        if D::COUPLES || D::COUNTS_EVENTS {
            return Err(EngineError::Invariant(
                "the weighted loop runs drives that act on each particle alone, in closed form",
            ));
        }
        sys.reset_kick_times(t0);
        let mut s = WeightedNoSplitting {
            kernel,
            law,
            drive,
            transfer,
            reduction,
            n0: sys.mass(),
            umax: 0.0,
            vref: Vec3::ZERO,
            tref: 0.0,
            gmax: 0.0,
            t: t0,
            until_refresh: 0,
            len: sys.len(),
            moved: 0.0,
            frame: Frame::IDENTITY,
            counts: Counts::default(),
            reductions: 0,
            split: 0.0,
            windows: None,
            splits: 0,
            dim: core::marker::PhantomData,
        };
        s.refresh(sys)?;
        Ok(s)
    }

    /// Particle `i` kicked from its last-kick time to now (a drive that acts only).
    #[inline(always)]
    fn kick<R: Rng + ?Sized>(&self, sys: &mut Particles<'_>, i: usize, rng: &mut R) {
        if D::ACTS {
            let dt = self.t - sys.kick_time(i);
            if dt > 0.0 {
                let v = self.drive.evolve(sys.velocity(i), dt, rng);
                let q = sys.get_mut(i);
                q.set_velocity(v);
                q.t_kick = self.t;
            }
        }
    }

    /// Every particle kicked to now (a drive that acts only), and the drive told the moments
    /// there ([`Drive::observe`]).
    fn synchronize<R: Rng + ?Sized>(&mut self, sys: &mut Particles<'_>, rng: &mut R) {
        if D::ACTS {
            for i in 0..sys.len() {
                self.kick(sys, i, rng);
            }
            if D::OBSERVES {
                self.drive.observe(&observables(sys, G::CHOICE.d()));
            }
        }
    }

    /// The bounds made exact: `vref` the flow, `Umax = 2 max |v - vref|`, `g_max` (every
    /// particle at the current time).
    fn refresh(&mut self, sys: &Particles<'_>) -> Result<(), EngineError> {
        let mass = sys.mass();
        let vref = (1.0 / mass) * momentum(sys);
        let (mut c2, mut g, mut s2) = (0.0, 0.0, 0.0);
        for (p, &w) in sys.as_slice().iter().zip(sys.weights()) {
            let x = (p.velocity() - vref).norm2();
            c2 = if x > c2 { x } else { c2 };
            g = if w > g { w } else { g };
            s2 += w * x;
        }
        self.tref = s2 / (mass * G::CHOICE.d() as Real);
        if !(c2.is_finite() && g.is_finite()) {
            return Err(EngineError::NonFinite(
                "a weighted particle's velocity or weight",
            ));
        }
        if let (
            true,
            Reduction::Allocated {
                target,
                shells,
                exponent,
                floor,
            },
        ) = (self.split > 0.0, self.reduction)
        {
            let speeds = (sys.as_slice().iter().zip(sys.weights()))
                .map(|(p, &w)| (sqrt((p.velocity() - vref).norm2()), w));
            let extent = (sqrt(c2), sqrt(self.tref));
            let a = Allocation::measure(speeds, vref, extent, (target, shells, exponent, floor));
            self.windows = Some(Windows::new(a, self.split));
        }
        self.vref = vref;
        self.umax = 2.0 * sqrt(c2);
        self.gmax = g;
        self.until_refresh = 2 * sys.len() as u64;
        Ok(())
    }

    /// Runs to `t_end` (not before the current time) and returns the weighted moments there
    /// (every particle kicked to `t_end`; [`super::moments::observables`]).
    pub fn advance_to<R: Rng + ?Sized>(
        &mut self,
        sys: &mut Particles<'_>,
        t_end: Real,
        rng: &mut R,
    ) -> Result<Observables, EngineError> {
        if !t_end.is_finite() || t_end < self.t {
            return Err(EngineError::TimeBackwards);
        }
        if sys.len() + 2 > sys.capacity() {
            // Started with no room for a collision's particles: reduced now, at this instant.
            self.reduce(sys, rng)?;
        }
        loop {
            let n = sys.len();
            let pairs = 0.5 * n as Real * (n - 1) as Real;
            let rate = pairs
                * (1.0 + self.transfer.kappa_max())
                * self.gmax
                * self.kernel.b_max(self.frame.scale * self.umax)
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
        self.len = sys.len();
        self.counts.observations += 1;
        self.synchronize(sys, rng);
        let mut o = observables(sys, G::CHOICE.d());
        self.rescale(sys, &mut o)?;
        // Every particle through the windows (the measure, and so what was observed, is kept).
        self.split_all(sys);
        self.physical(sys, &o)
    }

    /// One candidate at the current time: the acceptance, the collision, a reduction first
    /// when the buffer is full.
    fn event<R: Rng + ?Sized>(
        &mut self,
        sys: &mut Particles<'_>,
        rng: &mut R,
    ) -> Result<(), EngineError> {
        self.counts.candidates += 1;
        let (i, j) = uniform_pair(rng, sys.len());
        let (gi, gj) = (sys.weight(i), sys.weight(j));
        let heavier = if gi > gj { gi } else { gj };
        // The weights' thinning first: a pair it refuses is neither kicked nor split (a lazy
        // kick covers the whole time since the last one, whenever it comes).
        if uniform01(rng) * self.gmax >= heavier {
            self.counts.fictitious += 1;
            return self.count_refresh(sys, rng);
        }
        self.kick(sys, i, rng);
        self.kick(sys, j, rng);
        let (vi, vj) = (sys.velocity(i), sys.velocity(j));
        let u = vi - vj;
        let speed = u.norm();
        if K::USES_UMAX && speed > self.umax {
            // A drive moved the pair past the bound that drew this waiting time: the kernel
            // is truncated there (RW (19)); the bound then covers the kicked velocities.
            self.counts.overshoots += 1;
        }
        if D::ACTS {
            self.cover([vi, vj]);
        }
        // The kernel's acceptance (GRW (20); 1 for the Maxwell kernel, which draws nothing).
        if K::USES_UMAX && uniform01(rng) >= self.kernel.acceptance(speed, self.umax) {
            self.counts.fictitious += 1;
            self.split(sys, i);
            self.split(sys, j);
        } else {
            let e = G::scattering::<K, R>(u, rng);
            // The law in stored units: at the physical impact velocity (the map is linear).
            let alpha = clamped_coefficient(&self.law, u, e, &mut self.counts);
            let (a, b) = inelastic(vi, vj, e, alpha);
            let lighter = if gi < gj { gi } else { gj };
            let Some(kappa) = self.outcome_kappa((a, b), lighter, rng) else {
                // This outcome's rate is (1 + kappa)/(1 + kappa_max) of the majorant's.
                self.counts.fictitious += 1;
                self.split(sys, i);
                self.split(sys, j);
                return self.count_refresh(sys, rng);
            };
            let before = sys.len();
            let gamma =
                collide_with(sys, (i, j), ((a, b), self.t), kappa).map_err(|e| match e {
                    ParticlesError::Full => EngineError::Invariant("a reduction makes room first"),
                    _ => EngineError::Invariant("a collision keeps every weight > 0"),
                })?;
            self.moved += 2.0 * gamma;
            self.counts.collisions += 1;
            // Cover the new velocities: no pair overshoots the bound in a collision.
            self.cover([a, b]);
            // The windows: a change of state after the collision, at its instant.
            for k in [i, j].into_iter().chain(before..sys.len()) {
                self.split(sys, k);
            }
            if sys.len() + 2 > sys.capacity() {
                self.reduce(sys, rng)?;
            }
        }
        self.count_refresh(sys, rng)
    }

    /// Reduces the particles (all kicked to now first) so that the next collision's fit, and
    /// makes the bounds exact. Called right after the collision that filled the buffer: the
    /// state changes at that instant and the next waiting time is drawn at the new rate. (A
    /// reduction in place of the next candidate, as a first version did, discarded an event
    /// of the old rate: the gas cooled too slowly, z = 7 after a single reduction in 4000
    /// ensembles; core/tests/weighted.rs.)
    fn reduce<R: Rng + ?Sized>(
        &mut self,
        sys: &mut Particles<'_>,
        rng: &mut R,
    ) -> Result<(), EngineError> {
        self.synchronize(sys, rng);
        self.reduction.apply(sys, (self.t, 2), G::CHOICE, rng);
        self.reductions += 1;
        self.refresh(sys)
    }

    /// The `kappa` of the outcome `(a, b)` ([`Transfer::with_tail`]: the tail's when a partner
    /// lands beyond its speed from `vref`, in units of `sqrt(T)` of the last refresh; 0 for a pair
    /// whose lighter partner weighs less than [`LIGHTEST`]), or `None` when the outcome is
    /// thinned away, with probability `1 - (1 + kappa)/(1 + kappa_max)`.
    fn outcome_kappa<R: Rng + ?Sized>(
        &self,
        (a, b): (Vec3, Vec3),
        lighter: Real,
        rng: &mut R,
    ) -> Option<Real> {
        let far =
            |v: Vec3, (_, speed): (Real, Real)| (v - self.vref).norm2() > speed * speed * self.tref;
        let kappa = match self.transfer.tail() {
            _ if lighter < LIGHTEST => 0.0,
            Some(tail) if far(a, tail) || far(b, tail) => tail.0,
            Some(_) | None => self.transfer.kappa(),
        };
        let max = self.transfer.kappa_max();
        (kappa == max || uniform01(rng) * (1.0 + max) < 1.0 + kappa).then_some(kappa)
    }

    /// Counts a candidate toward the next refresh of the bounds, and refreshes them when due.
    fn count_refresh<R: Rng + ?Sized>(
        &mut self,
        sys: &mut Particles<'_>,
        rng: &mut R,
    ) -> Result<(), EngineError> {
        self.until_refresh = self.until_refresh.saturating_sub(1);
        if self.until_refresh == 0 {
            self.counts.refreshes += 1;
            if K::USES_UMAX {
                self.synchronize(sys, rng);
            }
            self.refresh(sys)?;
            // Every particle through the new windows ([`split`]: the shares moved).
            self.split_all(sys);
            // A cooling gas between observations: its temperature about vref from the refresh.
            if !D::ACTS && rescale_due(self.tref, self.vref, RESCALE_BELOW) {
                let mut o = observables(sys, G::CHOICE.d());
                self.rescale(sys, &mut o)?;
            }
        }
        Ok(())
    }

    /// `Umax` grown to cover the velocities `vs` about `vref`.
    #[inline(always)]
    fn cover(&mut self, vs: [Vec3; 2]) {
        for v in vs {
            let c = 2.0 * (v - self.vref).norm();
            if c > self.umax {
                self.umax = c;
            }
        }
    }
}
