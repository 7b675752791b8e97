//! The weighted exact loop (core/src/weighted/nosplit/mod.rs, Rjasanow and Wagner's SWPM) keeps
//! GRW's exact temperature of the Maxwell gas: `E[T_bulk(t)] = T_bulk(0) exp(-c t)`,
//! `c = (1 - alpha^2) int B de / 4`, given each ensemble's own start, for any weight transfer
//! and through reductions (module docs of `weighted::nosplit`). Judged at three times together
//! (Bonferroni) at 99.9%, with either reduction; the rate a transfer that forgot `gamma` would give,
//! `c (1 + kappa)`, is refused at the same intervals. Heated by white noise, GRW (13) at finite
//! weight (derived in [`heated_band`]).

use gdsmc_core::drive::{NoDrive, PlanarWhiteNoise, WhiteNoise};
use gdsmc_core::geometry::{Disks, Spheres};
use gdsmc_core::kernel::Maxwell;
use gdsmc_core::particles::{Particle, Particles};
use gdsmc_core::restitution::Constant;
use gdsmc_core::rng::Streams;
use gdsmc_core::sample::standard_normal3;
use gdsmc_core::weighted::moments::observables;
use gdsmc_core::weighted::nosplit::WeightedNoSplitting;
use gdsmc_core::weighted::{Reduction, Transfer};
use gdsmc_stats::Sample;

const ALPHA: f64 = 0.5;
const TIMES: [f64; 3] = [1.0, 4.0, 8.0];

/// Buffers of `cap` records and weights, the first `n0` a Maxwellian sample of weight 1 in
/// dimension `G`.
fn start<G: gdsmc_core::geometry::Geometry>(
    n0: usize,
    cap: usize,
    rng: &mut gdsmc_core::rng::Xoshiro256PlusPlus,
) -> (Vec<Particle>, Vec<f64>) {
    let (mut buf, mut g) = (vec![Particle::default(); cap], vec![0.0; cap]);
    for (p, w) in buf.iter_mut().zip(g.iter_mut()).take(n0) {
        let mut v = standard_normal3(rng);
        if G::CHOICE.d() == 2 {
            v.z = 0.0;
        }
        *p = Particle::new(v, 0.0);
        *w = 1.0;
    }
    (buf, g)
}

/// Each ensemble's `T_bulk(t)/T_bulk(0)` at [`TIMES`] in dimension `G`, with the most
/// particles a system held and the reductions.
fn ratios<G: gdsmc_core::geometry::Geometry>(
    (ensembles, cap): (usize, usize),
    seed: u64,
    (transfer, reduction, split): (Transfer, Reduction, f64),
) -> (Vec<[f64; 3]>, usize, u64) {
    let n0 = 64;
    // gamma C = 1/(4 pi): int B de = 1.
    let kernel = Maxwell::new(1.0, 1.0 / (4.0 * std::f64::consts::PI)).unwrap();
    let law = Constant::new(ALPHA).unwrap();
    let mut streams = Streams::new(seed);
    let (mut out, mut most, mut reductions) = (Vec::new(), 0, 0);
    for _ in 0..ensembles {
        let mut rng = streams.next().unwrap();
        let (mut buf, mut g) = start::<G>(n0, cap, &mut rng);
        let mut sys = Particles::weighted(&mut buf, &mut g, n0).unwrap();
        let t0 = observables(&sys, G::CHOICE.d()).t_bulk;
        let mut e = WeightedNoSplitting::<_, _, _, G>::start(
            (kernel, law, NoDrive),
            transfer,
            reduction,
            &mut sys,
            0.0,
        )
        .unwrap()
        .with_windows(split);
        e.resync(&mut sys).unwrap();
        let mut r = [0.0; 3];
        for (k, &t) in TIMES.iter().enumerate() {
            let o = e.advance_to(&mut sys, t, &mut rng).unwrap();
            assert!((sys.mass() - n0 as f64).abs() < 1e-9, "the weight is kept");
            r[k] = o.t_bulk / t0;
            most = most.max(sys.len());
        }
        reductions += e.reductions();
        out.push(r);
    }
    (out, most, reductions)
}

