//! Disks (`d = 2`, `gdsmc_core::geometry::Disks`): the hard-disk impact and scattering laws
//! (KS tests at fixed seeds), velocities that stay in the plane, the elastic perfectly rough
//! disks' equipartition of their finite system, and the refusals. Statistical checks use fixed
//! seeds and 99.9% levels.

use crate::common;

use common::{check_finite_equipartition, ks_critical_999, ks_statistic};
use gdsmc_core::engine::EventLoop;
use gdsmc_core::geometry::{DimensionChoice, Disks, Geometry};
use gdsmc_core::kernel::{HardSpheres, Maxwell};
use gdsmc_core::particles::{Particle, Particles, Spin};
use gdsmc_core::physics::{
    DriveChoice, KernelChoice, Physics, RestitutionLaw, RotationChoice, SchemeChoice, SpeciesChoice,
};
use gdsmc_core::rng::seeded;
use gdsmc_core::vec3::Vec3;

fn disks(n: usize, kernel: KernelChoice, alpha: f64, drive: DriveChoice) -> Physics {
    let mut ph = Physics::new(
        n,
        kernel,
        RestitutionLaw::Constant(alpha),
        drive,
        SchemeChoice::NoSplitting,
    );
    ph.dimension = DimensionChoice::Two;
    ph
}

const HARD: KernelChoice = KernelChoice::hard_spheres(1.0, 0.25 / core::f64::consts::PI);

/// The impact direction of hard disks: in the plane, on the approaching side, and its
/// component across `u_hat` (the impact parameter `b`) uniform on (-1, 1). Also the scattering
/// direction of GRW (3) for hard disks: `u_hat . e = 2 b^2 - 1`, so `sqrt((1 + u_hat . e)/2)
/// = |b|` is uniform on (0, 1); for the Maxwell kernel `e` is uniform on the circle (its angle
/// uniform). Three KS tests, Bonferroni 3 x 0.1%: the critical value at 0.1%/3 is taken as
/// the 99.9% one times 1.12 (sqrt(ln(2/0.000333)/ln(2/0.001))).
#[test]
fn hard_disks_have_the_impact_law_and_maxwell_disks_scatter_isotropically() {
    let mut rng = seeded(77);
    let u = Vec3::new(0.3, -1.7, 0.0);
    let (uh, up) = (
        (1.0 / u.norm()) * u,
        (1.0 / u.norm()) * Vec3::new(1.7, 0.3, 0.0),
    );
    let m = 200_000;
    let crit = 1.12 * ks_critical_999(m);
    let mut b = Vec::with_capacity(m);
    for _ in 0..m {
        let n = Disks::impact(u, &mut rng);
        assert_eq!(n.z, 0.0);
        assert!((n.norm() - 1.0).abs() < 1e-14 && n.dot(u) >= 0.0);
        b.push(n.dot(up));
    }
    let d = ks_statistic(&mut b, |x| ((x + 1.0) / 2.0).clamp(0.0, 1.0));
    assert!(d < crit, "impact parameter: KS {d} >= {crit}");
    let mut s = Vec::with_capacity(m);
    for _ in 0..m {
        let e = Disks::scattering::<HardSpheres, _>(u, &mut rng);
        assert_eq!(e.z, 0.0);
        s.push(((1.0 + uh.dot(e)) / 2.0).max(0.0).sqrt());
    }
    let d = ks_statistic(&mut s, |x| x.clamp(0.0, 1.0));
    assert!(d < crit, "hard-disk scattering: KS {d} >= {crit}");
    let mut a = Vec::with_capacity(m);
    for _ in 0..m {
        let e = Disks::scattering::<Maxwell, _>(u, &mut rng);
        assert!(e.z == 0.0 && (e.norm() - 1.0).abs() < 1e-14);
        a.push(e.y.atan2(e.x));
    }
    let pi = core::f64::consts::PI;
    let d = ks_statistic(&mut a, |x| ((x + pi) / (2.0 * pi)).clamp(0.0, 1.0));
    assert!(d < crit, "Maxwell disks' scattering: KS {d} >= {crit}");
}

/// Every velocity stays in the plane, through collisions, white noise and observations, and
/// the observables count two degrees of freedom (`T = <|v|^2>/2`).
#[test]
fn disks_stay_in_the_plane() {
    let n = 64;
    let model = disks(n, HARD, 0.8, DriveChoice::WhiteNoise(0.5))
        .validate()
        .unwrap();
    let mut buf = vec![Particle::default(); n];
    let mut p = Particles::new(&mut buf).unwrap();
    let mut rng = seeded(3);
    let (mut e, _) = model.launch(&mut p, 0.0, &mut rng).unwrap();
    let obs = e.advance_to(&mut p, 20.0, &mut rng).unwrap();
    assert!(e.counts().collisions > 10 * n as u64);
    assert!(p.as_slice().iter().all(|q| q.vz == 0.0));
    let t: f64 = p
        .as_slice()
        .iter()
        .map(|q| q.velocity().norm2())
        .sum::<f64>()
        / (2 * n) as f64;
    assert!((obs.t_raw - t).abs() <= 1e-12 * t, "{} vs {t}", obs.t_raw);
}

