//! Rough particles under BRS's impact-speed law (9): the normal restitution follows each
//! collision's normal impact speed `|g . n|` (the normal part of the contact velocity is that
//! of `v1 - v2`: the spins add only a tangential one).
//!
//! - The maps (one species and a pair of species) reverse the contact velocity's normal part
//!   with the law's coefficient at `|g . n|`, clamped to [0, 1] (a rounding bound: a few
//!   hundred ulps of the magnitudes), and count the clamped collisions.
//! - With `delta = 0` the law is the constant `alpha = 1 - 2 beta0` (BRS (9)), so a rough gas
//!   or a rough mixture under it follows the constant law's trajectory to the last bit
//!   (velocities, spins, counts), through the front door, for both kernels, spheres and disks,
//!   cooling, driven, split and time-stepped; with `delta > 0` it does not.
//! - With `beta = -1` the rough gas under the law is the smooth gas under it, to the bit
//!   (`rough::map::smooth_limit`), MS's time-stepped scheme included (its impact map).

use crate::common;

use common::kernels::{HARD, MAXWELL};
use common::strategies::{unit, vec3};
use gdsmc_core::engine::{CollisionMap, Counts, EventLoop};
use gdsmc_core::geometry::Spheres;
use gdsmc_core::kernel::HardSpheres;
use gdsmc_core::mixture::PairLaw;
use gdsmc_core::particles::{Particle, Particles, Spin};
use gdsmc_core::physics::{
    DimensionChoice, DriveChoice, KernelChoice, Physics, RestitutionLaw, RotationChoice,
    SchemeChoice, SpeciesChoice,
};
use gdsmc_core::restitution::ImpactSpeed;
use gdsmc_core::rng::{seeded, stream};
use gdsmc_core::rough::{RoughMap, RoughPairLaw};
use gdsmc_core::vec3::Vec3;
use proptest::prelude::*;

const EPS: f64 = f64::EPSILON;

/// BRS (9) at the normal impact speed `s`, clamped to [0, 1].
fn brs9(beta0: f64, delta: f64, s: f64) -> f64 {
    (1.0 - 2.0 * beta0 * s.powf(delta)).clamp(0.0, 1.0)
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(3000))]

    #[test]
    fn the_normal_contact_velocity_is_reversed_by_the_law_at_the_impact_speed(
        beta0 in 0.0f64..2.0, delta in 0.0f64..1.0, beta in -1.0f64..=1.0,
        kappa in 1e-2f64..=2.0 / 3.0, masses in (0.1f64..10.0, 0.1f64..10.0),
        v1 in vec3(10.0), w1 in vec3(10.0), v2 in vec3(10.0), w2 in vec3(10.0), n in unit(),
    ) {
        let law = ImpactSpeed::new(beta0, delta).unwrap();
        let g = RoughMap::contact_velocity(v1, w1, v2, w2, n);
        let c = g.dot(n);
        prop_assert!((c - (v1 - v2).dot(n)).abs() <= 64.0 * EPS * (v1.norm() + v2.norm()));
        let alpha = brs9(beta0, delta, c.abs());
        let scale = (v1.norm() + v2.norm() + w1.norm() + w2.norm()) / kappa;
        // One species.
        let one = RoughMap::new(0.5, beta, kappa).unwrap().with_law(law);
        let mut counts = Counts::default();
        let (a1, b1, a2, b2) = one.collide_counting(v1, w1, v2, w2, n, &mut counts);
        let g1 = RoughMap::contact_velocity(a1, b1, a2, b2, n);
        prop_assert!((g1.dot(n) + alpha * c).abs() <= 256.0 * EPS * scale, "{g1:?}, {alpha}");
        let clamped = 1.0 - 2.0 * beta0 * c.abs().powf(delta) < 0.0;
        prop_assert_eq!(counts.clamped, u64::from(clamped));
        // The closed-form energy change takes the same coefficient.
        let before = v1.norm2() + kappa * w1.norm2() + v2.norm2() + kappa * w2.norm2();
        let after = a1.norm2() + kappa * b1.norm2() + a2.norm2() + kappa * b2.norm2();
        let closed = one.energy_change(g, n);
        prop_assert!(((after - before) / 2.0 - closed).abs() <= 1e4 * EPS * scale * scale);
        // A pair of species: the same reversal, momentum kept.
        let (m1, m2) = masses;
        let pair = RoughPairLaw::new(0.5, beta, kappa, 0.4).unwrap().with_law(law).between(m1, m2);
        let (a1, b1, a2, b2) = pair.collide(v1, w1, v2, w2, n);
        let g1 = RoughMap::contact_velocity(a1, b1, a2, b2, n);
        let scale = scale * (m1 / m2 + m2 / m1);
        prop_assert!((g1.dot(n) + alpha * c).abs() <= 256.0 * EPS * scale, "{g1:?}, {alpha}");
        let p = (m1 * a1 + m2 * a2) - (m1 * v1 + m2 * v2);
        prop_assert!(p.norm() <= 64.0 * EPS * scale * (m1 + m2));
    }
}

