//! MS: steady states of inelastic hard spheres under the three thermostats at alpha = 0.8,
//! reduced sizes (the paper: N = 2e5 particles, N' = 1e7 pairs, M = 1e3 samples).
//!
//! Per ensemble the observables are averaged over the steady state (t in [20, 100]); the means
//! over ensembles carry 99.9% confidence half-widths. Checks, each within that half-width
//! (plus the paper's last-digit rounding where a published number is used):
//! - mu4 from pairs (MS (67)) against MS Table 1's direct value;
//! - the exact steady-state relations: white noise mu4 = 5 mu2 (MS (23)), Gaussian
//!   mu4 = 5 (1 + a2) mu2 (MS (38));
//! - a2 against the Sonine estimate where MS finds it good: (10) for white noise (allowance
//!   0.001, the spread MS quotes between (10) and (32)); (40) for the Gaussian thermostat at
//!   alpha = 0.4, where MS find it better than (5), allowance 20% of a2 (the size of the
//!   first-Sonine errors MS report, Section 2.2 and 4);
//! - the constant force keeps a2 negative (MS Section 4.3), between the estimates (50) and (76)
//!   widened by MS's 20% remark.

use gdsmc_runner::run::columns::name;
use gdsmc_theory::exact::sonine::*;
use gdsmc_validation::*;

/// A steady run at alpha with n = 2048 (24 ensembles), or n = 8192 (8 ensembles) at strong
/// dissipation, where n = 2048 leaves a finite-n bias of about 0.5% in mu4 (measured: 11.43
/// at n = 2048, 11.487 +- 0.053 at n = 16384 for the Gaussian thermostat at alpha = 0.4;
/// MS: 11.494).
fn steady(name: &str, seed: u64, alpha: f64) -> (gdsmc_runner::run::RunStats, f64) {
    let (n, m) = if alpha < 0.5 { (8192, 8) } else { (2048, 24) };
    let mut s = shipped(name, n, m, seed);
    s.with_physics(|ph| ph.restitution = gdsmc_runner::scene::RestitutionLaw::Constant(alpha))
        .expect("a valid physics");
    s.set_collisional_pairs(20_000).unwrap();
    (run(&s), alpha)
}

fn get(st: &gdsmc_runner::run::RunStats, col: &str) -> (f64, f64) {
    st.steady
        .as_ref()
        .unwrap()
        .steady_mean_ci(st, st.col(col).unwrap())
}

#[test]
fn white_noise_alpha_08() {
    let (st, a) = steady("ms-white-noise", 1001, 0.8);
    assert_eq!(a, 0.8);
    let (mu2, c2) = get(&st, name::MU2);
    let (mu4, c4) = get(&st, name::MU4);
    assert!(
        (mu4 - 4.499).abs() <= c4 + 5e-4,
        "mu4 {mu4} +- {c4}, MS Table 1: 4.499"
    );
    assert!(
        (mu4 - 5.0 * mu2).abs() <= c4 + 5.0 * c2,
        "MS (23): mu4 {mu4} vs 5 mu2 {}",
        5.0 * mu2
    );
    assert!(
        (mu4 - mu4_maxwellian(a)).abs() > c4,
        "departure from the Maxwellian not resolved"
    );
    let (a2, ca) = get(&st, name::A2);
    let est = a2_white_noise_10(a);
    assert!(
        (a2 - est).abs() <= ca + 1e-3,
        "a2 {a2} +- {ca}, MS (10) {est}"
    );
}

#[test]
fn gaussian_alpha_04() {
    let (st, a) = steady("ms-gaussian", 1002, 0.4);
    let (mu2, c2) = get(&st, name::MU2);
    let (mu4, c4) = get(&st, name::MU4);
    let (a2, ca) = get(&st, name::A2);
    assert!(
        (mu4 - 11.494).abs() <= c4 + 5e-4,
        "mu4 {mu4} +- {c4}, MS Table 1: 11.494"
    );
    let indirect = 5.0 * (1.0 + a2) * mu2;
    let ci_indirect = 5.0 * (c2 * (1.0 + a2) + mu2 * ca);
    assert!(
        (mu4 - indirect).abs() <= c4 + ci_indirect,
        "MS (38): {mu4} vs {indirect}"
    );
    let e40 = a2_gaussian_40(a);
    assert!(
        (a2 - e40).abs() <= ca + 0.2 * e40.abs(),
        "a2 {a2} +- {ca}, MS (40) {e40}"
    );
}

#[test]
#[ignore = "long suite: cargo test --workspace --release -- --include-ignored (README, CI)"]
fn constant_force_alpha_08() {
    let (st, a) = steady("ms-constant-force", 1003, 0.8);
    let (mu4, c4) = get(&st, name::MU4);
    assert!(
        (mu4 - 3.335).abs() <= c4 + 5e-4,
        "mu4 {mu4} +- {c4}, MS Table 1: 3.335"
    );
    let (a2, ca) = get(&st, name::A2);
    assert!(a2 + ca < 0.0, "a2 {a2} +- {ca} must be negative");
    let (e50, e76) = (a2_constant_force_50(a), a2_constant_force_76(a));
    let (lo, hi) = (e50.min(e76) * 1.2, e50.max(e76) / 1.2);
    assert!(
        a2 - ca <= hi && a2 + ca >= lo,
        "a2 {a2} +- {ca} outside [{lo}, {hi}] ((50) {e50}, (76) {e76})"
    );
}

// MS Table 1 cell by cell (direct mu4 and the indirect routes (23), (38), (44) at all four
// alpha) is `gdsmc reproduce ms-table1`, run by CI in quick mode.

/// The same white-noise steady state from MS's own time-stepped scheme (h = 0.01 lambda / v0).
#[test]
#[ignore = "long suite: cargo test --workspace --release -- --include-ignored (README, CI)"]
fn white_noise_alpha_08_time_stepped() {
    let mut s = shipped("ms-white-noise", 2048, 16, 1400);
    s.with_physics(|ph| ph.scheme = gdsmc_runner::scene::SchemeChoice::TimeStepped(0.01))
        .expect("a valid physics");
    s.set_collisional_pairs(20_000).unwrap();
    let st = run(&s);
    let (mu4, c4) = get(&st, name::MU4);
    assert!(
        (mu4 - 4.499).abs() <= c4 + 5e-4,
        "mu4 {mu4} +- {c4}, MS Table 1: 4.499"
    );
    let (a2, ca) = get(&st, name::A2);
    let est = a2_white_noise_10(0.8);
    assert!(
        (a2 - est).abs() <= ca + 1e-3,
        "a2 {a2} +- {ca}, MS (10) {est}"
    );
}
