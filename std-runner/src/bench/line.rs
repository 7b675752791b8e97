//! The bench's output lines as types: each line's fields, written as `key=value` words in the
//! documented order by their `Display`, so that what the bench measures is checked on the
//! values (its tests) and printed in one place (the command).

use std::fmt;

/// One line of `gdsmc bench throughput`.
#[derive(Clone, Debug, PartialEq)]
pub enum Line {
    /// `clock=thread-cpu-time`, first: every rate is per CPU second of the measuring thread.
    Clock,
    /// An event loop's speed beside the machine's limits.
    Loop(LoopLine),
    /// A batch kernel's or a limit's rate.
    Rate(RateLine),
}

/// An event loop's line: `case=<name> kernel=<k> n=<n> collisions_per_s=<x>
/// attempts_per_s=<y> acceptance=<a> of_pair_reference=<f> of_rng=<g> spread=<s>
/// [background_per_s=<b>] [choice_reads_per_candidate=<r> choice_reads_per_collision=<q>]`:
/// each rate the median of the bench's rounds, `f` the median of each round's candidates over
/// the pair reference timed just before it, `s` the rounds' range of candidates per second
/// over their median.
#[derive(Clone, Debug, PartialEq)]
pub struct LoopLine {
    /// The case (loop, drive, restitution).
    pub case: &'static str,
    /// The kernel's scene name (`maxwell`, `hard-spheres`, `vhs`).
    pub kernel: &'static str,
    /// Particles.
    pub n: usize,
    /// Real collisions per second (the rounds' median).
    pub collisions_per_s: f64,
    /// Candidates (events of the majorant process) per second (the rounds' median).
    pub attempts_per_s: f64,
    /// The rounds' median of candidates per second over the pair reference's pairs per
    /// second timed just before each round.
    pub of_pair_reference: f64,
    /// The rounds' range of candidates per second over their median.
    pub spread: f64,
    /// The limits at this `n` the line is set against.
    pub limits: Limits,
    /// A host medium's grain-background collisions per second (BRS (26)); `None` for the
    /// other drives.
    pub background_per_s: Option<f64>,
    /// The sum form's random particle reads per candidate in its weighted choice of the first
    /// particle (beyond the pair's two); `None` for the other loops.
    pub choice_reads_per_candidate: Option<f64>,
}

/// The machine's rates an event-loop line is set against.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Limits {
    /// The reference rate of random pairs read and written per CPU second at this `n`
    /// (`case=reference-pair-update`: short timings of one swap loop at its best lookahead,
    /// not a bound), the median of its timings between the loop's rounds.
    pub pairs: f64,
    /// Raw xoshiro256++ numbers per second (`case=limit-xoshiro256pp`).
    pub numbers: f64,
}

impl LoopLine {
    /// The fraction of candidates that collide.
    #[must_use]
    pub fn acceptance(&self) -> f64 {
        self.collisions_per_s / self.attempts_per_s
    }

    /// Candidates per second as a fraction of the generator's raw rate (a candidate needs
    /// several numbers: the pair, the waiting time, the direction, the acceptance draw).
    #[must_use]
    pub fn of_rng(&self) -> f64 {
        self.attempts_per_s / self.limits.numbers
    }
}

/// What a rate line counts.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Unit {
    /// Random numbers drawn.
    Numbers,
    /// Random pairs read and written.
    Pairs,
    /// Particles handled by a batch kernel.
    Particles,
    /// Random particle reads.
    Reads,
}

impl Unit {
    /// The line's key.
    #[must_use]
    pub fn key(self) -> &'static str {
        match self {
            Unit::Numbers => "numbers_per_s",
            Unit::Pairs => "pairs_per_s",
            Unit::Particles => "particles_per_s",
            Unit::Reads => "reads_per_s",
        }
    }
}

/// A batch kernel's or a limit's line: `case=<name> [n=<n>] <unit>_per_s=<x>
/// [lookahead=<l>] spread=<s>`: the rate the median of the bench's rounds, `s` their range over
/// it.
#[derive(Clone, Debug, PartialEq)]
pub struct RateLine {
    /// The case.
    pub case: &'static str,
    /// Particles, where the rate depends on them.
    pub n: Option<usize>,
    /// What is counted.
    pub unit: Unit,
    /// Counted per second.
    pub per_s: f64,
    /// The pair limit's best lookahead.
    pub lookahead: Option<usize>,
    /// The rounds' range over their median.
    pub spread: f64,
}

impl fmt::Display for Line {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Line::Clock => write!(f, "clock=thread-cpu-time"),
            Line::Loop(l) => {
                write!(
                    f,
                    "case={} kernel={} n={} collisions_per_s={:.4e} attempts_per_s={:.4e} acceptance={:.3} of_pair_reference={:.3} of_rng={:.4} spread={:.3}",
                    l.case,
                    l.kernel,
                    l.n,
                    l.collisions_per_s,
                    l.attempts_per_s,
                    l.acceptance(),
                    l.of_pair_reference,
                    l.of_rng(),
                    l.spread
                )?;
                if let Some(b) = l.background_per_s {
                    write!(f, " background_per_s={b:.4e}")?;
                }
                if let Some(r) = l.choice_reads_per_candidate {
                    write!(
                        f,
                        " choice_reads_per_candidate={r:.3} choice_reads_per_collision={:.3}",
                        r / l.acceptance()
                    )?;
                }
                Ok(())
            }
            Line::Rate(r) => {
                write!(f, "case={}", r.case)?;
                if let Some(n) = r.n {
                    write!(f, " n={n}")?;
                }
                write!(f, " {}={:.4e}", r.unit.key(), r.per_s)?;
                if let Some(l) = r.lookahead {
                    write!(f, " lookahead={l}")?;
                }
                write!(f, " spread={:.3}", r.spread)
            }
        }
    }
}

/// The line of `gdsmc bench scaling`.
#[derive(Clone, Debug, PartialEq)]
pub struct ScalingLine {
    /// The scene's name.
    pub scene: String,
    /// Its ensembles.
    pub ensembles: u64,
    /// Wall seconds on one thread.
    pub one_s: f64,
    /// Threads of the second run.
    pub threads: usize,
    /// Wall seconds on `threads` threads.
    pub many_s: f64,
    /// Whether both runs' statistics agree bit for bit.
    pub bit_identical: bool,
}

impl fmt::Display for ScalingLine {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(
            f,
            "case=ensemble-scaling scene={} ensembles={} threads=1 wall_s={:.3} threads={} wall_s={:.3} speedup={:.2} bit_identical={}",
            self.scene,
            self.ensembles,
            self.one_s,
            self.threads,
            self.many_s,
            self.one_s / self.many_s,
            self.bit_identical
        )
    }
}
