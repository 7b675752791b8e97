//! What a finished run's statistics say beyond the means: the tail exponent (GRW Section 4.3),
//! the reduced and marginal distributions (MS, BRS), the reduced tail's power law, and the warnings of its own diagnostics.

pub mod distribution;
pub mod power_tail;
pub mod tails;
pub mod warnings;
