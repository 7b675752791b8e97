//! The reduction of weighted particles (Rjasanow and Wagner 1996): cells of particles close in
//! velocity replaced by a sample of two of their own velocities each (unbiased: the expected
//! measure is the cell's), the replaced set's weight, momentum and energy kept by one affine
//! correction (super::group), so the particle number the collisions grow stays bounded. Every particle must be at the time `t`
//! a reduction is given (the loop kicks them there first): the replacements are last kicked
//! then.

use super::cells::reduce_cells;
use super::group::Tally;
use super::moments::momentum;
use super::packed::{pack, unpack, weight};
use super::windows::Allocation;
use crate::geometry::DimensionChoice;
use crate::math::{Real, sqrt};
use crate::particles::{Particle, Particles};
use crate::rng::Rng;

/// Reduces the weighted particles `p` (all at time `t`) cell by cell: split at the median of
/// the widest velocity component, recursively, into cells of at most `group` (at least 3),
/// each replaced by a sample of two of its velocities, the replaced set's weight, momentum and
/// energy kept (super::group, super::cells). Returns the particles left, at most
/// `2 len / group` or so.
pub fn reduce<R: Rng + ?Sized>(
    p: &mut Particles<'_>,
    t: Real,
    group: usize,
    dim: DimensionChoice,
    rng: &mut R,
) -> usize {
    let group = group.max(3);
    let mut out = 0;
    let small = |len: usize, _| len <= group;
    let flow = (1.0 / p.mass()) * momentum(p);
    let mut tally = Tally::new(flow);
    let (buf, _, len) = pack(p);
    reduce_cells(
        buf,
        (0, len),
        &mut out,
        &small,
        (&mut tally, dim, &mut *rng),
    );
    tally.conserve(buf, &mut out, dim, rng);
    unpack(p, out, t);
    out
}

/// A cell of an allocated reduction is small when it weighs at most this many times the
/// weight `w_s` a particle of its shell is to have ([`reduce_allocated`]): halving a shell's
/// cells until they weigh at most `c w_s` leaves cells spread over `(c w_s / 2, c w_s]`, about
/// log-uniformly, so `1 / (c w_s ln 2)` of them per unit weight, each of which becomes two
/// particles: `c = 2 / ln 2` gives the shell its `K_s` particles on average (a bound of
/// `2 w_s` left about 1.45 `K_s`, and reductions came 1.8 times as often as they need to).
pub const CELL_WEIGHT: Real = 2.0 / core::f64::consts::LN_2;

pub use super::windows::MAX_SHELLS;

/// How a weighted loop reduces its particles when the buffer is full.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Reduction {
    /// Every cell of at most `group` nearby velocities by a sample of two ([`reduce`]): the particles
    /// keep the shape of the distribution's mass.
    Cells {
        /// Particles per cell (at least 3).
        group: usize,
    },
    /// Toward `target` particles allocated among `shells` speed shells of equal width in
    /// proportion to `W_s^exponent` (`W_s` a shell's weight; [`reduce_allocated`]): exponent
    /// 1 follows the mass, 0 gives every shell the same number, so the thin tail keeps as
    /// many particles as the core (Rjasanow and Wagner 2001's rare events: particles where the
    /// quantity of interest is, lighter).
    Allocated {
        /// Particles aimed at after a reduction.
        target: usize,
        /// Speed shells.
        shells: usize,
        /// The exponent `q` in [0, 1].
        exponent: Real,
        /// The share `phi` in [0, 1) of `target` given equally to every occupied shell, the
        /// rest by `W_s^q` ([`super::windows::Allocation`]).
        floor: Real,
    },
}

impl Reduction {
    /// Reduces `p` (all at time `t`) so that at least `room` more particles fit: by the rule,
    /// then (if the rule left too many: particles too heavy to group, or spread over the shells
    /// a few to each) by cells of 4 until they fit.
    pub fn apply<R: Rng + ?Sized>(
        &self,
        p: &mut Particles<'_>,
        (t, room): (Real, usize),
        dim: DimensionChoice,
        rng: &mut R,
    ) {
        match *self {
            Reduction::Cells { group } => {
                reduce(p, t, group, dim, rng);
            }
            Reduction::Allocated {
                target,
                shells,
                exponent,
                floor,
            } => {
                reduce_allocated(p, t, (target, shells, exponent, floor), dim, rng);
            }
        }
        // Cells of at most 4 (a k-d split halves a run of 2^k particles down to pairs, which
        // cells of 3 would keep whole); with cells of 4 a run of 3 or more always shrinks.
        while p.len() + room > p.capacity() && p.len() > 2 {
            let before = p.len();
            reduce(p, t, 4, dim, rng);
            if p.len() == before {
                break;
            }
        }
    }
}