/// Through the collision-map trait (the loops' door): a clamped coefficient is counted there
/// too, and the spins change.
#[test]
fn the_loops_door_counts_a_clamped_coefficient() {
    let law = ImpactSpeed::new(1.0, 0.5).unwrap(); // alpha < 0 from |g . n| > 1/4
    let map = RoughMap::new(0.9, 0.5, 0.4).unwrap().with_law(law);
    let mut v = [
        Particle::new(Vec3::new(3.0, 0.0, 0.0), 0.0),
        Particle::new(Vec3::new(-3.0, 0.0, 0.0), 0.0),
    ];
    let mut s = [Spin::default(); 2];
    let mut p = Particles::with_spins(&mut v, &mut s).unwrap();
    let (mut rng, mut counts) = (seeded(3), Counts::default());
    let mut clamped = 0;
    for _ in 0..200 {
        let (vi, vj) = (p.velocity(0), p.velocity(1));
        if (vi - vj).norm() < 1.0 {
            break;
        }
        let before = counts.clamped;
        map.collide_pair::<HardSpheres, Spheres, _>(
            &mut p,
            (0, 1),
            (vi, vj),
            &mut rng,
            &mut counts,
        );
        clamped += counts.clamped - before;
    }
    assert!(
        clamped > 0,
        "no collision of normal speed above 1/4 among 200"
    );
    assert!(p.spin(0).norm2() > 0.0);
}

/// A rough gas (`species` empty) or a rough mixture of `species` (count, mass) under `law`.
fn rough(
    species: &[(usize, f64)],
    kernel: KernelChoice,
    law: RestitutionLaw,
    (dimension, drive, scheme): (DimensionChoice, DriveChoice, SchemeChoice),
    beta: f64,
) -> Physics {
    let n = if species.is_empty() {
        150
    } else {
        species.iter().map(|s| s.0).sum()
    };
    let mut ph = Physics::new(n, kernel, law, drive, scheme);
    for (k, &(count, mass)) in species.iter().enumerate() {
        ph.species
            .push(SpeciesChoice {
                inertia: Some(0.2 + 0.2 * k as f64),
                beta: 0.5 + 0.5 * k as f64,
                ..SpeciesChoice::new(count, mass, 1.0 + k as f64)
            })
            .unwrap();
    }
    ph.dimension = dimension;
    ph.rotation = Some(RotationChoice {
        noise: if matches!(drive, DriveChoice::WhiteNoise(_)) {
            0.3
        } else {
            0.0
        },
        ..RotationChoice::uniform(dimension, beta)
    });
    ph
}

/// `T_raw` at every time, the final velocities and spins (bits), and the counts.
fn trajectory(ph: &Physics, times: &[f64]) -> (Vec<u64>, Counts) {
    common::trajectory(ph, 61, times)
}

