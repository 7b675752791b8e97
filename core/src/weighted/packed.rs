//! Weighted particles packed for a reduction: each record's last-kick slot carries its weight.
//!
//! A reduction runs with every particle at one time (the loop kicks them all there first), so
//! while it sorts, splits and replaces records in place the last-kick time says nothing; the
//! weight rides in that slot instead, and the records move as one (a k-d split permutes one
//! slice, not two). [`pack`] before, [`unpack`] after: the weights back in their slice and
//! every last-kick time the reduction's.

use crate::math::Real;
use crate::particles::{Particle, Particles};
use crate::vec3::Vec3;

/// The weight of a packed record.
#[inline(always)]
pub(crate) fn weight(q: &Particle) -> Real {
    q.t_kick
}

/// A packed record of velocity `v` and weight `g`.
#[inline(always)]
pub(crate) fn packed(v: Vec3, g: Real) -> Particle {
    Particle::new(v, g)
}

/// Each weighted particle's weight into its record's last-kick slot: the records, the
/// weights' slice (free until [`unpack`]: scratch, one number a record) and the records in use.
pub(crate) fn pack<'b>(p: &'b mut Particles<'_>) -> (&'b mut [Particle], &'b mut [Real], usize) {
    let len = p.len();
    let (records, weights) = p.buffers_mut();
    for (q, &g) in records[..len].iter_mut().zip(&weights[..len]) {
        q.t_kick = g;
    }
    (records, weights, len)
}

/// Keeps the first `len` packed records, their weights back in their slice, every last-kick
/// time `t`.
pub(crate) fn unpack(p: &mut Particles<'_>, len: usize, t: Real) {
    p.truncate(len);
    let (records, weights) = p.buffers_mut();
    for (q, g) in records[..len].iter_mut().zip(&mut weights[..len]) {
        *g = q.t_kick;
        q.t_kick = t;
    }
}
