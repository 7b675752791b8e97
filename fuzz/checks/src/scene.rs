//! The scene reader takes untrusted files: for any bytes, and for any document built from the
//! schema's own tables and keys with arbitrary values, it returns a scene or an error naming
//! what is wrong, never panics; a scene it accepts has physics the core accepts, and `--set`
//! overrides on it are validated the same way.

use crate::wild;
use arbitrary::Unstructured;
use gdsmc_core::physics::{DriveKind, KernelKind, SchemeKind};
use std::path::Path;
use std::sync::LazyLock;

/// Arbitrary bytes as a scene file.
pub fn scene_reader(data: &[u8]) {
    let Ok(text) = std::str::from_utf8(data) else {
        return;
    };
    check(text, &[]);
}

/// Parses `text` with `overrides`; an accepted scene's physics must validate in the core.
fn check(text: &str, overrides: &[String]) {
    match gdsmc_scene::parse_with_overrides(Path::new("fuzz.toml"), text, overrides) {
        Ok(scene) => {
            if let Err(e) = scene.physics().validate() {
                panic!("the scene reader accepted physics the core refuses: {e}\n{text}");
            }
            assert!(
                scene.times().len() >= 2,
                "a scene needs two observation times"
            );
        }
        Err(e) => {
            let msg = e.to_string();
            assert!(!msg.is_empty(), "an error without a message");
        }
    }
}

/// Every table and key of the schema with the kinds of values it takes; `[drive]`'s keys are
/// derived from the core: none's, white noise's and the host medium's beside every declared
/// drive's parameters (`DriveKind::params`), and `[collisions]`'s every kernel's own keys
/// (`KernelKind::params`), so a new drive or kernel is fuzzed with its keys.
pub static KEYS: LazyLock<Vec<(&'static str, Vec<&'static str>)>> = LazyLock::new(|| {
    let mut drive = vec![
        "kind",
        "beta",
        "kernel",
        "c",
        "density",
        "mass",
        "temperature",
        "drift",
    ];
    for k in DriveKind::ALL {
        for p in k.params().unwrap_or(&[]) {
            if !drive.contains(&p.name) {
                drive.push(p.name);
            }
        }
    }
    // Every kernel's common keys, as the scene crate declares them.
    let mut collisions = gdsmc_scene::COLLISION_KEYS.to_vec();
    for k in KernelKind::ALL {
        for p in k.params() {
            if !collisions.contains(&p.name) {
                collisions.push(p.name);
            }
        }
    }
    let mut scheme = vec!["kind"];
    for k in SchemeKind::ALL {
        for p in k.params() {
            if !scheme.contains(&p.name) {
                scheme.push(p.name);
            }
        }
    }
    vec![
        ("particles", vec!["n"]),
        (
            "particles.initial",
            vec!["kind", "mass", "temperature", "drift", "components"],
        ),
        ("collisions", collisions),
        ("drive", drive),
        ("scheme", scheme),
        (
            "observe",
            vec![
                "t_start",
                "t_end",
                "intervals",
                "spacing",
                "first",
                "time_axis",
                "snapshots",
                "collisional_pairs",
                "steady_from",
            ],
        ),
        ("run", vec!["ensembles", "seed"]),
        ("histogram", vec!["shells", "radius"]),
        ("reduced_histogram", vec!["shells", "radius"]),
        ("marginal_histogram", vec!["axis", "bins", "radius"]),
    ]
});

/// The words the schema's string keys take, and some it does not: every kernel's, drive's and
/// scheme's scene word from the core's kinds, the host medium's background kernels, the initial
/// distributions, and near misses.
pub static WORDS: LazyLock<Vec<&'static str>> = LazyLock::new(|| {
    let mut words: Vec<&'static str> = KernelKind::ALL
        .iter()
        .map(|k| k.scene_name())
        .chain(DriveKind::ALL.iter().map(|k| k.scene_name()))
        .chain(SchemeKind::ALL.iter().map(|k| k.scene_name()))
        .collect();
    words.extend([
        "maxwellian",
        "mixture",
        "",
        "MAXWELL",
        "hard_spheres",
        "linear",
        "log",
        "collisions",
        "time",
    ]);
    words.dedup();
    words
});

fn value(u: &mut Unstructured<'_>, depth: u32) -> toml::Value {
    match u.int_in_range(0u8..=7).unwrap_or(0) {
        0 | 1 => toml::Value::Float(wild(u)),
        2 => toml::Value::Integer(match u.int_in_range(0u8..=3).unwrap_or(0) {
            0 => u.int_in_range(-3i64..=40).unwrap_or(0),
            1 => i64::MAX,
            2 => i64::MIN,
            _ => u.arbitrary().unwrap_or(0),
        }),
        3 | 4 => toml::Value::String(WORDS[u.choose_index(WORDS.len()).unwrap_or(0)].into()),
        5 => toml::Value::Boolean(u.arbitrary().unwrap_or(false)),
        6 if depth < 2 => toml::Value::Array(
            (0..u.int_in_range(0u8..=5).unwrap_or(0))
                .map(|_| value(u, depth + 1))
                .collect(),
        ),
        _ if depth < 2 => {
            let mut t = toml::Table::new();
            for _ in 0..u.int_in_range(0u8..=4).unwrap_or(0) {
                let keys = [
                    "weight",
                    "mass",
                    "temperature",
                    "drift",
                    "beta0",
                    "delta",
                    "kind",
                ];
                let k = keys[u.choose_index(keys.len()).unwrap_or(0)];
                t.insert(k.into(), value(u, depth + 1));
            }
            toml::Value::Table(t)
        }
        _ => toml::Value::Float(wild(u)),
    }
}

/// A document of the schema's tables and keys with arbitrary values (structure-aware), plus
/// arbitrary `--set` overrides of the same keys.
pub fn scene_structured(data: &[u8]) {
    let mut u = Unstructured::new(data);
    let mut doc = toml::Table::new();
    let mut paths = Vec::new();
    for _ in 0..u.int_in_range(0u8..=24).unwrap_or(0) {
        let (table, keys) = &KEYS[u.choose_index(KEYS.len()).unwrap_or(0)];
        let key = keys[u.choose_index(keys.len()).unwrap_or(0)];
        let v = value(&mut u, 0);
        let mut t = &mut doc;
        for part in table.split('.') {
            let entry = t
                .entry(part.to_string())
                .or_insert_with(|| toml::Value::Table(toml::Table::new()));
            match entry {
                toml::Value::Table(inner) => t = inner,
                _ => return,
            }
        }
        t.insert(key.into(), v);
        paths.push(format!("{table}.{key}"));
    }
    let Ok(text) = toml::to_string(&doc) else {
        return;
    };
    let mut overrides = Vec::new();
    for _ in 0..u.int_in_range(0u8..=3).unwrap_or(0) {
        if paths.is_empty() {
            break;
        }
        let p = &paths[u.choose_index(paths.len()).unwrap_or(0)];
        let v = value(&mut u, 1);
        overrides.push(format!("{p}={v}"));
    }
    check(&text, &[]);
    check(&text, &overrides);
}
