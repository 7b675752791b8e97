//! Property tests of the mixture's collision map (`mixture::MassRatio`, GRW (3) in the
//! centre-of-mass frame) and of the mixture loop's invariants. Tolerances are rounding bounds:
//! a few ulps of the largest magnitude involved (as in collision_maps.rs, with the masses).

use gdsmc_core::collision::inelastic;
use gdsmc_core::drive::NoDrive;
use gdsmc_core::kernel::{HardSpheres, Kernel, Maxwell, Vhs};
use gdsmc_core::mixture::{MassRatio, MixtureNoSplitting, PairPhysics, Species};
use gdsmc_core::particles::{Particle, Particles};
use gdsmc_core::restitution::Constant;
use gdsmc_core::rng::seeded;
use gdsmc_core::sample::Maxwellian;
use gdsmc_core::vec3::Vec3;
use proptest::prelude::*;

use crate::common;

use common::strategies::{alpha, unit, vec3};

fn mass() -> impl Strategy<Value = f64> {
    prop_oneof![Just(1.0), 1e-3f64..1e3]
}

const EPS: f64 = f64::EPSILON;

proptest! {
    #![proptest_config(ProptestConfig::with_cases(4000))]

    #[test]
    fn the_map_keeps_momentum(v in vec3(1e3), w in vec3(1e3), e in unit(), a in alpha(), ms in mass(), mt in mass()) {
        let (v1, w1) = MassRatio::new(ms, mt).collide(v, w, e, a);
        let dp = (ms * v1 + mt * w1) - (ms * v + mt * w);
        let scale = (ms + mt) * (v.norm() + w.norm());
        prop_assert!(dp.norm() <= 64.0 * EPS * scale, "{dp:?}");
    }

    #[test]
    fn the_energy_change_has_its_closed_form(v in vec3(1e3), w in vec3(1e3), e in unit(), a in alpha(), ms in mass(), mt in mass()) {
        let m = MassRatio::new(ms, mt);
        let (v1, w1) = m.collide(v, w, e, a);
        let de = ms * v1.norm2() + mt * w1.norm2() - ms * v.norm2() - mt * w.norm2();
        let closed = m.energy_change(v - w, e, a);
        let scale = (ms + mt) * (v.norm2() + w.norm2());
        prop_assert!((de - closed).abs() <= 256.0 * EPS * scale, "{de} vs {closed}");
        prop_assert!(closed <= 0.0);
        if a == 1.0 {
            prop_assert!(de.abs() <= 256.0 * EPS * scale);
        }
    }

    #[test]
    fn equal_masses_are_grw_3_bit_for_bit(v in vec3(1e3), w in vec3(1e3), e in unit(), a in alpha(), m in mass()) {
        prop_assert_eq!(MassRatio::new(m, m).collide(v, w, e, a), inelastic(v, w, e, a));
    }

    #[test]
    fn the_relative_velocity_is_grw_3s(v in vec3(1e3), w in vec3(1e3), e in unit(), a in alpha(), ms in mass(), mt in mass()) {
        // u' = (1 - a)/2 u + (1 + a)/2 |u| e, whatever the masses.
        let (v1, w1) = MassRatio::new(ms, mt).collide(v, w, e, a);
        let u = v - w;
        let expect = (0.5 * (1.0 - a)) * u + (0.5 * (1.0 + a) * u.norm()) * e;
        prop_assert!(((v1 - w1) - expect).norm() <= 64.0 * EPS * (v.norm() + w.norm()));
    }
}

