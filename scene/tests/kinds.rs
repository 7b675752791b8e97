//! Every kind the core declares (`gdsmc_core::physics::{Kernel,Law,Drive,Scheme}Kind`) is
//! written in a scene by its declared word and read back as that kind. The keys each one needs
//! are the kind's declared parameters or matched exhaustively, so a kind added to the core
//! does not compile here until a scene can name it, and fails until the reader takes it.

use gdsmc_core::physics::{DriveKind, KernelKind, LawKind, SchemeKind};
use gdsmc_scene::parse;
use std::path::Path;

/// A scene with these `[collisions]` lines, `[drive]` and `[scheme]` tables.
fn scene(collisions: &str, drive: &str, scheme: &str) -> String {
    format!(
        "[particles]\nn = 64\ninitial = {{ kind = \"maxwellian\", mass = 1.0, temperature = 1.0 }}\n\
         [collisions]\ngamma = 1.0\nc = 0.1\n{collisions}\n[drive]\n{drive}\n[scheme]\n{scheme}\n\
         [observe]\nt_end = 1.0\nintervals = 2\n[run]\nensembles = 2\n"
    )
}

fn read(text: &str) -> gdsmc_core::physics::Physics {
    match parse(Path::new("kinds.toml"), text) {
        Ok(s) => s.physics().clone(),
        Err(e) => panic!("{e}\n{text}"),
    }
}

const ALPHA: &str = "restitution = 0.8";
const MAXWELL: &str = "kernel = \"maxwell\"\nrestitution = 0.8";
const NONE: &str = "kind = \"none\"";
const EXACT: &str = "kind = \"no-splitting\"";

#[test]
fn every_kernel_is_read() {
    for &k in KernelKind::ALL {
        // Its own keys and example values from its declaration.
        let extra: String = k
            .params()
            .iter()
            .map(|p| format!("{} = {:?}\n", p.name, p.example))
            .collect();
        let c = format!("kernel = \"{}\"\n{extra}\n{ALPHA}", k.scene_name());
        let kernel = read(&scene(&c, NONE, EXACT)).kernel;
        assert_eq!(kernel.kind(), k);
        for p in k.params() {
            assert_eq!(kernel.get(p.name), Some(p.example), "{k:?}: {}", p.name);
        }
    }
}

/// A kernel's own key is required with it and refused with another kernel, the refusal naming
/// the keys that kernel has.
#[test]
fn a_kernels_keys_are_its_own() {
    for &k in KernelKind::ALL {
        for p in k.params() {
            let c = format!("kernel = \"{}\"\n{ALPHA}", k.scene_name());
            let e = parse(Path::new("kinds.toml"), &scene(&c, NONE, EXACT))
                .expect_err("its parameter is required")
                .to_string();
            assert!(
                e.contains(&format!("collisions.{}", p.name)) && e.contains("required"),
                "{e}"
            );
            for &other in KernelKind::ALL {
                if other.params().iter().any(|q| q.name == p.name) {
                    continue;
                }
                let c = format!(
                    "kernel = \"{}\"\n{} = {:?}\n{ALPHA}",
                    other.scene_name(),
                    p.name,
                    p.example
                );
                let e = parse(Path::new("kinds.toml"), &scene(&c, NONE, EXACT))
                    .expect_err("not a key of another kernel")
                    .to_string();
                assert!(
                    e.contains(&format!("`collisions.{}` is not a key", p.name))
                        && e.contains("its keys: kernel, gamma, c"),
                    "{e}"
                );
            }
        }
    }
}

/// Every restitution law is read with its declared keys and their example values (the constant
/// law's one parameter is its key, the impact-speed law's the keys of its table); a key the
/// impact-speed law does not declare is refused naming the keys it has, and docs/scenes.md's
/// row of each law names its keys.
#[test]
fn every_restitution_law_is_read() {
    let doc = std::fs::read_to_string(concat!(env!("CARGO_MANIFEST_DIR"), "/../docs/scenes.md"))
        .expect("docs/scenes.md");
    for &k in LawKind::ALL {
        let params = k.params();
        let value = match k {
            LawKind::Constant => format!("{:?}", params[0].example),
            LawKind::ImpactSpeed => format!(
                "{{ {} }}",
                params
                    .iter()
                    .map(|p| format!("{} = {:?}", p.name, p.example))
                    .collect::<Vec<_>>()
                    .join(", ")
            ),
        };
        let c = format!("kernel = \"maxwell\"\n{} = {value}", k.scene_name());
        let law = read(&scene(&c, NONE, EXACT)).restitution;
        assert_eq!(law.kind(), k);
        assert_eq!(
            &law.values()[..params.len()],
            &examples(params)[..params.len()]
        );
        let row = doc
            .lines()
            .find(|l| l.starts_with(&format!("| `collisions.{}` |", k.scene_name())))
            .unwrap_or_else(|| {
                panic!(
                    "docs/scenes.md has no row for collisions.{}",
                    k.scene_name()
                )
            });
        for p in params {
            assert!(row.contains(p.name), "{row}: no {}", p.name);
        }
    }
    let c = "kernel = \"maxwell\"\nimpact_speed_law = { beta0 = 0.1, delta = 0.2, gamma = 1.0 }";
    let e = parse(Path::new("kinds.toml"), &scene(c, NONE, EXACT))
        .expect_err("not a key of the impact-speed law")
        .to_string();
    assert!(
        e.contains("`collisions.impact_speed_law.gamma` is not a key")
            && e.contains("its keys: beta0, delta"),
        "{e}"
    );
    let c = "kernel = \"maxwell\"\nimpact_speed_law = { beta0 = 0.1 }";
    let e = parse(Path::new("kinds.toml"), &scene(c, NONE, EXACT))
        .expect_err("delta is required")
        .to_string();
    assert!(
        e.contains("`collisions.impact_speed_law.delta` is required"),
        "{e}"
    );
}

