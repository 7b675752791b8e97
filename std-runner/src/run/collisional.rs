//! What `observe.collisional_pairs` adds to a scene's columns, in one place: MS's collisional
//! moments, a smooth mixture's cooling rates and every gas's collisional cooling.

/// What `observe.collisional_pairs` adds to a scene's columns: the one place
/// [`super::columns::names`] and the ensemble loop read it from.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Collisional {
    /// MS's `mu2`, `mu4` (MS (65)-(67)): smooth spheres of one species, a constant coefficient,
    /// equal weights.
    pub moments: bool,
    /// A smooth mixture's [`super::columns::COOLING_COLUMNS`] (run/cooling.rs): spheres, constant coefficients.
    pub mixture_rates: bool,
    /// [`super::columns::CLOSING_COLUMNS`]: every gas.
    pub cooling: bool,
    /// [`gdsmc_theory::columns::LITERATURE_ZETA_STAR`] after them: smooth hard spheres or
    /// disks of one species (the literature's `nu_0` is theirs).
    pub nu0: bool,
}

/// What `observe.collisional_pairs` adds for `scene` ([`Collisional`]).
pub fn collisional(scene: &crate::scene::Scene) -> Collisional {
    let on = scene.collisional_pairs() > 0;
    let ph = scene.physics();
    let smooth_spheres =
        ph.rotation.is_none() && ph.dimension == gdsmc_core::physics::DimensionChoice::Three;
    Collisional {
        moments: on
            && ph.species.is_empty()
            && smooth_spheres
            && ph.restitution.constant().is_some()
            && !scene.model().weighted(),
        mixture_rates: on
            && !ph.species.is_empty()
            && smooth_spheres
            && crate::run::cooling::CoolingRates::new(scene).is_some(),
        cooling: on,
        nu0: on && ph.species.is_empty() && ph.rotation.is_none() && ph.kernel.kind().hard(),
    }
}
