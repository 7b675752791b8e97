//! The validated physics: a [`Physics`] whose every rule holds, composed from the building
//! blocks (`parts.rs`) and the axes that combine them (`species.rs`, `rotation.rs`,
//! `dimension.rs`), each of which imports the blocks and none this module.

use super::axes::WithKernel;
use super::error::PhysicsError;
use super::parts::{
    DriveModel, KernelModel, LawModel, SchemeModel, drive, initial, kernel, law, particle_count,
    scheme,
};
use super::species::Slot;
use super::{MAX_COMPONENTS, Physics};
use crate::kernel::Kernel;
use crate::math::Real;
use crate::sample::MaxwellianMixture;

/// A [`Physics`] whose every rule holds, ready to start engines ([`Model::start`]).
#[derive(Clone, Debug)]
pub struct Model {
    n: usize,
    initial: MaxwellianMixture<MAX_COMPONENTS>,
    pub(super) kernel: KernelModel,
    pub(super) law: LawModel,
    pub(super) drive: DriveModel,
    pub(super) scheme: SchemeModel,
    pub(super) mixture: Option<super::species::Kept>,
    pub(super) rough: Option<super::rotation::RoughModel>,
    pub(super) dimension: super::DimensionChoice,
    pub(super) momentum: super::Momentum,
    /// Hard spheres with no drive run on the sum-form majorant ([`crate::engine::SumNoSplitting`]);
    /// false: on `Umax` ([`crate::engine::NoSplitting`]), for comparisons.
    pub(super) sum_form: bool,
}

impl Model {
    /// Validates `physics` (see [`Physics::validate`]). Never inlined: its temporaries (the
    /// optional mixture and rotation models) then live in its own frame, not in every caller's
    /// for the whole run (a Cortex-M0 has 16 KiB of RAM).
    #[inline(never)]
    pub fn new(physics: &Physics) -> Result<Self, PhysicsError> {
        particle_count(physics.n)?;
        let initial = initial(&physics.initial)?;
        let kernel = kernel(physics.kernel)?;
        let law = law(physics.restitution)?;
        let drive = drive(physics.drive)?;
        let scheme = scheme(physics.scheme, physics.drive)?;
        // The mixture's and the rotation's validations run (and take their stack) only when
        // the physics has species or rotation.
        let mixture = if physics.species.is_empty() {
            None
        } else {
            super::species::mixture(physics, kernel, law, drive)?
        };
        let dimension = super::dimension::dimension(physics, drive)?;
        let rough = match physics.rotation {
            None => None,
            Some(_) => super::rotation::rotation(physics, law, drive)?,
        };
        #[cfg(feature = "weighted")]
        if let SchemeModel::Weighted(w) = scheme {
            weighted_fits(physics, w)?;
        }
        Ok(Model {
            n: physics.n,
            initial,
            kernel,
            law,
            drive,
            scheme,
            mixture,
            rough,
            dimension,
            momentum: physics.momentum,
            sum_form: true,
        })
    }

    /// The same model on the `Umax` majorant of GRW step 1.4 for hard spheres with no drive
    /// (the loop before the sum form): the same process, for comparisons and benchmarks.
    pub fn with_umax_majorant(mut self) -> Self {
        self.sum_form = false;
        self
    }

    /// The dimension (spheres or disks).
    pub fn dimension(&self) -> super::DimensionChoice {
        self.dimension
    }

    /// How the sample's total momentum starts.
    pub fn momentum(&self) -> super::Momentum {
        self.momentum
    }

    /// Particles per system.
    pub fn n(&self) -> usize {
        self.n
    }

    /// The collision map of a rough gas of one species (`None`: smooth particles or a mixture;
    /// [`Model::rotates`] tells whether spins are needed). Under the impact-speed law its
    /// constant alpha is 1 and unused (the engine puts the law into the map).
    pub fn rough_map(&self) -> Option<&crate::rough::RoughMap> {
        self.rough.as_ref().map(|r| &r.map)
    }

    /// Whether the particles are rough (one species or a mixture): the particle buffer then
    /// needs one spin per particle ([`crate::particles::Particles::with_spins`]).
    pub fn rotates(&self) -> bool {
        self.rough.is_some() || self.mixture.as_ref().is_some_and(Slot::rotates)
    }

    /// The validated mixture (`None`: one species, or a build without mixtures).
    pub(super) fn mixture(&self) -> Option<&super::species::MixtureModel> {
        self.mixture.as_ref()?.model()
    }

    /// Whether the physics has species (also in a build without mixtures, which refuses to
    /// start it).
    pub fn has_species(&self) -> bool {
        self.mixture.is_some()
    }

    /// The species of a mixture (`None`: one species, or a build without mixtures).
    pub fn species(&self) -> Option<&crate::mixture::Species> {
        self.mixture().map(|m| &m.species)
    }

