//! `gdsmc bench work-precision SCENE`: error against CPU time for each scheme over a ladder of
//! its parameters (RW Section 4.2: no splitting, Strang and Euler splitting).
//!
//! For a steady-state scene with an exact stationary temperature (the Maxwell gas, RW (25)),
//! every configuration runs `R` independent steady-state runs (each one ensemble, as RW) and
//! averages the temperature about the bulk velocity, `T_bulk` (RW's raw temperature carries an
//! extra `(T0 + 2 beta t)/n` from the random walk of the momentum, the same for every scheme;
//! `T_bulk`'s finite-n bias is only `-T/n`). Its
//! error is the 99.9% bound of the error one run makes, `|mean - T_inf| + 3.2 sd`, relative
//! to `T_inf`, with `mean` and `sd` over the R runs (the first term is the scheme's systematic
//! error, the second the noise of one run); its cost is the CPU time of one run. The cost of a
//! 1% error on each curve is read off by log-log interpolation, and the ratios to the
//! no-splitting scheme are RW's efficiency comparison (RW: Euler about 100, Strang about 2).

use crate::error::Error;
use crate::files::write_own;
use crate::report::charts::{Series, Style, profile};
use crate::run;
use crate::run::columns::name;
use crate::scene::{Scene, SchemeChoice};
use gdsmc_stats::LAMBDA_999;
use gdsmc_theory::curves::maxwell_temperature;
use plotters::style::{BLUE, GREEN, RED};
use std::path::Path;

/// One configuration: scheme, size, time step.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Config {
    /// Scheme name (`no-splitting`, `strang`, `euler`).
    pub scheme: &'static str,
    /// Particles.
    pub n: usize,
    /// Time step (0 for no splitting).
    pub dt: f64,
}

/// The measured point of a configuration.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Point {
    /// The configuration.
    pub config: Config,
    /// Runs.
    pub runs: u64,
    /// CPU seconds per run.
    pub cpu: f64,
    /// Mean of the runs' steady temperature `T_bulk` and its 99.9% half-width.
    pub mean: (f64, f64),
    /// Standard deviation of one run's steady temperature.
    pub sd: f64,
    /// The exact expected value of the estimator (finite n, time step), reference.rs.
    pub exact_mean: f64,
    /// Relative error bound of one run: `(|mean - T_inf| + 3.2 sd) / T_inf`.
    pub error: f64,
}

/// The default ladder for RW's steady state (RW Tables 3-5; `K = 8 / dt`): no splitting over
/// `n`, each splitting over `n` and `K` (its cheapest way to an error is read off the lower
/// envelope of its points).
pub fn default_ladder(quick: bool) -> Vec<Config> {
    let (ns, ns_split, ks_strang, ks_euler): (&[usize], &[usize], &[u32], &[u32]) = if quick {
        (
            &[256, 1024, 4096],
            &[1024, 4096],
            &[4, 8, 16],
            &[32, 128, 512],
        )
    } else {
        (
            &[256, 1024, 4096, 16384, 65536],
            &[4096, 16384, 65536],
            &[8, 16, 32, 64],
            &[32, 256, 512, 2048],
        )
    };
    let mut v: Vec<Config> = ns
        .iter()
        .map(|&n| Config {
            scheme: "no-splitting",
            n,
            dt: 0.0,
        })
        .collect();
    for (scheme, ks) in [("strang", ks_strang), ("euler", ks_euler)] {
        for &n in ns_split {
            for &k in ks {
                v.push(Config {
                    scheme,
                    n,
                    dt: 8.0 / k as f64,
                });
            }
        }
    }
    v
}

/// The lower envelope of a scheme's points: ordered by cost, each point that has a smaller
/// error than every cheaper one (the cheapest way to each error the ladder offers).
pub fn front(points: &[Point], scheme: &str) -> Vec<Point> {
    let mut v: Vec<Point> = points
        .iter()
        .filter(|p| p.config.scheme == scheme)
        .copied()
        .collect();
    v.sort_by(|a, b| a.cpu.total_cmp(&b.cpu));
    let mut out: Vec<Point> = Vec::new();
    for p in v {
        if out.last().is_none_or(|q| p.error < q.error) {
            out.push(p);
        }
    }
    out
}

