//! The uniform distribution on the unit sphere S^2 (density `1/(4 pi)`), by Marsaglia's (1972)
//! method: a point `(a, b)` uniform in the unit disk by rejection (acceptance pi/4), then
//! `(2a sqrt(1-s), 2b sqrt(1-s), 1-2s)` with `s = a^2 + b^2`. No trigonometry. Gives the
//! direction `e` of GRW (3). Each try takes one generator word, its halves the point's two
//! coordinates on a grid of 2^32 midpoints ([`signed_unit32`]; stream version 2).
//!
//! ```
//! use gdsmc_core::{rng::seeded, sample::unit_sphere};
//! let e = unit_sphere(&mut seeded(3));
//! assert!((e.norm() - 1.0).abs() < 1e-12);
//! ```

use crate::math::sqrt;
use crate::rng::{Rng, halves, signed_unit32};
use crate::vec3::Vec3;

/// A unit vector uniform on the sphere.
#[inline]
pub fn unit_sphere<R: Rng + ?Sized>(rng: &mut R) -> Vec3 {
    loop {
        let (ha, hb) = halves(rng.next_u64());
        let (a, b) = (signed_unit32(ha), signed_unit32(hb));
        let s = a * a + b * b;
        if s < 1.0 {
            let r = 2.0 * sqrt(1.0 - s);
            return Vec3::new(a * r, b * r, 1.0 - 2.0 * s);
        }
    }
}
