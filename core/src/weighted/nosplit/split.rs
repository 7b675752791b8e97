//! The weighted loop's weight windows ([`crate::weighted::windows`]): the splits after an
//! event, and the switch that turns them on.

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
