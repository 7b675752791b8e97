//! A mixture of Maxwellians (BRS (35)): `f_0(v) = sum_k w_k f_{M_k}(v) / sum_k w_k`, sampled by
//! choosing component `k` with probability `w_k / sum w` (one uniform against the cumulative
//! weights) and then a velocity from it. Capacity `CAP` is fixed at compile time and exceeding
//! it is an error, never a panic (heapless style).
//!
//! ```
//! use gdsmc_core::{rng::seeded, sample::{Maxwellian, MaxwellianMixture}, vec3::Vec3};
//! // BRS Example 1: equal weights, drifts (-2, 2, 0) and (2, 0, 0), unit mass and temperature.
//! let mut mix = MaxwellianMixture::<4>::new();
//! mix.push(0.5, Maxwellian::new(1.0, 1.0, Vec3::new(-2.0, 2.0, 0.0)).unwrap()).unwrap();
//! mix.push(0.5, Maxwellian::new(1.0, 1.0, Vec3::new(2.0, 0.0, 0.0)).unwrap()).unwrap();
//! let v = mix.sample(&mut seeded(9)).unwrap();
//! assert!(v.is_finite());
//! ```

use super::{Maxwellian, ParamError};
use crate::math::Real;
use crate::rng::{Rng, uniform01};
use crate::vec3::Vec3;

/// A finite mixture of at most `CAP` Maxwellians.
#[derive(Clone, Debug)]
pub struct MaxwellianMixture<const CAP: usize> {
    components: heapless::Vec<(Real, Maxwellian), CAP>,
    total: Real,
}

impl<const CAP: usize> Default for MaxwellianMixture<CAP> {
    fn default() -> Self {
        Self::new()
    }
}

impl<const CAP: usize> MaxwellianMixture<CAP> {
    /// An empty mixture.
    pub const fn new() -> Self {
        MaxwellianMixture {
            components: heapless::Vec::new(),
            total: 0.0,
        }
    }

    /// Adds a component with weight `weight >= 0` (weights need not sum to one).
    pub fn push(&mut self, weight: Real, m: Maxwellian) -> Result<(), ParamError> {
        if !(weight.is_finite() && weight >= 0.0) {
            return Err(ParamError::Weight);
        }
        self.components
            .push((weight, m))
            .map_err(|_| ParamError::Capacity)?;
        self.total += weight;
        Ok(())
    }

    /// The components and their (unnormalized) weights.
    pub fn components(&self) -> &[(Real, Maxwellian)] {
        &self.components
    }

    /// Mean velocity `sum w_k u_k / sum w_k`.
    pub fn mean(&self) -> Vec3 {
        let mut m = Vec3::ZERO;
        for (w, c) in &self.components {
            m += (*w / self.total) * c.drift();
        }
        m
    }

    /// Temperature about the mean velocity (unit grain mass, BRS (8)):
    /// `(1/3) sum_k w_k (3 T_k/m_k + |u_k - u|^2) / sum w`.
    pub fn temperature(&self) -> Real {
        self.temperature_in(3)
    }

    /// Temperature about the mean velocity in dimension `d` (disks: `d = 2`, the components'
    /// drifts in the plane): `(1/d) sum_k w_k (d T_k/m_k + |u_k - u|^2) / sum w`.
    pub fn temperature_in(&self, d: usize) -> Real {
        let u = self.mean();
        let d = d as Real;
        let mut t = 0.0;
        for (w, c) in &self.components {
            t += (*w / self.total) * (d * c.temperature() / c.mass() + (c.drift() - u).norm2()) / d;
        }
        t
    }

    /// `Err(ParamError::Weight)` when no component has positive weight (nothing to sample).
    pub fn check(&self) -> Result<(), ParamError> {
        if self.total.is_nan() || self.total <= 0.0 {
            return Err(ParamError::Weight);
        }
        Ok(())
    }

    /// One velocity; `Err(ParamError::Weight)` when there is no component of positive weight.
    #[inline]
    pub fn sample<R: Rng + ?Sized>(&self, rng: &mut R) -> Result<Vec3, ParamError> {
        self.check()?;
        let target = uniform01(rng) * self.total;
        let mut acc = 0.0;
        let mut chosen = None;
        for (w, c) in &self.components {
            if *w > 0.0 {
                chosen = Some(c);
                acc += *w;
                if target < acc {
                    break;
                }
            }
        }
        // `chosen` is the last positive-weight component if rounding left `target >= acc`.
        Ok(chosen.ok_or(ParamError::Weight)?.sample(rng))
    }
}
