//! The two forms of the inelastic Maxwell model, as the core declares a scene's kernel
//! (`KernelKind::uniform_impact`): GRW (3)'s scattering form, `e` uniform (Bobylev, Carrillo
//! and Gamba 2000; `theory/src/maxwell_cumulant.rs`), and Ernst and Brito's impact form, `n`
//! uniform (`theory/src/maxwell_impact.rs`). Each has its own moment coefficients, cooling
//! rate, `a2` and tail exponent; in `d = 2` they coincide. Every exact result of the Maxwell
//! gas reads its form here, so a run is never judged against the other model's numbers.

use crate::{maxwell_cumulant, maxwell_impact};
use gdsmc_scene::Scene;

/// A form of the inelastic Maxwell model (module docs).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Form {
    /// GRW (3): `e` uniform on the sphere.
    Scattering,
    /// Ernst and Brito: the impact direction `n` uniform, `e` its reflection of `u_hat`.
    Impact,
}

impl Form {
    /// The form of `scene`'s kernel, as the core declares it.
    #[must_use]
    pub fn of(scene: &Scene) -> Self {
        if scene.physics().kernel.kind().uniform_impact() {
            Form::Impact
        } else {
            Form::Scattering
        }
    }

    /// Its name in words, for summaries and docs.
    #[must_use]
    pub fn words(self) -> &'static str {
        match self {
            Form::Scattering => "GRW (3)'s scattering form, e uniform",
            Form::Impact => "Ernst and Brito's impact form, n uniform",
        }
    }

    /// `(lambda_2, lambda_4, b_4)` of `d mu_2/dt = -K lambda_2 mu_2`, `d mu_4/dt = K (-lambda_4
    /// mu_4 + b_4 mu_2^2)`, `K = 2 pi gamma C_0`.
    #[must_use]
    pub fn coefficients(self, d: usize, alpha: f64) -> (f64, f64, f64) {
        match self {
            Form::Scattering => maxwell_cumulant::coefficients(d, alpha),
            Form::Impact => maxwell_impact::coefficients(d, alpha),
        }
    }

    /// The energy's decay rate `K lambda_2` over `2 pi gamma C_0`: `(1 - alpha^2)/2` for the
    /// scattering form, `(1 - alpha^2)/d` for the impact form.
    #[must_use]
    pub fn lambda2(self, d: usize, alpha: f64) -> f64 {
        self.coefficients(d, alpha).0
    }

    /// The tail's rate `lambda_p` (exact at `p = 2, 4`).
    #[must_use]
    pub fn asymptotic_rate(self, d: usize, alpha: f64, p: f64) -> f64 {
        match self {
            Form::Scattering => maxwell_cumulant::asymptotic_rate(d, alpha, p),
            Form::Impact => maxwell_impact::asymptotic_rate(d, alpha, p),
        }
    }

    /// The cooling state's tail exponent `s` of `F(c) ~ c^-(d + s)` (Ernst and Brito 2002's
    /// method): the root above 2 of `lambda_p = p lambda_2 / 2`, by bisection on `[2, 200]`;
    /// infinite for the elastic gas.
    #[must_use]
    pub fn tail_exponent(self, d: usize, alpha: f64) -> f64 {
        let l2 = self.lambda2(d, alpha);
        let gap = |p: f64| self.asymptotic_rate(d, alpha, p) - p * l2 / 2.0;
        let (mut lo, mut hi) = (2.0 + 1e-9, 200.0);
        if gap(hi) >= 0.0 {
            return f64::INFINITY;
        }
        for _ in 0..80 {
            let mid = 0.5 * (lo + hi);
            if gap(mid) > 0.0 { lo = mid } else { hi = mid }
        }
        0.5 * (lo + hi)
    }

    /// The cooling state's `a2 = d r / (d + 2) - 1`, `r = b_4 / (lambda_4 - 2 lambda_2)`.
    #[must_use]
    pub fn cooling_state_a2(self, d: usize, alpha: f64) -> f64 {
        let (l2, l4, b4) = self.coefficients(d, alpha);
        let df = d as f64;
        df * b4 / ((df + 2.0) * (l4 - 2.0 * l2)) - 1.0
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use gdsmc_core::collision::inelastic::inelastic;
    use gdsmc_core::geometry::{Geometry, Spheres};
    use gdsmc_core::kernel::MaxwellImpact;
    use gdsmc_core::rng::seeded;

    /// In d = 2 the forms are one model: coefficients and tail rates agree.
    #[test]
    fn the_forms_coincide_for_disks() {
        for alpha in [0.0, 0.1, 0.5, 0.9, 1.0] {
            let (a, b) = (Form::Scattering, Form::Impact);
            let (x, y) = (a.coefficients(2, alpha), b.coefficients(2, alpha));
            for (p, q) in [(x.0, y.0), (x.1, y.1), (x.2, y.2)] {
                assert!((p - q).abs() < 1e-14, "alpha {alpha}: {x:?} {y:?}");
            }
            for p in [3.0, 5.5, 9.0] {
                let (r, s) = (
                    a.asymptotic_rate(2, alpha, p),
                    b.asymptotic_rate(2, alpha, p),
                );
                assert!((r - s).abs() < 1e-6, "alpha {alpha} p {p}: {r} {s}");
            }
        }
    }

    /// The impact form in d = 3: the tail rate is the moment equations' at p = 2 and 4 (two
    /// routes), a Maxwellian stays one when elastic, Santos's cooling-state a2 (Physica A 321,
    /// (5.6)) and the forms differ.
    #[test]
    fn the_impact_forms_closed_values() {
        let f = Form::Impact;
        for alpha in [0.1, 0.5, 0.9] {
            let (l2, l4, _) = f.coefficients(3, alpha);
            assert!((f.asymptotic_rate(3, alpha, 2.0) - l2).abs() < 1e-7);
            assert!((f.asymptotic_rate(3, alpha, 4.0) - l4).abs() < 1e-7);
            let santos = 6.0 * (1.0 - alpha).powi(2) / (12.0 - 7.0 + 3.0 * alpha * (2.0 - alpha));
            assert!(
                (f.cooling_state_a2(3, alpha) - santos).abs() < 1e-14,
                "{alpha}"
            );
            let scattering = Form::Scattering.cooling_state_a2(3, alpha);
            assert!((scattering - santos).abs() > 1e-3);
            assert!(
                (Form::Scattering.cooling_state_a2(3, alpha)
                    - maxwell_cumulant::cooling_state_a2(3, alpha))
                .abs()
                    < 1e-14
            );
        }
        let (_, l4, b4) = f.coefficients(3, 1.0);
        assert!((b4 / l4 - 5.0 / 3.0).abs() < 1e-14);
        assert!(f.tail_exponent(3, 1.0).is_infinite());
    }

    /// The impact form's coefficients against a Monte Carlo of the core's own map and its
    /// direction (`Spheres::scattering::<MaxwellImpact>`): independent isotropic scale mixtures
    /// of Gaussians (scales 0.5 and 1.5, `a2 = 0.64`), 400,000 pairs; the energy's and the
    /// fourth moment's mean change within their 99.9% intervals, jointly over the 6 checks
    /// (Bonferroni). The scattering form's coefficients are refused at alpha = 0.1, where
    /// `lambda_2` differs by a third (the check can tell the forms apart).
    #[test]
    fn the_impact_coefficients_are_the_cores_map() {
        const CHECKS: usize = 6;
        let mut rng = seeded(31);
        let scales: [f64; 2] = [0.5, 1.5];
        let mean = |p: i32| scales.iter().map(|s| s.powi(p)).sum::<f64>() / 2.0;
        let (mu2, mu4) = (3.0 * mean(2), 15.0 * mean(4));
        for alpha in [0.1, 0.5, 0.9] {
            let (mut s2, mut s4) = (Vec::new(), Vec::new());
            for i in 0..400_000 {
                let v = scales[i % 2] * Spheres::normal(&mut rng);
                let w = scales[(i / 2) % 2] * Spheres::normal(&mut rng);
                let e = Spheres::scattering::<MaxwellImpact, _>(v - w, &mut rng);
                let (a, b) = inelastic(v, w, e, alpha);
                s2.push(a.norm2() + b.norm2() - v.norm2() - w.norm2());
                s4.push(
                    a.norm2().powi(2) + b.norm2().powi(2) - v.norm2().powi(2) - w.norm2().powi(2),
                );
            }
            let (l2, l4, b4) = Form::Impact.coefficients(3, alpha);
            let s2 = gdsmc_stats::Sample::of(&s2);
            let s4 = gdsmc_stats::Sample::of(&s4);
            for (s, want) in [(&s2, -l2 * mu2), (&s4, -l4 * mu4 + b4 * mu2 * mu2)] {
                let h = s.joint_ci(CHECKS);
                assert!(
                    (s.mean - want).abs() <= h,
                    "alpha {alpha}: {} vs {want} +- {h}",
                    s.mean
                );
            }
            if alpha == 0.1 {
                let other = -Form::Scattering.lambda2(3, alpha) * mu2;
                assert!((s2.mean - other).abs() > s2.joint_ci(CHECKS));
            }
        }
    }
}
