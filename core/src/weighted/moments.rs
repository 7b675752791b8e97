//! The moments of a weighted system: every field of [`Observables`] as a weighted mean
//! `sum g phi(v) / sum g` (Rjasanow and Wagner 1996: the measure `mu = sum g delta_v` stands for
//! the distribution, so its moments are the gas's), so a weighted run reports the same columns
//! as an equal-weight one.

use crate::batch::sums::Sums;
use crate::math::{Real, max, sqrt};
use crate::moments::Observables;
use crate::particles::{Particle, Particles};
use crate::vec3::Vec3;

/// The total momentum `sum g v` of `p` (weights 1 unless weighted).
pub fn momentum(p: &Particles<'_>) -> Vec3 {
    (0..p.len()).fold(Vec3::ZERO, |m, i| m + p.weight(i) * p.velocity(i))
}

/// The total kinetic energy `sum g |v|^2 / 2` of `p`.
pub fn energy(p: &Particles<'_>) -> Real {
    (0..p.len())
        .map(|i| 0.5 * p.weight(i) * p.velocity(i).norm2())
        .sum()
}

/// The weighted means of the records `q` with weights `w` (at least one, total weight > 0)
/// as [`Sums`] of a single particle (`n = 1`): [`Observables::from_sums_dim`] then divides
/// by 1, and every field is the weighted mean (GRW (6)-(11) with `g` in place of `1/n`).
pub fn weighted_means(q: &[Particle], weights: &[Real]) -> Sums {
    let mass: Real = weights.iter().sum();
    let w = 1.0 / mass;
    let mut s = Sums {
        n: 1,
        ..Sums::default()
    };
    for (p, &gp) in q.iter().zip(weights) {
        let g = gp * w;
        let (x, y, z) = (p.vx, p.vy, p.vz);
        let v2 = x * x + y * y + z * z;
        s.s1[0] += g * x;
        s.s1[1] += g * y;
        s.s1[2] += g * z;
        s.s2[0] += g * x * x;
        s.s2[1] += g * y * y;
        s.s2[2] += g * z * z;
        s.s2[3] += g * x * y;
        s.s2[4] += g * x * z;
        s.s2[5] += g * y * z;
        s.s3[0] += g * x * v2;
        s.s3[1] += g * y * v2;
        s.s3[2] += g * z * v2;
        s.s4 += g * v2 * v2;
        s.s6 += g * v2 * v2 * v2;
    }
    let bulk = Vec3::new(s.s1[0], s.s1[1], s.s1[2]);
    for (p, &gp) in q.iter().zip(weights) {
        let g = gp * w;
        let c = p.velocity() - bulk;
        let c2 = c.norm2();
        s.c2[0] += g * c.x * c.x;
        s.c2[1] += g * c.y * c.y;
        s.c2[2] += g * c.z * c.z;
        s.c2[3] += g * c.x * c.y;
        s.c2[4] += g * c.x * c.z;
        s.c2[5] += g * c.y * c.z;
        s.c3[0] += g * c.x * c2;
        s.c3[1] += g * c.y * c2;
        s.c3[2] += g * c.z * c2;
        let cn = sqrt(c2);
        s.c1 += g * cn;
        s.c3n += g * cn * c2;
        s.c4 += g * c2 * c2;
        s.c6 += g * c2 * c2 * c2;
        s.max_c2 = max(s.max_c2, c2);
    }
    s
}

/// The observables of the weighted particles `p` in dimension `d` (2 or 3): weighted means
/// throughout, `a2` MS (3) at that `d`, `max_peculiar_speed` over the particles in use
/// whatever their weight.
pub fn observables(p: &Particles<'_>, d: usize) -> Observables {
    Observables::from_sums_dim(&weighted_means(p.as_slice(), p.weights()), d)
}

/// The weight beyond each of `speeds` about `center`: `sum_{|v - center| > c} g / sum g`, the
/// tail probability `P(|v - V| > c)` the weighted particles are there for.
pub fn weight_beyond<const K: usize>(
    p: &Particles<'_>,
    center: Vec3,
    speeds: [Real; K],
) -> [Real; K] {
    let mut out = [0.0; K];
    for i in 0..p.len() {
        let c2 = (p.velocity(i) - center).norm2();
        for (o, c) in out.iter_mut().zip(speeds) {
            if c2 > c * c {
                *o += p.weight(i);
            }
        }
    }
    let mass = p.mass();
    out.map(|w| w / mass)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Equal weights give the equal-weight observables (any common weight); a particle of
    /// weight 2 counts as two of weight 1.
    #[test]
    fn weighted_means_are_the_equal_weight_moments() {
        let vs = [
            Vec3::new(1.0, 0.5, -0.2),
            Vec3::new(-0.3, 0.1, 0.8),
            Vec3::new(0.7, -1.2, 0.4),
        ];
        let mut plain: [Particle; 4] = core::array::from_fn(|k| Particle::new(vs[k.min(2)], 0.0));
        let equal = Observables::of(&Particles::new(&mut plain).unwrap());
        let mut buf: [Particle; 3] = core::array::from_fn(|k| Particle::new(vs[k], 0.0));
        let mut g = [1.0, 1.0, 2.0];
        let sys = Particles::weighted(&mut buf, &mut g, 3).unwrap();
        let o = observables(&sys, 3);
        for (a, b) in [
            (o.t_bulk, equal.t_bulk),
            (o.a2, equal.a2),
            (o.c6, equal.c6),
            (o.heat_flux.x, equal.heat_flux.x),
            (o.v6, equal.v6),
            (o.max_peculiar_speed, equal.max_peculiar_speed),
        ] {
            assert!((a - b).abs() < 1e-14 * (1.0 + b.abs()), "{a} vs {b}");
        }
        let beyond = weight_beyond(&sys, Vec3::ZERO, [0.0, 1.0, 10.0]);
        assert_eq!(beyond[0], 1.0);
        assert_eq!(beyond[1], 0.75);
        assert_eq!(beyond[2], 0.0);
    }
}
