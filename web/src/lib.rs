//! # gdsmc-web
//!
//! gdsmc in the browser. Built for `wasm32-wasip1` (web/build.sh; docs/web.md says why not
//! `wasm32-unknown-unknown`), this crate is the page's whole engine: the runner's scene rules,
//! ensembles, statistics, references, summary, tables and charts ([`session`]), with the
//! command's bits and words. The page's workers (web/www/worker.js) drive it through the
//! functions below, exchanging bytes through two buffers the module owns: a worker writes its
//! input where [`gdsmc_web_input`] says, calls, and reads the answer (JSON, an ensemble's
//! bytes, or the error's words) at [`gdsmc_web_output`]. Nothing here is `unsafe` but the
//! exported names, each one of a kind; a panic traps, and its message is kept for
//! [`gdsmc_web_panic`].

pub mod session;

use session::Session;
use std::cell::RefCell;

thread_local! {
    static INPUT: RefCell<Vec<u8>> = const { RefCell::new(Vec::new()) };
    static OUTPUT: RefCell<Vec<u8>> = const { RefCell::new(Vec::new()) };
    static PANIC: RefCell<String> = const { RefCell::new(String::new()) };
    static SESSION: RefCell<Option<Session>> = const { RefCell::new(None) };
}

/// The call succeeded; the output holds its JSON.
pub const OK: i32 = 0;
/// The call was refused; the output holds the error's words (the command's).
pub const REFUSED: i32 = 1;
/// No run is prepared.
pub const NO_RUN: i32 = 2;

/// Puts `text` in the output buffer; returns `status`.
fn answer(status: i32, text: &str) -> i32 {
    answer_bytes(status, text.as_bytes())
}

/// Puts `bytes` in the output buffer; returns `status`.
fn answer_bytes(status: i32, bytes: &[u8]) -> i32 {
    OUTPUT.with_borrow_mut(|o| {
        o.clear();
        o.extend_from_slice(bytes);
    });
    status
}

/// The input buffer's first `len` bytes as text (lossy: the page writes UTF-8).
fn input(from: usize, len: usize) -> String {
    INPUT.with_borrow(|b| {
        String::from_utf8_lossy(&b[from.min(b.len())..(from + len).min(b.len())]).into_owned()
    })
}

/// Makes room for `len` bytes of input and returns where the page writes them.
// SAFETY: the name is exported once, for the page (no other symbol of the program has it).
#[unsafe(no_mangle)]
pub extern "C" fn gdsmc_web_input(len: u32) -> *mut u8 {
    INPUT.with_borrow_mut(|b| {
        b.clear();
        b.resize(len as usize, 0);
        b.as_mut_ptr()
    })
}

/// Where the last answer lies ([`gdsmc_web_output_len`] bytes).
// SAFETY: the name is exported once, for the page.
#[unsafe(no_mangle)]
pub extern "C" fn gdsmc_web_output() -> *const u8 {
    OUTPUT.with_borrow(|o| o.as_ptr())
}

/// The last answer's length in bytes.
// SAFETY: the name is exported once, for the page.
#[unsafe(no_mangle)]
pub extern "C" fn gdsmc_web_output_len() -> u32 {
    OUTPUT.with_borrow(|o| o.len() as u32)
}

/// Prepares a run from the input: the scene's name (`name_len` bytes), its text (`text_len`)
/// and the overrides (`sets_len`, `key=value` a line), one after another. [`OK`] with the
/// scene's facts ([`Session::prepare`]), or [`REFUSED`] with the command's words.
// SAFETY: the name is exported once, for the page.
#[unsafe(no_mangle)]
pub extern "C" fn gdsmc_web_prepare(name_len: u32, text_len: u32, sets_len: u32) -> i32 {
    std::panic::set_hook(Box::new(|info| {
        PANIC.with_borrow_mut(|p| *p = info.to_string());
    }));
    let (n, t, s) = (name_len as usize, text_len as usize, sets_len as usize);
    let (name, text, sets) = (input(0, n), input(n, t), input(n + t, s));
    SESSION.with_borrow_mut(|slot| *slot = None);
    match Session::prepare(&name, &text, &sets) {
        Ok((session, info)) => {
            SESSION.with_borrow_mut(|slot| *slot = Some(session));
            answer(OK, &info.to_string())
        }
        Err(e) => answer(REFUSED, &e),
    }
}

