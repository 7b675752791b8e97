//! The impact form of the inelastic Maxwell model (Ernst and Brito's, `kernel =
//! "maxwell-impact"`: the impact direction uniform) in d = 3, judged against its own exact
//! values (theory/src/maxwell_impact.rs, theory/src/maxwell_form.rs) and told apart from GRW
//! (3)'s scattering form, whose cooling rate is 3/2 of its own and whose `a2` and roots differ.
//!
//! Statistical tests with fixed seeds: every check at 99.9% jointly over its family
//! (Bonferroni over the columns and times checked), the interval the run's own.

use gdsmc_runner::run::columns::name;
use gdsmc_stats::{dof, family};
use gdsmc_theory::curves::{Kind, for_scene, maxwell_cumulant, maxwell_temperature};
use gdsmc_theory::maxwell_form::Form;
use gdsmc_validation::*;

/// The shipped Maxwell cooling scene as the impact form at `alpha`, with `sets` besides.
fn impact(alpha: f64, sets: &[&str], n: usize, m: u64, seed: u64) -> gdsmc_runner::scene::Scene {
    let alpha = format!("collisions.restitution={alpha}");
    let mut all = vec!["collisions.kernel=maxwell-impact", alpha.as_str()];
    all.extend_from_slice(sets);
    shipped_set("hcs-maxwell", &all, n, m, seed)
}

/// Every exact mean at n the scene attaches (GRW (13)-(14) at finite n with the impact form's
/// decay rate `2 pi gamma C (1 - alpha^2)/d`, raw and bulk, and `zeta_star_exact = (1 -
/// alpha^2)/(2 d) n/(n - 1)`) holds at n = 8, jointly over every column and time; the
/// scattering form's temperature (`k` 3/2 as large) is refused at t = 4.
#[test]
fn the_impact_forms_exact_means_hold_at_n() {
    let sets = [
        "observe.collisional_pairs=2000",
        "observe.t_end=8",
        "observe.intervals=8",
    ];
    let s = impact(0.5, &sets, 8, 40_000, 411);
    let curves: Vec<_> = for_scene(&s)
        .into_iter()
        .filter(|c| c.kind == Kind::MeanAtN)
        .collect();
    let names: Vec<&str> = curves.iter().map(|c| c.name).collect();
    for want in ["T_mean_n", "T_bulk_mean_n", "zeta_star_exact"] {
        assert!(names.contains(&want), "{want} not attached: {names:?}");
    }
    let st = run(&s);
    let f = family(curves.len() * st.times.len(), dof(st.ensembles));
    for c in &curves {
        assert_within_at_all_times(&st, c.of, f, |t| (c.curve)(t), c.name);
    }
    let mt = maxwell_temperature(&s).expect("a Maxwell gas");
    let scattering = {
        let mut m = mt;
        m.k *= Form::Scattering.lambda2(3, 0.5) / Form::Impact.lambda2(3, 0.5);
        m
    };
    let (tb, cb) = at(&st, time_index(&st, 4.0), name::T_BULK);
    assert!(
        (tb - scattering.finite_n_bulk_mean(8, 4.0)).abs() > f * cb,
        "the scattering form's temperature fits the impact form's run: {tb} +- {cb}"
    );
}

