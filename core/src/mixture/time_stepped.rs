//! MS's time-stepped scheme (MS Section 3; Bird's no-time-counter form for the Maxwell and VHS
//! kernels, [`crate::engine::time_stepped`]) for a mixture of `S` species: each pair type
//! `(s, t)` is a collision stage of its own, as each pair type is a majorant of its own in the
//! exact loop ([`super::MixtureNoSplitting`]).
//!
//! Each step of length `h`: pair type `(s, t)` (with `P_st` unordered pairs: `N_s N_t`, or
//! `N_s (N_s - 1)/2` for `s = t`) draws `P_st omega_max,st h / N` candidates (whole numbers, the
//! fraction carried), the partners uniform within their species, each tested and collided as
//! one species' candidates are, by the pair type's kernel, bound and collision map (smooth
//! particles of two masses, [`super::MassMap`], or rough ones, [`crate::rough::RoughPair`]);
//! the pair types take their turns in [`super::Species::pair`] order. Then every particle of
//! species `s` is kicked by its drive for `h`. Each unordered pair collides at `(1/N) int B de`,
//! the exact loop's rate, so a one-species mixture is [`crate::engine::TimeStepped`] to the
//! last bit (tests/mixture.rs).
//!
//! The step is the shortest of the pair types' `f / (sqrt(2) B_st(v_0,st))` with the relative
//! thermal speed `v_0,st = (T_s + T_t)^{1/2}` (`T_s = <|c|^2>_s / d` of species `s`, about its
//! own bulk velocity; one species: `(2 T)^{1/2}`), so that no pair type takes more than `f`
//! mean free times per step. Each stage's bound starts from the exact loop's `U_st`
//! (`|v_i - v_j| <= S_s + S_t + |V_s - V_t|`) and rises at each overshoot.

use super::StartError;
use super::drives::{kick_species, tell_drives};
use super::map::PairLaw;
use super::nosplit::{MixtureNoSplitting, PairPhysics, drives_off};
use crate::drive::{Drive, NoDrive};
use crate::engine::collision_map::CollisionMap;
use crate::engine::frame::Frame;
use crate::engine::time_stepped::{Stage, next_step};
use crate::engine::{Counts, EngineError, check_step};
use crate::geometry::{Geometry, Spheres};
use crate::kernel::Kernel;
use crate::math::{Real, min, sqrt};
use crate::observe::MixtureObservables;
use crate::particles::Particles;
use crate::rng::{Rng, uniform_index2, uniform_pair};
use crate::species::{MAX_PAIRS, MAX_SPECIES, Species};

/// MS's time-stepped scheme for a mixture: kernel `K`, drive `D` (one per species), pair law
/// `L` (one per pair type), dimension `G` (spheres unless named).
#[derive(Clone, Debug)]
pub struct MixtureTimeStepped<K, D, L: PairLaw, G = Spheres> {
    /// The exact loop, never advanced: its pair table (kernels, maps, species), bounds and
    /// observables.
    table: MixtureNoSplitting<K, NoDrive, L, G>,
    stages: [Stage<K, G>; MAX_PAIRS],
    drives: [D; MAX_SPECIES],
    step_factor: Real,
    /// Each species' `T_s` at the end of the last step.
    temperatures: [Real; MAX_SPECIES],
    t: Real,
    steps: u64,
    counts: Counts,
}

impl<K: Kernel, D: Drive, L: PairLaw, G: Geometry> MixtureTimeStepped<K, D, L, G> {
    /// Starts the scheme at `t0` with step factor `f > 0` (the arguments of
    /// [`MixtureNoSplitting::start`] and the factor), in dimension `G` (named by the result's
    /// type). Returns the observables at `t0`.
    #[inline(never)]
    pub fn start(
        sp: Species,
        physics: &[PairPhysics<K, L>],
        drives: &[D],
        step_factor: Real,
        p: &mut Particles<'_>,
        t0: Real,
    ) -> Result<(Self, MixtureObservables), StartError> {
        check_step(step_factor).map_err(StartError::Engine)?;
        let (table, obs) = drives_off(sp, physics, drives, p, t0)?;
        let mut s = MixtureTimeStepped {
            table,
            stages: core::array::from_fn(|k| {
                Stage::new(physics[k.min(sp.pair_types() - 1)].kernel)
            }),
            drives: core::array::from_fn(|k| drives[k.min(sp.len() - 1)]),
            step_factor,
            temperatures: [0.0; MAX_SPECIES],
            t: t0,
            steps: 0,
            // Observations count the advances, as the one-species scheme's do.
            counts: Counts::default(),
        };
        s.observed(&obs);
        s.cover();
        Ok((s, obs))
    }

    /// Current time.
    pub fn time(&self) -> Real {
        self.t
    }

    /// Event counts so far (all pair types).
    pub fn counts(&self) -> Counts {
        self.counts
    }

    /// Steps taken so far.
    pub fn steps(&self) -> u64 {
        self.steps
    }

    /// Stored and physical velocities coincide.
    pub fn velocity_map(&self) -> Frame {
        Frame::IDENTITY
    }

    /// Each species' observables of the particles `p` (right after an advance or a start).
    pub fn species_now(&self, p: &Particles<'_>) -> MixtureObservables {
        self.table.species_now(p)
    }

