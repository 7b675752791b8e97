//! The background-partner density BRS (29):
//! `p_2(w) = pi^{1/2} / (2 b rho^B) |w - u^B| f^B(w)`, `b = (2 T^B / m^B)^{1/2}` (BRS (28)),
//! i.e. the normalized background Maxwellian `M^B` weighted by the speed `|w - u^B|`.
//!
//! Exact method: with `s = |w - u^B|` the Maxwellian's speed density is proportional to
//! `s^2 exp(-s^2/b^2)`; weighting by `s` gives `s^3 exp(-s^2/b^2)`, so `y = s^2/b^2` has density
//! `y e^{-y}`, the Gamma(2, 1) law, which is the sum of two standard exponentials. The direction
//! is uniform on the sphere. So `w = u^B + b sqrt(E_1 + E_2) e`.
//!
//! ```
//! use gdsmc_core::{rng::seeded, sample::{BackgroundPartner, Maxwellian}, vec3::Vec3};
//! let bg = Maxwellian::new(1.0, 1.0, Vec3::ZERO).unwrap();
//! let w = BackgroundPartner::new(&bg).sample(&mut seeded(2));
//! assert!(w.is_finite());
//! ```

use super::{Maxwellian, standard_exponential, unit_sphere};
use crate::math::{Real, SQRT_PI, sqrt};
use crate::rng::Rng;
use crate::vec3::Vec3;

/// Sampler of BRS (29) for a given background Maxwellian.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct BackgroundPartner {
    drift: Vec3,
    b: Real,
}

impl BackgroundPartner {
    /// The partner density of the background `bg` (its mass, temperature and drift).
    pub fn new(bg: &Maxwellian) -> Self {
        BackgroundPartner {
            drift: bg.drift(),
            b: sqrt(2.0 * bg.temperature() / bg.mass()),
        }
    }

    /// `b = (2 T^B / m^B)^{1/2}` of BRS (28).
    pub fn b(&self) -> Real {
        self.b
    }

    /// The mean speed `int |w - u^B| M^B(w) dw = 2 b / sqrt(pi)` (BRS, text before (29)).
    pub fn mean_relative_speed(&self) -> Real {
        2.0 * self.b / SQRT_PI
    }

    /// One partner velocity.
    #[inline]
    pub fn sample<R: Rng + ?Sized>(&self, rng: &mut R) -> Vec3 {
        let y = standard_exponential(rng) + standard_exponential(rng);
        self.drift + (self.b * sqrt(y)) * unit_sphere(rng)
    }
}
