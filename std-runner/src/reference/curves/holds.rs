//! What physics a reference holds for ([`Holds`]): the particles and each axis' values, as
//! [`super::registry`] declares them.

use crate::scene::Scene;
use gdsmc_core::physics::{DriveKind, KernelKind, LawKind, SchemeKind};

/// Which particles a reference holds for.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Particles {
    /// One species without rotation.
    Smooth,
    /// One species whose translation is smooth: without rotation, or rough particles with
    /// `beta = -1` (whose translation is the smooth gas's, bit for bit).
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
                "smooth translation (rough with beta = -1 too), one species"
            }
            Particles::Rough => "rough, one species",
            Particles::SmoothMixture => "smooth mixture",
            Particles::RoughMixture => "rough mixture",
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
    pub drives: &'static [DriveKind],
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
            && self.drives.contains(&ph.drive.kind())
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
        w.extend(axis(self.drives, DriveKind::ALL, |k| k.scene_name()));
        w.extend(axis(self.schemes, SchemeKind::ALL, |k| k.scene_name()));
        if self.dimensions.len() == 1 {
            w.push(format!("d = {}", self.dimensions[0]));
        }
        w.extend(self.when.map(str::to_string));
        w.join("; ")
    }
}