    /// Candidates per unit time of pair type `k`: `P_st omega_max,st / N` (module docs).
    fn type_rate(&self, k: usize) -> Real {
        let sp = self.table.species();
        let n = sp.total();
        let (s, t) = sp.pair(k);
        let rate = self.stages[k].candidate_rate();
        if s == t {
            let ns = sp.count(s);
            if ns < 2 {
                0.0
            } else {
                0.5 * (ns - 1) as Real * rate * (ns as Real / n as Real)
            }
        } else {
            rate * (sp.pairs(s, t) / n as Real)
        }
    }

    /// The step length: the shortest of the pair types' (module docs).
    pub fn step_length(&self) -> Real {
        let sp = self.table.species();
        let mut h = Real::INFINITY;
        for k in 0..sp.pair_types() {
            let (s, t) = sp.pair(k);
            let v0 = sqrt(self.temperatures[s] + self.temperatures[t]);
            h = min(h, self.stages[k].step_length(self.step_factor, v0));
        }
        h
    }

    /// Work units per unit time from here ([`crate::engine::EventLoop::work_rate`]): every
    /// pair type's candidates and `n` kicks per step.
    pub fn work_rate(&self, n: usize) -> Real {
        let types = self.table.species().pair_types();
        let candidates: Real = (0..types).map(|k| self.type_rate(k)).sum();
        candidates + n as Real / self.step_length()
    }

    /// Runs steps up to `t_end` (the last one shortened to land on it) and returns the
    /// observables there.
    #[inline(never)]
    pub fn advance_to<R: Rng + ?Sized>(
        &mut self,
        p: &mut Particles<'_>,
        t_end: Real,
        rng: &mut R,
    ) -> Result<MixtureObservables, EngineError> {
        if !t_end.is_finite() || t_end < self.t {
            return Err(EngineError::TimeBackwards);
        }
        self.counts.observations += 1;
        let sp = *self.table.species();
        while self.t < t_end {
            let (h, t_next) = next_step(self.t, t_end, self.step_length());
            for k in 0..sp.pair_types() {
                let m = self.stages[k].count(self.type_rate(k), h);
                let (s, t) = sp.pair(k);
                let map = self.table.pair_map(k);
                for _ in 0..m {
                    let pair = if s == t {
                        let (a, b) = uniform_pair(rng, sp.count(s));
                        (sp.offset(s) + a, sp.offset(s) + b)
                    } else {
                        {
                            let (a, b) = uniform_index2(rng, sp.count(s), sp.count(t));
                            (sp.offset(s) + a, sp.offset(t) + b)
                        }
                    };
                    self.stages[k].candidate(&map, p, pair, rng, &mut self.counts);
                }
            }
            self.t = t_next;
            if D::ACTS {
                let background = &mut self.counts.background;
                kick_species(&self.drives, &sp, p, self.t, rng, background);
            }
            self.steps += 1;
            let obs = MixtureObservables::of_dim(p.as_slice(), &sp, G::CHOICE);
            if let Some(what) = obs.all.non_finite() {
                return Err(EngineError::NonFinite(what));
            }
            self.observed(&obs);
        }
        if L::Map::SPINS {
            crate::engine::nosplit::spins_finite(p)?;
        }
        Ok(self.table.species_now(p))
    }

    /// Re-synchronizes after the caller changed velocities between calls.
    pub fn resync(&mut self, p: &mut Particles<'_>) -> Result<MixtureObservables, EngineError> {
        let obs = self.table.resync(p)?;
        p.reset_kick_times(self.t);
        self.observed(&obs);
        self.cover();
        Ok(obs)
    }

    /// Tells the drives and the step length the observables `obs` of the particles now.
    fn observed(&mut self, obs: &MixtureObservables) {
        for s in 0..obs.len {
            self.temperatures[s] = obs.species[s].t_bulk;
        }
        tell_drives(&mut self.drives, obs);
    }

    /// Raises each stage's bound to the exact loop's `U_st` of the synchronized particles.
    fn cover(&mut self) {
        for k in 0..self.table.species().pair_types() {
            self.stages[k].cover(self.table.pair_bound(k));
        }
    }
}

crate::engine::impl_event_loop!(
    MixtureTimeStepped,
    [K: Kernel, D: Drive, L: PairLaw, G: Geometry],
    MixtureTimeStepped<K, D, L, G>,
    {
        #[inline(never)]
        fn species(&self, p: &Particles<'_>) -> Option<MixtureObservables> {
            Some(MixtureTimeStepped::species_now(self, p))
        }
    }
);

/// The collisional cooling ([`crate::engine::EventLoop::cooling`]).
impl<K: Kernel, D: Drive, L: PairLaw, G: Geometry> MixtureTimeStepped<K, D, L, G> {
    /// The collision frequency and `zeta*` of `p` now from `pairs` random pairs: the pair
    /// table's ([`MixtureNoSplitting::cooling`]).
    pub fn cooling<R: Rng + ?Sized>(
        &self,
        p: &Particles<'_>,
        pairs: u64,
        rng: &mut R,
    ) -> crate::observe::Cooling {
        self.table.cooling(p, pairs, rng)
    }
}