/// Measures every configuration with `runs` runs each; `done` is called after each.
pub fn measure(
    base: &Scene,
    ladder: &[Config],
    runs: u64,
    threads: usize,
    mut done: impl FnMut(&Point),
) -> Result<Vec<Point>, Error> {
    let mt = maxwell_temperature(base).ok_or_else(|| Error::Argument {
        flag: format!("work-precision {}", base.name()),
        message: "needs a Maxwell-kernel scene with an exact stationary temperature (white noise)"
            .into(),
    })?;
    let Some(first) = base.steady_from() else {
        return Err(Error::Argument {
            flag: format!("work-precision {}: observe.steady_from", base.name()),
            message: "must be set: the error is that of the steady-state average".into(),
        });
    };
    let t_inf = mt.stationary();
    let mut out = Vec::new();
    for (k, c) in ladder.iter().enumerate() {
        let mut s = base.clone();
        s.set_n(c.n)?;
        s.set_ensembles(runs)?;
        s.set_seed(base.seed().wrapping_add(k as u64));
        let scheme = match c.scheme {
            "strang" => SchemeChoice::Strang(c.dt),
            "euler" => SchemeChoice::Euler(c.dt),
            _ => SchemeChoice::NoSplitting,
        };
        s.with_physics(|ph| ph.scheme = scheme)?;
        let st = run::run(&s, threads, &|_| {})?;
        let steady = st.steady.as_ref().expect("steady_from set");
        let col = st.col(name::T_BULK).expect("the temperature column");
        let mean = (steady.acc.mean(col), steady.acc.ci(col));
        let sd = steady.acc.variance(col).sqrt();
        let pts = &s.times()[first..];
        let exact_mean = pts
            .iter()
            .map(|&t| match s.physics().scheme {
                SchemeChoice::Strang(dt) => mt.splitting_bulk_mean(c.n, dt, true, t),
                SchemeChoice::Euler(dt) => mt.splitting_bulk_mean(c.n, dt, false, t),
                _ => mt.finite_n_bulk_mean(c.n, t),
            })
            .sum::<f64>()
            / pts.len() as f64;
        let p = Point {
            config: *c,
            runs,
            cpu: st.cpu.as_secs_f64() / runs as f64,
            mean,
            sd,
            exact_mean,
            error: ((mean.0 - t_inf).abs() + LAMBDA_999 * sd) / t_inf,
        };
        done(&p);
        out.push(p);
    }
    Ok(out)
}

/// The CPU cost at which a scheme's lower envelope ([`front`]) reaches `target` relative
/// error: log-log interpolation between the first envelope point at or below the target and
/// the one before it; `None` when no point reaches it.
pub fn cost_at(points: &[Point], scheme: &str, target: f64) -> Option<f64> {
    let v = front(points, scheme);
    let i = v.iter().position(|p| p.error <= target)?;
    if i == 0 {
        return Some(v[0].cpu);
    }
    let (a, b) = (v[i - 1], v[i]);
    let f = (libm::log(target) - libm::log(a.error)) / (libm::log(b.error) - libm::log(a.error));
    Some(libm::exp(
        libm::log(a.cpu) + f * (libm::log(b.cpu) - libm::log(a.cpu)),
    ))
}

/// The CSV of the points.
pub fn csv(points: &[Point]) -> Result<Vec<u8>, csv::Error> {
    let mut w = csv::Writer::from_writer(Vec::new());
    w.write_record([
        "scheme",
        "n",
        "dt",
        "K",
        "runs",
        "cpu_s_per_run",
        "T_mean",
        "T_mean_ci",
        "T_sd_one_run",
        "T_exact_mean",
        "error_bound",
    ])?;
    for p in points {
        let k = if p.config.dt > 0.0 {
            format!("{}", (8.0 / p.config.dt).round())
        } else {
            String::new()
        };
        w.write_record([
            p.config.scheme.to_string(),
            p.config.n.to_string(),
            format!("{:?}", p.config.dt),
            k,
            p.runs.to_string(),
            format!("{:?}", p.cpu),
            format!("{:?}", p.mean.0),
            format!("{:?}", p.mean.1),
            format!("{:?}", p.sd),
            format!("{:?}", p.exact_mean),
            format!("{:?}", p.error),
        ])?;
    }
    w.into_inner().map_err(|e| e.into_error().into())
}

/// The chart: error bound against CPU seconds per run, both on log scales (the x axis as
/// log10): every configuration as a point, each scheme's lower envelope as a line.
pub fn chart(title: &str, points: &[Point]) -> Result<String, String> {
    let mut series = Vec::new();
    for (scheme, color) in [("no-splitting", BLUE), ("strang", GREEN), ("euler", RED)] {
        let pts = |v: &[Point]| -> Vec<(f64, f64, f64)> {
            v.iter()
                .filter(|p| p.cpu > 0.0)
                .map(|p| (libm::log10(p.cpu), p.error, 0.0))
                .collect()
        };
        let all: Vec<Point> = points
            .iter()
            .filter(|p| p.config.scheme == scheme)
            .copied()
            .collect();
        series.push(Series {
            label: format!("{scheme}: lower envelope"),
            points: pts(&front(points, scheme)),
            style: Style::Line,
            color,
        });
        series.push(Series {
            label: format!("{scheme}: configurations"),
            points: pts(&all),
            style: Style::Points,
            color,
        });
    }
    profile(
        title,
        "log10 CPU seconds per run",
        "relative error of one run (99.9% bound)",
        true,
        &series,
    )
    .map(|c| c.svg)
}

