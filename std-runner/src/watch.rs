//! What the caller sees of a running job (a run or a sweep) and how it stops one: the progress,
//! the notes for the user and the stop flag ([`Watch`]); [`Quiet`] for tests and scripts. The
//! command's own is `terminal::Terminal` (feature `cli`).

use std::sync::atomic::AtomicBool;

/// What the caller sees of a running job and how it stops one.
pub trait Watch: Sync {
    /// The job is about to run towards `total` ensembles (those a journal already holds
    /// included).
    fn begin(&self, total: u64);
    /// `k` more ensembles finished.
    fn advance(&self, k: u64);
    /// The ensembles are done or stopped; notes and the outcome follow.
    fn end(&self);
    /// Set when the user asks the job to stop: the running ensembles finish, the rest are
    /// skipped, and what is done is kept.
    fn stop(&self) -> &AtomicBool;
    /// A line for the user beside the results (the command's standard error).
    fn note(&self, line: &str);
}

/// A [`Watch`] that shows nothing and never stops (tests, scripts).
#[derive(Debug, Default)]
pub struct Quiet(AtomicBool);

impl Watch for Quiet {
    fn begin(&self, _: u64) {}
    fn advance(&self, _: u64) {}
    fn end(&self) {}
    fn stop(&self) -> &AtomicBool {
        &self.0
    }
    fn note(&self, _: &str) {}
}
