//! Granular mixtures (`gdsmc_core::mixture`): a one-species mixture is the one-species loop to
//! the last bit, and the inelastic Maxwell mixture's species temperatures follow the exact
//! finite-N second moments (`gdsmc_theory::mixture`) at every observation time.

use gdsmc_core::drive::{Drive, GaussianThermostat, NoDrive, WhiteNoise};
use gdsmc_core::engine::NoSplitting;
use gdsmc_core::engine::SplittingOrder;
use gdsmc_core::kernel::{HardSpheres, Kernel, Maxwell};
use gdsmc_core::math::PI;
use gdsmc_core::mixture::{
    MixtureNoSplitting, MixtureObservables, MixtureSplitting, MixtureTimeStepped, PairPhysics,
    Species,
};
use gdsmc_core::particles::{Particle, Particles};
use gdsmc_core::physics::Momentum;
use gdsmc_core::restitution::Constant;
use gdsmc_core::rng::{Streams, stream};
use gdsmc_core::sample::Maxwellian;
use gdsmc_core::vec3::Vec3;
use gdsmc_stats::{Sample, dof, joint};
use gdsmc_theory::mixture::MaxwellMixture;

/// Runs the one-species loop and the one-species mixture from the same start and seed and
/// asserts equal observables (every field, to the bit) and counts at each time.
fn same_as_one_species<K: Kernel, D: Drive>(
    kernel: K,
    drive: D,
    alpha: f64,
    n: usize,
    times: &[f64],
) {
    let law = Constant::new(alpha).unwrap();
    let f0 = Maxwellian::standard();
    let mut rng = stream(7, 0);
    let mut a = vec![Particle::default(); n];
    {
        let mut p = Particles::new(&mut a).unwrap();
        p.fill_with(0.0, || f0.sample(&mut rng));
    }
    let mut b = a.clone();
    let (mut ra, mut rb) = (rng.clone(), rng);
    let mut pa = Particles::new(&mut a).unwrap();
    let mut pb = Particles::new(&mut b).unwrap();
    let (mut one, o1) = NoSplitting::start(kernel, drive, law, &mut pa, 0.0).unwrap();
    let sp = Species::new(&[n], &[1.0]).unwrap();
    let pair = PairPhysics {
        kernel,
        restitution: law,
    };
    let (mut mix, o2) = MixtureNoSplitting::start(sp, &[pair], &[drive], &mut pb, 0.0).unwrap();
    assert_eq!(o1, o2.all);
    for &t in times {
        let o1 = one.advance_to(&mut pa, t, &mut ra).unwrap();
        let o2 = mix.advance_to(&mut pb, t, &mut rb).unwrap();
        assert_eq!(o1, o2.all, "t = {t}");
        assert_eq!(o1, o2.species[0], "t = {t}");
        assert_eq!(one.counts(), mix.counts(), "t = {t}");
    }
    assert!(mix.counts().collisions > 2 * n as u64);
}

#[test]
fn one_species_mixture_is_the_one_species_loop_bit_for_bit() {
    let times = [0.5, 1.0, 2.0, 4.0];
    let c = 1.0 / (4.0 * PI);
    same_as_one_species(
        Maxwell::new(4.0, c).unwrap(),
        WhiteNoise::new(1.0).unwrap(),
        0.5,
        500,
        &times,
    );
    same_as_one_species(
        HardSpheres::new(4.0, c).unwrap(),
        WhiteNoise::new(1.0).unwrap(),
        0.5,
        500,
        &times,
    );
    same_as_one_species(HardSpheres::new(4.0, c).unwrap(), NoDrive, 1.0, 500, &times);
    // A cooling gas followed long enough to be rescaled (the stored velocities and v6).
    let long: Vec<f64> = (1..=8).map(|k| 50.0 * k as f64).collect();
    same_as_one_species(HardSpheres::new(4.0, c).unwrap(), NoDrive, 0.5, 300, &long);
    same_as_one_species(Maxwell::new(4.0, c).unwrap(), NoDrive, 0.3, 300, &long);
    // The Gaussian thermostat (about the flow velocity, for one species its bulk velocity).
    same_as_one_species(
        HardSpheres::new(4.0, c).unwrap(),
        GaussianThermostat::new(0.3).unwrap(),
        0.5,
        500,
        &times,
    );
}

