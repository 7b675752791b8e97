//! The engines' invariants as property tests: collisions keep the total momentum exactly (and,
//! elastic, the energy) up to a rounding bound; the drives move the moments exactly as their
//! solutions say (the Gaussian thermostat MS (61) scales the peculiar energy by e^{2 zeta h},
//! the constant force keeps the bulk velocity MS (62), white noise GRW (18) adds 3 (2 beta h)
//! to the mean square speed, checked statistically).
//!
//! Rounding bounds: one collision changes `v_i + v_j` by at most 16 ulps of `|v_i| + |v_j|`
//! and the energy by at most 64 ulps of `|v_i|^2 + |v_j|^2` (core/tests/collision_maps.rs);
//! over C collisions the errors add, and no speed exceeds `sqrt(2 E)` (E the total energy over
//! unit masses, which collisions never increase), so the totals are bounded by
//! `32 C eps sqrt(2 E)` and `64 C eps E`.

use gdsmc_core::drive::{ConstantForce, Drive, GaussianThermostat, NoDrive, WhiteNoise};
use gdsmc_core::engine::NoSplitting;
use gdsmc_core::kernel::{HardSpheres, Kernel, Maxwell, Vhs};
use gdsmc_core::moments::Observables;
use gdsmc_core::particles::{Particle, Particles};
use gdsmc_core::restitution::Constant;
use gdsmc_core::rng::seeded;
use gdsmc_core::sample::Maxwellian;
use gdsmc_core::vec3::Vec3;
use proptest::prelude::*;

fn momentum_energy(p: &Particles<'_>) -> (Vec3, f64) {
    let mut m = Vec3::ZERO;
    let mut e = 0.0;
    for q in p.as_slice() {
        m += q.velocity();
        e += q.velocity().norm2();
    }
    (m, e)
}

/// `n` particles from the unit Maxwellian drifting along x at `drift`, all at time 0.
fn drifting_maxwellian(n: usize, drift: f64, seed: u64) -> Vec<Particle> {
    let mut rng = seeded(seed);
    let f0 = Maxwellian::new(1.0, 1.0, Vec3::new(drift, 0.0, 0.0)).unwrap();
    (0..n)
        .map(|_| Particle::new(f0.sample(&mut rng), 0.0))
        .collect()
}

/// A cooling run of `n` particles to time `t`: momentum kept for any alpha, energy for alpha = 1.
fn collisions_keep<K: Kernel>(kernel: K, n: usize, alpha: f64, drift: f64, seed: u64, t: f64) {
    let mut buf = drifting_maxwellian(n, drift, seed);
    let mut p = Particles::new(&mut buf).unwrap();
    let mut rng = seeded(seed ^ 1);
    let (m0, e0) = momentum_energy(&p);
    let law = Constant::new(alpha).unwrap();
    let (mut e, _) = NoSplitting::start(kernel, NoDrive, law, &mut p, 0.0).unwrap();
    // No rescaling: the stored velocities are the physical ones, so their sums are compared.
    e.set_rescale_below(0.0);
    e.advance_to(&mut p, t, &mut rng).unwrap();
    let c = e.counts().collisions as f64;
    assert!(
        n < 8 || c > 0.0,
        "no collision: the test would check nothing"
    );
    let (m1, e1) = momentum_energy(&p);
    let eps = f64::EPSILON;
    let bound_m = 32.0 * (c + 1.0) * eps * (2.0 * e0).sqrt();
    assert!(
        (m1 - m0).norm() <= bound_m,
        "momentum {m0:?} -> {m1:?} after {c} collisions"
    );
    assert!(
        e1 <= e0 + 64.0 * (c + 1.0) * eps * e0,
        "energy gained: {e0} -> {e1}"
    );
    if alpha == 1.0 {
        assert!(
            (e1 - e0).abs() <= 64.0 * (c + 1.0) * eps * e0,
            "energy {e0} -> {e1} ({c})"
        );
    }
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(96))]

    #[test]
    fn collisions_keep_momentum_and_elastic_energy(
        n in 2usize..96,
        alpha in prop_oneof![Just(1.0), 0.05f64..=1.0],
        drift in prop_oneof![Just(0.0), -1e3f64..1e3],
        seed in any::<u64>(),
        kernel in 0u8..3,
    ) {
        let c = 0.25 / std::f64::consts::PI;
        match kernel {
            0 => collisions_keep(Maxwell::new(4.0, c).unwrap(), n, alpha, drift, seed, 2.0),
            1 => collisions_keep(HardSpheres::new(1.0, c).unwrap(), n, alpha, drift, seed, 2.0),
            _ => collisions_keep(Vhs::new(1.0, c, 0.5).unwrap(), n, alpha, drift, seed, 2.0),
        }
    }

    #[test]
    fn gaussian_thermostat_scales_the_peculiar_energy_exactly(
        n in 2usize..200,
        zeta in -2.0f64..2.0,
        h in 0.0f64..3.0,
        drift in -10.0f64..10.0,
        seed in any::<u64>(),
    ) {
        let mut buf = drifting_maxwellian(n, drift, seed);
        let mut p = Particles::new(&mut buf).unwrap();
        let mut rng = seeded(seed ^ 1);
        let before = Observables::of(&p);
        let mut d = GaussianThermostat::new(zeta).unwrap();
        d.observe(&before);
        d.kick_all(&mut p, h, &mut rng);
        let after = Observables::of(&p);
        let want = (2.0 * zeta * h).exp() * before.t_bulk;
        // Each velocity: a subtraction, a product and an addition about the bulk, then the
        // sums: relative error a few hundred ulps of the kinetic energy's scale (|V|^2 + T).
        let scale = (before.bulk.norm2() + before.t_bulk) * (2.0 * zeta * h).exp().max(1.0);
        prop_assert!((after.t_bulk - want).abs() <= 512.0 * f64::EPSILON * scale * n as f64,
            "T_bulk {} -> {}, want {}", before.t_bulk, after.t_bulk, want);
        prop_assert!((after.bulk - before.bulk).norm() <= 64.0 * f64::EPSILON * (before.bulk.norm() + scale.sqrt()),
            "bulk {:?} -> {:?}", before.bulk, after.bulk);
    }

    #[test]
    fn constant_force_keeps_the_bulk_velocity(
        n in 2usize..200,
        g in 0.0f64..10.0,
        h in 0.0f64..2.0,
        drift in -10.0f64..10.0,
        seed in any::<u64>(),
    ) {
        let mut buf = drifting_maxwellian(n, drift, seed);
        let mut p = Particles::new(&mut buf).unwrap();
        let mut rng = seeded(seed ^ 1);
        let before = Observables::of(&p);
        let mut d = ConstantForce::new(g).unwrap();
        d.observe(&before);
        d.kick_all(&mut p, h, &mut rng);
        let after = Observables::of(&p);
        // MS (62): the increments g h (c_hat_i - k) sum to zero.
        let scale = before.bulk.norm() + before.t_bulk.sqrt() + g * h;
        prop_assert!((after.bulk - before.bulk).norm() <= 64.0 * f64::EPSILON * scale * n as f64,
            "bulk {:?} -> {:?}", before.bulk, after.bulk);
    }
}

