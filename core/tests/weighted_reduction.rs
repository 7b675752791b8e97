//! The reductions of weighted particles (core/src/weighted/reduce.rs, Rjasanow and Wagner's
//! SWPM): each keeps the weight, momentum and energy of what it replaces to rounding, the
//! allocated one keeps the thin tail's particles, and neither moves the distribution's tail.

use gdsmc_core::geometry::DimensionChoice;
use gdsmc_core::rng::{Streams, Xoshiro256PlusPlus};
use gdsmc_core::sample::standard_normal;
use gdsmc_core::vec3::Vec3;
use gdsmc_core::weighted::{WeightedParticle, WeightedSystem, reduce, reduce_allocated};

/// The generator of seed `seed`.
fn rng_of(seed: u64) -> Xoshiro256PlusPlus {
    Streams::new(seed).next().expect("a stream")
}

/// A system of `len` particles, velocities normal with a drift, weights spread over four
/// decades (as a weighted run's tail makes them), in a buffer of `cap`.
fn system(len: usize, cap: usize, rng: &mut Xoshiro256PlusPlus) -> [WeightedParticle; 512] {
    let mut buf = [WeightedParticle::default(); 512];
    for (k, p) in buf.iter_mut().enumerate().take(len.min(cap)) {
        let v = Vec3::new(
            1.0 + standard_normal(rng),
            standard_normal(rng),
            -0.5 + 3.0 * standard_normal(rng),
        );
        let g = libm::pow(10.0, -4.0 * (k % 7) as f64 / 6.0);
        *p = WeightedParticle::new(v, g);
    }
    buf
}

/// Rjasanow and Wagner's conservation: a reduction keeps the weight, momentum and energy
/// of every group, so of the system, to rounding (relative 1e-12 of the sums' sizes).
#[test]
fn a_reduction_keeps_weight_momentum_and_energy() {
    let mut rng = rng_of(5);
    for (len, group, dim) in [
        (500, 5, DimensionChoice::Three),
        (499, 3, DimensionChoice::Three),
        (301, 16, DimensionChoice::Two),
    ] {
        let mut buf = system(len, 512, &mut rng);
        if dim == DimensionChoice::Two {
            for p in &mut buf[..len] {
                p.vz = 0.0;
            }
        }
        let mut sys = WeightedSystem::new(&mut buf, len).unwrap();
        let (w, m, e) = (sys.mass(), sys.momentum(), sys.energy());
        let scale = (sys.particles().iter())
            .map(|p| p.g * p.velocity().norm2())
            .sum::<f64>();
        let left = reduce(&mut sys, group, dim, &mut rng);
        assert!(left < len && left >= 2 * (len / group), "{left} of {len}");
        assert!((sys.mass() - w).abs() <= 1e-12 * w);
        assert!((sys.momentum() - m).norm() <= 1e-12 * scale.max(w));
        assert!((sys.energy() - e).abs() <= 1e-12 * scale);
        if dim == DimensionChoice::Two {
            assert!(sys.particles().iter().all(|p| p.vz == 0.0));
        }
    }
}

/// The groups are shells of speed: after a reduction the speeds about the flow are kept
/// in range (no particle thrown far out of its shell: the largest speed grows at most by
/// the shell's spread).
#[test]
fn a_reduction_keeps_the_tail_where_it_was() {
    let mut rng = rng_of(6);
    let mut buf = system(500, 512, &mut rng);
    let mut sys = WeightedSystem::new(&mut buf, 500).unwrap();
    let flow = (1.0 / sys.mass()) * sys.momentum();
    let top = |s: &WeightedSystem<'_>| {
        (s.particles().iter())
            .map(|p| (p.velocity() - flow).norm())
            .fold(0.0, f64::max)
    };
    let before = top(&sys);
    reduce(&mut sys, 4, DimensionChoice::Three, &mut rng);
    let after = top(&sys);
    assert!(
        after > 0.5 * before && after < 1.5 * before,
        "{before} -> {after}"
    );
}

/// An allocated reduction keeps the sums too, lands near its target, and with exponent 0
/// keeps more of the fastest tenth than with exponent 1; with exponent 0 a shell of at
/// most `target / (2 shells)` unit weights is kept whole (each group is one particle), so
/// the fastest particle survives as it was.
#[test]
fn an_allocated_reduction_keeps_the_sums_and_feeds_the_tail() {
    let mut counts = [0usize; 2];
    let mut kept_fastest = false;
    for (k, q) in [0.0, 1.0].into_iter().enumerate() {
        let mut rng = rng_of(7);
        let mut buf = system(500, 512, &mut rng);
        for p in &mut buf[..500] {
            p.g = 1.0;
        }
        let mut sys = WeightedSystem::new(&mut buf, 500).unwrap();
        let (w, m, e) = (sys.mass(), sys.momentum(), sys.energy());
        let left = reduce_allocated(&mut sys, (100, 10, q), DimensionChoice::Three, &mut rng);
        assert!((50..=200).contains(&left), "q = {q}: {left} left");
        assert!((sys.mass() - w).abs() <= 1e-12 * w);
        assert!((sys.momentum() - m).norm() <= 1e-12 * 2.0 * e);
        assert!((sys.energy() - e).abs() <= 1e-12 * e);
        let flow = (1.0 / w) * m;
        // The fastest tenth of the speeds before: the particles left beyond its start.
        let mut speeds: [f64; 500] = [0.0; 500];
        let mut before = system(500, 512, &mut rng_of(7));
        for (s, p) in speeds.iter_mut().zip(before.iter_mut()) {
            *s = (p.velocity() - flow).norm();
        }
        speeds.sort_unstable_by(f64::total_cmp);
        let edge = speeds[450];
        if q == 0.0 {
            kept_fastest = (sys.particles().iter())
                .any(|p| ((p.velocity() - flow).norm() - speeds[499]).abs() < 1e-12);
        }
        counts[k] = (sys.particles().iter())
            .filter(|p| (p.velocity() - flow).norm() > edge)
            .count();
    }
    assert!(counts[0] > counts[1], "tail particles {counts:?}");
    assert!(kept_fastest, "exponent 0 keeps the fastest particle whole");
}

