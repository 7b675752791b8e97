//! The uniform distribution on the unit circle S^1 in the `(x, y)` plane (density `1/(2 pi)`):
//! a point uniform in the unit disk by rejection (acceptance pi/4), then its angle doubled,
//! `((a^2 - b^2)/s, 2ab/s)` with `s = a^2 + b^2` (von Neumann 1951). No trigonometry. Gives the
//! direction `e` of GRW (3) for disks with isotropic scattering. Each try takes one generator
//! word, as [`super::unit_sphere`]'s.
//!
//! ```
//! use gdsmc_core::{rng::seeded, sample::unit_circle};
//! let e = unit_circle(&mut seeded(3));
//! assert!((e.norm() - 1.0).abs() < 1e-12 && e.z == 0.0);
//! ```

use crate::rng::{Rng, halves, signed_unit32};
use crate::vec3::Vec3;

/// A unit vector uniform on the circle in the `(x, y)` plane (`z = 0`).
#[inline]
pub fn unit_circle<R: Rng + ?Sized>(rng: &mut R) -> Vec3 {
    loop {
        let (ha, hb) = halves(rng.next_u64());
        let (a, b) = (signed_unit32(ha), signed_unit32(hb));
        let s = a * a + b * b;
        // s > 1e-300: the doubled angle of a point at the centre is undefined.
        if s < 1.0 && s > 1e-300 {
            let inv = 1.0 / s;
            return Vec3::new((a * a - b * b) * inv, 2.0 * a * b * inv, 0.0);
        }
    }
}