/// The Maxwell mixture of the test: masses 1 and 4, `kappa = 4 pi gamma C` of 1, 1.5 and 0.5
/// for the pairs (0,0), (0,1), (1,1), restitution 0.9, 0.6, 0.8, and start temperatures 1 and 2.
pub(super) fn maxwell_mixture(counts: [usize; 2]) -> MaxwellMixture {
    MaxwellMixture {
        counts: counts.to_vec(),
        masses: vec![1.0, 4.0],
        kappa: vec![1.0, 1.5, 0.5],
        alpha: vec![0.9, 0.6, 0.8],
        temperatures: vec![1.0, 2.0],
        beta: vec![],
        momentum: Momentum::Drawn,
    }
}

/// `ensembles` runs of the mixture (each species driven by its drive); returns per time the
/// samples `(T_0, T_1)`.
fn simulate<D: Drive + 'static>(
    mix: &MaxwellMixture,
    drives: &[D],
    times: &[f64],
    ensembles: u64,
    seed: u64,
) -> Vec<Vec<(f64, f64)>> {
    simulate_scheme(mix, drives, times, ensembles, seed, Scheme::Exact)
}

/// One system's advance to a time, whichever the scheme.
type Advance<'a> = Box<
    dyn FnMut(
            &mut Particles<'_>,
            f64,
            &mut gdsmc_core::rng::Xoshiro256PlusPlus,
        ) -> MixtureObservables
        + 'a,
>;

/// The scheme a mixture runs by.
#[derive(Clone, Copy)]
enum Scheme {
    /// The exact no-splitting loop.
    Exact,
    /// RW's splitting of this order and step.
    Split(SplittingOrder, f64),
    /// The time-stepped scheme of this step factor.
    Stepped(f64),
}

/// As [`simulate`], by `scheme`.
fn simulate_scheme<D: Drive + 'static>(
    mix: &MaxwellMixture,
    drives: &[D],
    times: &[f64],
    ensembles: u64,
    seed: u64,
    scheme: Scheme,
) -> Vec<Vec<(f64, f64)>> {
    let sp = Species::new(&mix.counts, &mix.masses).unwrap();
    let physics: Vec<_> = (0..3)
        .map(|k| PairPhysics {
            kernel: Maxwell::new(1.0, mix.kappa[k] / (4.0 * PI)).unwrap(),
            restitution: Constant::new(mix.alpha[k]).unwrap(),
        })
        .collect();
    let starts: Vec<Maxwellian> = (0..2)
        .map(|s| Maxwellian::new(mix.masses[s], mix.temperatures[s], Vec3::ZERO).unwrap())
        .collect();
    let n = sp.total();
    let mut out = vec![Vec::new(); times.len()];
    let mut buf = vec![Particle::default(); n];
    for mut rng in Streams::new(seed).take(ensembles as usize) {
        for s in 0..2 {
            for q in &mut buf[sp.range(s)] {
                q.set_velocity(starts[s].sample(&mut rng));
            }
        }
        let mut p = Particles::new(&mut buf).unwrap();
        let mut e: Advance<'_> = match scheme {
            Scheme::Exact => {
                let (mut e, _) =
                    MixtureNoSplitting::start(sp, &physics, drives, &mut p, 0.0).unwrap();
                Box::new(move |p, t, rng| e.advance_to(p, t, rng).unwrap())
            }
            Scheme::Split(order, dt) => {
                let (mut e, _): (MixtureSplitting<_, _, _>, _) =
                    MixtureSplitting::start(sp, &physics, drives, order, dt, &mut p, 0.0).unwrap();
                Box::new(move |p, t, rng| e.advance_to(p, t, rng).unwrap())
            }
            Scheme::Stepped(f) => {
                let (mut e, _): (MixtureTimeStepped<_, _, _>, _) =
                    MixtureTimeStepped::start(sp, &physics, drives, f, &mut p, 0.0).unwrap();
                Box::new(move |p, t, rng| e.advance_to(p, t, rng).unwrap())
            }
        };
        for (ti, &t) in times.iter().enumerate() {
            let o = e(&mut p, t, &mut rng);
            out[ti].push((o.temperature(0), o.temperature(1)));
        }
    }
    out
}

/// Mean, and the standard error of the mean, of `xs`.
pub(super) fn mean_se(xs: &[f64]) -> (f64, f64) {
    let s = Sample::of(xs);
    (s.mean, s.se())
}

/// Asserts `T_0`, `T_1` and `T_0/T_1` of `samples` within `z` standard errors of the exact
/// expectations of `mix` at every time (the ratio of the means, its standard error by the
/// delta method); returns whether the species' temperatures were told apart by more than ten
/// intervals somewhere (so that the comparison can fail).
fn compare(mix: &MaxwellMixture, samples: &[Vec<(f64, f64)>], times: &[f64], z: f64) -> bool {
    compare_with(mix, samples, times, z, &|t| mix.temperatures_at(t, false))
}