/// Each parameter's example value in its place (`gdsmc_core::declared::examples`).
fn examples(params: &[gdsmc_core::declared::ParamSpec]) -> [f64; 4] {
    gdsmc_core::declared::examples(params)
}

#[test]
fn every_drive_is_read() {
    for &k in DriveKind::ALL {
        // A declared drive's keys and example values from its declaration.
        let keys = match k {
            DriveKind::None => String::new(),
            DriveKind::WhiteNoise => "beta = 1.0".to_string(),
            DriveKind::HostMedium => "kernel = \"maxwell\"".to_string(),
            declared => declared
                .params()
                .expect("a declared drive")
                .iter()
                .map(|p| format!("{} = {:?}\n", p.name, p.example))
                .collect(),
        };
        let scheme = match k.stepped_only() {
            Some(_) => "kind = \"time-stepped\"\nstep_factor = 0.01",
            None => EXACT,
        };
        let d = format!("kind = \"{}\"\n{keys}", k.scene_name());
        assert_eq!(read(&scene(MAXWELL, &d, scheme)).drive.kind(), k);
    }
}

/// Every scheme is read with its declared keys and their example values; each key is refused
/// on a scheme that does not declare it, naming the keys that scheme has.
#[test]
fn every_scheme_is_read() {
    for &k in SchemeKind::ALL {
        let keys: String = k
            .params()
            .iter()
            .map(|p| format!("{} = {:?}\n", p.name, p.example))
            .collect();
        let s = format!("kind = \"{}\"\n{keys}", k.scene_name());
        assert_eq!(read(&scene(MAXWELL, NONE, &s)).scheme.kind(), k);
        for p in k.params() {
            for &other in SchemeKind::ALL {
                if other.params().iter().any(|q| q.name == p.name) {
                    continue;
                }
                let s = format!(
                    "kind = \"{}\"\n{}\n{} = {:?}",
                    other.scene_name(),
                    other
                        .params()
                        .iter()
                        .map(|q| format!("{} = {:?}", q.name, q.example))
                        .collect::<Vec<_>>()
                        .join("\n"),
                    p.name,
                    p.example
                );
                let e = parse(Path::new("kinds.toml"), &scene(MAXWELL, NONE, &s))
                    .expect_err("not a key of another scheme")
                    .to_string();
                assert!(
                    e.contains(&format!("`scheme.{}` is not a key of [scheme]", p.name))
                        && e.contains("its keys: kind"),
                    "{e}"
                );
            }
        }
    }
}

/// Asserts that docs/scenes.md's row of `kind_key` names every variant's scene word and that
/// the documentation has a row `| \`TABLE.KEY\` |` for each of its keys (`variants`: scene
/// word and keys): a variant added to the core and not to the documentation fails.
fn documented<'a>(
    kind_key: &str,
    table: &str,
    variants: impl Iterator<Item = (&'a str, Vec<&'a str>)>,
) {
    let doc = std::fs::read_to_string(concat!(env!("CARGO_MANIFEST_DIR"), "/../docs/scenes.md"))
        .expect("docs/scenes.md");
    let kinds_row = doc
        .lines()
        .find(|l| l.starts_with(&format!("| `{kind_key}` |")))
        .unwrap_or_else(|| panic!("docs/scenes.md has no {kind_key} row"));
    for (word, keys) in variants {
        assert!(
            kinds_row.contains(&format!("`\"{word}\"`")),
            "docs/scenes.md's {kind_key} row does not name \"{word}\""
        );
        for key in keys {
            assert!(
                doc.contains(&format!("| `{table}.{key}` |")),
                "docs/scenes.md has no row for {table}.{key} ({word})"
            );
        }
    }
}

/// docs/scenes.md names every scheme's scene word and every key of its own.
#[test]
fn the_scene_documentation_names_every_scheme_and_its_keys() {
    let names = |k: SchemeKind| k.params().iter().map(|p| p.name).collect();
    documented(
        "scheme.kind",
        "scheme",
        SchemeKind::ALL.iter().map(|&k| (k.scene_name(), names(k))),
    );
}

/// docs/scenes.md names every kernel's scene word and every key of its own.
#[test]
fn the_scene_documentation_names_every_kernel_and_its_keys() {
    let names = |k: KernelKind| k.params().iter().map(|p| p.name).collect();
    documented(
        "collisions.kernel",
        "collisions",
        KernelKind::ALL.iter().map(|&k| (k.scene_name(), names(k))),
    );
}

/// docs/scenes.md names every drive's scene word and every key of a drive declared by its type.
#[test]
fn the_scene_documentation_names_every_drive_and_its_keys() {
    let names = |k: DriveKind| k.params().unwrap_or(&[]).iter().map(|p| p.name).collect();
    documented(
        "drive.kind",
        "drive",
        DriveKind::ALL.iter().map(|&k| (k.scene_name(), names(k))),
    );
}
