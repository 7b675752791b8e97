//! A rough gas's reference curves: the Maxwellian approximation of its translational and
//! rotational temperatures.

use super::{Kind, ReferenceCurve};
use crate::columns::name;
use crate::initial::initial_temperature;
use gdsmc_scene::Scene;

/// The Maxwellian approximation of a rough gas (`theory/src/rough.rs`), when the scene is one.
pub fn rough_approximation(scene: &Scene) -> Option<crate::rough::RoughApproximation> {
    let r = scene.physics().rotation?;
    let alpha = scene.physics().restitution.constant()?;
    let (strength, lambda) = scene.physics().kernel.power_law()?;
    // The constant force's work depends on `E|v - V|` (MS (14)), which the approximation
    // does not follow, nor does it a host medium's encounters: no curve (they heat otherwise
    // than linearly).
    // A drive that heats the translation linearly (the core's declaration, `Heating`) is
    // `dT/dt = a + b T` in the approximation's equations: white noise `2 beta`, a thermostat
    // `2 zeta T`, a Langevin bath both.
    let h = scene.model().heating()?;
    let (beta, zeta) = (h.a / 2.0, h.b / 2.0);
    let mut ma = crate::rough::RoughApproximation::in_dimension(
        scene.dimension(),
        alpha,
        r.beta,
        r.kappa,
        strength,
        lambda,
        [beta, r.noise],
    );
    ma.thermostat = zeta;
    Some(ma)
}

/// A rough gas's Maxwellian-approximation curves: `T_bulk_MA` (the translational temperature),
/// `T_rot_MA` and `theta_MA`, solved from the scene's start.
pub(super) fn rough_curves(scene: &Scene) -> Vec<ReferenceCurve> {
    let (Some(ma), Some(r)) = (rough_approximation(scene), scene.physics().rotation) else {
        return Vec::new();
    };
    let t_end = scene.times().last().copied().unwrap_or(1.0);
    let src = "Maxwellian approximation (Huthmann and Zippelius 1997)";
    match crate::rough::RoughTrajectory::new(
        &ma,
        [initial_temperature(scene), r.temperature],
        t_end,
    ) {
        Ok(tr) => {
            let tr = std::sync::Arc::new(tr);
            let (a, b, c) = (tr.clone(), tr.clone(), tr);
            vec![
                ReferenceCurve {
                    name: "T_bulk_MA",
                    of: name::T_BULK,
                    source: src,
                    kind: Kind::Approximation,
                    curve: Box::new(move |t| a.at(t).0),
                },
                ReferenceCurve {
                    name: "T_rot_MA",
                    of: name::T_ROT,
                    source: src,
                    kind: Kind::Approximation,
                    curve: Box::new(move |t| b.at(t).1),
                },
                ReferenceCurve {
                    name: "theta_MA",
                    of: name::THETA,
                    source: src,
                    kind: Kind::Approximation,
                    curve: Box::new(move |t| {
                        let (x, y) = c.at(t);
                        y / x
                    }),
                },
            ]
        }
        Err(e) => {
            eprintln!("{src}: not integrated ({e})");
            Vec::new()
        }
    }
}
