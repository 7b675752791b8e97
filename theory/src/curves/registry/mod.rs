//! Every reference the runner knows, each declaring once the physics it holds for (particles,
//! kernel, restitution law, drive, scheme, dimension), what it is to a run (exact mean at n,
//! Boltzmann limit or approximation), the columns it gives and the words a scene's description
//! cites it by. [`for_scene`] attaches every reference whose declaration holds for the scene;
//! no reference is matched to a scene by hand. docs/combinations.md lists them per runnable
//! combination, and the tests hold each builder to its declaration (every combination it
//! declares gets its curves) and each shipped scene's description to what its run attaches.

pub use super::holds::{Drive, Holds, Kernels, Laws, Particles, Schemes};
use super::{Kind, ReferenceCurve, cooling, mixture, rough, single, sonine};
use gdsmc_core::physics::DriveKind;
use gdsmc_scene::Scene;

/// One reference: its declaration and the builder of its curves.
pub struct Reference {
    /// Its short name: paper and equation, or the authors.
    pub id: &'static str,
    /// What it is to a run's means (every curve it gives is of this kind).
    pub kind: Kind,
    /// The physics it holds for.
    pub holds: Holds,
    /// The names of the curves it may give (columns beside the observables).
    pub columns: &'static [&'static str],
    /// Further words a scene's description cites it by (its id and columns cite it too).
    pub cites: &'static [&'static str],
    /// Its curves for a scene its declaration holds for.
    pub curves: fn(&Scene) -> Vec<ReferenceCurve>,
}

impl Reference {
    /// Whether `scene`'s description cites it: its id, a column or one of its words.
    pub fn cited_by(&self, description: &str) -> bool {
        std::iter::once(self.id)
            .chain(self.columns.iter().copied())
            .chain(self.cites.iter().copied())
            .any(|w| cites(description, w))
    }
}

/// Whether `text` holds `word` not inside a longer name (`T_exact` is not `T_bulk_exact`'s).
pub fn cites(text: &str, word: &str) -> bool {
    let name = |c: char| c.is_alphanumeric() || c == '_';
    text.match_indices(word).any(|(i, _)| {
        let before = text[..i].chars().next_back();
        let after = text[i + word.len()..].chars().next();
        !before.is_some_and(name) && !after.is_some_and(name)
    })
}

const ANY_D: &[usize] = &[2, 3];
/// Every drive.
const ANY_DRIVE: &[Drive] = &[Drive::Any];
/// The drives that heat linearly: those that declare it (the core's
/// [`gdsmc_core::drive::Heating`]), not a list of kinds.
const LINEAR: &[Drive] = &[Drive::Linear];
/// The cooling state: a drive that only rescales the velocities (no drive, the Gaussian
/// thermostat, a drag: its steady state in reduced units, MS Section 2.2), as the drive
/// declares it.
const COOLING: &[Drive] = &[Drive::Rescaling];

/// A one-species smooth gas's axes with the constant restitution of the Sonine estimates.
const fn hard_smooth(drives: &'static [Drive], dimensions: &'static [usize]) -> Holds {
    Holds {
        particles: Particles::Smooth,
        kernels: Kernels::Hard,
        laws: Laws::Constant,
        drives,
        schemes: Schemes::Any,
        dimensions,
        when: None,
    }
}

/// The one-species smooth Maxwell gas in a Maxwell host medium (BRS (14)-(17)).
const MAXWELL_HOST: Holds = Holds {
    particles: Particles::SmoothTranslation,
    kernels: Kernels::MaxwellScattering,
    laws: Laws::Constant,
    drives: &[Drive::Is(DriveKind::HostMedium)],
    schemes: Schemes::Any,
    dimensions: ANY_D,
    when: Some("a Maxwell host medium"),
};

/// The one-species smooth Maxwell gas under a linearly heating drive (GRW (13)-(14)), run by
/// `schemes`.
const fn maxwell_linear(schemes: Schemes) -> Holds {
    Holds {
        particles: Particles::SmoothTranslation,
        kernels: Kernels::Maxwell,
        laws: Laws::Constant,
        drives: LINEAR,
        schemes,
        dimensions: ANY_D,
        when: None,
    }
}

/// The Maxwell gas's `a2(t)` in the Boltzmann limit, of the model's form `kernels`.
const fn maxwell_a2(kernels: Kernels) -> Holds {
    Holds {
        particles: Particles::SmoothTranslation,
        kernels,
        laws: Laws::Constant,
        drives: LINEAR,
        schemes: Schemes::Boltzmann,
        dimensions: ANY_D,
        when: None,
    }
}

/// A one-species smooth gas of kernels `kernels`, a constant coefficient, any drive and the
/// schemes `schemes` in d = 2 and 3, observing its cooling (`observe.collisional_pairs`).
const fn smooth_cooling(kernels: Kernels, schemes: Schemes) -> Holds {
    Holds {
        particles: Particles::Smooth,
        kernels,
        laws: Laws::Constant,
        drives: ANY_DRIVE,
        schemes,
        dimensions: ANY_D,
        when: Some("observe.collisional_pairs > 0"),
    }
}

