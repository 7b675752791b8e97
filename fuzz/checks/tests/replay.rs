//! Replays every checked-in fuzz corpus through its target's checks (stable toolchain): the
//! corpora (`fuzz/corpus/TARGET`, minimized) and the inputs that once crashed or hung a target
//! (`fuzz/regressions/TARGET`, named for what they found) are regression tests.

use std::path::PathBuf;

fn replay(target: &str, check: fn(&[u8])) {
    let root = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("..");
    let mut k = 0;
    for dir in [
        root.join("corpus").join(target),
        root.join("regressions").join(target),
    ] {
        let Ok(entries) = std::fs::read_dir(&dir) else {
            continue;
        };
        for e in entries {
            let p = e.unwrap().path();
            let data = std::fs::read(&p).unwrap();
            let r = std::panic::catch_unwind(|| check(&data));
            assert!(r.is_ok(), "{target}: {} fails", p.display());
            k += 1;
        }
    }
    assert!(k > 0, "{target}: empty corpus");
    eprintln!("{target}: {k} inputs");
}

#[test]
fn collision_maps() {
    replay("collision_maps", gdsmc_fuzz_checks::collision_maps);
}

#[test]
fn rough_maps() {
    replay("rough_maps", gdsmc_fuzz_checks::rough_maps);
}

#[test]
fn samplers() {
    replay("samplers", gdsmc_fuzz_checks::samplers);
}

#[test]
fn scene_reader() {
    replay("scene_reader", gdsmc_fuzz_checks::scene_reader);
}

#[test]
fn scene_structured() {
    replay("scene_structured", gdsmc_fuzz_checks::scene_structured);
}

#[test]
fn c_abi() {
    replay("c_abi", gdsmc_fuzz_checks::c_abi);
}

#[test]
fn state_reader() {
    replay("state_reader", gdsmc_fuzz_checks::state_reader);
}
