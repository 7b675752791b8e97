//! The central moment sums' four lanes over whole blocks of four particles (lane `k` sums the
//! particles `4 b + k`), before [`super::sums`] adds them: the portable loop in
//! `wide::f64x4`, and the type both it and the AVX loop ([`super::lanes_avx`]) return.

use super::kick::load4;
use crate::math::{Real, RealX4};
use crate::particles::Particle;
use crate::vec3::Vec3;

/// The four lanes of each central sum over whole blocks of four particles (lane `k` sums the
/// particles `4 b + k`), before they are added.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Lanes {
    /// `sum c c^T`, upper triangle `[xx, yy, zz, xy, xz, yz]`.
    pub c2: [[Real; 4]; 6],
    /// `sum c |c|^2`.
    pub c3: [[Real; 4]; 3],
    /// `sum |c|`.
    pub c1: [Real; 4],
    /// `sum |c|^3`.
    pub c3n: [Real; 4],
    /// `sum |c|^4`.
    pub c4: [Real; 4],
    /// `sum |c|^6`.
    pub c6: [Real; 4],
    /// `max |c|^2` (0 and above).
    pub max_c2: [Real; 4],
    /// `sum |v|^6`.
    pub s6: [Real; 4],
}

impl Lanes {
    /// The lanes out of a kernel's registers `out` reads: `c c^T`'s six, `c |c|^2`'s three,
    /// then `|c|`, `|c|^3`, `|c|^4`, `|c|^6`, `max |c|^2` and `|v|^6`.
    #[inline(always)]
    pub fn from_registers<T>(
        c2: [T; 6],
        c3: [T; 3],
        [c1, c3n, c4, c6, max_c2, s6]: [T; 6],
        out: impl Fn(T) -> [Real; 4],
    ) -> Lanes {
        Lanes {
            c2: c2.map(&out),
            c3: c3.map(&out),
            c1: out(c1),
            c3n: out(c3n),
            c4: out(c4),
            c6: out(c6),
            max_c2: out(max_c2),
            s6: out(s6),
        }
    }
}

/// The central lanes of `q` (whole blocks of four) about `bulk` in `wide::f64x4` (the
/// portable kernel; x86_64 with AVX runs [`super::lanes_avx`], bit for bit the same).
pub fn central_lanes(q: &[Particle], bulk: Vec3) -> Lanes {
    let (bx, by, bz) = (
        RealX4::splat(bulk.x),
        RealX4::splat(bulk.y),
        RealX4::splat(bulk.z),
    );
    let z = RealX4::ZERO;
    let (mut c4, mut c6, mut m2) = (z, z, z);
    let (mut e1, mut e3) = (z, z);
    let (mut cxx, mut cyy, mut czz, mut cxy, mut cxz, mut cyz) = (z, z, z, z, z, z);
    let (mut d1, mut d2, mut d3) = (z, z, z);
    let mut q6 = z;
    for block in q.chunks_exact(4) {
        let [x, y, w, _] = load4(block);
        let v2 = x * x + y * y + w * w;
        q6 += v2 * v2 * v2;
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
    let out = |v: RealX4| v.to_array();
    Lanes::from_registers(
        [cxx, cyy, czz, cxy, cxz, cyz],
        [d1, d2, d3],
        [e1, e3, c4, c6, m2, q6],
        out,
    )
}