/// As [`compare`], against the expectations `exact(t)`.
fn compare_with(
    mix: &MaxwellMixture,
    samples: &[Vec<(f64, f64)>],
    times: &[f64],
    z: f64,
    exact: &dyn Fn(f64) -> Vec<f64>,
) -> bool {
    let mut distinct = false;
    let counts = &mix.counts;
    for (ti, &t) in times.iter().enumerate() {
        let exact = exact(t);
        let t0: Vec<f64> = samples[ti].iter().map(|x| x.0).collect();
        let t1: Vec<f64> = samples[ti].iter().map(|x| x.1).collect();
        let ((m0, s0), (m1, s1)) = (mean_se(&t0), mean_se(&t1));
        assert!(
            (m0 - exact[0]).abs() <= z * s0,
            "n = {counts:?} t = {t}: T_0 {m0} +- {} vs {}",
            z * s0,
            exact[0]
        );
        assert!(
            (m1 - exact[1]).abs() <= z * s1,
            "n = {counts:?} t = {t}: T_1 {m1} +- {} vs {}",
            z * s1,
            exact[1]
        );
        let (r, se) = gdsmc_stats::ratio_of_means(&t0, &t1);
        let exact_ratio = exact[0] / exact[1];
        assert!(
            (r - exact_ratio).abs() <= z * se,
            "n = {counts:?} t = {t}: T_0/T_1 {r} +- {} vs {exact_ratio}",
            z * se
        );
        if (exact[0] - exact[1]).abs() > 10.0 * z * (s0 + s1) {
            distinct = true;
        }
    }
    distinct
}

#[test]
fn maxwell_mixture_temperatures_follow_the_exact_finite_n_moments() {
    let times = [0.25, 0.5, 1.0, 2.0, 4.0];
    // Small n (8 particles: the finite-N terms are large) and large n (the Boltzmann limit
    // is then within the interval too).
    let cases = [([3usize, 5usize], 20_000u64), ([600, 400], 300)];
    // Every time, both sizes, three quantities (T_0, T_1, T_0/T_1): 30 checks, each at the
    // Bonferroni level that keeps the family at 99.9% (Student-t at the fewest, 300 ensembles).
    let z = joint(30, dof(300));
    let mut distinct = false;
    for (counts, ensembles) in cases {
        let mix = maxwell_mixture(counts);
        let samples = simulate(&mix, &[NoDrive; 2], &times, ensembles, 11);
        distinct |= compare(&mix, &samples, &times, z);
    }
    assert!(distinct, "the species temperatures were never told apart");
    // At 8 particles the finite-N solution differs from the Boltzmann limit by many intervals
    // at the last time: the comparison above sees N.
    let small = maxwell_mixture([3, 5]);
    let (fin, lim) = (
        small.temperatures_at(4.0, false),
        small.temperatures_at(4.0, true),
    );
    assert!(
        (fin[0] / fin[1] - lim[0] / lim[1]).abs() > 0.05,
        "{fin:?} vs {lim:?}"
    );
}

/// White noise of its own strength on each species (beta 0.5 on the light species, 2 on the
/// heavy one): the second moments stay closed (each kick adds `6 beta_s` to `<|v|^2>`), so the
/// heated mixture's species temperatures have exact finite-n expectations too, at every time
/// from the start into the steady state.
#[test]
fn heated_maxwell_mixture_follows_the_exact_finite_n_moments() {
    let times = [0.25, 1.0, 4.0, 10.0];
    let cases = [([3usize, 5usize], 20_000u64), ([600, 400], 300)];
    // 4 times x 2 sizes x 3 quantities.
    let z = joint(24, dof(300));
    let mut distinct = false;
    for (counts, ensembles) in cases {
        let mut mix = maxwell_mixture(counts);
        mix.beta = vec![0.5, 2.0];
        let drives = [WhiteNoise::new(0.5).unwrap(), WhiteNoise::new(2.0).unwrap()];
        let samples = simulate(&mix, &drives, &times, ensembles, 12);
        distinct |= compare(&mix, &samples, &times, z);
    }
    assert!(distinct, "the species temperatures were never told apart");
    // The drive matters: without it the expectations differ by far more than the intervals.
    let cold = maxwell_mixture([600, 400]).temperatures_at(10.0, false);
    let mut hot = maxwell_mixture([600, 400]);
    hot.beta = vec![0.5, 2.0];
    let hot = hot.temperatures_at(10.0, false);
    assert!(hot[1] > 10.0 * cold[1], "{hot:?} vs {cold:?}");
}

