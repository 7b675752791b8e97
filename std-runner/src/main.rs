//! The `gdsmc` command.

use clap::{Parser, Subcommand};
use gdsmc_runner::scene;
use std::path::PathBuf;
use std::process::ExitCode;

/// gdsmc: direct simulation Monte Carlo for the spatially homogeneous inelastic (granular)
/// Boltzmann equation, with ensemble statistics and exact references.
///
/// A run is described by a scene file (TOML; every key is documented in docs/scenes.md and
/// the shipped scenes in scenes/ reproduce the examples of the four papers: GRW, RW, BRS, MS).
/// Every number is an ensemble mean with the half-width of its 99.9% confidence interval
/// (t sqrt(Var/M), t the Student-t quantile: 3.2 for many ensembles); exact or hydrodynamic references are printed beside it where known.
///
/// Start with:  gdsmc run scenes/grw-example3.toml
#[derive(Parser)]
#[command(version, about, long_about)]
struct Cli {
    #[command(subcommand)]
    command: Command,
}

#[derive(Subcommand)]
enum Command {
    /// Run a scene: ensembles in parallel on all cores, then a summary on stdout.
    ///
    /// Writes into DIR (default out/NAME): observables.csv (per observation time, the mean and
    /// the 99.9% half-width of T, T_bulk, V, p, q, a2, a3, crit, ... and the reference
    /// columns), summary.json (scene, seed, version, timing, collision counts, errors against
    /// the references, steady-state averages, tail exponent), histograms.csv when the scene
    /// asks for it, and SVG charts. Files are replaced atomically. Ctrl-C, SIGTERM (a
    /// scheduler's time limit) and SIGHUP finish the running ensembles and write the results of
    /// those completed (exit code 130, 143, 129: 128 + the signal). Finished ensembles
    /// are kept as they finish in DIR's journal (.NAME.run.gdsmc-ensembles beside it): the same
    /// command continues an interrupted or killed run to the same results. Under mpirun (a
    /// build with the mpi feature) the ranks share the ensembles and rank 0 writes.
    ///
    /// Examples:
    ///   gdsmc run scenes/brs-example5.toml
    ///   gdsmc run scenes/grw-example7.toml --shard 3/8 --threads 4
    ///   gdsmc run scenes/ms-gaussian.toml --set collisions.restitution=0.4
    ///   gdsmc run scenes/rw-steady.toml --set scheme.kind=strang --set scheme.dt=0.25
    #[command(verbatim_doc_comment)]
    Run {
        /// The scene file (TOML), e.g. scenes/grw-example3.toml.
        scene: PathBuf,
        #[command(flatten)]
        flags: SceneFlags,
        /// Output directory (default: out/SCENE-NAME). Replaced only when it is empty or a
        /// whole gdsmc output set; a directory with other files, a file or a link is refused.
        #[arg(long)]
        out: Option<PathBuf>,
        /// Chart formats, comma-separated: svg, png (twice the pixel size, for slides), pdf
        /// (vector, for a paper).
        #[arg(long, value_name = "svg,png,pdf", default_value = "svg")]
        format: gdsmc_runner::report::charts::Formats,
        /// Run only shard K of S (K from 0): ensembles [K M/S, (K+1) M/S), the same ensembles
        /// the whole run has there. Writes DIR/NAME.shard-K-of-S.gdsmc-ensembles (DIR default
        /// out/NAME-shards) for `gdsmc merge`; an interrupted shard continues when run again.
        #[arg(long, value_name = "K/S")]
        shard: Option<String>,
        /// Start anew: do not continue the journal an interrupted run of the same scene and
        /// seed left (by default it is continued; the result is the same either way).
        #[arg(long)]
        fresh: bool,
        /// Save every ensemble's particles at the last observation into FILE (docs/state.md:
        /// a versioned binary file, physical velocities), to continue the run later with
        /// --initial-state. A file gdsmc did not write is refused, not replaced.
        #[arg(long, value_name = "FILE")]
        save_state: Option<PathBuf>,
        /// Start every ensemble from FILE (written by --save-state) at its time instead of the
        /// scene's initial distribution: the scene must have its particles and observe from
        /// that time on (--set observe.t_start=T --set observe.t_end=LATER); ensemble k
        /// continues from record k with a stream no earlier segment used.
        #[arg(long, value_name = "FILE")]
        initial_state: Option<PathBuf>,
    },
    /// Run a parameter study: the scene at every value of one or more keys, one table.
    ///
    /// Every point is validated before anything runs (a bad point is named), then the points
    /// run one after another on all cores, each journaled beside DIR (default out/NAME-sweep),
    /// so Ctrl-C keeps what is done and the same command continues. DIR gets sweep.csv (one
    /// row per point: the varied values, seed, ensembles, the window, each observable's
    /// mean and 99.9% half-width over the steady window, or at the last observation without
    /// one, and each reference that applies, averaged over the same times) and sweep.json.
    /// Point k runs with seed run.seed + k: it is `gdsmc run SCENE --set KEY=VALUE ...
    /// --seed SEED+k` to the last bit.
    ///
    /// Examples:
    ///   gdsmc sweep scenes/hcs-hard-spheres.toml --vary collisions.restitution=0.3:0.9:7
    ///   gdsmc sweep scenes/grw-example3.toml --vary drive.beta=log:0.1:10:5 --ensembles 50
    ///   gdsmc sweep SCENE --vary collisions.restitution=0.5,0.9 --vary particles.n=64,256
    ///   gdsmc sweep SCENE --vary a.b=1,2,3 --vary c.d=x,y,z --zip
    #[command(verbatim_doc_comment)]
    Sweep {
        /// The base scene file (TOML).
        scene: PathBuf,
        /// KEY=VALUES: a list (0.5,0.7,0.9; any scene value, a bare word is a string), a
        /// range start:stop:count (both ends included) or log:start:stop:count. Repeatable:
        /// several make a grid (the last key varies fastest), or pairs with --zip.
        /// Without --vary, the scene's [sweep] table says what varies.
        #[arg(long, value_name = "KEY=VALUES")]
        vary: Vec<String>,
        /// Pair the k-th values of every --vary instead of making a grid.
        #[arg(long)]
        zip: bool,
        #[command(flatten)]
        flags: SceneFlags,
        /// Output directory (default: out/SCENE-NAME-sweep), replaced only when it is empty or
        /// a whole gdsmc output set.
        #[arg(long)]
        out: Option<PathBuf>,
        /// Start every point anew instead of continuing the journals a stopped sweep left.
        #[arg(long)]
        fresh: bool,
        /// Chart formats, comma-separated: svg, png, pdf.
        #[arg(long, value_name = "svg,png,pdf", default_value = "svg")]
        format: gdsmc_runner::report::charts::Formats,
        /// Run only shard K of S (K from 0): the points k with k mod S = K, journaled beside
        /// DIR where the whole sweep looks for them (a Slurm array task each); with more
        /// shards than points, each point's ensembles split into ceil(S/P) shards too (as
        /// `gdsmc run --shard` splits a run). The same command without --shard then writes
        /// the sweep from the journals, running nothing again.
        #[arg(long, value_name = "K/S")]
        shard: Option<String>,
    },
    /// Merge shards into the outputs of the whole run (byte-identical to `gdsmc run`).
    ///
    /// Takes shard files or directories holding them (every *.gdsmc-ensembles file), checks
    /// that they are one run (same scene, seed, ensembles, shard count and gdsmc version),
    /// complete and undamaged, each shard once, and writes what `gdsmc run` writes. The scene
    /// comes from the shards themselves.
    ///
    /// Examples:
    ///   for k in 0 1 2 3; do gdsmc run scenes/grw-example3.toml --shard $k/4; done
    ///   gdsmc merge out/grw-example3-shards
    #[command(verbatim_doc_comment)]
    Merge {
        /// Shard files, or directories of them.
        #[arg(required = true)]
        inputs: Vec<PathBuf>,
        /// Output directory (default: out/SCENE-NAME): as for `run`, and never one holding
        /// the shards.
        #[arg(long)]
        out: Option<PathBuf>,
        /// Chart formats, comma-separated: svg, png, pdf.
        #[arg(long, value_name = "svg,png,pdf", default_value = "svg")]
        format: gdsmc_runner::report::charts::Formats,
    },
    /// Reproduce the tables of the four papers: our figures beside the published ones.
    ///
    /// Tables: grw-table1, grw-table2 (GRW Tables 1-2), rw-table1 ... rw-table6 (RW Tables
    /// 1-6), brs-table1, brs-table2, brs-equilibria (BRS Tables 1-2, Examples 4-5), ms-table1
    /// (MS Table 1). Each figure is printed with our 99.9% half-width, the exact expected value
    /// of the paper's estimator where known, the ranges the paper's figure and ours must lie
    /// in, and a verdict: agree (each check would catch a 10% error), weak (one would not; the
    /// error it catches is printed), disagree (paper) when the published figure misses an exact
    /// value, DISAGREE, disputed (by a consistency check run alongside), uninformative (the
    /// check could not have failed), shown. DIR/report.md (rewritten after every table, so an
    /// interrupted run keeps the finished ones) says what each range is made of. Exits with 1
    /// when a figure of ours misses an exact value, or the paper's where nothing is exact,
    /// beyond the report-wide range (Bonferroni over every check).
    ///
    /// --quick runs every table at reduced size (the costliest rows are skipped and listed);
    /// without it, the papers' sizes. Their durations on a 2-core machine: docs/timings.md and
    /// docs/reproduce-full.md.
    ///
    /// Examples:
    ///   gdsmc reproduce --quick
    ///   gdsmc reproduce rw-table2 rw-table4
    #[command(verbatim_doc_comment)]
    Reproduce {
        /// Tables to run (default: all).
        names: Vec<String>,
        /// Reduced sizes (for CI).
        #[arg(long)]
        quick: bool,
        /// Worker threads (default: all cores). Results are identical for any value.
        #[arg(long, default_value_t = 0, hide_default_value = true)]
        threads: usize,
        /// Base seed (row k of table j uses seed + 1000 j + k).
        #[arg(long, default_value_t = 1)]
        seed: u64,
        /// Output directory for report.md (default: out/reproduce).
        #[arg(long)]
        out: Option<PathBuf>,
    },
    /// Measure speed: the hot loops, work against precision, thread scaling.
    #[command(subcommand)]
    Bench(Bench),
}

