//! The one statistics kit of gdsmc, used by the runner, `reproduce`, the C and Python checks and
//! every test crate: the papers' 99.9% interval (GRW (25), BRS (33): lambda_p = 3.2) with its
//! Student-t form at few ensembles ([`multiplier`]), Bonferroni families of checks judged
//! together ([`joint`], [`family`]), an ensemble [`Accumulator`] whose merge does not depend on
//! the thread split (a vector's [`Covariance`] too, for the delta method), and the [`Sample`] summary of values held in memory.
//!
//! A z-level is never written as a number elsewhere: a single interval is [`multiplier`]`(M)`
//! (or [`LAMBDA_999`] where a paper prints 3.2), `k` intervals at once are [`joint`]`(k, dof)`.

pub mod accumulator;
pub mod covariance;
pub mod level;
pub mod sample;

pub use accumulator::{Accumulator, welford};
pub use covariance::Covariance;
pub use level::{KNOWN, LAMBDA_999, dof, family, joint, level_999, miss, multiplier, quantile_t};
pub use sample::{Sample, mean_ci, ratio_of_means};
