//! Every sampler at extreme parameters, from a generator seeded by the fuzzer: a sampler whose
//! constructor accepts its parameters gives finite values (the ziggurats, the sphere, the
//! Maxwellian, the mixture, BRS (29)), uniform variates stay in their ranges, and uniform
//! integers and pairs in theirs. An endless loop shows as a fuzzer timeout.

use crate::wild;
use arbitrary::Unstructured;
use gdsmc_core::rng::{seeded, uniform_index, uniform_open01, uniform_pair, uniform01};
use gdsmc_core::sample::{
    BackgroundPartner, Maxwellian, MaxwellianMixture, standard_exponential, standard_normal,
    unit_sphere,
};
use gdsmc_core::vec3::Vec3;

/// Draws per sampler and input.
const DRAWS: usize = 64;

/// The samplers.
pub fn samplers(data: &[u8]) {
    let mut u = Unstructured::new(data);
    let Ok(seed) = u.arbitrary::<u64>() else {
        return;
    };
    let mut rng = seeded(seed);
    for _ in 0..DRAWS {
        let (x, y) = (standard_normal(&mut rng), standard_exponential(&mut rng));
        assert!(
            x.is_finite() && y.is_finite() && y >= 0.0,
            "normal {x}, exponential {y}"
        );
        let (a, b) = (uniform01(&mut rng), uniform_open01(&mut rng));
        assert!(
            (0.0..1.0).contains(&a) && b > 0.0 && b < 1.0,
            "uniforms {a}, {b}"
        );
        let s = unit_sphere(&mut rng);
        assert!((s.norm() - 1.0).abs() < 1e-12, "sphere point {s:?}");
    }
    let n = u.int_in_range(1usize..=usize::MAX).unwrap_or(1);
    for _ in 0..DRAWS {
        assert!(uniform_index(&mut rng, n) < n);
        if n >= 2 {
            let (i, j) = uniform_pair(&mut rng, n);
            assert!(i < n && j < n && i != j, "pair ({i}, {j}) of {n}");
        }
    }
    let (mass, temperature) = (wild(&mut u), wild(&mut u));
    let drift = Vec3::new(wild(&mut u), wild(&mut u), wild(&mut u));
    if let Ok(m) = Maxwellian::new(mass, temperature, drift) {
        for _ in 0..DRAWS {
            let v = m.sample(&mut rng);
            assert!(
                v.is_finite(),
                "Maxwellian({mass}, {temperature}, {drift:?}) drew {v:?}"
            );
        }
        let partner = BackgroundPartner::new(&m);
        for _ in 0..DRAWS {
            let w = partner.sample(&mut rng);
            assert!(
                w.is_finite(),
                "BRS (29) partner of ({mass}, {temperature}, {drift:?}) drew {w:?}"
            );
        }
    }
    let mut mix = MaxwellianMixture::<4>::new();
    for _ in 0..u.int_in_range(0u8..=5).unwrap_or(0) {
        let (w, m, t) = (wild(&mut u), wild(&mut u), wild(&mut u));
        if let Ok(c) = Maxwellian::new(m, t, Vec3::new(wild(&mut u), 0.0, 0.0)) {
            let _ = mix.push(w, c);
        }
    }
    for _ in 0..DRAWS {
        if let Ok(v) = mix.sample(&mut rng) {
            assert!(v.is_finite(), "mixture drew {v:?}: {mix:?}");
        }
    }
}
