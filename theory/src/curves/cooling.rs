//! The references of the reduced cooling rate `zeta_star = zeta / nu` (the `zeta_star` column
//! of `observe.collisional_pairs`; gdsmc_core::observe::cooling), for a one-species smooth gas
//! with a constant restitution coefficient. Builders of [`super::registry`].
//!
//! - The Maxwell kernel: GRW (3) with `e` uniform changes a pair's energy by
//!   `-(1 - alpha^2) |u|^2 / 8` on average and every pair collides at the same rate, while the
//!   uniform pairs' `<|u|^2>` is `4 n/(n - 1)` times the energy per particle about the flow:
//!   `zeta* = (1 - alpha^2)/4 n/(n - 1)` for every state, in any dimension and under any drive
//!   (the drive is not a collision). Exact at n, as the estimate's mean. The impact form
//!   (`n` uniform) loses `(1 - alpha^2) |u|^2 / (4 d)`: `zeta* = (1 - alpha^2)/(2 d) n/(n - 1)`;
//!   both are `lambda_2 / 2 n/(n - 1)` of their form (`crate::maxwell_form::Form`).
//! - Hard particles at a Maxwellian of temperature `T`: over collisions (weighted by
//!   `|u . n|`) the normal relative speed has `<(u . n)^2> = 4 T`, so a collision loses
//!   `(1 - alpha^2) T` and `zeta* = (1 - alpha^2)/d`. The Maxwellian approximation (MS (5)'s
//!   Sonine correction moves it by `O(a2)`): shown, not judged.

use super::{Kind, ReferenceCurve};
use gdsmc_scene::Scene;

/// The constant curve `value` of `zeta_star`.
fn constant(name: &'static str, source: &'static str, kind: Kind, value: f64) -> ReferenceCurve {
    ReferenceCurve {
        name,
        of: "zeta_star",
        source,
        kind,
        curve: Box::new(move |_| value),
    }
}

/// The scene's constant coefficient when it observes the cooling (`observe.collisional_pairs`).
fn alpha(scene: &Scene) -> Option<f64> {
    (scene.collisional_pairs() > 0)
        .then(|| scene.physics().restitution.constant())
        .flatten()
}

/// `zeta_star_exact = lambda_2 / 2 n/(n - 1)` of the Maxwell model's form: `(1 - alpha^2)/4`
/// for GRW (3)'s scattering form, `(1 - alpha^2)/(2 d)` for the impact form (module docs).
pub(super) fn maxwell(scene: &Scene) -> Vec<ReferenceCurve> {
    let Some(a) = alpha(scene) else {
        return Vec::new();
    };
    let n = scene.n() as f64;
    let l2 = crate::maxwell_form::Form::of(scene).lambda2(scene.dimension(), a);
    let value = l2 / 2.0 * n / (n - 1.0);
    vec![constant(
        "zeta_star_exact",
        "zeta* of the Maxwell kernel",
        Kind::MeanAtN,
        value,
    )]
}

/// `zeta_star_MA = (1 - alpha^2)/d` of hard particles at a Maxwellian (module docs).
pub(super) fn hard_maxwellian(scene: &Scene) -> Vec<ReferenceCurve> {
    let Some(a) = alpha(scene) else {
        return Vec::new();
    };
    let d = scene.dimension() as f64;
    vec![constant(
        "zeta_star_MA",
        "zeta* of hard particles at a Maxwellian",
        Kind::Approximation,
        (1.0 - a * a) / d,
    )]
}

/// `zeta_star_nu0_sonine = (d + 2)/(4 d) (1 - alpha^2)(1 + 3 a2/16)`: the literature's
/// reduced cooling rate of hard particles (`zeta / nu_0`, Garzó and Dufty 1999 for spheres,
/// 5/12; Garzó's d-dimensional form, 1/2 for disks; the column `zeta_star_nu0`) to first
/// Sonine order, at the state's `a2` (MS (5) for a drive that only rescales, MS (10) for white
/// noise, in `d` dimensions: `super::sonine::state_a2`). An approximation.
pub(super) fn literature_sonine(scene: &Scene) -> Vec<ReferenceCurve> {
    let Some(a) = alpha(scene) else {
        return Vec::new();
    };
    let Some((a2, _)) = super::sonine::state_a2(scene, a) else {
        return Vec::new();
    };
    let d = scene.dimension() as f64;
    vec![ReferenceCurve {
        name: "zeta_star_nu0_sonine",
        of: crate::columns::LITERATURE_ZETA_STAR,
        source: "zeta* = zeta/nu_0 of hard particles to first Sonine order, (d + 2)/(4 d) (1 - alpha^2)(1 + 3 a2/16) (Garzó and Dufty 1999: 5/12 for spheres; 1/2 for disks; a2 of MS (5) or (10))",
        kind: Kind::Approximation,
        curve: Box::new(move |_| {
            (d + 2.0) / (4.0 * d) * (1.0 - a * a) * crate::balance::sonine_factor(a2)
        }),
    }]
}

#[cfg(test)]
mod tests {
    use crate::balance::{collision_rate, cooling_constant, nu0_hard};

    /// The energy balance's Maxwellian cooling constant (theory/src/balance.rs, derived there
    /// from the scattering of GRW (3)) over its Maxwellian collision rate is the `zeta*` these
    /// references state: `(1 - alpha^2)/d` for hard particles, `(1 - alpha^2)/4` for the
    /// Maxwell kernel (n -> infinity), in d = 2 and 3.
    #[test]
    fn the_values_are_the_energy_balance_per_collision() {
        let (alpha, t, gc): (f64, f64, f64) = (0.7, 1.3, 0.37);
        for d in [2, 3] {
            let hard = cooling_constant(d, true, gc, 1.0, alpha) * t.sqrt()
                / collision_rate(d, gc, 1.0, t);
            assert!(
                (hard - (1.0 - alpha * alpha) / d as f64).abs() < 1e-12,
                "d = {d}"
            );
            let maxwell =
                cooling_constant(d, false, gc, 0.0, alpha) / collision_rate(d, gc, 0.0, t);
            assert!(
                (maxwell - (1.0 - alpha * alpha) / 4.0).abs() < 1e-12,
                "d = {d}"
            );
        }
        // The literature's zeta* of hard particles at a Maxwellian: the Maxwellian cooling
        // rate over nu_0 is 5/12 (1 - alpha^2) for spheres (Garzó and Dufty 1999), 1/2 (1 -
        // alpha^2) for disks ((d + 2)/(4 d)).
        for (d, want) in [(3, 5.0 / 12.0), (2, 0.5)] {
            let literature =
                cooling_constant(d, true, gc, 1.0, alpha) * t.sqrt() / nu0_hard(d, gc, t);
            assert!(
                (literature - want * (1.0 - alpha * alpha)).abs() < 1e-12,
                "d = {d}"
            );
        }
        // nu_0 = 4 Omega_d / (sqrt(pi) (d + 2)) n sigma^(d-1) sqrt(T) with 4 pi gamma C the
        // pair rate's cross-section (pi sigma^2 n for spheres, 2 sigma n for disks).
        let pi = std::f64::consts::PI;
        let spheres = 16.0 * pi / (pi.sqrt() * 5.0) * (4.0 * gc) * t.sqrt();
        let disks = 8.0 * pi / (pi.sqrt() * 4.0) * (2.0 * pi * gc) * t.sqrt();
        assert!((nu0_hard(3, gc, t) / spheres - 1.0).abs() < 1e-12);
        assert!((nu0_hard(2, gc, t) / disks - 1.0).abs() < 1e-12);
    }
}