fn check<G: gdsmc_core::geometry::Geometry>(seed: u64, reduction: Reduction) {
    check_with::<G>(seed, (Transfer::new(1.0).unwrap(), reduction));
}

fn check_with<G: gdsmc_core::geometry::Geometry>(seed: u64, (t, r): (Transfer, Reduction)) {
    check_split::<G>(seed, (t, r, 0.0));
}

fn check_split<G: gdsmc_core::geometry::Geometry>(seed: u64, how: (Transfer, Reduction, f64)) {
    let (r, most, reductions) = ratios::<G>((400, 256), seed, how);
    assert!(
        most > 64 && reductions > 0,
        "the weighted path ran: {most}, {reductions}"
    );
    judge::<G>(&r);
}

/// Asserts each ensemble's `T_bulk(t)/T_bulk(0)` of `r` at GRW's exact rate at [`TIMES`]
/// (jointly, 99.9%), and the rate a transfer that forgot `gamma` would give refused.
fn judge<G: gdsmc_core::geometry::Geometry>(r: &[[f64; 3]]) {
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
        floor: 0.0,
    };
    check::<Spheres>(33, equal_shells);
    // A transfer that moves whole weights in the core and an eighth of the lighter partner's
    // into the tail beyond 2 sqrt(T) (its outcomes thinned by (1 + kappa)/(1 + 7)).
    let tail = Transfer::with_tail(0.0, 7.0, 2.0).unwrap();
    check_with::<Spheres>(34, (tail, equal_shells));
    check_with::<Disks>(35, (tail, Reduction::Cells { group: 4 }));
}

/// With weight windows (`weighted::windows`: a particle heavier than twice its speed shell's
/// share split into pieces of the share, after the event that touched it and at every
/// observation) the process keeps GRW's exact rate: a split keeps the measure itself, and it
/// is a change of state after an event, the next waiting time drawn at the new rate. Equal
/// weights with whole transfers: only the windows make particles (every shell given the same
/// number, so the few fast particles of the start are split at once), in d = 3 and 2.
#[test]
fn the_windowed_maxwell_gas_cools_at_grws_exact_rate() {
    let equal_shells = Reduction::Allocated {
        target: 96,
        shells: 16,
        exponent: 0.0,
        floor: 0.0,
    };
    let whole = Transfer::new(0.0).unwrap();
    check_split::<Spheres>(36, (whole, equal_shells, 2.0));
    check_split::<Disks>(37, (whole, equal_shells, 2.0));
}

/// A reduction is a change of state at an instant, after the collision that filled the buffer,
/// not an event of the majorant: a first version reduced in place of the next candidate and so
/// dropped one event of the old rate each time, and the gas cooled too slowly. With room for
/// only one more particle every ensemble is reduced once (64 equal weights to 32 of weight 2;
/// `kappa = 0` makes no particle after that): the dropped event made `T(t)/T(0)` 0.6% high at
/// t = 1 (0.8344 +- 0.0032 against 0.8290), and this test failed; it holds now (d = 3, 2).
#[test]
fn a_reduction_drops_no_event() {
    for (seed, d3) in [(81, true), (82, false)] {
        let how = (
            Transfer::new(0.0).unwrap(),
            Reduction::Cells { group: 4 },
            0.0,
        );
        let (r, _, reductions) = if d3 {
            ratios::<Spheres>((4000, 65), seed, how)
        } else {
            ratios::<Disks>((4000, 65), seed, how)
        };
        assert!(reductions >= 4000, "every ensemble reduced: {reductions}");
        if d3 {
            judge::<Spheres>(&r);
        } else {
            judge::<Disks>(&r);
        }
    }
}

