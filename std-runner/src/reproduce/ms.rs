//! MS Table 1: the collisional moment mu4 of inelastic hard spheres under the three
//! thermostats, directly from random pairs (MS (67)) and indirectly from mu2 and the moments
//! (MS (23), (38), (44)), with the Maxwellian value mu4^(0) (MS (29)).

use super::{Cell, Entry, Options, Row, Table, go, scene, steady};
use crate::Error;
use crate::reference::exact::sonine::mu4_maxwellian;

/// MS Table 1.
pub const TABLE1: Entry = Entry {
    name: "ms-table1",
    title: "MS Table 1: mu4 direct (MS (67)) and indirect (MS (23), (38), (44)) under the three thermostats",
    run: table1,
};

/// `(direct, indirect)` mu4 of one thermostat.
type Pair = (f64, f64);

/// `(alpha, mu4^(0), [white noise, Gaussian, constant force])`.
const PAPER: [(f64, f64, [Pair; 3]); 4] = [
    (
        0.2,
        10.925,
        [(12.157, 12.155), (13.881, 13.881), (8.744, 8.750)],
    ),
    (
        0.4,
        9.812,
        [(10.602, 10.600), (11.494, 11.488), (7.631, 7.631)],
    ),
    (0.6, 7.797, [(8.036, 8.038), (8.213, 8.217), (5.811, 5.810)]),
    (0.8, 4.638, [(4.499, 4.503), (4.414, 4.412), (3.335, 3.333)]),
];

/// MS's stated precision: their two routes to mu4 agree within 0.1% (MS Section 4).
const MS_PRECISION: f64 = 1e-3;

/// Why MS's Gaussian-thermostat figures at alpha = 0.8 are in doubt.
const GAUSSIAN_08: &str = "MS's 4.414 / 4.412 imply mu2 = 0.895 with a2 = -0.013; we find \
    mu2 = 0.8999 +- 0.0007 and a2 = -0.0141 +- 0.0007 (n = 16384, 8 ensembles) from three \
    independent routes: the no-splitting scheme, MS's own time-stepped scheme, and the \
    homogeneous cooling state stored rescaled (MS Section 2.2: the same reduced state). \
    The first-Sonine value mu2^(0) (1 + 3 a2 / 16) = 0.9000 agrees with ours; MS's value \
    would need a2 = -0.045. At alpha = 0.8 the thermostat's relaxation is the slowest of \
    the table (T still rises by 1% between t = 20 and 30), so an average begun early \
    would be low. Our mu4 lies about 0.5% above MS's.";

fn table1(o: &Options, seed: u64) -> Result<Table, Error> {
    let (n, m, pairs) = if o.quick {
        (4096, 16, 20_000)
    } else {
        (16384, 32, 100_000)
    };
    let mut rows = Vec::new();
    for (k, &(alpha, mu40, cells)) in PAPER.iter().enumerate() {
        let mut out = vec![
            Cell::within("mu4^(0) MS (29)", mu40, (mu4_maxwellian(alpha), 0.0), 0.0).rounding(5e-4),
        ];
        let mut secs = 0.0;
        for (j, (scene_name, route, (direct, indirect))) in [
            ("ms-white-noise", "(23)", cells[0]),
            ("ms-gaussian", "(38)", cells[1]),
            ("ms-constant-force", "(44)", cells[2]),
        ]
        .into_iter()
        .enumerate()
        {
            let set = [
                format!("collisions.restitution={alpha}"),
                format!("observe.collisional_pairs={pairs}"),
            ];
            let s = scene(scene_name, &set, n, m, seed + 10 * k as u64 + j as u64);
            let (st, t) = go(&s, o)?;
            secs += t;
            let (mu2, c2) = steady(&st, "mu2");
            let mu4 = steady(&st, "mu4");
            // The indirect routes, with half-widths propagated to first order (the sum of
            // the terms' half-widths: an upper bound whatever their correlation).
            let ind = match route {
                "(23)" => (5.0 * mu2, 5.0 * c2),
                "(38)" => {
                    let (a2, ca) = steady(&st, "a2");
                    (5.0 * (1.0 + a2) * mu2, 5.0 * (c2 * (1.0 + a2) + mu2 * ca))
                }
                _ => {
                    let (c1, cc1) = steady(&st, "c1");
                    let (c3, cc3) = steady(&st, "c3");
                    let v = 2.0 * mu2 * c3 / c1;
                    (v, v * (c2 / mu2 + cc3 / c3 + cc1 / c1))
                }
            };
            let short = scene_name.trim_start_matches("ms-");
            // MS publish no confidence; their direct and indirect routes "disagree less than
            // 0.1% in all the cases" (MS Section 4), which is the precision they claim.
            let mut d = Cell::within(&format!("mu4 {short}"), direct, mu4, MS_PRECISION * direct)
                .rounding(5e-4);
            let mut i = Cell::within(
                &format!("MS {route} {short}"),
                indirect,
                ind,
                MS_PRECISION * indirect,
            )
            .rounding(5e-4);
            if route == "(38)" && alpha == 0.8 {
                d = d.disputed(GAUSSIAN_08);
                i = i.disputed(GAUSSIAN_08);
            }
            out.push(d);
            out.push(i);
        }
        rows.push(Row {
            label: format!("alpha = {alpha}"),
            n,
            ensembles: m,
            seconds: secs,
            cells: out,
        });
    }
    Ok(Table {
        name: "ms-table1",
        title: TABLE1.title,
        notes: format!(
            "Steady state t in [20, 100] averaged per ensemble, then over {m} ensembles of n = \
             {n} (MS: N = 2e5 particles, 1e7 pairs, 1e3 samples). MS publish no confidence; the \
             paper's half-width is taken as 0.1% of the figure, the agreement MS state for \
             their direct and indirect routes (Section 4), plus the rounding 5e-4. At full \
             size our direct mu4 under the constant force (time-stepped scheme, step 0.01 mean \
             free times, an Euler-like bias of about 0.05%) lies 0.1-0.17% below MS's at \
             alpha = 0.6 and 0.8, beyond our own half-width alone. mu4 direct: \
             {pairs} random pairs per observation (MS (67)); indirect: 5 mu2 (23), 5 (1 + a2) \
             mu2 (38), 2 mu2 <c^3>/<c> (44), half-widths propagated to first order. mu4^(0): \
             the closed form MS (29)."
        ),
        rows,
        skipped: vec![],
    })
}
