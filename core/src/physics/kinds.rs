//! The variants of each axis (kernel, restitution law, drive, scheme), declared once: a row
//! per variant with its word in a scene file, its C code and the cargo feature that builds its
//! engine.
//! Every front end takes them from here or is checked against them: the C ABI decodes its
//! integers with [`DriveKind::from_c`] and friends and matches the kinds exhaustively (no
//! catch-all arm, so a new variant does not compile until it is decoded), its `GDSMC_*`
//! constants are asserted equal to [`DriveKind::c_code`] at compile time, and the scene's
//! names, the fuzzer's words and the combination matrix are tested to hold every kind
//! ([`DriveKind::ALL`]). A choice tells its kind ([`DriveChoice::kind`](super::DriveChoice::kind)), matched exhaustively
//! too, so a variant of a choice without its row here does not compile.

use super::axes::kernel_table;
use super::{RestitutionLaw, SchemeChoice};
use crate::drive::{Declared, ParamSpec};
use crate::kernel::Declared as DeclaredKernel;
use crate::math::Real;

/// Declares a kind enum: `Name of Choice { Variant = code, "scene-name", "feature"; ... }`.
macro_rules! kinds {
    ($(#[$m:meta])* $name:ident { $($(#[doc = $d:literal])+ $v:ident = $code:literal, $scene:literal, $feature:literal;)+ }) => {
        $(#[$m])*
        #[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
        pub enum $name {
            $($(#[doc = $d])+ $v,)+
        }

        impl $name {
            /// Every variant, in the order of their C codes.
            pub const ALL: &'static [$name] = &[$($name::$v),+];

            /// Its integer in the C ABI (`gdsmc_config`).
            #[must_use]
            pub const fn c_code(self) -> u32 {
                match self { $($name::$v => $code),+ }
            }

            /// Its word in a scene file: the value of its `kind` (`kernel`, `scheme`) key, or
            /// for a restitution law the key that gives it.
            #[must_use]
            pub const fn scene_name(self) -> &'static str {
                match self { $($name::$v => $scene),+ }
            }

            /// The cargo feature of gdsmc-core that builds its engine (`""`: always built).
            #[must_use]
            pub const fn feature(self) -> &'static str {
                match self { $($name::$v => $feature),+ }
            }

            /// What it is, in words (its doc comment here; the C header's comment).
            #[must_use]
            pub const fn doc(self) -> &'static str {
                match self { $($name::$v => concat!($($d),+)),+ }
            }

            /// The kind of a C code, if it is one.
            #[must_use]
            pub fn from_c(code: u32) -> Option<Self> {
                Self::ALL.iter().copied().find(|k| k.c_code() == code)
            }

            /// The kind of a scene name, if it is one.
            #[must_use]
            pub fn from_scene_name(name: &str) -> Option<Self> {
                Self::ALL.iter().copied().find(|k| k.scene_name() == name)
            }
        }
    };
}

/// Generates [`KernelKind`] (its codes, scene words, features and words through `kinds!`) and
/// what the kernels declare by their type ([`KernelKind::params`], [`KernelKind::title`],
/// [`KernelKind::exponent`]) from the kernel table ([`kernel_table`]).
macro_rules! kernel_kind {
    ($($v:ident($code:literal, $scene:literal, $t:ty, $feature:literal, $doc:literal)),* $(,)?) => {
        kinds! {
            /// The collision kernels (GRW (2), (4), (5)), generated from the kernel table
            /// (`physics/axes.rs`).
            KernelKind {
                $(#[doc = $doc] $v = $code, $scene, $feature;)*
            }
        }

        impl KernelKind {
            /// Its parameters beyond `gamma` and `C`, in the order of their values
            /// (`kernel_params` in C, [`super::KernelChoice::values`]).
            #[must_use]
            pub fn params(self) -> &'static [ParamSpec] {
                match self {
                    $(KernelKind::$v => <$t as DeclaredKernel>::PARAMS,)*
                }
            }

            /// Its name in a chart's title ("hard-sphere kernel").
            #[must_use]
            pub fn title(self) -> &'static str {
                match self {
                    $(KernelKind::$v => <$t as DeclaredKernel>::TITLE,)*
                }
            }

            /// Whether it is the hard-sphere (hard-disk) kernel (`Kernel::HARD`): a rough gas
            /// of it collides with the impact law in every dimension
            /// ([`crate::rough::collides_smooth`]).
            #[must_use]
            pub fn hard(self) -> bool {
                match self {
                    $(KernelKind::$v => <$t as crate::kernel::Kernel>::HARD,)*
                }
            }

            /// Whether its impact direction is uniform (`Kernel::UNIFORM_IMPACT`: the impact
            /// form of the inelastic Maxwell model, whose `e` is not uniform in d = 3).
            #[must_use]
            pub fn uniform_impact(self) -> bool {
                match self {
                    $(KernelKind::$v => <$t as crate::kernel::Kernel>::UNIFORM_IMPACT,)*
                }
            }

            /// The exponent `lambda` of `|u|^lambda` these values of its parameters give, when
            /// the kernel is that power law (`None` for one that is not).
            #[must_use]
            pub fn exponent(self, values: &[Real]) -> Option<Real> {
                match self {
                    $(KernelKind::$v => <$t as DeclaredKernel>::exponent(values),)*
                }
            }
        }
    };
}
kernel_table!(kernel_kind);

