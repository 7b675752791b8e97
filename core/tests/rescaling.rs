//! The rescaling of a cooling gas (no drive, no-splitting scheme) changes nothing but the
//! stored units: with the same seed, a run that rescales early and one that never rescales
//! give the same physical temperatures to rounding (1e-6 relative) while the unrescaled run
//! still resolves them (its peculiar velocities, stored beside a bulk velocity of order one,
//! lose digits as sqrt(1e-32 / T)). Beyond that only the rescaled run is right: Haff's law
//! holds over forty decades, and far below the smallest double log10 T stays finite.

use gdsmc_core::drive::NoDrive;
use gdsmc_core::engine::NoSplitting;
use gdsmc_core::kernel::{HardSpheres, Kernel, Maxwell};
use gdsmc_core::math::PI;
use gdsmc_core::particles::{Particle, Particles};
use gdsmc_core::restitution::Constant;
use gdsmc_core::rng::seeded;
use gdsmc_core::sample::Maxwellian;
use gdsmc_core::vec3::Vec3;

fn run<K: Kernel>(k: K, threshold: f64, times: &[f64]) -> (Vec<(f64, f64)>, u64) {
    let mut rng = seeded(51);
    let f0 = Maxwellian::new(1.0, 1.0, Vec3::new(0.5, 0.0, 0.0)).unwrap();
    let mut q: Vec<Particle> = (0..2048)
        .map(|_| Particle::new(f0.sample(&mut rng), 0.0))
        .collect();
    let mut p = Particles::new(&mut q).unwrap();
    let (mut e, _) =
        NoSplitting::start(k, NoDrive, Constant::new(0.5).unwrap(), &mut p, 0.0).unwrap();
    e.set_rescale_below(threshold);
    let out = times
        .iter()
        .map(|&t| {
            let o = e.advance_to(&mut p, t, &mut rng).unwrap();
            assert!(
                (o.bulk.x - 0.5).abs() < 0.2,
                "bulk velocity kept: {:?}",
                o.bulk
            );
            (o.t_bulk, o.log10_t_bulk)
        })
        .collect();
    (out, e.counts().rescales)
}

#[test]
fn hard_spheres_rescaled_equal_unrescaled_and_follow_haff() {
    let k = HardSpheres::new(4.0, 1.0 / (4.0 * PI)).unwrap();
    // Haff: T ~ (t0 / t)^2 for t >> t0, so T = 1e-12 near t = 1e6 t0 and 1e-40 near 1e20 t0.
    let times: Vec<f64> = (1..=20).map(|i| 10f64.powi(i)).collect();
    let (a, ra) = run(k, 1e-6, &times);
    let (b, rb) = run(k, 0.0, &times[..6]);
    assert!(ra > 3 && rb == 0, "rescales {ra}, {rb}");
    for ((ta, la), (tb, lb)) in a.iter().zip(&b) {
        assert!((ta / tb - 1.0).abs() < 1e-6, "{ta:e} vs {tb:e}");
        assert!((la - lb).abs() < 1e-6, "{la} vs {lb}");
    }
    // T t^2 constant from t = 1e6 to 1e20 (forty decades of T in all): one system of 2048
    // particles, relative sd of T about sqrt(2/(3n)) = 1.8%; 3.2 sd of a difference of two.
    let c6 = a[5].0 * 1e12;
    let c20 = 10f64.powf(a[19].1) * 1e40;
    assert!(
        (c20 / c6 - 1.0).abs() < gdsmc_stats::LAMBDA_999 * 2f64.sqrt() * (2.0f64 / 6144.0).sqrt(),
        "{c6} vs {c20}"
    );
}

#[test]
fn maxwell_cools_below_the_smallest_double() {
    let k = Maxwell::new(1.0, 1.0 / PI).unwrap(); // T = T0 exp(-0.75 t) on average
    let times = [20.0, 600.0, 1500.0];
    let (a, ra) = run(k, gdsmc_core::engine::nosplit::RESCALE_BELOW, &times);
    let (b, _) = run(k, 0.0, &times[..1]);
    // At t = 20 (T about 3e-7) both represent T to many digits; they agree.
    assert!(
        (a[0].0 / b[0].0 - 1.0).abs() < 1e-6,
        "{:e} vs {:e}",
        a[0].0,
        b[0].0
    );
    // At t = 1500, T is about 10^-489: the double underflows, its logarithm does not.
    assert!(ra >= 2, "rescales {ra}, {a:?}");
    let (t_end, l_end) = a[2];
    assert!(t_end == 0.0 || t_end < 1e-300, "{t_end:e}");
    assert!(
        l_end.is_finite() && l_end < -400.0 && l_end > -600.0,
        "log10 T = {l_end}"
    );
}
