//! Rough mixtures: the mixture loop with the rough pair map (`gdsmc_core::rough::pair`).
//!
//! - The map of unequal partners keeps momentum, changes the energy by exactly the closed form
//!   of its normal and tangential parts, and leaves the spins alone at `beta = -1`.
//! - A one-species rough mixture is the one-species rough loop to the last bit (velocities,
//!   spins, observables, counts), cooling (through rescales) or driven.
//! - A rough mixture with `beta = -1` for every pair is the smooth mixture to the last bit
//!   (rotation decouples), spheres and hard disks, cooling (through rescales) or driven.
//!
//! The elastic rough mixture's equipartition: `rough_mixture_equipartition.rs`.

use crate::rough_mixture_equipartition::c1;
use gdsmc_core::drive::{Drive, NoDrive};
use gdsmc_core::engine::{Counts, EventLoop, NoSplitting};
use gdsmc_core::geometry::{Disks, Geometry, Spheres};
use gdsmc_core::kernel::{HardSpheres, Kernel, Maxwell};
use gdsmc_core::math::PI;
use gdsmc_core::mixture::{MixtureNoSplitting, PairLaw, PairPhysics, Species};
use gdsmc_core::particles::{Particle, Particles, Spin};
use gdsmc_core::physics::{
    DimensionChoice, DriveChoice, KernelChoice, Physics, RestitutionLaw, RotationChoice,
    SchemeChoice, SpeciesChoice,
};
use gdsmc_core::rng::{seeded, stream};
use gdsmc_core::rough::{RoughMap, RoughNoise, RoughPairLaw};
use gdsmc_core::sample::{Maxwellian, unit_sphere};
use gdsmc_core::vec3::Vec3;

/// `sum m (|v|^2 + kappa |w|^2) / 2` of two partners.
fn energy(m: (f64, f64), k: (f64, f64), v: [Vec3; 4]) -> f64 {
    0.5 * (m.0 * (v[0].norm2() + k.0 * v[1].norm2()) + m.1 * (v[2].norm2() + k.1 * v[3].norm2()))
}

/// 10^4 random collisions of unequal partners (masses in (0.1, 10), kappa in (0, 2/3]): the
/// momentum is kept, and the energy changes by
/// `-(mu/2)(1 - alpha^2)|g_n|^2 - (1/(2 D))(1 - beta^2)|g_t|^2`, the closed form of an impulse
/// that reverses each part of the contact velocity (effective masses `mu` and `1/D`,
/// `D = 1/mu + 1/(kappa_1 m_1) + 1/(kappa_2 m_2)`), derived apart from the map's coefficients.
/// Both to rounding (relative 1e-12).
#[test]
fn the_rough_pair_map_keeps_momentum_and_loses_the_closed_form_energy() {
    let mut rng = seeded(5);
    let mut dirs = seeded(6);
    let mut u = || gdsmc_core::rng::uniform01(&mut rng);
    for _ in 0..10_000 {
        let (m1, m2) = (0.1 + 9.9 * u(), 0.1 + 9.9 * u());
        let (k1, k2) = ((2.0 / 3.0) * (1.0 - u()), (2.0 / 3.0) * (1.0 - u()));
        let (alpha, beta) = (1.0 - u(), 2.0 * u() - 1.0);
        let law = RoughPairLaw::new(alpha, beta, k1, k2).unwrap();
        let map = law.between(m1, m2);
        let speeds = [2.0 * u(), 2.0 * u(), 2.0 * u(), 2.0 * u()];
        let before = speeds.map(|r| r * unit_sphere(&mut dirs));
        let n = unit_sphere(&mut dirs);
        let (a1, b1, a2, b2) = map.collide(before[0], before[1], before[2], before[3], n);
        let p0 = m1 * before[0] + m2 * before[2];
        let p1 = m1 * a1 + m2 * a2;
        let scale = m1 * before[0].norm() + m2 * before[2].norm();
        assert!(
            (p1 - p0).norm() <= 1e-12 * scale,
            "momentum {p0:?} -> {p1:?}"
        );
        let g = RoughMap::contact_velocity(before[0], before[1], before[2], before[3], n);
        let gn2 = g.dot(n) * g.dot(n);
        let gt2 = (g.norm2() - gn2).max(0.0);
        let mu = m1 * m2 / (m1 + m2);
        let d = 1.0 / mu + 1.0 / (k1 * m1) + 1.0 / (k2 * m2);
        let expected =
            -0.5 * mu * (1.0 - alpha * alpha) * gn2 - 0.5 / d * (1.0 - beta * beta) * gt2;
        let e0 = energy((m1, m2), (k1, k2), before);
        let e1 = energy((m1, m2), (k1, k2), [a1, b1, a2, b2]);
        assert!(
            ((e1 - e0) - expected).abs() <= 1e-12 * e0,
            "energy change {} against {expected}",
            e1 - e0
        );
        if beta == -1.0 {
            assert_eq!((b1, b2), (before[1], before[3]));
        }
    }
    // beta = -1 exactly: the spins untouched, bit for bit.
    let map = RoughPairLaw::new(0.7, -1.0, 0.4, 0.1)
        .unwrap()
        .between(1.0, 3.0);
    let w = (Vec3::new(0.3, -0.2, 0.1), Vec3::new(-1.0, 0.5, 2.0));
    let (_, b1, _, b2) = map.collide(
        Vec3::new(1.0, 0.0, 0.0),
        w.0,
        Vec3::ZERO,
        w.1,
        Vec3::new(-1.0, 0.0, 0.0),
    );
    assert_eq!((b1, b2), w);
}