/// Every reference, in the order of their columns.
pub const REFERENCES: &[Reference] = &[
    Reference {
        id: "Huthmann and Zippelius 1997",
        kind: Kind::Approximation,
        holds: Holds {
            particles: Particles::Rough,
            kernels: Kernels::PowerLaw,
            laws: Laws::Constant,
            drives: LINEAR,
            schemes: Schemes::Any,
            dimensions: ANY_D,
            when: None,
        },
        columns: &["T_bulk_MA", "T_rot_MA", "theta_MA"],
        cites: &["Haff's law", "Luding et al. 1998", "Megías and Santos 2019"],
        curves: rough::rough_curves,
    },
    Reference {
        id: "Haff's law",
        kind: Kind::Approximation,
        holds: Holds {
            particles: Particles::Smooth,
            kernels: Kernels::PositivePower,
            laws: Laws::Constant,
            drives: LINEAR,
            schemes: Schemes::Any,
            dimensions: ANY_D,
            when: None,
        },
        columns: &["T_bulk_sonine", "T_bulk_MA"],
        cites: &[],
        curves: sonine::curves,
    },
    Reference {
        id: "MS (5)",
        kind: Kind::Approximation,
        holds: hard_smooth(COOLING, ANY_D),
        columns: &["a2_sonine"],
        cites: &["van Noije and Ernst"],
        curves: sonine::a2_ms5,
    },
    Reference {
        id: "MS (40)",
        kind: Kind::Approximation,
        holds: hard_smooth(COOLING, ANY_D),
        columns: &["a2_ms40"],
        cites: &[],
        curves: sonine::a2_ms40,
    },
    Reference {
        id: "MS (10)",
        kind: Kind::Approximation,
        holds: hard_smooth(&[Drive::Is(DriveKind::WhiteNoise)], ANY_D),
        columns: &["a2_ms10"],
        cites: &[],
        curves: sonine::a2_ms10,
    },
    Reference {
        id: "MS (32)",
        kind: Kind::Approximation,
        holds: hard_smooth(&[Drive::Is(DriveKind::WhiteNoise)], ANY_D),
        columns: &["a2_ms32"],
        cites: &[],
        curves: sonine::a2_ms32,
    },
    Reference {
        id: "MS (50)",
        kind: Kind::Approximation,
        holds: hard_smooth(&[Drive::Is(DriveKind::ConstantForce)], ANY_D),
        columns: &["a2_ms50"],
        cites: &[],
        curves: sonine::a2_ms50,
    },
    Reference {
        id: "MS (76)",
        kind: Kind::Approximation,
        holds: hard_smooth(&[Drive::Is(DriveKind::ConstantForce)], &[3]),
        columns: &["a2_ms76"],
        cites: &[],
        curves: sonine::a2_ms76,
    },
    Reference {
        id: "Bobylev, Carrillo and Gamba 2000",
        kind: Kind::Limit,
        holds: maxwell_a2(Kernels::MaxwellScattering),
        columns: &["a2_exact"],
        cites: &[],
        curves: single::a2_exact,
    },
    Reference {
        id: "the impact form's a2 (Ernst and Brito 2002; Santos 2003)",
        kind: Kind::Limit,
        holds: maxwell_a2(Kernels::MaxwellImpact),
        columns: &["a2_exact"],
        cites: &["Santos 2003"],
        curves: single::a2_exact,
    },
    Reference {
        id: "BRS (21), (22)",
        kind: Kind::Approximation,
        holds: Holds {
            particles: Particles::SmoothTranslation,
            kernels: Kernels::Hard,
            laws: Laws::Constant,
            drives: &[Drive::Is(DriveKind::HostMedium)],
            schemes: Schemes::Any,
            dimensions: &[3],
            when: Some("a hard-sphere host medium"),
        },
        columns: &[
            "T_bulk_hydro21",
            "V_y_hydro21",
            "T_bulk_hydro22",
            "V_y_hydro22",
        ],
        cites: &["BRS (21)", "BRS (22)"],
        curves: single::brs_hydro,
    },
    Reference {
        id: "BRS (14)",
        kind: Kind::MeanAtN,
        holds: MAXWELL_HOST,
        columns: &["V_x_exact", "V_y_exact", "V_z_exact"],
        cites: &[],
        curves: single::brs_bulk,
    },
    Reference {
        id: "BRS (15)-(17)",
        kind: Kind::Limit,
        holds: MAXWELL_HOST,
        columns: &["T_bulk_exact"],
        cites: &["BRS (15)", "BRS (37)-(38)"],
        curves: single::brs_temperature,
    },
    Reference {
        id: "GRW (13)-(14)",
        kind: Kind::Limit,
        holds: maxwell_linear(Schemes::Any),
        columns: &["T_exact", "T_bulk_exact"],
        cites: &["GRW (13)"],
        curves: single::grw_limit,
    },
    Reference {
        id: "GRW (13)-(14) at finite n",
        kind: Kind::MeanAtN,
        holds: maxwell_linear(Schemes::ExactMeans),
        columns: &["T_mean_n", "T_bulk_mean_n"],
        cites: &[],
        curves: single::grw_mean_at_n,
    },
    Reference {
        id: "GRW (13)-(14) at finite weight",
        kind: Kind::MeanAtN,
        // Where the drive adds no heat of its own (docs/weighted.md).
        holds: Holds {
            drives: COOLING,
            ..maxwell_linear(Schemes::Weighted)
        },
        columns: &["T_mean_n", "T_bulk_mean_n"],
        cites: &[],
        curves: single::grw_mean_at_n,
    },
    Reference {
        id: "Garzó and Dufty 1999",
        kind: Kind::Approximation,
        holds: Holds {
            particles: Particles::SmoothMixture,
            kernels: Kernels::PowerLaw,
            laws: Laws::Constant,
            drives: &[Drive::Rescaling, Drive::Is(DriveKind::WhiteNoise)],
            schemes: Schemes::Any,
            dimensions: &[3],
            when: None,
        },
        columns: &[
            "T_s0_ratio_MA",
            "T_s1_ratio_MA",
            "T_s2_ratio_MA",
            "T_s3_ratio_MA",
        ],
        cites: &[],
        curves: mixture::garzo_dufty_curves,
    },
    Reference {
        id: "Maxwell mixture's moments at finite n",
        kind: Kind::MeanAtN,
        holds: Holds {
            particles: Particles::SmoothMixture,
            kernels: Kernels::MaxwellScattering,
            laws: Laws::Constant,
            drives: &[Drive::Free, Drive::Is(DriveKind::WhiteNoise)],
            schemes: Schemes::ExactMeans,
            dimensions: &[3],
            when: None,
        },
        columns: &[
            "T_s0_mean_n",
            "T_s1_mean_n",
            "T_s2_mean_n",
            "T_s3_mean_n",
            "T_mix_mean_n",
        ],
        cites: &[],
        curves: mixture::maxwell_mixture_means,
    },
    Reference {
        id: "Maxwell mixture's moments",
        kind: Kind::Limit,
        holds: Holds {
            particles: Particles::SmoothMixture,
            kernels: Kernels::MaxwellScattering,
            laws: Laws::Constant,
            drives: &[Drive::Free, Drive::Is(DriveKind::WhiteNoise)],
            schemes: Schemes::Any,
            dimensions: &[3],
            when: None,
        },
        columns: &[
            "T_s0_ratio_limit",
            "T_s1_ratio_limit",
            "T_s2_ratio_limit",
            "T_s3_ratio_limit",
        ],
        cites: &[],
        curves: mixture::maxwell_mixture_limits,
    },
    Reference {
        id: "Santos, Kremer and Garzó 2010",
        kind: Kind::Approximation,
        holds: Holds {
            particles: Particles::RoughMixture,
            kernels: Kernels::PowerLaw,
            laws: Laws::Constant,
            drives: &[Drive::Free, Drive::Is(DriveKind::WhiteNoise)],
            schemes: Schemes::Any,
            dimensions: ANY_D,
            when: None,
        },
        columns: &[
            "T_s0_ratio_MA",
            "T_s1_ratio_MA",
            "T_s2_ratio_MA",
            "T_s3_ratio_MA",
            "theta_s0_MA",
            "theta_s1_MA",
            "theta_s2_MA",
            "theta_s3_MA",
        ],
        cites: &["Megías and Santos 2019"],
        curves: mixture::rough_mixture_curves,
    },
    Reference {
        id: "zeta* of the Maxwell kernel",
        kind: Kind::MeanAtN,
        // Equal weights: `n/(n - 1)` is their `W^2/(W^2 - sum g^2)` (core/tests/weighted.rs).
        holds: smooth_cooling(Kernels::Maxwell, Schemes::EqualWeights),
        columns: &["zeta_star_exact"],
        cites: &[],
        curves: cooling::maxwell,
    },
    Reference {
        id: "zeta* = zeta/nu_0 to first Sonine order",
        kind: Kind::Approximation,
        holds: Holds {
            drives: &[Drive::Rescaling, Drive::Is(DriveKind::WhiteNoise)],
            ..smooth_cooling(Kernels::Hard, Schemes::Any)
        },
        columns: &["zeta_star_nu0_sonine"],
        cites: &[],
        curves: cooling::literature_sonine,
    },
    Reference {
        id: "zeta* of hard particles at a Maxwellian",
        kind: Kind::Approximation,
        holds: smooth_cooling(Kernels::Hard, Schemes::Any),
        columns: &["zeta_star_MA"],
        cites: &[],
        curves: cooling::hard_maxwellian,
    },
];

/// The references whose declaration holds for `scene` (their `when` aside).
pub fn applicable(scene: &Scene) -> impl Iterator<Item = &'static Reference> + '_ {
    REFERENCES.iter().filter(|r| r.holds.of(scene))
}

/// Every reference curve that applies to `scene`: the curves of each reference whose
/// declaration holds for it.
pub fn for_scene(scene: &Scene) -> Vec<ReferenceCurve> {
    applicable(scene).flat_map(|r| (r.curves)(scene)).collect()
}

#[cfg(test)]
mod tests;
