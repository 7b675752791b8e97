//! What physics a reference holds for ([`Holds`]): predicates over what the core declares of
//! the scene's physics (the engine's own smooth-translation rule, the kernel's exponent, the
//! drive's heating, the scheme's process), never a list of kinds that a new variant would
//! silently miss. A scheme or a drive is classified by an exhaustive `match`, so a new one does
//! not compile until it is.

use gdsmc_core::physics::{DriveKind, SchemeKind};
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

/// Which kernels a reference holds for, by what the kernel declares: its exponent when it is
/// the power law `B = gamma C |u|^lambda` (`KernelChoice::exponent`, `None` for a kernel that
/// is not one) and whether it collides as hard particles (the core's `Kernel::HARD`).
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Kernels {
    /// Every power-law kernel: the reference reads its exponent (the Maxwellian and Sonine
    /// approximations, the collision rate).
    PowerLaw,
    /// The power laws with `lambda > 0`, whose temperature decays as a power of time (Haff's
    /// law; the Maxwell kernel's is exact, GRW (13)).
    PositivePower,
    /// A kernel that does not depend on the speed (`lambda = 0`: Maxwell molecules, GRW (2),
    /// the VHS kernel at 0, or the impact form of the inelastic Maxwell model): the exact
    /// solutions whose builders read the model's form (`crate::maxwell_form::Form`: GRW (13)'s
    /// temperature with the form's decay rate, the Maxwell gas's `zeta*`).
    Maxwell,
    /// A speed-independent kernel of GRW (3)'s scattering form (`e` uniform; not the core's
    /// `Kernel::UNIFORM_IMPACT`): the exact solutions derived for it alone (Bobylev, Carrillo
    /// and Gamba's `a2`, BRS's host medium, the Maxwell mixture's moments).
    MaxwellScattering,
    /// The impact form of the inelastic Maxwell model (`Kernel::UNIFORM_IMPACT`, `n` uniform):
    /// the exact solutions derived for it (`theory/src/maxwell_impact.rs`).
    MaxwellImpact,
    /// Hard particles with their impact law (the core's `Kernel::HARD`: MS's hard spheres and
    /// disks).
    Hard,
}

impl Kernels {
    /// Whether `scene`'s kernel is one of these.
    pub fn of(self, scene: &Scene) -> bool {
        let k = scene.physics().kernel;
        self.holds(k.kind().hard(), k.kind().uniform_impact(), k.exponent())
    }

    /// Whether a kernel that is (or is not) `hard`, whose impact direction is (or is not)
    /// uniform (`impact`), of power-law `exponent` (`None`: not a power law), is one of these.
    /// Every variant reads a power law: a kernel without an exponent is none of them, so it
    /// gets no power-law reference.
    pub fn holds(self, hard: bool, impact: bool, exponent: Option<f64>) -> bool {
        match self {
            Kernels::PowerLaw => exponent.is_some(),
            Kernels::PositivePower => exponent.is_some_and(|l| l > 0.0),
            Kernels::Maxwell => exponent == Some(0.0),
            Kernels::MaxwellScattering => !impact && exponent == Some(0.0),
            Kernels::MaxwellImpact => impact && exponent == Some(0.0),
            Kernels::Hard => hard && exponent == Some(1.0),
        }
    }

    /// Its words in docs/combinations.md.
    fn words(self) -> &'static str {
        match self {
            Kernels::PowerLaw => "a power-law kernel",
            Kernels::PositivePower => "a power-law kernel with lambda > 0",
            Kernels::Maxwell => "a speed-independent kernel (lambda = 0), either form",
            Kernels::MaxwellScattering => "a speed-independent kernel of GRW (3)'s form, e uniform",
            Kernels::MaxwellImpact => "the inelastic Maxwell model's impact form, n uniform",
            Kernels::Hard => "hard particles",
        }
    }
}

/// Which restitution laws a reference holds for.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Laws {
    /// A constant coefficient (`RestitutionLaw::constant`): the references' `alpha`.
    Constant,
}

