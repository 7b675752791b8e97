//! The cooling state of binary rough hard-sphere mixtures (equal sizes and mole fractions,
//! uniform spheres `kappa = 2/5`, alpha = 0.9 and one tangential restitution beta for every
//! pair): the temperature ratio `T_0/T_1` and each species' `theta_s = T_rot,s / T_s` against
//! the mass ratio `m_0/m_1` and beta, simulated by gdsmc (the steady-window averages of
//! `scenes/rough-mixture-hcs.toml`, run to t = 1e7 and averaged over t >= 5e6) beside the Maxwellian approximation (Santos, Kremer and
//! Garzó 2010; `reference::rough_mixture`), with the deviations. Writes `rough-mixture-hcs.csv`
//! and `rough-mixture-hcs-theta.svg` into the directory given (default `docs`) and prints the
//! markdown table of docs/rough.md.
//!
//! ```sh
//! cargo run --release -p gdsmc --example rough_mixture_cooling -- docs
//! ```

use gdsmc_runner::reference::curves::rough_mixture_approximation;
use gdsmc_runner::report::charts::{Series, Style, profile};
use gdsmc_runner::scene::{self, Override};
use plotters::style::{BLUE, GREEN, RED};
use std::fmt::Write;
use std::path::Path;

const MASS_RATIOS: [f64; 4] = [1.0, 2.0, 4.0, 8.0];
const BETAS: [f64; 3] = [-0.5, 0.0, 0.5];
const N: usize = 4000;
const ENSEMBLES: u64 = 40;