kinds! {
    /// The restitution laws (GRW (3), BRS (9)).
    LawKind {
        /// A constant restitution coefficient alpha (`restitution`).
        Constant = 0, "restitution", "";
        /// The impact-speed law BRS (9)-(10), `1 - e = 2 beta0 |g . n|^delta`.
        ImpactSpeed = 1, "impact_speed_law", "impact-speed";
    }
}

kinds! {
    /// The drives.
    DriveKind {
        /// No drive: the freely cooling gas.
        None = 0, "none", "cooling";
        /// White-noise heating of strength `beta` (GRW (1), (18)).
        WhiteNoise = 1, "white-noise", "white-noise";
        /// Elastic collisions with a Maxwellian host medium (BRS Section 2; the background's
        /// kernel, `C_1`, density, mass, temperature and drift).
        HostMedium = 2, "host-medium", "host-medium";
        /// The Gaussian thermostat `F = m zeta (v - V)` (MS (12)).
        Gaussian = 3, "gaussian", "gaussian-thermostat";
        /// The constant force along the peculiar velocity, `F = m g c/|c|` (MS (14)).
        ConstantForce = 4, "constant-force", "constant-force";
        /// The Langevin thermostat: the drag `-gamma v` and white noise at a bath temperature.
        Langevin = 5, "langevin", "langevin";
    }
}

/// Calls the macro `$then` with the table of the drives declared by their type
/// ([`Declared`](crate::drive::Declared): parameters, rules, words, title, heating, work), one
/// row per drive: `Variant(Type, "cargo-feature")`, the variant that of its [`DriveKind`].
/// The validated drive, the engine's drive level and the dispatch's drive `match` are generated
/// from it; none, white noise and the host medium are written out beside it (white noise is
/// each family's own, the host medium has a kernel and a vector among its parameters). A new
/// drive is its file in `drive/`, its row here and in [`DriveKind`], and its cargo feature.
macro_rules! declared_drives {
    ($then:ident) => {
        $then! {
            Gaussian(crate::drive::GaussianThermostat, "gaussian-thermostat"),
            ConstantForce(crate::drive::ConstantForce, "constant-force"),
            Langevin(crate::drive::Langevin, "langevin"),
        }
    };
}
pub(super) use declared_drives;

