//! RW Tables 3-6: the steady temperature of the heated Maxwell gas under the three schemes,
//! each figure judged under the two readings of what RW average.

use crate::Error;
use crate::reproduce::bounds::width;
use crate::reproduce::cells::{Cell, ReadingScores};
use crate::reproduce::judged::{PaperInterval, mean_exact};
use crate::reproduce::{Entry, Options, Row, Table, go, scene};
use crate::run::columns::name;
use gdsmc_theory::curves::maxwell_temperature;

/// How RW's steady-state figures are judged: with the scatter of the estimator itself.
const ESTIMATOR_SCATTER: &str = "the estimator's own scatter: our half-width of the same \
    estimator (one ensemble, the same n, scheme and points); RW's Conf, read as RW define it, \
    is about half of it (the Conf cells)";

/// RW Table 3.
pub const TABLE3: Entry = Entry {
    name: "rw-table3",
    title: "RW Table 3: Euler splitting, steady temperature at n = 65536",
    run: table3,
};

/// RW Table 4.
pub const TABLE4: Entry = Entry {
    name: "rw-table4",
    title: "RW Table 4: Strang splitting, steady temperature at n = 65536",
    run: table4,
};

/// RW Table 5.
pub const TABLE5: Entry = Entry {
    name: "rw-table5",
    title: "RW Table 5: no-splitting scheme, steady temperature at n = 65536",
    run: table5,
};

/// RW Table 6.
pub const TABLE6: Entry = Entry {
    name: "rw-table6",
    title: "RW Table 6: example (30) (beta = 37.5, T_inf = 100), the three schemes at K = 32",
    run: table6,
};

/// One steady-state figure of RW under the two readings of what RW average: the exact mean
/// of RW (23)'s raw temperature and of the temperature about the bulk velocity, with the
/// estimator's own scatter (ours: the same estimator, one ensemble, the same n and points).
#[derive(Clone, Copy, Debug)]
struct Reading {
    /// RW's figure.
    paper: f64,
    /// Half a unit of its last digit.
    round: f64,
    /// The exact mean of the raw temperature's average (RW (23)).
    raw: f64,
    /// The exact mean of the bulk temperature's average.
    bulk: f64,
    /// The estimator's standard error (our half-width over the Student-t multiplier).
    se: f64,
    /// Its degrees of freedom.
    dof: u64,
}

impl Reading {
    /// RW's figure's score against `exact`, with the rounding (uniform) in its variance.
    fn z(&self, exact: f64) -> f64 {
        let sd = (self.se * self.se + self.round * self.round / 3.0).sqrt();
        crate::reproduce::judged::t_to_z((self.paper - exact) / sd, self.dof)
    }

    /// Its scores under both readings, kept in the table for the report's pooled test.
    fn scores(&self) -> ReadingScores {
        ReadingScores {
            raw: self.z(self.raw),
            bulk: self.z(self.bulk),
        }
    }
}

/// The two readings over a table's rows, as a sentence: chi^2 of RW's figures against each
/// exact mean with the estimator's scatter, and which one they fit.
fn readings(rs: &[Reading]) -> String {
    let scores: Vec<ReadingScores> = rs.iter().map(Reading::scores).collect();
    format!(
        "Readings (RW's figures against the exact mean with the estimator's own scatter, ours \
         of the same estimator, not RW's Conf): {}",
        ReadingScores::words(&scores)
    )
}

