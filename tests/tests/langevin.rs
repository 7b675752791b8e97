//! The Langevin thermostat (drag `-gamma v`, white noise at the bath temperature `T_b`; the
//! exact Ornstein-Uhlenbeck step between collisions, `core/src/drive/langevin.rs`).
//!
//! - Maxwell gases, spheres and disks: the drive heats linearly (`a = 2 gamma T_b`,
//!   `b = p = -2 gamma`, [`gdsmc_core::drive::Heating`]), so `E T_bulk,n = (1 - 1/n) T(t)` with
//!   `T' = 2 gamma T_b - (2 gamma + k) T` (GRW (13) with the drive's rates) and the raw `T` adds
//!   `U/n`, `U' = 2 gamma T_b - 2 gamma U` (the bath drags the bulk velocity too): exact at
//!   finite n, through the no-splitting scheme and through Strang splitting.
//! - A mixture of elastic hard spheres started in equilibrium with the bath stays there: every
//!   grain's velocity is an independent Gaussian of variance `T_b / m` (the bath's stationary
//!   state, which elastic collisions keep), so `E T_s = T_b (1 - m_s / M)` exactly (`T_s` about
//!   the flow velocity, `M` the total mass), at every time. A bath acting with the wrong mass
//!   (variance `T_b` for every species) drives the heavy species to `m T_b`.

use gdsmc_runner::run::columns::name;
use gdsmc_stats::{dof, family};
use gdsmc_theory::curves::maxwell_temperature;
use gdsmc_validation::*;

/// A one-species Maxwell gas (GRW Example 3's kernel, alpha = 1/2: `k = 3/4`) in a bath of
/// friction 0.5 at `T_b = 2`, from `T_0 = 1` (so `T_inf = 2/1.75`), `n = 4`.
fn maxwell_scene(dimension: u32, scheme: &str, seed: u64) -> gdsmc_runner::scene::Scene {
    let text = format!(
        "[particles]\nn = 4\ndimension = {dimension}\ninitial = {{ kind = \"maxwellian\", temperature = 1.0 }}\n\
         [collisions]\nkernel = \"maxwell\"\ngamma = 4.0\nc = 0.07957747154594767\nrestitution = 0.5\n\
         [drive]\nkind = \"langevin\"\nfriction = 0.5\ntemperature = 2.0\n\
         [scheme]\n{scheme}\n\
         [observe]\nt_end = 4.0\nintervals = 8\n\
         [run]\nensembles = 100000\nseed = {seed}\n"
    );
    gdsmc_runner::scene::parse(std::path::Path::new("langevin.toml"), &text).expect("a valid scene")
}

/// The exact finite-n means of `T_bulk` and `T`, jointly at 99.9% over both columns and every
/// time (Bonferroni), n = 4, 100,000 ensembles, in d = 3 and d = 2. Power: the same check
/// refuses the means of a bath that kept the bulk velocity (`p = 0`, the raw `T`'s `U/n`
/// growing as white noise's does) and of one whose drag did not act (`b = 0`).
#[test]
fn maxwell_gases_in_a_langevin_bath_follow_their_exact_temperature() {
    for dimension in [3, 2] {
        let s = maxwell_scene(
            dimension,
            "kind = \"no-splitting\"",
            5400 + u64::from(dimension),
        );
        let n = s.n();
        let (mt, st, f) = assert_exact_maxwell_temperature(&s, &format!("d = {dimension}"));
        assert_eq!(
            (mt.heating.a, mt.heating.b, mt.heating.p),
            (2.0, -1.0, -1.0)
        );
        let mut kept = mt;
        kept.heating.p = 0.0;
        let kept = |t: f64| kept.finite_n_raw_mean(n, t);
        assert!(times_outside(&st, name::T, f, kept) >= st.times.len() - 3);
        let mut undragged = mt;
        undragged.heating.b = 0.0;
        let undragged = |t: f64| undragged.finite_n_bulk_mean(n, t);
        assert!(times_outside(&st, name::T_BULK, f, undragged) >= st.times.len() - 3);
    }
}

/// Strang splitting (RW Algorithm 2) with `dt = 1/2`: the kick multiplies `X = 3 n E T_bulk`
/// by `e^{b dt}` and adds `3 (n - 1) (a/b)(e^{b dt} - 1)`, the collisions multiply it by
/// `e^{-k dt}`, so the splitting's exact mean (`splitting_bulk_mean`) holds at every grid time,
/// jointly at 99.9%.
#[test]
fn strang_splitting_of_the_langevin_bath_has_its_exact_mean() {
    let s = maxwell_scene(3, "kind = \"strang\"\ndt = 0.5", 5410);
    let mt = maxwell_temperature(&s).expect("GRW (13) applies");
    let n = s.n();
    let st = run(&s);
    let f = family(st.times.len(), dof(st.ensembles));
    let exact = |t: f64| mt.splitting_bulk_mean(n, 0.5, true, t);
    assert_within_at_all_times(&st, name::T_BULK, f, exact, "Strang, dt = 1/2");
    // The splitting error is seen: the exact scheme's mean lies outside at most times.
    let exact_scheme = |t: f64| mt.finite_n_bulk_mean(n, t);
    assert!(times_outside(&st, name::T_BULK, f, exact_scheme) >= st.times.len() / 2);
}

/// Two species of elastic hard spheres (masses 1 and 4, two grains each: `M = 10`) started in
/// equilibrium with a bath at `T_b = 1.5`: `E T_s = T_b (1 - m_s/M)`, 1.35 and 0.9, at every
/// time, jointly over both species and every time at 99.9%. Power: the species' equilibrium
/// temperatures with a bath blind to mass (`T_s -> m_s T_b` for the heavy one) lie far outside.
#[test]
fn a_mixture_in_equilibrium_with_the_bath_stays_there() {
    let text = "[particles]\nn = 4\n\
        [[species]]\nname = \"light\"\nfraction = 0.5\nmass = 1.0\ntemperature = 1.5\ndiameter = 1.0\n\
        [[species]]\nname = \"heavy\"\nfraction = 0.5\nmass = 4.0\ntemperature = 1.5\ndiameter = 1.5\n\
        [collisions]\nkernel = \"hard-spheres\"\ngamma = 1.0\nc = 0.07957747154594767\nrestitution = 1.0\n\
        [drive]\nkind = \"langevin\"\nfriction = 1.0\ntemperature = 1.5\n\
        [observe]\nt_end = 4.0\nintervals = 8\n\
        [run]\nensembles = 40000\nseed = 5420\n";
    let s = gdsmc_runner::scene::parse(std::path::Path::new("langevin-mixture.toml"), text)
        .expect("a valid scene");
    let st = run(&s);
    let f = family(2 * st.times.len(), dof(st.ensembles));
    for (column, mass) in [("T_s0", 1.0), ("T_s1", 4.0)] {
        let exact = 1.5 * (1.0 - mass / 10.0);
        assert_within_at_all_times(&st, column, f, |_| exact, column);
    }
    // Blind to mass, the heavy species would settle near 4 T_b = 6: at the last times it is
    // not there, nor anywhere near.
    let last = st.times.len() - 1;
    let (m, c) = at(&st, last, "T_s1");
    assert!((m - 6.0).abs() > 100.0 * c, "T_s1 {m} +- {c}");
}
