//! MS (64)-(67): the pair estimator of mu_2 and mu_4 at the Maxwellian must give MS (27), (29):
//! mu_2^(0) = sqrt(2 pi)(1 - alpha^2), mu_4^(0) = (9/2 + alpha^2) mu_2^(0) (MS Table 1's first
//! column: 10.925 at alpha = 0.2). Tolerance: 3.2 standard errors of the pair average.

use gdsmc_core::collisional::*;
use gdsmc_core::moments::Observables;
use gdsmc_core::particles::{Particle, Particles};
use gdsmc_core::rng::seeded;
use gdsmc_core::sample::Maxwellian;
use gdsmc_core::vec3::Vec3;
use gdsmc_stats::LAMBDA_999;

#[test]
fn maxwellian_collisional_moments() {
    let mut rng = seeded(41);
    let mx = Maxwellian::new(1.0, 0.7, Vec3::new(0.3, 0.0, -0.1)).unwrap();
    let mut q: Vec<Particle> = (0..400_000)
        .map(|_| Particle::new(mx.sample(&mut rng), 0.0))
        .collect();
    let p = Particles::new(&mut q).unwrap();
    let o = Observables::of(&p);
    for alpha in [0.2, 0.4, 0.6, 0.8] {
        let pairs = 2_000_000u64;
        // The per-pair spread: sample it to bound the error of the average.
        let (mut m2, mut v2, mut m4, mut v4) = (0.0, 0.0, 0.0, 0.0);
        let v0 = (2.0 * o.t_bulk).sqrt();
        let mut r2 = seeded(42);
        for _ in 0..20_000 {
            let (i, j) = gdsmc_core::rng::uniform_pair(&mut r2, p.len());
            let (vi, vj) = (p.velocity(i) - o.bulk, p.velocity(j) - o.bulk);
            let a = phi2(vi, vj, alpha) / v0.powi(3);
            let b = phi4(vi, vj, alpha) / v0.powi(5);
            m2 += a;
            v2 += a * a;
            m4 += b;
            v4 += b * b;
        }
        let k = 20_000.0;
        let sd2 = (v2 / k - (m2 / k).powi(2)).sqrt();
        let sd4 = (v4 / k - (m4 / k).powi(2)).sqrt();
        let (mu2, mu4) = collisional_moments(&p, o.bulk, o.t_bulk, alpha, pairs, &mut rng);
        let mu2_0 = (2.0 * std::f64::consts::PI).sqrt() * (1.0 - alpha * alpha);
        let mu4_0 = (4.5 + alpha * alpha) * mu2_0;
        // Standard error of the pair average, plus the sample's own finite-n fluctuation of T
        // (relative sd sqrt(2/(3n)), entering mu_p as v0^-(p+1)).
        let t_rel = LAMBDA_999 * (2.0 / (3.0 * p.len() as f64)).sqrt();
        let tol2 = LAMBDA_999 * sd2 / (pairs as f64).sqrt() + 1.5 * t_rel * mu2_0;
        let tol4 = LAMBDA_999 * sd4 / (pairs as f64).sqrt() + 2.5 * t_rel * mu4_0;
        assert!(
            (mu2 - mu2_0).abs() < tol2,
            "alpha {alpha}: mu2 {mu2} vs {mu2_0} +- {tol2}"
        );
        assert!(
            (mu4 - mu4_0).abs() < tol4,
            "alpha {alpha}: mu4 {mu4} vs {mu4_0} +- {tol4}"
        );
    }
    assert!(
        (10.925 - (4.5f64 + 0.04) * (2.0 * std::f64::consts::PI).sqrt() * 0.96).abs() < 5e-4,
        "MS Table 1, mu4^(0) at 0.2"
    );
}
