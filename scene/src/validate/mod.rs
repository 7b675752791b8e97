//! From the file as written to a [`Scene`]: one validator per table. The tables that describe
//! physics only gather their values into the core's [`Physics`] and say which key holds which
//! parameter; [`Physics::validate`] checks every physical rule, and its error is reported
//! at the key and line of the parameter it names. Rules about observing and running (times,
//! histograms, ensembles) are the scene's own and checked here.

pub(crate) mod collisions;
mod ctx;
mod declared;
mod drive;
pub(crate) mod observe;
mod particles;
mod rotation;
pub(crate) mod scheme;
pub mod size;
pub mod species;
pub(crate) mod sweep;

use crate::Scene;
use crate::error::Error;
use crate::schema::SceneFile;
use gdsmc_core::physics::Physics;
use std::path::Path;

pub(crate) use ctx::Ctx;
pub use scheme::DEFAULT_STEP_FACTOR;

/// Why an observable written for spheres is refused for disks.
const SPHERES_ONLY: &str =
    "is written for spheres (d = 3); disks (particles.dimension = 2) do not have it";

/// The histograms a scene asks for that disks refuse: (a reduced one, a marginal one). Only
/// the marginal one now: the reduced distribution is measured in any dimension.
type Histograms = (bool, bool);

/// The scene's rules that depend on the physics, for a physics changed after the file was
/// read ([`crate::Scene::with_physics`]): the scheme's grid against the observation `times`
/// and what disks refuse (`histograms`: a reduced one, allowed, and a marginal one). The
/// key and what is wrong, or `None`. The file's validation applies the same rules with the
/// value's line.
pub(crate) fn physics_rules(
    physics: &gdsmc_core::physics::Physics,
    times: &[f64],
    histograms: Histograms,
) -> Option<(&'static str, String)> {
    if let Some(m) = scheme::grid_problem(physics.scheme, times) {
        return Some(("scheme.dt", m));
    }
    if physics.dimension == gdsmc_core::physics::DimensionChoice::Two {
        return histograms
            .1
            .then(|| ("marginal_histogram", SPHERES_ONLY.to_string()));
    }
    None
}

impl SceneFile {
    /// The file's `[sweep]` plan, checked (`path` and `text` name a bad value's line).
    pub fn sweep_plan(&self, path: &Path, text: &str) -> Result<Option<crate::vary::Plan>, Error> {
        sweep::sweep(&Ctx::new(path, text), &self.sweep)
    }

    /// Disks (`particles.dimension = 2`) run, observe their moments, speed shells (ring
    /// areas) and reduced distribution (the planar Maxwellian and Sonine polynomial beside it;
    /// MS's hard-sphere tail laws are for spheres) and compare with the references written
    /// for any dimension; BRS's marginal distribution is written for spheres, and is refused
    /// at its key rather than computed with the wrong volume.
    fn spheres_only(&self, ctx: &Ctx<'_>) -> Result<(), Error> {
        let why = SPHERES_ONLY;
        if let Some(h) = &self.marginal_histogram {
            return ctx.invalid(h.axis.span(), "marginal_histogram", why);
        }
        Ok(())
    }

    /// Validates the file's values; `path` and `text` are used to name the line of a bad value.
    pub fn validate(&self, path: &Path, text: &str) -> Result<Scene, Error> {
        let mut ctx = Ctx::new(path, text);
        let (n, initial) = particles::particles(&mut ctx, &self.particles)?;
        let dimension = particles::dimension(&mut ctx, &self.particles)?;
        let (kernel, restitution, derived) = collisions::collisions(
            &mut ctx,
            &self.collisions,
            dimension,
            self.species
                .as_ref()
                .is_some_and(|s| !s.get_ref().is_empty()),
        )?;
        let drive = drive::drive(&mut ctx, &self.drive)?;
        let times = observe::times(&ctx, &self.observe)?;
        let scheme = scheme::scheme(&mut ctx, &self.scheme)?;
        let mixture = species::mixture(&mut ctx, self, n)?;
        let rotation = rotation::rotation(&mut ctx, &self.rotation, dimension);
        let momentum = particles::momentum(&ctx, &self.particles)?;
        let physics = Physics {
            n,
            initial,
            kernel,
            restitution,
            drive,
            scheme,
            species: mixture.species,
            pair_restitution: mixture.pair_restitution,
            pair_tangential_restitution: mixture.pair_tangential_restitution,
            rotation,
            dimension,
            momentum,
        };
        let model = physics.validate().map_err(|e| ctx.physics_error(e))?;
        if dimension == gdsmc_core::physics::DimensionChoice::Two {
            self.spheres_only(&ctx)?;
        }
        scheme::on_grid(&ctx, &self.scheme, physics.scheme, &times)?;
        let observe = observe::observe(&ctx, &self.observe, &times)?;
        let snapshots = observe::snapshots(&ctx, &self.observe, &times)?;
        let histograms = observe::histograms(&ctx, self)?;
        let (ensembles, seed) = observe::run(&ctx, &self.run)?;
        // Checked with the file (a bad table is refused by `gdsmc run` too), read by the sweep
        // through `crate::sweep_plan`.
        sweep::sweep(&ctx, &self.sweep)?;
        let name = self.name.clone().unwrap_or_else(|| {
            path.file_stem()
                .map(|s| s.to_string_lossy().into_owned())
                .unwrap_or_default()
        });
        Ok(Scene {
            name,
            description: self.description.clone().unwrap_or_default(),
            physics,
            model,
            keys: ctx.keys(),
            times,
            steady_from: observe.0,
            collisional_pairs: observe.1,
            time_axis: observe.2,
            snapshots,
            histogram: histograms.0,
            reduced_histogram: histograms.1,
            marginal_histogram: histograms.2,
            ensembles,
            seed,
            species_names: mixture.names,
            species_fractions: mixture.fractions,
            derived: derived.into_iter().collect(),
        })
    }
}
