//! The SVG charts are written and hold the mean, the band and the reference curve.

use gdsmc_runner::scene;
use std::path::PathBuf;

#[test]
fn a_run_writes_csv_json_and_svg() {
    let path = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../scenes/grw-example3.toml");
    let mut s = scene::load(&path).unwrap();
    s.physics.n = 32;
    s.ensembles = 10;
    let st = gdsmc_runner::run::run(&s, 1, &|_| {}).unwrap();
    let refs = gdsmc_runner::reference::curves::for_scene(&s);
    let dir = std::env::temp_dir().join(format!("gdsmc-charts-{}", std::process::id()));
    gdsmc_runner::report::write_all(&dir, &s, &st, &refs).unwrap();
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
