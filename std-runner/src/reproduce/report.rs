//! The reproduced tables as terminal text and as a markdown report.

use super::figure::fmt;
use super::{Cell, Counts, Options, Side, Table, Verdict};
use std::fmt::Write;

/// The ranges of a cell's checks, short: `paper [lo, hi]; ours [lo, hi]`.
fn ranges(c: &Cell) -> String {
    if c.checks.is_empty() {
        return "-".into();
    }
    c.checks
        .iter()
        .map(|k| {
            format!(
                "{} [{}, {}]",
                match k.side {
                    Side::Paper => "paper",
                    Side::Ours => "ours",
                },
                fmt(k.lo),
                fmt(k.hi)
            )
        })
        .collect::<Vec<_>>()
        .join("; ")
}

/// Text for a markdown table cell: pipes escaped (`||V||_inf`).
fn cell_text(x: &str) -> String {
    x.replace('|', "\\|")
}

/// One table for the terminal: a line per cell, then the counts.
pub fn text(t: &Table) -> String {
    let mut s = String::new();
    let _ = writeln!(s, "\n{}", t.title);
    let _ = writeln!(
        s,
        "{:<20} {:<18} {:>11} {:>24} {:>11} {:>48} {:>16}",
        "row", "quantity", "paper", "ours +- 99.9%", "exact", "ranges", "verdict"
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
                "{:<20} {:<18} {:>11} {:>24} {:>11} {:>48} {:>16}",
                r.label,
                c.quantity,
                fmt(c.paper),
                ours,
                c.exact.map_or("-".into(), fmt),
                ranges(c),
                c.word()
            );
        }
    }
    let _ = writeln!(s, "{}", Counts::of([t]).line());
    for j in joints(t) {
        let _ = writeln!(s, "table-wide: {}", j.line());
    }
    for f in &t.findings {
        let _ = writeln!(s, "{f}");
    }
    if !t.skipped.is_empty() {
        let _ = writeln!(s, "not run in this mode: {}", t.skipped.join(", "));
    }
    s
}

/// The table-wide tests of a table, the paper's first (those that exist: a side needs two
/// scored figures).
fn joints(t: &Table) -> Vec<super::cells::Joint> {
    [super::Side::Paper, super::Side::Ours]
        .into_iter()
        .filter_map(|side| t.joint(side))
        .collect()
}

/// The lines that end a `reproduce` run on the terminal, one per unusual class of cell, each
/// saying why the cell is what it is: a disagreement of ours that stays within the report-wide
/// range (expected now and then from sound code, so it does not fail the run), a disputed cell
/// with the evidence against the paper's figure, the published figures off an exact value, the
/// weak cells with the error their checks let through, and the uninformative ones with their
/// ranges; RW's readings pooled over the tables that have them.
pub fn epilogue(tables: &[Table]) -> String {
    let mut s = String::new();
    let mut within = Vec::new();
    let mut disputed = Vec::new();
    let mut paper_off = Vec::new();
    let mut weak = Vec::new();
    let mut uninformative = Vec::new();
    let mut jointly = Vec::new();
    let mut findings = Vec::new();
    for t in tables {
        for j in joints(t) {
            if j.off() {
                jointly.push(format!("{}: {}", t.name, j.line()));
            }
        }
        findings.extend(t.findings.iter().map(|f| format!("{}: {f}", t.name)));
        for r in &t.rows {
            for c in &r.cells {
                let at = format!("{} {}: {}", t.name, r.label, c.quantity);
                match c.verdict() {
                    v if v.against_us() && !c.fails_run() => {
                        within.push(format!("{at} (ours {}; {})", fmt(c.ours), c.basis()))
                    }
                    Verdict::Disputed => {
                        disputed.push(format!("{at}: {}", c.dispute.as_deref().unwrap_or("")))
                    }
                    Verdict::Disagree(crate::reproduce::Blame::Paper) => paper_off.push(format!(
                        "{at} (paper {}, ours {})",
                        fmt(c.paper),
                        fmt(c.ours)
                    )),
                    Verdict::Uninformative => {
                        uninformative.push(format!("{at} (ours {}; {})", fmt(c.ours), c.basis()))
                    }
                    Verdict::Weak => weak.push(format!(
                        "{at} (detects {} of {})",
                        super::percent(c.detectable().unwrap_or(f64::INFINITY)),
                        c.power_of()
                    )),
                    _ => {}
                }
            }
        }
    }
    if !within.is_empty() {
        let _ = writeln!(
            s,
            "disagreements of ours within the report-wide range (each misses its own 99.9% range; \
             the run is judged at 99.9% over every check a report may hold, Bonferroni over {}, \
             so a sound run shows about one such miss per {} checks and still passes):",
            super::bounds::FAMILY,
            (1.0 / gdsmc_stats::miss()).round()
        );
        for w in &within {
            let _ = writeln!(s, "  {w}");
        }
    }
    if !disputed.is_empty() {
        let _ = writeln!(
            s,
            "disputed (a check failed, and a consistency check of the same run puts the paper's \
             figure off):"
        );
        for d in &disputed {
            let _ = writeln!(s, "  {d}");
        }
    }
    if !paper_off.is_empty() {
        let _ = writeln!(
            s,
            "published figures outside the range of an exact value (findings, not failures):"
        );
        for p in &paper_off {
            let _ = writeln!(s, "  {p}");
        }
    }
    if !jointly.is_empty() {
        let _ = writeln!(
            s,
            "figures jointly off their exact laws (table-wide: each figure's score against the \
             law of its estimator, chi^2 over the table and its largest |z|; findings, not \
             failures, when the paper's):"
        );
        for j in &jointly {
            let _ = writeln!(s, "  {j}");
        }
    }
    let pooled: Vec<_> = tables.iter().flat_map(|t| &t.readings).copied().collect();
    let pooling: Vec<&str> = tables
        .iter()
        .filter(|t| !t.readings.is_empty())
        .map(|t| t.name)
        .collect();
    if pooling.len() > 1 {
        findings.push(format!(
            "{} pooled: {}",
            pooling.join(", "),
            super::ReadingScores::words(&pooled)
        ));
    }
    if !findings.is_empty() {
        let _ = writeln!(s, "what tables show together:");
        for f in &findings {
            let _ = writeln!(s, "  {f}");
        }
    }
    if !weak.is_empty() {
        let _ = writeln!(
            s,
            "weak (every check passed, but one would let an error of more than {} of the quantity \
             or of the effect its row studies through: the error it catches with probability {} \
             is beside each):",
            super::percent(super::POWER),
            super::percent(super::POWER_PROBABILITY)
        );
        for w in &weak {
            let _ = writeln!(s, "  {w}");
        }
    }
    if !uninformative.is_empty() {
        let _ = writeln!(
            s,
            "uninformative (every check passed, but one could not have failed: its range holds 0 \
             or ten times the expected value):"
        );
        for u in &uninformative {
            let _ = writeln!(s, "  {u}");
        }
    }
    s
}

