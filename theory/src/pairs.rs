//! A mixture's pair kernels: the scene's diameters and coefficients as the kernel of each pair
//! type (GRW Section 3 with the pair's cross section), for the mixture references and the
//! runner's cooling-rate estimate.

use gdsmc_core::mixture::Species;
use gdsmc_scene::Physics;

/// Every pair type of a mixture physics (`species` its validated species), in the core's pair
/// order: `(4 pi gamma C ((d_s + d_t)/2)^2, alpha_st)`, so that `int B_st de = strength
/// |u|^lambda` (the description's kernel with the pair's cross section). The one place
/// gdsmc turns the scene's diameters and coefficients into pair kernels (the references and
/// the cooling-rate estimate use it). `None` when a coefficient is not constant.
pub fn pair_kernels(ph: &Physics, species: &Species) -> Option<Vec<(f64, f64)>> {
    let strength = ph.kernel.strength();
    (0..species.pair_types())
        .map(|k| {
            let (s, t) = species.pair(k);
            let d = 0.5 * (ph.species[s].diameter + ph.species[t].diameter);
            let alpha = match ph.pair_restitution.get(k) {
                Some(&a) => a,
                None => ph.restitution.constant()?,
            };
            Some((4.0 * std::f64::consts::PI * strength * d * d, alpha))
        })
        .collect()
}
