//! What every Markov-jump event loop does with a candidate pair: the fictitious-collision test
//! against the majorant (GRW (20)), the collision map ([`super::CollisionMap`]: GRW (3) or
//! the rough map), and the majorant update with the bound that holds, `max(Umax, 2|v - V|)`
//! (RW (21)); and what every loop does when all particles are at one time
//! ([`Collider::synchronized`], [`observables`]).

use super::collision_map::CollisionMap;
use super::pairs::PairsAhead;
use super::{Counts, EngineError};
use crate::drive::Drive;
use crate::geometry::{Geometry, Spheres};
use crate::kernel::Kernel;
use crate::math::{Real, max, sqrt};
use crate::moments::Observables;
use crate::particles::Particles;
use crate::rng::Rng;
use crate::vec3::Vec3;

/// The adaptive majorant `Umax` of the relative speed and the reference velocity `V` it is
/// measured from (GRW step 1.4: `Umax = 2 max_i |v_i - V|`).
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Majorant {
    /// Current bound on the relative speed.
    pub umax: Real,
    /// Reference velocity.
    pub vref: Vec3,
    /// A squared distance from `vref` below which [`Majorant::cover`] cannot raise `umax`: the
    /// test is made on `|v - V|^2`, and the square root is taken only when it may.
    below2: Real,
}

impl Majorant {
    /// The majorant `umax` about `vref`.
    pub fn new(umax: Real, vref: Vec3) -> Self {
        let half = 0.5 * umax;
        Majorant {
            umax,
            vref,
            // (umax/2)^2 lowered by 1e-15 relative: for |v - V|^2 below it, 2 |v - V| lies
            // below umax by more than the rounding of the square root and the doubling, so
            // `max(umax, 2 |v - V|)` would keep umax: skipping it changes no bit.
            below2: half * half * (1.0 - 1e-15),
        }
    }

    /// The exact majorant of a gas whose observables are `obs`, `Umax = 2 max_i |v_i - V|`
    /// about its bulk velocity `V` (GRW step 1.4): every loop's start and synchronization.
    pub fn about(obs: &Observables) -> Self {
        Majorant::new(2.0 * obs.max_peculiar_speed, obs.bulk)
    }

    /// Raises the bound to cover `v`: `Umax = max(Umax, 2 |v - V|)` (RW (21)), the same bits as
    /// computing it every time, with a square root only when `|v - V|^2` passes the last one.
    #[inline(always)]
    pub fn cover(&mut self, v: Vec3) {
        let d2 = (v - self.vref).norm2();
        if d2 > self.below2 {
            self.below2 = d2;
            self.umax = max(self.umax, 2.0 * sqrt(d2));
        }
    }
}

/// What the Markov-jump loops ([`super::NoSplitting`], [`super::Splitting`]) share: the
/// physics (kernel, drive, restitution law), the majorant, the counts and the pairs drawn
/// ahead, with the two things both do the same way: process a candidate pair and synchronize.
/// `G` is the dimension ([`crate::geometry`]): it chooses the scattering direction.
#[derive(Clone, Debug)]
pub struct Collider<K, D, A, G = Spheres> {
    /// The collision kernel.
    pub kernel: K,
    /// The drive.
    pub drive: D,
    /// The collision map: a restitution law (smooth particles) or the rough map.
    pub map: A,
    /// The majorant of the relative speed.
    pub maj: Majorant,
    /// Event counts.
    pub counts: Counts,
    /// Candidate pairs drawn ahead.
    pub pairs: PairsAhead,
    dim: core::marker::PhantomData<G>,
}

impl<K: Kernel, D: Drive, A: CollisionMap, G: Geometry> Collider<K, D, A, G> {
    /// The physics with an empty majorant and zero counts.
    pub fn new(kernel: K, drive: D, map: A) -> Self {
        Collider {
            kernel,
            drive,
            map,
            maj: Majorant::default(),
            counts: Counts::default(),
            pairs: PairsAhead::default(),
            dim: core::marker::PhantomData,
        }
    }

    /// The majorant event rate of `n` particles whose stored speeds are `scale` times smaller
    /// than the physical ones (GRW Section 3, RW (20)).
    #[inline(always)]
    pub fn rate(&self, n: usize, scale: Real) -> Real {
        self.kernel.majorant_rate(n, scale * self.maj.umax)
    }

    /// [`crate::engine::EventLoop::work_rate`] of a loop on this collider: the majorant's
    /// candidates ([`Collider::rate`]) and `n` times the drive's events per grain at the
    /// largest speed the majorant allows, `|V| + Umax / 2` (physical: `offset + scale V`).
    pub fn work_rate(&self, n: usize, scale: Real, offset: Vec3) -> Real {
        let speed = (offset + scale * self.maj.vref).norm() + 0.5 * scale * self.maj.umax;
        self.rate(n, scale) + n as Real * self.drive.event_rate(speed)
    }

    /// The next candidate pair (uniform, drawn ahead), both partners kicked lazily to the event
    /// time `t` (GRW steps 2.3-2.6).
    #[inline(always)]
    pub fn kicked_pair<R: Rng + ?Sized>(
        &mut self,
        p: &mut Particles<'_>,
        t: Real,
        rng: &mut R,
    ) -> (usize, usize) {
        let (i, j) = self.pairs.next(p, rng);
        self.drive
            .kick_pair_counting(p, (i, j), t, rng, &mut self.counts.background);
        (i, j)
    }

