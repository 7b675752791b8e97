//! Rough particles (`gdsmc_core::rough`) through the scene and the runner: with tangential
//! restitution beta = -1 the translation is the smooth gas's, exactly in law: the Maxwell
//! kernel's `T_bulk` is GRW (13)'s exact finite-n mean at every time, and hard spheres give the
//! smooth loop's `T_bulk` (a two-sample check). Both families are checked at the 99.9% level
//! jointly (Bonferroni over their time points), and each shows it can fail: beta = 0 leaves
//! GRW (13) at most times.

use gdsmc_runner::run::columns::name;
use gdsmc_stats::{dof, family};
use gdsmc_theory::curves::maxwell_temperature;
use gdsmc_validation::*;

const MAXWELL_SMOOTH: [&str; 6] = [
    "collisions.kernel=maxwell",
    "collisions.restitution=0.5",
    "rotation.tangential_restitution=-1",
    "rotation.temperature=2.0",
    "drive.kind=white-noise",
    "drive.beta=1.0",
];

#[test]
fn the_smooth_limit_of_the_rough_maxwell_gas_is_grw_13_at_every_time() {
    let n = 8;
    let mut s = shipped_set("rough-hcs", &MAXWELL_SMOOTH, n, 20_000, 1601);
    s.set_times((0..=8).map(|k| 0.5 * k as f64).collect())
        .expect("valid observation times");
    s.set_steady_from(None).unwrap();
    let mt = maxwell_temperature(&s).expect("beta = -1: GRW (13) applies");
    let st = run(&s);
    let f = family(st.times.len(), dof(st.ensembles));
    for (ti, &t) in st.times.iter().enumerate() {
        let (m, c) = at(&st, ti, name::T_BULK);
        let exact = mt.finite_n_bulk_mean(n, t);
        assert!(
            (m - exact).abs() <= f * c,
            "t = {t}: T_bulk {m} +- {}, exact {exact}",
            f * c
        );
        // No collision touches the rotation: T_rot keeps its start (a Maxwellian at 2).
        let (r, rc) = at(&st, ti, name::T_ROT);
        assert!((r - 2.0).abs() <= f * rc, "t = {t}: T_rot {r} +- {rc}");
    }
    // The same comparison refuses a rough gas: with beta = 0 the translation loses energy to
    // the rotation and GRW (13) no longer holds.
    let mut set = MAXWELL_SMOOTH;
    set[2] = "rotation.tangential_restitution=0";
    let mut r = shipped_set("rough-hcs", &set, n, 20_000, 1602);
    r.set_times(s.times().to_vec())
        .expect("valid observation times");
    r.set_steady_from(None).unwrap();
    assert!(maxwell_temperature(&r).is_none());
    let st = run(&r);
    let outside = times_outside(&st, name::T_BULK, f, |t| mt.finite_n_bulk_mean(n, t));
    assert!(
        outside >= st.times.len() - 2,
        "only {outside} times tell beta = 0 from smooth"
    );
}

#[test]
fn the_smooth_limit_of_rough_hard_spheres_is_the_smooth_gas() {
    let n = 64;
    let set = [
        "collisions.restitution=0.7",
        "rotation.tangential_restitution=-1",
    ];
    let mut rough = shipped_set("rough-hcs", &set, n, 4000, 1603);
    rough
        .set_times((0..=6).map(|k| 0.5 * k as f64).collect())
        .expect("valid observation times");
    rough.set_steady_from(None).unwrap();
    let mut smooth = rough.clone();
    smooth
        .with_physics(|ph| ph.rotation = None)
        .expect("a valid physics");
    smooth.set_seed(1604);
    let (a, b) = (run(&rough), run(&smooth));
    let f = family(a.times.len() - 1, dof(a.ensembles.min(b.ensembles)));
    let mut moved = 0.0;
    for ti in 1..a.times.len() {
        let (ma, ca) = at(&a, ti, name::T_BULK);
        let (mb, cb) = at(&b, ti, name::T_BULK);
        let h = f * (ca * ca + cb * cb).sqrt();
        assert!(
            (ma - mb).abs() <= h,
            "t = {}: rough (beta = -1) {ma} vs smooth {mb} +- {h}",
            a.times[ti]
        );
        moved = ma;
    }
    // The gas cooled: the check compares something that changed.
    assert!(moved < 0.5, "T_bulk only fell to {moved}");
}

