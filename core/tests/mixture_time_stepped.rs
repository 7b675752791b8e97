//! The mixture's time-stepped scheme (`MixtureTimeStepped`: one collision stage per pair type,
//! MS Section 3 for hard spheres, Bird's no-time-counter form for the other kernels).
//!
//! - A one-species mixture is the one-species time-stepped scheme to the last bit
//!   (observables, counts, velocities, spins at every time): smooth and rough particles, hard
//!   spheres, Maxwell and VHS kernels, spheres and disks, cooling and driven.
//! - The elastic perfectly rough mixture keeps its energy to rounding under the scheme (each
//!   collision does) and relaxes to the equipartition of its finite system.

use gdsmc_core::drive::{
    ConstantForce, Drive, GaussianThermostat, NoDrive, PlanarWhiteNoise, WhiteNoise,
};
use gdsmc_core::engine::{CollisionMap, EventLoop, TimeStepped};
use gdsmc_core::geometry::{Disks, Geometry, Spheres};
use gdsmc_core::kernel::{HardSpheres, Kernel, Maxwell, Vhs};
use gdsmc_core::math::PI;
use gdsmc_core::mixture::{MixtureTimeStepped, PairLaw, PairPhysics, Species};
use gdsmc_core::particles::{Particle, Particles, Spin};
use gdsmc_core::physics::DimensionChoice;
use gdsmc_core::restitution::Constant;
use gdsmc_core::rng::stream;
use gdsmc_core::rough::{RoughMap, RoughNoise, RoughPairLaw};
use gdsmc_core::sample::Maxwellian;
use gdsmc_core::vec3::Vec3;

/// `n` particles of one species (spins when `spins`) run by `TimeStepped` with map `one_map`
/// and by `MixtureTimeStepped` with pair law `law` (the same physics), step factor `f`: the
/// same observables, counts, velocities and spins at every time, to the bit.
#[allow(clippy::too_many_arguments)]
fn same_as_one_species<K: Kernel, D: Drive, A: CollisionMap, L: PairLaw, G: Geometry>(
    kernel: K,
    drive: D,
    one_map: A,
    law: L,
    n: usize,
    f: f64,
    times: &[f64],
) {
    let f0 = Maxwellian::standard();
    let mut rng = stream(17, 0);
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
        TimeStepped::<K, D, A, G>::start(kernel, drive, one_map, f, &mut pa, 0.0).unwrap();
    let sp = Species::new(&[n], &[1.0]).unwrap();
    let pair = PairPhysics {
        kernel,
        restitution: law,
    };
    let (mut mix, o2) =
        MixtureTimeStepped::<K, D, L, G>::start(sp, &[pair], &[drive], f, &mut pb, 0.0).unwrap();
    assert_eq!(o1, o2.all);
    for &t in times {
        let o1 = one.advance_to(&mut pa, t, &mut ra).unwrap();
        let o2 = mix.advance_to(&mut pb, t, &mut rb).unwrap();
        assert_eq!(o1, o2.all, "t = {t}");
        assert_eq!(one.counts(), EventLoop::counts(&mix), "t = {t}");
        let same = |x: &[Particle], y: &[Particle]| {
            x.iter().zip(y).all(|(x, y)| x.velocity() == y.velocity())
        };
        assert!(
            same(pa.as_slice(), pb.as_slice()),
            "t = {t}: velocities differ"
        );
        assert_eq!(pa.spins(), pb.spins(), "t = {t}");
        if A::SPINS {
            let r1 = one.rough(&pa).unwrap();
            let r2 = EventLoop::species(&mix, &pb).unwrap().rotation.unwrap()[0];
            assert_eq!(r1, r2, "t = {t}");
        }
    }
    assert!(EventLoop::counts(&mix).collisions > n as u64);
}

