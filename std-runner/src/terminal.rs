//! The command's view of a run on a terminal (feature `cli`): its progress bar and the signals
//! that stop it.
//!
//! Ctrl-C (SIGINT), and on Unix a scheduler's SIGTERM (Slurm's time limit, `timeout`,
//! systemd) and SIGHUP (the terminal closed), all stop a run the same way: the running
//! ensembles finish, the rest are skipped, what is done is written as a partial set and the
//! journal is left for the same command to continue. The process then exits with 128 plus
//! the signal's number (130 for SIGINT, 143 for SIGTERM, 129 for SIGHUP: [`exit_code`]), as a
//! shell reports a process the signal ended. A second signal ends the process at once with
//! that code.

use std::sync::atomic::{AtomicI32, Ordering};

/// The first stopping signal received (0: none).
static SIGNAL: AtomicI32 = AtomicI32::new(0);

/// The exit code of a run stopped by a signal: 128 plus the first stopping signal's number
/// (130 when none was recorded: an interruption is Ctrl-C's by default).
#[must_use]
pub fn exit_code() -> u8 {
    match SIGNAL.load(Ordering::SeqCst) {
        s @ 1..=127 => 128 + s as u8,
        _ => 130,
    }
}

/// The terminal's view of a run: a progress bar on standard error (when it is a terminal)
/// and the stopping signals (module docs): the first lets the running ensembles finish and
/// keeps what is done, a second ends the process at once.
pub struct Terminal {
    bar: indicatif::ProgressBar,
    stop: std::sync::Arc<std::sync::atomic::AtomicBool>,
}

/// What the first stopping signal `sig` does: records it and asks the run to stop, with a
/// line saying so; a second signal ends the process at once.
fn on_signal(stop: &std::sync::atomic::AtomicBool, sig: i32, name: &str) {
    let _ = SIGNAL.compare_exchange(0, sig, Ordering::SeqCst, Ordering::SeqCst);
    if stop.swap(true, Ordering::SeqCst) {
        std::process::exit(i32::from(exit_code()));
    }
    eprintln!(
        "\n{name}: finishing the running ensembles and keeping what is done (a second signal, \
         e.g. Ctrl-C, quits at once)"
    );
}

impl Terminal {
    /// A hidden bar (drawn from [`crate::job::Watch::begin`] when standard error is a
    /// terminal) and the signal handlers, set once for the process.
    #[must_use]
    pub fn install() -> Self {
        let stop = std::sync::Arc::new(std::sync::atomic::AtomicBool::new(false));
        #[cfg(unix)]
        {
            use signal_hook::consts::{SIGHUP, SIGINT, SIGTERM};
            let stop = stop.clone();
            // A thread of its own receives the signals (signal-hook's self-pipe): the handler
            // proper only writes to the pipe.
            if let Ok(mut signals) = signal_hook::iterator::Signals::new([SIGINT, SIGTERM, SIGHUP])
            {
                std::thread::spawn(move || {
                    for sig in signals.forever() {
                        let name = match sig {
                            SIGTERM => "terminated (SIGTERM)",
                            SIGHUP => "hung up (SIGHUP)",
                            _ => "interrupted",
                        };
                        on_signal(&stop, sig, name);
                    }
                });
            }
        }
        #[cfg(not(unix))]
        {
            let stop = stop.clone();
            let _ = ctrlc::set_handler(move || on_signal(&stop, 2, "interrupted"));
        }
        let bar = indicatif::ProgressBar::hidden();
        bar.set_style(
            indicatif::ProgressStyle::with_template(
                "{spinner} [{elapsed_precise}] {wide_bar} {pos}/{len} ensembles, {per_sec}, ETA {eta}",
            )
            .expect("template"),
        );
        Terminal { bar, stop }
    }
}

impl crate::job::Watch for Terminal {
    fn begin(&self, total: u64) {
        self.bar.set_length(total);
        if std::io::IsTerminal::is_terminal(&std::io::stderr()) {
            self.bar
                .set_draw_target(indicatif::ProgressDrawTarget::stderr());
        }
    }
    fn advance(&self, k: u64) {
        self.bar.inc(k);
    }
    fn end(&self) {
        self.bar.finish_and_clear();
    }
    fn stop(&self) -> &std::sync::atomic::AtomicBool {
        &self.stop
    }
    fn note(&self, line: &str) {
        eprintln!("{line}");
    }
}
