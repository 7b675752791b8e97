//! The cooling state of rough hard spheres (uniform spheres, kappa = 2/5) against the
//! tangential restitution beta at alpha = 0.9 and 0.7: `theta = T_rot/T_tr` and the reduced
//! cooling rate `zeta* = zeta / sqrt(T_tr)` simulated by gdsmc (`scenes/rough-hcs.toml` on a
//! geometric time grid), beside the Maxwellian approximation of Huthmann and Zippelius 1997
//! (`reference/rough.rs`), with the deviations. Writes `rough-hcs.csv`, `rough-hcs-theta.svg`
//! and `rough-hcs-zeta.svg` into the directory given (default `docs`) and prints the markdown
//! table of docs/rough.md.
//!
//! Each run follows the gas for about 300 collisions per particle (the time grid is uniform in
//! `ln(1 + t/t0)`, Haff's law's natural clock, with `t0` from the approximation) and averages
//! over the second half (150 collisions per particle after at least 150 of relaxation).
//! `zeta*` is twice the slope of `<T_tr>^(-1/2)` over that window (Haff: `T^(-1/2)` is linear
//! in t with slope `zeta*/2` in the cooling state); its half-width is the sum of the two
//! ends' (a bound whatever their correlation).
//!
//! With a second argument `disks` the same for rough hard disks (`d = 2`, uniform disks,
//! kappa = 1/2, `scenes/rough-disks-hcs.toml`, the approximation for disks), writing
//! `rough-disks-hcs.*`.
//!
//! ```sh
//! cargo run --release -p gdsmc --example rough_cooling -- docs
//! cargo run --release -p gdsmc --example rough_cooling -- docs disks
//! ```

use gdsmc_runner::reference::rough::RoughApproximation;
use gdsmc_runner::report::charts::{Series, Style, profile};
use gdsmc_runner::run::columns::name;
use gdsmc_runner::scene::{self, Override};
use plotters::style::{BLUE, RED};
use std::fmt::Write;
use std::path::Path;

const BETAS: [f64; 9] = [-0.75, -0.5, -0.25, 0.0, 0.25, 0.5, 0.75, 0.9, 1.0];
const ALPHAS: [f64; 2] = [0.9, 0.7];
const N: usize = 2048;
const ENSEMBLES: u64 = 40;
/// gamma C of the scene (gamma = 4, C = 1/(4 pi)).
const STRENGTH: f64 = 1.0 / std::f64::consts::PI;
/// Collisions per particle over the whole run.
const COLLISIONS: f64 = 300.0;
const POINTS: usize = 60;

/// The particles: dimension, reduced moment of inertia, scene and output name, chart title.
struct Shape {
    d: usize,
    kappa: f64,
    name: &'static str,
    title: &'static str,
}

const SPHERES: Shape = Shape {
    d: 3,
    kappa: 0.4,
    name: "rough-hcs",
    title: "Rough hard spheres (kappa = 2/5)",
};

const DISKS: Shape = Shape {
    d: 2,
    kappa: 0.5,
    name: "rough-disks-hcs",
    title: "Rough hard disks (kappa = 1/2)",
};

fn approximation(shape: &Shape, alpha: f64, beta: f64) -> RoughApproximation {
    RoughApproximation::in_dimension(shape.d, alpha, beta, shape.kappa, STRENGTH, 1.0, [0.0; 2])
}

