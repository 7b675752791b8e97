//! The documentation stays inside the repository: every link and image in README.md,
//! ARCHITECTURE.md, CHANGELOG.md and docs/*.md is a relative path to a file that exists in the
//! repository (no web address, nothing outside the tree, no `../shared`), and the bibliography
//! (docs/references.md) lists the four papers and every method the code names.

use std::fs;
use std::path::{Path, PathBuf};

fn root() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .parent()
        .expect("tests/ has a parent")
        .to_path_buf()
}

fn documents() -> Vec<PathBuf> {
    let r = root();
    let mut docs = vec![
        r.join("README.md"),
        r.join("ARCHITECTURE.md"),
        r.join("CHANGELOG.md"),
    ];
    for e in fs::read_dir(r.join("docs")).expect("docs/ exists") {
        let p = e.expect("readable entry").path();
        if p.extension().is_some_and(|x| x == "md") {
            docs.push(p);
        }
    }
    docs
}

/// Targets of markdown links and images, `[text](target)`, with their line numbers.
fn link_targets(text: &str) -> Vec<(usize, String)> {
    let mut out = Vec::new();
    for (k, line) in text.lines().enumerate() {
        let mut rest = line;
        while let Some(at) = rest.find("](") {
            let after = &rest[at + 2..];
            let Some(end) = after.find(')') else { break };
            out.push((k + 1, after[..end].trim().to_string()));
            rest = &after[end..];
        }
    }
    out
}

#[test]
fn every_link_is_a_file_in_the_repository() {
    let r = root().canonicalize().expect("root resolves");
    let mut bad = Vec::new();
    let mut seen = 0;
    for doc in documents() {
        let text = fs::read_to_string(&doc).expect("readable");
        let dir = doc.parent().expect("has a folder");
        let name = doc.strip_prefix(&r).unwrap_or(&doc).display().to_string();
        for (line, target) in link_targets(&text) {
            seen += 1;
            let path = target.split('#').next().unwrap_or("");
            if target.contains("://") || target.starts_with("mailto:") {
                bad.push(format!("{name}:{line}: `{target}` leaves the repository"));
                continue;
            }
            if path.is_empty() {
                continue; // an anchor in the same file
            }
            match dir.join(path).canonicalize() {
                Ok(p) if p.starts_with(&r) => {}
                Ok(_) => bad.push(format!(
                    "{name}:{line}: `{target}` is outside the repository"
                )),
                Err(_) => bad.push(format!("{name}:{line}: `{target}` does not exist")),
            }
        }
        if text.contains("../shared") {
            bad.push(format!("{name}: names ../shared, outside the repository"));
        }
    }
    assert!(seen > 0, "no link found at all: the scanner is broken");
    assert!(bad.is_empty(), "{}", bad.join("\n"));
}

#[test]
fn the_scanner_catches_what_it_must() {
    let t = "see [a](docs/x.md) and ![b](https://example.org/c.png) [c](#top)";
    let targets: Vec<String> = link_targets(t).into_iter().map(|(_, s)| s).collect();
    assert_eq!(targets, ["docs/x.md", "https://example.org/c.png", "#top"]);
}

#[test]
fn the_bibliography_names_every_paper_and_method_cited() {
    let refs = fs::read_to_string(root().join("docs/references.md")).expect("docs/references.md");
    for needle in [
        "| GRW |",
        "| RW |",
        "| BRS |",
        "| MS |",
        "Marsaglia, W. W. Tsang",
        "Choosing a point from the surface of a sphere",
        "Lemire",
        "Blackman, S. Vigna",
        "Welford",
        "Chan, G. H. Golub",
        "Haff",
        "van Noije",
        "Student",
        "Garzó, J. W. Dufty",
        "Montanero, V. Garzó",
    ] {
        assert!(refs.contains(needle), "docs/references.md lacks {needle}");
    }
    // Every row of a table gives a DOI or says why not.
    for line in refs
        .lines()
        .filter(|l| l.starts_with("| ") && !l.starts_with("| short") && !l.starts_with("| where"))
    {
        let last = line
            .trim_end_matches('|')
            .rsplit('|')
            .next()
            .unwrap_or("")
            .trim();
        let is_doi = last.starts_with("10.") && last.contains('/');
        let says_why = last.contains("not checked")
            || last.contains("no DOI")
            || last.contains("not identified");
        assert!(is_doi || says_why, "no DOI and no reason in: {line}");
    }
}
