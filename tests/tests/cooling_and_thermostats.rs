//! No drive (the homogeneous cooling state) and the Gaussian thermostat (MS (12)).
//!
//! Maxwell kernel: `E T_bulk,n(t) = (1 - 1/n) T_0 exp(-(k - 2 zeta) t)` exactly (the argument of
//! `MaxwellTemperature::finite_n_bulk_mean`, with the Gaussian kick scaling every velocity by
//! `e^{zeta h}`), checked within the 99.9% confidence interval over many decades.
//! Hard spheres: Haff's law, `T^{-1/2}(t)` linear in t with slope `xi/2`,
//! `xi = (1 - alpha^2) (16/3) sqrt(pi) gamma C (1 + 3 a2 / 16)` (the cooling rate of MS (27)-(28)
//! with a2 of the homogeneous cooling state, MS (5)), checked decade by decade.

use gdsmc_runner::run::columns::name;
use gdsmc_runner::scene::{DriveChoice, KernelKind, SchemeChoice};
use gdsmc_theory::curves::maxwell_temperature;
use gdsmc_validation::*;

#[test]
fn maxwell_cooling_is_exponential_over_thirty_decades() {
    let n = 8;
    let mut s = shipped("rw-transient", n, 20_000, 901);
    s.with_physics(|ph| ph.drive = DriveChoice::None)
        .expect("a valid physics");
    s.set_times((0..=10).map(|i| 10.0 * i as f64).collect())
        .expect("valid observation times"); // k = 3/4: T falls to e^-75 ~ 3e-33
    let mt = maxwell_temperature(&s).unwrap();
    let st = run(&s);
    for (ti, &t) in st.times.iter().enumerate() {
        let (m, c) = at(&st, ti, name::T_BULK);
        let exact = mt.finite_n_bulk_mean(n, t);
        assert!(
            (m - exact).abs() <= c,
            "t={t}: T_bulk {m:e} +- {c:e}, exact {exact:e}"
        );
        assert!(m > 0.0 && m.is_finite());
    }
    assert!(mt.at(100.0) < 1e-30);
}

#[test]
fn gaussian_thermostat_with_maxwell_kernel_is_exact() {
    // zeta = k/4: T = T0 exp(-k t / 2); also through Strang splitting (the kick scales X by
    // e^{2 zeta dt}, see MaxwellTemperature::splitting_bulk_mean).
    let n = 8;
    for (k, scheme) in [SchemeChoice::NoSplitting, SchemeChoice::Strang(1.0)]
        .into_iter()
        .enumerate()
    {
        let mut s = shipped("rw-transient", n, 20_000, 910 + k as u64);
        s.with_physics(|ph| {
            ph.drive =
                DriveChoice::declared(gdsmc_core::physics::DriveKind::Gaussian, &[0.75 / 4.0])
                    .unwrap()
        })
        .expect("a valid physics");
        s.set_times((0..=8).map(f64::from).collect())
            .expect("valid observation times");
        s.with_physics(|ph| ph.scheme = scheme)
            .expect("a valid physics");
        let mt = maxwell_temperature(&s).unwrap();
        let st = run(&s);
        for (ti, &t) in st.times.iter().enumerate() {
            let (m, c) = at(&st, ti, name::T_BULK);
            let exact = match scheme {
                SchemeChoice::NoSplitting => mt.finite_n_bulk_mean(n, t),
                _ => mt.splitting_bulk_mean(n, 1.0, true, t),
            };
            assert!(
                (m - exact).abs() <= c,
                "{scheme:?} t={t}: T_bulk {m} +- {c}, exact {exact}"
            );
        }
    }
}