/// The impact form's `a2(t)` from a Maxwellian to its cooling state (Santos 2003's `6 (1 -
/// alpha)^2 / (5 + 3 alpha (2 - alpha))` at d = 3), n = 16384 where the O(1/n) of a mean at
/// finite n is a small part of the interval, at alpha = 0.3: within the 99.9% interval
/// jointly over five times; the scattering form's solution is refused at the late times.
#[test]
#[ignore = "long suite: cargo test --workspace --release -- --include-ignored (README, CI)"]
fn the_impact_forms_a2_follows_its_exact_solution() {
    let alpha = 0.3;
    let sets = ["observe.t_end=16", "observe.intervals=16"];
    let s = impact(alpha, &sets, 16_384, 60, 412);
    let exact = maxwell_cumulant(&s).expect("the impact form has one");
    let st = run(&s);
    let times = [1.0, 2.0, 4.0, 8.0, 16.0];
    let f = family(times.len(), dof(st.ensembles));
    let (l2, l4, b4) = Form::Scattering.coefficients(3, alpha);
    let other = gdsmc_theory::maxwell_cumulant::MaxwellCumulant::heated(
        3,
        (l2, l4, b4),
        (1.0, 1.0 / std::f64::consts::PI),
        (1.0, 5.0 / 3.0),
        gdsmc_core::drive::Heating {
            a: 0.0,
            b: 0.0,
            p: 0.0,
        },
    )
    .unwrap();
    for t in times {
        let (a2, c) = at(&st, time_index(&st, t), name::A2);
        assert!(
            (a2 - exact.at(t)).abs() <= f * c,
            "t {t}: a2 {a2} +- {}, exact {}",
            f * c,
            exact.at(t)
        );
        if t >= 8.0 {
            assert!(
                (a2 - other.at(t)).abs() > f * c,
                "t {t}: the scattering form's {} fits",
                other.at(t)
            );
        }
    }
    let santos = 6.0 * (1.0 - alpha).powi(2) / (5.0 + 3.0 * alpha * (2.0 - alpha));
    assert!((exact.at(1e3) - santos).abs() < 1e-12);
}

/// The impact form's cooling-state tail on weighted particles (the shipped windows of
/// `scenes/hcs-maxwell-tail-weighted.toml`, `n0 = 1024`, 240 or 320 ensembles): the exponent
/// extrapolated from the local slopes over `[5, 10]` and `[10, 20]` holds the impact form's root
/// (Ernst and Brito 2002: 5.763, 7.099, 9.733 at alpha = 0.1, 0.3, 0.5) within its interval,
/// under 1% of the root, jointly over the three (Bonferroni), and refuses the scattering
/// form's root. The far tail scales later than the core, and later for the impact form (its
/// cooling rate is 2/3 of the scattering form's): at alpha = 0.1 the slopes over t in [20, 30]
/// still lie 1% above the root (two seeds; docs/weighted.md), over [50, 60] they hold it.
#[test]
#[ignore = "long suite: cargo test --workspace --release -- --include-ignored (README, CI)"]
fn the_impact_forms_tail_exponent_is_its_root() {
    use gdsmc_runner::analysis::power_tail::measure;
    // `(alpha, t_end, steady_from, ensembles, seed)`: alpha = 1/2's larger root has the wider
    // interval, so more ensembles there.
    let cases = [
        (0.1, "60", "50", 240, 421),
        (0.3, "30", "20", 240, 422),
        (0.5, "30", "20", 320, 423),
    ];
    for (alpha, end, from, m, seed) in cases {
        let sets = [
            "collisions.kernel=maxwell-impact".to_string(),
            format!("collisions.restitution={alpha}"),
            format!("observe.t_end={end}"),
            format!("observe.intervals={end}"),
            format!("observe.steady_from={from}"),
        ];
        let sets: Vec<&str> = sets.iter().map(String::as_str).collect();
        let s = shipped_set("hcs-maxwell-tail-weighted", &sets, 1024, m, seed);
        let st = run(&s);
        let t = measure(&s, &st).expect("a reduced histogram");
        let root = Form::Impact.tail_exponent(3, alpha);
        assert_eq!(
            t.exact,
            Some(root),
            "alpha {alpha}: the impact form's root is attached"
        );
        let (v, ci) = t.exponent().expect("an extrapolated exponent");
        // The verdict's 99.9% interval widened to the family of three.
        let h = ci * family(3, dof(st.ensembles));
        assert!(h < 0.01 * root, "alpha {alpha}: uninformative, {v} +- {h}");
        assert!(
            (v - root).abs() <= h,
            "alpha {alpha}: {v} +- {h}, root {root}"
        );
        let other = Form::Scattering.tail_exponent(3, alpha);
        assert!((v - other).abs() > h, "alpha {alpha}: holds {other} too");
    }
}