/// Alpha = beta = 1 keeps the energy; its stationary law is uniform on the energy shell with
/// the momentum fixed: `2(n - 1)` translational and `n` rotational degrees of freedom (one
/// per disk) share it equally, so `E[T_tr] = (n - 1)/n E[T_rot]` with `T_tr = <|c|^2>/2`,
/// `T_rot = kappa <w_z^2>`. At n = 8 the sample must also refuse `T_tr = T_rot`.
/// The constant force (MS (14)) on disks, smooth and rough, split and time-stepped: the
/// velocities stay in the plane, the bulk velocity is kept (MS (62)) to rounding, and with
/// elastic collisions (smooth, or perfectly rough: energy kept) the force alone changes the
/// energy, by `2 g h sum |c_i| + (g h)^2 sum |c_hat_i - k|^2 > 0` per step (`sum c_i = 0`), so
/// `T_bulk` grows at every observation.
#[test]
fn disks_under_the_constant_force_stay_in_the_plane_keep_their_momentum_and_heat() {
    let n = 64;
    for (scheme, rough) in [
        (SchemeChoice::Strang(0.05), false),
        (SchemeChoice::TimeStepped(0.01), false),
        (SchemeChoice::Euler(0.05), true),
    ] {
        let mut ph = disks(
            n,
            HARD,
            1.0,
            DriveChoice::declared(gdsmc_core::physics::DriveKind::ConstantForce, &[0.5]).unwrap(),
        );
        ph.scheme = scheme;
        ph.initial[0].drift = [1.0, -2.0, 0.0];
        if rough {
            ph.rotation = Some(RotationChoice::disks(1.0));
        }
        let model = ph.validate().unwrap();
        let (mut buf, mut spins) = (vec![Particle::default(); n], vec![Spin::default(); n]);
        let mut p = if rough {
            Particles::with_spins(&mut buf, &mut spins).unwrap()
        } else {
            Particles::new(&mut buf).unwrap()
        };
        let mut rng = seeded(5);
        let (mut e, o0) = model.launch(&mut p, 0.0, &mut rng).unwrap();
        let mut last = o0.t_bulk;
        for t in [0.5, 1.0, 2.0, 4.0] {
            let o = e.advance_to(&mut p, t, &mut rng).unwrap();
            assert!(
                o.t_bulk > last,
                "{scheme:?}, rough {rough}: T_bulk {last} -> {} at t = {t}",
                o.t_bulk
            );
            last = o.t_bulk;
            let dv = (o.bulk - o0.bulk).norm();
            assert!(
                dv <= 1e-12 * (1.0 + last.sqrt()),
                "{scheme:?}, rough {rough}: bulk moved {dv}"
            );
        }
        assert!(
            e.counts().collisions > 2 * n as u64,
            "{scheme:?}: {:?}",
            e.counts()
        );
        assert!(p.as_slice().iter().all(|q| q.vz == 0.0), "{scheme:?}");
    }
}

#[test]
fn elastic_perfectly_rough_disks_relax_to_equipartition_of_their_finite_system() {
    let n = 8;
    let mut ph = disks(n, HARD, 1.0, DriveChoice::None);
    ph.rotation = Some(RotationChoice {
        temperature: 0.0,
        ..RotationChoice::disks(1.0)
    });
    let model = ph.validate().unwrap();
    check_finite_equipartition(&model, 20_000, 2025, 0.5, |p| {
        assert!(p.as_slice().iter().all(|q| q.vz == 0.0));
        assert!(
            p.spins()
                .iter()
                .all(|s| s.rim_velocity().x == 0.0 && s.rim_velocity().y == 0.0)
        );
    });
}

