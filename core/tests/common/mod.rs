//! Shared statistics for the core's tests.
#![allow(dead_code)]

/// Kolmogorov-Smirnov statistic of `xs` (sorted in place) against the CDF `cdf`.
pub fn ks_statistic(xs: &mut [f64], cdf: impl Fn(f64) -> f64) -> f64 {
    xs.sort_by(|a, b| a.partial_cmp(b).unwrap());
    let n = xs.len() as f64;
    let mut d: f64 = 0.0;
    for (i, &x) in xs.iter().enumerate() {
        let f = cdf(x);
        d = d.max((i as f64 + 1.0) / n - f).max(f - i as f64 / n);
    }
    d
}

/// Critical value of the KS statistic at level 99.9% for `n` samples (asymptotic:
/// sqrt(-ln(0.0005)/2) / sqrt(n) = 1.9495 / sqrt(n)).
pub fn ks_critical_999(n: usize) -> f64 {
    1.9495 / (n as f64).sqrt()
}

/// Standard normal CDF.
pub fn normal_cdf(x: f64) -> f64 {
    0.5 * (1.0 + libm::erf(x / std::f64::consts::SQRT_2))
}

pub use gdsmc_stats::mean_ci;

/// The elastic perfectly rough gas's check (`core/tests/rough_gas.rs`, `core/tests/disks.rs`):
/// `ensembles` systems of `model` (n particles and spins, reduced moment of inertia `kappa`)
/// from the streams of `seed`, each run to t = 40 keeping `sum |v|^2 + kappa |w|^2` to
/// rounding, then `each` on the final system; the finite system's equipartition
/// `E[T_tr] = (n - 1)/n E[T_rot]` must hold within the 99.9% interval and the same sample
/// must refuse `T_tr = T_rot`.
pub fn check_finite_equipartition(
    model: &gdsmc_core::physics::Model,
    ensembles: usize,
    seed: u64,
    kappa: f64,
    each: impl Fn(&gdsmc_core::particles::Particles<'_>),
) {
    use gdsmc_core::engine::EventLoop;
    use gdsmc_core::particles::{Particle, Particles, Spin};
    let n = model.n();
    let energy = |p: &Particles<'_>| {
        let tr: f64 = p.as_slice().iter().map(|q| q.velocity().norm2()).sum();
        let rot: f64 = p.spins().iter().map(|s| s.rim_velocity().norm2()).sum();
        tr + kappa * rot
    };
    let (mut d_finite, mut d_naive) = (Vec::new(), Vec::new());
    let mut streams = gdsmc_core::rng::Streams::new(seed);
    let mut collisions = 0u64;
    for _ in 0..ensembles {
        let mut rng = streams.next().unwrap();
        let mut buf = vec![Particle::default(); n];
        let mut spins = vec![Spin::default(); n];
        let mut p = Particles::with_spins(&mut buf, &mut spins).unwrap();
        let (mut e, _) = model.launch(&mut p, 0.0, &mut rng).unwrap();
        let e0 = energy(&p);
        e.advance_to(&mut p, 40.0, &mut rng).unwrap();
        let e1 = energy(&p);
        assert!((e1 - e0).abs() <= 1e-12 * e0, "energy {e0} -> {e1}");
        collisions += e.counts().collisions;
        each(&p);
        let r = e.rough(&p).unwrap();
        d_finite.push(r.t_tr - (n as f64 - 1.0) / n as f64 * r.t_rot);
        d_naive.push(r.t_tr - r.t_rot);
    }
    // Relaxed: dozens of collisions per particle.
    assert!(collisions as f64 / (ensembles * n) as f64 > 20.0);
    let (m, h) = mean_ci(&d_finite);
    assert!(m.abs() <= h, "E[T_tr - (n-1)/n T_rot] = {m} +- {h}");
    let (m, h) = mean_ci(&d_naive);
    assert!(
        m.abs() > h,
        "the test cannot tell (n-1)/n from 1: {m} +- {h}"
    );
}

/// Proptest strategies shared by the collision-map tests.
pub mod strategies {
    use gdsmc_core::vec3::Vec3;
    use proptest::prelude::*;

    /// A vector with components in `(-r, r)`.
    pub fn vec3(r: f64) -> impl Strategy<Value = Vec3> {
        (-r..r, -r..r, -r..r).prop_map(|(x, y, z)| Vec3::new(x, y, z))
    }

    /// A unit vector, uniform on the sphere.
    pub fn unit() -> impl Strategy<Value = Vec3> {
        (-1.0f64..1.0, 0.0..std::f64::consts::TAU).prop_map(|(z, phi)| {
            let r = (1.0 - z * z).sqrt();
            Vec3::new(r * phi.cos(), r * phi.sin(), z)
        })
    }

    /// A restitution coefficient in (0, 1], with 1 often.
    pub fn alpha() -> impl Strategy<Value = f64> {
        prop_oneof![Just(1.0), 1e-6f64..=1.0]
    }
}

/// A launched physics's trajectory as bits: `T_raw` at each of `times` and every final
/// (physical) velocity, and rim velocity when the particles are rough, from stream `(seed,
/// 0)`, with the counts. Two physics that must be the same process to the last bit compare
/// these.
pub fn trajectory(
    ph: &gdsmc_core::physics::Physics,
    seed: u64,
    times: &[f64],
) -> (Vec<u64>, gdsmc_core::engine::Counts) {
    use gdsmc_core::engine::EventLoop;
    use gdsmc_core::particles::{Particle, Particles, Spin};
    let model = ph.validate().unwrap();
    let mut buf = vec![Particle::default(); ph.n];
    let mut spins = vec![Spin::default(); ph.n];
    let mut p = if model.rotates() {
        Particles::with_spins(&mut buf, &mut spins).unwrap()
    } else {
        Particles::new(&mut buf).unwrap()
    };
    let mut rng = gdsmc_core::rng::stream(seed, 0);
    let (mut e, _) = model.launch(&mut p, 0.0, &mut rng).unwrap();
    let mut bits = Vec::new();
    for &t in times {
        let o = e.advance_to(&mut p, t, &mut rng).unwrap();
        bits.push(o.t_raw.to_bits());
    }
    let frame = e.velocity_map();
    for i in 0..p.len() {
        let v = frame.physical(p.velocity(i));
        bits.extend([v.x, v.y, v.z].map(f64::to_bits));
        if p.has_spins() {
            let w = p.spin(i);
            bits.extend([w.x, w.y, w.z].map(f64::to_bits));
        }
    }
    (bits, e.counts())
}

/// [`trajectory`] with the collision count alone.
pub fn trajectory_bits(
    ph: &gdsmc_core::physics::Physics,
    seed: u64,
    times: &[f64],
) -> (Vec<u64>, u64) {
    let (bits, counts) = trajectory(ph, seed, times);
    (bits, counts.collisions)
}

/// The kernels the bit-identity tests run: hard spheres and Maxwell molecules of unit
/// `gamma` and `C = 1/(4 pi)`.
pub mod kernels {
    use gdsmc_core::physics::KernelChoice;
    /// Hard spheres.
    pub const HARD: KernelChoice = KernelChoice::hard_spheres(1.0, 0.25 / core::f64::consts::PI);
    /// Maxwell molecules.
    pub const MAXWELL: KernelChoice = KernelChoice::maxwell(1.0, 0.25 / core::f64::consts::PI);
}
