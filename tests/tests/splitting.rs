//! RW Algorithms 1 and 2: Euler and Strang splitting of the heated Maxwell gas (RW (27)).
//!
//! For the Maxwell kernel the ensemble mean of T_bulk of each splitting scheme is known
//! exactly at every n and dt (`MaxwellTemperature::splitting_bulk_mean`); the simulated means
//! must match it within their 99.9% confidence intervals, and must differ from the no-splitting
//! value where the time-step error is resolved. The convergence factors of the temperature
//! error in dt are then near 2 (Euler) and 4 (Strang), RW Table 2.

use gdsmc_runner::run::columns::name;
use gdsmc_runner::scene::{Scene, SchemeChoice};
use gdsmc_stats::{dof, family};
use gdsmc_theory::curves::maxwell_temperature;
use gdsmc_validation::*;

/// A shipped scene observed at `times` (set first: the scheme's grid is checked against them)
/// with scheme `s`.
fn scheme(name: &str, n: usize, m: u64, seed: u64, s: SchemeChoice, times: Vec<f64>) -> Scene {
    let mut sc = shipped(name, n, m, seed);
    sc.set_times(times).expect("valid observation times");
    sc.with_physics(|ph| ph.scheme = s)
        .expect("a valid physics");
    sc
}

#[test]
fn splitting_means_are_exact_at_small_n() {
    let n = 8;
    for (k, s) in [SchemeChoice::Euler(1.0), SchemeChoice::Strang(1.0)]
        .into_iter()
        .enumerate()
    {
        let times = (0..=8).map(f64::from).collect();
        let sc = scheme("rw-transient", n, 40_000, 600 + k as u64, s, times);
        let mt = maxwell_temperature(&sc).unwrap();
        let st = run(&sc);
        let strang = matches!(s, SchemeChoice::Strang(_));
        for t in [1.0, 2.0, 4.0, 8.0] {
            let (m, c) = at(&st, time_index(&st, t), name::T_BULK);
            let exact = mt.splitting_bulk_mean(n, 1.0, strang, t);
            assert!(
                (m - exact).abs() <= c,
                "{s:?} t={t}: T_bulk {m} +- {c}, exact {exact}"
            );
            let nosplit = mt.finite_n_bulk_mean(n, t);
            assert!(
                (m - nosplit).abs() > c,
                "{s:?} t={t}: time-step error not resolved"
            );
        }
    }
}

#[test]
fn euler_is_first_order_and_strang_second_order() {
    // RW Table 2 (n = 4096, t in [0, 8], dt = 8/K): E_max = max_k |T(t_k) - T_k| / T(t_k).
    // Each simulated point is compared with the exact value of the scheme's mean at this n
    // within its confidence (joint 99.9% over the 95 points); the factors per halving of dt
    // must be near 2 and 4.
    let n = 4096;
    let cases: [(SchemeChoice, &[f64], f64); 2] = [
        (SchemeChoice::Euler(0.0), &[2.0, 1.0, 0.5, 0.25], 2.0),
        (SchemeChoice::Strang(0.0), &[2.0, 1.0, 0.5], 4.0),
    ];
    for (kind, dts, order_factor) in cases {
        let mut errs = Vec::new();
        for (k, &dt) in dts.iter().enumerate() {
            let s = match kind {
                SchemeChoice::Euler(_) => SchemeChoice::Euler(dt),
                _ => SchemeChoice::Strang(dt),
            };
            let kk = (8.0 / dt).round() as usize;
            let times = (0..=kk).map(|i| i as f64 * dt).collect();
            let sc = scheme("rw-transient", n, 150, 700 + k as u64, s, times);
            let mt = maxwell_temperature(&sc).unwrap();
            let st = run(&sc);
            let strang = matches!(s, SchemeChoice::Strang(_));
            let (mut e, mut conf, mut e_exact) = (0.0f64, 0.0, 0.0f64);
            for (ti, &t) in st.times.iter().enumerate() {
                let (m, c) = at(&st, ti, name::T);
                // 95 points are checked in this test (Euler 5 + 9 + 17 + 33, Strang 5 + 9 + 17):
                // each at the Bonferroni level that keeps the family at 99.9%.
                let c = c * family(95, dof(st.ensembles));
                let exact_curve = mt.at(t);
                let mean_n = mt.splitting_bulk_mean(n, dt, strang, t) + mt.bulk_to_raw(n, t);
                assert!(
                    (m - mean_n).abs() <= c,
                    "{s:?} t={t}: T {m} +- {c}, exact mean {mean_n}"
                );
                let ek = (m - exact_curve).abs() / exact_curve;
                if ek > e {
                    e = ek;
                    conf = c / exact_curve;
                }
                e_exact = e_exact.max((mean_n - exact_curve).abs() / exact_curve);
            }
            errs.push((e, conf, e_exact));
        }
        for w in errs.windows(2) {
            let ((e1, c1, x1), (e2, c2, x2)) = (w[0], w[1]);
            // The ratio of two intervals; one whose denominator's interval reaches 0 (the
            // smaller step's error not resolved) has no upper end.
            let lo = (e1 - c1) / (e2 + c2);
            let hi = if e2 > c2 {
                (e1 + c1) / (e2 - c2)
            } else {
                f64::INFINITY
            };
            assert!(
                lo <= x1 / x2 && x1 / x2 <= hi,
                "{kind:?}: factor of exact errors {} outside [{lo}, {hi}]",
                x1 / x2
            );
            assert!(
                lo < order_factor * 1.5 && hi > order_factor / 1.5,
                "{kind:?}: factor interval [{lo}, {hi}] far from {order_factor}"
            );
        }
    }
}

