//! The weighted loop's weight windows ([`crate::weighted::windows`]): the splits after an
//! event and at every refresh of the bounds, and the switch that turns them on.
//!
//! The windows are measured again at every refresh (every `2 n` candidates), and the shares
//! of the thin shells move with them: with the shells' width (the fastest particle's speed
//! over their number) and with the few particles a far shell holds. A particle that was
//! within its window may then be far over it. Split only when an event next touched it, it
//! was first kicked whole: a particle near 8 sqrt(T) of GRW Example 3, a few times
//! over its share, kicked a third of sqrt(T) out, landed where it weighed hundreds
//! of shares, and those arrivals made most of the variance of the weight found there (and
//! the rare rounds whose variance was ten to a hundred times the median). So every refresh
//! passes every particle through the new windows. A particle not touched since its last kick
//! is cut into copies at its velocity and last-kick time, which part at their own first
//! kicks: independent pieces of what the lone kick would have carried. A split keeps the
//! measure itself and is a change of state after the event whose count was due, so the
//! process stays exact (docs/weighted.md, "Every particle through the windows at every
//! refresh").

use super::WeightedNoSplitting;
use crate::drive::Drive;
use crate::geometry::Geometry;
use crate::kernel::Kernel;
use crate::math::Real;
use crate::particles::Particles;
use crate::restitution::Restitution;

impl<K: Kernel, A: Restitution, D: Drive, G: Geometry> WeightedNoSplitting<K, A, D, G> {
    /// The loop with weight windows ([`crate::weighted::windows`]): after every event a particle the
    /// event touched that is heavier than `split` times its speed shell's share (the allocated
    /// reduction's, measured at every refresh of the bounds) is split into pieces of about
    /// the share. `split = 0` never splits; a reduction by cells has no shares and never
    /// splits. The windows are measured at the next refresh (the run's resync).
    #[must_use]
    pub fn with_windows(mut self, split: Real) -> Self {
        self.split = split;
        self
    }

    /// The copies the weight windows have made so far.
    pub fn splits(&self) -> u64 {
        self.splits
    }

    /// Every particle split by the windows ([`Self::split`]; nothing without them).
    pub(super) fn split_all(&mut self, sys: &mut Particles<'_>) {
        if self.windows.is_some() {
            for i in 0..sys.len() {
                self.split(sys, i);
            }
        }
    }

    /// Particle `i` split by the windows (module docs of [`crate::weighted::windows`]) into copies at
    /// its velocity and last-kick time, as many as half the free room beyond a collision's two
    /// allows.
    pub(super) fn split(&mut self, sys: &mut Particles<'_>, i: usize) {
        let Some(w) = &self.windows else {
            return;
        };
        let (q, g) = (sys.as_slice()[i], sys.weight(i));
        // Half the free room beyond the two a collision's particles need.
        let room = (sys.capacity() - sys.len()).saturating_sub(2) / 2;
        let m = w.pieces(q.velocity(), g).min(room + 1);
        if m < 2 {
            return;
        }
        let piece = g / m as Real;
        sys.set_weight(i, piece);
        for _ in 1..m {
            // Room was counted above.
            let _ = sys.push(q.velocity(), piece, q.t_kick);
        }
        self.splits += (m - 1) as u64;
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::drive::WhiteNoise;
    use crate::geometry::Spheres;
    use crate::kernel::Maxwell;
    use crate::particles::Particle;
    use crate::restitution::Constant;
    use crate::rng::stream;
    use crate::sample::standard_normal3;
    use crate::vec3::Vec3;
    use crate::weighted::{Reduction, Transfer};

    /// A refresh passes every particle through the windows it measures: 64 particles of a
    /// Maxwellian and one of weight 20 at 6 sqrt(T), windows turned on after the start
    /// (so the first refresh measures them); after it every particle is within its window and
    /// the heavy one was cut. Fails when the refresh leaves the particles to the next event
    /// that touches them (checked).
    #[test]
    fn a_refresh_puts_every_particle_through_the_new_windows() {
        let mut rng = stream(56, 1);
        let (mut buf, mut g) = ([Particle::default(); 512], [0.0; 512]);
        for (p, w) in buf.iter_mut().zip(g.iter_mut()).take(64) {
            *p = Particle::new(standard_normal3(&mut rng), 0.0);
            *w = 1.0;
        }
        buf[64] = Particle::new(Vec3::new(6.0, 0.0, 0.0), 0.0);
        g[64] = 20.0;
        let mut sys = Particles::weighted(&mut buf, &mut g, 65).unwrap();
        let reduction = Reduction::Allocated {
            target: 128,
            shells: 32,
            exponent: 0.25,
            floor: 0.25,
        };
        let mut e = WeightedNoSplitting::<_, _, _, Spheres>::start(
            (
                Maxwell::new(1.0, 1.0).unwrap(),
                Constant::new(0.5).unwrap(),
                WhiteNoise::new(1.0).unwrap(),
            ),
            Transfer::new(0.0).unwrap(),
            reduction,
            &mut sys,
            0.0,
        )
        .unwrap()
        .with_windows(2.0);
        assert!(e.windows.is_none(), "measured at the next refresh");
        e.until_refresh = 1;
        e.count_refresh(&mut sys, &mut rng).unwrap();
        let w = e.windows.expect("measured");
        assert!(sys.len() > 65, "the heavy particle was cut: {}", sys.len());
        assert!((sys.mass() - 84.0).abs() < 1e-12, "the weight is kept");
        for (p, &gk) in sys.as_slice().iter().zip(sys.weights()) {
            assert_eq!(w.pieces(p.velocity(), gk), 1, "{:?} of {gk}", p.velocity());
        }
    }
}
