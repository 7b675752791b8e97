//! Moment sums over all particles, accumulated with SIMD: the raw moments GRW (6)-(9) and
//! `|v|^4`, `|v|^6` in one pass, then the central `|c|^4`, `|c|^6` and `max |c|^2`
//! (`c = v - V`) in a second pass once the bulk velocity `V` is known.
//!
//! Sums are taken lane-wise over blocks of four particles and reduced at the end, in a fixed
//! order, so results depend only on the particle values.

use super::kick::load4;
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

/// The sums over the particles `q` (at least one): SIMD unless the `scalar` feature is on.
pub fn accumulate(q: &[Particle]) -> Sums {
    if cfg!(feature = "scalar") {
        accumulate_scalar(q)
    } else {
        accumulate_simd(q)
    }
}

/// Adds one particle's raw moments.
#[inline(always)]
fn add_raw(s: &mut Sums, x: Real, y: Real, z: Real) {
    let v2 = x * x + y * y + z * z;
    s.s1[0] += x;
    s.s1[1] += y;
    s.s1[2] += z;
    s.s2[0] += x * x;
    s.s2[1] += y * y;
    s.s2[2] += z * z;
    s.s2[3] += x * y;
    s.s2[4] += x * z;
    s.s2[5] += y * z;
    s.s3[0] += x * v2;
    s.s3[1] += y * v2;
    s.s3[2] += z * v2;
    s.s4 += v2 * v2;
    s.s6 += v2 * v2 * v2;
}

/// Adds one particle's central moments about `bulk`.
#[inline(always)]
fn add_central(s: &mut Sums, p: &Particle, bulk: Vec3) {
    let c = p.velocity() - bulk;
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
        add_raw(&mut s, p.vx, p.vy, p.vz);
    }
    let bulk = bulk_of(&s);
    for p in q {
        add_central(&mut s, p, bulk);
    }
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
    let (mut a1, mut a2, mut a3) = (z, z, z);
    let (mut xx, mut yy, mut zz, mut xy, mut xz, mut yz) = (z, z, z, z, z, z);
    let (mut b1, mut b2, mut b3, mut q4, mut q6) = (z, z, z, z, z);
    for b in 0..blocks {
        let [x, y, w, _] = load4(&q[4 * b..]);
        let v2 = x * x + y * y + w * w;
        a1 += x;
        a2 += y;
        a3 += w;
        xx += x * x;
        yy += y * y;
        zz += w * w;
        xy += x * y;
        xz += x * w;
        yz += y * w;
        b1 += x * v2;
        b2 += y * v2;
        b3 += w * v2;
        let v4 = v2 * v2;
        q4 += v4;
        q6 += v4 * v2;
    }
    let mut s = Sums {
        n,
        s1: [a1.reduce_add(), a2.reduce_add(), a3.reduce_add()],
        s2: [
            xx.reduce_add(),
            yy.reduce_add(),
            zz.reduce_add(),
            xy.reduce_add(),
            xz.reduce_add(),
            yz.reduce_add(),
        ],
        s3: [b1.reduce_add(), b2.reduce_add(), b3.reduce_add()],
        s4: q4.reduce_add(),
        s6: q6.reduce_add(),
        ..Sums::default()
    };
    for p in &q[4 * blocks..] {
        add_raw(&mut s, p.vx, p.vy, p.vz);
    }
    let bulk = bulk_of(&s);
    let (bx, by, bz) = (
        RealX4::splat(bulk.x),
        RealX4::splat(bulk.y),
        RealX4::splat(bulk.z),
    );
    let (mut c4, mut c6, mut m2) = (z, z, z);
    let (mut e1, mut e3) = (z, z);
    let (mut cxx, mut cyy, mut czz, mut cxy, mut cxz, mut cyz) = (z, z, z, z, z, z);
    let (mut d1, mut d2, mut d3) = (z, z, z);
    for b in 0..blocks {
        let [x, y, w, _] = load4(&q[4 * b..]);
        let (x, y, w) = (x - bx, y - by, w - bz);
        let c2 = x * x + y * y + w * w;
        cxx += x * x;
        cyy += y * y;
        czz += w * w;
        cxy += x * y;
        cxz += x * w;
        cyz += y * w;
        d1 += x * c2;
        d2 += y * c2;
        d3 += w * c2;
        let c4v = c2 * c2;
        let cn = c2.sqrt();
        e1 += cn;
        e3 += cn * c2;
        c4 += c4v;
        c6 += c4v * c2;
        m2 = m2.max(c2);
    }
    s.c2 = [
        cxx.reduce_add(),
        cyy.reduce_add(),
        czz.reduce_add(),
        cxy.reduce_add(),
        cxz.reduce_add(),
        cyz.reduce_add(),
    ];
    s.c3 = [d1.reduce_add(), d2.reduce_add(), d3.reduce_add()];
    s.c1 = e1.reduce_add();
    s.c3n = e3.reduce_add();
    s.c4 = c4.reduce_add();
    s.c6 = c6.reduce_add();
    s.max_c2 = m2.to_array().into_iter().fold(0.0, max);
    for p in &q[4 * blocks..] {
        add_central(&mut s, p, bulk);
    }
    s
}
