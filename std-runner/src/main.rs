//! The `gdsmc` command.

use clap::{Parser, Subcommand};
use gdsmc::{ensemble, output, references, scene, summary};
use std::path::PathBuf;
use std::process::ExitCode;

/// gdsmc: direct simulation Monte Carlo for the spatially homogeneous inelastic (granular)
/// Boltzmann equation, with ensemble statistics and exact references.
///
/// A run is described by a scene file (TOML; every key is documented in docs/scenes.md and
/// the shipped scenes in scenes/ reproduce the examples of the four papers: GRW, RW, BRS, MS).
/// Every number is an ensemble mean with the half-width of its 99.9% confidence interval
/// (3.2 sqrt(Var/M)); exact or hydrodynamic references are printed beside it where known.
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
    /// asks for it, and SVG charts. Files are replaced atomically. Ctrl-C finishes the running
    /// ensembles and writes the results of those completed (exit code 130).
    ///
    /// Examples:
    ///   gdsmc run scenes/brs-example5.toml
    ///   gdsmc run scenes/ms-gaussian.toml --set collisions.restitution=0.4
    ///   gdsmc run scenes/rw-steady.toml --set scheme.kind=strang --set scheme.dt=0.25
    #[command(verbatim_doc_comment)]
    Run {
        /// The scene file (TOML), e.g. scenes/grw-example3.toml.
        scene: PathBuf,
        /// Particles per ensemble (overrides particles.n).
        #[arg(long)]
        n: Option<i64>,
        /// Number of independent ensembles (overrides run.ensembles).
        #[arg(long)]
        ensembles: Option<i64>,
        /// Seed of the run (overrides run.seed); ensemble k uses its generator jumped k times.
        #[arg(long)]
        seed: Option<u64>,
        /// Worker threads (default: all cores). Results are identical for any value.
        #[arg(long, default_value_t = 0)]
        threads: usize,
        /// Output directory (default: out/SCENE-NAME).
        #[arg(long)]
        out: Option<PathBuf>,
        /// Override any scene value, e.g. --set collisions.restitution=0.4 (repeatable; the
        /// value is TOML, a bare word is a string). Validated like the file.
        #[arg(long = "set", value_name = "KEY.PATH=VALUE")]
        set: Vec<String>,
    },
    /// Reproduce the tables of the four papers: our figures beside the published ones.
    ///
    /// Tables: grw-table1, grw-table2 (GRW Tables 1-2), rw-table1 ... rw-table6 (RW Tables
    /// 1-6), brs-table1, brs-table2, brs-equilibria (BRS Tables 1-2, Examples 4-5), ms-table1
    /// (MS Table 1). Each figure is printed with our 99.9% half-width, the exact expected value
    /// of the paper's estimator where known, the tolerance and whether it agrees. Writes
    /// DIR/report.md after every table (so an interrupted run keeps the finished ones) and
    /// exits with 1 when a figure disagrees.
    ///
    /// --quick runs every table at reduced size (about 5 minutes on 2 cores; the costliest
    /// rows are skipped and listed); without it, the papers' sizes (see README for the time).
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
        #[arg(long, default_value_t = 0)]
        threads: usize,
        /// Base seed (row k of table j uses seed + 1000 j + k).
        #[arg(long, default_value_t = 1)]
        seed: u64,
        /// Output directory for report.md (default: out/reproduce).
        #[arg(long)]
        out: Option<PathBuf>,
    },
}

fn main() -> ExitCode {
    let cli = Cli::parse();
    match run(cli) {
        Ok(()) => ExitCode::SUCCESS,
        Err(gdsmc::Error::Interrupted) => ExitCode::from(130),
        Err(e) => {
            eprintln!("error: {e}");
            ExitCode::FAILURE
        }
    }
}

