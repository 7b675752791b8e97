//! `gdsmc bench throughput`: the speed of the hot loops, one line per case, beside the
//! machine's own limits (random numbers per second, random reads per second).
//!
//! Lines have the form `case=<name> kernel=<k> n=<n> collisions_per_s=<x> attempts_per_s=<y>
//! acceptance=<a>` for the no-splitting event loop (GRW Section 3 / RW Algorithm 3; `a` the
//! fraction of candidates that collide), and
//! `case=<name> n=<n> particles_per_s=<x>` (or `numbers_per_s`, `reads_per_s`) for the
//! batch kernels and the limits. Each loop line ends with `of_pair_reference`, its candidates
//! per second as a fraction of a reference rate for that memory traffic at the same n
//! (`case=reference-pair-update`: random pairs read and written, drawn ahead and prefetched at
//! the best lookahead, in the run's huge-page buffer; not a bound: a loop can exceed it),
//! timed again just before each of the loop's rounds so that both see the same machine, and
//! `of_rng`, the same as a fraction of the generator's raw rate (`case=limit-xoshiro256pp`);
//! the host medium's line adds `background_per_s`, its grain-background collisions (BRS
//! (26)), which are most of its work, and the sum-form line `choice_reads_per_candidate` and
//! `choice_reads_per_collision`, the random particle reads its weighted choice of `i` makes
//! (its memory traffic beyond the pair's).
//!
//! Every figure is the median of [`ROUNDS`] timed rounds and every line says their `spread`
//! (range over median): a round slowed by other work moves the spread, not the figure.
//!
//! Every rate is per CPU second of the measuring thread (`cpu_time::ThreadTime`), and every
//! budget is CPU time: a machine busy with other work slows the bench's wall clock, not its
//! figures (the first line, `clock=thread-cpu-time`, says so).

mod timed;

pub use timed::LOOKAHEADS;
pub use timed::ROUNDS;
use timed::{
    PairReference, Rounds, event_loop, median, rates, rng_limit, rough_loop, spread, sum_form_loop,
    system, timed,
};

use super::line::{Limits, Line, LoopLine, RateLine, Unit};
use gdsmc_core::batch::{kick, sums};
use gdsmc_core::drive::{HardSphereBackground, HostMedium, HostMediumParams, NoDrive, WhiteNoise};
use gdsmc_core::engine::NoSplitting;
use gdsmc_core::kernel::{HardSpheres, Maxwell, Vhs};
use gdsmc_core::particles::Particles;
use gdsmc_core::restitution::Constant;
use gdsmc_core::rng::{seeded, uniform_index};
use gdsmc_core::rough::RoughNoise;
use gdsmc_core::sample::{Maxwellian, standard_normal};
use gdsmc_core::vec3::Vec3;
use std::f64::consts::PI;
use std::hint::black_box;
use std::time::Duration;

/// What to measure.
#[derive(Clone, Debug)]
pub struct Options {
    /// Particle numbers of the event-loop cases (default 10^3, 10^5, 10^6, 10^7).
    pub sizes: Vec<usize>,
    /// Minimum measuring time per case.
    pub budget: Duration,
}

impl Default for Options {
    fn default() -> Self {
        Options {
            sizes: vec![1_000, 100_000, 1_000_000, 10_000_000],
            budget: Duration::from_millis(1500),
        }
    }
}

/// An event loop's line from its rounds, against the generator's raw rate `numbers`: the
/// medians, the pair reference's ratio round by round, the spread of the candidates; the
/// background where a drive has one; no weighted choice.
fn loop_line(
    (case, kernel): (&'static str, &'static str),
    n: usize,
    r: &Rounds,
    numbers: f64,
) -> LoopLine {
    let background = median(&r.background);
    LoopLine {
        case,
        kernel,
        n,
        collisions_per_s: median(&r.collisions),
        attempts_per_s: median(&r.attempts),
        of_pair_reference: median(&r.of_pairs()),
        spread: spread(&r.attempts),
        limits: Limits {
            pairs: median(&r.pairs),
            numbers,
        },
        background_per_s: (background > 0.0).then_some(background),
        choice_reads_per_candidate: None,
    }
}

/// A rate line from its rounds.
fn rate_line(case: &'static str, n: Option<usize>, unit: Unit, rounds: &[f64]) -> Line {
    Line::Rate(RateLine {
        case,
        n,
        unit,
        per_s: median(rounds),
        lookahead: None,
        spread: spread(rounds),
    })
}

/// One event-loop case: `(alpha, heated)` and the pair reference to its rounds.
type LoopCase<'a> = dyn Fn(f64, bool, &mut PairReference) -> Rounds + 'a;