/// A steady-state row of RW Section 4.2: one ensemble of `n = 65536`, the raw temperature
/// averaged over the 65 observation points `s = 8, 10, ..., 136`; returns the cells, the wall
/// seconds, the CPU seconds and the figure's two readings.
fn steady_row(
    o: &Options,
    scene_name: &str,
    scheme: Option<(&str, f64)>,
    seed: u64,
    paper: (f64, f64, f64),
) -> Result<([Cell; 2], f64, f64, Reading), Error> {
    let set: Vec<String> = match scheme {
        Some((kind, dt)) => vec![format!("scheme.kind={kind}"), format!("scheme.dt={dt}")],
        None => vec![],
    };
    let n = 65_536;
    let s = scene(scene_name, &set, n, 1, seed);
    let (st, secs) = go(&s, o)?;
    let mt = maxwell_temperature(&s).expect("a Maxwell scene");
    let first = s.steady_from().expect("a steady-state scene");
    let pts = &s.times()[first..];
    let bulk_at = |t: f64| match scheme {
        Some((kind, dt)) => mt.splitting_bulk_mean(n, dt, kind == "strang", t),
        None => mt.finite_n_bulk_mean(n, t),
    };
    let average =
        |f: &dyn Fn(f64) -> f64| pts.iter().map(|&t| f(t)).sum::<f64>() / pts.len() as f64;
    let bulk = average(&bulk_at);
    let exact = average(&|t| bulk_at(t) + mt.bulk_to_raw(n, t));
    let (t_inf, conf, round) = paper;
    // One ensemble: our interval comes from the spread of the steady points (results.rs).
    let dof = pts.len() as u64 - 1;
    let ours = crate::reproduce::steady(&st, name::T);
    // RW's figure is the same estimator as ours (one ensemble, the same n, scheme and
    // points): its scatter is ours. RW's own Conf is shown beside it (read as RW define it,
    // a width, it is about half of ours: not the estimator's scatter).
    // What the row studies: the time step's shift of the exact mean from the no-splitting
    // scheme's, or (no splitting) the raw term that tells RW (23)'s raw temperature from the
    // temperature about the bulk velocity; the power rule asks for a tenth of it, not of T.
    let effect = match scheme {
        Some(_) => {
            let no_split = average(&|t| mt.finite_n_bulk_mean(n, t) + mt.bulk_to_raw(n, t));
            ((exact - no_split).abs(), "the time step's shift")
        }
        None => ((exact - bulk).abs(), "the raw term"),
    };
    let cell = mean_exact(
        "T_inf",
        t_inf,
        ours,
        dof,
        exact,
        &PaperInterval {
            half: ours.1,
            round,
            source: ESTIMATOR_SCATTER,
        },
    )
    .effect(effect.0, effect.1);
    let reading = Reading {
        paper: t_inf,
        round,
        raw: exact,
        bulk,
        se: ours.1 / gdsmc_stats::multiplier(dof + 1),
        dof,
    };
    // RW's Conf beside ours read the same way: the width of a 3.2-sigma interval from the
    // spread of the points taken as independent (RW Section 4.2: "big enough to assure almost
    // independent observations").
    let col = st.col(name::T).expect("a known column");
    let xs: Vec<f64> = (first..s.times().len())
        .map(|ti| st.mean(ti, col))
        .collect();
    let points = gdsmc_stats::Sample::of(&xs);
    Ok((
        [
            cell,
            Cell::shown("Conf", conf, width(points.sd, points.n as f64)),
        ],
        secs,
        st.cpu.as_secs_f64(),
        reading,
    ))
}

fn cpu_cell(paper: f64, ours: f64) -> Cell {
    Cell::shown("CPU", paper, ours)
}

/// `RW's Conf / ours` for every Conf cell of `rows`, as one sentence.
fn conf_ratios(rows: &[Row]) -> String {
    let r: Vec<String> = rows
        .iter()
        .flat_map(|r| &r.cells)
        .filter(|c| c.quantity == "Conf")
        .map(|c| format!("{:.2}", c.paper / c.ours))
        .collect();
    format!("RW's Conf / ours: {}.", r.join(", "))
}

fn steady_notes(extra: &str) -> String {
    format!(
        "One ensemble of n = 65536 as RW; the raw temperature averaged over s = 8, 10, ..., 136 \
         with its 99.9% half-width from the spread of those points (widened for their lag-1 \
         autocorrelation, Student t over the points). Both figures are judged against the exact \
         mean of RW (23)'s raw temperature average (finite n, time step; theory/src/exact.rs) \
         with the estimator's own scatter: ours is the same estimator (one ensemble, the same \
         n, scheme and points), so our half-width is the range of both figures. RW's Conf is \
         shown beside ours read as RW define it, \"the width of the confidence interval\" (RW \
         Section 4.2): the width of a 3.2-sigma interval from our spread of the same points \
         taken as independent (RW's Conf / ours, row by row, below: near 1/2 means RW's Conf \
         is a half-width in fact, or their interval, read as they define it, is narrower \
         than their scatter). RW's figures are also tested together under both readings of \
         what they average, RW (23)'s raw temperature and the temperature about the bulk \
         velocity (whose exact mean lacks the raw term (T0 + 2 beta t)/n), below. CPU: CPU \
         time relative to our no-splitting run (shown, not judged; see `gdsmc bench`). A row \
         studies an effect smaller than T: the time step's shift of the exact mean from the \
         no-splitting one, or without splitting the raw term; T_inf agrees only if its checks \
         catch a tenth of that effect (each check's power is given against both). {extra}"
    )
}

