//! The curves of the smooth gas's energy balance and Sonine estimates: Haff's law and its
//! heated forms (`theory/src/balance.rs`) for `T_bulk`, and MS's first-Sonine `a2` of the
//! cooling state (MS (5), (40)), the white-noise state (MS (10), (32)) and the constant-force
//! state (MS (50), (76)). All are approximations: shown beside the run, not judged. Each is a
//! builder of [`super::registry`], called where its declaration holds.

use super::holds::Drive;
use super::{Kind, ReferenceCurve};
use crate::balance::{EnergyBalance, cooling_constant, sonine_factor};
use crate::columns::name;
use crate::exact::sonine;
use crate::initial::initial_temperature;
use gdsmc_scene::{DriveKind, Scene};
use std::sync::Arc;

/// The first-Sonine `a2` of a hard-particle gas's steady state under its drive, with the
/// equation it is: MS (5) for the cooling state (a drive that only rescales the velocities, as
/// it declares: none, the Gaussian thermostat, a drag; MS Section 2.2), MS (10) for white noise
/// (both in `d` dimensions); none for a drive whose state MS do not give.
pub(super) fn state_a2(scene: &Scene, alpha: f64) -> Option<(f64, &'static str)> {
    let d = scene.dimension() as f64;
    if Drive::Rescaling.of(scene) {
        Some((sonine::a2_cooling_in(d, alpha), "MS (5)"))
    } else if Drive::Is(DriveKind::WhiteNoise).of(scene) {
        Some((sonine::a2_white_noise_10_in(d, alpha), "MS (10)"))
    } else {
        None
    }
}

/// Haff's law and its heated forms for `T_bulk`: for hard particles `T_bulk_sonine` with the
/// first Sonine correction `1 + 3 a2/16` at the state's `a2` ([`state_a2`]), the better of the
/// two and so the first; `T_bulk_MA` with a Maxwellian's cooling rate.
pub(super) fn curves(scene: &Scene) -> Vec<ReferenceCurve> {
    let ph = scene.physics();
    let (Some(alpha), Some(heating)) = (ph.restitution.constant(), scene.model().heating()) else {
        return Vec::new();
    };
    // Power-law results: a kernel that is no power law has none.
    let Some((gc, lambda)) = ph.kernel.power_law() else {
        return Vec::new();
    };
    let hard = ph.kernel.kind().hard();
    let kappa = cooling_constant(scene.dimension(), hard, gc, lambda, alpha);
    let t_end = scene.times().last().copied().unwrap_or(1.0);
    let balance = EnergyBalance {
        t0: initial_temperature(scene),
        kappa,
        q: 1.0 + 0.5 * lambda,
        heating,
    };
    let mut out = Vec::new();
    let mut push = |name: &'static str, source: &'static str, b: EnergyBalance| match b.solve(t_end)
    {
        Ok(tr) => {
            let tr = Arc::new(tr);
            out.push(ReferenceCurve {
                name,
                of: name::T_BULK,
                source,
                kind: Kind::Approximation,
                curve: Box::new(move |t| tr.at(t)),
            });
        }
        Err(e) => eprintln!("{source}: not integrated ({e})"),
    };
    if let Some((a2, _)) = hard.then(|| state_a2(scene, alpha)).flatten() {
        push(
            "T_bulk_sonine",
            "Haff's law with the first Sonine cooling rate (1 + 3 a2/16) at the state's a2 (MS (5) or (10), van Noije and Ernst 1998); an approximation, once the gas has relaxed",
            EnergyBalance {
                kappa: kappa * sonine_factor(a2),
                ..balance
            },
        );
    }
    push(
        "T_bulk_MA",
        "Haff's law: the energy balance at a Maxwellian's cooling rate, the drive's heating added (theory/src/balance.rs); an approximation",
        balance,
    );
    out
}

/// A constant `a2` curve of one of MS's estimates at the scene's restitution.
fn a2_line(
    scene: &Scene,
    name: &'static str,
    source: &'static str,
    a2: impl Fn(f64, f64) -> f64,
) -> Vec<ReferenceCurve> {
    let Some(alpha) = scene.physics().restitution.constant() else {
        return Vec::new();
    };
    let v = a2(scene.dimension() as f64, alpha);
    vec![ReferenceCurve {
        name,
        of: name::A2,
        source,
        kind: Kind::Approximation,
        curve: Box::new(move |_| v),
    }]
}

/// MS (5) in `d` dimensions (van Noije and Ernst 1998): the cooling state's and the Gaussian
/// thermostat's `a2` (`a2_sonine`).
pub(super) fn a2_ms5(scene: &Scene) -> Vec<ReferenceCurve> {
    a2_line(
        scene,
        "a2_sonine",
        "van Noije and Ernst 1998, first Sonine approximation of the cooling state in d dimensions (MS (5)); an approximation, reached once the gas has relaxed",
        sonine::a2_cooling_in,
    )
}

/// MS (40): the cooling state's `a2` by the other route, better below `alpha = 0.5`.
pub(super) fn a2_ms40(scene: &Scene) -> Vec<ReferenceCurve> {
    a2_line(
        scene,
        "a2_ms40",
        "MS (40), first Sonine approximation of the cooling state (Gaussian thermostat), better than MS (5) for alpha < 0.5; an approximation",
        sonine::a2_gaussian_40_in,
    )
}

/// MS (10): the white-noise state's `a2`.
pub(super) fn a2_ms10(scene: &Scene) -> Vec<ReferenceCurve> {
    a2_line(
        scene,
        "a2_ms10",
        "MS (10), first Sonine approximation of the white-noise state (van Noije and Ernst 1998); an approximation, reached once the gas has relaxed",
        sonine::a2_white_noise_10_in,
    )
}

/// MS (32): the white-noise state's `a2` by the other linearization.
pub(super) fn a2_ms32(scene: &Scene) -> Vec<ReferenceCurve> {
    a2_line(
        scene,
        "a2_ms32",
        "MS (32), the white-noise state's a2 by the other linearization (within 0.001 of MS (10)); an approximation",
        sonine::a2_white_noise_32_in,
    )
}

/// MS (50): the constant-force state's `a2`.
pub(super) fn a2_ms50(scene: &Scene) -> Vec<ReferenceCurve> {
    a2_line(
        scene,
        "a2_ms50",
        "MS (50), first Sonine approximation of the constant-force state (about 20% too small in magnitude, MS); an approximation",
        sonine::a2_constant_force_50_in,
    )
}

/// MS (76): the constant-force state's `a2`, fitted by MS to their simulations (`d = 3`).
pub(super) fn a2_ms76(scene: &Scene) -> Vec<ReferenceCurve> {
    a2_line(
        scene,
        "a2_ms76",
        "MS (76), the constant-force state's a2 improved from MS's simulations (d = 3); an approximation",
        |_, a| sonine::a2_constant_force_76(a),
    )
}
