//! Every kind the core declares (`gdsmc_core::physics::{Kernel,Law,Drive,Scheme}Kind`) has its
//! constant in the C header, `GDSMC_<AXIS>_<NAME>` with the kind's code: a kind added to the
//! core without its C constant fails here (the decoder's exhaustive matches fail to compile,
//! and ffi/src/physics.rs asserts the constants it has at compile time).

use gdsmc_core::physics::{DriveKind, KernelKind, LawKind, SchemeKind};

/// `HardSpheres` -> `HARD_SPHERES`.
fn upper_snake(debug: &str) -> String {
    let mut out = String::new();
    for (i, ch) in debug.chars().enumerate() {
        if ch.is_uppercase() && i > 0 {
            out.push('_');
        }
        out.push(ch.to_ascii_uppercase());
    }
    out
}

fn defines() -> Vec<(String, u32)> {
    let header =
        std::fs::read_to_string(concat!(env!("CARGO_MANIFEST_DIR"), "/../include/gdsmc.h"))
            .expect("include/gdsmc.h");
    header
        .lines()
        .filter_map(|l| {
            let mut w = l.strip_prefix("#define ")?.split_whitespace();
            Some((w.next()?.to_string(), w.next()?.parse().ok()?))
        })
        .collect()
}

#[test]
fn every_kind_has_its_constant_in_the_header() {
    let defines = defines();
    let mut want: Vec<(String, u32)> = Vec::new();
    let mut add = |axis: &str, name: String, code: u32| {
        want.push((format!("GDSMC_{axis}_{}", upper_snake(&name)), code));
    };
    for k in KernelKind::ALL {
        add("KERNEL", format!("{k:?}"), k.c_code());
    }
    for k in LawKind::ALL {
        add("RESTITUTION", format!("{k:?}"), k.c_code());
    }
    for k in DriveKind::ALL {
        add("DRIVE", format!("{k:?}"), k.c_code());
    }
    for k in SchemeKind::ALL {
        add("SCHEME", format!("{k:?}"), k.c_code());
    }
    for (name, code) in &want {
        assert!(
            defines.iter().any(|(n, c)| n == name && c == code),
            "include/gdsmc.h has no `#define {name} {code}`"
        );
    }
    // And no constant of these families that is not a kind.
    for (n, c) in &defines {
        let family = [
            "GDSMC_KERNEL_",
            "GDSMC_RESTITUTION_",
            "GDSMC_DRIVE_",
            "GDSMC_SCHEME_",
        ];
        if family.iter().any(|f| n.starts_with(f)) {
            assert!(
                want.iter().any(|(w, k)| w == n && k == c),
                "include/gdsmc.h's {n} = {c} is no kind of the core"
            );
        }
    }
    assert_eq!(upper_snake("ConstantForce"), "CONSTANT_FORCE");
}