/// Disks refuse what is written for spheres only, naming the parameter.
#[test]
fn disks_refuse_what_they_do_not_have() {
    // Disks take the splittings and (hard disks) MS's time-stepped scheme.
    let mut stepped = disks(8, HARD, 0.9, DriveChoice::None);
    stepped.scheme = SchemeChoice::TimeStepped(0.01);
    assert!(stepped.validate().is_ok());
    let mut splitting = disks(8, HARD, 0.9, DriveChoice::None);
    splitting.scheme = SchemeChoice::Euler(0.1);
    assert!(splitting.validate().is_ok());
    let mut impact = disks(8, HARD, 0.9, DriveChoice::None);
    impact.restitution = RestitutionLaw::ImpactSpeed {
        beta0: 0.1,
        delta: 0.1,
    };
    impact
        .species
        .push(SpeciesChoice::new(4, 1.0, 1.0))
        .unwrap();
    impact
        .species
        .push(SpeciesChoice::new(4, 2.0, 1.0))
        .unwrap();
    // A mixture of disks takes the impact-speed law too (one law for every pair).
    assert!(impact.validate().is_ok());
    let mut drift = disks(8, HARD, 0.9, DriveChoice::None);
    drift.initial[0].drift = [0.0, 0.0, 1.0];
    let mut inertia = disks(8, HARD, 0.9, DriveChoice::None);
    inertia.rotation = Some(RotationChoice {
        kappa: 1.2,
        ..RotationChoice::disks(0.0)
    });
    let host = |drift| {
        disks(
            8,
            HARD,
            0.9,
            DriveChoice::HostMedium {
                kernel: gdsmc_core::physics::BackgroundKernel::Maxwell,
                c1: 1.0,
                density: 1.0,
                mass: 1.0,
                temperature: 1.0,
                drift,
            },
        )
    };
    // Disks take a host medium (tests/tests/host_medium.rs), about a drift in the plane.
    assert!(host([1.0, 2.0, 0.0]).validate().is_ok());
    let cases: [(Physics, &str); 3] = [
        (
            host([0.0, 0.0, 1.0]),
            "background_drift must lie in the plane (z = 0) for disks",
        ),
        (
            drift,
            "components[0].drift must lie in the plane (z = 0) for disks",
        ),
        (inertia, "inertia must lie in (0, 1] for disks, got 1.2"),
    ];
    for (ph, want) in cases {
        let got = ph.validate().unwrap_err().to_string();
        assert!(
            got.starts_with(want),
            "{got:?} does not start with {want:?}"
        );
    }
    // A rough disk's kappa may exceed a sphere's 2/3.
    let mut ring = disks(8, HARD, 0.9, DriveChoice::None);
    ring.rotation = Some(RotationChoice {
        kappa: 0.9,
        ..RotationChoice::disks(0.0)
    });
    assert!(ring.validate().is_ok());
}

/// The impact-speed law BRS (9) with `delta = 0` is the constant `alpha = 1 - 2 beta0`: disks
/// under it follow the constant law's trajectory to the last bit (the same draws, the same
/// coefficient), for both kernels, cooling and heated.
#[test]
fn disks_under_the_impact_speed_law_of_delta_0_are_the_constant_law_to_the_last_bit() {
    let beta0 = 0.05;
    for kernel in [
        HARD,
        KernelChoice::maxwell(1.0, 0.25 / core::f64::consts::PI),
    ] {
        for drive in [DriveChoice::None, DriveChoice::WhiteNoise(0.5)] {
            let constant = disks(64, kernel, 1.0 - 2.0 * beta0, drive);
            let mut impact = constant.clone();
            impact.restitution = RestitutionLaw::ImpactSpeed { beta0, delta: 0.0 };
            let trajectory = |ph: &Physics| common::trajectory_bits(ph, 41, &[1.0, 2.0, 4.0, 8.0]);
            let (a, ca) = trajectory(&constant);
            let (b, cb) = trajectory(&impact);
            assert!(ca > 100, "{kernel:?}, {drive:?}: {ca} collisions");
            assert_eq!((a, ca), (b, cb), "{kernel:?}, {drive:?}");
        }
    }
}

