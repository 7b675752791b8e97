//! Uniform white-noise heating: the Brownian kick GRW (18), RW (9),
//! `v(t + dt) = v(t) + sqrt(2 beta dt) xi`, `xi` standard normal in R^3, which solves the
//! heating term `beta Laplace_v f` of GRW (1) exactly for any `dt`.

use super::Drive;
use crate::batch::kick::white_noise_kick_all;
use crate::geometry::{Disks, Geometry, Spheres};
use crate::math::{Real, sqrt};
use crate::particles::Particles;
use crate::rng::Rng;
use crate::sample::{standard_normal_pair, standard_normal3, standard_normals};
use crate::vec3::Vec3;

/// White noise of strength `beta >= 0` (GRW (1)).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct WhiteNoise {
    beta: Real,
}

impl WhiteNoise {
    /// `None` unless `beta` is finite and `>= 0`.
    pub fn new(beta: Real) -> Option<Self> {
        if beta.is_finite() && beta >= 0.0 {
            Some(WhiteNoise { beta })
        } else {
            None
        }
    }
    /// The heating strength `beta`.
    pub fn beta(&self) -> Real {
        self.beta
    }
}

impl Drive for WhiteNoise {
    const ACTS: bool = true;

    #[inline(always)]
    fn evolve<R: Rng + ?Sized>(&self, v: Vec3, dt: Real, rng: &mut R) -> Vec3 {
        v + sqrt(2.0 * self.beta * dt) * standard_normal3(rng)
    }

    fn kick_all<R: Rng + ?Sized>(&self, p: &mut Particles<'_>, t: Real, rng: &mut R) {
        white_noise_kick_all(2.0 * self.beta, p, t, rng);
    }

    #[inline(always)]
    fn kick_pair_counting<R: Rng + ?Sized>(
        &self,
        p: &mut Particles<'_>,
        pair: (usize, usize),
        t: Real,
        rng: &mut R,
        _events: &mut u64,
    ) {
        white_noise_kick_pair(2.0 * self.beta, p, pair, t, rng);
    }
}

/// Kicks the partners `i` and `j` to `t` with strength `two_beta = 2 beta` (GRW (18)): six
/// normals from three words ([`standard_normals`]), `i`'s three first.
#[inline(always)]
pub fn white_noise_kick_pair<R: Rng + ?Sized>(
    two_beta: Real,
    p: &mut Particles<'_>,
    (i, j): (usize, usize),
    t: Real,
    rng: &mut R,
) {
    let g: [Real; 6] = if cfg!(target_os = "none") {
        // A loop in a firmware built for size; on hosts the three pairs written out.
        standard_normals(rng)
    } else {
        let (a, b) = standard_normal_pair(rng);
        let (c, d) = standard_normal_pair(rng);
        let (e, f) = standard_normal_pair(rng);
        [a, b, c, d, e, f]
    };
    for (k, g) in [
        (i, Vec3::new(g[0], g[1], g[2])),
        (j, Vec3::new(g[3], g[4], g[5])),
    ] {
        let q = p.get_mut(k);
        let v = q.velocity() + sqrt(two_beta * (t - q.t_kick)) * g;
        q.set_velocity(v);
        q.t_kick = t;
    }
}

/// White noise of strength `beta >= 0` on disks (`d = 2`, [`crate::geometry`]): GRW (18) on
/// the two components of the plane, `dT/dt = 2 beta` per degree of freedom as in d = 3.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct PlanarWhiteNoise {
    beta: Real,
}

impl PlanarWhiteNoise {
    /// `None` unless `beta` is finite and `>= 0`.
    pub fn new(beta: Real) -> Option<Self> {
        WhiteNoise::new(beta).map(|w| PlanarWhiteNoise { beta: w.beta })
    }
    /// The heating strength `beta`.
    pub fn beta(&self) -> Real {
        self.beta
    }
}

impl Drive for PlanarWhiteNoise {
    const ACTS: bool = true;

    #[inline(always)]
    fn evolve<R: Rng + ?Sized>(&self, v: Vec3, dt: Real, rng: &mut R) -> Vec3 {
        v + sqrt(2.0 * self.beta * dt) * Disks::normal(rng)
    }
}

/// White noise in the dimension a [`Geometry`] names: [`WhiteNoise`] for spheres,
/// [`PlanarWhiteNoise`] for disks (a loop generic over the dimension takes `G::Noise`).
pub trait WhiteNoiseIn: Geometry {
    /// The white noise of this dimension.
    type Noise: Drive;
    /// A validated white noise in this dimension (same `beta`).
    fn noise(w: WhiteNoise) -> Self::Noise;
}

impl WhiteNoiseIn for Spheres {
    type Noise = WhiteNoise;
    fn noise(w: WhiteNoise) -> WhiteNoise {
        w
    }
}

impl WhiteNoiseIn for Disks {
    type Noise = PlanarWhiteNoise;
    fn noise(w: WhiteNoise) -> PlanarWhiteNoise {
        PlanarWhiteNoise { beta: w.beta }
    }
}