impl Laws {
    /// Whether `scene`'s law is one of these.
    pub fn of(self, scene: &Scene) -> bool {
        match self {
            Laws::Constant => scene.physics().restitution.constant().is_some(),
        }
    }

    /// Its words in docs/combinations.md.
    fn words(self) -> &'static str {
        match self {
            Laws::Constant => "constant restitution",
        }
    }
}

/// One kind of drive a reference holds for: by what the drive declares of its temperature law
/// (`gdsmc_core::drive::Heating`, through the scene's validated model), or one drive where the
/// reference is about that drive's own physics (a host medium's encounters, MS's white-noise
/// and constant-force states).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Drive {
    /// Every drive.
    Any,
    /// Every drive that declares a linear temperature law (`Model::heating`): with the Maxwell
    /// kernel the temperature is then exact (GRW (13)). A new drive that declares its heating
    /// gets these references with no other change.
    Linear,
    /// Every drive whose linear law adds no heat of its own (`a = 0`: no drive, the Gaussian
    /// thermostat, a drag): it only rescales the velocities, so the reduced distribution is the
    /// freely cooling gas's (MS Section 2.2).
    Rescaling,
    /// A drive that does nothing (its declared law all zero): the freely cooling gas.
    Free,
    /// This drive (a reference about its own physics).
    Is(DriveKind),
}

impl Drive {
    /// Whether `scene`'s drive is this.
    pub fn of(self, scene: &Scene) -> bool {
        let heating = scene.model().heating();
        match self {
            Drive::Any => true,
            Drive::Linear => heating.is_some(),
            Drive::Rescaling => heating.is_some_and(|h| h.a == 0.0),
            Drive::Free => heating.is_some_and(|h| h.a == 0.0 && h.b == 0.0 && h.p == 0.0),
            Drive::Is(kind) => scene.physics().drive.kind() == kind,
        }
    }

    /// Its words in docs/combinations.md.
    fn words(self) -> String {
        match self {
            Drive::Any => "any drive".into(),
            Drive::Linear => "a drive with a linear temperature law (declared heating)".into(),
            Drive::Rescaling => {
                "a drive that only rescales the velocities (declared heating, a = 0)".into()
            }
            Drive::Free => "no drive (declared heating all zero)".into(),
            Drive::Is(kind) => kind.scene_name().into(),
        }
    }
}

/// Which schemes a reference holds for, by the process each scheme runs (classified by an
/// exhaustive `match`: a new scheme is placed here before it compiles).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Schemes {
    /// Every scheme.
    Any,
    /// The schemes whose exact means at finite n are known: the no-splitting process and its
    /// Euler and Strang splittings (RW Algorithms 1-2).
    ExactMeans,
    /// The schemes whose n -> infinity limit is the Boltzmann equation's solution: all but
    /// MS's time-stepped scheme, whose collisions are not the Markov process's.
    Boltzmann,
    /// The schemes whose particles weigh alike (all but the weighted one, whose finite-n means
    /// carry `sum g^2`).
    EqualWeights,
    /// The weighted scheme alone.
    Weighted,
}

impl Schemes {
    /// Whether `scheme` is one of these.
    pub fn holds(self, scheme: SchemeKind) -> bool {
        let (exact_means, boltzmann, weighted) = match scheme {
            SchemeKind::NoSplitting | SchemeKind::Euler | SchemeKind::Strang => (true, true, false),
            SchemeKind::Weighted => (false, true, true),
            SchemeKind::TimeStepped => (false, false, false),
        };
        match self {
            Schemes::Any => true,
            Schemes::ExactMeans => exact_means,
            Schemes::Boltzmann => boltzmann,
            Schemes::EqualWeights => !weighted,
            Schemes::Weighted => weighted,
        }
    }

    /// Its words in docs/combinations.md (`None`: every scheme).
    fn words(self) -> Option<String> {
        (self != Schemes::Any).then(|| {
            SchemeKind::ALL
                .iter()
                .filter(|&&s| self.holds(s))
                .map(|s| s.scene_name())
                .collect::<Vec<_>>()
                .join(" or ")
        })
    }
}

