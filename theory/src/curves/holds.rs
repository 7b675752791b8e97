//! What physics a reference holds for ([`Holds`]): the particles and each axis' values, as
//! [`super::registry`] declares them.

use gdsmc_core::physics::{DriveKind, KernelKind, LawKind, SchemeKind};
use gdsmc_scene::Scene;

/// Which particles a reference holds for.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Particles {
    /// One species without rotation.
    Smooth,
    /// One species whose translation is smooth as the engine decides it
    /// (`Physics::translation_is_smooth`): without rotation, or rough particles with `beta = -1`
    /// whose collisions are the smooth gas's, bit for bit (hard particles, or spheres of any
    /// kernel; not rough pseudo-Maxwell disks, which collide with the hard-disk impact law).
    SmoothTranslation,
    /// One species of rough particles.
    Rough,
    /// Two or more species without rotation.
    SmoothMixture,
    /// Two or more species of rough particles.
    RoughMixture,
}

impl Particles {
    /// Whether `scene`'s particles are these.
    pub fn of(self, scene: &Scene) -> bool {
        let ph = scene.physics();
        let (mixture, rough) = (!ph.species.is_empty(), ph.rotation.is_some());
        match self {
            Particles::Smooth => !mixture && !rough,
            Particles::SmoothTranslation => !mixture && scene.translation_is_smooth(),
            Particles::Rough => !mixture && rough,
            Particles::SmoothMixture => mixture && !rough,
            Particles::RoughMixture => mixture && rough,
        }
    }

    /// Its words in docs/combinations.md.
    pub fn words(self) -> &'static str {
        match self {
            Particles::Smooth => "smooth, one species",
            Particles::SmoothTranslation => {
                "smooth translation (rough with beta = -1 too, but for pseudo-Maxwell disks), one \
                 species"
            }
            Particles::Rough => "rough, one species",
            Particles::SmoothMixture => "smooth mixture",
            Particles::RoughMixture => "rough mixture",
        }
    }
}

/// Which drives a reference holds for: by what the drive declares of its temperature law
/// (`gdsmc_core::drive::Heating`, through the scene's validated model), or by kind where the
/// reference is about one drive's physics.
#[derive(Clone, Copy, Debug)]
pub enum Drives {
    /// Every drive that declares a linear temperature law (`Model::heating`): with the Maxwell
    /// kernel the temperature is then exact (GRW (13)). A new drive that declares its heating
    /// gets these references with no other change.
    Linear,
    /// Every drive whose linear law adds no heat of its own (`a = 0`: no drive, the Gaussian
    /// thermostat, a drag): it only rescales the velocities, so the reduced distribution is the
    /// freely cooling gas's (MS Section 2.2).
    Rescaling,
    /// These drives (a reference about one drive's physics).
    Kinds(&'static [DriveKind]),
}

impl Drives {
    /// Whether `scene`'s drive is one of these.
    pub fn of(self, scene: &Scene) -> bool {
        match self {
            Drives::Linear => scene.model().heating().is_some(),
            Drives::Rescaling => scene.model().heating().is_some_and(|h| h.a == 0.0),
            Drives::Kinds(kinds) => kinds.contains(&scene.physics().drive.kind()),
        }
    }

    /// Its words in docs/combinations.md (`None`: every drive).
    fn words(self) -> Option<String> {
        match self {
            Drives::Linear => {
                Some("a drive with a linear temperature law (declared heating)".into())
            }
            Drives::Rescaling => {
                Some("a drive that only rescales the velocities (declared heating, a = 0)".into())
            }
            Drives::Kinds(kinds) if kinds.len() == DriveKind::ALL.len() => None,
            Drives::Kinds(kinds) => Some(
                kinds
                    .iter()
                    .map(|k| k.scene_name())
                    .collect::<Vec<_>>()
                    .join(" or "),
            ),
        }
    }
}

/// The physics a reference holds for: each axis the values it holds at.
#[derive(Clone, Copy, Debug)]
pub struct Holds {
    /// The particles.
    pub particles: Particles,
    /// The kernels.
    pub kernels: &'static [KernelKind],
    /// The restitution laws.
    pub laws: &'static [LawKind],
    /// The drives.
    pub drives: Drives,
    /// The schemes.
    pub schemes: &'static [SchemeKind],
    /// The dimensions.
    pub dimensions: &'static [usize],
    /// A condition on parameters the axes do not show (a host medium's kernel), in words; a
    /// reference with one attaches where its builder finds it holds.
    pub when: Option<&'static str>,
}

impl Holds {
    /// Whether the axes hold for `scene` (its `when`, if any, is the builder's).
    pub fn of(&self, scene: &Scene) -> bool {
        let ph = scene.physics();
        self.particles.of(scene)
            && self.kernels.contains(&ph.kernel.kind())
            && self.laws.contains(&ph.restitution.kind())
            && self.drives.of(scene)
            && self.schemes.contains(&ph.scheme.kind())
            && self.dimensions.contains(&scene.dimension())
    }

    /// Its words: the particles, then each axis it restricts.
    pub fn words(&self) -> String {
        fn axis<T: Copy + PartialEq>(
            of: &[T],
            all: &[T],
            name: impl Fn(T) -> &'static str,
        ) -> Option<String> {
            (of.len() < all.len())
                .then(|| of.iter().map(|&k| name(k)).collect::<Vec<_>>().join(" or "))
        }
        let mut w = vec![self.particles.words().to_string()];
        w.extend(axis(self.kernels, KernelKind::ALL, |k| k.scene_name()));
        w.extend(axis(self.laws, LawKind::ALL, |k| match k {
            LawKind::Constant => "constant restitution",
            LawKind::ImpactSpeed => "impact-speed law",
        }));
        w.extend(self.drives.words());
        w.extend(axis(self.schemes, SchemeKind::ALL, |k| k.scene_name()));
        if self.dimensions.len() == 1 {
            w.push(format!("d = {}", self.dimensions[0]));
        }
        w.extend(self.when.map(str::to_string));
        w.join("; ")
    }
}