    /// Processes the candidate pair `(i, j)` whose partners are already at the event time: the
    /// fictitious-collision test against the majorant that generated the event (GRW (20)),
    /// else the collision map ([`CollisionMap::collide_pair`]: GRW (3) with a scattering
    /// direction, or the rough map); the majorant covers the new velocities (and the kicked
    /// ones when `cover_kicked`). Returns true when the majorant changed (the caller
    /// then recomputes its rate).
    #[inline(always)]
    pub fn candidate<R: Rng + ?Sized>(
        &mut self,
        p: &mut Particles<'_>,
        i: usize,
        j: usize,
        cover_kicked: bool,
        accept: Real,
        rng: &mut R,
    ) -> bool {
        let (vi, vj) = (p.velocity(i), p.velocity(j));
        let umax_event = self.maj.umax;
        if !admits(
            &self.kernel,
            &mut self.maj,
            &mut self.counts,
            (vi, vj),
            cover_kicked,
            accept,
        ) {
            return self.maj.umax != umax_event;
        }
        let (a, b) = self
            .map
            .collide_pair::<K, G, R>(p, (i, j), (vi, vj), rng, &mut self.counts);
        self.counts.collisions += 1;
        if K::USES_UMAX {
            self.maj.cover(a);
            self.maj.cover(b);
        }
        self.maj.umax != umax_event
    }

    /// Every particle is at one time and `obs` are its observables (in stored units): count
    /// the synchronization, tell the drive (drives acting about the bulk velocity take it from
    /// here), and make the majorant exact, `Umax = 2 max |v_i - V|` (GRW step 1.4).
    pub fn synchronized(&mut self, obs: &Observables) {
        self.counts.observations += 1;
        self.drive.observe(obs);
        if K::USES_UMAX {
            self.maj = Majorant::about(obs);
        }
    }
}

/// The fictitious-collision test of a candidate pair with velocities `vi`, `vj` at the event
/// time, against the majorant that generated the event (GRW (20)): counts the candidate (and
/// an overshoot of the majorant, after which the kernel is truncated, RW (19)), lets the
/// majorant cover the kicked velocities when `cover_kicked` (RW (21)), and returns whether
/// the pair collides for real (counting a fictitious one) when the uniform `accept` in (0, 1)
/// falls below the kernel's ratio. Kernels with no `Umax` always collide (and `accept` is not
/// read). Every Markov-jump loop's candidates pass through here.
#[inline(always)]
pub fn admits<K: Kernel>(
    kernel: &K,
    maj: &mut Majorant,
    counts: &mut Counts,
    (vi, vj): (Vec3, Vec3),
    cover_kicked: bool,
    accept: Real,
) -> bool {
    counts.candidates += 1;
    if !K::USES_UMAX {
        return true;
    }
    let umax_event = maj.umax;
    let u2 = (vi - vj).norm2();
    if u2 > umax_event * umax_event {
        counts.overshoots += 1;
    }
    if cover_kicked {
        maj.cover(vi);
        maj.cover(vj);
    }
    if !kernel.accepts(u2, umax_event, accept) {
        counts.fictitious += 1;
        return false;
    }
    true
}

/// The observables of a synchronized system, or [`EngineError::NonFinite`] (every loop's
/// check after a synchronization).
pub fn observables(p: &Particles<'_>) -> Result<Observables, EngineError> {
    observables_dim(p, 3)
}

/// As [`observables`] in `d` dimensions ([`Observables::of_dim`]).
pub fn observables_dim(p: &Particles<'_>, d: usize) -> Result<Observables, EngineError> {
    let obs = Observables::of_dim(p, d);
    match obs.non_finite() {
        None => Ok(obs),
        Some(what) => Err(EngineError::NonFinite(what)),
    }
}

/// When a no-splitting loop makes its majorant exact between observations (module docs of
/// [`super::NoSplitting`]): with no drive every `2n` candidates; with a drive when more than
/// half of the last `after` candidates were fictitious, the window doubling after a refresh
/// that gained little (a steady gas soon stops paying the O(n) cost).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct RefreshWindow {
    after: u64,
    window: u64,
    wasted: u64,
}

impl RefreshWindow {
    /// The schedule of an `n`-particle system: first window `2n`.
    pub fn new(n: usize) -> Self {
        RefreshWindow {
            after: 2 * n as u64,
            window: 0,
            wasted: 0,
        }
    }

    /// Counts from zero again (a new advance, or after the bound was made exact).
    #[inline(always)]
    pub fn restart(&mut self) {
        (self.window, self.wasted) = (0, 0);
    }

    /// One more candidate, `fictitious` of them (0 or 1) rejected.
    #[inline(always)]
    pub fn record(&mut self, fictitious: u64) {
        self.window += 1;
        self.wasted += fictitious;
    }

    /// `k` more candidates, every one a collision.
    #[inline(always)]
    pub fn record_collisions(&mut self, k: u64) {
        self.window += k;
    }

    /// No drive: `2n` candidates since the last synchronization.
    #[inline(always)]
    pub fn synchronization_due(&self, n: usize) -> bool {
        self.until_synchronization(n) == 0
    }

    /// No drive: the candidates left before the synchronization is due.
    #[inline(always)]
    pub fn until_synchronization(&self, n: usize) -> u64 {
        (2 * n as u64).saturating_sub(self.window)
    }

    /// With a drive: the window is full and more than half of it was fictitious.
    #[inline(always)]
    pub fn refresh_due(&self) -> bool {
        self.window >= self.after && 2 * self.wasted > self.window
    }

    /// After a refresh that took the (physical) bound from `before` to `now`: the next window
    /// doubles when the bound fell by less than a fifth, else it is `2n` again; counts restart.
    pub fn refreshed(&mut self, before: Real, now: Real, n: usize) {
        self.after = if now > 0.8 * before {
            self.after.saturating_mul(2)
        } else {
            2 * n as u64
        };
        self.restart();
    }
}