/// The physics a reference holds for: each axis a predicate over what the core declares.
#[derive(Clone, Copy, Debug)]
pub struct Holds {
    /// The particles.
    pub particles: Particles,
    /// The kernels.
    pub kernels: Kernels,
    /// The restitution laws.
    pub laws: Laws,
    /// The drives: any of these.
    pub drives: &'static [Drive],
    /// The schemes.
    pub schemes: Schemes,
    /// The dimensions.
    pub dimensions: &'static [usize],
    /// A condition on parameters the axes do not show (a host medium's kernel), in words; a
    /// reference with one attaches where its builder finds it holds.
    pub when: Option<&'static str>,
}

impl Holds {
    /// Whether the axes hold for `scene` (its `when`, if any, is the builder's).
    pub fn of(&self, scene: &Scene) -> bool {
        self.particles.of(scene)
            && self.kernels.of(scene)
            && self.laws.of(scene)
            && self.drives.iter().any(|d| d.of(scene))
            && self.schemes.holds(scene.physics().scheme.kind())
            && self.dimensions.contains(&scene.dimension())
    }

    /// Its words: the particles, then each axis it restricts.
    pub fn words(&self) -> String {
        let mut w = vec![
            self.particles.words().to_string(),
            self.kernels.words().to_string(),
            self.laws.words().to_string(),
        ];
        if self.drives != [Drive::Any] {
            w.push(
                self.drives
                    .iter()
                    .map(|d| d.words())
                    .collect::<Vec<_>>()
                    .join(" or "),
            );
        }
        w.extend(self.schemes.words());
        if self.dimensions.len() == 1 {
            w.push(format!("d = {}", self.dimensions[0]));
        }
        w.extend(self.when.map(str::to_string));
        w.join("; ")
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A kernel that is not a power law (a capped or tabulated kernel declares no exponent)
    /// holds for no kernel axis, hard or not; each axis holds where its words say.
    #[test]
    fn a_kernel_without_an_exponent_holds_for_no_reference() {
        let all = [
            Kernels::PowerLaw,
            Kernels::PositivePower,
            Kernels::Maxwell,
            Kernels::MaxwellScattering,
            Kernels::MaxwellImpact,
            Kernels::Hard,
        ];
        for k in all {
            for (hard, impact) in [(false, false), (true, false), (false, true)] {
                assert!(!k.holds(hard, impact, None), "{k:?}");
            }
        }
        let at = |hard, impact, l| all.map(|k| k.holds(hard, impact, Some(l)));
        assert_eq!(
            at(false, false, 0.0),
            [true, false, true, true, false, false]
        );
        assert_eq!(
            at(false, true, 0.0),
            [true, false, true, false, true, false]
        );
        assert_eq!(
            at(false, false, 0.5),
            [true, true, false, false, false, false]
        );
        assert_eq!(
            at(true, false, 1.0),
            [true, true, false, false, false, true]
        );
        assert_eq!(
            at(false, false, 1.0),
            [true, true, false, false, false, false]
        );
    }

    /// Every scheme is placed by [`Schemes::holds`] as the references need it: the exact
    /// means of the no-splitting process and its splittings, the Boltzmann limit of all but
    /// MS's time-stepped scheme.
    #[test]
    fn the_schemes_are_placed() {
        use SchemeKind as S;
        let of = |s| {
            [
                Schemes::ExactMeans,
                Schemes::Boltzmann,
                Schemes::EqualWeights,
                Schemes::Weighted,
            ]
            .map(|x| x.holds(s))
        };
        assert_eq!(of(S::NoSplitting), [true, true, true, false]);
        assert_eq!(of(S::Strang), [true, true, true, false]);
        assert_eq!(of(S::Weighted), [false, true, false, true]);
        assert_eq!(of(S::TimeStepped), [false, false, true, false]);
    }
}
