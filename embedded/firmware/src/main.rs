//! gdsmc on a Cortex-M. On the MPS2 boards (feature `full`, the default) runs GRW Example 3
//! (heated Maxwell gas), the homogeneous cooling of hard spheres and of rough hard spheres, and
//! a binary mixture of rough hard disks heated by white noise (`gdsmc_demo::all`) on a static
//! buffer of 512 particles (the rough runs on 256 of them, with 256 static spins); on the
//! micro:bit (Cortex-M0, without `full`: the core holds only the Maxwell kernel and white
//! noise) GRW Example 3 alone on 64 particles (`gdsmc_demo::grw3`).
//! Prints every observation over semihosting with round-trip digits, then the figures
//! `embedded/run.sh` tabulates: instructions per collision (SysTick under QEMU's `-icount
//! shift=0`, where one instruction is one nanosecond of virtual time: the MPS2 SysTick counts
//! 25 MHz, one tick is 40 instructions; the nRF51's counts 16 MHz, 62.5), peak stack (a painted
//! stack; a stack that reached the statics fails the run) and the static RAM of the particles
//! and spins.
//! Exits through semihosting with status 0, or 1 when a run fails.

#![no_std]
#![no_main]

use core::fmt::Write;
use core::sync::atomic::{AtomicU32, Ordering};
use cortex_m::peripheral::syst::SystClkSource;
use cortex_m_rt::{entry, exception};
use cortex_m_semihosting::{debug, hio};
use gdsmc_core::particles::Particle;
#[cfg(feature = "full")]
use gdsmc_core::particles::Spin;
use gdsmc_core::vec3::Vec3;
use panic_semihosting as _;

/// Particles per system: the demo's on the MPS2 boards, [`gdsmc_demo::N_M0`] on the micro:bit.
#[cfg(feature = "full")]
const N: usize = gdsmc_demo::N;
#[cfg(not(feature = "full"))]
const N: usize = gdsmc_demo::N_M0;

/// The particles: caller-owned static memory, as the core expects (no allocator here).
static mut PARTICLES: [Particle; N] = [Particle::new(Vec3::ZERO, 0.0); N];

/// The rough runs' spins: caller-owned static memory too.
#[cfg(feature = "full")]
static mut SPINS: [Spin; gdsmc_demo::N_ROUGH] = [Spin::new(Vec3::ZERO); gdsmc_demo::N_ROUGH];

/// Bytes of the static particles and spins.
#[cfg(feature = "full")]
const PARTICLE_BYTES: usize =
    core::mem::size_of::<[Particle; N]>() + core::mem::size_of::<[Spin; gdsmc_demo::N_ROUGH]>();
#[cfg(not(feature = "full"))]
const PARTICLE_BYTES: usize = core::mem::size_of::<[Particle; N]>();

/// SysTick wraps (each 2^24 ticks).
static WRAPS: AtomicU32 = AtomicU32::new(0);
/// SysTick reload: the full 24 bits.
const RELOAD: u32 = 0x00ff_ffff;
/// Instructions per SysTick tick under `-icount shift=0` (1 ns each), as a fraction: the MPS2's
/// SysTick counts 25 MHz (40 ns), the nRF51's 16 MHz (62.5 ns).
#[cfg(feature = "full")]
const INSTRUCTIONS_PER_TICK: (u64, u64) = (40, 1);
#[cfg(not(feature = "full"))]
const INSTRUCTIONS_PER_TICK: (u64, u64) = (125, 2);
/// The byte painted below the stack pointer to find the peak stack afterwards.
const PAINT: u32 = 0xdead_beef;

unsafe extern "C" {
    /// End of .bss/.data: the lowest address the stack may reach (cortex-m-rt's symbol).
    static __sheap: u32;
    /// The initial stack pointer, the end of RAM (cortex-m-rt's symbol).
    static _stack_start: u32;
}

#[exception]
fn SysTick() {
    // Only this handler writes (a Cortex-M0 has no atomic read-modify-write).
    WRAPS.store(WRAPS.load(Ordering::Relaxed) + 1, Ordering::Relaxed);
}

/// A fault (a stray access, an overflowed stack) ends the run with a failure instead of
/// spinning until QEMU's timeout.
#[exception]
unsafe fn HardFault(_frame: &cortex_m_rt::ExceptionFrame) -> ! {
    if let Ok(mut out) = hio::hstdout() {
        let _ = out.write_all(b"error: hard fault\n");
    }
    debug::exit(debug::EXIT_FAILURE);
    loop {
        cortex_m::asm::wfi();
    }
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

/// The demo's four runs on the static buffers, one summary each with its name.
#[cfg(feature = "full")]
fn runs(
    out: &mut Out,
    clock: impl FnMut() -> u64,
) -> Result<[(&'static str, gdsmc_demo::Summary); 4], gdsmc_demo::DemoError> {
    // SAFETY: the only references to PARTICLES and SPINS, taken once here.
    let (buf, spins) = unsafe {
        (
            &mut *core::ptr::addr_of_mut!(PARTICLES),
            &mut *core::ptr::addr_of_mut!(SPINS),
        )
    };
    let [a, b, c, d] = gdsmc_demo::all(buf, spins, 1, out, clock)?;
    Ok([("grw3", a), ("hcs", b), ("rough", c), ("rough-mix", d)])
}

/// GRW Example 3 on the static particles (the micro:bit build).
#[cfg(not(feature = "full"))]
fn runs(
    out: &mut Out,
    clock: impl FnMut() -> u64,
) -> Result<[(&'static str, gdsmc_demo::Summary); 1], gdsmc_demo::DemoError> {
    // SAFETY: the only reference to PARTICLES, taken once here.
    let buf = unsafe { &mut *core::ptr::addr_of_mut!(PARTICLES) };
    Ok([("grw3", gdsmc_demo::grw3(buf, 1, out, clock)?)])
}

#[entry]
fn main() -> ! {
    let stack_top = core::ptr::addr_of!(_stack_start) as usize;
    let (bottom, top) = paint_stack();
    let mut cp = cortex_m::Peripherals::take().expect("first take");
    cp.SYST.set_clock_source(SystClkSource::Core);
    cp.SYST.set_reload(RELOAD);
    cp.SYST.clear_current();
    cp.SYST.enable_interrupt();
    cp.SYST.enable_counter();
    let mut out = Out(hio::hstdout().expect("semihosting stdout"));
    let status = match runs(&mut out, ticks) {
        Ok(summaries) => {
            for (name, s) in summaries {
                let (num, den) = INSTRUCTIONS_PER_TICK;
                let instr = s.instructions * num / den;
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
            if low <= bottom {
                // The stack reached the statics: the run's numbers cannot be trusted.
                let _ = writeln!(out, "error: the stack outgrew the RAM");
                debug::exit(debug::EXIT_FAILURE);
            }
            let _ = writeln!(
                out,
                "figure stack_peak_bytes={} particles_bytes={} particles_per_kib={}",
                stack_top - low,
                PARTICLE_BYTES,
                1024 / core::mem::size_of::<Particle>()
            );
            debug::EXIT_SUCCESS
        }
        Err(e) => {
            let _ = writeln!(out, "error: {e}");
            debug::EXIT_FAILURE
        }
    };
    debug::exit(status);
    loop {
        cortex_m::asm::wfi();
    }
}