/// GRW (13) for the weighted system: `Q = S2 - |P|^2/n0 = n0 d T_bulk` obeys
/// `dE[Q]/dt = -c E[Q] + 2 beta d (n0 - E[sum g^2]/n0)` (the collisions as above; each
/// particle's kicks add `2 beta g` per unit time to `E[S2]` and `2 beta g^2 / n0` to
/// `E[|P|^2/n0]`, per degree of freedom). With `0 <= sum g^2 / n0^2 <= g_max / n0` the mean
/// `E[T_bulk(t)]` lies between `T0 e^{-ct} + f 2 beta (1 - e^{-ct}) / c` at `f = 1 - g_max/n0`
/// and at `f = 1`: the band a verdict must touch, from this bound and not from a run.
fn heated_band(t0: f64, beta: f64, c: f64, t: f64, gmax_over_n0: f64) -> (f64, f64) {
    let decay = (-c * t).exp();
    let at = |f: f64| t0 * decay + f * 2.0 * beta * (1.0 - decay) / c;
    (at(1.0 - gmax_over_n0), at(1.0))
}

fn heated<G: gdsmc_core::geometry::Geometry, D: gdsmc_core::drive::Drive>(
    drive: D,
    beta: f64,
    seed: u64,
) {
    let (n0, cap, ensembles) = (64, 256, 400);
    let kernel = Maxwell::new(1.0, 1.0 / (4.0 * std::f64::consts::PI)).unwrap();
    let law = Constant::new(ALPHA).unwrap();
    let mut streams = Streams::new(seed);
    let (mut samples, mut gmax, mut reductions) = (vec![Vec::new(); 3], 0.0_f64, 0);
    let mut t0s = Vec::new();
    for _ in 0..ensembles {
        let mut rng = streams.next().unwrap();
        let (mut buf, mut g) = start::<G>(n0, cap, &mut rng);
        let mut sys = Particles::weighted(&mut buf, &mut g, n0).unwrap();
        t0s.push(observables(&sys, G::CHOICE.d()).t_bulk);
        let mut e = WeightedNoSplitting::<_, _, _, G>::start(
            (kernel, law, drive),
            Transfer::new(1.0).unwrap(),
            Reduction::Cells { group: 4 },
            &mut sys,
            0.0,
        )
        .unwrap();
        for (k, &t) in TIMES.iter().enumerate() {
            let o = e.advance_to(&mut sys, t, &mut rng).unwrap();
            samples[k].push(o.t_bulk);
            gmax = sys.weights().iter().fold(gmax, |m, &g| m.max(g));
        }
        reductions += e.reductions();
    }
    assert!(reductions > 0, "the weighted path ran");
    let t0 = Sample::of(&t0s).mean;
    let c = (1.0 - ALPHA * ALPHA) / 4.0;
    for (k, &t) in TIMES.iter().enumerate() {
        let s = Sample::of(&samples[k]);
        let (lo, hi) = heated_band(t0, beta, c, t, gmax / n0 as f64);
        let half = s.joint_ci(TIMES.len());
        assert!(
            s.mean + half >= lo && s.mean - half <= hi,
            "d = {}, t = {t}: {} +- {half}, GRW (13) band [{lo}, {hi}]",
            G::CHOICE.d(),
            s.mean
        );
        // A drive that heated twice as fast is refused.
        let (_, wrong) = heated_band(t0, 2.0 * beta, c, t, 0.0);
        assert!(
            s.mean + half < wrong,
            "t = {t}: twice the heating {wrong} not refused"
        );
    }
}

#[test]
fn the_weighted_maxwell_gas_heats_as_grw_13() {
    heated::<Spheres, _>(WhiteNoise::new(0.5).unwrap(), 0.5, 41);
    heated::<Disks, _>(PlanarWhiteNoise::new(0.5).unwrap(), 0.5, 42);
}

