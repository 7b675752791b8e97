//! What every Markov-jump event loop does with a candidate pair: the fictitious-collision test
//! against the majorant (GRW (20)), the inelastic map GRW (3) with a uniform direction, and the
//! majorant update with the bound that holds, `max(Umax, 2|v - V|)` (RW (21)).

use super::Counts;
use crate::collision::inelastic;
use crate::kernel::Kernel;
use crate::math::{Real, max};
use crate::particles::Particles;
use crate::restitution::Restitution;
use crate::rng::{Rng, uniform01};
use crate::sample::unit_sphere;
use crate::vec3::Vec3;

/// The adaptive majorant `Umax` of the relative speed and the reference velocity `V` it is
/// measured from (GRW step 1.4: `Umax = 2 max_i |v_i - V|`).
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Majorant {
    /// Current bound on the relative speed.
    pub umax: Real,
    /// Reference velocity.
    pub vref: Vec3,
}

impl Majorant {
    /// Raises the bound to cover `v`: `Umax = max(Umax, 2 |v - V|)`.
    #[inline(always)]
    pub fn cover(&mut self, v: Vec3) {
        self.umax = max(self.umax, 2.0 * (v - self.vref).norm());
    }
}

/// Processes the candidate pair `(i, j)` whose partners are already at the event time.
/// `umax_event` is the majorant that generated the event's waiting time; `cover_kicked` says
/// whether the partners were just kicked (so the majorant must cover their new velocities).
/// Returns true when the majorant changed (the caller then recomputes its rate).
#[inline(always)]
#[allow(clippy::too_many_arguments)]
pub fn candidate<K: Kernel, A: Restitution, R: Rng + ?Sized>(
    kernel: &K,
    restitution: &A,
    p: &mut Particles<'_>,
    i: usize,
    j: usize,
    maj: &mut Majorant,
    cover_kicked: bool,
    counts: &mut Counts,
    rng: &mut R,
) -> bool {
    let (vi, vj) = (p.velocity(i), p.velocity(j));
    let u = vi - vj;
    counts.candidates += 1;
    let umax_event = maj.umax;
    if K::USES_UMAX {
        let urel = u.norm();
        if urel > umax_event {
            counts.overshoots += 1;
        }
        if cover_kicked {
            maj.cover(vi);
            maj.cover(vj);
        }
        if uniform01(rng) >= kernel.acceptance(urel, umax_event) {
            counts.fictitious += 1;
            return maj.umax != umax_event;
        }
    }
    let e = unit_sphere(rng);
    let alpha = clamped_coefficient(restitution, u, e, counts);
    let (a, b) = inelastic(vi, vj, e, alpha);
    p.set_velocity(i, a);
    p.set_velocity(j, b);
    counts.collisions += 1;
    if K::USES_UMAX {
        maj.cover(a);
        maj.cover(b);
    }
    maj.umax != umax_event
}

/// The restitution coefficient of a law, clamped to [0, 1] (counted in
/// [`Counts::clamped`] when it had to be).
#[inline(always)]
pub fn clamped_coefficient<A: Restitution>(a: &A, u: Vec3, e: Vec3, counts: &mut Counts) -> Real {
    let alpha = a.coefficient(u, e);
    if A::CAN_LEAVE_UNIT_INTERVAL && !(0.0..=1.0).contains(&alpha) {
        counts.clamped += 1;
        return if alpha > 1.0 { 1.0 } else { 0.0 };
    }
    alpha
}