/// The Gaussian thermostat on a rough gas's translation (MS (12)): with beta = -1 the
/// translation is the smooth Maxwell gas's under the thermostat, whose `T_bulk` is GRW (13)
/// times `e^{2 zeta t}` exactly at finite n, while the rotation keeps its start (2). Checked
/// at every time jointly (two quantities per time, Bonferroni); beta = 0 must leave the
/// same curve.
#[test]
fn the_thermostatted_smooth_limit_of_the_rough_maxwell_gas_is_exact() {
    let n = 8;
    let mut set = MAXWELL_SMOOTH;
    set[4] = "drive.kind=gaussian";
    set[5] = "drive.zeta=0.3";
    let mut s = shipped_set("rough-hcs", &set, n, 20_000, 1605);
    s.set_times((0..=8).map(|k| 0.5 * k as f64).collect())
        .expect("valid observation times");
    s.set_steady_from(None).unwrap();
    let mt = maxwell_temperature(&s).expect("beta = -1: GRW (13) with the thermostat applies");
    let st = run(&s);
    let f = family(2 * st.times.len(), dof(st.ensembles));
    assert_within_at_all_times(
        &st,
        name::T_BULK,
        f,
        |t| mt.finite_n_bulk_mean(n, t),
        "rough beta = -1, thermostat",
    );
    assert_within_at_all_times(&st, name::T_ROT, f, |_| 2.0, "T_rot, thermostat");
    // The thermostat acted: T_bulk at the end is not the cooling gas's.
    let last = st.times.len() - 1;
    let cooling = maxwell_temperature(&shipped_set("rough-hcs", &MAXWELL_SMOOTH[..4], n, 1, 1))
        .expect("the cooling smooth limit");
    assert!(
        at(&st, last, name::T_BULK).0 > 2.0 * cooling.finite_n_bulk_mean(n, st.times[last]),
        "the thermostat did not heat"
    );
    let mut rough_set = set;
    rough_set[2] = "rotation.tangential_restitution=0";
    let mut r = shipped_set("rough-hcs", &rough_set, n, 20_000, 1606);
    r.set_times(s.times().to_vec())
        .expect("valid observation times");
    r.set_steady_from(None).unwrap();
    let st = run(&r);
    let outside = times_outside(&st, name::T_BULK, f, |t| mt.finite_n_bulk_mean(n, t));
    assert!(
        outside >= st.times.len() - 2,
        "only {outside} times tell beta = 0 from smooth under the thermostat"
    );
}

/// The constant force (MS (14), (62)) on a rough gas's translation, Euler-split: with beta = -1
/// the translation is the smooth gas's in law, so rough and smooth hard spheres under the same
/// force and step give the same `T_bulk` (two independent runs, every time jointly); with
/// beta = 0 the translation gives energy to the rotation and the same comparison refuses it.
#[test]
fn the_forced_smooth_limit_of_rough_hard_spheres_is_the_smooth_gas() {
    let n = 64;
    let set = [
        "collisions.restitution=0.7",
        "rotation.tangential_restitution=-1",
        "drive.kind=constant-force",
        "drive.g=0.5",
        "scheme.kind=euler",
        "scheme.dt=0.25",
    ];
    let times: Vec<f64> = (0..=6).map(|k| 0.5 * k as f64).collect();
    let runs = |set: &[&str], seed: u64, smooth: bool| {
        let mut s = shipped_set("rough-hcs", set, n, 3000, seed);
        s.set_times(times.clone()).expect("valid observation times");
        s.set_steady_from(None).unwrap();
        if smooth {
            s.with_physics(|ph| ph.rotation = None)
                .expect("a valid physics");
        }
        run(&s)
    };
    let (a, b) = (runs(&set, 1607, false), runs(&set, 1608, true));
    let mut other = set;
    other[1] = "rotation.tangential_restitution=0";
    let c = runs(&other, 1609, false);
    let f = family(2 * (a.times.len() - 1), dof(a.ensembles));
    let mut refused = 0;
    for ti in 1..a.times.len() {
        let (ma, ca) = at(&a, ti, name::T_BULK);
        let (mb, cb) = at(&b, ti, name::T_BULK);
        let (mc, cc) = at(&c, ti, name::T_BULK);
        let h = f * (ca * ca + cb * cb).sqrt();
        assert!(
            (ma - mb).abs() <= h,
            "t = {}: rough (beta = -1) {ma} vs smooth {mb} +- {h}",
            a.times[ti]
        );
        if (mc - mb).abs() > f * (cc * cc + cb * cb).sqrt() {
            refused += 1;
        }
    }
    assert!(
        refused >= a.times.len() - 3,
        "beta = 0 told from smooth at only {refused} times"
    );
}
