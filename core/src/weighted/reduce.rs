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
}
