//! The balance of MS's Gaussian thermostat: `F = m zeta (v - V)` (MS (12)) heats at
//! `dT/dt = 2 zeta T`, while inelastic collisions cool at a rate that grows with `T`, so a
//! constant `zeta` does not hold the temperature: it drives it to the `T*` where the two
//! balance (for the Maxwell kernel, whose cooling rate is proportional to `T`, there is no such
//! point and `T` grows or decays exponentially).
//!
//! The cooling rate is a Maxwellian gas's, `dT/dt = -kappa T^(1 + lambda/2)`
//! ([`crate::balance::cooling_constant`], in `d = 2` and 3): `kappa = pi gamma C
//! (1 - alpha^2)` for Maxwell molecules (GRW (13)'s rate) and `9.45 gamma C (1 - alpha^2)` for
//! hard spheres. The non-Gaussian correction (for hard particles `1 + 3 a2 / 16`, a fraction of
//! a percent at MS's `a2`) is left out: the figures are estimates for choosing `zeta`, not
//! references to judge a run by (the run's `T_bulk_sonine` curve has it). A Maxwell gas needs
//! none in any dimension: its exact `T` is GRW (13) times `e^{2 zeta t}`
//! (`curves::maxwell_temperature`).

use crate::balance::cooling_constant;
use gdsmc_scene::{DriveKind, RestitutionLaw, Scene};

/// The Gaussian thermostat of a scene against the collisional cooling of its kernel.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct GaussianBalance {
    /// The thermostat's rate `zeta` (MS (12)).
    pub zeta: f64,
    /// The cooling constant `kappa` of `dT/dt = -kappa T^(1 + lambda/2)` (Maxwellian
    /// estimate, module docs).
    pub kappa: f64,
    /// The kernel's exponent `lambda`.
    pub lambda: f64,
    /// The initial temperature.
    pub t0: f64,
}

impl GaussianBalance {
    /// The balance for a scene of smooth particles with a Gaussian thermostat and a constant
    /// restitution coefficient below 1 (else none), from its initial temperature.
    pub fn of(scene: &Scene) -> Option<Self> {
        // The balance is the smooth gas's cooling rate (MS (12)); a rough gas's translation
        // cools otherwise unless beta = -1.
        if !scene.translation_is_smooth() {
            return None;
        }
        let t0 = crate::initial::initial_temperature(scene);
        let zeta = scene
            .physics()
            .drive
            .params_of(DriveKind::Gaussian)?
            .get("zeta")?;
        let RestitutionLaw::Constant(alpha) = scene.physics().restitution else {
            return None;
        };
        let (gc, lambda) = scene.physics().kernel.power_law()?;
        let hard = scene.physics().kernel.kind().hard();
        let kappa = cooling_constant(scene.dimension(), hard, gc, lambda, alpha);
        (kappa > 0.0 && t0 > 0.0).then_some(GaussianBalance {
            zeta,
            kappa,
            lambda,
            t0,
        })
    }

    /// The temperature where heating and cooling balance, `(2 zeta / kappa)^(2 / lambda)`
    /// (none for the Maxwell kernel, or for `zeta <= 0`).
    pub fn steady_temperature(&self) -> Option<f64> {
        (self.lambda > 0.0 && self.zeta > 0.0)
            .then(|| libm::pow(2.0 * self.zeta / self.kappa, 2.0 / self.lambda))
    }

    /// The `zeta` that holds the initial temperature: `kappa T0^(lambda/2) / 2`.
    pub fn holding_zeta(&self) -> f64 {
        0.5 * self.kappa * libm::pow(self.t0, 0.5 * self.lambda)
    }

    /// One sentence for the summary: what the thermostat does to `T` and which `zeta` holds it.
    pub fn describe(&self) -> String {
        let hold = self.holding_zeta();
        let cooling = format!(
            "collisions cool at about {:.4} T^{} (Maxwellian estimate)",
            self.kappa,
            1.0 + 0.5 * self.lambda
        );
        let head = format!(
            "Gaussian thermostat zeta = {}: it heats at 2 zeta T, {cooling}",
            self.zeta
        );
        let fate = match self.steady_temperature() {
            Some(ts) => format!(
                "so T relaxes from {} toward T* = {:.4} whatever it starts at",
                self.t0, ts
            ),
            None => {
                let rate = 2.0 * self.zeta - self.kappa;
                format!("so T changes as exp({rate:.4} t): no temperature is steady")
            }
        };
        format!(
            "{head}, {fate}; zeta = {hold:.4} holds T = {}. The reduced distribution (a2, a3, tails) does not depend on zeta (MS Section 2.2: the homogeneous cooling state); T and the time scale do.",
            self.t0
        )
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::f64::consts::PI;

    fn scene(kernel: &str, zeta: f64, alpha: f64) -> Scene {
        let text = format!(
            "name = \"t\"\n[particles]\nn = 64\n[collisions]\nkernel = \"{kernel}\"\ngamma = 1.0\nc = 0.07957747154594767\nrestitution = {alpha}\n[drive]\nkind = \"gaussian\"\nzeta = {zeta}\n[observe]\nt_end = 1.0\nintervals = 1\n"
        );
        gdsmc_scene::parse(std::path::Path::new("t.toml"), &text).expect("valid scene")
    }

    #[test]
    fn maxwell_cooling_is_grw_13s_rate() {
        // GRW (13): T relaxes at gamma pi C0 (1 - alpha^2) without drive.
        let b = GaussianBalance::of(&scene("maxwell", 0.1, 0.5)).expect("gaussian");
        let c0 = 1.0 / (4.0 * PI);
        assert!((b.kappa - PI * c0 * 0.75).abs() < 1e-14 * b.kappa);
        assert_eq!(b.steady_temperature(), None);
        assert!((b.holding_zeta() - 0.5 * PI * c0 * 0.75).abs() < 1e-14);
    }

    #[test]
    fn hard_sphere_cooling_and_balance() {
        // E|u|^3 = 2^3 Gamma(3) / Gamma(3/2) T^(3/2) = 32 / sqrt(pi) T^(3/2) for u ~ N(0, 2T).
        let b = GaussianBalance::of(&scene("hard-spheres", 0.25, 0.8)).expect("gaussian");
        let gc = 1.0 / (4.0 * PI);
        let kappa = PI / 6.0 * gc * 0.36 * 32.0 / PI.sqrt();
        assert!((b.kappa - kappa).abs() < 1e-12 * kappa);
        let ts = b.steady_temperature().expect("hard spheres balance");
        // At T*, heating equals cooling.
        assert!((2.0 * 0.25 * ts - kappa * libm::pow(ts, 1.5)).abs() < 1e-12 * ts);
        // The holding zeta gives T* = T0.
        let mut hold = b;
        hold.zeta = b.holding_zeta();
        assert!((hold.steady_temperature().expect("balance") - 1.0).abs() < 1e-12);
        assert!(b.describe().contains("T* = 3.4"));
    }
}