/// A one-species rough mixture and the rough loop from the same start and stream: equal
/// observables, rotational observables, velocities, spins and counts at every time, to the bit.
fn same_as_rough_loop<K: Kernel, D: Drive, G: Geometry>(
    kernel: K,
    drive: D,
    law: RoughPairLaw,
    n: usize,
    times: &[f64],
) {
    let kappa = law.inertia().0;
    let one_map = match G::CHOICE {
        DimensionChoice::Three => RoughMap::new(law.alpha(), law.beta(), kappa),
        DimensionChoice::Two => RoughMap::for_disks(law.alpha(), law.beta(), kappa),
    }
    .unwrap();
    let f0 = Maxwellian::standard();
    let mut rng = stream(9, 0);
    let planar = |v: Vec3| match G::CHOICE {
        DimensionChoice::Three => v,
        DimensionChoice::Two => Vec3::new(v.x, v.y, 0.0),
    };
    let mut a: Vec<Particle> = (0..n)
        .map(|_| Particle::new(planar(f0.sample(&mut rng)), 0.0))
        .collect();
    let mut sa: Vec<Spin> = (0..n)
        .map(|_| {
            let w = f0.sample(&mut rng);
            Spin::new(match G::CHOICE {
                DimensionChoice::Three => w,
                DimensionChoice::Two => Vec3::new(0.0, 0.0, w.z),
            })
        })
        .collect();
    let (mut b, mut sb) = (a.clone(), sa.clone());
    let (mut ra, mut rb) = (rng.clone(), rng);
    let mut pa = Particles::with_spins(&mut a, &mut sa).unwrap();
    let mut pb = Particles::with_spins(&mut b, &mut sb).unwrap();
    let (mut one, o1) =
        NoSplitting::<K, D, RoughMap, G>::start_in(kernel, drive, one_map, &mut pa, 0.0).unwrap();
    let sp = Species::new(&[n], &[1.0]).unwrap();
    let pair = PairPhysics {
        kernel,
        restitution: law,
    };
    let (mut mix, o2) =
        MixtureNoSplitting::<K, D, RoughPairLaw, G>::start_in(sp, &[pair], &[drive], &mut pb, 0.0)
            .unwrap();
    assert_eq!(o1, o2.all);
    for &t in times {
        let o1 = one.advance_to(&mut pa, t, &mut ra).unwrap();
        let o2 = mix.advance_to(&mut pb, t, &mut rb).unwrap();
        assert_eq!(o1, o2.all, "t = {t}");
        assert_eq!(one.counts(), mix.counts(), "t = {t}");
        // The physical state (the loops may store it differently: the mixture kicks no
        // undriven particle, so its last-kick times stay at the start).
        let (fa, fb) = (one.velocity_map(), EventLoop::velocity_map(&mix));
        assert_eq!(fa, fb, "t = {t}");
        let same = |x: &[Particle], y: &[Particle]| {
            x.iter().zip(y).all(|(x, y)| x.velocity() == y.velocity())
        };
        assert!(
            same(pa.as_slice(), pb.as_slice()),
            "t = {t}: velocities differ"
        );
        assert_eq!(pa.spins(), pb.spins(), "t = {t}");
        let r1 = one.rough(&pa).unwrap();
        let r2 = EventLoop::species(&mix, &pb).unwrap().rotation.unwrap()[0];
        assert_eq!(r1, r2, "t = {t}");
    }
    assert!(mix.counts().collisions > 2 * n as u64);
}

