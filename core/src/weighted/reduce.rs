//! The reduction of a weighted system (Rjasanow and Wagner 1996): groups of particles close in
//! velocity replaced by two each, keeping each group's weight, momentum and energy, so the
//! particle number the collisions grow stays bounded.

use super::particle::{WeightedParticle, WeightedSystem};
use crate::geometry::DimensionChoice;
use crate::math::{Real, sqrt};
use crate::rng::Rng;
use crate::sample::{unit_circle, unit_sphere};
use crate::vec3::Vec3;

/// Two particles in place of `group` (at least one particle, weights > 0): weight `W/2` each
/// at `V + sigma e` and `V - sigma e`, with `W = sum g`, `V = sum g v / W`,
/// `sigma^2 = sum g |v - V|^2 / W` and `e` uniform on the unit sphere (`dim` three) or circle
/// (two: the velocities stay in the plane). The group's weight, momentum `W V` and energy
/// `sum g |v|^2 / 2 = W (|V|^2 + sigma^2) / 2` are kept to rounding.
pub fn reduce_group<R: Rng + ?Sized>(
    group: &[WeightedParticle],
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
    let e = match dim {
        DimensionChoice::Three => unit_sphere(rng),
        DimensionChoice::Two => unit_circle(rng),
    };
    let d = sqrt(s2) * e;
    [
        WeightedParticle::new(v + d, 0.5 * w),
        WeightedParticle::new(v - d, 0.5 * w),
    ]
}

/// Reduces `sys`: its particles sorted by speed about the flow velocity, each run of `group`
/// consecutive ones (`group >= 3`; the last run is the rest, reduced when it holds 3 or more)
/// replaced by two ([`reduce_group`]). A run spans a thin shell of speeds, so the tail's
/// particles are grouped among themselves. Returns the particles left, about `2 len / group`
/// (at least 2).
pub fn reduce<R: Rng + ?Sized>(
    sys: &mut WeightedSystem<'_>,
    group: usize,
    dim: DimensionChoice,
    rng: &mut R,
) -> usize {
    let group = group.max(3);
    let len = sys.len();
    let flow = (1.0 / sys.mass()) * sys.momentum();
    let buf = sys.buffer();
    buf[..len].sort_unstable_by(|a, b| {
        let (sa, sb) = ((a.velocity() - flow).norm2(), (b.velocity() - flow).norm2());
        sa.total_cmp(&sb)
    });
    let mut out = 0;
    let mut start = 0;
    while start < len {
        let end = (start + group).min(len);
        if end - start >= 3 {
            let two = reduce_group(&buf[start..end], dim, rng);
            buf[out] = two[0];
            buf[out + 1] = two[1];
            out += 2;
        } else {
            for k in start..end {
                buf[out] = buf[k];
                out += 1;
            }
        }
        start = end;
    }
    sys.truncate(out);
    out
}

/// The most speed shells an allocated reduction cuts ([`reduce_allocated`]).
pub const MAX_SHELLS: usize = 64;