/// `zeta*` of the weighted Maxwell gas from random pairs, each counted by `g_i g_j`
/// (`EventLoop::cooling`): for the Maxwell kernel every state's exact value is
/// `(1 - alpha^2)/4 W^2 / (W^2 - sum g^2)`, `W = sum g` (the pair sums of the module docs of
/// `weighted::nosplit`: `sum_{i<j} g_i g_j |u|^2 = W S2 - |P|^2` against the energy about the
/// flow and `sum_{i<j} g_i g_j = (W^2 - sum g^2)/2`; `n/(n - 1)` for equal weights). Eight
/// particles, four of weight 1 and four of 1e-3 (exact factor 1.333; equal weights' 8/7 =
/// 1.143 is refused), 60 independent estimates of 4000 pairs, at 99.9%.
#[test]
fn the_weighted_cooling_rate_is_the_maxwell_gas_exact_one() {
    use gdsmc_core::engine::EventLoop;
    let kernel = Maxwell::new(1.0, 1.0 / (4.0 * std::f64::consts::PI)).unwrap();
    let law = Constant::new(ALPHA).unwrap();
    let mut rng = Streams::new(61).next().unwrap();
    let (mut buf, mut g) = start::<Spheres>(8, 16, &mut rng);
    for w in &mut g[4..8] {
        *w = 1e-3;
    }
    let mut sys = Particles::weighted(&mut buf, &mut g, 8).unwrap();
    let e = WeightedNoSplitting::<_, _, _, Spheres>::start(
        (kernel, law, NoDrive),
        Transfer::new(1.0).unwrap(),
        Reduction::Cells { group: 4 },
        &mut sys,
        0.0,
    )
    .unwrap();
    let w = sys.mass();
    let g2: f64 = sys.weights().iter().map(|g| g * g).sum();
    let base = (1.0 - ALPHA * ALPHA) / 4.0;
    let (exact, equal) = (base * w * w / (w * w - g2), base * 8.0 / 7.0);
    let mut diag = Streams::new(62).next().unwrap();
    let z: Vec<f64> = (0..60)
        .map(|_| EventLoop::cooling(&e, &sys, 4000, &mut diag).zeta_star)
        .collect();
    let s = Sample::of(&z);
    assert!(
        s.admits(exact, 1),
        "{} +- {}, exact {exact}",
        s.mean,
        s.joint_ci(1)
    );
    assert!(!s.admits(equal, 1), "the equal-weight {equal} not refused");
}

/// A cooling gas of hard spheres on weighted particles (alpha = 0.3, `n0 = 128`, `kappa` 1 in
/// the core and 7 beyond 3 sqrt(T), the allocated reduction) runs to t = 20, where its
/// temperature has fallen 2500-fold, with every velocity and weight finite and no weight
/// below [`LIGHTEST`]`/(1 + kappa_max)`. It failed in every one of 20 seeds before (t = 4-28):
/// a light particle at a few sqrt(T), halved by each of its ever more frequent
/// collisions, fell below 1e-300 and to 0, and the global scale of a reduction's correction
/// walked such particles out to overflow.
#[test]
fn a_weighted_hard_sphere_gas_cools_without_overflow() {
    use gdsmc_core::kernel::HardSpheres;
    use gdsmc_core::weighted::nosplit::LIGHTEST;
    let kernel = HardSpheres::new(1.0, 1.0).unwrap();
    let law = Constant::new(0.3).unwrap();
    let transfer = Transfer::with_tail(1.0, 7.0, 3.0).unwrap();
    let floor = LIGHTEST / (1.0 + transfer.kappa_max());
    let mut streams = Streams::new(91);
    for _ in 0..4 {
        let mut rng = streams.next().unwrap();
        let (mut buf, mut g) = start::<Spheres>(128, 384, &mut rng);
        let mut sys = Particles::weighted(&mut buf, &mut g, 128).unwrap();
        let t0 = observables(&sys, 3).t_bulk;
        let reduction = Reduction::Allocated {
            target: 192,
            shells: 32,
            exponent: 0.5,
            floor: 0.0,
        };
        let mut e = WeightedNoSplitting::<_, _, _, Spheres>::start(
            (kernel, law, NoDrive),
            transfer,
            reduction,
            &mut sys,
            0.0,
        )
        .unwrap();
        let mut lightest = f64::INFINITY;
        let mut t_bulk = t0;
        for k in 1..=40 {
            let o = e.advance_to(&mut sys, 0.5 * k as f64, &mut rng).unwrap();
            lightest = sys.weights().iter().fold(lightest, |m, &w| m.min(w));
            t_bulk = o.t_bulk;
        }
        assert!(e.reductions() > 100, "reduced: {}", e.reductions());
        assert!(lightest >= floor, "a weight {lightest:e} below {floor:e}");
        assert!(
            t_bulk.is_finite() && t_bulk < t0 / 1000.0,
            "T_bulk {t_bulk} from {t0}"
        );
    }
}
