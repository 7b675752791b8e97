//! Disks (`particles.dimension = 2`) through the scene and the runner: GRW (13) counts degrees
//! of freedom, so the Maxwell disks' `T_bulk` is its exact finite-n mean at every time (n = 8,
//! 99.9% jointly: Bonferroni over the time points), and the same check refuses hard disks,
//! whose cooling is not GRW (13)'s. The scene's references say which apply.

use gdsmc_runner::run::columns::name;
use gdsmc_stats::{dof, family};
use gdsmc_theory::curves::{for_scene, maxwell_temperature};
use gdsmc_validation::*;

#[test]
fn maxwell_disks_follow_grw_13_exactly_at_finite_n() {
    let n = 8;
    let mut s = shipped_set("disks-white-noise", &[], n, 20_000, 2201);
    s.set_times((0..=8).map(|k| 0.5 * k as f64).collect())
        .expect("valid observation times");
    let mt = maxwell_temperature(&s).expect("Maxwell disks: GRW (13) applies");
    let st = run(&s);
    let f = family(st.times.len(), dof(st.ensembles));
    assert_within_at_all_times(
        &st,
        name::T_BULK,
        f,
        |t| mt.finite_n_bulk_mean(n, t),
        "Maxwell disks",
    );
    // Hard disks with the same parameters cool differently: the check must tell.
    let mut h = shipped_set(
        "disks-white-noise",
        &["collisions.kernel=hard-spheres"],
        n,
        20_000,
        2202,
    );
    h.set_times(s.times().to_vec())
        .expect("valid observation times");
    assert!(maxwell_temperature(&h).is_none());
    let st = run(&h);
    let outside = times_outside(&st, name::T_BULK, f, |t| mt.finite_n_bulk_mean(n, t));
    assert!(
        outside >= st.times.len() - 2,
        "only {outside} times tell hard disks from Maxwell disks"
    );
}

/// The scene's `a2_sonine` reference (MS (5) in `d` dimensions), if attached.
fn sonine_cooling_a2(s: &gdsmc_runner::scene::Scene) -> Option<f64> {
    let c = for_scene(s).into_iter().find(|c| c.name == "a2_sonine")?;
    Some((c.curve)(0.0))
}

#[test]
fn cooling_hard_disks_get_the_first_sonine_a2_of_d_2() {
    let s = shipped_set("disks-hcs", &[], 64, 1, 1);
    let a2 = sonine_cooling_a2(&s).expect("cooling hard disks");
    // van Noije and Ernst 1998 at d = 2, alpha = 1/2: 16 (1/2)(1/2) / (9 + 48 - 25/2 + 15/4).
    assert!((a2 - 4.0 / 48.25).abs() < 1e-15, "{a2}");
    let spheres = shipped_set("disks-hcs", &["particles.dimension=3"], 64, 1, 1);
    let a3 = sonine_cooling_a2(&spheres).unwrap();
    assert!((a3 - 4.0 / 76.25).abs() < 1e-15, "{a3}");
}

/// Maxwell spheres and disks under the Gaussian thermostat (MS (12), `zeta` about the bulk
/// velocity): the thermostat's scaling of `v - V` commutes with collisions whose rate does not
/// depend on `|u|`, so `T_bulk` is GRW (13) times `e^{2 zeta t}` at finite n exactly, and the raw
/// `T` adds the constant `T_0 / n` of the kept momentum (`bulk_to_raw`; it once grew as
/// `e^{2 zeta t}` there, and this check catches that). n = 4, 100,000 ensembles, 99.9% jointly
/// over both columns and every time (Bonferroni).
#[test]
fn maxwell_gases_under_the_gaussian_thermostat_follow_grw_13_scaled_at_finite_n() {
    for dimension in [3, 2] {
        let text = format!(
            "[particles]\nn = 4\ndimension = {dimension}\ninitial = {{ kind = \"maxwellian\", temperature = 1.0 }}\n\
             [collisions]\nkernel = \"maxwell\"\ngamma = 4.0\nc = 0.07957747154594767\nrestitution = 0.5\n\
             [drive]\nkind = \"gaussian\"\nzeta = 0.5\n\
             [observe]\nt_end = 4.0\nintervals = 8\n\
             [run]\nensembles = 100000\nseed = {}\n",
            2300 + dimension
        );
        let s = gdsmc_runner::scene::parse(std::path::Path::new("gaussian.toml"), &text)
            .expect("a valid scene");
        let n = s.n();
        let (mt, st, f) = assert_exact_maxwell_temperature(&s, &format!("d = {dimension}"));
        // The check has the power to refuse the raw term that grew with the thermostat, and a
        // thermostat counted once (`e^{zeta t}`) in T_bulk.
        let grown =
            |t: f64| mt.finite_n_bulk_mean(n, t) + mt.t0 * (mt.heating.b * t).exp() / n as f64;
        assert!(times_outside(&st, name::T, f, grown) >= st.times.len() - 3);
        let once = mt.with_gaussian(0.25 * mt.heating.b);
        let once = |t: f64| once.finite_n_bulk_mean(n, t);
        assert!(times_outside(&st, name::T_BULK, f, once) >= st.times.len() - 3);
    }
}
