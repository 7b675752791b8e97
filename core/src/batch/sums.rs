//! Moment sums over all particles, accumulated with SIMD: the bulk velocity `V` (GRW (7)) in
//! a light first pass (four particles' rows added as they lie, no transposition), then in one
//! pass every central sum about `V` (`c = v - V`: `c c^T`, `c |c|^2`, `|c|`, `|c|^3`,
//! `|c|^4`, `|c|^6`, `max |c|^2`) and `sum |v|^6`. The raw sums GRW (6), (8), (9) and
//! `sum |v|^4` follow from the central ones ([`raw_from_central`]: the binomial expansion of
//! `v = V + c` with `sum c = 0`, which holds to rounding, a few ulps of the sums), so an
//! observation reads the particles twice, and the first time lightly.
//!
//! Sums are taken lane-wise over blocks of four particles and reduced at the end, in a fixed
//! order, so results depend only on the particle values.

use crate::math::{Real, RealX4, max, sqrt};
use crate::particles::Particle;
use crate::vec3::Vec3;

/// Unnormalized moment sums of a particle system.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Sums {
    /// Number of particles `n`.
    pub n: usize,
    /// `sum v` (GRW (7) times n).
    pub s1: [Real; 3],
    /// `sum v v^T`, upper triangle `[xx, yy, zz, xy, xz, yz]` (GRW (8) times n).
    pub s2: [Real; 6],
    /// `sum v |v|^2` (twice GRW (9) times n).
    pub s3: [Real; 3],
    /// `sum |v|^4`.
    pub s4: Real,
    /// `sum |v|^6`.
    pub s6: Real,
    /// `sum c c^T`, `c = v - V`, `V = s1 / n`, upper triangle `[xx, yy, zz, xy, xz, yz]`:
    /// accumulated about `V` so that the temperature keeps its digits however large `|V|` is.
    pub c2: [Real; 6],
    /// `sum c |c|^2`.
    pub c3: [Real; 3],
    /// `sum |v - V|` (the odd moments enter MS (44)).
    pub c1: Real,
    /// `sum |v - V|^3`.
    pub c3n: Real,
    /// `sum |v - V|^4`.
    pub c4: Real,
    /// `sum |v - V|^6`.
    pub c6: Real,
    /// `max |v - V|^2`.
    pub max_c2: Real,
}

/// The raw sums `s2`, `s3`, `s4` of `s` from its central ones and the bulk velocity `bulk`
/// (`v = V + c`, `sum c = 0` to rounding, `C = sum c c^T`, `Q = tr C`, `n` particles):
/// `sum v v^T = C + n V V^T`, `sum v |v|^2 = sum c|c|^2 + 2 C V + Q V + n |V|^2 V`,
/// `sum |v|^4 = sum |c|^4 + 4 (sum c|c|^2).V + 4 V.C V + 2 |V|^2 Q + n |V|^4`.
// Once per observation: out of line (the micro:bit's firmware is built for size).
#[inline(never)]
pub fn raw_from_central(s: &mut Sums, bulk: Vec3) {
    let n = s.n as Real;
    let v = bulk.to_array();
    // The symmetric C as a matrix from its upper triangle [xx, yy, zz, xy, xz, yz].
    let c = [
        [s.c2[0], s.c2[3], s.c2[4]],
        [s.c2[3], s.c2[1], s.c2[5]],
        [s.c2[4], s.c2[5], s.c2[2]],
    ];
    let cv: [Real; 3] = core::array::from_fn(|a| c[a][0] * v[0] + c[a][1] * v[1] + c[a][2] * v[2]);
    let v2 = v[0] * v[0] + v[1] * v[1] + v[2] * v[2];
    let q = s.c2[0] + s.c2[1] + s.c2[2];
    const UPPER: [(usize, usize); 6] = [(0, 0), (1, 1), (2, 2), (0, 1), (0, 2), (1, 2)];
    for (k, &(a, b)) in UPPER.iter().enumerate() {
        s.s2[k] = c[a][b] + n * v[a] * v[b];
    }
    for a in 0..3 {
        s.s3[a] = s.c3[a] + 2.0 * cv[a] + q * v[a] + n * v2 * v[a];
    }
    let c3v = s.c3[0] * v[0] + s.c3[1] * v[1] + s.c3[2] * v[2];
    let vcv = v[0] * cv[0] + v[1] * cv[1] + v[2] * cv[2];
    s.s4 = s.c4 + 4.0 * c3v + 4.0 * vcv + 2.0 * v2 * q + n * v2 * v2;
}

