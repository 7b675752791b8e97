//! GRW Example 5: heated hard spheres (alpha = 1/2, beta = 1/8, gamma = 4, C1 = 1/(4 pi)),
//! whose temperature curves converge as n grows (GRW Figure 5). No exact solution exists; the
//! test checks convergence at the O(1/n) rate: with T(n) = T + c/n + o(1/n), the differences
//! D1 = T(64) - T(256) and D2 = T(256) - T(1024) are significant, of one sign, and their ratio
//! is 4; the ratio's interval is propagated from the 99.9% confidence half-widths.

use gdsmc_runner::run::columns::name;
use gdsmc_validation::*;

#[test]
#[ignore = "long suite: cargo test --workspace --release -- --include-ignored (README, CI)"]
fn example5_converges_in_n() {
    let runs: Vec<(f64, f64)> = [(64usize, 4_000u64), (256, 4_000), (1024, 2_000)]
        .iter()
        .enumerate()
        .map(|(k, &(n, m))| {
            let st = run(&shipped("grw-example5", n, m, 500 + k as u64));
            // Every candidate above the majorant is counted; they must stay rare.
            assert!(
                st.counts.overshoots * 10_000 < st.counts.candidates,
                "overshoots {:?}",
                st.counts
            );
            assert!(
                st.counts.fictitious > 0,
                "hard spheres must see fictitious collisions"
            );
            at(&st, time_index(&st, 2.0), name::T)
        })
        .collect();
    let d1 = runs[0].0 - runs[1].0;
    let c1 = runs[0].1 + runs[1].1;
    let d2 = runs[1].0 - runs[2].0;
    let c2 = runs[1].1 + runs[2].1;
    assert!(
        d1.abs() > c1 && d2.abs() > c2,
        "differences not resolved: {d1} +- {c1}, {d2} +- {c2}"
    );
    assert!(d1.signum() == d2.signum(), "not monotone in n: {d1}, {d2}");
    let lo = (d1.abs() - c1) / (d2.abs() + c2);
    let hi = (d1.abs() + c1) / (d2.abs() - c2);
    assert!(
        lo <= 4.0 && 4.0 <= hi,
        "ratio interval [{lo}, {hi}] misses 4"
    );
}
