//! Hard spheres with no drive run on the sum-form majorant (`engine::SumNoSplitting`):
//! the same process as on `Umax` (`engine::NoSplitting`), shown in law: two independent
//! samples of 4,000 systems each (n = 64, alpha = 0.7, cooling), the mean `T_bulk`, `a2` and
//! collision count at four times compared by the two-sample z statistic at the 99.9% level,
//! Bonferroni over the 12 checks (z = 4.0). And the same comparison refuses a wrong process
//! (alpha = 0.72 against 0.7), so it can fail. The sum form must also waste far fewer
//! candidates (acceptance above 0.6 against about 0.2).

use gdsmc_core::engine::EventLoop;
use gdsmc_core::particles::{Particle, Particles};
use gdsmc_core::physics::{
    DriveChoice, KernelChoice, Model, Physics, RestitutionLaw, SchemeChoice,
};
use gdsmc_core::rng::Streams;
use gdsmc_stats::Sample;

const TIMES: [f64; 4] = [0.5, 1.0, 2.0, 4.0];

fn model(alpha: f64) -> Model {
    Physics::new(
        64,
        KernelChoice::hard_spheres(4.0, 0.25 / core::f64::consts::PI),
        RestitutionLaw::Constant(alpha),
        DriveChoice::None,
        SchemeChoice::NoSplitting,
    )
    .validate()
    .unwrap()
}

/// Per time: (T_bulk, a2, collisions) of every system; and the acceptance.
fn sample(m: &Model, seed: u64) -> (Vec<[Vec<f64>; 3]>, f64) {
    let mut out: Vec<[Vec<f64>; 3]> = (0..TIMES.len()).map(|_| Default::default()).collect();
    let mut streams = Streams::new(seed);
    let (mut cand, mut coll) = (0u64, 0u64);
    for _ in 0..4000 {
        let mut rng = streams.next().unwrap();
        let mut buf = vec![Particle::default(); m.n()];
        let mut p = Particles::new(&mut buf).unwrap();
        let (mut e, _) = m.launch(&mut p, 0.0, &mut rng).unwrap();
        for (k, &t) in TIMES.iter().enumerate() {
            let o = e.advance_to(&mut p, t, &mut rng).unwrap();
            out[k][0].push(o.t_bulk);
            out[k][1].push(o.a2);
            out[k][2].push(e.counts().collisions as f64);
        }
        cand += e.counts().candidates;
        coll += e.counts().collisions;
    }
    (out, coll as f64 / cand as f64)
}

/// The largest two-sample z over every time and observable.
fn largest_z(a: &[[Vec<f64>; 3]], b: &[[Vec<f64>; 3]]) -> f64 {
    let mut z: f64 = 0.0;
    for (x, y) in a.iter().zip(b) {
        for q in 0..3 {
            let (sa, sb) = (Sample::of(&x[q]), Sample::of(&y[q]));
            z = z.max(sa.z_from(&sb).abs());
        }
    }
    z
}

#[test]
fn the_sum_majorant_runs_the_umax_process() {
    let (sum, acc_sum) = sample(&model(0.7), 71);
    let (umax, acc_umax) = sample(&model(0.7).with_umax_majorant(), 72);
    // Every time and observable, held together at 99.9% (Bonferroni; thousands of systems).
    let limit = gdsmc_stats::joint(3 * TIMES.len(), gdsmc_stats::KNOWN);
    let z = largest_z(&sum, &umax);
    assert!(
        z < limit,
        "sum form against Umax: largest z = {z} > {limit}"
    );
    assert!(
        acc_sum > 0.6 && acc_umax < 0.35,
        "acceptance {acc_sum} vs {acc_umax}"
    );
    // It can fail: a slightly different restitution is refused by the same comparison.
    let (other, _) = sample(&model(0.72), 73);
    let z = largest_z(&other, &umax);
    assert!(z > limit, "alpha 0.72 not told from 0.7: largest z = {z}");
}