#[test]
fn a_one_species_rough_mixture_is_the_rough_loop_bit_for_bit() {
    let c = 1.0 / (4.0 * PI);
    let times = [0.5, 1.0, 2.0, 4.0];
    let hs = HardSpheres::new(4.0, c).unwrap();
    let law = RoughPairLaw::new(0.9, 0.3, 0.4, 0.4).unwrap();
    let noise = RoughNoise::new(Some(1.0), 0.5, 0.4).unwrap();
    same_as_rough_loop::<_, _, Spheres>(hs, noise, law, 400, &times);
    same_as_rough_loop::<_, _, Spheres>(Maxwell::new(4.0, c).unwrap(), noise, law, 400, &times);
    // Cooling long enough to be rescaled (velocities and spins together): the temperature
    // falls as 1/t^2, below the rescale threshold 1e-8 within these decades.
    let long: Vec<f64> = (0..=9).map(|k| 10f64.powi(k)).collect();
    let cold = RoughPairLaw::new(0.4, 0.0, 0.4, 0.4).unwrap();
    same_as_rough_loop::<_, _, Spheres>(hs, NoDrive, cold, 300, &long);
    // Disks, one rotational degree of freedom.
    let disks = RoughPairLaw::for_disks(0.8, 0.5, 0.5, 0.5).unwrap();
    same_as_rough_loop::<_, _, Disks>(hs, NoDrive, disks, 300, &times);
    same_as_rough_loop::<_, _, Disks>(hs, noise.in_dim::<Disks>(), disks, 300, &times);
}

/// A mixture of `species` (count, mass) pairs with hard spheres or Maxwell
/// molecules, restitution `alpha`, in `dimension`, cooling or under white noise; rough with
/// `beta = -1` for every pair when `rough`.
fn smooth_or_rough(
    species: &[(usize, f64)],
    (maxwell, alpha): (bool, f64),
    (dimension, scheme): (DimensionChoice, SchemeChoice),
    drive: DriveChoice,
    rough: bool,
) -> Physics {
    let n = species.iter().map(|s| s.0).sum::<usize>();
    let kernel = if maxwell {
        KernelChoice::maxwell(4.0, c1())
    } else {
        KernelChoice::hard_spheres(4.0, c1())
    };
    let mut ph = Physics::new(n, kernel, RestitutionLaw::Constant(alpha), drive, scheme);
    for (k, &(count, mass)) in species.iter().enumerate() {
        ph.species
            .push(SpeciesChoice {
                // Each species its own inertia where rough, to show it cannot matter; under white
                // noise the first species a zero strength (its kicks still draw), the second 0.5.
                inertia: rough.then_some(0.1 + 0.1 * k as f64),
                beta: 0.5 * k as f64,
                ..SpeciesChoice::new(count, mass, 1.0 + k as f64)
            })
            .unwrap();
    }
    ph.dimension = dimension;
    if rough {
        ph.rotation = Some(RotationChoice {
            beta: -1.0,
            kappa: 0.4,
            temperature: 2.0,
            noise: 0.0,
        });
    }
    ph
}

/// The dimension and the scheme of a case (the exact scheme unless named).
struct How(DimensionChoice, SchemeChoice);

impl From<DimensionChoice> for How {
    fn from(d: DimensionChoice) -> How {
        How(d, SchemeChoice::NoSplitting)
    }
}

impl From<(DimensionChoice, SchemeChoice)> for How {
    fn from((d, s): (DimensionChoice, SchemeChoice)) -> How {
        How(d, s)
    }
}

/// Rotation decouples at `beta = -1`: the rough gas (one species or a mixture) and the smooth
/// one from the same seed have equal translational observables, velocities and counts at every
/// time, to the bit, through the front door (`Model::launch`: the rough start draws its spins
/// from their own stream), cooling through rescales or driven. Returns the counts.
fn rough_at_beta_minus_one_is_smooth(
    species: &[(usize, f64)],
    kernel: (bool, f64),
    dimension: impl Into<How>,
    drive: DriveChoice,
    times: &[f64],
) -> Counts {
    let How(d, scheme) = dimension.into();
    let how = (d, scheme);
    let smooth = smooth_or_rough(species, kernel, how, drive, false)
        .validate()
        .unwrap();
    let rough = smooth_or_rough(species, kernel, how, drive, true)
        .validate()
        .unwrap();
    assert!(rough.rotates() && !smooth.rotates());
    let n = smooth.n();
    let (mut a, mut b) = (vec![Particle::default(); n], vec![Particle::default(); n]);
    let mut spins = vec![Spin::default(); n];
    let mut pa = Particles::new(&mut a).unwrap();
    let mut pb = Particles::with_spins(&mut b, &mut spins).unwrap();
    let (mut ra, mut rb) = (stream(4, 2), stream(4, 2));
    let (mut ea, oa) = smooth.launch(&mut pa, 0.0, &mut ra).unwrap();
    let (mut eb, ob) = rough.launch(&mut pb, 0.0, &mut rb).unwrap();
    assert_eq!(oa, ob);
    assert!(
        (0..n).any(|i| pb.spin(i).norm2() > 0.0),
        "the spins were drawn"
    );
    let spins0 = pb.spins().to_vec();
    for &t in times {
        let oa = ea.advance_to(&mut pa, t, &mut ra).unwrap();
        let ob = eb.advance_to(&mut pb, t, &mut rb).unwrap();
        assert_eq!(oa, ob, "t = {t}");
        assert_eq!(ea.counts(), eb.counts(), "t = {t}");
        let (va, vb) = (pa.as_slice(), pb.as_slice());
        assert!(
            va.iter().zip(vb).all(|(x, y)| x.velocity() == y.velocity()),
            "t = {t}: velocities differ"
        );
        if !species.is_empty() {
            let (sa, sb) = (ea.species(&pa).unwrap(), eb.species(&pb).unwrap());
            for s in 0..species.len() {
                assert_eq!(sa.species[s], sb.species[s], "t = {t}, species {s}");
            }
        }
    }
    assert!(ea.counts().collisions > 3 * n as u64);
    if ea.counts().rescales == 0 {
        // Undriven and unrescaled, the spins are the start's (rescales multiply both).
        assert_eq!(pb.spins(), &spins0[..]);
    }
    ea.counts()
}

