//! MS's time-stepped scheme converges to the exact (no-splitting) process as h -> 0: at MS's
//! step h = 0.01 lambda / v0 the mean temperature of GRW Example 5 (heated hard spheres) agrees
//! with the no-splitting scheme's within the combined 99.9% half-width of the difference,
//! sqrt(ci_a^2 + ci_b^2); with steps 50 times longer the time-step error is resolved.

use gdsmc_runner::run::columns::name;
use gdsmc_runner::scene::SchemeChoice;
use gdsmc_validation::*;

#[test]
fn time_stepped_converges_to_no_splitting() {
    let n = 256;
    let mut exact = shipped("grw-example5", n, 3000, 1101);
    exact
        .set_times(vec![0.0, 0.5, 1.0, 2.0])
        .expect("valid observation times");
    let st_exact = run(&exact);
    let mut fine = exact.clone();
    fine.seed = 1102;
    fine.with_physics(|ph| ph.scheme = SchemeChoice::TimeStepped(0.01))
        .expect("a valid physics");
    let st_fine = run(&fine);
    let mut coarse = fine.clone();
    coarse
        .with_physics(|ph| ph.scheme = SchemeChoice::TimeStepped(0.5))
        .expect("a valid physics");
    let st_coarse = run(&coarse);
    let mut resolved = false;
    for ti in 1..exact.times.len() {
        let (a, ca) = at(&st_exact, ti, name::T_BULK);
        let (b, cb) = at(&st_fine, ti, name::T_BULK);
        let (c, cc) = at(&st_coarse, ti, name::T_BULK);
        let t = exact.times[ti];
        assert!(
            (a - b).abs() <= (ca * ca + cb * cb).sqrt(),
            "t={t}: no-splitting {a} +- {ca}, time-stepped {b} +- {cb}"
        );
        resolved |= (a - c).abs() > (ca * ca + cc * cc).sqrt();
    }
    assert!(resolved, "the coarse steps' error should be visible");
    assert!(st_fine.counts.collisions > 0 && st_fine.counts.fictitious > 0);
}
