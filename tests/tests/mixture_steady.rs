//! A granular mixture run through the runner to its steady state: the Gaussian thermostat keeps
//! the cooling state's temperature ratio, and the cooling rates the runner estimates from
//! random pairs are the exact rate of change.

use super::mixture::{maxwell_mixture, mean_se};
use gdsmc_core::math::PI;
use gdsmc_core::particles::{Particle, Particles};
use gdsmc_core::rng::Streams;
use gdsmc_stats::{dof, family, joint};
use gdsmc_theory::mixture::MaxwellMixture;

/// The steady averages of `cols` of a scene run through the runner, each with its 99.9%
/// half-width.
fn steady(text: &str, cols: &[&str]) -> Vec<(f64, f64)> {
    let scene = gdsmc_runner::scene::parse(std::path::Path::new("mix.toml"), text).unwrap();
    let stats = gdsmc_runner::run::run(&scene, 0, &|_| {}).unwrap();
    let st = stats.steady.as_ref().unwrap();
    cols.iter()
        .map(|c| st.steady_mean_ci(&stats, stats.col(c).unwrap()))
        .collect()
}

/// The Gaussian thermostat is a dilation of the velocities about the flow velocity, which
/// the hard-sphere mixture's scaling state does not notice (MS Section 2 for one species):
/// heated by it, the mixture settles where its species share the energy as in the cooling
/// state. The steady ratio T_0/T_mix with the thermostat and in the homogeneous cooling state
/// agree within their combined half-widths (two independent runs), and both differ from
/// equipartition by many of them. In the thermostat's steady state each species' temperature
/// is steady, so the collisions cool every species at exactly the thermostat's heating rate
/// `2 zeta` (MS (12): `dT/dt = 2 zeta T`): `zeta_mix`, `zeta_s0`, `zeta_s1` (run/cooling.rs)
/// within their half-widths of 1 at zeta = 0.5 (the per-ensemble ratio's bias is O(1/n),
/// 0.1% here, inside the intervals). Four checks, Bonferroni.
#[test]
fn gaussian_thermostat_keeps_the_cooling_states_temperature_ratio() {
    let hcs = std::fs::read_to_string(gdsmc_validation::scene_path("mixture-hcs-hard-spheres"))
        .unwrap()
        .replace("n = 2000", "n = 1000")
        .replace("restitution = 0.9", "restitution = 0.7")
        .replace("ensembles = 20", "ensembles = 24");
    // zeta = 0.5: T settles where the hard-sphere cooling rate (about T^{1/2}) equals 2 zeta.
    let thermostat = hcs
        .replace("kind = \"none\"", "kind = \"gaussian\"\nzeta = 0.5")
        .replace("t_end = 200.0", "t_end = 60.0")
        .replace(
            "steady_from = 100.0",
            "steady_from = 30.0\ncollisional_pairs = 2000",
        );
    let family = family(4, dof(24));
    let (a, ha) = steady(&hcs, &["T_s0_ratio"])[0];
    let heated = steady(
        &thermostat,
        &["T_s0_ratio", "zeta_mix", "zeta_s0", "zeta_s1"],
    );
    let (b, hb) = heated[0];
    let both = family * (ha * ha + hb * hb).sqrt();
    assert!(
        (a - b).abs() <= both,
        "cooling {a} +- {ha}, thermostat {b} +- {hb}"
    );
    assert!(
        a - 1.0 > 10.0 * both,
        "no departure from equipartition: {a} +- {ha}"
    );
    for (name, &(z, hz)) in ["zeta_mix", "zeta_s0", "zeta_s1"].iter().zip(&heated[1..]) {
        assert!(
            (z - 1.0).abs() <= family * hz,
            "{name} = {z} +- {hz}, 2 zeta = 1"
        );
    }
}

/// The cooling rates' estimate (run/cooling.rs): its expectation over the pairs is the
/// collisions' exact rate of change of `T_s` given the velocities, so averaged over ensembles
/// it is `d E[T_s]/dt`, which the Maxwell mixture's exact moments give (their time derivative
/// by a difference with step 1e-4, central at t = 1 and forward at t = 0: errors about 1e-8
/// and 1e-4, far inside the intervals). Checked at t = 0 and t = 1 at n = 50, both species
/// (4 checks, Bonferroni).
#[test]
fn cooling_rates_estimate_the_exact_rate_of_change() {
    use gdsmc_runner::run::cooling::CoolingRates;
    let mix = maxwell_mixture([30, 20]);
    let text = format!(
        "[particles]\nn = 50\n[[species]]\nfraction = 3.0\nmass = 1.0\ntemperature = 1.0\ndiameter = 1.0\n\
         [[species]]\nfraction = 2.0\nmass = 4.0\ntemperature = 2.0\ndiameter = {}\n\
         [collisions]\nkernel = \"maxwell\"\ngamma = 1.0\nc = {}\npair_restitution = [[0.9, 0.6], [0.6, 0.8]]\n\
         [observe]\nt_end = 1.0\n",
        // kappa = 4 pi C ((d_s + d_t)/2)^2 = 1, 1.5, 0.5: d_0 = 1, d_1 = sqrt(0.5).
        0.5f64.sqrt(),
        1.0 / (4.0 * PI),
    );
    let scene = gdsmc_runner::scene::parse(std::path::Path::new("mix.toml"), &text).unwrap();
    // The scene's kernel constants are the test mixture's (kappa_01 = ((1 + sqrt .5)/2)^2 is
    // not 1.5, so the exact reference is built from the scene's own values).
    let d1 = 0.5f64.sqrt();
    let k01 = (0.5 * (1.0 + d1)).powi(2);
    let exact = MaxwellMixture {
        kappa: vec![1.0, k01, 0.5],
        alpha: vec![0.9, 0.6, 0.8],
        ..mix
    };
    let rates = CoolingRates::new(&scene).unwrap();
    let model = scene.physics().validate().unwrap();
    let z = joint(4, dof(4000));
    let ensembles = 4000;
    for &t in &[0.0, 1.0] {
        let mut samples = vec![Vec::new(); 2];
        let mut buf = vec![Particle::default(); 50];
        for mut rng in Streams::new(21).take(ensembles) {
            let mut p = Particles::new(&mut buf).unwrap();
            let (mut e, _) = model.launch(&mut p, 0.0, &mut rng).unwrap();
            if t > 0.0 {
                gdsmc_core::engine::EventLoop::advance_to(&mut e, &mut p, t, &mut rng).unwrap();
            }
            for (s, (_, dt)) in rates.rates(&p, 50, &mut rng).into_iter().enumerate() {
                samples[s].push(dt);
            }
        }
        let h = 1e-4;
        let (a, b) = (
            exact.temperatures_at(t + h, false),
            exact.temperatures_at((t - h).max(0.0), false),
        );
        let width = if t > 0.0 { 2.0 * h } else { h };
        for s in 0..2 {
            let derivative = (a[s] - b[s]) / width;
            let (m, se) = mean_se(&samples[s]);
            assert!(
                (m - derivative).abs() <= z * se,
                "t = {t} species {s}: dT/dt {m} +- {} vs exact {derivative}",
                z * se
            );
            assert!(
                derivative.abs() > 10.0 * z * se,
                "too noisy to tell: {m} +- {se}"
            );
        }
    }
}
