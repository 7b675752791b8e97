//! The clocks a run reads: its wall time and its process's CPU time. WebAssembly in a browser
//! (`wasm32-unknown-unknown`) has neither (the standard library's `Instant::now` panics there):
//! a run's timing reads zero, and the page times its runs on its own side.

/// Whether this build has clocks (every target but WebAssembly without an operating system).
pub const HAS_CLOCKS: bool = !cfg!(target_family = "wasm");

/// The wall and CPU time since it was started, where the platform has them.
#[derive(Clone, Copy, Debug)]
pub struct Stopwatch {
    #[cfg(not(target_family = "wasm"))]
    wall: std::time::Instant,
    #[cfg(not(target_family = "wasm"))]
    cpu: Option<cpu_time::ProcessTime>,
}

impl Stopwatch {
    /// Starts both clocks.
    #[must_use]
    pub fn start() -> Self {
        Stopwatch {
            #[cfg(not(target_family = "wasm"))]
            wall: std::time::Instant::now(),
            #[cfg(not(target_family = "wasm"))]
            cpu: cpu_time::ProcessTime::try_now().ok(),
        }
    }

    /// Seconds of wall time since the start (0 without a clock).
    #[must_use]
    pub fn wall(&self) -> f64 {
        #[cfg(not(target_family = "wasm"))]
        return self.wall.elapsed().as_secs_f64();
        #[cfg(target_family = "wasm")]
        0.0
    }

    /// Seconds of the process's CPU time since the start (0 without a clock).
    #[must_use]
    pub fn cpu(&self) -> f64 {
        #[cfg(not(target_family = "wasm"))]
        return self.cpu.map_or(0.0, |c| c.elapsed().as_secs_f64());
        #[cfg(target_family = "wasm")]
        0.0
    }
}
