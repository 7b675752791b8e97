//! The start with exact momentum (`particles.momentum = "exact"`): the draws shifted so that
//! the sample's mean velocity is the distribution's. It keeps the temperature about the flow
//! (`T_bulk`'s exact finite-n mean is the drawn start's) and removes the drift's fluctuation
//! from the raw `T` (`bulk_to_raw_from`: `U(0) = 0`), and the scene's references follow it.
//!
//! Statistical tests with fixed seeds: every check at 99.9% jointly over its family
//! (Bonferroni over the columns and times checked), the interval the run's own.

use gdsmc_runner::run::columns::name;
use gdsmc_stats::{dof, family};
use gdsmc_theory::curves::{Kind, for_scene, maxwell_temperature};
use gdsmc_validation::*;

/// GRW Examples 3 (white noise) and 4 (cooling) at n = 8 with exact momentum: `T_bulk` is the
/// drawn start's exact mean and the raw `T` is it plus the kicks' random walk alone, at every
/// time; at t = 0 the drawn start's raw mean (`T_0`, 1/8 above) is refused, so the test fails
/// if the shift is not made.
#[test]
fn an_exact_momentum_start_keeps_t_bulk_and_drops_the_drift_from_t() {
    for (scene, seed) in [("grw-example3", 311), ("grw-example4", 312)] {
        let n = 8;
        let s = shipped_set(scene, &["particles.momentum=exact"], n, 40_000, seed);
        let mt = maxwell_temperature(&s).expect("a Maxwell gas");
        let st = run(&s);
        let f = family(2 * st.times.len(), dof(st.ensembles));
        let exact = gdsmc_core::physics::Momentum::Exact;
        assert_within_at_all_times(&st, name::T_BULK, f, |t| mt.finite_n_bulk_mean(n, t), scene);
        assert_within_at_all_times(
            &st,
            name::T,
            f,
            |t| mt.finite_n_bulk_mean(n, t) + mt.bulk_to_raw_from(exact, n, t),
            scene,
        );
        let (t0, c0) = at(&st, time_index(&st, 0.0), name::T);
        assert!(
            (t0 - mt.finite_n_raw_mean(n, 0.0)).abs() > f * c0,
            "{scene}: the raw T at t = 0, {t0} +- {c0}, is the drawn start's"
        );
        // The bulk velocity starts at zero exactly, in every ensemble.
        for col in [name::V_X, name::V_Y, name::V_Z] {
            let (m, c) = at(&st, 0, col);
            assert!(m.abs() < 1e-15 && c < 1e-15, "{scene}: {col} = {m} +- {c}");
        }
    }
}

/// Every exact mean at n a scene attaches holds for the exact-momentum start too: the one
/// species' (GRW (13)-(14) at finite n, raw and bulk) and a Maxwell mixture's species
/// temperatures (whose second-moment system starts at `P_st = 0`), checked against the curves
/// the theory gives the scene, jointly over every column and time; the drawn start's curves
/// are refused somewhere (the check can tell the starts apart).
#[test]
fn the_references_at_n_follow_the_start() {
    for (scene, n, seed) in [("grw-example3", 8, 321), ("mixture-maxwell", 10, 322)] {
        let s = shipped_set(scene, &["particles.momentum=exact"], n, 40_000, seed);
        let at_n = |s: &gdsmc_runner::scene::Scene| -> Vec<_> {
            for_scene(s)
                .into_iter()
                .filter(|c| c.kind == Kind::MeanAtN)
                .collect()
        };
        let curves = at_n(&s);
        assert!(!curves.is_empty(), "{scene}: no exact mean at n attached");
        let st = run(&s);
        let f = family(curves.len() * st.times.len(), dof(st.ensembles));
        for c in &curves {
            assert_within_at_all_times(&st, c.of, f, |t| (c.curve)(t), c.name);
        }
        let drawn = at_n(&shipped_set(scene, &[], n, 1, 1));
        let refused = drawn.iter().any(|c| {
            (0..st.times.len()).any(|ti| {
                let (m, h) = at(&st, ti, c.of);
                ((c.curve)(st.times[ti]) - m).abs() > f * h
            })
        });
        assert!(
            refused,
            "{scene}: the drawn start's means fit the exact start's run"
        );
    }
}