/// Hard disks under the impact-speed law BRS (9)-(10), `delta > 0`: the mean energy a pair of
/// fixed velocities loses per collision under GRW (3), `(1 - alpha^2) |u|^2 (1 - u_hat . e) / 8`
/// with `u_hat . e = 2 b^2 - 1`, `b` uniform on (-1, 1) (the hard-disk impact law) and
/// `alpha = 1 - 2 beta0 |g . n|^delta`, `|g . n|^2 = (|u|^2 - |u| (u . e)) / 2` (BRS (9)-(10),
/// the normal of the map itself: `restitution::ImpactSpeed`),
/// by quadrature, against 200,000 collisions
/// of the loop's map (99.9%, 3.2 standard errors). The spheres' scattering (`u_hat . e`
/// uniform) gives another mean, which the check must refuse.
#[test]
fn hard_disks_under_the_impact_speed_law_lose_the_energy_of_brs_9_10() {
    use gdsmc_core::engine::{CollisionMap, Counts};
    use gdsmc_core::restitution::ImpactSpeed;
    let (beta0, delta) = (0.2, 0.6);
    let law = ImpactSpeed::new(beta0, delta).unwrap();
    let (vi, vj) = (Vec3::new(1.3, -0.4, 0.0), Vec3::new(-0.5, 0.2, 0.0));
    let u2 = (vi - vj).norm2();
    // The mean loss for the cosine `ue = u_hat . e` of the scattering direction.
    let loss = |ue: f64| {
        let gn = (0.5 * u2 * (1.0 - ue)).max(0.0).sqrt();
        let alpha = (1.0 - 2.0 * beta0 * gn.powf(delta)).clamp(0.0, 1.0);
        (1.0 - alpha * alpha) * u2 * (1.0 - ue) / 8.0
    };
    let k = 200_000;
    let disks_mean = (0..k)
        .map(|i| {
            let b = -1.0 + 2.0 * (i as f64 + 0.5) / k as f64;
            loss(2.0 * b * b - 1.0)
        })
        .sum::<f64>()
        / k as f64;
    let spheres_mean = (0..k)
        .map(|i| loss(-1.0 + 2.0 * (i as f64 + 0.5) / k as f64)) // u_hat . e uniform
        .sum::<f64>()
        / k as f64;
    let mut rng = seeded(77);
    let mut counts = Counts::default();
    let mut buf = [Particle::default(); 2];
    let mut p = Particles::new(&mut buf).unwrap();
    let energy = |a: Vec3, b: Vec3| 0.5 * (a.norm2() + b.norm2());
    let samples: Vec<f64> = (0..k)
        .map(|_| {
            let (a, b) = law.collide_pair::<HardSpheres, Disks, _>(
                &mut p,
                (0, 1),
                (vi, vj),
                &mut rng,
                &mut counts,
            );
            energy(vi, vj) - energy(a, b)
        })
        .collect();
    let (m, h) = common::mean_ci(&samples);
    assert!(
        (m - disks_mean).abs() <= h,
        "hard disks: mean loss {m} +- {h}, BRS (9)-(10) with the impact law {disks_mean}"
    );
    assert!(
        (m - spheres_mean).abs() > h,
        "the check cannot tell the disks' scattering from the spheres' ({spheres_mean})"
    );
}

/// The time unit of hard disks: a gas of diameter `sigma` at areal density `n_A` collides, per
/// particle, `2 sigma n_A <|g|>` times per unit time (the 2D cross-section is `2 sigma`: two
/// disks meet when the impact parameter lies in `(-sigma, sigma)`), so it is the engine's
/// `4 pi gamma C <|g|>` with `4 pi gamma C = 2 sigma n_A` (spheres: `pi sigma^2 n`,
/// docs/disks.md). Elastic hard disks from the Maxwellian at `T = 1` (the product Maxwellian
/// is stationary, so `<|g|> = sqrt(pi T)` at every time), `sigma = 0.02`, `n_A = 25`: the mean
/// number of collisions in `[0, t]` of `n` particles is `n/2 (n - 1)/n 2 sigma n_A sqrt(pi) t`
/// exactly. Checked at 99.9% over 400 ensembles (the half-width below 1% of the count, asserted); the
/// mapping `4 pi gamma C = sigma n_A` the docs gave before would halve it.
#[test]
fn hard_disks_collide_at_twice_sigma_n_a_times_the_mean_relative_speed() {
    let (sigma, n_a) = (0.02, 25.0);
    let kernel = KernelChoice::hard_spheres(1.0, 2.0 * sigma * n_a / (4.0 * core::f64::consts::PI));
    let (n, t) = (1000, 2.0);
    let model = disks(n, kernel, 1.0, DriveChoice::None).validate().unwrap();
    let mut streams = gdsmc_core::rng::Streams::new(2051);
    let mut buf = vec![Particle::default(); n];
    let counts: Vec<f64> = (0..400)
        .map(|_| {
            let mut rng = streams.next().unwrap();
            let mut p = Particles::new(&mut buf).unwrap();
            let (mut e, _) = model.launch(&mut p, 0.0, &mut rng).unwrap();
            e.advance_to(&mut p, t, &mut rng).unwrap();
            e.counts().collisions as f64
        })
        .collect();
    let want = 0.5 * (n as f64 - 1.0) * 2.0 * sigma * n_a * core::f64::consts::PI.sqrt() * t;
    let (m, h) = common::mean_ci(&counts);
    assert!(
        (m - want).abs() <= h,
        "collisions {m} +- {h}, 2 sigma n_A <|g|> gives {want}"
    );
    assert!(h < 0.01 * want, "no power: +- {h} of {want}");
}
