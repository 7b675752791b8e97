//! Every SIMD batch kernel against its plain scalar twin with a fixed seed (RustFFT style).

use crate::common;
use common::*;
use gdsmc_core::batch::kick::*;
use gdsmc_core::batch::lanes::{Lanes, central_lanes};
use gdsmc_core::batch::sums::*;
use gdsmc_core::batch::sync::*;
use gdsmc_core::moments::Observables;
use gdsmc_core::particles::{Particle, Particles};
use gdsmc_core::rng::seeded;
use gdsmc_core::sample::{Maxwellian, standard_normal};
use gdsmc_core::vec3::Vec3;

fn rel(a: f64, b: f64) -> f64 {
    (a - b).abs() / a.abs().max(b.abs()).max(1e-300)
}

#[test]
fn simd_sums_equal_scalar_sums() {
    let mut rng = seeded(31);
    let mx = Maxwellian::new(1.0, 2.0, Vec3::new(0.3, -0.2, 1.0)).unwrap();
    for n in [1usize, 2, 3, 4, 5, 7, 8, 9, 63, 64, 65, 1001] {
        let q: Vec<Particle> = (0..n)
            .map(|_| Particle::new(mx.sample(&mut rng), 0.0))
            .collect();
        let a = accumulate_simd(&q);
        let b = accumulate_scalar(&q);
        assert_eq!(a.n, b.n);
        let pairs =
            a.s1.iter()
                .zip(&b.s1)
                .chain(a.s2.iter().zip(&b.s2))
                .chain(a.s3.iter().zip(&b.s3));
        for (x, y) in pairs {
            // Different summation order: a few ulps per term of the sum of magnitudes.
            assert!(
                (x - y).abs() <= 1e-13 * (n as f64) * (1.0 + y.abs()),
                "n = {n}: {x} vs {y}"
            );
        }
        for (x, y) in a.c2.iter().zip(&b.c2).chain(a.c3.iter().zip(&b.c3)) {
            assert!(
                (x - y).abs() <= 1e-13 * (n as f64) * (1.0 + y.abs()),
                "n = {n}: {x} vs {y}"
            );
        }
        for (x, y) in [
            (a.s4, b.s4),
            (a.s6, b.s6),
            (a.c1, b.c1),
            (a.c3n, b.c3n),
            (a.c4, b.c4),
            (a.c6, b.c6),
        ] {
            assert!(rel(x, y) < 1e-13, "n = {n}: {x} vs {y}");
        }
        assert!(rel(a.max_c2, b.max_c2) < 1e-13, "n = {n}");
    }
}

#[test]
fn simd_sync_sums_equal_scalar_and_the_observables() {
    let mut rng = seeded(37);
    // A drift far above the thermal speed: the sums about a nearby reference keep the digits.
    let mx = Maxwellian::new(1.0, 2.0, Vec3::new(30.0, -20.0, 100.0)).unwrap();
    for n in [1usize, 2, 3, 4, 5, 7, 8, 9, 63, 64, 65, 1001] {
        let mut q: Vec<Particle> = (0..n)
            .map(|_| Particle::new(mx.sample(&mut rng), 0.0))
            .collect();
        let vref = Vec3::new(30.1, -19.9, 100.05);
        let a = sync_sums_simd(&q, vref);
        let b = sync_sums_scalar(&q, vref);
        assert_eq!(a.n, b.n);
        for (x, y) in a.s1.iter().zip(&b.s1) {
            assert!(
                (x - y).abs() <= 1e-13 * (n as f64) * (1.0 + y.abs()),
                "n = {n}: {x} vs {y}"
            );
        }
        assert!(rel(a.s2, b.s2) < 1e-13, "n = {n}");
        assert_eq!(a.max2, b.max2, "n = {n}: the same maximum");
        if n < 2 {
            continue;
        }
        let obs = Observables::of(&Particles::new(&mut q).unwrap());
        let v = a.bulk(vref);
        assert!((v - obs.bulk).norm() <= 1e-13 * obs.bulk.norm(), "n = {n}");
        assert!(rel(a.t_bulk(3), obs.t_bulk) < 1e-10, "n = {n}");
        // Umax = 2 max |v - vref| bounds every relative speed, as GRW step 1.4's about V.
        let umax = 2.0 * a.max2.sqrt();
        for x in &q {
            for y in &q {
                assert!((x.velocity() - y.velocity()).norm() <= umax, "n = {n}");
            }
        }
    }
}

/// A system with staggered last-kick times.
fn staggered(n: usize) -> Vec<Particle> {
    let mut rng = seeded(34);
    (0..n)
        .map(|i| {
            Particle::new(
                Vec3::new(standard_normal(&mut rng), 1.0, -2.0),
                (i % 7) as f64 * 0.1,
            )
        })
        .collect()
}

