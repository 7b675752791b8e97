//! gdsmc on a Cortex-M. Runs GRW Example 3 (heated Maxwell gas), the homogeneous cooling of
//! hard spheres and of rough hard spheres (`gdsmc_demo::all`) on a static buffer of 512
//! particles (the rough run on 256 of them, with 256 static spins), prints every
//! observation over semihosting with round-trip digits, then the figures `embedded/run.sh`
//! tabulates: instructions per collision (SysTick under QEMU's `-icount shift=0`, where one
//! instruction is one nanosecond of virtual time and the MPS2 SysTick counts 25 MHz, so one
//! tick is 40 instructions), peak stack (a painted stack) and the static RAM of the particles
//! and spins.
//! Exits through semihosting with status 0, or 1 when a run fails.

#![no_std]
#![no_main]

use core::fmt::Write;
use core::sync::atomic::{AtomicU32, Ordering};
use cortex_m::peripheral::syst::SystClkSource;
use cortex_m_rt::{entry, exception};
use cortex_m_semihosting::{debug, hio};
use gdsmc_core::particles::{Particle, Spin};
use gdsmc_core::vec3::Vec3;
use gdsmc_demo::{N, N_ROUGH};
use panic_semihosting as _;

/// The particles: caller-owned static memory, as the core expects (no allocator here).
static mut PARTICLES: [Particle; N] = [Particle::new(Vec3::ZERO, 0.0); N];

/// The rough run's spins: caller-owned static memory too.
static mut SPINS: [Spin; N_ROUGH] = [Spin::new(Vec3::ZERO); N_ROUGH];

/// SysTick wraps (each 2^24 ticks).
static WRAPS: AtomicU32 = AtomicU32::new(0);
/// SysTick reload: the full 24 bits.
const RELOAD: u32 = 0x00ff_ffff;
/// Instructions per SysTick tick under `-icount shift=0` (1 ns each) at the MPS2's 25 MHz.
const INSTRUCTIONS_PER_TICK: u64 = 40;
/// The byte painted below the stack pointer to find the peak stack afterwards.
const PAINT: u32 = 0xdead_beef;

unsafe extern "C" {
    /// End of .bss/.data: the lowest address the stack may reach (cortex-m-rt's symbol).
    static __sheap: u32;
}

#[exception]
fn SysTick() {
    WRAPS.fetch_add(1, Ordering::Relaxed);
}

/// Ticks since SysTick started (wraps counted by the exception).
fn ticks() -> u64 {
    loop {
        let w = WRAPS.load(Ordering::Relaxed);
        let v = cortex_m::peripheral::SYST::get_current();
        if WRAPS.load(Ordering::Relaxed) == w {
            return w as u64 * (RELOAD as u64 + 1) + (RELOAD - v) as u64;
        }
    }
}

/// Semihosting stdout as a `core::fmt::Write`.
struct Out(hio::HostStream);

impl Write for Out {
    fn write_str(&mut self, s: &str) -> core::fmt::Result {
        self.0.write_all(s.as_bytes()).map_err(|_| core::fmt::Error)
    }
}

/// Fills the free RAM between the statics and the current stack with `PAINT`; returns its
/// bounds.
fn paint_stack() -> (usize, usize) {
    let bottom = core::ptr::addr_of!(__sheap) as usize;
    let top = cortex_m::register::msp::read() as usize - 256;
    let mut a = bottom;
    while a < top {
        // SAFETY: [bottom, top) lies between the end of the statics and 256 bytes below the
        // current stack pointer: memory nothing uses yet; aligned words.
        unsafe { core::ptr::write_volatile(a as *mut u32, PAINT) };
        a += 4;
    }
    (bottom, top)
}

/// The lowest painted word the stack overwrote.
fn stack_low_water(bottom: usize, top: usize) -> usize {
    let mut a = bottom;
    // SAFETY: reads of the painted region, aligned words.
    while a < top && unsafe { core::ptr::read_volatile(a as *const u32) } == PAINT {
        a += 4;
    }
    a
}

#[entry]
fn main() -> ! {
    let stack_top = 0x2000_0000usize + 4 * 1024 * 1024;
    let (bottom, top) = paint_stack();
    let mut cp = cortex_m::Peripherals::take().expect("first take");
    cp.SYST.set_clock_source(SystClkSource::Core);
    cp.SYST.set_reload(RELOAD);
    cp.SYST.clear_current();
    cp.SYST.enable_interrupt();
    cp.SYST.enable_counter();
    let mut out = Out(hio::hstdout().expect("semihosting stdout"));
    // SAFETY: the only references to PARTICLES and SPINS, taken once here.
    let (buf, spins) = unsafe {
        (
            &mut *core::ptr::addr_of_mut!(PARTICLES),
            &mut *core::ptr::addr_of_mut!(SPINS),
        )
    };
    let status = match gdsmc_demo::all(buf, spins, 1, &mut out, ticks) {
        Ok(summaries) => {
            for (name, s) in ["grw3", "hcs", "rough"].iter().zip(summaries) {
                let instr = s.instructions * INSTRUCTIONS_PER_TICK;
                let _ = writeln!(
                    out,
                    "figure {name} collisions={} candidates={} instructions={instr} per_collision={} per_candidate={}",
                    s.counts.collisions,
                    s.counts.candidates,
                    instr / s.counts.collisions.max(1),
                    instr / s.counts.candidates.max(1),
                );
            }
            let low = stack_low_water(bottom, top);
            let _ = writeln!(
                out,
                "figure stack_peak_bytes={} particles_bytes={} particles_per_kib={}",
                stack_top - low,
                core::mem::size_of::<[Particle; N]>() + core::mem::size_of::<[Spin; N_ROUGH]>(),
                1024 / core::mem::size_of::<Particle>()
            );
            debug::EXIT_SUCCESS
        }
        Err(e) => {
            let _ = writeln!(out, "error: {e:?}");
            debug::EXIT_FAILURE
        }
    };
    debug::exit(status);
    loop {
        cortex_m::asm::wfi();
    }
}
