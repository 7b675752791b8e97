//! The weighted exact loop (core/src/weighted/nosplit.rs, Rjasanow and Wagner's SWPM) keeps
//! GRW's exact temperature of the Maxwell gas: `E[T_bulk(t)] = T_bulk(0) exp(-c t)`,
//! `c = (1 - alpha^2) int B de / 4`, given each ensemble's own start, for any weight transfer
//! and through reductions (module docs of `weighted::nosplit`). Judged at three times together
//! (Bonferroni) at 99.9%, with either reduction; the rate a transfer that forgot `gamma` would give,
//! `c (1 + kappa)`, is refused at the same intervals.

use gdsmc_core::geometry::{Disks, Spheres};
use gdsmc_core::kernel::Maxwell;
use gdsmc_core::restitution::Constant;
use gdsmc_core::rng::Streams;
use gdsmc_core::sample::standard_normal3;
use gdsmc_core::weighted::nosplit::WeightedNoSplitting;
use gdsmc_core::weighted::{Reduction, Transfer, WeightedParticle, WeightedSystem};
use gdsmc_stats::Sample;

const ALPHA: f64 = 0.5;
const TIMES: [f64; 3] = [1.0, 4.0, 8.0];

/// Each ensemble's `T_bulk(t)/T_bulk(0)` at [`TIMES`] in dimension `G`, with the most
/// particles a system held and the reductions.
fn ratios<G: gdsmc_core::geometry::Geometry>(
    ensembles: usize,
    seed: u64,
    reduction: Reduction,
) -> (Vec<[f64; 3]>, usize, u64) {
    let (n0, cap) = (64, 256);
    // gamma C = 1/(4 pi): int B de = 1.
    let kernel = Maxwell::new(1.0, 1.0 / (4.0 * std::f64::consts::PI)).unwrap();
    let law = Constant::new(ALPHA).unwrap();
    let mut streams = Streams::new(seed);
    let (mut out, mut most, mut reductions) = (Vec::new(), 0, 0);
    for _ in 0..ensembles {
        let mut rng = streams.next().unwrap();
        let mut buf = vec![WeightedParticle::default(); cap];
        for p in buf.iter_mut().take(n0) {
            let mut v = standard_normal3(&mut rng);
            if G::CHOICE.d() == 2 {
                v.z = 0.0;
            }
            *p = WeightedParticle::new(v, 1.0);
        }
        let mut sys = WeightedSystem::new(&mut buf, n0).unwrap();
        let t0 = gdsmc_core::weighted::nosplit::observe(&sys, G::CHOICE.d(), 0.0).t_bulk;
        let mut e = WeightedNoSplitting::<_, _, G>::start(
            (kernel, law),
            Transfer::new(1.0).unwrap(),
            reduction,
            &sys,
            0.0,
        )
        .unwrap();
        let mut r = [0.0; 3];
        for (k, &t) in TIMES.iter().enumerate() {
            let o = e.advance_to(&mut sys, t, &mut rng).unwrap();
            assert!((o.mass - n0 as f64).abs() < 1e-9, "the weight is kept");
            r[k] = o.t_bulk / t0;
            most = most.max(sys.len());
        }
        reductions += e.reductions();
        out.push(r);
    }
    (out, most, reductions)
}

fn check<G: gdsmc_core::geometry::Geometry>(seed: u64, reduction: Reduction) {
    let (r, most, reductions) = ratios::<G>(400, seed, reduction);
    assert!(
        most > 64 && reductions > 0,
        "the weighted path ran: {most}, {reductions}"
    );
    let c = (1.0 - ALPHA * ALPHA) / 4.0;
    for (k, &t) in TIMES.iter().enumerate() {
        let s = Sample::of(&r.iter().map(|x| x[k]).collect::<Vec<_>>());
        let exact = (-c * t).exp();
        assert!(
            s.admits(exact, TIMES.len()),
            "d = {}, t = {t}: {} +- {}, exact {exact}",
            G::CHOICE.d(),
            s.mean,
            s.joint_ci(TIMES.len())
        );
        if t > 1.0 {
            let wrong = (-2.0 * c * t).exp();
            assert!(
                !s.admits(wrong, TIMES.len()),
                "t = {t}: {wrong} not refused"
            );
        }
    }
}

#[test]
fn the_weighted_maxwell_gas_cools_at_grws_exact_rate() {
    check::<Spheres>(31, Reduction::Cells { group: 4 });
    check::<Disks>(32, Reduction::Cells { group: 4 });
    // The allocated reduction, every shell given the same number (the tail's particles kept).
    let equal_shells = Reduction::Allocated {
        target: 96,
        shells: 16,
        exponent: 0.0,
    };
    check::<Spheres>(33, equal_shells);
}