/// Generates [`DriveKind::params`] and [`DriveKind::title`] from the declared drives.
macro_rules! drive_kind_declarations {
    ($($v:ident($t:ty, $feature:literal)),* $(,)?) => {
        impl DriveKind {
            /// The parameters of a drive declared by its type, in the order of their values
            /// (`drive_params` in C, [`DriveParams`](super::DriveParams)); `None` for none,
            /// white noise and the host medium, whose parameters are their own.
            #[must_use]
            pub fn params(self) -> Option<&'static [ParamSpec]> {
                match self {
                    $(DriveKind::$v => Some(<$t as Declared>::PARAMS),)*
                    DriveKind::None | DriveKind::WhiteNoise | DriveKind::HostMedium => None,
                }
            }

            /// A declared drive's name in a chart's title.
            #[must_use]
            pub fn title(self) -> Option<&'static str> {
                match self {
                    $(DriveKind::$v => Some(<$t as Declared>::TITLE),)*
                    DriveKind::None | DriveKind::WhiteNoise | DriveKind::HostMedium => None,
                }
            }

            /// Why no exact scheme runs a declared drive, when none does.
            #[must_use]
            pub fn stepped_only(self) -> Option<&'static str> {
                match self {
                    $(DriveKind::$v => <$t as Declared>::STEPPED_ONLY,)*
                    DriveKind::None | DriveKind::WhiteNoise | DriveKind::HostMedium => None,
                }
            }
        }

        #[cfg(test)]
        /// The declared drives' rows as `(kind, feature)`.
        const DECLARED_ROWS: &[(DriveKind, &str)] = &[$((DriveKind::$v, $feature)),*];
    };
}
declared_drives!(drive_kind_declarations);

kinds! {
    /// The schemes that advance the system in time.
    SchemeKind {
        /// The exact no-splitting scheme (GRW Section 3).
        NoSplitting = 0, "no-splitting", "";
        /// Euler splitting with time step `dt` (RW Algorithm 1).
        Euler = 1, "euler", "splitting";
        /// Strang splitting with time step `dt` (RW Algorithm 2).
        Strang = 2, "strang", "splitting";
        /// MS's time-stepped scheme (MS Section 3; Bird's no-time-counter form for the Maxwell
        /// and VHS kernels), step `step_factor` mean free paths over the thermal speed.
        TimeStepped = 3, "time-stepped", "time-stepped";
        /// The exact no-splitting scheme on weighted particles (Rjasanow and Wagner's SWPM): the
        /// tails resolved by many light particles, reductions keeping the number bounded.
        Weighted = 4, "weighted", "weighted";
    }
}

impl RestitutionLaw {
    /// Which law this is.
    #[must_use]
    pub const fn kind(&self) -> LawKind {
        match self {
            RestitutionLaw::Constant(_) => LawKind::Constant,
            RestitutionLaw::ImpactSpeed { .. } => LawKind::ImpactSpeed,
        }
    }
}