#[derive(Subcommand)]
enum Bench {
    /// Throughput of the hot loops beside the machine's limits.
    ///
    /// The no-splitting loop (n = 10^3 ... 10^7, three kernels, heated alpha = 0.5, elastic
    /// alpha = 1, a host medium), the batch kick and moment kernels, and the machine's
    /// limits (random numbers per second, independent random reads per second).
    ///
    /// Every rate is per CPU second of the measuring thread (the first line says
    /// clock=thread-cpu-time); --seconds is CPU time. One line per case:
    ///   case=<name> kernel=<maxwell|hard-spheres|vhs> n=<n> collisions_per_s=<x> attempts_per_s=<y> acceptance=<a> of_pair_reference=<f> of_rng=<g> spread=<s> [background_per_s=<b>] [choice_reads_per_candidate=<r> choice_reads_per_collision=<q>]
    ///   case=<name> n=<n> particles_per_s=<x> spread=<s>
    /// of_pair_reference: candidates per second over case=reference-pair-update's pairs per
    /// second (a reference rate, not a bound), timed again before each round of the loop.
    /// Every figure is the median of five rounds; spread: their range over the median.
    #[command(verbatim_doc_comment)]
    Throughput {
        /// Particle numbers of the event-loop cases (comma-separated).
        #[arg(long, value_delimiter = ',', default_values_t = [1_000usize, 100_000, 1_000_000, 10_000_000])]
        sizes: Vec<usize>,
        /// Measuring time per case, CPU seconds of the measuring thread.
        #[arg(long, default_value_t = 1.5)]
        seconds: f64,
    },
    /// Error against CPU time of no splitting, Strang and Euler splitting (RW Section 4.2).
    ///
    /// Runs each scheme over a ladder of n and time steps on a steady Maxwell-gas scene such as
    /// scenes/rw-steady.toml. Writes work_precision.csv and work_precision.svg and prints the
    /// CPU cost of a 1% error per scheme and its ratio to no splitting (RW: Euler about 100).
    WorkPrecision {
        /// The scene (a Maxwell gas with white noise and observe.steady_from).
        scene: PathBuf,
        /// Independent runs per configuration (each one ensemble, as RW).
        #[arg(long, default_value_t = 8)]
        runs: u64,
        /// A small ladder (n <= 4096) for a quick look.
        #[arg(long)]
        quick: bool,
        /// The relative error at which the costs are compared (default: RW's 0.01; with
        /// --quick, the smallest error every scheme of the small ladder reaches).
        #[arg(long)]
        target: Option<f64>,
        /// Worker threads (default: all cores).
        #[arg(long, default_value_t = 0, hide_default_value = true)]
        threads: usize,
        /// Output directory (default: out/work-precision).
        #[arg(long)]
        out: Option<PathBuf>,
    },
    /// The same run on 1 thread and on all cores: the speed-up and a bit-identity check.
    Scaling {
        /// The scene.
        scene: PathBuf,
        /// Threads of the parallel run (default: all cores).
        #[arg(long, default_value_t = 0, hide_default_value = true)]
        threads: usize,
    },
}