/// RW's splittings of the heated Maxwell mixture (`MixtureSplitting`: the exact loop's
/// collisions with the drives off, then every species kicked): the second moments stay
/// closed, so each scheme's species temperatures have exact finite-n expectations
/// (`MaxwellMixture::splitting_temperatures_at`), checked at every grid time (n = 8, dt = 2,
/// both orders; 4 times, 3 quantities, jointly). The step error is large enough to see: wherever
/// a scheme's expectation and the exact scheme's lie more than two half-widths apart, the
/// same samples must refuse the exact scheme's.
#[test]
#[ignore = "long suite: cargo test --workspace --release -- --include-ignored (README, CI)"]
fn split_maxwell_mixture_follows_the_exact_finite_n_moments_of_its_scheme() {
    let (dt, times) = (2.0, [2.0, 4.0, 6.0, 8.0]);
    let mut mix = maxwell_mixture([3, 5]);
    mix.beta = vec![0.5, 2.0];
    let drives = [WhiteNoise::new(0.5).unwrap(), WhiteNoise::new(2.0).unwrap()];
    // Strang's error is second order: 2e5 systems resolve it (half a percent of T).
    let ensembles = 200_000;
    let z = joint(24, dof(ensembles));
    for (k, order) in [SplittingOrder::Euler, SplittingOrder::Strang]
        .into_iter()
        .enumerate()
    {
        let strang = order == SplittingOrder::Strang;
        let samples = simulate_scheme(
            &mix,
            &drives,
            &times,
            ensembles,
            30 + k as u64,
            Scheme::Split(order, dt),
        );
        compare_with(&mix, &samples, &times, z, &|t| {
            mix.splitting_temperatures_at(t, dt, strang)
        });
        let mut apart = 0;
        for (ti, &t) in times.iter().enumerate() {
            let (split, exact) = (
                mix.splitting_temperatures_at(t, dt, strang),
                mix.temperatures_at(t, false),
            );
            for s in 0..2 {
                let xs: Vec<f64> = samples[ti]
                    .iter()
                    .map(|x| if s == 0 { x.0 } else { x.1 })
                    .collect();
                let (m, se) = mean_se(&xs);
                if (split[s] - exact[s]).abs() > 2.0 * z * se {
                    apart += 1;
                    assert!(
                        (m - exact[s]).abs() > z * se,
                        "{order:?} t = {t}: T_{s} {m} does not refuse the exact scheme's {}",
                        exact[s]
                    );
                }
            }
        }
        assert!(
            apart >= 3,
            "{order:?}: the step error resolved at only {apart} points"
        );
    }
}

/// The time-stepped scheme of the heated Maxwell mixture (`MixtureTimeStepped`: one stage per
/// pair type, Bird's no-time-counter form): at n = 1000 (600 + 400) and a fine step (f = 0.01)
/// the species temperatures and their ratio follow the exact finite-n moments of the exact
/// scheme at every time jointly (its whole-number candidate counts' bias is of order `1/n`,
/// tests/time_stepped.rs). At f = 2 the step's error is resolved (at two points at least), so
/// the comparison can fail.
#[test]
#[ignore = "long suite: cargo test --workspace --release -- --include-ignored (README, CI)"]
fn time_stepped_maxwell_mixture_follows_the_exact_finite_n_moments() {
    let times = [0.25, 1.0, 2.0, 4.0];
    let mut mix = maxwell_mixture([600, 400]);
    mix.beta = vec![0.5, 2.0];
    let drives = [WhiteNoise::new(0.5).unwrap(), WhiteNoise::new(2.0).unwrap()];
    let ensembles = 300;
    let z = joint(12, dof(ensembles));
    let fine = simulate_scheme(&mix, &drives, &times, ensembles, 41, Scheme::Stepped(0.01));
    assert!(
        compare(&mix, &fine, &times, z),
        "the species were never told apart"
    );
    let coarse = simulate_scheme(&mix, &drives, &times, ensembles, 42, Scheme::Stepped(2.0));
    let mut refused = 0;
    for (ti, &t) in times.iter().enumerate() {
        let exact = mix.temperatures_at(t, false);
        for (s, &e) in exact.iter().enumerate().take(2) {
            let xs: Vec<f64> = coarse[ti]
                .iter()
                .map(|x| if s == 0 { x.0 } else { x.1 })
                .collect();
            let (m, se) = mean_se(&xs);
            refused += usize::from((m - e).abs() > z * se);
        }
    }
    assert!(
        refused >= 2,
        "the coarse step's error resolved at only {refused} points"
    );
}
