//! The reduction of a weighted system (Rjasanow and Wagner 1996): groups of particles close in
//! velocity replaced by two each, keeping each group's weight, momentum and energy, so the
//! particle number the collisions grow stays bounded.

use super::cells::reduce_cells;
use super::particle::{WeightedParticle, WeightedSystem};
use crate::geometry::DimensionChoice;
use crate::math::{Real, sqrt};
use crate::rng::Rng;
use crate::sample::{unit_circle, unit_sphere};
use crate::vec3::Vec3;

/// Two particles in place of `group` (at least one particle, weights > 0): weight `W/2` each
/// at `V + d` and `V - d`, `W = sum g`, `V = sum g v / W`, `|d|^2 = sigma^2 =
/// sum g |v - V|^2 / W`. The group's weight, momentum `W V` and energy
/// `sum g |v|^2 / 2 = W (|V|^2 + sigma^2) / 2` are kept to rounding. The direction of `d`
/// keeps the spread of the squared speeds about the flow `flow` too: with `A = V - flow`, the
/// two squared speeds are `|A|^2 + sigma^2 +- 2 A . d`, so `d` leans toward `A` by the angle
/// whose cosine is `sqrt(Var |v - flow|^2) / (2 |A| sigma)` (at most 1) and lies otherwise
/// along the group's principal axis across `A`; then `sum g |v - flow|^4` is kept as well
/// (the fourth moment, so `a2`), unless the cosine had to be cut at 1. Two points symmetric
/// about `V` along one fixed direction would put the whole group at one speed (across `A`) or
/// spread it over twice its width (along a uniform direction); repeated, either moves the tail
/// where the density falls (docs/weighted.md).
pub fn reduce_group<R: Rng + ?Sized>(
    group: &[WeightedParticle],
    flow: Vec3,
    dim: DimensionChoice,
    rng: &mut R,
) -> [WeightedParticle; 2] {
    let w: Real = group.iter().map(|p| p.g).sum();
    let m = (group.iter()).fold(Vec3::ZERO, |m, p| m + p.g * p.velocity());
    let v = (1.0 / w) * m;
    let s2: Real = group
        .iter()
        .map(|p| p.g * (p.velocity() - v).norm2())
        .sum::<Real>()
        / w;
    let start = match dim {
        DimensionChoice::Three => unit_sphere(rng),
        DimensionChoice::Two => unit_circle(rng),
    };
    let axis = principal_axis(group, v, start);
    let a = v - flow;
    let (na, sigma) = (a.norm(), sqrt(s2));
    let e = if na > 0.0 && sigma > 0.0 {
        let radial = (1.0 / na) * a;
        let mean_r: Real = s2 + na * na;
        let var_r: Real = (group.iter())
            .map(|p| {
                let x = (p.velocity() - flow).norm2() - mean_r;
                p.g * x * x
            })
            .sum::<Real>()
            / w;
        let cos = sqrt(var_r) / (2.0 * na * sigma);
        let cos = if cos < 1.0 { cos } else { 1.0 };
        // The principal axis across A (or the random start's part across it).
        let across = |x: Vec3| x - x.dot(radial) * radial;
        let t = match across(axis) {
            t if t.norm() > 1e-12 => (1.0 / t.norm()) * t,
            _ => {
                let t = across(start);
                if t.norm() > 1e-12 {
                    (1.0 / t.norm()) * t
                } else {
                    Vec3::ZERO
                }
            }
        };
        cos * radial + sqrt(1.0 - cos * cos) * t
    } else {
        axis
    };
    let d = sigma * e;
    [
        WeightedParticle::new(v + d, 0.5 * w),
        WeightedParticle::new(v - d, 0.5 * w),
    ]
}

/// The unit principal axis of the weighted covariance of `group` about `v`: 24 steps of power
/// iteration from `start` (a unit vector; returned when the group has no spread).
fn principal_axis(group: &[WeightedParticle], v: Vec3, start: Vec3) -> Vec3 {
    let mut x = start;
    for _ in 0..24 {
        // C x = sum g (c . x) c, c = v_k - v.
        let y = (group.iter()).fold(Vec3::ZERO, |acc, p| {
            let c = p.velocity() - v;
            acc + (p.g * c.dot(x)) * c
        });
        let norm = y.norm();
        if !(norm > 0.0 && norm.is_finite()) {
            return x;
        }
        x = (1.0 / norm) * y;
    }
    x
}

