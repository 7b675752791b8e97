//! The page's session on the host: the same statistics as the library's run, the command's
//! words for bad input, and every kind the core declares offered.

use gdsmc_runner::report::observables_csv;
use gdsmc_runner::scene::{Override, parse_with};
use gdsmc_theory::curves::for_scene;
use gdsmc_web::session::{Session, kinds};
use std::path::Path;

const GRW3: &str = include_str!("../../scenes/grw-example3.toml");

#[test]
fn a_session_gives_the_runs_observables() {
    let sets = "particles.n=64\nrun.ensembles=5\n";
    let (mut s, info) = Session::prepare("scenes/grw-example3.toml", GRW3, sets).unwrap();
    assert_eq!(info["n"], 64);
    assert_eq!(s.advance(2).unwrap(), 2);
    assert_eq!(s.advance(10).unwrap(), 5);
    let done = s.finish().unwrap();
    let scene = parse_with(
        Path::new("x.toml"),
        GRW3,
        &[
            Override::set("particles.n=64"),
            Override::set("run.ensembles=5"),
        ],
    )
    .unwrap();
    let stats = gdsmc_runner::run::run(&scene, 2, &|_| {}).unwrap();
    let want = String::from_utf8(observables_csv(&stats, &for_scene(&scene)).unwrap()).unwrap();
    assert_eq!(done["files"]["observables.csv"], want);
    assert!(done["summary"].as_str().unwrap().contains("verdict"));
    assert!(
        s.charts()["charts"]["T"]
            .as_str()
            .unwrap()
            .starts_with("<svg")
    );
    // The merged scene file is the scene with the keys in it.
    let merged = info["toml"].as_str().unwrap();
    let again = gdsmc_runner::scene::parse(Path::new("m.toml"), merged).unwrap();
    assert_eq!((again.n(), again.ensembles()), (64, 5));
}

#[test]
fn bad_input_gets_the_commands_words() {
    let e = Session::prepare("scenes/grw-example3.toml", GRW3, "particles.n=1")
        .err()
        .unwrap();
    let want = parse_with(Path::new("x"), GRW3, &[Override::set("particles.n=1")])
        .unwrap_err()
        .to_string();
    assert_eq!(e, format!("error: {want}"));
    let e = Session::prepare("scenes/bad.toml", "[particles]\nn = 0\n", "")
        .err()
        .unwrap();
    assert!(e.starts_with("error: scenes/bad.toml"), "{e}");
}

#[test]
fn every_declared_kind_is_offered() {
    use gdsmc_core::physics::{DriveKind, KernelKind};
    let k = kinds();
    let names = |table: &str| -> Vec<String> {
        k[table]
            .as_array()
            .unwrap()
            .iter()
            .map(|v| v["name"].as_str().unwrap().to_string())
            .collect()
    };
    let kernels: Vec<String> = KernelKind::ALL
        .iter()
        .map(|k| k.scene_name().into())
        .collect();
    let drives: Vec<String> = DriveKind::ALL
        .iter()
        .map(|k| k.scene_name().into())
        .collect();
    assert_eq!(names("kernels"), kernels);
    assert_eq!(names("drives"), drives);
    assert_eq!(k["stream_version"], gdsmc_runner::STREAM_VERSION);
}

/// Ensembles run by helper sessions (the page's helper workers) and folded by another, in
/// order, from their bytes: the library run's observables. Cut bytes are refused.
#[test]
fn helpers_ensembles_folded_give_the_run() {
    let sets = "particles.n=64\nrun.ensembles=4\n";
    let name = "scenes/grw-example3.toml";
    let (mut folder, _) = Session::prepare(name, GRW3, sets).unwrap();
    let (mut helper, _) = Session::prepare(name, GRW3, sets).unwrap();
    let mut bytes: Vec<Vec<u8>> = [3u64, 1, 0, 2]
        .into_iter()
        .map(|k| (k, helper.ensemble(k).unwrap()))
        .collect::<std::collections::BTreeMap<_, _>>()
        .into_values()
        .collect();
    let cut = bytes[0][..bytes[0].len() - 3].to_vec();
    assert!(folder.fold(&cut).is_err());
    for (k, b) in bytes.drain(..).enumerate() {
        assert_eq!(folder.fold(&b).unwrap(), k as u64 + 1);
    }
    let (mut alone, _) = Session::prepare(name, GRW3, sets).unwrap();
    alone.advance(4).unwrap();
    assert_eq!(
        folder.finish().unwrap()["files"]["observables.csv"],
        alone.finish().unwrap()["files"]["observables.csv"]
    );
}
