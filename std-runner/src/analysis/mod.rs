//! What a finished run's statistics say beyond the means: the tail exponent (GRW Section 4.3),
//! the reduced and marginal distributions (MS, BRS), and the warnings of its own diagnostics.

pub mod distribution;
pub mod tails;
pub mod warnings;
