//! The variants of each axis (kernel, restitution law, drive, scheme), declared once: a row
//! per variant with its word in a scene file, its C code and the cargo feature that builds its
//! engine.
//! Every front end takes them from here or is checked against them: the C ABI decodes its
//! integers with [`DriveKind::from_c`] and friends and matches the kinds exhaustively (no
//! catch-all arm, so a new variant does not compile until it is decoded), its `GDSMC_*`
//! constants are asserted equal to [`DriveKind::c_code`] at compile time, and the scene's
//! names, the fuzzer's words and the combination matrix are tested to hold every kind
//! ([`DriveKind::ALL`]). A choice tells its kind ([`DriveChoice::kind`]), matched exhaustively
//! too, so a variant of a choice without its row here does not compile.

use super::{DriveChoice, KernelChoice, RestitutionLaw, SchemeChoice};

/// Declares a kind enum: `Name of Choice { Variant = code, "scene-name", "feature"; ... }`.
macro_rules! kinds {
    ($(#[$m:meta])* $name:ident { $($(#[$vm:meta])* $v:ident = $code:literal, $scene:literal, $feature:literal;)+ }) => {
        $(#[$m])*
        #[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
        pub enum $name {
            $($(#[$vm])* $v,)+
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

kinds! {
    /// The collision kernels (GRW (2), (4), (5)).
    KernelKind {
        /// Maxwell pseudo-molecules (GRW (2)).
        Maxwell = 0, "maxwell", "maxwell";
        /// Hard spheres (hard disks in `d = 2`; GRW (4)).
        HardSpheres = 1, "hard-spheres", "hard-spheres";
        /// Variable hard spheres (GRW (5)).
        Vhs = 2, "vhs", "vhs";
    }
}

kinds! {
    /// The restitution laws (GRW (3), BRS (9)).
    LawKind {
        /// A constant coefficient alpha.
        Constant = 0, "restitution", "";
        /// The impact-speed law BRS (9)-(10).
        ImpactSpeed = 1, "impact_speed_law", "impact-speed";
    }
}

kinds! {
    /// The drives.
    DriveKind {
        /// None: the freely cooling gas.
        None = 0, "none", "cooling";
        /// White-noise heating (GRW (1), (18)).
        WhiteNoise = 1, "white-noise", "white-noise";
        /// A Maxwellian host medium (BRS Section 2).
        HostMedium = 2, "host-medium", "host-medium";
        /// The Gaussian thermostat (MS (12)).
        Gaussian = 3, "gaussian", "gaussian-thermostat";
        /// The constant force along the velocity (MS (14)).
        ConstantForce = 4, "constant-force", "constant-force";
    }
}

kinds! {
    /// The schemes that advance the system in time.
    SchemeKind {
        /// The exact no-splitting scheme (GRW Section 3).
        NoSplitting = 0, "no-splitting", "";
        /// Euler splitting (RW Algorithm 1).
        Euler = 1, "euler", "splitting";
        /// Strang splitting (RW Algorithm 2).
        Strang = 2, "strang", "splitting";
        /// MS's time-stepped scheme (MS Section 3).
        TimeStepped = 3, "time-stepped", "time-stepped";
    }
}

impl KernelChoice {
    /// Which kernel this is.
    #[must_use]
    pub const fn kind(&self) -> KernelKind {
        match self {
            KernelChoice::Maxwell { .. } => KernelKind::Maxwell,
            KernelChoice::HardSpheres { .. } => KernelKind::HardSpheres,
            KernelChoice::Vhs { .. } => KernelKind::Vhs,
        }
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

impl DriveChoice {
    /// Which drive this is.
    #[must_use]
    pub const fn kind(&self) -> DriveKind {
        match self {
            DriveChoice::None => DriveKind::None,
            DriveChoice::WhiteNoise(_) => DriveKind::WhiteNoise,
            DriveChoice::HostMedium { .. } => DriveKind::HostMedium,
            DriveChoice::Gaussian(_) => DriveKind::Gaussian,
            DriveChoice::ConstantForce(_) => DriveKind::ConstantForce,
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
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The kernel table's rows (`axes.rs`, from which the engine's kernel level is generated)
    /// as `(kind, feature)`.
    macro_rules! kernel_rows {
        ($($v:ident($t:ty, $f:literal, $d:literal)),+ $(,)?) => {
            &[$((KernelKind::$v, $f)),+]
        };
    }

    /// The engine's kernel table and the kinds name the same kernels with the same features.
    #[test]
    fn the_kernel_table_is_the_kinds() {
        let rows: &[(KernelKind, &str)] = super::super::axes::kernel_table!(kernel_rows);
        assert_eq!(rows.len(), KernelKind::ALL.len());
        for (k, feature) in rows {
            assert_eq!(k.feature(), *feature, "{k:?}");
        }
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
