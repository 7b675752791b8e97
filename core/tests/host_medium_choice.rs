//! The host medium simulated grain by grain (lazily, `drive::HostMedium`) against BRS's global
//! algorithm with the direct O(n) choice of the grain by the weights `E_1max(v_i)` (BRS
//! Algorithm 2, background part): the same process, so the ensemble means of the bulk velocity
//! and the temperature at t = 0.5 must agree. Two-sample check: the difference of the means
//! within 3.2 standard errors of the difference (99.9%). Fixed seeds.

use gdsmc_core::collision::{MassRatio, elastic_background};
use gdsmc_core::drive::{Drive, HardSphereBackground, HostMedium, HostMediumParams};
use gdsmc_core::math::PI;
use gdsmc_core::moments::Observables;
use gdsmc_core::particles::{Particle, Particles};
use gdsmc_core::rng::{Streams, uniform01};
use gdsmc_core::sample::{BackgroundPartner, Maxwellian, standard_exponential, unit_sphere};
use gdsmc_core::vec3::Vec3;
use gdsmc_stats::{KNOWN, Sample, joint};

const N: usize = 16;
const ENSEMBLES: usize = 20_000;
const T_END: f64 = 0.5;

fn background() -> Maxwellian {
    Maxwellian::new(1.0, 1.0, Vec3::new(0.0, 1.0, 0.0)).unwrap()
}

fn start(rng: &mut gdsmc_core::rng::Xoshiro256PlusPlus) -> Vec<Particle> {
    let f0 = Maxwellian::new(1.0, 2.0, Vec3::new(1.0, 0.0, 0.0)).unwrap();
    (0..N).map(|_| Particle::new(f0.sample(rng), 0.0)).collect()
}

fn e1max(v: Vec3, ub: Vec3, b: f64) -> f64 {
    4.0 * PI * (v - ub).norm() + 8.0 * PI.sqrt() * b
}

/// BRS Algorithm 2, background collisions only, with C_1 = rho^B = 1.
fn direct(q: &mut [Particle], rng: &mut gdsmc_core::rng::Xoshiro256PlusPlus) {
    let bg = background();
    let partner = BackgroundPartner::new(&bg);
    let (ub, b) = (bg.drift(), partner.b());
    let ratio = MassRatio::new(1.0, 1.0).unwrap();
    let mut t = 0.0;
    loop {
        let weights: Vec<f64> = q.iter().map(|p| e1max(p.velocity(), ub, b)).collect();
        let total: f64 = weights.iter().sum();
        t += standard_exponential(rng) / total;
        if t >= T_END {
            return;
        }
        // The direct O(n) choice of the grain.
        let mut x = uniform01(rng) * total;
        let mut i = 0;
        while i + 1 < N && x >= weights[i] {
            x -= weights[i];
            i += 1;
        }
        let v = q[i].velocity();
        let a = (v - ub).norm();
        let w = if uniform01(rng) * (a + 2.0 * b / PI.sqrt()) < a {
            bg.sample(rng)
        } else {
            partner.sample(rng)
        };
        let omega = unit_sphere(rng);
        if uniform01(rng) * (a + (w - ub).norm()) < (v - w).norm() {
            q[i].set_velocity(elastic_background(v, w, omega, ratio).0);
        }
    }
}

#[test]
fn lazy_grains_equal_the_direct_weighted_choice() {
    let drive = HostMedium::new(
        HostMediumParams::new(background(), 1.0, 1.0).unwrap(),
        HardSphereBackground,
    );
    let (mut lazy_t, mut lazy_v, mut dir_t, mut dir_v) = (vec![], vec![], vec![], vec![]);
    for (k, mut rng) in Streams::new(77).take(2 * ENSEMBLES).enumerate() {
        let mut q = start(&mut rng);
        if k % 2 == 0 {
            let mut p = Particles::new(&mut q).unwrap();
            drive.kick_all(&mut p, T_END, &mut rng);
            let o = Observables::of(&p);
            lazy_t.push(o.t_bulk);
            lazy_v.push(o.bulk.y);
        } else {
            direct(&mut q, &mut rng);
            let o = Observables::of(&Particles::new(&mut q).unwrap());
            dir_t.push(o.t_bulk);
            dir_v.push(o.bulk.y);
        }
    }
    for (what, a, b) in [("T_bulk", &lazy_t, &dir_t), ("V_y", &lazy_v, &dir_v)] {
        let (sa, sb) = (Sample::of(a), Sample::of(b));
        // Two checks (T_bulk, V_y) held together at 99.9%; thousands of samples: normal.
        let (z, bound) = (sa.z_from(&sb), joint(2, KNOWN));
        assert!(
            z.abs() <= bound,
            "{what}: lazy {} vs direct {} ({z} standard errors; bound {bound})",
            sa.mean,
            sb.mean
        );
    }
    // The process did something: V_y moved from 0 towards u^B = 1.
    assert!(Sample::of(&lazy_v).mean > 0.2, "no relaxation seen");
}

/// The background collisions counted: with the Maxwell background kernel every grain meets the
/// background as a Poisson process of rate 4 pi C_1 rho^B whatever its velocity (BRS (11)), so
/// the count over n grains and a time t is Poisson with mean n 4 pi C_1 rho^B t, and kicking
/// the same draws without counting gives the same velocities. Checked within 3.29 standard
/// deviations (99.9%, normal approximation at a mean of about 1e5). Fixed seed.
#[test]
fn background_collisions_are_counted() {
    use gdsmc_core::drive::MaxwellBackground;
    let (c1, rho) = (0.5, 2.0);
    let drive = HostMedium::new(
        HostMediumParams::new(background(), rho, c1).unwrap(),
        MaxwellBackground,
    );
    let mut rng = Streams::new(5).next().unwrap();
    let mut q = start(&mut rng);
    let mut twin = q.clone();
    let mut twin_rng = rng.clone();
    let t = 1000.0 / N as f64;
    let mut events = 0u64;
    drive.kick_all_counting(
        &mut Particles::new(&mut q).unwrap(),
        t,
        &mut rng,
        &mut events,
    );
    let mean = N as f64 * 4.0 * PI * c1 * rho * t;
    let z = (events as f64 - mean) / mean.sqrt();
    assert!(
        z.abs() < 3.29,
        "{events} background collisions, expected {mean:.0} (z = {z:.2})"
    );
    drive.kick_all(&mut Particles::new(&mut twin).unwrap(), t, &mut twin_rng);
    assert_eq!(q, twin, "counting changed the draws");
}
