//! The fuzzer draws every kind the core declares: the scene fuzzer's words hold each kernel's,
//! drive's and scheme's scene word and its keys each restitution law's key, and the C fuzzer's
//! enumeration codes reach every kind (`cabi::MOST_KINDS`). A kind added to the core and not
//! to the fuzzer fails here.

use gdsmc_core::physics::{DriveKind, KernelKind, LawKind, SchemeKind};
use gdsmc_fuzz_checks::{KEYS, MOST_KINDS, WORDS};

#[test]
fn the_fuzzers_draw_every_kind() {
    let words = KernelKind::ALL
        .iter()
        .map(|k| k.scene_name())
        .chain(DriveKind::ALL.iter().map(|k| k.scene_name()))
        .chain(SchemeKind::ALL.iter().map(|k| k.scene_name()));
    for w in words {
        assert!(WORDS.contains(&w), "the scene fuzzer never writes `{w}`");
    }
    let collisions = KEYS
        .iter()
        .find(|(t, _)| *t == "collisions")
        .expect("collisions");
    for k in LawKind::ALL {
        assert!(
            collisions.1.contains(&k.scene_name()),
            "the scene fuzzer never sets collisions.{}",
            k.scene_name()
        );
    }
    for n in [
        KernelKind::ALL.len(),
        LawKind::ALL.len(),
        DriveKind::ALL.len(),
        SchemeKind::ALL.len(),
    ] {
        assert!(n <= MOST_KINDS);
    }
}
