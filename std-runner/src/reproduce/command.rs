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
    let mut done = Vec::new();
    let mut write_err = None;
    let tables = super::run(names, &opts, |t| {
        print!("{}", super::text(t));
        done.push(t.clone());
        let md = super::markdown(&done, &opts, start.elapsed().as_secs_f64());
        if let Err(e) = crate::files::write_own(&report, md.as_bytes(), REPORT_SIGNATURE) {
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
