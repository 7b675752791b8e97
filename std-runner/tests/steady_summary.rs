//! The summary's steady-state block shows only what settles (issue 35: a cooling gas's window
//! mean of a decaying T printed beside the exact value at the last time read as a 50x miss):
//! a freely cooling gas lists its scale-free quantities and no temperature, a heated gas its
//! temperatures, and a reference beside a mean is the reference's mean over the same window.

use gdsmc_runner::report::summary::text;
use gdsmc_runner::run::columns::{MIXTURE_TEMPERATURE, name};
use gdsmc_runner::scene;
use gdsmc_theory::curves::for_scene;
use std::path::PathBuf;

/// The steady block of the summary of `file` at n = 32, 4 ensembles.
fn steady_block(file: &str) -> (scene::Scene, gdsmc_runner::run::RunStats, String) {
    let path = PathBuf::from(env!("CARGO_MANIFEST_DIR"))
        .join("../scenes")
        .join(file);
    let mut s = scene::load(&path).unwrap();
    s.set_n(32).expect("a valid particle count");
    s.set_ensembles(4).unwrap();
    let st = gdsmc_runner::run::run(&s, 0, &|_| {}).unwrap();
    let out = text(&s, &st, &for_scene(&s));
    let from = out.find("\nsteady state").expect("a steady block");
    let block = out[from + 1..].split("\n\n").next().unwrap().to_string();
    (s, st, block)
}

fn lists(block: &str, name: &str) -> bool {
    block
        .lines()
        .any(|l| l.trim_start().starts_with(&format!("{name} ")))
}

#[test]
fn a_cooling_gas_lists_no_temperature_in_its_steady_block() {
    for file in ["disks-hcs.toml", "mixture-hcs-hard-spheres.toml"] {
        let (_, _, block) = steady_block(file);
        for t in [name::T, name::T_BULK, MIXTURE_TEMPERATURE, "zeta_mix"] {
            assert!(!lists(&block, t), "{file}: {t} in\n{block}");
        }
        assert!(
            lists(&block, name::A2) || lists(&block, "a2_s0"),
            "{file}: no cumulant in\n{block}"
        );
    }
}

#[test]
fn a_heated_gas_lists_its_temperature_beside_the_reference_window_mean() {
    let (_, st, block) = steady_block("rw-steady.toml");
    assert!(lists(&block, name::T_BULK), "{block}");
    let line = block
        .lines()
        .find(|l| l.trim_start().starts_with(&format!("{} ", name::T_BULK)))
        .unwrap();
    let shown: f64 = line
        .split("T_bulk_exact ")
        .nth(1)
        .and_then(|r| r.split_whitespace().next())
        .and_then(|v| v.parse().ok())
        .expect("T_bulk_exact beside T_bulk");
    // GRW (13)-(14) at RW (27)'s parameters: T_inf + (1 - T_inf) exp(-3t/4), T_inf = 8/3.
    let t_inf = 8.0 / 3.0;
    let first = st.steady.as_ref().unwrap().first;
    let window = &st.times[first..];
    let mean = window
        .iter()
        .map(|&t| t_inf + (1.0 - t_inf) * (-0.75 * t).exp())
        .sum::<f64>()
        / window.len() as f64;
    assert!((shown - mean).abs() < 1e-6, "{shown} against {mean}");
}
