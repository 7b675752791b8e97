//! MPI (cargo feature `mpi`): `mpirun -n P gdsmc run SCENE` runs shard r of P on rank r and
//! merges the shards on rank 0 in ensemble order, the fold every run uses, so the outputs are
//! byte-identical to one process's.
//!
//! Each rank keeps its ensembles in its own journal beside the output directory
//! (`.NAME.rank-r-of-P.gdsmc-ensembles`), so a job that is killed or loses a node continues
//! when the same `mpirun` command is run again; the journals go once rank 0 has written the
//! outputs. Ranks send rank 0 their journal's bytes (point to point, in rank order), so nodes
//! need no shared file system.

use crate::error::Error;
use crate::run::journal::{self, Header};
use crate::run::shard::{self, Merged};
use crate::run::{JournalRun, Journaled};
use crate::scene::Scene;
use mpi::traits::*;
use std::path::{Path, PathBuf};
use std::sync::atomic::AtomicBool;

/// The MPI world when this process was started by an MPI launcher with more than one rank
/// (OpenMPI, MPICH and Slurm set their size variables); `None` otherwise, and MPI is then not
/// initialized at all, so a plain `gdsmc run` of an MPI build behaves as any other.
pub struct World {
    _universe: mpi::environment::Universe,
    world: mpi::topology::SimpleCommunicator,
}

/// The launcher variables that say how many ranks there are.
const SIZE_VARS: [&str; 4] = [
    "OMPI_COMM_WORLD_SIZE",
    "PMI_SIZE",
    "PMIX_SIZE",
    "MPI_LOCALNRANKS",
];

impl World {
    /// Initializes MPI when launched with more than one rank.
    pub fn init() -> Option<World> {
        let many = SIZE_VARS.iter().any(|v| {
            std::env::var(v)
                .ok()
                .and_then(|s| s.parse::<u32>().ok())
                .is_some_and(|n| n > 1)
        });
        if !many {
            return None;
        }
        let universe = mpi::initialize()?;
        let world = universe.world();
        (world.size() > 1).then_some(World {
            _universe: universe,
            world,
        })
    }

    /// This process's rank.
    pub fn rank(&self) -> u64 {
        self.world.rank() as u64
    }

    /// The number of ranks.
    pub fn size(&self) -> u64 {
        self.world.size() as u64
    }

    /// Rank 0's `ok` (the other ranks pass anything), heard by every rank.
    pub fn broadcast_ok(&self, ok: bool) -> bool {
        let mut flag = u8::from(ok);
        self.world.process_at_rank(0).broadcast_into(&mut flag);
        flag == 1
    }

    /// Every rank's `blobs` to rank 0, in rank order (point to point, so the nodes need no
    /// shared file system): rank 0 gets each rank's list, its own first; the others `None`.
    pub fn gather(&self, blobs: &[Vec<u8>]) -> Option<Vec<Vec<Vec<u8>>>> {
        let root = self.world.process_at_rank(0);
        if self.rank() != 0 {
            root.send(&[blobs.len() as u64][..]);
            for b in blobs {
                root.send(&b[..]);
            }
            return None;
        }
        let mut all = vec![blobs.to_vec()];
        for q in 1..self.size() {
            let from = self.world.process_at_rank(q as i32);
            let (count, _) = from.receive_vec::<u64>();
            let n = count.first().copied().unwrap_or(0);
            all.push((0..n).map(|_| from.receive_vec::<u8>().0).collect());
        }
        Some(all)
    }
}

