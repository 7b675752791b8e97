//! No drive at all: the freely cooling gas. Kicks compile to nothing.

use super::Drive;
use crate::math::Real;
use crate::particles::Particles;
use crate::rng::Rng;
use crate::vec3::Vec3;

/// No force between collisions (`beta = 0` in GRW (1)).
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct NoDrive;

impl Drive for NoDrive {
    const ACTS: bool = false;
    #[inline(always)]
    fn evolve<R: Rng + ?Sized>(&self, v: Vec3, _dt: Real, _rng: &mut R) -> Vec3 {
        v
    }
    #[inline(always)]
    fn kick_all<R: Rng + ?Sized>(&self, p: &mut Particles<'_>, t: Real, _rng: &mut R) {
        p.reset_kick_times(t);
    }
}