/// Runs the next `k` ensembles of the prepared run: [`OK`] with `{"done": ...}`.
// SAFETY: the name is exported once, for the page.
#[unsafe(no_mangle)]
pub extern "C" fn gdsmc_web_advance(k: u32) -> i32 {
    let done = SESSION.with_borrow_mut(|slot| slot.as_mut().map(|s| s.advance(u64::from(k))));
    match done {
        None => answer(NO_RUN, "no run is prepared"),
        Some(Ok(d)) => answer(OK, &serde_json::json!({ "done": d }).to_string()),
        Some(Err(e)) => answer(REFUSED, &e),
    }
}

/// The charts of the ensembles finished so far ([`Session::charts`]).
// SAFETY: the name is exported once, for the page.
#[unsafe(no_mangle)]
pub extern "C" fn gdsmc_web_charts() -> i32 {
    match SESSION.with_borrow(|slot| slot.as_ref().map(Session::charts)) {
        None => answer(NO_RUN, "no run is prepared"),
        Some(v) => answer(OK, &v.to_string()),
    }
}

/// The summary and tables of the ensembles finished so far ([`Session::finish`]).
// SAFETY: the name is exported once, for the page.
#[unsafe(no_mangle)]
pub extern "C" fn gdsmc_web_finish() -> i32 {
    match SESSION.with_borrow(|slot| slot.as_ref().map(Session::finish)) {
        None => answer(NO_RUN, "no run is prepared"),
        Some(Ok(v)) => answer(OK, &v.to_string()),
        Some(Err(e)) => answer(REFUSED, &e),
    }
}

/// After a trap: the panic's message into the output (empty if none); its length.
// SAFETY: the name is exported once, for the page.
#[unsafe(no_mangle)]
pub extern "C" fn gdsmc_web_panic() -> u32 {
    let message = PANIC.with_borrow(Clone::clone);
    answer(OK, &message);
    message.len() as u32
}

/// The variants the core declares ([`session::kinds`]): [`OK`] with their JSON.
// SAFETY: the name is exported once, for the page.
#[unsafe(no_mangle)]
pub extern "C" fn gdsmc_web_kinds() -> i32 {
    answer(OK, &session::kinds().to_string())
}

/// Runs ensemble `k` of the prepared run alone ([`Session::ensemble`]): [`OK`] with its bytes
/// (not JSON) for the worker that folds.
// SAFETY: the name is exported once, for the page.
#[unsafe(no_mangle)]
pub extern "C" fn gdsmc_web_ensemble(k: u32) -> i32 {
    match SESSION.with_borrow_mut(|slot| slot.as_mut().map(|s| s.ensemble(u64::from(k)))) {
        None => answer(NO_RUN, "no run is prepared"),
        Some(Ok(bytes)) => answer_bytes(OK, &bytes),
        Some(Err(e)) => answer(REFUSED, &e),
    }
}

/// Folds the next ensemble from the input's first `len` bytes ([`Session::fold`]): [`OK`]
/// with `{"done": ...}`.
// SAFETY: the name is exported once, for the page.
#[unsafe(no_mangle)]
pub extern "C" fn gdsmc_web_fold(len: u32) -> i32 {
    let bytes = INPUT.with_borrow(|b| b[..(len as usize).min(b.len())].to_vec());
    match SESSION.with_borrow_mut(|slot| slot.as_mut().map(|s| s.fold(&bytes))) {
        None => answer(NO_RUN, "no run is prepared"),
        Some(Ok(d)) => answer(OK, &serde_json::json!({ "done": d }).to_string()),
        Some(Err(e)) => answer(REFUSED, &e),
    }
}

/// Adds the helper workers' wall and CPU seconds to the prepared run's time.
// SAFETY: the name is exported once, for the page.
#[unsafe(no_mangle)]
pub extern "C" fn gdsmc_web_add_time(wall: f64, cpu: f64) -> i32 {
    match SESSION.with_borrow_mut(|slot| slot.as_mut().map(|s| s.add_time(wall, cpu))) {
        None => answer(NO_RUN, "no run is prepared"),
        Some(()) => answer(OK, "{}"),
    }
}
