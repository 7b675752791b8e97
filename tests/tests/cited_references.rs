//! A shipped scene's description cites only references its run attaches: every reference of
//! the registry (theory/src/curves/registry/) that a description names by its
//! id, one of its columns or its words is given to that scene's run by some attached
//! reference that answers to the same name, with at least one curve.

use gdsmc_runner::scene;
use gdsmc_theory::curves::registry::{REFERENCES, Reference, applicable, cites};

/// Every shipped scene's name and the scene.
fn shipped() -> Vec<(String, scene::Scene)> {
    let dir = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("../scenes");
    let mut out: Vec<(String, scene::Scene)> = std::fs::read_dir(&dir)
        .expect("scenes/ is readable")
        .map(|e| e.expect("a directory entry").path())
        .filter(|p| p.extension().is_some_and(|x| x == "toml"))
        .map(|p| {
            let s = scene::load(&p).expect("a shipped scene loads");
            (p.file_stem().unwrap().to_string_lossy().into_owned(), s)
        })
        .collect();
    out.sort_by(|a, b| a.0.cmp(&b.0));
    out
}

/// The names a reference answers to.
fn names(r: &Reference) -> Vec<&'static str> {
    std::iter::once(r.id)
        .chain(r.columns.iter().copied())
        .chain(r.cites.iter().copied())
        .collect()
}

#[test]
fn every_cited_reference_is_attached() {
    let scenes = shipped();
    assert!(scenes.len() >= 30, "only {} shipped scenes", scenes.len());
    let (mut cited, mut missing) = (0, Vec::new());
    for (name, s) in &scenes {
        let text = s.description();
        let attached: Vec<&Reference> = applicable(s)
            .filter(|r| !(r.curves)(s).is_empty())
            .collect();
        for w in REFERENCES.iter().flat_map(names) {
            if !cites(text, w) {
                continue;
            }
            cited += 1;
            if !attached.iter().any(|a| names(a).contains(&w)) {
                missing.push(format!(
                    "scenes/{name}.toml cites {w:?}, which its run does not attach (attached: {:?})",
                    attached.iter().map(|r| r.id).collect::<Vec<_>>()
                ));
            }
        }
    }
    assert!(missing.is_empty(), "{}", missing.join("\n"));
    // The check reaches the scenes: MS's, the GRW, BRS and Haff's-law ones cite references.
    assert!(cited >= 15, "only {cited} citations found");
}
