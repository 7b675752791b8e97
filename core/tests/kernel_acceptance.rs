//! `Kernel::accepts`, the fictitious-collision test GRW (20) as the loops make it (without
//! square roots or powers where the kernel allows), against `r < acceptance(|u|, Umax)`, the
//! test as written, over random relative speeds (overshoots included) and uniforms: the two
//! agree wherever `r` is not within `1e-12` of the acceptance probability (rounding ties).

use gdsmc_core::kernel::{HardSpheres, Kernel, Vhs};
use gdsmc_core::rng::{seeded, uniform01};

fn agrees<K: Kernel>(k: K, what: &str) {
    let mut rng = seeded(11);
    let mut decided = 0;
    for _ in 0..200_000 {
        let umax = 10.0 * uniform01(&mut rng) + 1e-3;
        // Up to 1.5 Umax: a third of them overshoots, which is always accepted.
        let u = 1.5 * umax * uniform01(&mut rng);
        let r = uniform01(&mut rng);
        let p = k.acceptance(u, umax);
        if (r - p).abs() < 1e-12 {
            continue;
        }
        decided += 1;
        assert_eq!(
            k.accepts(u * u, umax, r),
            r < p,
            "{what}: |u| {u}, Umax {umax}, r {r}, acceptance {p}"
        );
    }
    assert!(decided > 199_000, "{what}: only {decided} away from ties");
}

#[test]
fn accepts_is_the_acceptance_test() {
    let c = 1.0 / (4.0 * std::f64::consts::PI);
    agrees(HardSpheres::new(16.0, c).unwrap(), "hard spheres");
    agrees(Vhs::new(16.0, c, 0.5).unwrap(), "VHS lambda = 1/2");
    agrees(Vhs::new(16.0, c, 0.3).unwrap(), "VHS lambda = 0.3");
    agrees(Vhs::new(16.0, c, 1.0).unwrap(), "VHS lambda = 1");
}