/// A simulated value with its half-width, the approximation's, and the cell of the table.
fn cell(sim: (f64, f64), ma: f64) -> String {
    let dev = sim.0 / ma - 1.0;
    format!(
        "{:.4} +- {:.4} | {ma:.4} | {:+.1}%{}",
        sim.0,
        sim.1,
        100.0 * dev,
        if (sim.0 - ma).abs() <= sim.1 {
            ""
        } else {
            " (outside)"
        }
    )
}

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let out = std::env::args().nth(1).unwrap_or_else(|| "docs".into());
    let path = Path::new(env!("CARGO_MANIFEST_DIR")).join("../scenes/rough-mixture-hcs.toml");
    let mut csv = String::from(
        "beta,mass_ratio,T0_over_T1,half_width,T0_over_T1_MA,theta0,theta0_half_width,theta0_MA,theta1,theta1_half_width,theta1_MA\n",
    );
    let mut table = String::from(
        "| beta | m_0/m_1 | T_0/T_1 (gdsmc, 99.9%) | MA | deviation | theta_0 (gdsmc) | MA | deviation | theta_1 (gdsmc) | MA | deviation |\n|---|---|---|---|---|---|---|---|---|---|---|\n",
    );
    let mut series = Vec::new();
    let started = std::time::Instant::now();
    for (b, (beta, color)) in BETAS.into_iter().zip([BLUE, GREEN, RED]).enumerate() {
        let (mut sim0, mut sim1, mut ma0, mut ma1) =
            (Vec::new(), Vec::new(), Vec::new(), Vec::new());
        for (k, mu) in MASS_RATIOS.into_iter().enumerate() {
            let set = [
                Override::set(format!("species[0].mass={mu:?}")),
                Override::set(format!("rotation.tangential_restitution={beta:?}")),
                Override::flag("n", "particles.n", N),
                Override::flag("ensembles", "run.ensembles", ENSEMBLES),
                Override::flag("seed", "run.seed", 200 + 10 * b + k),
                // The heavy species' rotation relaxes slowly when beta is near -1 (at -0.5
                // and m_0/m_1 = 4, theta_0 is 2.70 at t = 250, 3.16 at 2000 and 3.52 from
                // 2e6 to 1e7, flat): a late window (the cooling gas is rescaled in storage).
                Override::set("observe.t_end=10000000.0"),
                Override::set("observe.steady_from=5000000.0"),
            ];
            let s = scene::load_with(&path, &set)?;
            let ma = rough_mixture_approximation(&s).ok_or("not a rough mixture")?;
            let (ratios, theta) = ma.steady().ok_or("the approximation did not converge")?;
            let stats = gdsmc_runner::run::run(&s, 0, &|_| {})?;
            let st = stats
                .steady
                .as_ref()
                .ok_or("the scene has no steady window")?;
            let get = |name: &str| -> Result<(f64, f64), String> {
                let col = stats.col(name).ok_or(format!("no {name} column"))?;
                Ok(st.mean_ci(&stats, col))
            };
            // Equal mole fractions: T_mix = (T_0 + T_1)/2, so T_0/T_1 = r / (2 - r), whose
            // half-width follows from r's (derivative 2/(2 - r)^2).
            let (r, hw) = get("T_s0_ratio")?;
            let ratio = (r / (2.0 - r), hw * 2.0 / ((2.0 - r) * (2.0 - r)));
            let ratio_ma = ratios[0] / ratios[1];
            let (t0, t1) = (get("theta_s0")?, get("theta_s1")?);
            let _ = writeln!(
                csv,
                "{beta},{mu},{},{},{ratio_ma},{},{},{},{},{},{}",
                ratio.0, ratio.1, t0.0, t0.1, theta[0], t1.0, t1.1, theta[1]
            );
            let _ = writeln!(
                table,
                "| {beta} | {mu} | {} | {} | {} |",
                cell(ratio, ratio_ma),
                cell(t0, theta[0]),
                cell(t1, theta[1])
            );
            sim0.push((mu.log10(), t0.0, t0.1));
            sim1.push((mu.log10(), t1.0, t1.1));
            eprintln!(
                "beta {beta} m0/m1 {mu}: T0/T1 {:.4} (MA {ratio_ma:.4}), theta {:.4} {:.4} (MA {:.4} {:.4})",
                ratio.0, t0.0, t1.0, theta[0], theta[1]
            );
        }
        // The approximation on a fine grid.
        for i in 0..=40 {
            let mu = 10f64.powf(1.0 * i as f64 / 40.0 * 0.95);
            let set = [
                Override::set(format!("species[0].mass={mu:?}")),
                Override::set(format!("rotation.tangential_restitution={beta:?}")),
            ];
            let s = scene::load_with(&path, &set)?;
            let ma = rough_mixture_approximation(&s).ok_or("not a rough mixture")?;
            let (_, theta) = ma.steady().ok_or("the approximation did not converge")?;
            ma0.push((mu.log10(), theta[0], 0.0));
            ma1.push((mu.log10(), theta[1], 0.0));
        }
        for (who, sim, ma, style) in [
            ("heavy theta_0", sim0, ma0, Style::Dashed),
            ("light theta_1", sim1, ma1, Style::Line),
        ] {
            series.push(Series {
                label: format!(
                    "gdsmc {who}, beta = {beta} (n = {N}, {ENSEMBLES} ensembles, 99.9%)"
                ),
                points: sim,
                style: Style::Points,
                color,
            });
            series.push(Series {
                label: format!("Maxwellian approximation {who}, beta = {beta}"),
                points: ma,
                style,
                color,
            });
        }
    }
    let chart = profile(
        "Binary rough hard-sphere mixture, cooling state (alpha = 0.9, kappa = 2/5): theta_s",
        "mass ratio log10 m_0/m_1",
        "temperature ratio theta_s = T_rot,s / T_s",
        false,
        &series,
    )?;
    let dir = Path::new(&out);
    std::fs::create_dir_all(dir)?;
    std::fs::write(dir.join("rough-mixture-hcs.csv"), csv)?;
    std::fs::write(dir.join("rough-mixture-hcs-theta.svg"), chart.svg)?;
    print!("{table}");
    eprintln!("{:.1} s", started.elapsed().as_secs_f64());
    Ok(())
}
