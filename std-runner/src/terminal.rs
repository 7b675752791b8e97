//! The command's view of a run on a terminal (feature `cli`): its progress bar and Ctrl-C.

/// The terminal's view of a run: a progress bar on standard error (when it is a terminal)
/// and Ctrl-C: the first lets the running ensembles finish and keeps what is done, a second
/// ends the process at once.
pub struct Terminal {
    bar: indicatif::ProgressBar,
    stop: std::sync::Arc<std::sync::atomic::AtomicBool>,
}

impl Terminal {
    /// A hidden bar (drawn from [`crate::job::Watch::begin`] when standard error is a
    /// terminal) and the Ctrl-C handler, set once for the process.
    #[must_use]
    pub fn install() -> Self {
        let stop = std::sync::Arc::new(std::sync::atomic::AtomicBool::new(false));
        {
            let stop = stop.clone();
            let _ = ctrlc::set_handler(move || {
                if stop.swap(true, std::sync::atomic::Ordering::SeqCst) {
                    std::process::exit(130);
                }
                eprintln!(
                    "\ninterrupted: finishing the running ensembles and keeping what is done (Ctrl-C again to quit)"
                );
            });
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