/// A cooling mixture of three species run to `t`: the mass-weighted momentum is kept for any
/// restitution, the mass-weighted energy never grows and is kept when elastic. Bounds as in
/// engine_invariants.rs, with the masses: C collisions, each changing the momentum by at most
/// 64 ulps of `(m_s + m_t)(|v| + |w|)` and the energy by 256 ulps of
/// `(m_s + m_t)(|v|^2 + |w|^2)`, speeds bounded by `sqrt(E / m_min)`.
fn mixture_keeps<K: Kernel>(kernel: K, counts: [usize; 3], alpha: f64, seed: u64) {
    let masses = [1.0, 3.0, 0.2];
    let sp = Species::new(&counts, &masses).unwrap();
    let mut buf = vec![Particle::default(); sp.total()];
    let mut rng = seeded(seed);
    let f0 = Maxwellian::standard();
    for q in &mut buf {
        q.set_velocity(f0.sample(&mut rng));
    }
    let mut p = Particles::new(&mut buf).unwrap();
    let totals = |p: &Particles<'_>| {
        let (mut m, mut e) = (Vec3::ZERO, 0.0);
        for (s, &mass) in masses.iter().enumerate() {
            for i in sp.range(s) {
                m += mass * p.velocity(i);
                e += mass * p.velocity(i).norm2();
            }
        }
        (m, e)
    };
    let (m0, e0) = totals(&p);
    let law = Constant::new(alpha).unwrap();
    let physics = [PairPhysics {
        kernel,
        restitution: law,
    }; 6];
    let (mut engine, _) =
        MixtureNoSplitting::start(sp, &physics, &[NoDrive; 3], &mut p, 0.0).unwrap();
    engine.advance_to(&mut p, 0.5, &mut rng).unwrap();
    let c = engine.counts().collisions as f64;
    assert!(c > 0.0, "no collision: the test would check nothing");
    assert_eq!(
        engine.counts().rescales,
        0,
        "rescaled: the sums would not compare"
    );
    let per_type: u64 = (0..6).map(|k| engine.pair_collisions(k)).sum();
    assert_eq!(per_type, engine.counts().collisions);
    let (m1, e1) = totals(&p);
    let vmax = (e0 / 0.2).sqrt();
    // (m_s + m_t) <= 6 and |v| + |w| <= 2 vmax.
    let bound_m = 64.0 * (c + 1.0) * EPS * 12.0 * vmax;
    assert!(
        (m1 - m0).norm() <= bound_m,
        "momentum {m0:?} -> {m1:?} ({c})"
    );
    let bound_e = 256.0 * (c + 1.0) * EPS * 12.0 * e0 / 0.2;
    assert!(e1 <= e0 + bound_e, "energy gained: {e0} -> {e1}");
    if alpha == 1.0 {
        assert!((e1 - e0).abs() <= bound_e, "energy {e0} -> {e1} ({c})");
    }
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(64))]

    #[test]
    fn mixture_collisions_keep_momentum_and_elastic_energy(
        a in 1usize..40, b in 1usize..40, c in 1usize..40,
        alpha in prop_oneof![Just(1.0), 0.05f64..=1.0],
        seed in any::<u64>(),
        kernel in 0u8..3,
    ) {
        let k = 0.25 / std::f64::consts::PI;
        match kernel {
            0 => mixture_keeps(Maxwell::new(4.0, k).unwrap(), [a, b, c], alpha, seed),
            1 => mixture_keeps(HardSpheres::new(4.0, k).unwrap(), [a, b, c], alpha, seed),
            _ => mixture_keeps(Vhs::new(4.0, k, 0.5).unwrap(), [a, b, c], alpha, seed),
        }
    }
}

#[test]
fn species_pair_types_are_listed_once() {
    for s in 1..=gdsmc_core::mixture::MAX_SPECIES {
        let sp = Species::new(&vec![2; s], &vec![1.0; s]).unwrap();
        assert_eq!(sp.pair_types(), s * (s + 1) / 2);
        for k in 0..sp.pair_types() {
            let (a, b) = sp.pair(k);
            assert!(a <= b && b < s);
            assert_eq!(sp.pair_index(a, b), k);
            assert_eq!(sp.pair_index(b, a), k);
        }
    }
}

#[test]
fn bad_mixtures_are_refused_by_name() {
    use gdsmc_core::mixture::MixtureError;
    assert_eq!(Species::new(&[], &[]), Err(MixtureError::SpeciesCount(0)));
    assert_eq!(
        Species::new(&[3, 0], &[1.0, 1.0]),
        Err(MixtureError::EmptySpecies(1))
    );
    assert_eq!(
        Species::new(&[1], &[1.0]),
        Err(MixtureError::TooFewParticles)
    );
    // Counts whose sum overflows are too many, not too few.
    assert_eq!(
        Species::new(&[usize::MAX, 2], &[1.0, 1.0]),
        Err(MixtureError::TooManyParticles)
    );
    assert_eq!(
        Species::new(&[usize::MAX / 2, usize::MAX / 2], &[1.0, 1.0]),
        Err(MixtureError::TooManyParticles)
    );
    assert_eq!(
        Species::new(&[2, 2], &[1.0, -1.0]),
        Err(MixtureError::Mass(1))
    );
    assert_eq!(
        Species::new(&[2, 2], &[1.0, f64::NAN]),
        Err(MixtureError::Mass(1))
    );
    assert_eq!(
        Species::new(&[1; 9], &[1.0; 9]),
        Err(MixtureError::SpeciesCount(9))
    );
    let sp = Species::new(&[2, 2], &[1.0, 2.0]).unwrap();
    let mut buf = vec![Particle::default(); 4];
    let mut p = Particles::new(&mut buf).unwrap();
    let pair = PairPhysics {
        kernel: Maxwell::new(1.0, 1.0).unwrap(),
        restitution: Constant::new(1.0).unwrap(),
    };
    let e = MixtureNoSplitting::start(sp, &[pair; 2], &[NoDrive; 2], &mut p, 0.0).unwrap_err();
    assert_eq!(
        e.to_string(),
        "one entry per pair of species is needed (3), got 2"
    );
}
