//! What a synchronization inside a run needs, in one SIMD pass: the bulk velocity, the
//! temperature and the largest peculiar speed, summed about a reference velocity `vref` close
//! to the bulk (the previous synchronization's: with no drive the collisions conserve the
//! momentum, so the bulk does not move). An observation needs every moment and two passes
//! ([`super::sums`]); a synchronization within a run (every `2n` candidates of a gas with no
//! drive, GRW step 1.4's `Umax` made exact) needs only these, and at `n = 1e7`, where every
//! pass streams the whole particle array from memory, one pass instead of two is the saving.
//!
//! Sums are taken lane-wise over blocks of four particles and reduced at the end, in a fixed
//! order, so results depend only on the particle values.

use super::kick::load4;
use crate::math::{Real, RealX4, max};
use crate::particles::Particle;
use crate::vec3::Vec3;

/// Sums about a reference velocity `vref` (`c = v - vref`).
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct SyncSums {
    /// Number of particles `n`.
    pub n: usize,
    /// `sum c`.
    pub s1: [Real; 3],
    /// `sum |c|^2`.
    pub s2: Real,
    /// `max |c|^2`.
    pub max2: Real,
}

impl SyncSums {
    /// The bulk velocity `V = vref + sum c / n` (GRW (7)).
    pub fn bulk(&self, vref: Vec3) -> Vec3 {
        let inv = 1.0 / self.n as Real;
        vref + Vec3::new(self.s1[0] * inv, self.s1[1] * inv, self.s1[2] * inv)
    }

    /// The temperature about the bulk in `d` dimensions, `(<|c|^2> - |<c>|^2) / d` (GRW (8)'s
    /// trace; no cancellation while `vref` is near the bulk).
    pub fn t_bulk(&self, d: usize) -> Real {
        let inv = 1.0 / self.n as Real;
        let m = Vec3::new(self.s1[0] * inv, self.s1[1] * inv, self.s1[2] * inv);
        (self.s2 * inv - m.norm2()) / d as Real
    }
}

/// The sums over the particles `q` (at least one) about `vref`: SIMD unless the `scalar`
/// feature is on.
pub fn sync_sums(q: &[Particle], vref: Vec3) -> SyncSums {
    if cfg!(feature = "scalar") {
        sync_sums_scalar(q, vref)
    } else {
        sync_sums_simd(q, vref)
    }
}

/// Adds one particle.
#[inline(always)]
fn add(s: &mut SyncSums, p: &Particle, vref: Vec3) {
    let c = p.velocity() - vref;
    let c2 = c.norm2();
    s.s1[0] += c.x;
    s.s1[1] += c.y;
    s.s1[2] += c.z;
    s.s2 += c2;
    s.max2 = max(s.max2, c2);
}

/// Scalar twin of [`sync_sums`].
pub fn sync_sums_scalar(q: &[Particle], vref: Vec3) -> SyncSums {
    let mut s = SyncSums {
        n: q.len(),
        ..SyncSums::default()
    };
    for p in q {
        add(&mut s, p, vref);
    }
    s
}

/// SIMD kernel of [`sync_sums`]: four particles per lane-step (loaded and transposed).
pub fn sync_sums_simd(q: &[Particle], vref: Vec3) -> SyncSums {
    let n = q.len();
    let blocks = n / 4;
    let z = RealX4::ZERO;
    let (bx, by, bz) = (
        RealX4::splat(vref.x),
        RealX4::splat(vref.y),
        RealX4::splat(vref.z),
    );
    let (mut a1, mut a2, mut a3, mut a4, mut m2) = (z, z, z, z, z);
    for b in 0..blocks {
        let [x, y, w, _] = load4(&q[4 * b..]);
        let (x, y, w) = (x - bx, y - by, w - bz);
        let c2 = x * x + y * y + w * w;
        a1 += x;
        a2 += y;
        a3 += w;
        a4 += c2;
        m2 = m2.max(c2);
    }
    let mut s = SyncSums {
        n,
        s1: [a1.reduce_add(), a2.reduce_add(), a3.reduce_add()],
        s2: a4.reduce_add(),
        max2: m2.to_array().into_iter().fold(0.0, max),
    };
    for p in &q[4 * blocks..] {
        add(&mut s, p, vref);
    }
    s
}
