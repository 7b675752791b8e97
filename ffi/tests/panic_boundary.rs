//! The panic boundary, with a panic injected on purpose (feature `fault-injection`) where one
//! once leaked the particle buffer: between allocating the particles and handing them to the
//! handle. The call must return `GDSMC_PANIC`, leave `*out` NULL, keep the panic's message and
//! place for `gdsmc_last_error`, print nothing (the panic hook the caller had is not called),
//! and give back every byte it allocated.
//!
//! One test in this binary: the panic hook is process-wide, so nothing may run beside it.

use gdsmc::{
    fault, gdsmc_config, gdsmc_config_default, gdsmc_last_error, gdsmc_sim, gdsmc_sim_create,
    gdsmc_sim_destroy, gdsmc_status,
};
use std::alloc::{GlobalAlloc, Layout, System};
use std::cell::Cell;
use std::sync::atomic::{AtomicUsize, Ordering};

/// The system allocator, counting the bytes this thread holds.
struct Counting;

thread_local! {
    static HELD: Cell<isize> = const { Cell::new(0) };
}

// SAFETY: every call is forwarded to the system allocator unchanged; the counter is a
// thread-local `Cell` with a const initializer, which never allocates.
unsafe impl GlobalAlloc for Counting {
    unsafe fn alloc(&self, l: Layout) -> *mut u8 {
        let _ = HELD.try_with(|h| h.set(h.get() + l.size() as isize));
        // SAFETY: the caller's layout, forwarded.
        unsafe { System.alloc(l) }
    }
    unsafe fn dealloc(&self, p: *mut u8, l: Layout) {
        let _ = HELD.try_with(|h| h.set(h.get() - l.size() as isize));
        // SAFETY: `p` came from `alloc` with this layout.
        unsafe { System.dealloc(p, l) }
    }
}

#[global_allocator]
static ALLOCATOR: Counting = Counting;

fn held() -> isize {
    HELD.with(Cell::get)
}

/// Calls the hook the "caller" installed before using gdsmc.
static CALLER_HOOK_CALLS: AtomicUsize = AtomicUsize::new(0);

fn config(n: u64) -> gdsmc_config {
    let mut c = std::mem::MaybeUninit::<gdsmc_config>::uninit();
    // SAFETY: a writable config.
    assert_eq!(
        unsafe { gdsmc_config_default(c.as_mut_ptr()) },
        gdsmc_status::GDSMC_OK
    );
    // SAFETY: initialized by gdsmc_config_default.
    let mut c = unsafe { c.assume_init() };
    c.n = n as _;
    c
}

fn last_error() -> String {
    let mut buf = vec![0u8; 1024];
    // SAFETY: a writable buffer of its length.
    let len = unsafe { gdsmc_last_error(buf.as_mut_ptr().cast(), buf.len()) };
    String::from_utf8(buf[..len].to_vec()).unwrap()
}

#[test]
fn a_panic_inside_a_call_is_caught_silently_and_frees_what_it_allocated() {
    std::panic::set_hook(Box::new(|info| {
        CALLER_HOOK_CALLS.fetch_add(1, Ordering::SeqCst);
        eprintln!("caller's hook: {info}");
    }));
    // A normal create and destroy first: whatever the library sets up once (the hook wrapper)
    // is not counted below.
    let c = config(100_000);
    let mut sim: *mut gdsmc_sim = std::ptr::null_mut();
    // SAFETY: valid pointers.
    assert_eq!(
        unsafe { gdsmc_sim_create(&c, &mut sim) },
        gdsmc_status::GDSMC_OK
    );
    // SAFETY: a handle from gdsmc_sim_create.
    assert_eq!(
        unsafe { gdsmc_sim_destroy(&mut sim) },
        gdsmc_status::GDSMC_OK
    );

    let before = held();
    fault::panic_in_next_build();
    let mut sim: *mut gdsmc_sim = std::ptr::null_mut();
    // SAFETY: valid pointers.
    let status = unsafe { gdsmc_sim_create(&c, &mut sim) };
    let leaked = held() - before;
    assert_eq!(status, gdsmc_status::GDSMC_PANIC);
    assert!(sim.is_null());
    // 100,000 particles are 3.2 MB: without the box owning them, this is what leaked.
    assert_eq!(leaked, 0, "bytes still held after the caught panic");
    let m = last_error();
    assert!(
        m.starts_with("internal error (panic caught at the C boundary at ")
            && m.contains("sim.rs:")
            && m.ends_with("injected fault"),
        "{m}"
    );
    assert_eq!(
        CALLER_HOOK_CALLS.load(Ordering::SeqCst),
        0,
        "the caught panic went through the caller's panic hook (printed)"
    );

    // A panic of the caller's own, outside any gdsmc call, still reaches the caller's hook.
    let r = std::panic::catch_unwind(|| panic!("the caller's own"));
    assert!(r.is_err());
    assert_eq!(CALLER_HOOK_CALLS.load(Ordering::SeqCst), 1);

    // The thread is usable again: the next call succeeds and clears the message.
    let mut sim: *mut gdsmc_sim = std::ptr::null_mut();
    // SAFETY: valid pointers.
    assert_eq!(
        unsafe { gdsmc_sim_create(&c, &mut sim) },
        gdsmc_status::GDSMC_OK
    );
    assert_eq!(last_error(), "");
    // SAFETY: a handle from gdsmc_sim_create.
    unsafe { gdsmc_sim_destroy(&mut sim) };
}