pub(super) fn table3(o: &Options, seed: u64) -> Result<Table, Error> {
    // (K, T_inf, Conf, CPU); RW prints K = 4094 where dt = 8/K must divide the observation
    // spacing 2: we run K = 4096.
    let paper = [
        (32usize, 2.9226, 0.0046, 1.09),
        (256, 2.6975, 0.0041, 6.57),
        (512, 2.6817, 0.0040, 12.8),
        (2048, 2.6719, 0.0039, 51.1),
        (4096, 2.6710, 0.0053, 100.4),
    ];
    steady_table(o, seed, "euler", &paper, TABLE3.title, "rw-table3", 256)
}

pub(super) fn table4(o: &Options, seed: u64) -> Result<Table, Error> {
    let paper = [
        (8usize, 2.6055, 0.0040, 0.61),
        (16, 2.6520, 0.0047, 0.86),
        (32, 2.6620, 0.0038, 1.07),
        (64, 2.6655, 0.0045, 1.87),
    ];
    steady_table(o, seed, "strang", &paper, TABLE4.title, "rw-table4", 64)
}

fn steady_table(
    o: &Options,
    seed: u64,
    kind: &str,
    paper: &[(usize, f64, f64, f64)],
    title: &'static str,
    name: &'static str,
    quick_max_k: usize,
) -> Result<Table, Error> {
    let (_, _, base, _) = steady_row(o, "rw-steady", None, seed, (8.0 / 3.0, 0.0, 0.0))?;
    let mut rows = Vec::new();
    let mut skipped = Vec::new();
    let mut read = Vec::new();
    for (k, &(kk, t_inf, conf, cpu)) in paper.iter().enumerate() {
        if o.quick && kk > quick_max_k {
            skipped.push(format!("K = {kk}"));
            continue;
        }
        let dt = 8.0 / kk as f64;
        let ([cell, conf_cell], secs, cpu_s, reading) = steady_row(
            o,
            "rw-steady",
            Some((kind, dt)),
            seed + 1 + k as u64,
            // RW print T_inf with four decimals: half a unit of the last is 5e-5.
            (t_inf, conf, 5e-5),
        )?;
        read.push(reading);
        rows.push(Row {
            label: format!("K = {kk}"),
            n: 65_536,
            ensembles: 1,
            seconds: secs,
            cells: vec![cell, conf_cell, cpu_cell(cpu, cpu_s / base)],
        });
    }
    Ok(Table {
        name,
        title,
        notes: steady_notes(&format!("dt = 8/K. {}", conf_ratios(&rows))),
        rows,
        skipped,
        findings: vec![readings(&read)],
        readings: read.iter().map(Reading::scores).collect(),
    })
}

pub(super) fn table5(o: &Options, seed: u64) -> Result<Table, Error> {
    // RW Table 5 prints four decimals: half a unit of the last is 5e-5.
    let (cells, secs, _, reading) = steady_row(o, "rw-steady", None, seed, (2.6684, 0.0040, 5e-5))?;
    Ok(Table {
        name: "rw-table5",
        title: TABLE5.title,
        notes: steady_notes(&format!(
            "No time step: the exact mean is (1 - 1/n) T_inf plus the raw term. RW's Conf / \
             ours: {:.2}.",
            cells[1].paper / cells[1].ours
        )),
        rows: vec![Row {
            label: "no splitting".into(),
            n: 65_536,
            ensembles: 1,
            seconds: secs,
            cells: cells.into(),
        }],
        skipped: vec![],
        findings: vec![readings(&[reading])],
        readings: vec![reading.scores()],
    })
}

pub(super) fn table6(o: &Options, seed: u64) -> Result<Table, Error> {
    let paper = [
        ("Euler", Some(("euler", 0.25)), 109.596, 0.1711),
        ("Strang", Some(("strang", 0.25)), 99.739, 0.1425),
        ("no-split", None, 99.981, 0.1877),
    ];
    let mut rows = Vec::new();
    let mut read = Vec::new();
    for (k, &(label, scheme, t_inf, conf)) in paper.iter().enumerate() {
        let (cells, secs, _, reading) = steady_row(
            o,
            "rw-steady-30",
            scheme,
            seed + k as u64,
            // RW Table 6 prints three decimals: half a unit of the last is 5e-4.
            (t_inf, conf, 5e-4),
        )?;
        read.push(reading);
        rows.push(Row {
            label: label.into(),
            n: 65_536,
            ensembles: 1,
            seconds: secs,
            cells: cells.into(),
        });
    }
    Ok(Table {
        name: "rw-table6",
        title: TABLE6.title,
        notes: steady_notes(&format!(
            "RW (30): beta = 37.5, K = 32 (dt = 1/4) for both splittings. {}",
            conf_ratios(&rows)
        )),
        rows,
        skipped: vec![],
        findings: vec![readings(&read)],
        readings: read.iter().map(Reading::scores).collect(),
    })
}
