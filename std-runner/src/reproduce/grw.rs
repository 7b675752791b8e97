//! GRW Tables 1 and 2: convergence in `n` of the heated Maxwell gas (Examples 3 and 4).

use super::{
    Cell, Check, Entry, Options, Row, Table, at, ensembles, go, max_relative_error, scene,
};
use crate::Error;
use crate::reference::curves::maxwell_temperature;

/// GRW Table 1 (Example 3, beta = 1).
pub const TABLE1: Entry = Entry {
    name: "grw-table1",
    title: "GRW Table 1: E_max and ||V||_inf of Example 3 (heated Maxwell gas, beta = 1)",
    run: |o, seed| {
        table(
            o,
            seed,
            "grw-table1",
            TABLE1.title,
            "grw-example3",
            &[
                (64, 0.895e-1, 0.672e-2),
                (256, 0.235e-1, 0.516e-2),
                (1024, 0.571e-2, 0.211e-2),
                (4096, 0.150e-2, 0.141e-2),
                (16384, 0.305e-3, 0.355e-3),
            ],
        )
    },
};

/// GRW Table 2 (Example 4, beta = 1/8).
pub const TABLE2: Entry = Entry {
    name: "grw-table2",
    title: "GRW Table 2: E_max and ||V||_inf of Example 4 (heated Maxwell gas, beta = 1/8)",
    run: |o, seed| {
        table(
            o,
            seed,
            "grw-table2",
            TABLE2.title,
            "grw-example4",
            &[
                (64, 0.130, 0.306e-2),
                (256, 0.336e-1, 0.188e-2),
                (1024, 0.823e-2, 0.874e-2),
                (4096, 0.211e-2, 0.581e-2),
                (16384, 0.455e-3, 0.148e-2),
            ],
        )
    },
};

/// GRW's ensembles per row.
const PAPER_ENSEMBLES: u64 = 10_000;

/// The 99.9% quantile of the chi distribution with 3 degrees of freedom.
const CHI3_999: f64 = 4.033;

fn table(
    o: &Options,
    seed: u64,
    name: &'static str,
    title: &'static str,
    scene_name: &str,
    rows: &[(usize, f64, f64)],
) -> Result<Table, Error> {
    let mut out = Vec::new();
    for (k, &(n, e_paper, v_paper)) in rows.iter().enumerate() {
        let m = ensembles(o, n, PAPER_ENSEMBLES, 1 << 22);
        let s = scene(scene_name, &[], n, m, seed + k as u64);
        let mt = maxwell_temperature(&s).expect("a Maxwell scene");
        let (st, secs) = go(&s, o)?;
        let ours = max_relative_error(&st, "T", 0.0, |t| mt.at(t));
        let exact = s
            .times
            .iter()
            .map(|&t| ((mt.finite_n_raw_mean(n, t) - mt.at(t)) / mt.at(t)).abs())
            .fold(0.0, f64::max);
        // The paper's half-width: ours rescaled from our ensembles to GRW's.
        let paper_ci = ours.1 * (m as f64 / PAPER_ENSEMBLES as f64).sqrt();
        let e = Cell::within("E_max", e_paper, ours, paper_ci).exact(exact);
        // ||V||_inf = max_t |V(t)|: pure noise (E V = 0). Each component of the mean over N
        // ensembles has variance (T0 + 2 beta t)/(n N) (collisions keep momentum, kicks make
        // it a random walk), largest at t_end.
        let t_end = *s.times.last().expect("observation times");
        let var1 = mt.bulk_to_raw(n, t_end);
        let v = (0..st.times.len())
            .map(|ti| {
                let c = |x| at(&st, ti, x).0;
                (c("V_x").powi(2) + c("V_y").powi(2) + c("V_z").powi(2)).sqrt()
            })
            .fold(0.0, f64::max);
        let vcell = Cell {
            quantity: "||V||_inf".into(),
            paper: v_paper,
            ours: v,
            ours_ci: 0.0,
            exact: Some(0.0),
            check: Check::Below {
                paper_bound: CHI3_999 * (var1 / PAPER_ENSEMBLES as f64).sqrt(),
                ours_bound: CHI3_999 * (var1 / m as f64).sqrt(),
            },
            disputed: None,
        };
        out.push(Row {
            label: format!("n = {n}"),
            n,
            ensembles: m,
            seconds: secs,
            cells: vec![e, vcell],
        });
    }
    Ok(Table {
        name,
        title,
        notes: format!(
            "Raw temperature T = (1/3n) sum |v|^2 against GRW (13) at the scene's observation \
             times on [0, 8]; GRW ran {PAPER_ENSEMBLES} ensembles per row. E_max: the paper's \
             half-width is ours rescaled to {PAPER_ENSEMBLES} ensembles; 'exact' is the exact \
             E_max of the ensemble mean, (T0 (1 - e^(-kt)) + 2 beta (t - (1 - e^(-kt))/k))/n \
             relative (reference.rs). GRW's E_max lie about 10% above that exact value (5.9/n \
             against 5.39/n at t = 8, as RW's Table 1 for the same process), beyond GRW's noise \
             at n <= 256; ours land on it. ||V||_inf is noise only: ours must lie below the \
             99.9% chi(3) bound 4.03 sqrt((T0 + 2 beta t_end)/(n N)) at our N (the running \
             maximum passes it with probability about 0.002); the bound at GRW's N is printed \
             first. GRW's Table 2 values for n >= 1024 exceed it several times, so they cannot \
             be the norm of a 10000-ensemble mean; they are shown, not judged."
        ),
        rows: out,
        skipped: vec![],
    })
}