fn main() -> ExitCode {
    let cli = Cli::parse();
    match run(cli) {
        Ok(()) => ExitCode::SUCCESS,
        Err(gdsmc_runner::Error::Interrupted) => {
            ExitCode::from(gdsmc_runner::terminal::exit_code())
        }
        Err(e) => {
            eprintln!("error: {e}");
            ExitCode::FAILURE
        }
    }
}

fn run(cli: Cli) -> Result<(), gdsmc_runner::Error> {
    match cli.command {
        Command::Run {
            scene: path,
            flags,
            out,
            format,
            shard,
            fresh,
            save_state,
            initial_state,
        } => {
            let job = gdsmc_runner::job::Job {
                source: flags.source(&path)?,
                threads: flags.threads,
                allow_long: flags.allow_long,
                shard,
                out,
                fresh,
                format,
                initial_state,
                save_state,
            };
            let outcome = job.run(&gdsmc_runner::terminal::Terminal::install())?;
            print!("{}", outcome.text);
            if outcome.complete {
                Ok(())
            } else {
                Err(gdsmc_runner::Error::Interrupted)
            }
        }
        Command::Sweep {
            scene: path,
            vary,
            zip,
            flags,
            out,
            fresh,
            format,
            shard,
        } => {
            use gdsmc_runner::sweep;
            let source = flags.source(&path)?;
            let plan = sweep::plan(&source, &vary, zip)?;
            let s = sweep::Sweep {
                source,
                vary: plan.vary,
                combine: plan.combine,
                threads: flags.threads,
                allow_long: flags.allow_long,
                out,
                fresh,
                format,
                shard,
            };
            let outcome = s.run(&gdsmc_runner::terminal::Terminal::install())?;
            print!("{}", outcome.text);
            if outcome.complete {
                Ok(())
            } else {
                Err(gdsmc_runner::Error::Interrupted)
            }
        }
        Command::Merge {
            inputs,
            out,
            format,
        } => {
            print!("{}", gdsmc_runner::job::merge(&inputs, out, format)?);
            Ok(())
        }
        Command::Reproduce {
            names,
            quick,
            threads,
            seed,
            out,
        } => gdsmc_runner::reproduce::command(
            &names,
            &gdsmc_runner::reproduce::Options {
                quick,
                threads,
                seed,
            },
            out,
        ),
        Command::Bench(b) => bench(b),
    }
}