/// Every case, as output lines, handed to `line` as they are measured.
pub fn run(o: &Options, mut line: impl FnMut(Line)) {
    let g = 4.0;
    let c = 1.0 / (4.0 * PI);
    line(Line::Clock);
    let numbers = rng_limit(o.budget);
    line(rate_line(
        "limit-xoshiro256pp",
        None,
        Unit::Numbers,
        &numbers,
    ));
    let numbers = median(&numbers);
    let b = o.budget;
    for &n in &o.sizes {
        let (mut reference, pairs) = PairReference::new(n, b);
        line(Line::Rate(RateLine {
            case: "reference-pair-update",
            n: Some(n),
            unit: Unit::Pairs,
            per_s: median(&pairs),
            lookahead: Some(reference.lookahead()),
            spread: spread(&pairs),
        }));
        let reference = &mut reference;
        let kernels: [(&str, &LoopCase); 3] = [
            ("maxwell", &|a, heated, r| {
                let k = Maxwell::new(g, c).expect("valid");
                if heated {
                    event_loop(k, WhiteNoise::new(1.0).expect("valid"), a, n, (b, r))
                } else {
                    event_loop(k, NoDrive, a, n, (b, r))
                }
            }),
            ("hard-spheres", &|a, heated, r| {
                let k = HardSpheres::new(g, c).expect("valid");
                // With no drive: the sum form's own line below.
                assert!(heated, "the elastic hard-sphere case is the sum form's");
                event_loop(k, WhiteNoise::new(1.0).expect("valid"), a, n, (b, r))
            }),
            ("vhs", &|a, heated, r| {
                let k = Vhs::new(g, c, 0.5).expect("valid");
                if heated {
                    event_loop(k, WhiteNoise::new(1.0).expect("valid"), a, n, (b, r))
                } else {
                    event_loop(k, NoDrive, a, n, (b, r))
                }
            }),
        ];
        // BRS Example 4: hard spheres in a hard-sphere host medium (C1 = 1, C2 = 1/8,
        // m^B = 1, T^B = 1, u^B = (0, 1, 0)); the lazy per-grain background process rides on
        // the kicks of the event loop.
        let bg = Maxwellian::new(1.0, 1.0, Vec3::new(0.0, 1.0, 0.0)).expect("valid");
        let hm = HostMedium::new(
            HostMediumParams::new(bg, 1.0, 1.0).expect("valid"),
            HardSphereBackground,
        );
        let k = HardSpheres::new(1.0, 0.125).expect("valid");
        let rounds = {
            let mut buf = system(n, 1);
            let mut p = Particles::new(&mut buf).expect("n >= 2");
            let law = Constant::new(0.5).expect("alpha in (0, 1]");
            let (mut e, _) = NoSplitting::start(k, hm, law, &mut p, 0.0).expect("finite start");
            timed(&mut e, &mut p, b, reference)
        };
        line(Line::Loop(loop_line(
            ("nosplit-host-medium-alpha0.5", "hard-spheres"),
            n,
            &rounds,
            numbers,
        )));
        // Hard spheres with no drive on the Umax majorant (GRW step 1.4), the loop before the
        // sum form: the comparison for the elastic hard-sphere line below.
        let rounds = event_loop(
            HardSpheres::new(g, c).expect("valid"),
            NoDrive,
            1.0,
            n,
            (b, reference),
        );
        line(Line::Loop(loop_line(
            ("nosplit-umax-elastic-alpha1", "hard-spheres"),
            n,
            &rounds,
            numbers,
        )));
        // Rough hard spheres (uniform spheres): the elastic perfectly rough gas and the heated
        // one with beta = 0 (both translation and rotation kicked).
        let rough = rough_loop(NoDrive, (1.0, 1.0), n, (b, reference));
        line(Line::Loop(loop_line(
            ("nosplit-rough-elastic-alpha1-beta1", "hard-spheres"),
            n,
            &rough,
            numbers,
        )));
        let noise = RoughNoise::new(Some(1.0), 1.0, 0.4).expect("valid");
        let rough = rough_loop(noise, (0.5, 0.0), n, (b, reference));
        line(Line::Loop(loop_line(
            ("nosplit-rough-white-noise-alpha0.5-beta0", "hard-spheres"),
            n,
            &rough,
            numbers,
        )));
        for (name, f) in kernels {
            for (case, alpha, heated) in [
                ("nosplit-white-noise-alpha0.5", 0.5, true),
                ("nosplit-elastic-alpha1", 1.0, false),
            ] {
                if name == "hard-spheres" && !heated {
                    let k = HardSpheres::new(g, c).expect("valid");
                    let (rounds, reads) = sum_form_loop(k, alpha, n, (b, reference));
                    line(Line::Loop(LoopLine {
                        choice_reads_per_candidate: Some(reads),
                        ..loop_line((case, name), n, &rounds, numbers)
                    }));
                    continue;
                }
                let rounds = f(alpha, heated, reference);
                line(Line::Loop(loop_line((case, name), n, &rounds, numbers)));
            }
        }
    }
    for n in [1_000usize, 1_000_000] {
        let mut buf = system(n, 3);
        let mut p = Particles::new(&mut buf).expect("n >= 2");
        let mut rng = seeded(4);
        let mut t = 0.0;
        let r = rates(o.budget, n, || {
            t += 1e-3;
            kick::white_noise_kick_all(2.0, &mut p, t, &mut rng);
        });
        line(rate_line("kick-white-noise", Some(n), Unit::Particles, &r));
        let buf = system(n, 5);
        let r = rates(o.budget, n, || {
            black_box(sums::accumulate(&buf));
        });
        line(rate_line("moment-sums", Some(n), Unit::Particles, &r));
    }
    // The machine's other limits for the loops above.
    let mut rng = seeded(6);
    let r = rates(o.budget, 1 << 16, || {
        let mut x = 0.0;
        for _ in 0..1 << 16 {
            x += standard_normal(&mut rng);
        }
        black_box(x);
    });
    line(rate_line("limit-normal-ziggurat", None, Unit::Numbers, &r));
    for n in [1_000usize, 10_000_000] {
        let buf = system(n, 7);
        // Independent random reads (the addresses do not depend on earlier loads), as the
        // event loop's pair choice: bounded by memory-level parallelism, not latency alone.
        let r = rates(o.budget, 1 << 16, || {
            let mut x = 0.0;
            for _ in 0..1 << 16 {
                x += buf[uniform_index(&mut rng, n)].vx;
            }
            black_box(x);
        });
        line(rate_line("limit-random-read", Some(n), Unit::Reads, &r));
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn lines_have_the_documented_form() {
        let o = Options {
            sizes: vec![64],
            budget: Duration::from_millis(5),
        };
        let mut lines = Vec::new();
        run(&o, |l| lines.push(l));
        assert_eq!(lines[0], Line::Clock, "the clock is said first");
        assert_eq!(lines[0].to_string(), "clock=thread-cpu-time");
        let loops: Vec<&LoopLine> = lines
            .iter()
            .filter_map(|l| match l {
                Line::Loop(l) => Some(l),
                _ => None,
            })
            .collect();
        assert_eq!(loops.len(), 10);
        for l in &loops {
            let text = Line::Loop((*l).clone()).to_string();
            let keys: Vec<&str> = text
                .split(' ')
                .map(|kv| kv.split('=').next().unwrap())
                .collect();
            assert_eq!(
                keys,
                [
                    "case",
                    "kernel",
                    "n",
                    "collisions_per_s",
                    "attempts_per_s",
                    "acceptance",
                    "of_pair_reference",
                    "of_rng",
                    "spread",
                    if l.background_per_s.is_some() {
                        "background_per_s"
                    } else {
                        "choice_reads_per_candidate"
                    },
                    "choice_reads_per_collision"
                ][..keys.len()],
                "{text}"
            );
            assert!(l.case.starts_with("nosplit"), "{text}");
            // Only the host medium's line counts background events.
            assert_eq!(
                l.background_per_s.is_some(),
                l.case.contains("host-medium"),
                "{text}"
            );
            assert!(l.attempts_per_s >= l.collisions_per_s, "{text}");
            assert!(l.collisions_per_s > 0.0, "{text}");
            assert!(l.of_rng() > 0.0, "{text}");
            // The figures are medians of the rounds, each ratio a round's own.
            assert!(l.spread >= 0.0 && l.of_pair_reference > 0.0, "{text}");
            // Only the sum form (elastic hard spheres with no drive) has a weighted choice;
            // it draws at least once per candidate.
            let sum_form = l.kernel == "hard-spheres" && l.case == "nosplit-elastic-alpha1";
            assert_eq!(l.choice_reads_per_candidate.is_some(), sum_form, "{text}");
            if let Some(r) = l.choice_reads_per_candidate {
                assert!(r >= 1.0, "{text}");
            }
            if let Some(bg) = l.background_per_s {
                // BRS Example 4: about 16 background collisions per grain-grain one.
                assert!(bg > l.collisions_per_s, "{text}");
            }
        }
        assert!(
            loops
                .iter()
                .any(|l| l.kernel == "maxwell" && l.n == 64 && l.case.contains("elastic-alpha1"))
        );
        for k in [
            "kick-white-noise",
            "moment-sums",
            "limit-xoshiro256pp",
            "limit-random-read",
            "reference-pair-update",
        ] {
            assert!(
                lines
                    .iter()
                    .any(|l| matches!(l, Line::Rate(r) if r.case == k && r.per_s > 0.0)),
                "{k}"
            );
        }
    }
}
