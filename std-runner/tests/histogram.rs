//! The radial-shell histogram (GRW (31)-(33)) of the initial standard Maxwellian against the
//! exact shell probabilities of the chi distribution with 3 degrees of freedom,
//! `P(|v| < r) = erf(r / sqrt 2) - sqrt(2/pi) r exp(-r^2/2)`. Each of the 17 shells within its
//! standard error (the 99.9% half-width over the Student-t multiplier of its 40 ensembles)
//! times z = 4.0, a Bonferroni family level of 99.9%.

use gdsmc_runner::scene;
use gdsmc_stats::multiplier;
use std::path::PathBuf;

fn chi3_cdf(r: f64) -> f64 {
    libm::erf(r / 2f64.sqrt()) - (2.0 / std::f64::consts::PI).sqrt() * r * (-0.5 * r * r).exp()
}

/// The 16 shells up to 4 (and the last, [4, inf)) of a shipped scene's initial Maxwellian:
/// n = 5000, 40 ensembles.
fn initial_shells(scene_name: &str) -> gdsmc_runner::run::RunStats {
    let p = PathBuf::from(env!("CARGO_MANIFEST_DIR"))
        .join("../scenes")
        .join(format!("{scene_name}.toml"));
    let mut s = scene::load(&p).unwrap();
    s.set_n(5000).expect("a valid particle count");
    s.set_ensembles(40).unwrap();
    s.set_times(vec![0.0]).expect("valid observation times");
    s.set_histogram(Some(gdsmc_runner::scene::Shells {
        shells: 16,
        radius: 4.0,
    }))
    .expect("a valid histogram");
    gdsmc_runner::run::run(&s, 0, &|_| {}).unwrap()
}

#[test]
fn initial_shells_are_maxwellian() {
    let st = initial_shells("grw-example3");
    let gdsmc_runner::run::ShellHistogram { radius, weights: h } = st.histogram.as_ref().unwrap();
    assert_eq!(h.len(), 17);
    let mut total = 0.0;
    let mut exact_hist = gdsmc_stats::Accumulator::new(17);
    let mut exact_row = vec![0.0; 17];
    for (k, slot) in exact_row.iter_mut().enumerate() {
        let lo = radius * k as f64 / 16.0;
        let exact = if k == 16 {
            1.0 - chi3_cdf(*radius)
        } else {
            chi3_cdf(lo + 0.25) - chi3_cdf(lo)
        };
        *slot = exact;
        let (m, ci) = (h.mean(k), h.ci(k));
        total += m;
        if exact > 1e-6 {
            assert!(
                (m - exact).abs() <= ci * 4.0 / multiplier(40),
                "shell {k}: {m} +- {ci}, exact {exact}"
            );
        }
    }
    assert!((total - 1.0).abs() < 1e-12, "weights sum to one: {total}");
    // The tail fit of the simulated shells matches the fit of the exact shells within its
    // interval (the same shells: the exact histogram is resolved everywhere).
    exact_hist.push(&exact_row);
    let fit = gdsmc_runner::analysis::tails::fit(*radius, h, 3).expect("enough resolved shells");
    let want = gdsmc_runner::analysis::tails::fit(*radius, &exact_hist, 3).expect("exact fit");
    assert!(
        (fit.slope - want.slope).abs() <= fit.slope_ci,
        "slope {} +- {} vs exact shells {}",
        fit.slope,
        fit.slope_ci,
        want.slope
    );
    assert!(
        want.slope > 1.5 && want.slope < 2.5,
        "a Maxwellian's shells give an exponent near 2: {}",
        want.slope
    );
}

/// Disks: the initial shells of the two-dimensional Maxwellian against the chi distribution
/// with 2 degrees of freedom, `P(|v| < r) = 1 - exp(-r^2/2)`, each of the 17 shells as above
/// (Bonferroni z = 4.0); and the density of histograms.csv's rule (weight over the ring's
/// area) against the reduced Maxwellian's weight over the same area (`phi_shell_in(2, ..)`).
#[test]
fn initial_shells_of_disks_are_the_planar_maxwellian() {
    use gdsmc_theory::exact::tail::{phi_shell_in, shell_volume_in};
    let st = initial_shells("disks-white-noise");
    assert_eq!(st.dimension, 2);
    let gdsmc_runner::run::ShellHistogram { radius, weights: h } = st.histogram.as_ref().unwrap();
    let chi2 = |r: f64| 1.0 - (-0.5 * r * r).exp();
    for k in 0..=16 {
        let lo = radius * k as f64 / 16.0;
        let hi = if k == 16 { f64::INFINITY } else { lo + 0.25 };
        let exact = chi2(hi) - chi2(lo);
        // The reduced Maxwellian of unit temperature, c = |v| / sqrt 2, gives the same weight.
        let s2 = 2f64.sqrt();
        assert!((phi_shell_in(2, lo / s2, hi / s2) - exact).abs() < 1e-15);
        let (m, ci) = (h.mean(k), h.ci(k));
        if exact > 1e-6 {
            assert!(
                (m - exact).abs() <= ci * 4.0 / multiplier(40),
                "shell {k}: {m} +- {ci}, exact {exact}"
            );
        }
        if k < 16 {
            let area = std::f64::consts::PI * (hi * hi - lo * lo);
            assert!((shell_volume_in(2, lo, hi) - area).abs() <= 1e-15 * area);
        }
    }
}
