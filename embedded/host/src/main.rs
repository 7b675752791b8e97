//! The firmware's runs on the host: `gdsmc-demo-host [SEED]` prints exactly the lines the
//! firmware prints over semihosting. The core's batch kernels run as `wide::f64x4` on both:
//! SSE2 lanes here, the portable four-lane fallback on the MCU, the same IEEE operations in
//! the same order, so the moment sums agree to the last bit too.

use gdsmc_core::particles::{Particle, Spin};

fn main() {
    let seed = std::env::args()
        .nth(1)
        .map_or(1, |s| s.parse().expect("a seed"));
    let mut buf = [Particle::default(); gdsmc_demo::N];
    let mut spins = [Spin::default(); gdsmc_demo::N_ROUGH];
    let mut out = String::new();
    let r = gdsmc_demo::all(&mut buf, &mut spins, seed, &mut out, || 0);
    print!("{out}");
    if let Err(e) = r {
        eprintln!("error: {e:?}");
        std::process::exit(1);
    }
}