/// Reduces `sys` cell by cell: its particles split at the median of the widest velocity
/// component, recursively, into cells of at most `group` (at least 3), each replaced by two
/// ([`reduce_group`], super::cells). Returns the particles left, about `2 len / group`.
pub fn reduce<R: Rng + ?Sized>(
    sys: &mut WeightedSystem<'_>,
    group: usize,
    dim: DimensionChoice,
    rng: &mut R,
) -> usize {
    let group = group.max(3);
    let len = sys.len();
    let mut out = 0;
    let small = |c: &[WeightedParticle]| c.len() <= group;
    let flow = (1.0 / sys.mass()) * sys.momentum();
    reduce_cells(sys.buffer(), (0, len), &mut out, &small, (flow, dim, rng));
    sys.truncate(out.max(2));
    out.max(2)
}

/// The most speed shells an allocated reduction cuts ([`reduce_allocated`]).
pub const MAX_SHELLS: usize = 64;

/// How a weighted loop reduces its particles when the buffer is full.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Reduction {
    /// Every cell of at most `group` nearby velocities by two ([`reduce`]): the particles
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
    },
}

impl Reduction {
    /// Reduces `sys` so that at least `room` more particles fit: by the rule, then (if the rule
    /// left too many: particles too heavy to group) by cells of 3 until they fit.
    pub fn apply<R: Rng + ?Sized>(
        &self,
        sys: &mut WeightedSystem<'_>,
        room: usize,
        dim: DimensionChoice,
        rng: &mut R,
    ) {
        match *self {
            Reduction::Cells { group } => {
                reduce(sys, group, dim, rng);
            }
            Reduction::Allocated {
                target,
                shells,
                exponent,
            } => {
                reduce_allocated(sys, (target, shells, exponent), dim, rng);
            }
        }
        while sys.len() + room > sys.capacity() && sys.len() > 2 {
            let before = sys.len();
            reduce(sys, 3, dim, rng);
            if sys.len() == before {
                break;
            }
        }
    }
}

/// Reduces `sys` toward `target` particles: sorted by speed about the flow and cut into
/// `shells` shells of equal width in speed up to the fastest, shell `s` of weight `W_s` is
/// given
/// `K_s = target W_s^q / sum W^q` particles (`q` the `exponent`), so each particle it keeps
/// weighs about `w_s = W_s / K_s`; its particles are split into cells of nearby velocities
/// (super::cells) until a cell weighs at most `2 w_s`, and each cell of 3 or more becomes two
/// ([`reduce_group`]; a cell of 1 or 2 is kept as it is). Keeps every group's weight, momentum and energy. Returns the
/// particles left.
pub fn reduce_allocated<R: Rng + ?Sized>(
    sys: &mut WeightedSystem<'_>,
    (target, shells, q): (usize, usize, Real),
    dim: DimensionChoice,
    rng: &mut R,
) -> usize {
    let len = sys.len();
    let shells = shells.clamp(1, MAX_SHELLS);
    let flow = (1.0 / sys.mass()) * sys.momentum();
    let buf = sys.buffer();
    buf[..len].sort_unstable_by(|a, b| {
        let (sa, sb) = ((a.velocity() - flow).norm2(), (b.velocity() - flow).norm2());
        sa.total_cmp(&sb)
    });
    // Shells of equal width in speed up to the fastest particle (the last one when sorted),
    // their bounds and weights taken before any is rewritten.
    let top = sqrt((buf[len - 1].velocity() - flow).norm2());
    let mut edges = [len; MAX_SHELLS + 1];
    let mut weights = [0.0; MAX_SHELLS];
    for (s, e) in edges.iter_mut().enumerate().take(shells) {
        let c = top * s as Real / shells as Real;
        *e = buf[..len].partition_point(|p| sqrt((p.velocity() - flow).norm2()) < c);
    }
    for s in 0..shells {
        weights[s] = buf[edges[s]..edges[s + 1]].iter().map(|p| p.g).sum();
    }
    let norm: Real = (weights[..shells].iter())
        .filter(|&&w| w > 0.0)
        .map(|&w| libm::pow(w, q))
        .sum();
    let mut out = 0;
    for s in 0..shells {
        let (a, b) = (edges[s], edges[s + 1]);
        let ws = weights[s];
        if a == b {
            continue;
        }
        let keep = target as Real * libm::pow(ws, q) / norm;
        let each = ws / keep;
        let small = |c: &[WeightedParticle]| c.iter().map(|p| p.g).sum::<Real>() <= 2.0 * each;
        reduce_cells(buf, (a, b), &mut out, &small, (flow, dim, &mut *rng));
    }
    sys.truncate(out.max(2));
    out.max(2)
}
