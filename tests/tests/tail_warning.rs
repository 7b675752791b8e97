//! The `tail-not-asymptotic` warning: GRW Example 7 (heated hard spheres) at the shipped size
//! fits an exponent near 1.75, not GRW (16)'s asymptotic 1.5, and is flagged; an elastic gas
//! with no heating stays Maxwellian (exponent 2 at every speed, nothing to converge) and is
//! not. Fixed seeds.

use gdsmc_validation::*;

fn codes(set: &[&str]) -> Vec<&'static str> {
    let s = shipped_set("grw-example7", set, 20_000, 8, 5);
    let st = run(&s);
    gdsmc_runner::analysis::warnings::check(&s, &st)
        .into_iter()
        .map(|w| w.code)
        .collect()
}

#[test]
fn a_tail_short_of_its_asymptote_is_flagged() {
    assert!(codes(&[]).contains(&"tail-not-asymptotic"));
}

#[test]
fn a_maxwellian_tail_is_not() {
    let c = codes(&["drive.beta=0", "collisions.restitution=1"]);
    assert!(!c.contains(&"tail-not-asymptotic"), "{c:?}");
}
