//! `mpirun -n R gdsmc sweep SCENE` (cargo feature `mpi`): rank r runs the sweep's shard task
//! r of R ([`super::shard`]: the points `k mod R = r`, or with more ranks than points shards
//! of every point's ensembles), sends rank 0 its journals' bytes (point to point, so the nodes
//! need no shared file system), and rank 0 puts them beside the output directory and
//! assembles the sweep from them: the single process's bytes. A job that is killed continues
//! from the journals when the same `mpirun` command runs again; the journals go once rank 0
//! has written the outputs.

use super::{PointScene, Sweep, shard};
use crate::error::Error;
use crate::job::{Outcome, Quiet, Watch};
use crate::run::mpi::World;
use std::fmt::Write as _;

impl Sweep {
    /// Rank r's part of the sweep (see the module docs); rank 0 returns the sweep's outcome,
    /// the others an empty one.
    pub(super) fn run_mpi(
        &self,
        w: &World,
        points: Vec<PointScene>,
        watch: &dyn Watch,
    ) -> Result<Outcome, Error> {
        let (r, p) = (w.rank(), w.size());
        let dir = self.dir();
        let started = std::time::Instant::now();
        // The output place is rank 0's to check, before any work; every rank hears its verdict
        // (the others leave quietly, so that rank 0's message is out before mpirun ends).
        let place = if r == 0 {
            crate::report::set::check_replaceable(&dir)
        } else {
            Ok(())
        };
        if !w.broadcast_ok(place.is_ok()) {
            place?;
            return Ok(Outcome {
                text: String::new(),
                complete: true,
            });
        }
        let quiet = Quiet::default();
        let shown: &dyn Watch = if r == 0 { watch } else { &quiet };
        let task = self.shard_task((r, p), points.clone(), shown);
        // Every rank sends, even after an error, so that no rank waits forever.
        let mine = shard::journals(&dir, r, p, &points);
        let bytes: Vec<Vec<u8>> = mine
            .iter()
            .map(|f| crate::run::journal::read_file(f).unwrap_or_default())
            .collect();
        let mut result = None;
        if let Some(all) = w.gather(&bytes) {
            // Rank q's journals are the ones its task names: rank 0 names them itself.
            let placed = (1..p).try_for_each(|q| {
                let files = shard::journals(&dir, q, p, &points);
                for (f, b) in files.iter().zip(&all[q as usize]) {
                    let there = crate::run::journal::read_file(f).ok();
                    if !b.is_empty() && there.as_deref() != Some(&b[..]) {
                        crate::files::write_atomic(f, b)?;
                    }
                }
                Ok::<(), Error>(())
            });
            result = Some(placed.and_then(|()| self.assemble(points, watch)));
        }
        let done = w.broadcast_ok(
            result
                .as_ref()
                .is_some_and(|o| o.as_ref().is_ok_and(|o| o.complete)),
        );
        if done && r != 0 {
            for f in &mine {
                let _ = std::fs::remove_file(f);
            }
        }
        task?;
        match result {
            Some(out) => {
                let mut out = out?;
                let _ = writeln!(
                    out.text,
                    "{p} MPI ranks, {:.2} s from start to the written sweep",
                    started.elapsed().as_secs_f64()
                );
                Ok(out)
            }
            None => Ok(Outcome {
                text: String::new(),
                complete: true,
            }),
        }
    }
}
