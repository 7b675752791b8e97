//! The no-splitting scheme (GRW Section 3, RW Algorithm 3) for a mixture of `S` species.
//!
//! Pair type `(s, t)` (with `P_st` unordered pairs: `N_s N_t`, or `N_s (N_s - 1)/2` for
//! `s = t`) has the majorant rate `P_st B_max,st(U_st) / N`, with `B_max` of GRW (19) for that
//! pair's kernel: each unordered pair collides at `(1/N) int B de`, as in GRW Section 3 for
//! one species. Waiting times are exponential with the total rate; the pair type is chosen by
//! its rate, the particles uniformly within their species; the candidate is fictitious with
//! probability `1 - (|u| / U_st)^lambda` (GRW (20)); otherwise the pair type's collision map
//! ([`super::PairLaw`]: smooth particles of two masses, [`super::MassMap`], or rough ones,
//! [`crate::rough::RoughPair`]) in dimension `G`. There is no time step: the process is the
//! mixture's Markov jump process exactly, as the one-species loop is (the same thinning
//! argument, per pair type). Rotation does not enter the collision rate, so a rough mixture
//! differs only in its map, its drive (white noise on translation and rotation per species,
//! [`crate::rough::RoughNoise`]) and its observables.
//!
//! The majorant of pair type `(s, t)`: with `V_s` the bulk velocity of species `s` and
//! `S_s >= max_{i in s} |v_i - V_s|`, the triangle inequality gives
//! `|v_i - v_j| <= S_s + S_t + |V_s - V_t| = U_st` (`U_ss = 2 S_s`, GRW step 1.4 for one
//! species). Each `S_s` is raised after every kick and collision as in RW (21); overshoots by
//! untouched diffusing particles are counted, as in the one-species loop. With every particle
//! at one time (observations, and refreshes every `2N` candidates with no drive, or when the
//! bound went loose with one) the `S_s` and `V_s` are made exact.
//!
//! A one-species mixture draws the same random numbers as [`crate::engine::NoSplitting`]
//! below [`crate::engine::pairs::PREFETCH_FROM`] particles (no pair-type draw for one type; pairs
//! drawn when used) and gives its results to the last bit.

mod events;
mod observe;

use super::StartError;
use super::drives::kick_species;
use super::map::PairLaw;
use crate::drive::{Drive, NoDrive};
use crate::engine::collision_map::CollisionMap;
use crate::engine::event::{Majorant, RefreshWindow};
use crate::engine::frame::Frame;
use crate::engine::{Counts, EngineError};
use crate::geometry::{Geometry, Spheres};
use crate::kernel::Kernel;
use crate::math::{Real, max};
use crate::observe::MixtureObservables;
use crate::particles::Particles;
use crate::rng::{Rng, halves, unit_open32};
use crate::sample::{exponential_from_half, standard_exponential};
use crate::species::{MAX_PAIRS, MAX_SPECIES, MixtureError, Species, pair_index};

/// The physics of one pair type `(s, t)`: kernel and particle model (a restitution law, or
/// [`crate::rough::RoughPairLaw`]); the masses are the species'.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct PairPhysics<K, A> {
    /// The collision kernel of the pair (e.g. hard spheres of diameter `(d_s + d_t)/2`).
    pub kernel: K,
    /// The pair's law ([`PairLaw`]).
    pub restitution: A,
}

/// The exact event loop of a mixture: kernel type `K`, drive type `D` (one per species),
/// pair law `L` (one per pair type: a restitution law, or rough particles) and dimension `G`
/// (spheres unless named).
#[derive(Clone, Debug)]
pub struct MixtureNoSplitting<K, D, L: PairLaw, G = Spheres> {
    sp: Species,
    kernels: [K; MAX_PAIRS],
    maps: [L::Map; MAX_PAIRS],
    /// Each species' reduced moment of inertia (rough particles; 0 otherwise).
    kappa: [Real; MAX_SPECIES],
    pair_of: [(usize, usize); MAX_PAIRS],
    drives: [D; MAX_SPECIES],
    maj: [Majorant; MAX_SPECIES],
    /// `|V_s - V_t|` of each pair type at the last synchronization (stored units).
    apart: [Real; MAX_PAIRS],
    /// Cumulative majorant rates of the pair types (physical time).
    cumulative: [Real; MAX_PAIRS],
    /// The last pair type with a positive rate.
    last: usize,
    counts: Counts,
    pair_collisions: [u64; MAX_PAIRS],
    t: Real,
    refresh: RefreshWindow,
    frame: Frame,
    /// Whether a cooling mixture's velocities may be stored rescaled (not under a splitting,
    /// whose kicks move physical velocities).
    rescale: bool,
    dim: core::marker::PhantomData<G>,
}

