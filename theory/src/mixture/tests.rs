//! The exact second moments of a Maxwell mixture against one species and their own limits.

use super::*;
use gdsmc_core::physics::Momentum;

/// One species of `n` particles, unit mass, start temperature 1.5.
fn one_species(n: usize, alpha: f64, kappa: f64, beta: f64) -> MaxwellMixture {
    MaxwellMixture {
        counts: vec![n],
        masses: vec![1.0],
        kappa: vec![kappa],
        alpha: vec![alpha],
        temperatures: vec![1.5],
        beta: vec![beta],
        momentum: Momentum::Drawn,
    }
}

/// One cooling species: the temperature about the flow velocity decays as GRW (13) with
/// beta = 0 (the flow velocity's expected square is conserved), from `(n - 1)/n` of the
/// start temperature.
#[test]
fn one_species_is_the_closed_form() {
    let (n, alpha, kappa) = (10usize, 0.5, 2.0);
    let mix = one_species(n, alpha, kappa, 0.0);
    for &t in &[0.0, 0.3, 2.0] {
        // E sum |v - V|^2 = (A - |Q|^2/n): d/dt = -(1 - alpha^2)/4 kappa/n (n A - |Q|^2)
        // and |Q|^2 is conserved, so (A - |Q|^2/n) decays at (1 - alpha^2)/4 kappa.
        // T = (A - |Q|^2/n)/(3n): E T(0) = 1.5 (n - 1)/n.
        let exact =
            1.5 * (n as f64 - 1.0) / n as f64 * libm::exp(-(1.0 - alpha * alpha) / 4.0 * kappa * t);
        let got = mix.temperatures_at(t, false)[0];
        assert!(
            (got - exact).abs() < 1e-12 * exact,
            "t = {t}: {got} vs {exact}"
        );
    }
}

/// One heated species: GRW (13), `T(t) = T_inf + (T0 - T_inf) e^{-k t}` with
/// `k = (1 - alpha^2)/4 kappa` and `T_inf = 2 beta / k`, for the temperature about the
/// flow velocity at finite n: `E T = (n-1)/n` of it (the flow velocity's own share).
#[test]
/// One heated species split: the same recurrence as the one-species closed form
/// (`MaxwellTemperature::splitting_bulk_mean`, RW Tables 3-4), Euler and Strang, to
/// rounding; and with no noise the splitting is the exact solution (the collision steps
/// compose).
fn one_species_splitting_is_the_closed_form() {
    let (n, alpha, kappa, beta) = (20usize, 0.5, 2.0, 0.7);
    let mix = one_species(n, alpha, kappa, beta);
    let mt = crate::exact::MaxwellTemperature::new(
        1.5,
        alpha,
        beta,
        1.0,
        kappa / (4.0 * std::f64::consts::PI),
    );
    for strang in [false, true] {
        for &t in &[0.5, 2.0, 6.0] {
            let got = mix.splitting_temperatures_at(t, 0.5, strang)[0];
            let exact = mt.splitting_bulk_mean(n, 0.5, strang, t);
            assert!(
                (got - exact).abs() < 1e-12 * exact,
                "strang {strang} t = {t}: {got} vs {exact}"
            );
        }
    }
    let cold = one_species(n, alpha, kappa, 0.0);
    let (a, b) = (
        cold.splitting_temperatures_at(3.0, 0.5, true)[0],
        cold.temperatures_at(3.0, false)[0],
    );
    assert!((a - b).abs() < 1e-12 * b, "{a} vs {b}");
}

#[test]
fn one_heated_species_is_grw_13() {
    let (n, alpha, kappa, beta) = (20usize, 0.5, 2.0, 0.7);
    let mix = one_species(n, alpha, kappa, beta);
    let k = (1.0 - alpha * alpha) / 4.0 * kappa;
    let t_inf = 2.0 * beta / k;
    for &t in &[0.0, 0.4, 3.0] {
        let exact = (n as f64 - 1.0) / n as f64 * (t_inf + (1.5 - t_inf) * libm::exp(-k * t));
        let got = mix.temperatures_at(t, false)[0];
        assert!(
            (got - exact).abs() < 1e-12 * exact,
            "t = {t}: {got} vs {exact}"
        );
    }
}

/// Two identical species are one species: the temperatures equal the one-species
/// closed form.
#[test]
fn two_equal_species_are_one() {
    let (alpha, kappa) = (0.7, 3.0);
    let mix = MaxwellMixture {
        counts: vec![4, 6],
        masses: vec![2.0, 2.0],
        kappa: vec![kappa; 3],
        alpha: vec![alpha; 3],
        temperatures: vec![1.0, 1.0],
        beta: vec![],
        momentum: Momentum::Drawn,
    };
    for &t in &[0.5, 1.5] {
        let ts = mix.temperatures_at(t, false);
        let one = MaxwellMixture {
            counts: vec![10],
            masses: vec![2.0],
            kappa: vec![kappa],
            alpha: vec![alpha],
            temperatures: vec![1.0],
            beta: vec![],
            momentum: Momentum::Drawn,
        }
        .temperatures_at(t, false)[0];
        let mixed = (4.0 * ts[0] + 6.0 * ts[1]) / 10.0;
        assert!((mixed - one).abs() < 1e-12, "{mixed} vs {one}");
    }
}