proptest! {
    /// The constant force pushes along the peculiar velocity `c = v - V`: a gas given a drift
    /// `u` is kicked as the gas at rest, shifted by `u` (before the force took `c` it pushed
    /// along `v`, and a drifting gas heated less: `T_bulk` 0.40 at `t = 10` against 1.01 at rest
    /// with `V = (3, 0, 0)`, g = 0.25). Rounding: a few ulps of `|u| + |v| + g h` per component.
    #[test]
    fn the_constant_force_is_the_same_in_every_frame(
        n in 2usize..100,
        g in 0.0f64..10.0,
        h in 0.0f64..2.0,
        u in (-10.0f64..10.0, -10.0f64..10.0, -10.0f64..10.0),
        seed in any::<u64>(),
    ) {
        let u = Vec3::new(u.0, u.1, u.2);
        let mut rest = drifting_maxwellian(n, 0.0, seed);
        let mut moving: Vec<Particle> =
            rest.iter().map(|q| Particle::new(q.velocity() + u, 0.0)).collect();
        let mut rng = seeded(seed ^ 1);
        let mut kick = |buf: &mut [Particle]| {
            let mut p = Particles::new(buf).unwrap();
            let mut d = ConstantForce::new(g).unwrap();
            d.observe(&Observables::of(&p));
            d.kick_all(&mut p, h, &mut rng);
        };
        kick(&mut rest);
        kick(&mut moving);
        for (a, b) in rest.iter().zip(&moving) {
            let scale = u.norm() + a.velocity().norm() + g * h + 1.0;
            let d = (b.velocity() - u) - a.velocity();
            prop_assert!(d.norm() <= 1024.0 * f64::EPSILON * scale, "{d:?}");
        }
    }
}

/// White noise GRW (18) adds `3 (2 beta h)` to the mean square speed: checked at 8 fixed seeds,
/// together at the 99.9% level (Bonferroni over 8, `joint`), with the sample's own standard error.
#[test]
fn white_noise_adds_its_exact_mean_square() {
    let (n, beta, h) = (20_000, 0.7, 0.3);
    for seed in 0..8u64 {
        let mut buf = vec![Particle::default(); n];
        let mut p = Particles::new(&mut buf).unwrap();
        let mut rng = seeded(100 + seed);
        let f0 = Maxwellian::standard();
        p.fill_with(0.0, || f0.sample(&mut rng));
        let before: Vec<f64> = p.as_slice().iter().map(|q| q.velocity().norm2()).collect();
        WhiteNoise::new(beta).unwrap().kick_all(&mut p, h, &mut rng);
        let gain: Vec<f64> = p
            .as_slice()
            .iter()
            .zip(&before)
            .map(|(q, b)| q.velocity().norm2() - b)
            .collect();
        let s = gdsmc_stats::Sample::of(&gain);
        let (m, z) = (s.mean, s.joint_ci(8));
        let want = 3.0 * 2.0 * beta * h;
        assert!(
            (m - want).abs() <= z,
            "seed {seed}: mean gain {m} +- {z}, exact {want}"
        );
    }
}