impl<K: Kernel, D: Drive, L: PairLaw> MixtureNoSplitting<K, D, L> {
    /// Starts the scheme at `t0` on the particles `p` (species `s` in `sp.range(s)`, velocities
    /// already set; rough particles with one spin each) with one [`PairPhysics`] per pair type
    /// (in [`Species::pair`] order) and one drive per species. Returns the observables at `t0`.
    /// Spheres; disks: [`MixtureNoSplitting::start_in`].
    pub fn start(
        sp: Species,
        physics: &[PairPhysics<K, L>],
        drives: &[D],
        p: &mut Particles<'_>,
        t0: Real,
    ) -> Result<(Self, MixtureObservables), StartError> {
        Self::start_in(sp, physics, drives, p, t0)
    }
}

impl<K: Kernel, D: Drive, L: PairLaw, G: Geometry> MixtureNoSplitting<K, D, L, G> {
    /// As [`MixtureNoSplitting::start`] in dimension `G` (named by the result's type).
    #[inline(never)]
    pub fn start_in(
        sp: Species,
        physics: &[PairPhysics<K, L>],
        drives: &[D],
        p: &mut Particles<'_>,
        t0: Real,
    ) -> Result<(Self, MixtureObservables), StartError> {
        crate::engine::open(p, t0, L::Map::SPINS).map_err(StartError::Engine)?;
        let types = sp.pair_types();
        if physics.len() != types {
            return Err(StartError::Mixture(MixtureError::PairCount {
                expected: types,
                got: physics.len(),
            }));
        }
        if drives.len() != sp.len() {
            return Err(StartError::Mixture(MixtureError::SpeciesCount(
                drives.len(),
            )));
        }
        if p.len() != sp.total() {
            return Err(StartError::Mixture(MixtureError::ParticleCount));
        }
        let maps: [L::Map; MAX_PAIRS] = core::array::from_fn(|k| {
            let k = k.min(types - 1);
            let (a, b) = sp.pair(k);
            physics[k].restitution.between(sp.mass(a), sp.mass(b))
        });
        let mut s = MixtureNoSplitting {
            sp,
            kernels: core::array::from_fn(|k| physics[k.min(types - 1)].kernel),
            maps,
            kappa: core::array::from_fn(|s| {
                let s = s.min(sp.len() - 1);
                physics[pair_index(sp.len(), s, s)].restitution.inertia().0
            }),
            pair_of: core::array::from_fn(|k| sp.pair(k.min(types - 1))),
            drives: core::array::from_fn(|k| drives[k.min(sp.len() - 1)]),
            maj: [Majorant::default(); MAX_SPECIES],
            apart: [0.0; MAX_PAIRS],
            cumulative: [0.0; MAX_PAIRS],
            last: 0,
            counts: Counts::default(),
            pair_collisions: [0; MAX_PAIRS],
            t: t0,
            refresh: RefreshWindow::new(p.len()),
            frame: Frame::IDENTITY,
            rescale: true,
            dim: core::marker::PhantomData,
        };
        let obs = s.synchronized(p).map_err(StartError::Engine)?;
        Ok((s, obs))
    }

    /// Current time.
    pub fn time(&self) -> Real {
        self.t
    }

    /// The loop that keeps physical velocities stored (for the splittings' collision steps).
    pub(super) fn never_rescaled(mut self) -> Self {
        self.rescale = false;
        self
    }

    /// Event counts so far (all pair types).
    pub fn counts(&self) -> Counts {
        self.counts
    }

    /// Real collisions of pair type `k` so far ([`Species::pair`] order).
    pub fn pair_collisions(&self, k: usize) -> u64 {
        self.pair_collisions[k]
    }

    /// The species.
    pub fn species(&self) -> &Species {
        &self.sp
    }

    /// The collision map of pair type `k` (the time-stepped scheme's table).
    pub(super) fn pair_map(&self, k: usize) -> L::Map {
        self.maps[k]
    }

    /// The majorant `U_st` of pair type `k` in physical units (the time-stepped scheme's
    /// start; 0 for the Maxwell kernel, which keeps none).
    pub(super) fn pair_bound(&self, k: usize) -> Real {
        self.frame.scale * self.pair_umax(k)
    }

    /// The majorant `U_st` of pair type `k` (stored units).
    #[inline(always)]
    fn pair_umax(&self, k: usize) -> Real {
        let (s, t) = self.pair_of[k];
        if s == t {
            self.maj[s].umax
        } else {
            0.5 * (self.maj[s].umax + self.maj[t].umax) + self.apart[k]
        }
    }

    /// The majorant rate of pair type `k` (physical units).
    fn type_rate(&self, k: usize) -> Real {
        let n = self.sp.total();
        let (s, t) = self.pair_of[k];
        let umax = self.frame.scale * self.pair_umax(k);
        let kernel = &self.kernels[k];
        if s == t {
            let ns = self.sp.count(s);
            if ns < 2 {
                0.0
            } else {
                kernel.majorant_rate(ns, umax) * (ns as Real / n as Real)
            }
        } else {
            kernel.b_max(umax) * (self.sp.pairs(s, t) / n as Real)
        }
    }