#[test]
fn a_one_species_mixture_is_the_time_stepped_loop_bit_for_bit() {
    let c = 1.0 / (4.0 * PI);
    let times = [0.25, 0.5, 1.0, 2.0];
    let hs = HardSpheres::new(4.0, c).unwrap();
    let mx = Maxwell::new(4.0, c).unwrap();
    let vhs = Vhs::new(4.0, c, 0.5).unwrap();
    let a = Constant::new(0.8).unwrap();
    let noise = WhiteNoise::new(1.0).unwrap();
    same_as_one_species::<_, _, _, _, Spheres>(hs, noise, a, a, 200, 0.02, &times);
    same_as_one_species::<_, _, _, _, Spheres>(mx, NoDrive, a, a, 200, 0.02, &times);
    let force = ConstantForce::new(0.5).unwrap();
    same_as_one_species::<_, _, _, _, Spheres>(hs, force, a, a, 200, 0.02, &times);
    let gauss = GaussianThermostat::new(0.25).unwrap();
    same_as_one_species::<_, _, _, _, Spheres>(vhs, gauss, a, a, 200, 0.02, &times);
    let planar = PlanarWhiteNoise::new(1.0).unwrap();
    same_as_one_species::<_, _, _, _, Disks>(hs, planar, a, a, 200, 0.02, &times);
    // Rough particles: the rough map against the rough pair law of equal masses.
    let law = RoughPairLaw::new(0.9, 0.3, 0.4, 0.4).unwrap();
    let map = RoughMap::new(0.9, 0.3, 0.4).unwrap();
    let rough_noise = RoughNoise::new(Some(1.0), 0.5, 0.4).unwrap();
    same_as_one_species::<_, _, _, _, Spheres>(hs, rough_noise, map, law, 200, 0.02, &times);
    same_as_one_species::<_, _, _, _, Spheres>(mx, NoDrive, map, law, 200, 0.02, &times);
    let disks = RoughPairLaw::for_disks(0.8, 0.5, 0.5, 0.5).unwrap();
    let disk_map = RoughMap::for_disks(0.8, 0.5, 0.5).unwrap();
    same_as_one_species::<_, _, _, _, Disks>(hs, NoDrive, disk_map, disks, 200, 0.02, &times);
}

/// The constant force on a mixture (masses 1 and 4, smooth and rough, by the time-stepped
/// scheme and Strang's splitting): its correction is weighted by mass, so the total momentum
/// `sum m v` is kept to rounding (collisions keep it too), while the unweighted mean velocity
/// moves (the force is not a no-op).
#[test]
fn the_constant_force_keeps_a_mixtures_momentum() {
    use gdsmc_core::physics::{
        DriveChoice, KernelChoice, Physics, RestitutionLaw, RotationChoice, SchemeChoice,
        SpeciesChoice,
    };
    let masses = [1.0, 4.0];
    for scheme in [SchemeChoice::TimeStepped(0.05), SchemeChoice::Strang(0.05)] {
        for rough in [false, true] {
            let mut ph = Physics::new(
                64,
                KernelChoice::hard_spheres(1.0, 0.25 / PI),
                RestitutionLaw::Constant(0.8),
                DriveChoice::declared(gdsmc_core::physics::DriveKind::ConstantForce, &[1.0])
                    .unwrap(),
                scheme,
            );
            ph.species.extend([
                SpeciesChoice::new(32, masses[0], 1.0),
                SpeciesChoice::new(32, masses[1], 1.0),
            ]);
            if rough {
                ph.rotation = Some(RotationChoice {
                    beta: 0.5,
                    kappa: 0.4,
                    temperature: 1.0,
                    noise: 0.0,
                });
            }
            let model = ph.validate().unwrap();
            let mut buf = vec![Particle::default(); 64];
            let mut spins = vec![Spin::default(); 64];
            let mut p = if rough {
                Particles::with_spins(&mut buf, &mut spins).unwrap()
            } else {
                Particles::new(&mut buf).unwrap()
            };
            let mut rng = stream(21, 0);
            let momentum = |p: &Particles<'_>| {
                (0..64).fold(Vec3::ZERO, |m, i| m + masses[i / 32] * p.velocity(i))
            };
            let scale = |p: &Particles<'_>| {
                (0..64)
                    .map(|i| masses[i / 32] * p.velocity(i).norm())
                    .sum::<f64>()
            };
            let (mut e, _) = model.launch(&mut p, 0.0, &mut rng).unwrap();
            let m0 = momentum(&p);
            let mean0 = (0..64).fold(Vec3::ZERO, |m, i| m + p.velocity(i));
            for t in [0.5, 1.0, 2.0] {
                e.advance_to(&mut p, t, &mut rng).unwrap();
                let drift = (momentum(&p) - m0).norm();
                assert!(
                    drift <= 1e-12 * scale(&p),
                    "{scheme:?} rough {rough} t = {t}: momentum moved by {drift}"
                );
            }
            let mean1 = (0..64).fold(Vec3::ZERO, |m, i| m + p.velocity(i));
            assert!(
                (mean1 - mean0).norm() > 1e-6,
                "the unweighted mean did not move"
            );
            assert!(e.counts().collisions > 64);
        }
    }
}