impl SchemeChoice {
    /// Which scheme this is.
    #[must_use]
    pub const fn kind(&self) -> SchemeKind {
        match self {
            SchemeChoice::NoSplitting => SchemeKind::NoSplitting,
            SchemeChoice::Euler(_) => SchemeKind::Euler,
            SchemeChoice::Strang(_) => SchemeKind::Strang,
            SchemeChoice::TimeStepped(_) => SchemeKind::TimeStepped,
            SchemeChoice::Weighted(_) => SchemeKind::Weighted,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Each kernel's declared parameters fit `kernel_params`, are named uniquely, apart from
    /// `gamma` and `c`, with defaults and examples that obey their rules.
    #[test]
    fn the_kernels_declarations_hold() {
        for &k in KernelKind::ALL {
            let params = k.params();
            assert_eq!(
                crate::declared::check_specs(params, crate::kernel::MAX_KERNEL_PARAMS),
                Ok(()),
                "{k:?}"
            );
            assert!(params.iter().all(|p| p.name != "gamma" && p.name != "c"));
            assert!(!k.title().is_empty());
        }
    }

    /// Checks each kernel of the table: where its declaration states a power law for its
    /// example values, the kernel built from them is that law (`Kernel::lambda`, and
    /// `Kernel::pair_rate` growing as the power).
    macro_rules! exponents_agree {
        ($($v:ident($code:literal, $scene:literal, $t:ty, $feature:literal, $doc:literal)),* $(,)?) => {
            $({
                let values: [Real; crate::kernel::MAX_KERNEL_PARAMS] =
                    crate::declared::examples(<$t as DeclaredKernel>::PARAMS);
                let k = <$t as DeclaredKernel>::from_values(1.0, 0.1, &values)
                    .expect("the example values build the kernel");
                // A declared power law is the built kernel's: its exponent, and its pair rate
                // growing as that power of the speed.
                if let Some(l) = <$t as DeclaredKernel>::exponent(&values) {
                    assert_eq!(crate::kernel::Kernel::lambda(&k), l, "{}", stringify!($v));
                    for u in [0.5, 2.0, 7.0] {
                        let ratio = crate::kernel::Kernel::pair_rate(&k, u)
                            / crate::kernel::Kernel::pair_rate(&k, 1.0);
                        let want = libm::pow(u, l);
                        assert!((ratio - want).abs() <= 1e-12 * want, "{}", stringify!($v));
                    }
                }
            })*
        };
    }

    /// A kernel's declared exponent (what the references read) is its built kernel's.
    #[test]
    fn each_kernels_declared_exponent_is_its_own() {
        kernel_table!(exponents_agree);
    }

    /// The declared drives' table and the kinds name the same features; each declared drive's
    /// parameters are at most `MAX_DRIVE_PARAMS`, named uniquely, with defaults that obey their
    /// rules.
    #[test]
    fn the_declared_drives_are_kinds() {
        for (k, feature) in DECLARED_ROWS {
            assert_eq!(k.feature(), *feature, "{k:?}");
            let params = k.params().expect("a declared drive has its parameters");
            assert_eq!(
                crate::declared::check_specs(params, crate::drive::MAX_DRIVE_PARAMS),
                Ok(()),
                "{k:?}"
            );
        }
        let irregular = DriveKind::ALL
            .iter()
            .filter(|k| k.params().is_none())
            .count();
        assert_eq!(irregular + DECLARED_ROWS.len(), DriveKind::ALL.len());
    }

    /// The codes are 0, 1, ... in order (the C header's enumerations), names and codes unique.
    #[test]
    fn codes_are_dense_and_names_unique() {
        fn check<K: Copy + PartialEq + core::fmt::Debug>(
            all: &[K],
            code: fn(K) -> u32,
            name: fn(K) -> &'static str,
            from_c: fn(u32) -> Option<K>,
            from_name: fn(&str) -> Option<K>,
        ) {
            for (i, &k) in all.iter().enumerate() {
                assert_eq!(code(k), i as u32, "{k:?}");
                assert_eq!(from_c(code(k)), Some(k));
                assert_eq!(from_name(name(k)), Some(k), "{k:?}: its name is another's");
            }
            assert_eq!(from_c(all.len() as u32), None);
            assert_eq!(from_name("no-such-kind"), None);
        }
        check(
            KernelKind::ALL,
            KernelKind::c_code,
            KernelKind::scene_name,
            KernelKind::from_c,
            KernelKind::from_scene_name,
        );
        check(
            LawKind::ALL,
            LawKind::c_code,
            LawKind::scene_name,
            LawKind::from_c,
            LawKind::from_scene_name,
        );
        check(
            DriveKind::ALL,
            DriveKind::c_code,
            DriveKind::scene_name,
            DriveKind::from_c,
            DriveKind::from_scene_name,
        );
        check(
            SchemeKind::ALL,
            SchemeKind::c_code,
            SchemeKind::scene_name,
            SchemeKind::from_c,
            SchemeKind::from_scene_name,
        );
    }
}