    /// Work units per unit time from here ([`crate::engine::EventLoop::work_rate`]): the
    /// majorant's candidates of every pair type and, per species, its count times its drive's
    /// events per grain at the largest speed its majorant allows (`|V_s| + Umax_s / 2`). The
    /// species' counts sum to `n`.
    pub fn work_rate(&self, _n: usize) -> Real {
        let candidates: Real = (0..self.sp.pair_types()).map(|k| self.type_rate(k)).sum();
        let events: Real = (0..self.sp.len())
            .map(|s| {
                let m = &self.maj[s];
                let speed = (self.frame.offset + self.frame.scale * m.vref).norm()
                    + 0.5 * self.frame.scale * m.umax;
                self.sp.count(s) as Real * self.drives[s].event_rate(speed)
            })
            .sum();
        candidates + events
    }

    /// Recomputes the cumulative majorant rates; returns the total.
    fn rates(&mut self) -> Real {
        let mut total = 0.0;
        for k in 0..self.sp.pair_types() {
            let r = self.type_rate(k);
            total += r;
            self.cumulative[k] = total;
            if r > 0.0 {
                self.last = k;
            }
        }
        total
    }

    /// Runs the process to `t_end >= time()`, kicks every particle there and returns the
    /// observables (GRW steps 2-3 per pair type, module docs).
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
        let n = p.len();
        let mut rate = self.rates();
        self.refresh.restart();
        loop {
            if !D::ACTS && self.refresh.synchronization_due(n) {
                self.synchronized(p)?;
                self.counts.observations -= 1;
                rate = self.rates();
                self.refresh.restart();
            } else if D::ACTS && K::USES_UMAX && self.refresh.refresh_due() {
                let before = self.frame.scale * self.bound();
                self.kick_all(p, self.t, rng);
                self.synchronized(p)?;
                self.counts.observations -= 1;
                self.counts.refreshes += 1;
                rate = self.rates();
                self.refresh
                    .refreshed(before, self.frame.scale * self.bound(), n);
            }
            if !D::ACTS && !K::USES_UMAX {
                self.counted(p, t_end, rate, rng)?;
                break;
            }
            // With a `Umax`, the waiting time and the acceptance uniform from one word; without,
            // the waiting time from a word of its own: as the one-species loop's (stream
            // version 2).
            let (wait, accept) = if K::USES_UMAX {
                let (hi, lo) = halves(rng.next_u64());
                (exponential_from_half(rng, lo), unit_open32(hi))
            } else {
                (standard_exponential(rng), 0.0)
            };
            let t_next = self.t + wait / rate;
            if t_next.partial_cmp(&t_end) != Some(core::cmp::Ordering::Less) {
                break;
            }
            self.t = t_next;
            let before = self.counts.fictitious;
            if self.event(p, t_next, rate, accept, rng) {
                rate = self.rates();
            }
            self.refresh.record(self.counts.fictitious - before);
        }
        self.t = t_end;
        self.kick_all(p, t_end, rng);
        self.synchronized(p)
    }

    /// The largest species majorant (for the refresh rule's "did it gain" test).
    fn bound(&self) -> Real {
        (0..self.sp.len()).fold(0.0, |m, s| max(m, self.maj[s].umax))
    }

    /// Brings every particle to `t`, species by species with its drive.
    fn kick_all<R: Rng + ?Sized>(&mut self, p: &mut Particles<'_>, t: Real, rng: &mut R) {
        if D::ACTS {
            kick_species(
                &self.drives,
                &self.sp,
                p,
                t,
                rng,
                &mut self.counts.background,
            );
        }
    }
}

/// The exact loop with the drives off ([`drives_off`]).
pub(super) type Undriven<K, L, G> = MixtureNoSplitting<K, NoDrive, L, G>;

/// The exact loop with the drives off and velocities never stored rescaled (a kick moves
/// physical velocities), started at `t0`: the collision process of RW's splittings and the
/// pair table of the time-stepped scheme, which kick every species with `drives` themselves
/// (one per species: [`MixtureError::SpeciesCount`] otherwise).
pub(super) fn drives_off<K: Kernel, D: Drive, L: PairLaw, G: Geometry>(
    sp: Species,
    physics: &[PairPhysics<K, L>],
    drives: &[D],
    p: &mut Particles<'_>,
    t0: Real,
) -> Result<(Undriven<K, L, G>, MixtureObservables), StartError> {
    if drives.len() != sp.len() {
        return Err(StartError::Mixture(MixtureError::SpeciesCount(
            drives.len(),
        )));
    }
    let off = [NoDrive; MAX_SPECIES];
    let (table, obs) = MixtureNoSplitting::start_in(sp, physics, &off[..sp.len()], p, t0)?;
    Ok((table.never_rescaled(), obs))
}

crate::engine::impl_event_loop!(
    MixtureNoSplitting,
    [K: Kernel, D: Drive, L: PairLaw, G: Geometry],
    MixtureNoSplitting<K, D, L, G>,
    {
        #[inline(never)]
        fn species(&self, p: &Particles<'_>) -> Option<MixtureObservables> {
            Some(MixtureNoSplitting::species_now(self, p))
        }
    }
);
