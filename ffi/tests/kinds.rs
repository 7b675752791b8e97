//! Every kind the core declares (`gdsmc_core::physics::{Kernel,Law,Drive,Scheme}Kind`) has its
//! constant in the C header, `GDSMC_<AXIS>_<NAME>` with the kind's code: a kind added to the
//! core without its C constant fails here.
//!
//! The constants come from `ffi/src/codes.rs`, generated from the core's declarations (glam's
//! "generated from one table"): the kinds (code and words) and each kernel's and declared
//! drive's parameters (`KernelKind::params`, `DriveKind::params`: name, rule, words, unit,
//! their places in `kernel_params` and `drive_params`). A test here
//! fails when the file is not what the declarations give;
//! `GDSMC_UPDATE_CODES=1 cargo test --release -p gdsmc-ffi --test kinds` rewrites it (then
//! cbindgen the header, `include/gdsmc.h`).

use gdsmc_core::declared::ParamSpec;
use gdsmc_core::physics::{
    DriveKind, KernelKind, LawKind, MAX_DRIVE_PARAMS, MAX_KERNEL_PARAMS, SchemeKind,
};
use std::fmt::Write;

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

/// ` Its parameters in `kernel_params`: GDSMC_VHS_LAMBDA.` (nothing when it has none).
fn places(kind: &str, params: &[ParamSpec], array: &str) -> String {
    if params.is_empty() {
        return String::new();
    }
    let names: Vec<String> = params
        .iter()
        .map(|p| format!("GDSMC_{}_{}", upper_snake(kind), p.name.to_uppercase()))
        .collect();
    format!(" Its parameters in `{array}`: {}.", names.join(", "))
}

/// A parameter array's length and every kind's places in it: `(axis, array, whose words)`.
fn array(
    out: &mut String,
    (axis, name, whose): (&str, &str, &str),
    max: usize,
    kinds: Vec<(String, &[ParamSpec])>,
) {
    let _ = writeln!(
        out,
        "\n/// Most parameters {whose}: the length of\n\
         /// `gdsmc_config.{name}`.\n\
         pub const GDSMC_MAX_{}: usize = {max};",
        name.to_uppercase()
    );
    for (kind, params) in kinds {
        constants(out, axis, &kind, params, name);
    }
}

/// Each parameter's place in `array` as a constant, with its words, unit and rule.
fn constants(out: &mut String, axis: &str, kind: &str, params: &[ParamSpec], array: &str) {
    for (i, p) in params.iter().enumerate() {
        let default = p
            .default
            .map_or(String::new(), |d| format!("; default {d}"));
        let _ = writeln!(
            out,
            "\n/// `{array}[{i}]` of GDSMC_{axis}_{}: {} ({}, {}{default}).\n\
             pub const GDSMC_{}_{}: usize = {i};",
            upper_snake(kind),
            p.words,
            p.unit,
            p.rule,
            upper_snake(kind),
            p.name.to_uppercase(),
        );
    }
}

/// The parameters of scheme `k` that live in `scheme_params` (the splittings' `dt` and the
/// time-stepped scheme's `step_factor` have fields of their own; a new scheme says here).
fn in_scheme_params(k: SchemeKind) -> &'static [ParamSpec] {
    match k {
        SchemeKind::Weighted => k.params(),
        SchemeKind::NoSplitting
        | SchemeKind::Euler
        | SchemeKind::Strang
        | SchemeKind::TimeStepped => &[],
    }
}

/// The file the declarations give.
fn generated() -> String {
    let mut out = String::from(
        "//! The C ABI's codes: generated by `ffi/tests/kinds.rs` from the core's declarations (the\n\
         //! kinds `gdsmc_core::physics::{Kernel,Law,Drive,Scheme}Kind` and each declared drive's\n\
         //! parameters); do not edit. `GDSMC_UPDATE_CODES=1 cargo test --release -p gdsmc-ffi\n\
         //! --test kinds` rewrites it.\n",
    );
    let _ = writeln!(
        out,
        "\n/// The version of the random streams (`gdsmc_core::rng::STREAM_VERSION`): a simulation\n\
         /// is a pure function of its configuration, seed and this version.\n\
         pub const GDSMC_STREAM_VERSION: u32 = {};",
        gdsmc_core::rng::STREAM_VERSION
    );
    let mut family = |axis: &str, rows: Vec<(String, u32, &str, String)>| {
        for (name, code, doc, extra) in rows {
            let _ = writeln!(out, "\n/// {}{extra}", doc.trim());
            let _ = writeln!(
                out,
                "pub const GDSMC_{axis}_{}: u32 = {code};",
                upper_snake(&name)
            );
        }
    };
    family(
        "KERNEL",
        KernelKind::ALL
            .iter()
            .map(|k| {
                let extra = places(&format!("{k:?}"), k.params(), "kernel_params");
                (format!("{k:?}"), k.c_code(), k.doc(), extra)
            })
            .collect(),
    );
    family(
        "RESTITUTION",
        LawKind::ALL
            .iter()
            .map(|k| (format!("{k:?}"), k.c_code(), k.doc(), String::new()))
            .collect(),
    );
    family(
        "DRIVE",
        DriveKind::ALL
            .iter()
            .map(|k| {
                let extra = places(&format!("{k:?}"), k.params().unwrap_or(&[]), "drive_params");
                (format!("{k:?}"), k.c_code(), k.doc(), extra)
            })
            .collect(),
    );
    family(
        "SCHEME",
        SchemeKind::ALL
            .iter()
            .map(|k| {
                let extra = places(&format!("{k:?}"), in_scheme_params(*k), "scheme_params");
                (format!("{k:?}"), k.c_code(), k.doc(), extra)
            })
            .collect(),
    );
    let kernels = KernelKind::ALL
        .iter()
        .map(|k| (format!("{k:?}"), k.params()));
    array(
        &mut out,
        ("KERNEL", "kernel_params", "a kernel has beyond gamma and C"),
        MAX_KERNEL_PARAMS,
        kernels.collect(),
    );
    let drives = DriveKind::ALL
        .iter()
        .map(|k| (format!("{k:?}"), k.params().unwrap_or(&[])));
    array(
        &mut out,
        ("DRIVE", "drive_params", "a drive declared by its type has"),
        MAX_DRIVE_PARAMS,
        drives.collect(),
    );
    let schemes = SchemeKind::ALL
        .iter()
        .map(|&k| (format!("{k:?}"), in_scheme_params(k)));
    array(
        &mut out,
        ("SCHEME", "scheme_params", "a scheme has in `scheme_params`"),
        gdsmc_core::physics::WEIGHTED_PARAMS,
        schemes.collect(),
    );
    out
}

#[test]
fn the_codes_file_is_generated_from_the_declarations() {
    let path = concat!(env!("CARGO_MANIFEST_DIR"), "/src/codes.rs");
    let want = generated();
    if std::env::var_os("GDSMC_UPDATE_CODES").is_some() {
        std::fs::write(path, &want).expect("ffi/src/codes.rs written");
    }
    let have = std::fs::read_to_string(path).expect("ffi/src/codes.rs");
    assert!(
        have == want,
        "ffi/src/codes.rs is not what the core's declarations give: rerun with \
         GDSMC_UPDATE_CODES=1 (then cbindgen the header)\n{want}"
    );
}
