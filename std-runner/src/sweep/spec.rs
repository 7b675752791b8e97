//! A sweep as the command takes it, and where its points' journals are.

use crate::report::charts::Formats;
use crate::run;
use crate::scene::Sourced;
use crate::scene::vary::{Combine, Vary};
use std::path::{Path, PathBuf};

/// A sweep as `gdsmc sweep` takes it.
#[derive(Clone, Debug)]
pub struct Sweep {
    /// The base scene (with the command's `--set`, `--n`, `--ensembles`, `--seed`).
    pub source: Sourced,
    /// The varied keys.
    pub vary: Vec<Vary>,
    /// How several keys make points.
    pub combine: Combine,
    /// Worker threads per point (0: all cores).
    pub threads: usize,
    /// Run even when the summed work estimate is above the limit.
    pub allow_long: bool,
    /// The output directory (default out/NAME-sweep).
    pub out: Option<PathBuf>,
    /// Start every point anew instead of continuing its journal.
    pub fresh: bool,
    /// Chart formats.
    pub format: Formats,
    /// Run only shard K of S (`K/S`): the points `k` with `k mod S = K`, journaled where the
    /// whole sweep looks for them; the same command without it then writes the sweep from the
    /// journals.
    pub shard: Option<String>,
}

/// The journal of point `k` of the sweep written to `dir`: beside it, as a run's; with
/// `chunk = Some((c, C))`, the journal of the shard `c` of `C` of the point's ensembles
/// (`.NAME.point-K-shard-c-of-C.gdsmc-ensembles`).
pub(crate) fn point_journal_of(dir: &Path, k: usize, chunk: Option<(u64, u64)>) -> PathBuf {
    run::journal::beside(
        dir,
        match chunk {
            None => run::journal::Of::Point(k),
            Some((c, n)) => run::journal::Of::PointShard(k, c, n),
        },
    )
}

/// The journal of the whole point `k`.
pub(crate) fn point_journal(dir: &Path, k: usize) -> PathBuf {
    point_journal_of(dir, k, None)
}