/// A reduction must not move the tail: a Maxwellian sample (unit temperature) split in halves
/// and reduced back, ten times over, keeps `P(|v| > 3)` and `P(|v| > 4)` (2.929e-2, 1.139e-3:
/// the chi distribution with three degrees of freedom) within the 99.9% intervals of 40
/// samples, Bonferroni over the two cuts and two reductions. The replacements along a uniform
/// direction failed this (P(|v| > 4) fell to 4.3e-4 by cells, the allocation doubled
/// P(|v| > 3)): along the principal axis they pass.
#[test]
fn repeated_reductions_keep_a_maxwellians_tail() {
    use gdsmc_core::sample::standard_normal3;
    use gdsmc_core::weighted::Reduction;
    let exact = [2.929e-2, 1.139e-3];
    let reductions = [
        Reduction::Cells { group: 4 },
        Reduction::Allocated {
            target: 4000,
            shells: 32,
            exponent: 0.0,
        },
    ];
    for (r, red) in reductions.iter().enumerate() {
        let mut rng = rng_of(40 + r as u64);
        let mut tails = [Vec::new(), Vec::new()];
        for _ in 0..40 {
            let mut buf = vec![WeightedParticle::default(); 20_000];
            for p in buf.iter_mut().take(4000) {
                *p = WeightedParticle::new(standard_normal3(&mut rng), 1.0);
            }
            let mut sys = WeightedSystem::new(&mut buf, 4000).unwrap();
            for _ in 0..10 {
                for i in 0..sys.len() {
                    let half = WeightedParticle::new(
                        sys.particles()[i].velocity(),
                        0.5 * sys.particles()[i].g,
                    );
                    sys.particles_mut()[i] = half;
                    sys.push(half).unwrap();
                }
                red.apply(&mut sys, 2, DimensionChoice::Three, &mut rng);
            }
            let w = sys.mass();
            for (k, cut) in [3.0, 4.0].into_iter().enumerate() {
                let p: f64 = (sys.particles().iter())
                    .filter(|p| p.velocity().norm() > cut)
                    .map(|p| p.g)
                    .sum();
                tails[k].push(p / w);
            }
        }
        for (k, t) in tails.iter().enumerate() {
            let s = gdsmc_stats::Sample::of(t);
            assert!(
                s.admits(exact[k], 4),
                "{red:?}, cut {}: {} +- {}, exact {}",
                k + 3,
                s.mean,
                s.joint_ci(4),
                exact[k]
            );
        }
    }
}

/// A group's two replacements keep its weight, momentum, energy and, while the lean toward the
/// flow is below its limit, the fourth moment `sum g |v - flow|^4` (module docs of
/// `reduce_group`): a cell of five unequal particles around (2, 1, 0), flow (0.1, 0, 0).
#[test]
fn a_group_keeps_its_fourth_moment_about_the_flow() {
    use gdsmc_core::weighted::reduce_group;
    let flow = Vec3::new(0.1, 0.0, 0.0);
    let group = [
        WeightedParticle::new(Vec3::new(2.1, 1.0, 0.1), 0.3),
        WeightedParticle::new(Vec3::new(1.9, 1.2, -0.1), 0.1),
        WeightedParticle::new(Vec3::new(2.0, 0.8, 0.2), 0.25),
        WeightedParticle::new(Vec3::new(2.2, 1.1, -0.2), 0.05),
        WeightedParticle::new(Vec3::new(1.8, 0.9, 0.0), 0.3),
    ];
    let sums = |ps: &[WeightedParticle]| {
        ps.iter()
            .fold((0.0, Vec3::ZERO, 0.0, 0.0), |(w, m, e, f), p| {
                let c2 = (p.velocity() - flow).norm2();
                (
                    w + p.g,
                    m + p.g * p.velocity(),
                    e + p.g * p.velocity().norm2(),
                    f + p.g * c2 * c2,
                )
            })
    };
    let mut rng = rng_of(50);
    for dim in [DimensionChoice::Three, DimensionChoice::Two] {
        let mut g = group;
        if dim == DimensionChoice::Two {
            for p in &mut g {
                p.vz = 0.0;
            }
        }
        let two = reduce_group(&g, flow, dim, &mut rng);
        let (a, b) = (sums(&g), sums(&two));
        assert!((a.0 - b.0).abs() < 1e-14);
        assert!((a.1 - b.1).norm() < 1e-13);
        assert!((a.2 - b.2).abs() < 1e-13 * a.2);
        assert!(
            (a.3 - b.3).abs() < 1e-12 * a.3,
            "{dim:?}: {} vs {}",
            a.3,
            b.3
        );
        if dim == DimensionChoice::Two {
            assert!(two.iter().all(|p| p.vz == 0.0));
        }
    }
}