/// `E |g|` at `T_tr = 1` in `d` dimensions: `2 Gamma((d + 1)/2) / Gamma(d/2)`.
fn mean_relative_speed(d: usize) -> f64 {
    let d = d as f64;
    2.0 * libm::tgamma((d + 1.0) / 2.0) / libm::tgamma(d / 2.0)
}

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let out = std::env::args().nth(1).unwrap_or_else(|| "docs".into());
    let shape = match std::env::args().nth(2).as_deref() {
        Some("disks") => DISKS,
        _ => SPHERES,
    };
    let path = Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("../scenes")
        .join(format!("{}.toml", shape.name));
    let mut csv = String::from(
        "alpha,beta,theta,theta_half_width,theta_ma,zeta_star,zeta_half_width,zeta_ma\n",
    );
    let mut table = String::from(
        "| alpha | beta | theta (gdsmc, 99.9%) | theta, MA | deviation | zeta* (gdsmc, bound) | zeta*, MA | deviation | a2 | a2_rot | theta settled |\n|---|---|---|---|---|---|---|---|---|---|---|\n",
    );
    let (mut theta_series, mut zeta_series) = (Vec::new(), Vec::new());
    let started = std::time::Instant::now();
    for (alpha, color) in ALPHAS.into_iter().zip([BLUE, RED]) {
        let (mut th_sim, mut th_ma, mut z_sim, mut z_ma) =
            (Vec::new(), Vec::new(), Vec::new(), Vec::new());
        for (k, beta) in BETAS.into_iter().enumerate() {
            let ma = approximation(&shape, alpha, beta);
            let theta_ma = ma.cooling_theta().ok_or("beta > -1 has a theta")?;
            let (zeta_ma, _) = ma.cooling_rates(1.0).ok_or("beta > -1 has rates")?;
            // Collisions per particle per unit of ln(1 + t/t0): 2 nu / zeta at T_tr = 1, with
            // nu = 4 pi gamma C E|g| (spheres: 3 / (2 (A - B theta))).
            let per_log = 2.0 * ma.rate * mean_relative_speed(shape.d) / zeta_ma;
            let span = COLLISIONS / per_log;
            let t0 = 2.0 / zeta_ma; // Haff: T = 1/(1 + t/t0)^2 from T_tr = 1
            let set = [
                Override::set(format!("collisions.restitution={alpha:?}")),
                Override::set(format!("rotation.tangential_restitution={beta:?}")),
                Override::flag("n", "particles.n", N),
                Override::flag("ensembles", "run.ensembles", ENSEMBLES),
                Override::flag("seed", "run.seed", 300 + k),
            ];
            let mut s = scene::load_with(&path, &set)?;
            let times: Vec<f64> = (0..=POINTS)
                .map(|i| t0 * ((span * i as f64 / POINTS as f64).exp() - 1.0))
                .collect();
            let from = times[POINTS / 2];
            s.set_times(times)?;
            s.set_steady_from(Some(from))?;
            let stats = gdsmc_runner::run::run(&s, 0, &|_| {})?;
            let st = stats.steady.as_ref().ok_or("no steady window")?;
            let col = |name| stats.col(name).ok_or(format!("no column {name}"));
            let (theta, th_half) = st.mean_ci(&stats, col(name::THETA)?);
            // Settled: theta's per-time means over the window's two halves agree within the
            // sum of their mean half-widths (the runner's `unsteady` check).
            let thc = col(name::THETA)?;
            let half_mean = |r: std::ops::Range<usize>| {
                let k = r.len() as f64;
                let (m, h) = r.fold((0.0, 0.0), |(m, h), i| {
                    (m + stats.mean(i, thc), h + stats.ci(i, thc))
                });
                (m / k, h / k)
            };
            let q = POINTS / 4;
            let ((ma1, ha1), (mb1, hb1)) = (
                half_mean(POINTS / 2..POINTS / 2 + q),
                half_mean(POINTS + 1 - q..POINTS + 1),
            );
            let settled = (mb1 - ma1).abs() <= ha1 + hb1;
            let (a2, a2_half) = st.mean_ci(&stats, col(name::A2)?);
            let (a2r, a2r_half) = st.mean_ci(&stats, col(name::A2_ROT)?);
            let tc = col(name::T_BULK)?;
            let (i1, i2) = (POINTS / 2, POINTS);
            let x = |i: usize| {
                let (m, c) = (stats.mean(i, tc), stats.ci(i, tc));
                (m.powf(-0.5), 0.5 * m.powf(-1.5) * c)
            };
            let ((x1, c1), (x2, c2)) = (x(i1), x(i2));
            let dt = stats.times[i2] - stats.times[i1];
            let (zeta, z_half) = (2.0 * (x2 - x1) / dt, 2.0 * (c1 + c2) / dt);
            let (dth, dz) = (theta / theta_ma - 1.0, zeta / zeta_ma - 1.0);
            let _ = writeln!(
                csv,
                "{alpha},{beta},{theta},{th_half},{theta_ma},{zeta},{z_half},{zeta_ma}"
            );
            let mark = |ok: bool| if ok { "" } else { " (outside)" };
            let _ = writeln!(
                table,
                "| {alpha} | {beta} | {theta:.4} +- {th_half:.4} | {theta_ma:.4} | {:+.1}%{} | {zeta:.4} +- {z_half:.4} | {zeta_ma:.4} | {:+.1}%{} | {a2:.3} +- {a2_half:.3} | {a2r:.3} +- {a2r_half:.3} | {} |",
                100.0 * dth,
                mark((theta - theta_ma).abs() <= th_half),
                100.0 * dz,
                mark((zeta - zeta_ma).abs() <= z_half),
                if settled {
                    "yes".to_string()
                } else {
                    format!("no: {ma1:.4} then {mb1:.4}")
                },
            );
            th_sim.push((beta, theta, th_half));
            z_sim.push((beta, zeta, z_half));
            eprintln!(
                "alpha {alpha} beta {beta}: theta {theta:.4} +- {th_half:.4} (MA {theta_ma:.4}), zeta* {zeta:.4} +- {z_half:.4} (MA {zeta_ma:.4}), a2_rot {a2r:.3}"
            );
        }
        for i in 0..=80 {
            let beta = -0.9 + 1.9 * i as f64 / 80.0;
            let ma = approximation(&shape, alpha, beta);
            if let (Some(th), Some((z, _))) = (ma.cooling_theta(), ma.cooling_rates(1.0)) {
                th_ma.push((beta, th, 0.0));
                z_ma.push((beta, z, 0.0));
            }
        }
        for (series, sim, ma) in [
            (&mut theta_series, th_sim, th_ma),
            (&mut zeta_series, z_sim, z_ma),
        ] {
            series.push(Series {
                label: format!("gdsmc, alpha = {alpha} (n = {N}, {ENSEMBLES} ensembles)"),
                points: sim,
                style: Style::Points,
                color,
            });
            series.push(Series {
                label: format!("Maxwellian approximation (Huthmann-Zippelius), alpha = {alpha}"),
                points: ma,
                style: Style::Dashed,
                color,
            });
        }
    }
    let dir = Path::new(&out);
    std::fs::create_dir_all(dir)?;
    let theta = profile(
        &format!("{}, cooling state: theta = T_rot / T_tr", shape.title),
        "tangential restitution beta",
        "temperature ratio theta = T_rot / T_tr",
        false,
        &theta_series,
    )?;
    let zeta = profile(
        &format!("{}, cooling state: zeta / sqrt(T_tr)", shape.title),
        "tangential restitution beta",
        "reduced cooling rate zeta* = zeta / sqrt(T_tr)",
        false,
        &zeta_series,
    )?;
    std::fs::write(dir.join(format!("{}.csv", shape.name)), csv)?;
    std::fs::write(dir.join(format!("{}-theta.svg", shape.name)), theta.svg)?;
    std::fs::write(dir.join(format!("{}-zeta.svg", shape.name)), zeta.svg)?;
    print!("{table}");
    eprintln!("{:.1} s", started.elapsed().as_secs_f64());
    Ok(())
}