/// The sums over the particles `q` (at least one): SIMD unless the `scalar` feature is on.
pub fn accumulate(q: &[Particle]) -> Sums {
    if cfg!(feature = "scalar") {
        accumulate_scalar(q)
    } else {
        accumulate_simd(q)
    }
}

/// Adds one particle's central moments about `bulk`.
#[inline(always)]
fn add_central(s: &mut Sums, p: &Particle, bulk: Vec3) {
    let v = p.velocity();
    let v2 = v.norm2();
    s.s6 += v2 * v2 * v2;
    let c = v - bulk;
    let c2 = c.norm2();
    s.c2[0] += c.x * c.x;
    s.c2[1] += c.y * c.y;
    s.c2[2] += c.z * c.z;
    s.c2[3] += c.x * c.y;
    s.c2[4] += c.x * c.z;
    s.c2[5] += c.y * c.z;
    s.c3[0] += c.x * c2;
    s.c3[1] += c.y * c2;
    s.c3[2] += c.z * c2;
    let cn = sqrt(c2);
    s.c1 += cn;
    s.c3n += cn * c2;
    s.c4 += c2 * c2;
    s.c6 += c2 * c2 * c2;
    s.max_c2 = max(s.max_c2, c2);
}

/// Scalar twin of [`accumulate`].
pub fn accumulate_scalar(q: &[Particle]) -> Sums {
    let mut s = Sums {
        n: q.len(),
        ..Sums::default()
    };
    for p in q {
        s.s1[0] += p.vx;
        s.s1[1] += p.vy;
        s.s1[2] += p.vz;
    }
    let bulk = bulk_of(&s);
    for p in q {
        add_central(&mut s, p, bulk);
    }
    raw_from_central(&mut s, bulk);
    s
}

fn bulk_of(s: &Sums) -> Vec3 {
    let inv = 1.0 / s.n as Real;
    Vec3::new(s.s1[0] * inv, s.s1[1] * inv, s.s1[2] * inv)
}

/// SIMD kernel of [`accumulate`]: four particles per lane-step (loaded and transposed).
pub fn accumulate_simd(q: &[Particle]) -> Sums {
    let n = q.len();
    let blocks = n / 4;
    let z = RealX4::ZERO;
    // The bulk velocity: each of four accumulators takes one particle of each block as its
    // row `[vx, vy, vz, t]`.
    let mut rows = [z; 4];
    for b in 0..blocks {
        for (k, r) in rows.iter_mut().enumerate() {
            let p = &q[4 * b + k];
            *r += RealX4::from([p.vx, p.vy, p.vz, p.t_kick]);
        }
    }
    let [r0, r1, r2, r3] = rows.map(|r| r.to_array());
    let mut s = Sums {
        n,
        s1: core::array::from_fn(|a| (r0[a] + r1[a]) + (r2[a] + r3[a])),
        ..Sums::default()
    };
    for p in &q[4 * blocks..] {
        s.s1[0] += p.vx;
        s.s1[1] += p.vy;
        s.s1[2] += p.vz;
    }
    let bulk = bulk_of(&s);
    #[cfg(target_arch = "x86_64")]
    let lanes = super::lanes_avx::central_lanes(&q[..4 * blocks], bulk)
        .unwrap_or_else(|| super::lanes::central_lanes(&q[..4 * blocks], bulk));
    #[cfg(not(target_arch = "x86_64"))]
    let lanes = super::lanes::central_lanes(&q[..4 * blocks], bulk);
    // Each sum the lanes' `(l0 + l1) + (l2 + l3)`, as `wide::f64x4::reduce_add` adds them on
    // SSE2 (the default target's).
    let sum = |l: [Real; 4]| (l[0] + l[1]) + (l[2] + l[3]);
    s.c2 = lanes.c2.map(sum);
    s.c3 = lanes.c3.map(sum);
    s.c1 = sum(lanes.c1);
    s.c3n = sum(lanes.c3n);
    s.c4 = sum(lanes.c4);
    s.c6 = sum(lanes.c6);
    s.max_c2 = lanes.max_c2.into_iter().fold(0.0, max);
    s.s6 = sum(lanes.s6);
    for p in &q[4 * blocks..] {
        add_central(&mut s, p, bulk);
    }
    raw_from_central(&mut s, bulk);
    s
}
