//! The reproduced tables as terminal text and as a markdown report.

use super::{Check, Options, Table};
use std::fmt::Write;

fn fmt(x: f64) -> String {
    if x == 0.0 {
        "0".into()
    } else if x.abs() >= 1e-2 && x.abs() < 1e4 {
        format!("{x:.4}")
    } else {
        format!("{x:.3e}")
    }
}

fn verdict(c: &super::Cell) -> &'static str {
    match (c.agrees(), c.disputed.is_some()) {
        (Some(true), false) => "yes",
        (Some(true), true) => "yes*",
        (Some(false), false) => "NO",
        (Some(false), true) => "no*",
        (None, _) => "shown",
    }
}

fn tolerance(c: &super::Cell) -> String {
    match c.check {
        Check::Within { .. } => c.tolerance().map_or("-".into(), fmt),
        Check::Below {
            paper_bound,
            ours_bound,
        } => format!("< {} / {}", fmt(paper_bound), fmt(ours_bound)),
        Check::Shown => "-".into(),
    }
}

/// Text for a markdown table cell: pipes escaped (`||V||_inf`).
fn cell_text(x: &str) -> String {
    x.replace('|', "\\|")
}

/// One table for the terminal: a line per cell.
pub fn text(t: &Table) -> String {
    let mut s = String::new();
    let _ = writeln!(s, "\n{}", t.title);
    let _ = writeln!(
        s,
        "{:<26} {:<22} {:>11} {:>24} {:>11} {:>22} {:>6}",
        "row", "quantity", "paper", "ours +- 99.9%", "exact", "tolerance", "agrees"
    );
    for r in &t.rows {
        for c in &r.cells {
            let ours = if c.ours_ci > 0.0 {
                format!("{} +- {}", fmt(c.ours), fmt(c.ours_ci))
            } else {
                fmt(c.ours)
            };
            let _ = writeln!(
                s,
                "{:<26} {:<22} {:>11} {:>24} {:>11} {:>22} {:>6}",
                r.label,
                c.quantity,
                fmt(c.paper),
                ours,
                c.exact.map_or("-".into(), fmt),
                tolerance(c),
                verdict(c)
            );
        }
    }
    if !t.skipped.is_empty() {
        let _ = writeln!(s, "not run in this mode: {}", t.skipped.join(", "));
    }
    s
}

/// The markdown report of a whole `reproduce` run.
pub fn markdown(tables: &[Table], opts: &Options, seconds: f64) -> String {
    let mut s = String::new();
    let agree = tables
        .iter()
        .flat_map(|t| &t.rows)
        .flat_map(|r| &r.cells)
        .filter(|c| c.agrees() == Some(true) && c.disputed.is_none())
        .count();
    let cells: usize = tables
        .iter()
        .flat_map(|t| &t.rows)
        .flat_map(|r| &r.cells)
        .filter(|c| c.agrees().is_some())
        .count();
    let _ = writeln!(s, "# gdsmc reproduce: the papers' tables beside ours\n");
    let _ = writeln!(
        s,
        "Mode: {}; seed {}; {} version {}; {:.0} s wall.\n",
        if opts.quick { "quick" } else { "full" },
        opts.seed,
        env!("CARGO_PKG_NAME"),
        env!("CARGO_PKG_VERSION"),
        seconds
    );
    let disputed: Vec<String> = tables
        .iter()
        .flat_map(|t| t.rows.iter().map(move |r| (t, r)))
        .flat_map(|(t, r)| {
            r.cells.iter().filter_map(move |c| {
                c.disputed.map(|why| {
                    format!(
                        "- `{}` {}, {}: {why}",
                        t.name,
                        r.label,
                        cell_text(&c.quantity)
                    )
                })
            })
        })
        .collect();
    let _ = writeln!(
        s,
        "**{} of {} judged figures agree** (|ours - paper| <= our 99.9% half-width + the \
         paper's + rounding + stated bias; noise-only figures (ours) below their 99.9% bound); \
         {} disputed (marked *, listed below; they do not fail the run).\n",
        agree,
        cells,
        disputed.len()
    );
    if !disputed.is_empty() {
        let _ = writeln!(
            s,
            "Disputed figures (the paper's value, not ours, is in doubt):\n"
        );
        for d in &disputed {
            let _ = writeln!(s, "{d}");
        }
        let _ = writeln!(s);
    }
    for t in tables {
        let _ = writeln!(s, "## {} (`{}`)\n", t.title, t.name);
        let _ = writeln!(s, "{}\n", t.notes);
        let _ = writeln!(
            s,
            "| row | n | ensembles | s | quantity | paper | ours | +- 99.9% | exact | tolerance | agrees |"
        );
        let _ = writeln!(s, "|---|---|---|---|---|---|---|---|---|---|---|");
        for r in &t.rows {
            for c in &r.cells {
                let _ = writeln!(
                    s,
                    "| {} | {} | {} | {:.1} | {} | {} | {} | {} | {} | {} | {} |",
                    cell_text(&r.label),
                    r.n,
                    r.ensembles,
                    r.seconds,
                    cell_text(&c.quantity),
                    fmt(c.paper),
                    fmt(c.ours),
                    if c.ours_ci > 0.0 {
                        fmt(c.ours_ci)
                    } else {
                        "-".into()
                    },
                    c.exact.map_or("-".into(), fmt),
                    tolerance(c),
                    verdict(c)
                );
            }
        }
        if !t.skipped.is_empty() {
            let _ = writeln!(
                s,
                "\nNot run in quick mode: {} (run `gdsmc reproduce {}`).",
                t.skipped.join(", "),
                t.name
            );
        }
        let _ = writeln!(s);
    }
    s
}
