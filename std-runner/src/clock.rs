//! The clocks a run reads: its wall time and its process's CPU time. A browser has no CPU
//! clock (the page runs on `wasm32-wasip1`, whose wall clock is the page's `performance.now`
//! through its WASI shim), and `wasm32-unknown-unknown` has neither (the standard library's
//! `Instant::now` panics there). Where the CPU clock is missing, the wall time stands for it:
//! those builds run every ensemble on the one thread that reads the clock.

/// The wall and CPU time since it was started, where the platform has them.
#[derive(Clone, Copy, Debug)]
pub struct Stopwatch {
    #[cfg(not(all(target_family = "wasm", target_os = "unknown")))]
    wall: std::time::Instant,
    #[cfg(not(target_family = "wasm"))]
    cpu: Option<cpu_time::ProcessTime>,
}

impl Stopwatch {
    /// Starts both clocks.
    #[must_use]
    pub fn start() -> Self {
        Stopwatch {
            #[cfg(not(all(target_family = "wasm", target_os = "unknown")))]
            wall: std::time::Instant::now(),
            #[cfg(not(target_family = "wasm"))]
            cpu: cpu_time::ProcessTime::try_now().ok(),
        }
    }

    /// Seconds of wall time since the start (0 without a wall clock).
    #[must_use]
    pub fn wall(&self) -> f64 {
        #[cfg(not(all(target_family = "wasm", target_os = "unknown")))]
        return self.wall.elapsed().as_secs_f64();
        #[cfg(all(target_family = "wasm", target_os = "unknown"))]
        0.0
    }

    /// Seconds of the process's CPU time since the start, or of wall time where the platform
    /// has no CPU clock (module docs).
    #[must_use]
    pub fn cpu(&self) -> f64 {
        #[cfg(not(target_family = "wasm"))]
        return self.cpu.map_or(0.0, |c| c.elapsed().as_secs_f64());
        #[cfg(target_family = "wasm")]
        self.wall()
    }
}
