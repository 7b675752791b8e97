//! The firmware's runs on the host: `gdsmc-demo-host [SEED]` prints exactly the lines the
//! firmware prints over semihosting; `gdsmc-demo-host m0 [SEED]` those of the Cortex-M0 build
//! (GRW Example 3 on `N_M0` particles). The core's batch kernels run as `wide::f64x4` on both:
//! SSE2 lanes here, the portable four-lane fallback on the MCU, the same IEEE operations in
//! the same order, so the moment sums agree to the last bit too.

use gdsmc_core::particles::{Particle, Spin};

fn main() {
    let mut args: Vec<String> = std::env::args().skip(1).collect();
    let m0 = args.first().is_some_and(|a| a == "m0");
    if m0 {
        args.remove(0);
    }
    let seed = args.first().map_or(1, |s| s.parse().expect("a seed"));
    let mut out = String::new();
    let r = if m0 {
        let mut buf = [Particle::default(); gdsmc_demo::N_M0];
        gdsmc_demo::grw3(&mut buf, seed, &mut out, || 0).map(|_| ())
    } else {
        let mut buf = [Particle::default(); gdsmc_demo::N];
        let mut spins = [Spin::default(); gdsmc_demo::N_ROUGH];
        gdsmc_demo::all(&mut buf, &mut spins, seed, &mut out, || 0).map(|_| ())
    };
    print!("{out}");
    if let Err(e) = r {
        eprintln!("error: {e}");
        std::process::exit(1);
    }
}