/// Runs this rank's shard of `scene` (`header_of(shard, range)` gives its journal header) and,
/// on rank 0, merges every rank's and hands the result to `write`; the journals are removed
/// when `write` succeeds. Before any work rank 0 asks `check_place` whether the output place
/// may be written (every rank hears the answer: rank 0 returns the refusal, the others
/// `None`). Returns the merged run on rank 0, `None` on the others.
#[allow(clippy::too_many_arguments)]
pub fn run(
    w: &World,
    scene: &Scene,
    header_of: impl Fn((u64, u64), std::ops::Range<u64>) -> Header,
    dir: &Path,
    threads: usize,
    check_place: impl FnOnce() -> Result<(), Error>,
    write: impl FnOnce(&Merged) -> Result<(), Error>,
) -> Result<Option<Merged>, Error> {
    let (r, p) = (w.rank(), w.size());
    // Every rank decides this alike, before any message: no rank waits for another.
    if p > scene.ensembles() {
        return Err(Error::Argument {
            flag: "mpirun -n".into(),
            message: format!(
                "{p} ranks for {} ensembles (run.ensembles) would leave ranks without an \
                 ensemble; use at most {} ranks",
                scene.ensembles(),
                scene.ensembles()
            ),
        });
    }
    // The output place is rank 0's to check, before any work; every rank hears its verdict.
    let mut place_ok = 1u8;
    let place = if r == 0 {
        let c = check_place();
        place_ok = u8::from(c.is_ok());
        c
    } else {
        Ok(())
    };
    w.world.process_at_rank(0).broadcast_into(&mut place_ok);
    place?;
    if place_ok == 0 {
        // Rank 0 reports the refusal and exits non-zero; the others leave quietly. Had they
        // exited non-zero too, mpirun could abort the job (killing rank 0) before rank 0's
        // message was out: a race seen in CI, where only "refused by rank 0" was printed.
        return Ok(None);
    }
    let range = shard::range(r, p, scene.ensembles());
    let path = journal::beside(dir, journal::Of::Rank(r, p));
    let job = Journaled {
        scene,
        header: header_of((r, p), range),
        path: &path,
        threads,
        fresh: false,
        state: Default::default(),
    };
    let ran: Result<JournalRun, Error> = job.run(&|_| {}, &AtomicBool::new(false));
    match &ran {
        Err(e) => eprintln!("rank {r}: {e}"),
        Ok(j) if j.resumed > 0 => eprintln!(
            "rank {r}: continued {}: {} ensembles were already done",
            path.display(),
            j.resumed
        ),
        Ok(j) => {
            if let Some(why) = &j.discarded {
                eprintln!("rank {r}: {} not continued ({why})", path.display());
            }
        }
    }
    // Every rank sends, even after an error, so that no rank waits forever.
    let bytes = journal::read_file(&path).unwrap_or_default();
    let root = w.world.process_at_rank(0);
    let mut verdict: u8 = 0;
    let merged = if r == 0 {
        let mut inputs = vec![(path.clone(), bytes)];
        for q in 1..p {
            let (b, _) = w.world.process_at_rank(q as i32).receive_vec::<u8>();
            inputs.push((journal::beside(dir, journal::Of::Rank(q, p)), b));
        }
        let merged = check(&inputs).and_then(|()| shard::merge(&inputs));
        let written = merged.and_then(|m| write(&m).map(|()| m));
        verdict = u8::from(written.is_ok());
        root.broadcast_into(&mut verdict);
        Some(written)
    } else {
        root.send(&bytes[..]);
        root.broadcast_into(&mut verdict);
        None
    };
    if verdict == 1 {
        let _ = std::fs::remove_file(&path);
    }
    ran?;
    merged.transpose()
}

/// Every rank's shard complete; else which ranks stopped early and that the same command
/// continues them.
fn check(inputs: &[(PathBuf, Vec<u8>)]) -> Result<(), Error> {
    let mut short = Vec::new();
    for (i, (path, bytes)) in inputs.iter().enumerate() {
        let c = journal::read(path, bytes)?;
        if c.end.is_none() {
            short.push(format!(
                "rank {i} has {} of its {} ensembles",
                c.rows.len(),
                c.header.end - c.header.start
            ));
        }
    }
    if short.is_empty() {
        Ok(())
    } else {
        Err(Error::Shards(format!(
            "the run stopped early ({}); run the same mpirun command again to continue from \
             the ranks' journals",
            short.join(", ")
        )))
    }
}
