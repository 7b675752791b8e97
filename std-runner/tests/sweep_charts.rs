//! A sweep's charts (`gdsmc_runner::sweep::chart`): readable by the chart review's rules, the
//! shipped scenes' sweep tables included.

use super::sweep::root;
use gdsmc_runner::scene::{Override, Sourced};
use gdsmc_runner::sweep::Sweep;
use gdsmc_runner::sweep::vary::{Combine, Vary};
use std::path::PathBuf;

/// A sweep of `source` over `vary` for the chart tests (all cores, no work limit).
fn chart_sweep(source: Sourced, vary: Vec<Vary>, combine: Combine, out: PathBuf) -> Sweep {
    Sweep {
        source,
        vary,
        combine,
        threads: 0,
        allow_long: true,
        out: Some(out),
        fresh: false,
        format: "svg".parse().unwrap(),
        shard: None,
    }
}

/// Every point of `s` run in memory and the sweep's charts drawn from them.
fn charts_of(s: &Sweep) -> Vec<(String, Result<gdsmc_runner::report::charts::Chart, String>)> {
    let points = s.points().unwrap();
    let results: Vec<_> = points
        .iter()
        .map(|p| {
            let st = gdsmc_runner::run::run(&p.source.scene, 0, &|_| {}).unwrap();
            gdsmc_runner::sweep::point::PointResult::of(p, &st)
        })
        .collect();
    gdsmc_runner::sweep::chart::charts(&s.source, &s.vary, &points, &results)
}

/// Every chart of three small sweeps (a cooling state's a2 against alpha beside its Sonine
/// approximation; a grid of the heated Maxwell gas over beta on a logarithmic range and alpha,
/// each alpha a series with its exact temperature; a rough gas over the tangential
/// restitution) passes the run charts' review (`Geometry::objections`: legend off the data,
/// every point and bar end inside a plot, lines told apart) and its title names the physics
/// (not the file), n and the ensembles per point, and not the varied values.
#[test]
fn the_charts_of_a_sweep_are_readable() {
    let r = root("charts");
    let scenes = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../scenes");
    let cases: [(&str, &[&str], &[&str]); 3] = [
        (
            "hcs-hard-spheres.toml",
            &["collisions.restitution=0.5,0.7,0.9"],
            &["observe.steady_from=20"],
        ),
        (
            "grw-example3.toml",
            &["drive.beta=log:0.5:2:3", "collisions.restitution=0.5,1"],
            &[],
        ),
        (
            "rough-hcs.toml",
            &["rotation.tangential_restitution=-0.5,0,0.5"],
            &[],
        ),
    ];
    let mut checked = 0;
    for (k, (file, vary, sets)) in cases.into_iter().enumerate() {
        let mut overrides: Vec<Override> = sets.iter().map(|s| Override::set(*s)).collect();
        overrides.extend(Override::run_flags(Some(256), Some(3), None));
        let s = chart_sweep(
            Sourced::read(&scenes.join(file), overrides).unwrap(),
            vary.iter().map(|v| Vary::parse(v).unwrap()).collect(),
            Combine::Grid,
            r.join(k.to_string()),
        );
        let charts = charts_of(&s);
        let t = gdsmc_runner::run::columns::name::T;
        assert!(charts.iter().any(|(stem, _)| stem == t), "{file}");
        for (stem, chart) in &charts {
            let c = chart
                .as_ref()
                .unwrap_or_else(|e| panic!("{file}: {stem}: {e}"));
            let g = &c.geometry;
            let at = format!("{file}: {stem}");
            assert!(
                g.title.contains("n = 256")
                    && g.title.contains("3 ensembles per point")
                    && (g.title.contains("spheres") || g.title.contains("disks"))
                    && !g.title.contains(".toml")
                    && !g.title.contains("alpha = 0.5"),
                "{at}: title {}",
                g.title
            );
            assert_eq!(g.objections(), Vec::<String>::new(), "{at}");
            checked += 1;
        }
    }
    assert!(checked > 30, "only {checked} charts checked");
}
/// Every shipped sweep (`scenes/sweep-*.toml`, each by its `[sweep]` table) at n = 64 and two
/// ensembles per point: its charts pass the run charts' review (legend off the data, bands
/// visible, n and ensembles in the title), so a shipped sweep's docs chart cannot regress.
#[test]
#[ignore = "long suite: cargo test --workspace --release -- --include-ignored (README, CI)"]
fn every_shipped_sweeps_charts_are_readable() {
    let r = root("shipped");
    let scenes = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../scenes");
    let mut files: Vec<PathBuf> = std::fs::read_dir(&scenes)
        .unwrap()
        .flatten()
        .map(|e| e.path())
        .filter(|p| {
            p.file_name()
                .is_some_and(|n| n.to_string_lossy().starts_with("sweep-"))
        })
        .collect();
    files.sort();
    assert!(files.len() >= 6, "{files:?}");
    for (k, file) in files.iter().enumerate() {
        let source = Sourced::read(file, Override::run_flags(Some(64), Some(2), None)).unwrap();
        let plan = gdsmc_runner::sweep::plan(&source, &[], false).unwrap();
        let s = chart_sweep(source, plan.vary, plan.combine, r.join(k.to_string()));
        let charts = charts_of(&s);
        assert!(!charts.is_empty(), "{}", file.display());
        for (stem, chart) in &charts {
            let at = format!("{}: {stem}", file.display());
            let c = chart.as_ref().unwrap_or_else(|e| panic!("{at}: {e}"));
            let g = &c.geometry;
            assert!(
                g.title.contains("n = 64") && g.title.contains("2 ensembles per point"),
                "{at}: title {}",
                g.title
            );
            assert_eq!(g.objections(), Vec::<String>::new(), "{at}");
        }
    }
}
