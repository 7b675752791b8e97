//! Every TOML example in docs/scenes.md is a valid part of a scene: merged into a minimal scene,
//! it parses and validates. Every shipped scene validates too.

use gdsmc_scene::parse;
use std::path::{Path, PathBuf};

const BASE: &str = include_str!("scenes/docs_base.toml");

fn merge(base: &mut toml::Table, part: toml::Table) {
    for (k, v) in part {
        match (base.get_mut(&k), v) {
            (Some(toml::Value::Table(b)), toml::Value::Table(p)) => merge(b, p),
            (_, v) => {
                base.insert(k, v);
            }
        }
    }
}

#[test]
fn docs_examples_are_valid_scenes() {
    let root = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("..");
    let doc = std::fs::read_to_string(root.join("docs/scenes.md")).unwrap();
    let mut blocks = 0;
    for block in doc.split("```toml\n").skip(1) {
        let text = block.split("```").next().unwrap();
        let part: toml::Table = toml::from_str(text).unwrap_or_else(|e| panic!("{text}\n{e}"));
        let mut scene: toml::Table = toml::from_str(BASE).unwrap();
        // An example with its own restitution law (or one per species pair) replaces the
        // base's constant.
        let collisions = part.get("collisions");
        if ["impact_speed_law", "pair_restitution"]
            .iter()
            .any(|k| collisions.and_then(|c| c.get(k)).is_some())
        {
            scene["collisions"]
                .as_table_mut()
                .unwrap()
                .remove("restitution");
        }
        merge(&mut scene, part);
        let merged = toml::to_string(&scene).unwrap();
        parse(Path::new("docs/scenes.md"), &merged).unwrap_or_else(|e| panic!("{merged}\n{e}"));
        blocks += 1;
    }
    assert!(blocks >= 10, "found {blocks} examples");
}

#[test]
fn shipped_scenes_are_valid() {
    let dir = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../scenes");
    let mut k = 0;
    for e in std::fs::read_dir(dir).unwrap() {
        let p = e.unwrap().path();
        if p.extension().is_some_and(|x| x == "toml") {
            gdsmc_scene::load(&p).unwrap_or_else(|e| panic!("{e}"));
            k += 1;
        }
    }
    assert!(k >= 19, "{k} scenes");
}

/// The first number a description states after `alpha = ` (a decimal or a fraction `p/q`),
/// unless a list follows it (`alpha = 0.2, 0.4, ...` names a table's rows, not the file's).
fn stated_alpha(description: &str) -> Option<f64> {
    let rest = &description[description.find("alpha = ")? + "alpha = ".len()..];
    let end = rest
        .find(|c: char| !(c.is_ascii_digit() || c == '.' || c == '/'))
        .unwrap_or(rest.len());
    let (num, after) = rest.split_at(end);
    let num = num.trim_end_matches('.');
    // A list: ", " then another number ending in "," or ")".
    if let Some(next) = after.strip_prefix(", ") {
        let k = next
            .find(|c: char| !(c.is_ascii_digit() || c == '.' || c == '/'))
            .unwrap_or(next.len());
        if k > 0 && next[k..].starts_with([',', ')']) {
            return None;
        }
    }
    match num.split_once('/') {
        Some((p, q)) => Some(p.parse::<f64>().ok()? / q.parse::<f64>().ok()?),
        None => num.parse().ok(),
    }
}

/// A shipped scene whose description states its restitution states the one the file sets (a
/// reader compares the run with the description's figures). disks-hcs said alpha = 0.9 and
/// set 0.5.
#[test]
fn shipped_descriptions_state_the_restitution_the_file_sets() {
    assert_eq!(
        stated_alpha("GRW Example 3: alpha = 1/2, beta = 1"),
        Some(0.5)
    );
    assert_eq!(stated_alpha("Table 1 (alpha = 0.2, 0.4, 0.6)"), None);
    assert_eq!(stated_alpha("disks, alpha = 0.9, 4 pi"), Some(0.9));
    let dir = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../scenes");
    let mut checked = 0;
    for e in std::fs::read_dir(dir).unwrap() {
        let p = e.unwrap().path();
        if p.extension().is_none_or(|x| x != "toml") {
            continue;
        }
        let s = gdsmc_scene::load(&p).unwrap_or_else(|e| panic!("{e}"));
        let (Some(stated), Some(set)) = (
            stated_alpha(s.description()),
            s.physics().restitution.constant(),
        ) else {
            continue;
        };
        assert!(
            (stated - set).abs() < 1e-12,
            "{}: the description says alpha = {stated}, the file sets {set}",
            p.display()
        );
        checked += 1;
    }
    assert!(checked >= 15, "only {checked} descriptions state alpha");
}
