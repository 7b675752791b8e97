//! The one dispatch from a validated [`Model`] to the statically composed [`Engine`]: one
//! `match` per level (kernel, drive, restitution law, scheme), each level generic over the
//! choices above it, so that every leaf is a monomorphized event loop.

use super::engine::{ByDrive, ByLaw, ByScheme, Engine};
use super::model::{DriveModel, KernelModel, LawModel, Model, SchemeModel};
use crate::drive::{Drive, NoDrive};
use crate::engine::{EngineError, NoSplitting, Splitting, TimeStepped};
use crate::kernel::Kernel;
use crate::math::Real;
use crate::moments::Observables;
use crate::particles::Particles;
use crate::restitution::Restitution;
use crate::rng::Rng;
use crate::vec3::Vec3;

impl Model {
    /// Draws every particle's velocity from the initial distribution (one uniform for the
    /// component, then the Maxwellian; particle by particle) and sets its last-kick time to
    /// `t0`. Fails with [`EngineError::ParticleCount`] unless `p` holds `n` particles.
    pub fn initialize<R: Rng + ?Sized>(
        &self,
        p: &mut Particles<'_>,
        t0: Real,
        rng: &mut R,
    ) -> Result<(), EngineError> {
        if p.len() != self.n() {
            return Err(EngineError::ParticleCount);
        }
        let mut bad = false;
        p.fill_with(t0, || {
            // The weights were validated: a positive total, so sampling cannot fail.
            self.initial().sample(rng).unwrap_or_else(|_| {
                bad = true;
                Vec3::ZERO
            })
        });
        if bad {
            return Err(EngineError::NonFinite("an initial velocity"));
        }
        Ok(())
    }

    /// Starts the statically composed engine of this physics at `t0` on `p` (which holds the
    /// initial velocities): the one dispatch from the description to the event loop. Returns
    /// the engine and the observables at `t0`.
    pub fn start(
        &self,
        p: &mut Particles<'_>,
        t0: Real,
    ) -> Result<(Engine, Observables), EngineError> {
        if p.len() != self.n() {
            return Err(EngineError::ParticleCount);
        }
        match self.kernel {
            KernelModel::Maxwell(k) => wrap(self.by_drive(k, p, t0), Engine::Maxwell),
            KernelModel::HardSpheres(k) => wrap(self.by_drive(k, p, t0), Engine::HardSpheres),
            KernelModel::Vhs(k) => wrap(self.by_drive(k, p, t0), Engine::Vhs),
        }
    }

    /// [`Model::initialize`] then [`Model::start`].
    pub fn launch<R: Rng + ?Sized>(
        &self,
        p: &mut Particles<'_>,
        t0: Real,
        rng: &mut R,
    ) -> Result<(Engine, Observables), EngineError> {
        self.initialize(p, t0, rng)?;
        self.start(p, t0)
    }

    fn by_drive<K: Kernel>(
        &self,
        k: K,
        p: &mut Particles<'_>,
        t0: Real,
    ) -> Result<(ByDrive<K>, Observables), EngineError> {
        match self.drive {
            DriveModel::None => wrap(self.by_law(k, NoDrive, p, t0), ByDrive::None),
            DriveModel::WhiteNoise(d) => wrap(self.by_law(k, d, p, t0), ByDrive::WhiteNoise),
            DriveModel::Gaussian(d) => wrap(self.by_law(k, d, p, t0), ByDrive::Gaussian),
            DriveModel::ConstantForce(d) => wrap(self.by_law(k, d, p, t0), ByDrive::ConstantForce),
            DriveModel::HostMaxwell(d) => wrap(self.by_law(k, d, p, t0), ByDrive::HostMaxwell),
            DriveModel::HostHardSpheres(d) => {
                wrap(self.by_law(k, d, p, t0), ByDrive::HostHardSpheres)
            }
        }
    }

    fn by_law<K: Kernel, D: Drive>(
        &self,
        k: K,
        d: D,
        p: &mut Particles<'_>,
        t0: Real,
    ) -> Result<(ByLaw<K, D>, Observables), EngineError> {
        match self.law {
            LawModel::Constant(a) => wrap(self.by_scheme(k, d, a, p, t0), ByLaw::Constant),
            LawModel::ImpactSpeed(a) => wrap(self.by_scheme(k, d, a, p, t0), ByLaw::ImpactSpeed),
        }
    }

    fn by_scheme<K: Kernel, D: Drive, A: Restitution>(
        &self,
        k: K,
        d: D,
        a: A,
        p: &mut Particles<'_>,
        t0: Real,
    ) -> Result<(ByScheme<K, D, A>, Observables), EngineError> {
        match self.scheme {
            SchemeModel::NoSplitting => {
                wrap(NoSplitting::start(k, d, a, p, t0), ByScheme::NoSplitting)
            }
            SchemeModel::Splitting(order, dt) => wrap(
                Splitting::start(k, d, a, order, dt, p, t0),
                ByScheme::Splitting,
            ),
            SchemeModel::TimeStepped(hs, f) => wrap(
                TimeStepped::start(hs, d, a, f, p, t0),
                ByScheme::TimeStepped,
            ),
        }
    }
}

fn wrap<E, F>(
    r: Result<(E, Observables), EngineError>,
    f: impl FnOnce(E) -> F,
) -> Result<(F, Observables), EngineError> {
    r.map(|(e, o)| (f(e), o))
}