#[test]
fn rough_particles_under_the_law_of_delta_0_follow_the_constant_law_to_the_last_bit() {
    use DimensionChoice::{Three, Two};
    let beta0 = 0.05;
    let times = [0.5, 1.0, 2.0, 4.0, 8.0];
    let (none, hot) = (DriveChoice::None, DriveChoice::WhiteNoise(0.2));
    let (exact, strang) = (SchemeChoice::NoSplitting, SchemeChoice::Strang(0.5));
    let mix: &[(usize, f64)] = &[(64, 1.0), (32, 3.0)];
    for (species, kernel, how) in [
        (&[][..], HARD, (Three, none, exact)),
        (&[][..], MAXWELL, (Three, hot, exact)),
        (&[][..], HARD, (Two, hot, strang)),
        (
            &[][..],
            HARD,
            (
                Three,
                DriveChoice::declared(gdsmc_core::physics::DriveKind::Gaussian, &[0.2]).unwrap(),
                strang,
            ),
        ),
        (&[][..], HARD, (Three, hot, SchemeChoice::TimeStepped(0.05))),
        (&[][..], HARD, (Two, none, SchemeChoice::TimeStepped(0.05))),
        (mix, HARD, (Three, none, exact)),
        (mix, MAXWELL, (Three, hot, exact)),
        (mix, HARD, (Two, hot, exact)),
        (
            mix,
            HARD,
            (
                Three,
                DriveChoice::declared(gdsmc_core::physics::DriveKind::Gaussian, &[0.2]).unwrap(),
                strang,
            ),
        ),
    ] {
        let constant = rough(
            species,
            kernel,
            RestitutionLaw::Constant(1.0 - 2.0 * beta0),
            how,
            0.4,
        );
        let impact = RestitutionLaw::ImpactSpeed { beta0, delta: 0.0 };
        let (a, ca) = trajectory(&constant, &times);
        let (b, cb) = trajectory(&rough(species, kernel, impact, how, 0.4), &times);
        let n = constant.n as u64;
        assert!(
            ca.collisions > 2 * n,
            "{species:?}, {kernel:?}, {how:?}: {ca:?}"
        );
        assert_eq!((&a, ca), (&b, cb), "{species:?}, {kernel:?}, {how:?}");
        // The law acts: a speed-dependent coefficient leaves the constant's trajectory.
        let moving = RestitutionLaw::ImpactSpeed { beta0, delta: 0.5 };
        let (c, _) = trajectory(&rough(species, kernel, moving, how, 0.4), &times);
        assert_ne!(
            c, a,
            "{species:?}, {kernel:?}, {how:?}: delta = 0.5 changed nothing"
        );
    }
}

#[test]
fn rough_particles_with_beta_minus_one_under_the_law_are_smooth_to_the_last_bit() {
    use DimensionChoice::{Three, Two};
    let law = RestitutionLaw::ImpactSpeed {
        beta0: 0.1,
        delta: 0.2,
    };
    let times = [0.5, 1.0, 2.0, 4.0, 8.0];
    let mix: &[(usize, f64)] = &[(64, 1.0), (32, 3.0)];
    let cooling = DriveChoice::None;
    for (species, kernel, how) in [
        // (Not hard spheres cooling: the smooth gas takes the sum-form majorant there.)
        (
            &[][..],
            MAXWELL,
            (Three, cooling, SchemeChoice::NoSplitting),
        ),
        (
            &[][..],
            MAXWELL,
            (
                Three,
                DriveChoice::WhiteNoise(0.2),
                SchemeChoice::Euler(0.5),
            ),
        ),
        (&[][..], HARD, (Two, cooling, SchemeChoice::NoSplitting)),
        (
            &[][..],
            HARD,
            (Three, cooling, SchemeChoice::TimeStepped(0.05)),
        ),
        (
            &[][..],
            HARD,
            (
                Two,
                DriveChoice::WhiteNoise(0.2),
                SchemeChoice::TimeStepped(0.05),
            ),
        ),
        (mix, HARD, (Three, cooling, SchemeChoice::NoSplitting)),
        (
            mix,
            HARD,
            (
                Two,
                DriveChoice::declared(gdsmc_core::physics::DriveKind::Gaussian, &[0.2]).unwrap(),
                SchemeChoice::Strang(0.5),
            ),
        ),
    ] {
        let mut r = rough(species, kernel, law, how, -1.0);
        // No rotational noise (its kicks draw numbers the smooth gas does not).
        r.rotation = r.rotation.map(|c| RotationChoice { noise: 0.0, ..c });
        let mut s = r.clone();
        s.rotation = None;
        for c in s.species.iter_mut() {
            c.inertia = None;
        }
        let (model_r, model_s) = (r.validate().unwrap(), s.validate().unwrap());
        let n = model_r.n();
        let (mut a, mut b) = (vec![Particle::default(); n], vec![Particle::default(); n]);
        let mut spins = vec![Spin::default(); n];
        let mut pa = Particles::new(&mut a).unwrap();
        let mut pb = Particles::with_spins(&mut b, &mut spins).unwrap();
        let (mut ra, mut rb) = (stream(5, 0), stream(5, 0));
        let (mut es, _) = model_s.launch(&mut pa, 0.0, &mut ra).unwrap();
        let (mut er, _) = model_r.launch(&mut pb, 0.0, &mut rb).unwrap();
        for &t in &times {
            let oa = es.advance_to(&mut pa, t, &mut ra).unwrap();
            let ob = er.advance_to(&mut pb, t, &mut rb).unwrap();
            assert_eq!(oa, ob, "{species:?}, {how:?}, t = {t}");
            assert_eq!(es.counts(), er.counts(), "{species:?}, {how:?}, t = {t}");
        }
        assert!(
            es.counts().collisions > 2 * n as u64,
            "{species:?}, {how:?}"
        );
    }
}
