//! Event loops. [`NoSplitting`] is the exact scheme of GRW Section 3 / RW Algorithm 3.

pub mod nosplit;

pub use nosplit::NoSplitting;

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
        }
    }

    /// Number of single-particle kicks for `n` particles: two per candidate and `n` per
    /// observation (RW Section 4.2, `N_kick = 2 N_coll + n M`).
    pub fn kicks(&self, n: usize) -> u64 {
        2 * self.candidates + n as u64 * self.observations
    }
}

/// Why an event loop stopped.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum EngineError {
    /// The requested time lies before the system's current time (or is NaN).
    TimeBackwards,
    /// A velocity or moment became non-finite (overflow, NaN input).
    NonFinite,
}

impl core::fmt::Display for EngineError {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        f.write_str(match self {
            EngineError::TimeBackwards => "observation time lies before the current time",
            EngineError::NonFinite => "a velocity or moment became non-finite",
        })
    }
}