/// The schemes compared, no splitting first (the base of the ratios).
const SCHEMES: [&str; 3] = ["no-splitting", "strang", "euler"];

/// The smallest relative error every scheme of the ladder reached (the largest of the
/// schemes' smallest errors), rounded up to two significant digits: the error at which all
/// costs can be compared. `None` when a scheme has no point.
pub fn reachable_target(points: &[Point]) -> Option<f64> {
    let mut worst: f64 = 0.0;
    for scheme in SCHEMES {
        worst = worst.max(best_error(points, scheme)?);
    }
    let unit = libm::pow(10f64, libm::log10(worst).floor() - 1.0);
    Some((worst / unit).ceil() * unit)
}

/// The smallest error a scheme reached in the ladder.
fn best_error(points: &[Point], scheme: &str) -> Option<f64> {
    points
        .iter()
        .filter(|p| p.config.scheme == scheme)
        .map(|p| p.error)
        .reduce(f64::min)
}

/// Writes work_precision.csv and work_precision.svg into `dir`; returns the summary text.
pub fn write(dir: &Path, scene: &str, points: &[Point], target: f64) -> Result<String, Error> {
    std::fs::create_dir_all(dir).map_err(|source| Error::Write {
        path: dir.to_path_buf(),
        source,
    })?;
    let path = dir.join("work_precision.csv");
    let bytes = csv(points).map_err(|e| Error::Write {
        path: path.clone(),
        source: std::io::Error::other(e.to_string()),
    })?;
    // Into a place the user may have chosen: only files of gdsmc's are replaced.
    write_own(&path, &bytes, "scheme,n,dt,K,runs,cpu_s_per_run")?;
    match chart(&format!("{scene}: work against precision (RW 4.2)"), points) {
        Ok(svg) => write_own(
            &dir.join("work_precision.svg"),
            svg.as_bytes(),
            "work against precision (RW 4.2)",
        )?,
        Err(e) => eprintln!("work_precision.svg: not drawn ({e})"),
    }
    let mut s = String::new();
    let base = cost_at(points, "no-splitting", target);
    for scheme in SCHEMES {
        let c = cost_at(points, scheme, target);
        let ratio = match (c, base) {
            (Some(c), Some(b)) => format!("{:.1}", c / b),
            _ => "-".into(),
        };
        s.push_str(&format!(
            "{scheme:<13} CPU per run at {}% error: {:>12}   ratio to no splitting: {ratio}\n",
            100.0 * target,
            c.map_or_else(
                || match best_error(points, scheme) {
                    Some(b) => format!(
                        "not reached (smallest error in the ladder {:.2}%)",
                        100.0 * b
                    ),
                    None => "not run".into(),
                },
                |c| format!("{c:.3e} s")
            )
        ));
    }
    Ok(s)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn pt(scheme: &'static str, cpu: f64, error: f64) -> Point {
        Point {
            config: Config {
                scheme,
                n: 1,
                dt: 0.0,
            },
            runs: 1,
            cpu,
            mean: (0.0, 0.0),
            sd: 0.0,
            exact_mean: 0.0,
            error,
        }
    }

    #[test]
    fn the_reachable_target_is_reached_by_every_scheme() {
        let p = |scheme, error| Point {
            config: Config {
                scheme,
                n: 64,
                dt: 0.0,
            },
            runs: 1,
            cpu: 1.0,
            mean: (1.0, 0.0),
            sd: 0.0,
            exact_mean: 1.0,
            error,
        };
        let pts = [
            p("no-splitting", 0.004),
            p("no-splitting", 0.02),
            p("strang", 0.0123),
            p("euler", 0.031),
            p("euler", 0.0456),
        ];
        // Euler's smallest error, 0.031, rounded up to two digits.
        let t = reachable_target(&pts).unwrap();
        assert!((t - 0.031).abs() < 1e-12, "{t}");
        for s in SCHEMES {
            assert!(cost_at(&pts, s, t).is_some(), "{s} does not reach {t}");
        }
        assert_eq!(reachable_target(&pts[..3]), None);
    }

    #[test]
    fn envelope_and_cost_at_a_target() {
        let pts = [
            pt("euler", 1.0, 0.1),
            pt("euler", 2.0, 0.2), // dearer and worse: not on the envelope
            pt("euler", 10.0, 0.001),
            pt("no-splitting", 0.5, 0.005),
        ];
        let f = front(&pts, "euler");
        assert_eq!(f.len(), 2);
        // log-log between (1, 0.1) and (10, 0.001): error 0.01 at cpu sqrt(10).
        let c = cost_at(&pts, "euler", 0.01).unwrap();
        assert!((c - 10f64.sqrt()).abs() < 1e-12, "{c}");
        assert_eq!(cost_at(&pts, "no-splitting", 0.01), Some(0.5));
        assert_eq!(cost_at(&pts, "strang", 0.01), None);
        assert_eq!(cost_at(&pts, "euler", 1e-4), None);
    }
}
