//! Benchmarks of the hot loops: the no-splitting event loop per collision, the batch kick of all
//! particles (SIMD against its scalar twin), the moment sums, and the samplers.

use criterion::{BenchmarkId, Criterion, Throughput, criterion_group, criterion_main};
use gdsmc_core::batch::{kick, sums};
use gdsmc_core::drive::WhiteNoise;
use gdsmc_core::engine::NoSplitting;
use gdsmc_core::kernel::{HardSpheres, Maxwell};
use gdsmc_core::math::PI;
use gdsmc_core::particles::{Particle, Particles};
use gdsmc_core::restitution::Constant;
use gdsmc_core::rng::seeded;
use gdsmc_core::sample::{Maxwellian, standard_exponential, standard_normal, unit_sphere};
use std::hint::black_box;

fn system(n: usize, seed: u64) -> Vec<Particle> {
    let mut buf = vec![Particle::default(); n];
    let mut p = Particles::new(&mut buf).unwrap();
    let mut rng = seeded(seed);
    let f0 = Maxwellian::standard();
    p.fill_with(0.0, || f0.sample(&mut rng));
    buf
}

/// Time per unit of simulated time with GRW Example 3 parameters: 2 (n - 1) collisions.
fn event_loop(c: &mut Criterion) {
    let mut g = c.benchmark_group("nosplit");
    for &n in &[1024usize, 65_536, 1 << 20] {
        let collisions = 2 * (n as u64 - 1) / 4; // per quarter unit of time
        g.throughput(Throughput::Elements(collisions));
        g.bench_with_input(BenchmarkId::new("maxwell_white_noise", n), &n, |b, &n| {
            let mut buf = system(n, 1);
            let mut p = Particles::new(&mut buf).unwrap();
            let mut rng = seeded(2);
            let (mut e, _) = NoSplitting::start(
                Maxwell::new(4.0, 1.0 / (4.0 * PI)).unwrap(),
                WhiteNoise::new(1.0).unwrap(),
                Constant::new(0.5).unwrap(),
                &mut p,
                0.0,
            )
            .unwrap();
            b.iter(|| {
                let t = e.time() + 0.25;
                black_box(e.advance_to(&mut p, t, &mut rng).unwrap());
            });
        });
        g.bench_with_input(
            BenchmarkId::new("hard_spheres_white_noise", n),
            &n,
            |b, &n| {
                let mut buf = system(n, 1);
                let mut p = Particles::new(&mut buf).unwrap();
                let mut rng = seeded(2);
                let (mut e, _) = NoSplitting::start(
                    HardSpheres::new(4.0, 1.0 / (4.0 * PI)).unwrap(),
                    WhiteNoise::new(0.125).unwrap(),
                    Constant::new(0.5).unwrap(),
                    &mut p,
                    0.0,
                )
                .unwrap();
                b.iter(|| {
                    let t = e.time() + 0.25;
                    black_box(e.advance_to(&mut p, t, &mut rng).unwrap());
                });
            },
        );
    }
    g.finish();
}

fn batch(c: &mut Criterion) {
    let mut g = c.benchmark_group("batch");
    for &n in &[1024usize, 1 << 20] {
        g.throughput(Throughput::Elements(n as u64));
        g.bench_with_input(BenchmarkId::new("kick_all_simd", n), &n, |b, &n| {
            let mut buf = system(n, 3);
            let mut p = Particles::new(&mut buf).unwrap();
            let mut rng = seeded(4);
            let mut t = 0.0;
            b.iter(|| {
                t += 1e-3;
                kick::white_noise_kick_all_simd(2.0, &mut p, t, &mut rng);
            });
        });
        g.bench_with_input(BenchmarkId::new("kick_all_scalar", n), &n, |b, &n| {
            let mut buf = system(n, 3);
            let mut p = Particles::new(&mut buf).unwrap();
            let mut rng = seeded(4);
            let mut t = 0.0;
            b.iter(|| {
                t += 1e-3;
                kick::white_noise_kick_all_scalar(2.0, &mut p, t, &mut rng);
            });
        });
        g.bench_with_input(BenchmarkId::new("sums_simd", n), &n, |b, &n| {
            let buf = system(n, 5);
            b.iter(|| black_box(sums::accumulate_simd(&buf)));
        });
        g.bench_with_input(BenchmarkId::new("sums_scalar", n), &n, |b, &n| {
            let buf = system(n, 5);
            b.iter(|| black_box(sums::accumulate_scalar(&buf)));
        });
    }
    g.finish();
}

fn samplers(c: &mut Criterion) {
    let mut g = c.benchmark_group("samplers");
    g.throughput(Throughput::Elements(1000));
    let mut rng = seeded(6);
    g.bench_function("normal_ziggurat", |b| {
        b.iter(|| (0..1000).map(|_| standard_normal(&mut rng)).sum::<f64>())
    });
    g.bench_function("exponential_ziggurat", |b| {
        b.iter(|| {
            (0..1000)
                .map(|_| standard_exponential(&mut rng))
                .sum::<f64>()
        })
    });
    g.bench_function("unit_sphere", |b| {
        b.iter(|| (0..1000).map(|_| unit_sphere(&mut rng).z).sum::<f64>())
    });
    g.finish();
}

criterion_group! {
    name = benches;
    config = Criterion::default().sample_size(20).warm_up_time(std::time::Duration::from_millis(500)).measurement_time(std::time::Duration::from_secs(2));
    targets = event_loop, batch, samplers
}
criterion_main!(benches);