#[test]
fn simd_kick_is_bit_identical_to_scalar_kick() {
    // Both draw their normals in particle order from the same generator and do the same IEEE
    // operations (no FMA), so the results must agree to the bit, remainders included.
    for n in [2usize, 3, 4, 5, 8, 13, 1000, 1003] {
        let mut a = staggered(n);
        let mut b = a.clone();
        white_noise_kick_all_simd(
            1.6,
            &mut Particles::new(&mut a).unwrap(),
            1.0,
            &mut seeded(35),
        );
        white_noise_kick_all_scalar(
            1.6,
            &mut Particles::new(&mut b).unwrap(),
            1.0,
            &mut seeded(35),
        );
        assert_eq!(a, b, "n = {n}");
    }
}

#[test]
fn kick_increments_are_normal_with_variance_2_beta_dt() {
    // v_i(t) - v_i(t_i) = sqrt(2 beta (t - t_i)) xi: the scaled increments are standard normal
    // (KS at 99.9%), and every last-kick time becomes t.
    let n = 30_003;
    let before = staggered(n);
    let mut after = before.clone();
    let (beta, t) = (0.8, 1.0);
    white_noise_kick_all(
        2.0 * beta,
        &mut Particles::new(&mut after).unwrap(),
        t,
        &mut seeded(36),
    );
    let mut z = Vec::new();
    for (p, q) in before.iter().zip(&after) {
        assert_eq!(q.t_kick, t);
        let s = (2.0 * beta * (t - p.t_kick)).sqrt();
        let d = q.velocity() - p.velocity();
        z.extend_from_slice(&[d.x / s, d.y / s, d.z / s]);
    }
    let m = z.len();
    let d = ks_statistic(&mut z, normal_cdf);
    assert!(d < ks_critical_999(m), "KS D = {d}");
}

#[test]
fn central_moments_equal_grw_formulas_from_raw_moments() {
    // GRW Section 1: P = M - rho V V^T, q = r - (M + (tr M / 2 - rho |V|^2) I) V. The observables
    // take P and q from central sums; for a moderate drift the raw-moment formulas must agree
    // to rounding.
    use gdsmc_core::moments::Observables;
    let mut rng = seeded(37);
    let mx = Maxwellian::new(1.0, 1.5, Vec3::new(0.7, -0.4, 0.2)).unwrap();
    let mut q: Vec<Particle> = (0..999)
        .map(|_| Particle::new(mx.sample(&mut rng), 0.0))
        .collect();
    let o = Observables::of(&Particles::new(&mut q).unwrap());
    let (v, m, r) = (o.bulk, o.momentum_flow, o.energy_flow);
    let vv = [
        v.x * v.x,
        v.y * v.y,
        v.z * v.z,
        v.x * v.y,
        v.x * v.z,
        v.y * v.z,
    ];
    for k in 0..6 {
        assert!((o.stress[k] - (m[k] - vv[k])).abs() < 1e-12, "P[{k}]");
    }
    let tr = m[0] + m[1] + m[2];
    let d = 0.5 * tr - v.norm2();
    let mv = Vec3::new(
        m[0] * v.x + m[3] * v.y + m[4] * v.z,
        m[3] * v.x + m[1] * v.y + m[5] * v.z,
        m[4] * v.x + m[5] * v.y + m[2] * v.z,
    );
    let q_grw = r - (mv + d * v);
    assert!(
        (o.heat_flux - q_grw).norm() < 1e-11,
        "{:?} vs {:?}",
        o.heat_flux,
        q_grw
    );
    assert!((o.t_bulk - (o.t_raw - v.norm2() / 3.0)).abs() < 1e-12);
}

#[test]
fn bulk_temperature_keeps_its_digits_under_a_large_drift() {
    // A cold gas moving fast: T = 1e-20 about a drift of 1. From raw sums T_bulk would be lost
    // to cancellation; the central sums keep it.
    let mut rng = seeded(38);
    let mx = Maxwellian::new(1.0, 1e-20, Vec3::new(1.0, 0.0, 0.0)).unwrap();
    let mut q: Vec<Particle> = (0..10_000)
        .map(|_| Particle::new(mx.sample(&mut rng), 0.0))
        .collect();
    let o = gdsmc_core::moments::Observables::of(&Particles::new(&mut q).unwrap());
    // Sample temperature of 10^4 draws: relative sd sqrt(2/(3n)) = 0.8%; 3.2 sd bound.
    assert!(
        (o.t_bulk / 1e-20 - 1.0).abs() < gdsmc_stats::LAMBDA_999 * (2.0f64 / 30_000.0).sqrt(),
        "T_bulk = {:e}",
        o.t_bulk
    );
}