#[test]
fn hard_spheres_follow_haffs_law_over_ten_decades() {
    let (n, alpha) = (2048, 0.5);
    let mut s = shipped("grw-example5", n, 60, 920);
    s.with_physics(|ph| ph.drive = DriveChoice::None)
        .expect("a valid physics");
    s.with_physics(|ph| ph.restitution = gdsmc_runner::scene::RestitutionLaw::Constant(alpha))
        .expect("a valid physics");
    let k = s.physics().kernel;
    assert_eq!(k.kind(), KernelKind::HardSpheres);
    let (gamma, c) = (k.gamma(), k.c());
    // MS (5), d = 3: a2 of the homogeneous cooling state.
    let a2 = 16.0 * (1.0 - alpha) * (1.0 - 2.0 * alpha * alpha)
        / (9.0 + 72.0 - alpha * (41.0 - 24.0) + 30.0 * (1.0 - alpha) * alpha * alpha);
    let xi = (1.0 - alpha * alpha) * 16.0 / 3.0
        * std::f64::consts::PI.sqrt()
        * gamma
        * c
        * (1.0 + 3.0 * a2 / 16.0);
    let t0 = 2.0 / xi; // T0 = 1: T = 1 / (1 + t/t0)^2
    // Times where Haff's T is 1e-2, 1e-4, ..., 1e-10.
    s.set_times(
        [0.0, 1e1, 1e2, 1e3, 1e4, 1e5]
            .iter()
            .map(|&r: &f64| (r - 1.0).max(0.0) * t0)
            .collect(),
    )
    .expect("valid observation times");
    let st = run(&s);
    assert_eq!(
        st.counts.overshoots, 0,
        "no drive: the majorant always holds"
    );
    let (t_last, _) = at(&st, st.times.len() - 1, name::T_BULK);
    assert!(t_last < 1e-9, "ten decades: T = {t_last:e}");
    for w in 1..st.times.len() - 1 {
        let (ta, tb) = (st.times[w], st.times[w + 1]);
        let (ma, ca) = at(&st, w, name::T_BULK);
        let (mb, cb) = at(&st, w + 1, name::T_BULK);
        let slope = (mb.powf(-0.5) - ma.powf(-0.5)) / (tb - ta);
        // Propagated half-width: d(T^{-1/2}) = T^{-3/2} dT / 2.
        let conf = (0.5 * mb.powf(-1.5) * cb + 0.5 * ma.powf(-1.5) * ca) / (tb - ta);
        // Allowance beyond the interval: 1/n for the finite-n bias of T_bulk (about -T/n, which
        // shifts T^{-1/2} by T^{-1/2}/(2n)) and 0.5% for the Sonine estimate of a2.
        let allow = conf + slope * (1.0 / n as f64 + 0.005);
        assert!(
            (slope - xi / 2.0).abs() <= allow,
            "window {w}: slope {slope} vs Haff {} (+- {allow})",
            xi / 2.0
        );
    }
}

/// MS Section 2.2: in reduced variables the homogeneous cooling state is the steady state of
/// the Gaussian thermostat. The collisional moments (MS (67)) of a cooling gas, which the
/// engine stores rescaled far below T = 1e-8, must equal the Gaussian thermostat's within the
/// two runs' 99.9% half-widths (alpha = 0.8: T falls by about five decades over the average).
#[test]
fn cooling_gas_has_the_gaussian_thermostats_collisional_moments() {
    let common = [
        "collisions.restitution=0.8",
        "observe.collisional_pairs=20000",
    ];
    let mut hcs_set = common.to_vec();
    hcs_set.extend([
        "observe.t_end=20000",
        "observe.intervals=50",
        "observe.spacing=linear",
        "observe.steady_from=2000",
    ]);
    let hcs = run(&shipped_set("hcs-hard-spheres", &hcs_set, 2048, 16, 1500));
    let gauss = run(&shipped_set("ms-gaussian", &common, 2048, 16, 1501));
    let get = |st: &gdsmc_runner::run::RunStats, c: &str| {
        st.steady
            .as_ref()
            .unwrap()
            .steady_mean_ci(st, st.col(c).unwrap())
    };
    let t_last = at(&hcs, hcs.times.len() - 1, name::LOG10_T_BULK).0;
    assert!(
        t_last < -8.0,
        "the cooling gas must be stored rescaled: log10 T = {t_last}"
    );
    for c in [name::MU2, name::MU4, name::A2] {
        let (a, ca) = get(&hcs, c);
        let (b, cb) = get(&gauss, c);
        assert!(
            a.is_finite() && (a - b).abs() <= ca + cb,
            "{c}: HCS {a} +- {ca}, Gaussian thermostat {b} +- {cb}"
        );
    }
}
