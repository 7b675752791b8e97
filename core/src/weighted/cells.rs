//! Cells of nearby velocities for a reduction: a run of particles split at the median of its
//! widest velocity component, recursively and in place (a k-d partition), until a cell is
//! small; each cell of 3 or more particles is then replaced by a sample of two of its own
//! velocities ([`Tally::replace`]). Grouping by the velocity vector keeps a reduction local: a
//! cell's sample lies where its particles were (grouping by speed alone mixes directions).

use super::group::Tally;
use super::packed::weight;
use crate::geometry::DimensionChoice;
use crate::math::Real;
use crate::particles::Particle;
use crate::rng::Rng;

/// Component `k` of a particle's velocity.
fn component(p: &Particle, k: usize) -> Real {
    match k {
        0 => p.vx,
        1 => p.vy,
        _ => p.vz,
    }
}

/// Reduces the packed records `buf[a..b]` ([`super::packed`]) cell by cell (module docs; each
/// cell's sample marked and counted in `tally`, [`Tally::replace`]), writing what is left from
/// `buf[*out]` on (`*out <= a`: what a call writes never passes what it has read) and
/// advancing `*out`. A cell is small when `small(len, weight)` holds of its number of
/// particles and their weight (summed in order), or it has at most 2 particles.
pub(crate) fn reduce_cells<R: Rng + ?Sized>(
    buf: &mut [Particle],
    (a, b): (usize, usize),
    out: &mut usize,
    small: &impl Fn(usize, Real) -> bool,
    (tally, dim, rng): (&mut Tally, DimensionChoice, &mut R),
) {
    debug_assert!(*out <= a);
    // Every component's range and the weight in one pass over the cell (a comparison each,
    // not `f64::min`'s NaN handling: no velocity is NaN).
    let (mut lo, mut hi, mut w) = ([Real::INFINITY; 3], [Real::NEG_INFINITY; 3], 0.0);
    for p in &buf[a..b] {
        for (k, x) in [p.vx, p.vy, p.vz].into_iter().enumerate() {
            if x < lo[k] {
                lo[k] = x;
            }
            if x > hi[k] {
                hi[k] = x;
            }
        }
        w += weight(p);
    }
    if b - a <= 2 || small(b - a, w) {
        if b - a >= 3 {
            let (first, second) = tally.replace(&mut buf[a..b], rng);
            buf[*out] = first;
            *out += 1;
            if let Some(p) = second {
                buf[*out] = p;
                *out += 1;
            }
        } else {
            for k in a..b {
                buf[*out] = buf[k];
                *out += 1;
            }
        }
        return;
    }
    let spread = [hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2]];
    let axis = (1..dim.d()).fold(0, |best, k| if spread[k] > spread[best] { k } else { best });
    let mid = a + (b - a) / 2;
    buf[a..b].select_nth_unstable_by(mid - a, |p, q| {
        component(p, axis).total_cmp(&component(q, axis))
    });
    reduce_cells(buf, (a, mid), out, small, (&mut *tally, dim, &mut *rng));
    reduce_cells(buf, (mid, b), out, small, (tally, dim, rng));
}