/// How a weighted loop reduces its particles when the buffer is full.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Reduction {
    /// Every run of `group` particles of similar speed by two ([`reduce`]): the particles keep
    /// the shape of the distribution's mass.
    Shells {
        /// Particles per run (at least 3).
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
    /// left too many: particles too heavy to group) by runs of 3 until they fit.
    pub fn apply<R: Rng + ?Sized>(
        &self,
        sys: &mut WeightedSystem<'_>,
        room: usize,
        dim: DimensionChoice,
        rng: &mut R,
    ) {
        match *self {
            Reduction::Shells { group } => {
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
/// weighs about `w_s = W_s / K_s`; its particles are grouped in speed order until a group
/// weighs `2 w_s`, and each group of 3 or more becomes two ([`reduce_group`]; a lighter group
/// of 1 or 2 is kept as it is). Keeps every group's weight, momentum and energy. Returns the
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
        if ws <= 0.0 {
            continue;
        }
        let keep = target as Real * libm::pow(ws, q) / norm;
        let each = if keep > 0.0 {
            ws / keep
        } else {
            Real::INFINITY
        };
        let mut start = a;
        while start < b {
            let (mut end, mut w) = (start, 0.0);
            while end < b && w < 2.0 * each {
                w += buf[end].g;
                end += 1;
            }
            if end - start >= 3 {
                let two = reduce_group(&buf[start..end], dim, rng);
                buf[out] = two[0];
                buf[out + 1] = two[1];
                out += 2;
            } else {
                for k in start..end {
                    buf[out] = buf[k];
                    out += 1;
                }
            }
            start = end;
        }
    }
    sys.truncate(out.max(2));
    out.max(2)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::rng::Xoshiro256PlusPlus;
    use crate::sample::standard_normal;
    use rand_core::SeedableRng;

    /// A system of `len` particles, velocities normal with a drift, weights spread over four
    /// decades (as a weighted run's tail makes them), in a buffer of `cap`.
    fn system(len: usize, cap: usize, rng: &mut Xoshiro256PlusPlus) -> [WeightedParticle; 512] {
        let mut buf = [WeightedParticle::default(); 512];
        for (k, p) in buf.iter_mut().enumerate().take(len.min(cap)) {
            let v = Vec3::new(
                1.0 + standard_normal(rng),
                standard_normal(rng),
                -0.5 + 3.0 * standard_normal(rng),
            );
            let g = libm::pow(10.0, -4.0 * (k % 7) as f64 / 6.0);
            *p = WeightedParticle::new(v, g);
        }
        buf
    }

    /// Rjasanow and Wagner's conservation: a reduction keeps the weight, momentum and energy
    /// of every group, so of the system, to rounding (relative 1e-12 of the sums' sizes).
    #[test]
    fn a_reduction_keeps_weight_momentum_and_energy() {
        let mut rng = Xoshiro256PlusPlus::seed_from_u64(5);
        for (len, group, dim) in [
            (500, 5, DimensionChoice::Three),
            (499, 3, DimensionChoice::Three),
            (301, 16, DimensionChoice::Two),
        ] {
            let mut buf = system(len, 512, &mut rng);
            if dim == DimensionChoice::Two {
                for p in &mut buf[..len] {
                    p.vz = 0.0;
                }
            }
            let mut sys = WeightedSystem::new(&mut buf, len).unwrap();
            let (w, m, e) = (sys.mass(), sys.momentum(), sys.energy());
            let scale = (sys.particles().iter())
                .map(|p| p.g * p.velocity().norm2())
                .sum::<f64>();
            let left = reduce(&mut sys, group, dim, &mut rng);
            assert!(left < len && left >= 2 * (len / group), "{left} of {len}");
            assert!((sys.mass() - w).abs() <= 1e-12 * w);
            assert!((sys.momentum() - m).norm() <= 1e-12 * scale.max(w));
            assert!((sys.energy() - e).abs() <= 1e-12 * scale);
            if dim == DimensionChoice::Two {
                assert!(sys.particles().iter().all(|p| p.vz == 0.0));
            }
        }
    }

    /// The groups are shells of speed: after a reduction the speeds about the flow are kept
    /// in range (no particle thrown far out of its shell: the largest speed grows at most by
    /// the shell's spread).
    #[test]
    fn a_reduction_keeps_the_tail_where_it_was() {
        let mut rng = Xoshiro256PlusPlus::seed_from_u64(6);
        let mut buf = system(500, 512, &mut rng);
        let mut sys = WeightedSystem::new(&mut buf, 500).unwrap();
        let flow = (1.0 / sys.mass()) * sys.momentum();
        let top = |s: &WeightedSystem<'_>| {
            (s.particles().iter())
                .map(|p| (p.velocity() - flow).norm())
                .fold(0.0, f64::max)
        };
        let before = top(&sys);
        reduce(&mut sys, 4, DimensionChoice::Three, &mut rng);
        let after = top(&sys);
        assert!(
            after > 0.5 * before && after < 1.5 * before,
            "{before} -> {after}"
        );
    }

    /// An allocated reduction keeps the sums too, lands near its target, and with exponent 0
    /// keeps more of the fastest tenth than with exponent 1; with exponent 0 a shell of at
    /// most `target / (2 shells)` unit weights is kept whole (each group is one particle), so
    /// the fastest particle survives as it was.
    #[test]
    fn an_allocated_reduction_keeps_the_sums_and_feeds_the_tail() {
        let mut counts = [0usize; 2];
        let mut kept_fastest = false;
        for (k, q) in [0.0, 1.0].into_iter().enumerate() {
            let mut rng = Xoshiro256PlusPlus::seed_from_u64(7);
            let mut buf = system(500, 512, &mut rng);
            for p in &mut buf[..500] {
                p.g = 1.0;
            }
            let mut sys = WeightedSystem::new(&mut buf, 500).unwrap();
            let (w, m, e) = (sys.mass(), sys.momentum(), sys.energy());
            let left = reduce_allocated(&mut sys, (100, 10, q), DimensionChoice::Three, &mut rng);
            assert!((50..=200).contains(&left), "q = {q}: {left} left");
            assert!((sys.mass() - w).abs() <= 1e-12 * w);
            assert!((sys.momentum() - m).norm() <= 1e-12 * 2.0 * e);
            assert!((sys.energy() - e).abs() <= 1e-12 * e);
            let flow = (1.0 / w) * m;
            // The fastest tenth of the speeds before: the particles left beyond its start.
            let mut speeds: [f64; 500] = [0.0; 500];
            let mut before = system(500, 512, &mut Xoshiro256PlusPlus::seed_from_u64(7));
            for (s, p) in speeds.iter_mut().zip(before.iter_mut()) {
                *s = (p.velocity() - flow).norm();
            }
            speeds.sort_unstable_by(f64::total_cmp);
            let edge = speeds[450];
            if q == 0.0 {
                kept_fastest = (sys.particles().iter())
                    .any(|p| ((p.velocity() - flow).norm() - speeds[499]).abs() < 1e-12);
            }
            counts[k] = (sys.particles().iter())
                .filter(|p| (p.velocity() - flow).norm() > edge)
                .count();
        }
        assert!(counts[0] > counts[1], "tail particles {counts:?}");
        assert!(kept_fastest, "exponent 0 keeps the fastest particle whole");
    }
}
