//! How a sample's total momentum starts: `n` independent draws of the initial distribution
//! (GRW (27), the start every finite-n estimator of GRW and RW assumes), or those draws moved
//! so that the sample's mean velocity is the distribution's exactly (a gas at rest in its
//! centre-of-mass frame: zero total momentum about the drift, so that the raw temperature does
//! not freeze at the sample's centre-of-mass energy `|P|^2/(d n^2)` while the gas cools).

use crate::math::Real;
use crate::particles::Particle;
use crate::vec3::Vec3;

/// How the sample's total momentum starts.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum Momentum {
    /// `n` independent draws: the sample's mean velocity fluctuates about the distribution's
    /// by `sqrt(T/(m n))` per component (the default; GRW (27)).
    #[default]
    Drawn,
    /// The draws shifted by one velocity so that their mean is the distribution's mean (each
    /// species' for a mixture): the sample's total momentum is exact. The temperature about
    /// the flow is unchanged by the shift; only the drift's fluctuation is gone.
    Exact,
}

impl Momentum {
    /// Every choice, in the order of their names.
    pub const ALL: [Momentum; 2] = [Momentum::Drawn, Momentum::Exact];

    /// Its scene word (`particles.momentum = "..."`).
    pub const fn scene_name(self) -> &'static str {
        match self {
            Momentum::Drawn => "drawn",
            Momentum::Exact => "exact",
        }
    }

    /// What it means, in words for a summary.
    pub const fn words(self) -> &'static str {
        match self {
            Momentum::Drawn => "n independent draws of the initial distribution",
            Momentum::Exact => {
                "independent draws shifted so that the sample's mean velocity is the \
                 distribution's (zero total momentum about the drift)"
            }
        }
    }
}

/// Shifts `particles` by one velocity so that their mean velocity is `target` (equal weights:
/// the start, before any collision). Nothing for an empty slice.
pub(super) fn set_mean(particles: &mut [Particle], target: Vec3) {
    if particles.is_empty() {
        return;
    }
    let mut sum = Vec3::ZERO;
    for q in particles.iter() {
        sum += q.velocity();
    }
    let shift = target - (1.0 / particles.len() as Real) * sum;
    for q in particles.iter_mut() {
        q.set_velocity(q.velocity() + shift);
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_shifted_sample_has_the_target_mean_and_its_spread() {
        let mut p = [
            Particle::new(Vec3::new(1.0, 2.0, -1.0), 0.0),
            Particle::new(Vec3::new(3.0, -2.0, 0.5), 0.0),
            Particle::new(Vec3::new(-0.5, 0.0, 2.0), 0.0),
        ];
        let before: [Vec3; 3] = core::array::from_fn(|i| p[i].velocity() - p[0].velocity());
        set_mean(&mut p, Vec3::new(0.25, 0.0, -1.0));
        let mean = (1.0 / 3.0) * (p[0].velocity() + p[1].velocity() + p[2].velocity());
        assert!((mean - Vec3::new(0.25, 0.0, -1.0)).norm2() < 1e-28);
        // The differences (the temperature about the flow) are kept.
        for (i, b) in before.iter().enumerate() {
            assert!(((p[i].velocity() - p[0].velocity()) - *b).norm2() < 1e-28);
        }
    }
}