#[test]
fn a_rough_mixture_with_beta_minus_one_is_the_smooth_mixture_bit_for_bit() {
    use DimensionChoice::{Three, Two};
    let times = [0.5, 1.0, 2.0, 4.0, 8.0];
    let mix = [(120, 1.0), (80, 3.0)];
    let (hard, maxwell) = ((false, 0.8), (true, 0.8));
    let (none, hot) = (DriveChoice::None, DriveChoice::WhiteNoise(0.0));
    // Spheres: hard spheres cooling and driven, Maxwell molecules cooling.
    rough_at_beta_minus_one_is_smooth(&mix, hard, Three, none, &times);
    rough_at_beta_minus_one_is_smooth(&mix, hard, Three, hot, &times);
    rough_at_beta_minus_one_is_smooth(&mix, maxwell, Three, none, &times);
    // Cooling long enough to be rescaled (velocities and spins together): the temperature
    // falls as 1/t^2, below the rescale threshold 1e-8 within these decades.
    let long: Vec<f64> = (0..=9).map(|k| 10f64.powi(k)).collect();
    let c = rough_at_beta_minus_one_is_smooth(&mix, (false, 0.3), Three, none, &long);
    assert!(c.rescales > 0, "{c:?}");
    // Hard disks, cooling and driven; one species.
    rough_at_beta_minus_one_is_smooth(&mix, hard, Two, none, &times);
    rough_at_beta_minus_one_is_smooth(&mix, hard, Two, hot, &times);
    rough_at_beta_minus_one_is_smooth(&mix[..1], hard, Two, none, &times);
    rough_at_beta_minus_one_is_smooth(&mix[..1], hard, Three, hot, &times);
    // The Gaussian thermostat on translation, a mixture and one species, spheres and disks.
    let thermostat =
        DriveChoice::declared(gdsmc_core::physics::DriveKind::Gaussian, &[0.3]).unwrap();
    rough_at_beta_minus_one_is_smooth(&mix, hard, Three, thermostat, &times);
    rough_at_beta_minus_one_is_smooth(&mix, hard, Two, thermostat, &times);
    rough_at_beta_minus_one_is_smooth(&mix, maxwell, Three, thermostat, &times);
    rough_at_beta_minus_one_is_smooth(&mix[..1], hard, Three, thermostat, &times);
    // RW's splittings (the grid dt = 0.5 holds every time), driven and cooling. (Maxwell
    // disks are left out: rough disks collide with the hard-disk impact law whatever the
    // kernel, smooth Maxwell disks isotropically, `rough::map::smooth_limit`.)
    let (euler, strang) = (SchemeChoice::Euler(0.5), SchemeChoice::Strang(0.5));
    rough_at_beta_minus_one_is_smooth(&mix, hard, (Three, euler), hot, &times);
    rough_at_beta_minus_one_is_smooth(&mix, hard, (Two, strang), hot, &times);
    rough_at_beta_minus_one_is_smooth(&mix, hard, (Three, strang), thermostat, &times);
    rough_at_beta_minus_one_is_smooth(&mix[..1], hard, (Three, euler), hot, &times);
    rough_at_beta_minus_one_is_smooth(&mix[..1], maxwell, (Three, strang), thermostat, &times);
    rough_at_beta_minus_one_is_smooth(&mix[..1], hard, (Two, strang), thermostat, &times);
    rough_at_beta_minus_one_is_smooth(&mix, hard, (Three, euler), none, &times);
}
