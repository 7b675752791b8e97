//! The impact direction of two hard spheres (MS Section 3's kernel), a sampler every loop
//! that collides at an impact direction takes through [`crate::geometry::Geometry::impact`].

use crate::math::sqrt;
use crate::rng::Rng;
use crate::sample::unit_sphere;
use crate::vec3::Vec3;

/// The unit vector `n` from particle 1 to particle 2 at a hard-sphere collision with relative
/// velocity `u = v1 - v2`: on the hemisphere where the pair approaches, `u . n >= 0`, with
/// density proportional to `u_hat . n` (the impact parameter uniform on the disk; MS
/// Section 3's kernel `Theta(u . s)(u . s)`). For `u = 0`, uniform on the sphere.
///
/// Drawn as `n = (u_hat - e)/|u_hat - e|` with `e` uniform on the sphere: the elastic smooth
/// collision reflects `u_hat` into `e = u_hat - 2 (u_hat . n) n`, which is uniform exactly
/// when `n` has the impact law (the hard-sphere scattering is isotropic, GRW (3)), and the map
/// from `n` on the hemisphere to `e` on the sphere is one to one. One draw of the sphere and
/// one normalization.
#[inline]
pub fn impact_direction<R: Rng + ?Sized>(u: Vec3, rng: &mut R) -> Vec3 {
    // Scaled by its largest component first: `|u|^2` of a tiny `u` (below 1e-154) underflows,
    // which made such a `u` look like 0 (found by the `rough_maps` fuzz target); divided, not
    // multiplied by `1/big`, which overflows for a subnormal `big`.
    let big = u.x.abs().max(u.y.abs()).max(u.z.abs());
    if big == 0.0 {
        return unit_sphere(rng);
    }
    let us = Vec3::new(u.x / big, u.y / big, u.z / big);
    let uh = (1.0 / us.norm()) * us;
    loop {
        let d = uh - unit_sphere(rng);
        let d2 = d.norm2();
        // e = u_hat has probability 0; near it the direction is still accurate to 1e-8.
        if d2 > 1e-16 {
            return (1.0 / sqrt(d2)) * d;
        }
    }
}