fn run(cli: Cli) -> Result<(), gdsmc::Error> {
    match cli.command {
        Command::Run {
            scene: path,
            n,
            ensembles,
            seed,
            threads,
            out,
            set,
        } => {
            let mut sc = scene::load_with_overrides(&path, &set)?;
            let flag = |key: &str, message: String| gdsmc::Error::Invalid {
                path: PathBuf::from(format!("--{key}")),
                line: 0,
                key: key.to_string(),
                message,
            };
            if let Some(n) = n {
                if n < 2 {
                    return Err(flag(
                        "n",
                        format!("must be >= 2 (a pair is needed to collide), got {n}"),
                    ));
                }
                sc.n = n as usize;
            }
            if let Some(m) = ensembles {
                if m < 1 {
                    return Err(flag("ensembles", format!("must be >= 1, got {m}")));
                }
                sc.ensembles = m as u64;
            }
            if let Some(s) = seed {
                sc.seed = s;
            }
            let stop = std::sync::Arc::new(std::sync::atomic::AtomicBool::new(false));
            {
                let stop = stop.clone();
                // A second Ctrl-C ends the process at once.
                let _ = ctrlc::set_handler(move || {
                    if stop.swap(true, std::sync::atomic::Ordering::SeqCst) {
                        std::process::exit(130);
                    }
                    eprintln!(
                        "\ninterrupted: finishing the running ensembles and keeping what is done (Ctrl-C again to quit)"
                    );
                });
            }
            let bar = indicatif::ProgressBar::with_draw_target(
                Some(sc.ensembles),
                indicatif::ProgressDrawTarget::stderr(),
            );
            bar.set_style(
                indicatif::ProgressStyle::with_template(
                    "{spinner} [{elapsed_precise}] {wide_bar} {pos}/{len} ensembles, {per_sec}, ETA {eta}",
                )
                .expect("template"),
            );
            if !std::io::IsTerminal::is_terminal(&std::io::stderr()) {
                bar.set_draw_target(indicatif::ProgressDrawTarget::hidden());
            }
            let stats = ensemble::run_interruptible(&sc, threads, &|k| bar.inc(k), &stop)?;
            bar.finish_and_clear();
            let interrupted = stats.ensembles < sc.ensembles;
            if interrupted {
                eprintln!("kept {} of {} ensembles", stats.ensembles, sc.ensembles);
                if stats.ensembles == 0 {
                    return Err(gdsmc::Error::Interrupted);
                }
            }
            let refs = references::for_scene(&sc);
            let dir = out.unwrap_or_else(|| PathBuf::from("out").join(&sc.name));
            output::write_all(&dir, &sc, &stats, &refs)?;
            print!("{}", summary::text(&sc, &stats, &refs));
            println!("\nwrote {}", dir.join("observables.csv").display());
            if interrupted {
                return Err(gdsmc::Error::Interrupted);
            }
            Ok(())
        }
        Command::Reproduce {
            names,
            quick,
            threads,
            seed,
            out,
        } => reproduce(&names, quick, threads, seed, out),
    }
}

fn reproduce(
    names: &[String],
    quick: bool,
    threads: usize,
    seed: u64,
    out: Option<PathBuf>,
) -> Result<(), gdsmc::Error> {
    use gdsmc::reproduce;
    let opts = reproduce::Options {
        quick,
        threads,
        seed,
    };
    let dir = out.unwrap_or_else(|| PathBuf::from("out").join("reproduce"));
    std::fs::create_dir_all(&dir).map_err(|e| gdsmc::Error::Write {
        path: dir.clone(),
        source: e,
    })?;
    let report = dir.join("report.md");
    let start = std::time::Instant::now();
    let mut done = Vec::new();
    let mut write_err = None;
    let tables = reproduce::run(names, &opts, |t| {
        print!("{}", reproduce::text(t));
        done.push(t.clone());
        let md = reproduce::markdown(&done, &opts, start.elapsed().as_secs_f64());
        if let Err(e) = output::write_atomic(&report, md.as_bytes()) {
            write_err.get_or_insert(e);
        }
    })?;
    if let Some(e) = write_err {
        return Err(e);
    }
    let bad: Vec<String> = tables
        .iter()
        .flat_map(|t| {
            t.disagreements()
                .into_iter()
                .map(move |d| format!("{}: {d}", t.name))
        })
        .collect();
    println!(
        "\n{} tables in {:.0} s; wrote {}",
        tables.len(),
        start.elapsed().as_secs_f64(),
        report.display()
    );
    if bad.is_empty() {
        println!("every judged figure agrees with the paper");
        Ok(())
    } else {
        Err(gdsmc::Error::Disagrees(bad))
    }
}