/// The flags `run` and `sweep` share: the scene's overrides, the threads, the work limit.
#[derive(clap::Args, Debug)]
struct SceneFlags {
    /// Particles per ensemble (overrides particles.n).
    #[arg(long)]
    n: Option<i64>,
    /// Number of independent ensembles (overrides run.ensembles; a sweep's, per point).
    #[arg(long)]
    ensembles: Option<i64>,
    /// Seed (overrides run.seed); ensemble k uses its generator jumped k times, a sweep's
    /// point k the seed SEED + k.
    #[arg(long)]
    seed: Option<u64>,
    /// Worker threads (default: all cores). Results are identical for any value.
    #[arg(long, default_value_t = 0, hide_default_value = true)]
    threads: usize,
    /// Override any scene value, e.g. --set collisions.restitution=0.4 (repeatable; the
    /// value is TOML, a bare word is a string). Validated like the file; a key given twice
    /// (here, by --n, --ensembles, --seed, or by a sweep's --vary) is refused.
    #[arg(long = "set", value_name = "KEY.PATH=VALUE")]
    set: Vec<String>,
    /// Run even when the work estimate is above the limit (1e12 events and particle
    /// updates, about a day of one core; a sweep's summed over its points).
    #[arg(long)]
    allow_long: bool,
}

impl SceneFlags {
    /// The scene read once with the overrides: --set, then --n, --ensembles and --seed as
    /// overrides of their keys (the same validation as the file's, errors naming the flag).
    fn source(&self, path: &std::path::Path) -> Result<scene::Sourced, gdsmc_runner::Error> {
        let mut overrides: Vec<scene::Override> =
            self.set.iter().map(scene::Override::set).collect();
        overrides.extend(scene::Override::run_flags(
            self.n,
            self.ensembles,
            self.seed,
        ));
        Ok(scene::Sourced::read(path, overrides)?)
    }
}

fn bench(b: Bench) -> Result<(), gdsmc_runner::Error> {
    use gdsmc_runner::bench;
    match b {
        Bench::Throughput { sizes, seconds } => {
            let o = bench::throughput::Options {
                sizes,
                budget: std::time::Duration::from_secs_f64(seconds.max(0.01)),
            };
            bench::throughput::run(&o, |l| println!("{l}"));
            Ok(())
        }
        Bench::WorkPrecision {
            scene: path,
            runs,
            quick,
            target,
            threads,
            out,
        } => bench::work_precision(
            &scene::load(&path)?,
            &bench::WorkPrecision {
                runs,
                quick,
                target,
                threads,
                out,
            },
        ),
        Bench::Scaling {
            scene: path,
            threads,
        } => {
            let sc = scene::load(&path)?;
            let k = if threads == 0 {
                std::thread::available_parallelism().map_or(1, |n| n.get())
            } else {
                threads
            };
            println!("{}", bench::scaling::measure(&sc, k)?);
            Ok(())
        }
    }
}