/// The splittings on disks and on rough particles, through the same generic loop: Maxwell
/// disks heated by white noise in the plane (scenes/disks-white-noise.toml) and rough Maxwell
/// spheres with beta = -1 (rotation untouched; the translation is the smooth gas's in law)
/// under white noise. In both the second moments close as in three dimensions for smooth
/// spheres (`splitting_bulk_mean`: a collision step multiplies `E[S - |P|^2/n]` by `exp(-k h)`, a
/// kick adds `2 d (n - 1) beta dt`; `d` cancels from `T_bulk`), so `T_bulk`'s mean at each grid
/// time is exact at n = 8, and at dt = 1 the time-step error is many half-widths: the
/// no-splitting scheme's exact mean must be refused at most times. Every case's times held
/// together (Bonferroni).
#[test]
fn splitting_on_disks_and_rough_particles_follows_its_exact_finite_n_mean() {
    let n = 8;
    let rough = [
        "collisions.kernel=maxwell",
        "collisions.restitution=0.5",
        "rotation.tangential_restitution=-1",
        "drive.kind=white-noise",
        "drive.beta=1.0",
    ];
    let cases: [(&str, &[&str]); 2] = [("disks-white-noise", &[]), ("rough-hcs", &rough)];
    for (k, (name_, set)) in cases.into_iter().enumerate() {
        for (j, s) in [SchemeChoice::Euler(1.0), SchemeChoice::Strang(1.0)]
            .into_iter()
            .enumerate()
        {
            let mut sc = shipped_set(name_, set, n, 20_000, 900 + 2 * k as u64 + j as u64);
            sc.set_times((0..=6).map(f64::from).collect())
                .expect("valid observation times");
            sc.set_steady_from(None).unwrap();
            sc.with_physics(|ph| ph.scheme = s)
                .expect("a valid physics");
            let mt = maxwell_temperature(&sc).expect("a Maxwell gas: GRW (13) applies");
            let st = run(&sc);
            let strang = matches!(s, SchemeChoice::Strang(_));
            // The rough case checks T_rot at every time too.
            let f = family((1 + k) * st.times.len(), dof(st.ensembles));
            assert_within_at_all_times(
                &st,
                name::T_BULK,
                f,
                |t| mt.splitting_bulk_mean(n, 1.0, strang, t),
                &format!("{name_} {s:?}"),
            );
            let outside = times_outside(&st, name::T_BULK, f, |t| mt.finite_n_bulk_mean(n, t));
            assert!(
                outside >= st.times.len() - 3,
                "{name_} {s:?}: only {outside} times tell the splitting from the exact scheme"
            );
            if k == 1 {
                // beta = -1: no collision touches the rotation (its start temperature, 1).
                assert_within_at_all_times(&st, name::T_ROT, f, |_| 1.0, "rough T_rot");
            }
        }
    }
}
