//! What an event loop counts: candidates, collisions, fictitious collisions, observations.

/// Event counts of a run.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Counts {
    /// Candidate pairs drawn (events of the majorant process).
    pub candidates: u64,
    /// Real collisions (candidates accepted).
    pub collisions: u64,
    /// Fictitious collisions (candidates rejected, GRW (20)).
    pub fictitious: u64,
    /// Candidates whose relative speed exceeded the majorant `Umax` that generated their
    /// waiting time: the kernel was truncated there (RW (19)). Every such pair is accepted.
    pub overshoots: u64,
    /// Observations (synchronizing kicks of all particles).
    pub observations: u64,
    /// Collisions whose restitution law gave a value outside [0, 1], clamped to it.
    pub clamped: u64,
    /// Majorant refreshes between observations (no-splitting scheme, loose bound).
    pub refreshes: u64,
    /// Rescalings of a cooling gas's stored velocities (no-splitting scheme, no drive).
    pub rescales: u64,
    /// Real collisions of grains with the host medium's background (BRS (26) events; 0 for
    /// other drives).
    pub background: u64,
}

impl Counts {
    /// Sum of two counts.
    pub fn add(&self, o: &Counts) -> Counts {
        Counts {
            candidates: self.candidates + o.candidates,
            collisions: self.collisions + o.collisions,
            fictitious: self.fictitious + o.fictitious,
            overshoots: self.overshoots + o.overshoots,
            observations: self.observations + o.observations,
            clamped: self.clamped + o.clamped,
            refreshes: self.refreshes + o.refreshes,
            rescales: self.rescales + o.rescales,
            background: self.background + o.background,
        }
    }

    /// Number of single-particle kicks for `n` particles: two per candidate and `n` per
    /// observation (RW Section 4.2, `N_kick = 2 N_coll + n M`).
    pub fn kicks(&self, n: usize) -> u64 {
        2 * self.candidates + n as u64 * self.observations
    }
}
