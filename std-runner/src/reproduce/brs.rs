//! BRS Tables 1 and 2 (Maxwell gas in a host medium, convergence in `n` against the exact
//! BRS (15)) and the equilibrium temperatures of Examples 4 and 5 (hard spheres) beside the
//! closures BRS (21) and (22).

use super::{Cell, Check, Entry, Options, Row, Table, ensembles, go, max_relative_error, scene};
use crate::Error;
use crate::reference::curves::{host_medium_maxwell, hydro_models};
use crate::reference::hydro::Trajectory;
use crate::run::initial_sampler;

/// BRS Table 1.
pub const TABLE1: Entry = Entry {
    name: "brs-table1",
    title: "BRS Table 1: Example 1, Err of the temperature for n = 4 ... 1024",
    run: |o, seed| {
        table(
            o,
            seed,
            "brs-table1",
            TABLE1.title,
            "brs-example1",
            &[
                (4, 64, 3.49e-1, 1.15e0),
                (16, 256, 8.80e-2, 2.50e-1),
                (64, 1024, 1.99e-2, 6.41e-2),
                (256, 4096, 5.51e-3, 1.62e-2),
                (1024, 16384, 1.08e-3, 3.99e-3),
            ],
        )
    },
};

/// BRS Table 2.
pub const TABLE2: Entry = Entry {
    name: "brs-table2",
    title: "BRS Table 2: Example 2, Err of the temperature for n = 4 ... 1024",
    run: |o, seed| {
        table(
            o,
            seed,
            "brs-table2",
            TABLE2.title,
            "brs-example2",
            &[
                (4, 64, 3.14e-1, 1.99e-1),
                (16, 256, 9.20e-2, 4.51e-2),
                (64, 1024, 2.34e-2, 1.13e-2),
                (256, 4096, 5.71e-3, 2.73e-3),
                (1024, 16384, 1.48e-3, 6.80e-4),
            ],
        )
    },
};

/// The equilibrium temperatures of BRS Examples 4 and 5.
pub const EQUILIBRIA: Entry = Entry {
    name: "brs-equilibria",
    title: "BRS Examples 4 and 5: kinetic equilibrium temperature T* beside the closures (21), (22)",
    run: equilibria,
};

fn table(
    o: &Options,
    seed: u64,
    name: &'static str,
    title: &'static str,
    scene_name: &str,
    paper: &[(usize, u64, f64, f64)],
) -> Result<Table, Error> {
    let mut rows = Vec::new();
    for (k, &(n, n_rep, err, conf)) in paper.iter().enumerate() {
        let m = ensembles(o, n, n_rep, 1 << 18);
        let s = scene(scene_name, &[], n, m, seed + k as u64);
        let h = host_medium_maxwell(&s).expect("a Maxwell host-medium scene");
        let (st, secs) = go(&s, o)?;
        let ours = max_relative_error(&st, "T_bulk", 0.0, |t| h.temperature(t));
        rows.push(Row {
            label: format!("n = {n}, N_rep = {n_rep}"),
            n,
            ensembles: m,
            seconds: secs,
            cells: vec![Cell::within("Err", err, ours, conf)],
        });
    }
    Ok(Table {
        name,
        title,
        notes: "Err = max over the 513 points t_i = i/512 of |T(t_i) - mean| / T(t_i), the \
                temperature about the bulk velocity against the exact BRS (15); the paper's \
                half-width is its Conf (the thickness of its confidence band)."
            .into(),
        rows,
        skipped: vec![],
    })
}

fn equilibria(o: &Options, seed: u64) -> Result<Table, Error> {
    let (n, m) = if o.quick { (2048, 64) } else { (16384, 256) };
    let mut rows = Vec::new();
    for (k, (name, paper, h21, h22)) in [
        ("brs-example4", 0.953, 0.956, 0.956),
        ("brs-example5", 0.732, 0.743, 0.757),
    ]
    .into_iter()
    .enumerate()
    {
        let s = scene(name, &[], n, m, seed + k as u64);
        let (st, secs) = go(&s, o)?;
        let ours = super::steady(&st, "T_bulk");
        let f0 = initial_sampler(&s).expect("a shipped scene's physics is valid");
        let models = hydro_models(&s).expect("a hard-sphere host-medium scene");
        let mut cells = vec![
            // The finite-n bias of T_bulk is about T/n (exactly (1 - 1/n) for the Maxwell gas).
            Cell::within("T* kinetic", paper, ours, 0.0).bias(paper / n as f64),
        ];
        for (model, (label, published)) in models
            .iter()
            .zip([("T* BRS (21)", h21), ("T* BRS (22)", h22)])
        {
            let tr = Trajectory::new(model, f0.mean().to_array(), f0.temperature(), 60.0).map_err(
                |e| Error::Engine {
                    ensemble: 0,
                    message: format!("{label}: {e}"),
                },
            )?;
            let t = tr.temperature(60.0);
            cells.push(Cell {
                quantity: label.into(),
                paper: published,
                ours: t,
                ours_ci: 0.0,
                exact: None,
                check: Check::Within {
                    paper_ci: 0.0,
                    rounding: 5e-4,
                    bias: 0.0,
                },
                disputed: None,
            });
        }
        rows.push(Row {
            label: name.replace("brs-example", "Example "),
            n,
            ensembles: m,
            seconds: secs,
            cells,
        });
    }
    Ok(Table {
        name: "brs-equilibria",
        title: EQUILIBRIA.title,
        notes: "Kinetic T*: T_bulk averaged over t in [0.5, 4] per ensemble, then over ensembles \
                (99.9% half-width), allowed the paper's rounding (5e-4) and the finite-n bias \
                T/n. Closures: BRS (21) and (22) integrated by Dormand-Prince to t = 60 (hydro.rs), \
                against the paper's three digits."
            .into(),
        rows,
        skipped: vec![],
    })
}