/// Reduces the weighted particles `p` (all at time `t`) toward `target` particles: sorted by speed about the flow and cut into
/// `shells` shells of equal width in speed up to the fastest (or to
/// [`super::windows::REACH`] `sqrt(T)`, the last shell holding the particles beyond), shell `s` of weight `W_s` is
/// given `K_s = target (phi / S + (1 - phi) W_s^q / sum W^q)` particles (`q` the `exponent`,
/// `phi` the `floor`, `S` the occupied shells; super::windows::Allocation), so each particle it keeps
/// weighs about `w_s = W_s / K_s`; its particles are split into cells of nearby velocities
/// (super::cells) until a cell weighs at most [`CELL_WEIGHT`] `w_s`, and each cell of 3 or
/// more becomes a sample of two of its velocities (a cell of 1 or 2 is kept as it is), the
/// replaced set's weight, momentum and energy kept (super::group). Returns the particles left.
pub fn reduce_allocated<R: Rng + ?Sized>(
    p: &mut Particles<'_>,
    t: Real,
    (target, shells, q, floor): (usize, usize, Real, Real),
    dim: DimensionChoice,
    rng: &mut R,
) -> usize {
    let flow = (1.0 / p.mass()) * momentum(p);
    let mut tally = Tally::new(flow);
    let (buf, scratch, len) = pack(p);
    let (records, keys) = (&mut buf[..len], &mut scratch[..len]);
    // Each record's speed about the flow once (the scratch slot), the shells of equal width up
    // to the fastest (or the reach) and their weights from them, before any record is rewritten; then each
    // record's shell in the same slot, the key of the counting sort.
    for (c, q) in keys.iter_mut().zip(records.iter()) {
        *c = sqrt((q.velocity() - flow).norm2());
    }
    let (mut top, mut s2, mut mass) = (0.0, 0.0, 0.0);
    for (&c, q) in keys.iter().zip(records.iter()) {
        top = if c > top { c } else { top };
        s2 += weight(q) * c * c;
        mass += weight(q);
    }
    let thermal = sqrt(s2 / (mass * dim.d() as Real));
    let speeds = keys
        .iter()
        .zip(records.iter())
        .map(|(&c, q)| (c, weight(q)));
    let alloc = Allocation::measure(speeds, flow, (top, thermal), (target, shells, q, floor));
    let shells = alloc.shells;
    for c in keys.iter_mut() {
        *c = alloc.shell(*c) as Real;
    }
    let edges = by_shell(records, keys, shells);
    let mut out = 0;
    for s in 0..shells {
        let (a, b) = (edges[s], edges[s + 1]);
        if a == b {
            continue;
        }
        let each = alloc.each[s];
        let small = |_, w: Real| w <= CELL_WEIGHT * each;
        reduce_cells(buf, (a, b), &mut out, &small, (&mut tally, dim, &mut *rng));
    }
    tally.conserve(buf, &mut out, dim, rng);
    unpack(p, out, t);
    out
}

/// Orders `buf` by shell in place (`keys[i]` the shell of `buf[i]`, below `shells`, as a
/// number; permuted along), in linear time (a counting sort that permutes in cycles: each
/// record is moved at most once into its shell's run); the order within a shell is left as
/// it falls. Returns the runs' bounds: shell `s` is `edges[s]..edges[s + 1]`.
fn by_shell(buf: &mut [Particle], keys: &mut [Real], shells: usize) -> [usize; MAX_SHELLS + 1] {
    let mut edges = [0; MAX_SHELLS + 1];
    for &k in keys.iter() {
        edges[k as usize + 1] += 1;
    }
    for s in 0..shells {
        edges[s + 1] += edges[s];
    }
    let mut next = edges;
    for s in 0..shells {
        while next[s] < edges[s + 1] {
            let k = keys[next[s]] as usize;
            if k == s {
                next[s] += 1;
            } else {
                buf.swap(next[s], next[k]);
                keys.swap(next[s], next[k]);
                next[k] += 1;
            }
        }
    }
    edges
}