/// The markdown report of a whole `reproduce` run.
pub fn markdown(tables: &[Table], opts: &Options, seconds: f64) -> String {
    let mut s = String::new();
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
    let _ = writeln!(s, "**{}.**\n", Counts::of(tables).line());
    let _ = writeln!(
        s,
        "How a cell is judged: each check names the figure it judges (the paper's or ours), \
         the range that figure must lie in at the 99.9% level and what the range is made of. \
         Where the estimator's expectation is known exactly (every Maxwell table), the paper's \
         figure is judged against it with the paper's own noise (the interval it states, read \
         as it defines it, or ours rescaled to its ensembles when it states none) and ours with \
         ours; elsewhere ours is judged against the paper's figure. A check whose range holds 0, \
         or ten times the expected value, could not fail: its cell is *uninformative*, never \
         *agree*. Each check that can fail states its power, the relative error of the judged \
         figure it catches with probability {} (`detects`: the range's reach plus 1.645 standard \
         deviations of the figure's noise; an error of the half-width alone is caught only half \
         the time); a cell whose checks all pass is *agree* only if each would catch an error \
         of {} of the quantity, or of the effect the row measures where that is not the figure \
         itself (RW's steady tables: the time step's shift or the raw term, beside each \
         check), else *weak*. *disagree (paper)*: the published figure lies outside the range of an exact \
         value (a finding; it does not fail the run). *DISAGREE* or *disagree (ours)*: fails \
         the run. *disputed*: a disagreement that a consistency check computed in the same run \
         puts on the paper (the table's notes give the evidence). *at the edge*: the published \
         figure lies within one standard deviation of its noise of an end of its range, so its \
         agreement or its being off is fragile (a redraw, or a small error of the exact value, \
         could flip it). Intervals use Student-t \
         quantiles for the ensembles run.\n",
        super::percent(super::POWER_PROBABILITY),
        super::percent(super::POWER)
    );
    let _ = writeln!(
        s,
        "| table | agree | disagree (paper) | disagree | disputed | weak | uninformative | shown |"
    );
    let _ = writeln!(s, "|---|---|---|---|---|---|---|---|");
    for t in tables {
        let k = Counts::of([t]);
        let _ = writeln!(
            s,
            "| `{}` | {} | {} | {} | {} | {} | {} | {} |",
            t.name, k.agree, k.paper_off, k.failing, k.disputed, k.weak, k.uninformative, k.shown
        );
    }
    let _ = writeln!(s);
    let named: Vec<String> = tables
        .iter()
        .flat_map(|t| t.rows.iter().map(move |r| (t, r)))
        .flat_map(|(t, r)| {
            r.cells.iter().filter_map(move |c| {
                let v = c.verdict();
                matches!(v, Verdict::Disagree(_) | Verdict::Disputed).then(|| {
                    format!(
                        "- `{}` {}, {}: {} (paper {}, ours {}){}",
                        t.name,
                        r.label,
                        cell_text(&c.quantity),
                        c.word(),
                        fmt(c.paper),
                        fmt(c.ours),
                        c.dispute
                            .as_ref()
                            .map_or(String::new(), |d| format!(": {d}"))
                    )
                })
            })
        })
        .collect();
    if !named.is_empty() {
        let _ = writeln!(s, "Disagreeing and disputed figures:\n");
        for d in &named {
            let _ = writeln!(s, "{d}");
        }
        let _ = writeln!(s);
    }
    for t in tables {
        let _ = writeln!(s, "## {} (`{}`)\n", t.title, t.name);
        let _ = writeln!(s, "{}\n", t.notes);
        let _ = writeln!(s, "{}\n", Counts::of([t]).line());
        let _ = writeln!(
            s,
            "| row | n | ensembles | s | quantity | paper | ours | +- 99.9% | exact | verdict | judged by |"
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
                    c.word(),
                    if c.checks.is_empty() {
                        "shown, not judged".into()
                    } else {
                        cell_text(&c.basis())
                    }
                );
            }
        }
        let js = joints(t);
        if !js.is_empty() {
            let _ = writeln!(s);
        }
        for j in js {
            let _ = writeln!(s, "Table-wide: {}.", j.line());
        }
        for f in &t.findings {
            let _ = writeln!(s, "\n{f}");
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