    /// A mixture's pair cross sections, the factor of each pair type's kernel
    /// (`((d_s + d_t)/2)^(d - 1)`), in [`crate::mixture::pair_index`] order (`None`: one
    /// species).
    pub fn pair_cross_sections(&self) -> Option<&[Real]> {
        self.mixture().map(|m| &m.factors[..m.species.pair_types()])
    }

    /// A rough mixture's law of each pair type (alpha, beta, the partners' kappa), in
    /// [`crate::mixture::pair_index`] order (`None`: not a rough mixture). Under the
    /// impact-speed law each constant alpha is 1 and unused (the engine puts the law in).
    pub fn rough_pair_laws(&self) -> Option<&[crate::rough::RoughPairLaw]> {
        let m = self.mixture()?;
        Some(&m.rotation.as_ref()?.laws[..m.species.pair_types()])
    }

    /// A rough mixture's white noise of each species (`None`: not driven, or not a rough
    /// mixture).
    pub fn rough_noises(&self) -> Option<&[crate::rough::RoughNoise]> {
        let m = self.mixture()?;
        Some(&m.rotation.as_ref()?.noises.as_ref()?[..m.species.len()])
    }

    /// The initial distribution as a sampler (of a one-species gas; a mixture's species start
    /// from their own Maxwellians).
    pub fn initial(&self) -> &MaxwellianMixture<MAX_COMPONENTS> {
        &self.initial
    }

    /// The particles a system's buffers hold: `n`, or for the weighted scheme its `capacity`
    /// times `n` (room for the particles collisions create, [`crate::particles::Particles::weighted`]).
    pub fn capacity(&self) -> usize {
        match self.scheme {
            #[cfg(feature = "weighted")]
            SchemeModel::Weighted(w) => w.capacity(self.n),
            SchemeModel::NoSplitting | SchemeModel::Splitting(..) | SchemeModel::TimeStepped(_) => {
                self.n
            }
        }
    }

    /// Whether the scheme runs weighted particles.
    pub fn weighted(&self) -> bool {
        #[cfg(feature = "weighted")]
        {
            matches!(self.scheme, SchemeModel::Weighted(_))
        }
        #[cfg(not(feature = "weighted"))]
        {
            false
        }
    }

    /// The exact schemes' candidate rate of `n` particles whose relative speeds stay below
    /// `umax`, `2 pi gamma C_lambda (n - 1) Umax^lambda` (GRW Section 3, RW (20)): the
    /// kernel's [`Kernel::majorant_rate`], for estimates made before any engine exists.
    pub fn majorant_rate(&self, n: usize, umax: Real) -> Real {
        /// [`Kernel::majorant_rate`] of `n` particles below `umax`.
        struct Rate(usize, Real);
        impl WithKernel for Rate {
            type Out = Real;
            fn with<K: Kernel>(self, k: K) -> Real {
                k.majorant_rate(self.0, self.1)
            }
        }
        self.kernel.with(Rate(n, umax))
    }

    /// The candidate rate of one grain's background events, a grain of speed `speed` taken
    /// as far from the background's drift as it can be (`|v - u^B| <= speed + |u^B|`): a host
    /// medium's bound, `4 pi C_1 rho^B` (BRS (11)) or BRS (28) ([`crate::drive::Drive::event_rate`]); 0
    /// without a host medium.
    pub fn background_rate(&self, speed: Real) -> Real {
        self.drive.event_rate(speed)
    }

    /// How the drive alone changes the temperature, when it does so linearly
    /// ([`crate::drive::Heating`]: none, white noise, the Gaussian and Langevin thermostats):
    /// with the Maxwell kernel the temperature is then exact (GRW (13)).
    pub fn heating(&self) -> Option<crate::drive::Heating> {
        self.drive.heating()
    }

    /// A declared drive's bound for a run's work estimate ([`crate::drive::Declared::work`]):
    /// the largest temperature and the time at the start's collision rate; `None` for none,
    /// white noise and the host medium.
    pub fn drive_work(&self, w: crate::drive::WorkInput) -> Option<(Real, Real)> {
        self.drive.work(w)
    }
}

#[cfg(feature = "weighted")]
/// The weighted scheme's rules against the rest of `physics`: smooth particles of one species,
/// and buffers of `capacity n` particles that memory can address.
fn weighted_fits(
    physics: &Physics,
    w: super::weighted_scheme::WeightedModel,
) -> Result<(), PhysicsError> {
    use super::error::{Param, Problem};
    let refuse = |why| {
        Err(PhysicsError {
            param: Param::Scheme,
            problem: Problem::DoesNotFit(why),
        })
    };
    if !physics.species.is_empty() {
        return refuse("runs one species (no [[species]] yet)");
    }
    if physics.rotation.is_some() {
        return refuse("runs smooth particles (no [rotation] yet)");
    }
    crate::particles::check_count(w.capacity(physics.n)).map_err(|_| PhysicsError {
        param: Param::Step(super::SchemeKind::Weighted, 3),
        problem: Problem::DoesNotFit("makes more particles than memory can address"),
    })
}
