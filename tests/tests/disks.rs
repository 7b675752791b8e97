//! Disks (`particles.dimension = 2`) through the scene and the runner: GRW (13) counts degrees
//! of freedom, so the Maxwell disks' `T_bulk` is its exact finite-n mean at every time (n = 8,
//! 99.9% jointly: Bonferroni over the time points), and the same check refuses hard disks,
//! whose cooling is not GRW (13)'s. The scene's references say which apply.

use gdsmc_runner::reference::curves::{maxwell_temperature, sonine_cooling_a2};
use gdsmc_validation::*;

#[test]
fn maxwell_disks_follow_grw_13_exactly_at_finite_n() {
    let n = 8;
    let mut s = shipped_set("disks-white-noise", &[], n, 20_000, 2201);
    s.set_times((0..=8).map(|k| 0.5 * k as f64).collect())
        .expect("valid observation times");
    let mt = maxwell_temperature(&s).expect("Maxwell disks: GRW (13) applies");
    let st = run(&s);
    let f = family_factor(st.times.len());
    for (ti, &t) in st.times.iter().enumerate() {
        let (m, c) = at(&st, ti, "T_bulk");
        let exact = mt.finite_n_bulk_mean(n, t);
        assert!(
            (m - exact).abs() <= f * c,
            "t = {t}: T_bulk {m} +- {}, exact {exact}",
            f * c
        );
    }
    // Hard disks with the same parameters cool differently: the check must tell.
    let mut h = shipped_set(
        "disks-white-noise",
        &["collisions.kernel=hard-spheres"],
        n,
        20_000,
        2202,
    );
    h.set_times(s.times.clone())
        .expect("valid observation times");
    assert!(maxwell_temperature(&h).is_none());
    let st = run(&h);
    let outside = times_outside(&st, "T_bulk", f, |t| mt.finite_n_bulk_mean(n, t));
    assert!(
        outside >= st.times.len() - 2,
        "only {outside} times tell hard disks from Maxwell disks"
    );
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
