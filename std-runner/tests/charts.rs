//! The SVG charts are written and hold the mean, the band and the reference curve.

use gdsmc_runner::scene;
use std::path::PathBuf;

#[test]
fn a_run_writes_csv_json_and_svg() {
    let path = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../scenes/grw-example3.toml");
    let mut s = scene::load(&path).unwrap();
    s.set_n(32).expect("a valid particle count");
    s.set_ensembles(10).unwrap();
    let st = gdsmc_runner::run::run(&s, 1, &|_| {}).unwrap();
    let refs = gdsmc_theory::curves::for_scene(&s);
    let dir = std::env::temp_dir().join(format!("gdsmc-charts-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    gdsmc_runner::report::write_all(&dir, &s, &st, &refs, Default::default()).unwrap();
    for f in [
        "observables.csv",
        "summary.json",
        "T.svg",
        "T_bulk.svg",
        "a2.svg",
        "crit.svg",
    ] {
        assert!(dir.join(f).is_file(), "{f} missing");
    }
    let svg = std::fs::read_to_string(dir.join("T.svg")).unwrap();
    assert!(
        svg.starts_with("<svg")
            && svg.contains("T_exact (GRW (13)-(14))")
            && svg.contains("99.9% confidence band")
    );
    assert!(!dir.join("T.svg.partial").exists() && !dir.join("observables.csv.partial").exists());
    let json: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(dir.join("summary.json")).unwrap()).unwrap();
    assert_eq!(json["ensembles"], 10);
    assert_eq!(json["interrupted"], false);
    std::fs::remove_dir_all(&dir).unwrap();
}

/// Every chart of every shipped scene (at n = 256, 4 ensembles) is drawn, rendered to PNG and
/// checked as a reviewer would look at it (`Geometry::objections`, itself tested to object
/// to each fault of the old T chart): the legend shares no pixel with a plotting area, every
/// drawn point, band corner and error-bar end lies inside a plotting area, a band is drawn
/// only where it is taller than the line and over the lines, every line is dark enough for
/// grey scale and told apart from the others, every axis label names its quantity in words;
/// the title names the physics (not the file), n and the ensembles; every observable has its
/// chart.
#[test]
#[ignore = "long suite: cargo test --workspace --release -- --include-ignored (README, CI)"]
fn every_chart_of_every_shipped_scene_is_readable() {
    use gdsmc_runner::report::charts;
    let scenes = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../scenes");
    let mut names: Vec<PathBuf> = std::fs::read_dir(&scenes)
        .unwrap()
        .map(|e| e.unwrap().path())
        .filter(|p| p.extension().is_some_and(|x| x == "toml"))
        .collect();
    names.sort();
    assert!(names.len() >= 19, "shipped scenes missing");
    let mut checked = 0;
    #[cfg(feature = "render")]
    let mut svgs: Vec<(String, String)> = Vec::new();
    for path in names {
        let mut s = scene::load(&path).unwrap();
        s.set_n(256).expect("a valid particle count");
        s.set_ensembles(4).unwrap();
        let st = gdsmc_runner::run::run(&s, 0, &|_| {}).unwrap();
        let refs = gdsmc_theory::curves::for_scene(&s);
        let reduced = gdsmc_runner::analysis::distribution::reduced(&s, &st);
        let marginal = gdsmc_runner::analysis::distribution::marginal(&st);
        let power = gdsmc_runner::analysis::power_tail::measure(&s, &st);
        let title = charts::title(&s, st.ensembles);
        let all = charts::all(
            &title,
            &st,
            (s.time_axis(), s.species_names()),
            &refs,
            reduced.as_ref(),
            marginal.as_ref(),
            power.as_ref(),
        );
        for &col in &st.names {
            // Disks move in the plane: no chart of their V_z, which is 0 by construction.
            let flat = s.dimension() == 2 && col == gdsmc_runner::run::columns::name::V_Z;
            assert_eq!(
                all.iter().any(|(stem, c)| stem == col && c.is_ok()),
                !flat,
                "{}: a chart of {col} {}",
                s.name(),
                if flat { "drawn" } else { "missing" }
            );
        }
        for (stem, chart) in &all {
            let Ok(c) = chart else { continue };
            let g = &c.geometry;
            let at = format!("{}: {stem}", s.name());
            assert!(
                g.title.contains("n = 256")
                    && g.title.contains("4 ensembles")
                    && !g.title.contains(s.name())
                    && (g.title.contains("spheres") || g.title.contains("disks")),
                "{at}: title {}",
                g.title
            );
            assert_eq!(g.objections(), Vec::<String>::new(), "{at}");
            assert!(!g.axes.is_empty(), "{at}: no axis labels recorded");
            #[cfg(feature = "render")]
            svgs.push((at, c.svg.clone()));
            checked += 1;
        }
    }
    assert!(checked > 200, "only {checked} charts checked");
    // Every chart rendered to PNG, on every core (the renderer is most of this test's time).
    #[cfg(feature = "render")]
    {
        use rayon::prelude::*;
        svgs.par_iter().for_each(|(at, svg)| {
            let png = charts::export::png(svg).unwrap_or_else(|e| panic!("{at}: PNG: {e}"));
            assert!(
                png.starts_with(b"\x89PNG") && png.len() > 1000,
                "{at}: PNG empty"
            );
        });
        assert_eq!(svgs.len(), checked);
    }
}
