//! The cooling state of binary hard-sphere mixtures (equal sizes and mole fractions, one
//! restitution coefficient for every pair): the temperature ratio `T_0/T_1` against the mass
//! ratio `m_0/m_1` at alpha = 0.9 and 0.8, simulated by gdsmc (the steady-window average of
//! `T_s0_ratio` of `scenes/mixture-hcs-hard-spheres.toml`) beside Garzó and Dufty 1999's
//! Maxwellian approximation, with the deviations. Writes `mixtures-hcs.csv` and
//! `mixtures-hcs.svg` into the directory given (default `docs`) and prints the markdown table
//! of docs/mixtures.md.
//!
//! ```sh
//! cargo run --release -p gdsmc --example mixture_cooling -- docs
//! ```

use gdsmc_runner::reference::mixture::MaxwellianApproximation;
use gdsmc_runner::report::charts::{Series, Style, profile};
use gdsmc_runner::scene::{self, Override};
use plotters::style::{BLUE, RED};
use std::fmt::Write;
use std::path::Path;

const MASS_RATIOS: [f64; 8] = [0.5, 1.0, 2.0, 3.0, 4.0, 6.0, 8.0, 10.0];
const ALPHAS: [f64; 2] = [0.9, 0.8];
const N: usize = 4000;
const ENSEMBLES: u64 = 40;

/// `T_0/T_1` of the Maxwellian approximation: equal sizes and fractions, masses `mu` and 1.
fn approximation(mu: f64, alpha: f64) -> f64 {
    let r = MaxwellianApproximation {
        fractions: vec![0.5, 0.5],
        masses: vec![mu, 1.0],
        kappa: vec![1.0; 3],
        alpha: vec![alpha; 3],
        lambda: 1.0,
        beta: vec![0.0, 0.0],
    }
    .steady_ratios()
    .expect("the approximation converges");
    r[0] / r[1]
}

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let out = std::env::args().nth(1).unwrap_or_else(|| "docs".into());
    let path =
        Path::new(env!("CARGO_MANIFEST_DIR")).join("../scenes/mixture-hcs-hard-spheres.toml");
    let mut csv =
        String::from("alpha,mass_ratio,T0_over_T1,half_width,maxwellian_approximation,deviation\n");
    let mut table = String::from(
        "| alpha | m_0/m_1 | T_0/T_1 (gdsmc, 99.9%) | Maxwellian approximation | deviation | within the interval |\n|---|---|---|---|---|---|\n",
    );
    let mut series = Vec::new();
    let started = std::time::Instant::now();
    for (alpha, color) in ALPHAS.into_iter().zip([BLUE, RED]) {
        let (mut sim, mut ma) = (Vec::new(), Vec::new());
        for (k, mu) in MASS_RATIOS.into_iter().enumerate() {
            let set = [
                Override::set(format!("species[0].mass={mu:?}")),
                Override::set(format!("collisions.restitution={alpha:?}")),
                Override::flag("n", "particles.n", N),
                Override::flag("ensembles", "run.ensembles", ENSEMBLES),
                Override::flag("seed", "run.seed", 100 + k),
            ];
            let s = scene::load_with(&path, &set)?;
            let stats = gdsmc_runner::run::run(&s, 0, &|_| {})?;
            let st = stats
                .steady
                .as_ref()
                .ok_or("the scene has no steady window")?;
            let col = stats.col("T_s0_ratio").ok_or("no T_s0_ratio column")?;
            // Equal mole fractions: T_mix = (T_0 + T_1)/2, so T_1/T_mix = 2 - r and
            // T_0/T_1 = r / (2 - r), whose half-width follows from r's (derivative 2/(2-r)^2).
            let (r, hw) = st.mean_ci(&stats, col);
            let (ratio, half) = (r / (2.0 - r), hw * 2.0 / ((2.0 - r) * (2.0 - r)));
            let reference = approximation(mu, alpha);
            let dev = ratio / reference - 1.0;
            let _ = writeln!(csv, "{alpha},{mu},{ratio},{half},{reference},{dev}");
            let _ = writeln!(
                table,
                "| {alpha} | {mu} | {ratio:.4} +- {half:.4} | {reference:.4} | {:+.2}% | {} |",
                100.0 * dev,
                if (ratio - reference).abs() <= half {
                    "yes"
                } else {
                    "no"
                }
            );
            sim.push((mu.log10(), ratio, half));
            eprintln!("alpha {alpha} m0/m1 {mu}: {ratio:.4} +- {half:.4}, MA {reference:.4}");
        }
        // The approximation on a fine grid.
        for i in 0..=60 {
            let mu = 10f64.powf(-0.35 + 1.4 * i as f64 / 60.0);
            ma.push((mu.log10(), approximation(mu, alpha), 0.0));
        }
        series.push(Series {
            label: format!("gdsmc, alpha = {alpha} (n = {N}, {ENSEMBLES} ensembles, 99.9%)"),
            points: sim,
            style: Style::Points,
            color,
        });
        series.push(Series {
            label: format!("Maxwellian approximation (Garzó-Dufty 1999), alpha = {alpha}"),
            points: ma,
            style: Style::Dashed,
            color,
        });
    }
    let chart = profile(
        "Binary hard-sphere mixture, cooling state: T_0/T_1",
        "mass ratio log10 m_0/m_1",
        "temperature ratio T_0 / T_1",
        false,
        &series,
    )?;
    let dir = Path::new(&out);
    std::fs::create_dir_all(dir)?;
    std::fs::write(dir.join("mixtures-hcs.csv"), csv)?;
    std::fs::write(dir.join("mixtures-hcs.svg"), chart.svg)?;
    print!("{table}");
    eprintln!("{:.1} s", started.elapsed().as_secs_f64());
    Ok(())
}