/// The raw sums `sum v v^T`, `sum v |v|^2`, `sum |v|^4`, `sum |v|^6` that the kernels rebuild
/// from the central ones ([`raw_from_central`]) against the same sums taken directly, for a gas
/// at rest and one drifting at 30 sqrt(T), both kernels: each within a rounding bound
/// (1e-13 of the sum of the terms' magnitudes per particle). A wrong coefficient in the
/// expansion is off by a fraction of the sum itself.
#[test]
fn raw_sums_follow_from_central_ones() {
    let mut rng = seeded(37);
    for drift in [Vec3::ZERO, Vec3::new(30.0, -20.0, 10.0)] {
        let mx = Maxwellian::new(1.0, 1.0, drift).unwrap();
        let n = 1001;
        let q: Vec<Particle> = (0..n)
            .map(|_| Particle::new(mx.sample(&mut rng), 0.0))
            .collect();
        let (mut s2, mut s3, mut s4, mut s6) = ([0.0; 6], [0.0; 3], 0.0, 0.0);
        let (mut m2, mut m3, mut m4, mut m6) = ([0.0; 6], [0.0; 3], 0.0, 0.0);
        for p in &q {
            let v = [p.vx, p.vy, p.vz];
            let v2 = v[0] * v[0] + v[1] * v[1] + v[2] * v[2];
            for (k, (a, b)) in [(0, 0), (1, 1), (2, 2), (0, 1), (0, 2), (1, 2)]
                .into_iter()
                .enumerate()
            {
                s2[k] += v[a] * v[b];
                m2[k] += (v[a] * v[b]).abs();
            }
            for a in 0..3 {
                s3[a] += v[a] * v2;
                m3[a] += (v[a] * v2).abs();
            }
            (s4, m4) = (s4 + v2 * v2, m4 + v2 * v2);
            (s6, m6) = (s6 + v2 * v2 * v2, m6 + v2 * v2 * v2);
        }
        for sums in [accumulate_simd(&q), accumulate_scalar(&q)] {
            let bound = |m: f64| 1e-13 * n as f64 * m;
            for k in 0..6 {
                assert!(
                    (sums.s2[k] - s2[k]).abs() <= bound(m2[k]),
                    "s2[{k}] {drift:?}"
                );
            }
            for a in 0..3 {
                assert!(
                    (sums.s3[a] - s3[a]).abs() <= bound(m3[a]),
                    "s3[{a}] {drift:?}"
                );
            }
            assert!(
                (sums.s4 - s4).abs() <= bound(m4),
                "s4 {drift:?}: {} {s4}",
                sums.s4
            );
            assert!((sums.s6 - s6).abs() <= bound(m6), "s6 {drift:?}");
        }
    }
}

/// The AVX loop of the moment sums (chosen at run time on x86_64) against the portable one,
/// lane by lane to the bit: the Maxwellian about a far bulk velocity, a cold gas, spreads over
/// ten decades. Where the processor has no AVX there is nothing to compare (and nothing runs
/// it).
#[cfg(target_arch = "x86_64")]
#[test]
fn avx_lanes_are_the_portable_lanes_to_the_bit() {
    use gdsmc_core::batch::lanes_avx;
    if !lanes_avx::available() {
        eprintln!("no AVX here: the AVX lanes are not run");
        return;
    }
    let mut rng = seeded(41);
    for (t, drift) in [
        (1.0, Vec3::new(0.3, -0.2, 1.0)),
        (1e-12, Vec3::new(1e3, 0.0, -2.0)),
        (1e8, Vec3::new(0.0, 0.0, 0.0)),
    ] {
        let mx = Maxwellian::new(1.0, t, drift).unwrap();
        for n in [0usize, 4, 8, 64, 1000] {
            let q: Vec<Particle> = (0..n)
                .map(|k| Particle::new((1.0 + k as f64) * mx.sample(&mut rng), 0.5))
                .collect();
            let bulk = Vec3::new(0.25, -1.0, 3.0);
            let a = lanes_avx::central_lanes(&q, bulk).unwrap();
            let b = central_lanes(&q, bulk);
            let bits = |l: &Lanes| -> Vec<u64> {
                let mut v: Vec<f64> = l.c2.iter().chain(&l.c3).flatten().copied().collect();
                for x in [l.c1, l.c3n, l.c4, l.c6, l.max_c2, l.s6] {
                    v.extend(x);
                }
                v.into_iter().map(f64::to_bits).collect()
            };
            assert_eq!(bits(&a), bits(&b), "n = {n}, T = {t}");
        }
    }
}
