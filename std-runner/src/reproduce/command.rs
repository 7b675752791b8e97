//! `gdsmc reproduce` as the command runs it: the tables one after another, the report
//! rewritten after each.

use super::Options;
use crate::Error;
use std::path::PathBuf;

/// The first words of every report.md `gdsmc reproduce` writes.
const REPORT_SIGNATURE: &str = "# gdsmc reproduce:";

/// `gdsmc reproduce`: runs the tables `names` (all when empty) with `opts`, printing each as
/// it finishes and rewriting `out/report.md` (default `out/reproduce`) after each, so a run
/// cut short keeps the tables it finished; a report.md gdsmc did not write is refused before
/// any table runs. Fails with [`Error::Disagrees`] when a figure of ours disagrees beyond the
/// report-wide range.
pub fn command(names: &[String], opts: &Options, out: Option<PathBuf>) -> Result<(), Error> {
    let opts = *opts;
    let dir = out.unwrap_or_else(|| PathBuf::from("out").join("reproduce"));
    std::fs::create_dir_all(&dir).map_err(|e| Error::Write {
        path: dir.clone(),
        source: e,
    })?;
    let report = dir.join("report.md");
    // A report.md that is not gdsmc's is refused before any table runs, not replaced.
    crate::files::check_own(&report, REPORT_SIGNATURE)?;
    let start = std::time::Instant::now();
    // The tables asked for, in the order they run: the report names those not yet done.
    let asked: Vec<&str> = super::TABLES
        .iter()
        .map(|e| e.name)
        .filter(|n| names.is_empty() || names.iter().any(|m| m == n))
        .collect();
    let write = |done: &[super::Table]| {
        let mut md = super::markdown(done, &opts, start.elapsed().as_secs_f64());
        md.push_str(&not_run(&asked, done));
        crate::files::write_own(&report, md.as_bytes(), REPORT_SIGNATURE)
    };
    // Written before the first table too: a run killed in it leaves a report that says so.
    write(&[])?;
    super::runs::progress_within_tables();
    let mut done = Vec::new();
    let mut write_err = None;
    let tables = super::run(names, &opts, |t| {
        print!("{}", super::text(t));
        done.push(t.clone());
        super::runs::next_table();
        if let Err(e) = write(&done) {
            write_err.get_or_insert(e);
        }
    })?;
    if let Some(e) = write_err {
        return Err(e);
    }
    let bad = super::failures(&tables);
    println!(
        "\n{} tables in {:.0} s; wrote {}\n{}",
        tables.len(),
        start.elapsed().as_secs_f64(),
        report.display(),
        super::Counts::of(&tables).line()
    );
    print!("{}", super::epilogue(&tables));
    if bad.is_empty() {
        println!(
            "no disagreement of ours beyond the report-wide range (Bonferroni over every \
             check): the run passes"
        );
        Ok(())
    } else {
        Err(Error::Disagrees(bad))
    }
}

/// The report's section on the tables asked for that have not run (the run was cut short
/// before them, or is still running); empty once every one has.
fn not_run(asked: &[&str], done: &[super::Table]) -> String {
    let missing: Vec<String> = asked
        .iter()
        .skip(done.len())
        .map(|n| format!("`{n}`"))
        .collect();
    if missing.is_empty() {
        return String::new();
    }
    format!(
        "\n## Not run\n\n{} of the {} tables asked for have not run: {}. The run was cut short \
         before them, or is still running; the figures above cover only the tables shown.\n",
        missing.len(),
        asked.len(),
        missing.join(", ")
    )
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_report_names_the_tables_that_did_not_run() {
        let asked = ["grw-table1", "rw-table1", "ms-table1"];
        let s = not_run(&asked, &[]);
        assert!(
            s.contains("3 of the 3 tables") && s.contains("`ms-table1`"),
            "{s}"
        );
        let t = crate::reproduce::Table {
            name: "grw-table1",
            title: "",
            notes: String::new(),
            rows: Vec::new(),
            skipped: Vec::new(),
            findings: Vec::new(),
            readings: Vec::new(),
        };
        let s = not_run(&asked, std::slice::from_ref(&t));
        assert!(
            s.contains("2 of the 3") && !s.contains("`grw-table1`"),
            "{s}"
        );
        assert_eq!(not_run(&asked[..1], &[t]), "");
    }
}
