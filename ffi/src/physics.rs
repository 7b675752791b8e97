//! gdsmc_config and the core's physics description, both ways. The C struct carries integers
//! for its enumerations; they are checked here (an ABI rule), and every physical rule is left
//! to [`Physics::validate`], whose message is passed on with the C field's name, the same
//! words the command prints for the same bad value.

use crate::config::*;
use crate::status::{Failure, Msg, fail, gdsmc_status, msg};
use gdsmc_core::physics::{
    BackgroundKernel, Component, DimensionChoice, DriveChoice, DriveKind, KernelChoice, KernelKind,
    LawKind, Model, Momentum, Param, Physics, PhysicsError, RestitutionLaw, RotationChoice,
    SchemeChoice, SchemeKind, SpeciesChoice,
};

// The C header's codes are generated from the core's kinds (`src/codes.rs`, checked by
// ffi/tests/kinds.rs, which also checks that every kind has its constant in include/gdsmc.h).

fn invalid<T>(m: Msg) -> Result<T, Failure> {
    fail(gdsmc_status::GDSMC_INVALID_ARGUMENT, m)
}

/// An enumeration field: the core's kind of its C code (`gdsmc_core::physics::DriveKind` and
/// its siblings declare the codes), or an error naming the field.
fn decode<K>(
    value: u32,
    of: fn(u32) -> Option<K>,
    field: &str,
    family: &str,
) -> Result<K, Failure> {
    of(value).map_or_else(
        || {
            invalid(msg!(
                "config.{field} = {value} is not a GDSMC_{family}_* value"
            ))
        },
        Ok,
    )
}

/// The C field that holds a physics parameter.
fn field(p: Param) -> &'static str {
    match p {
        Param::N => "n",
        Param::Components | Param::Weight(_) | Param::Mass(_) => "mass",
        Param::Temperature(_) => "temperature",
        Param::Drift(_) => "drift",
        Param::Gamma => "gamma",
        Param::C => "c",
        Param::Kernel(..) => "kernel_params",
        Param::Law(LawKind::Constant, _) => "restitution",
        Param::Law(LawKind::ImpactSpeed, 0) => "impact_beta0",
        Param::Law(LawKind::ImpactSpeed, _) => "impact_delta",
        Param::Beta => "beta",
        Param::Drive(..) => "drive_params",
        Param::BackgroundC => "background_c",
        Param::BackgroundDensity => "background_density",
        Param::BackgroundMass => "background_mass",
        Param::BackgroundTemperature => "background_temperature",
        Param::BackgroundDrift => "background_drift",
        Param::Step(SchemeKind::Euler | SchemeKind::Strang, _) => "dt",
        Param::Step(SchemeKind::TimeStepped, _) => "step_factor",
        Param::Step(SchemeKind::Weighted, _) => "scheme_params",
        Param::Step(SchemeKind::NoSplitting, _) => "scheme",
        Param::Scheme => "scheme",
        Param::Species => "species",
        Param::SpeciesCount(_) => "species_count",
        Param::SpeciesMass(_) => "species_mass",
        Param::SpeciesTemperature(_) => "species_temperature",
        Param::SpeciesDiameter(_) => "species_diameter",
        Param::SpeciesBeta(_) => "species_beta",
        Param::PairRestitution(..) => "pair_restitution",
        Param::SpeciesInertia(_) => "species_inertia",
        Param::SpeciesRotationTemperature(_) => "species_rotation_temperature",
        Param::SpeciesRotationNoise(_) => "species_rotation_noise",
        Param::PairTangentialRestitution(..) => "pair_tangential_restitution",
        Param::Rotation => "rough",
        Param::TangentialRestitution => "tangential_restitution",
        Param::Inertia => "inertia",
        Param::RotationTemperature => "rotation_temperature",
        Param::RotationNoise => "rotation_noise",
        Param::Dimension => "dimension",
    }
}

/// The index of an array field that holds a parameter: the species, or the pair's entry.
fn index(p: Param, species: usize) -> Option<usize> {
    match p {
        Param::SpeciesCount(k)
        | Param::SpeciesMass(k)
        | Param::SpeciesTemperature(k)
        | Param::SpeciesDiameter(k)
        | Param::SpeciesBeta(k)
        | Param::SpeciesInertia(k)
        | Param::SpeciesRotationTemperature(k)
        | Param::SpeciesRotationNoise(k) => Some(k),
        Param::Drive(_, i) | Param::Kernel(_, i) | Param::Step(SchemeKind::Weighted, i) => Some(i),
        Param::PairRestitution(s, t) | Param::PairTangentialRestitution(s, t) => {
            Some(gdsmc_core::mixture::pair_index(species, s, t))
        }
        _ => None,
    }
}

/// The core's verdict, with the C field's name: `config.restitution must lie in (0, 1], ...`,
/// `config.species_mass[1] must be > 0, ...`.
pub(crate) fn physics_failure(e: PhysicsError, species: usize) -> Failure {
    let name = match index(e.param, species) {
        Some(k) => msg!("{}[{k}]", field(e.param)),
        None => msg!("{}", field(e.param)),
    };
    Failure(
        gdsmc_status::GDSMC_INVALID_ARGUMENT,
        msg!("config.{name} {}", e.problem),
    )
}

impl gdsmc_config {
    /// The physics this configuration describes (enumeration integers checked).
    pub(crate) fn physics(&self) -> Result<Physics, Failure> {
        let kernel_kind = decode(self.kernel, KernelKind::from_c, "kernel", "KERNEL")?;
        let drive_kind = decode(self.drive, DriveKind::from_c, "drive", "DRIVE")?;
        let scheme_kind = decode(self.scheme, SchemeKind::from_c, "scheme", "SCHEME")?;
        let law_kind = decode(
            self.restitution_law,
            LawKind::from_c,
            "restitution_law",
            "RESTITUTION",
        )?;
        let Ok(n) = usize::try_from(self.n) else {
            return invalid(msg!("config.n = {} is too large", self.n));
        };
        // Every kernel is declared by its type: its parameters from `kernel_params` in its
        // order (`GDSMC_MAX_KERNEL_PARAMS` holds the most any kernel has).
        let Some(kernel) = KernelChoice::new(kernel_kind, self.gamma, self.c, &self.kernel_params)
        else {
            return invalid(msg!(
                "config.kernel = {} has more parameters than kernel_params holds",
                self.kernel
            ));
        };
        // Every match below names every kind (no catch-all): a new kind does not compile until
        // it is decoded here.
        let restitution = match law_kind {
            LawKind::Constant => RestitutionLaw::Constant(self.restitution),
            LawKind::ImpactSpeed => RestitutionLaw::ImpactSpeed {
                beta0: self.impact_beta0,
                delta: self.impact_delta,
            },
        };
        let drive = match drive_kind {
            DriveKind::None => DriveChoice::None,
            DriveKind::WhiteNoise => DriveChoice::WhiteNoise(self.beta),
            DriveKind::HostMedium => DriveChoice::HostMedium {
                kernel: match self.background_kernel {
                    GDSMC_BACKGROUND_MAXWELL => BackgroundKernel::Maxwell,
                    GDSMC_BACKGROUND_HARD_SPHERES => BackgroundKernel::HardSpheres,
                    other => {
                        return invalid(msg!(
                            "config.background_kernel = {other} is not a GDSMC_BACKGROUND_* value"
                        ));
                    }
                },
                c1: self.background_c,
                density: self.background_density,
                mass: self.background_mass,
                temperature: self.background_temperature,
                drift: self.background_drift,
            },
            // A drive declared by its type: its parameters from `drive_params` in its order.
            declared => match DriveChoice::declared(declared, &self.drive_params) {
                Some(d) => d,
                None => {
                    return invalid(msg!(
                        "config.drive = {} has no parameters in drive_params",
                        self.drive
                    ));
                }
            },
        };
        let scheme = match scheme_kind {
            SchemeKind::NoSplitting => SchemeChoice::NoSplitting,
            SchemeKind::Euler => SchemeChoice::Euler(self.dt),
            SchemeKind::Strang => SchemeChoice::Strang(self.dt),
            SchemeKind::TimeStepped => SchemeChoice::TimeStepped(self.step_factor),
            SchemeKind::Weighted => SchemeChoice::new(SchemeKind::Weighted, &self.scheme_params)
                .ok_or_else(|| {
                    Failure(
                        gdsmc_status::GDSMC_INVALID_ARGUMENT,
                        msg!("config.scheme = GDSMC_SCHEME_WEIGHTED needs feature `weighted`"),
                    )
                })?,
        };
        let mut physics = Physics::new(n, kernel, restitution, drive, scheme);
        physics.initial[0] = Component {
            weight: 1.0,
            mass: self.mass,
            temperature: self.temperature,
            drift: self.drift,
        };
        self.mixture(&mut physics)?;
        physics.dimension = match self.dimension {
            3 => DimensionChoice::Three,
            2 => DimensionChoice::Two,
            d => {
                return invalid(msg!(
                    "config.dimension must be 2 (disks) or 3 (spheres), got {d}"
                ));
            }
        };
        physics.momentum = if self.exact_momentum != 0 {
            Momentum::Exact
        } else {
            Momentum::Drawn
        };
        if self.rough != 0 {
            physics.rotation = Some(RotationChoice {
                beta: self.tangential_restitution,
                kappa: self.inertia,
                temperature: self.rotation_temperature,
                noise: self.rotation_noise,
            });
        }
        Ok(physics)
    }

    /// A mixture's species and pair restitution into `physics` (nothing for `species = 0`).
    fn mixture(&self, physics: &mut Physics) -> Result<(), Failure> {
        let s = self.species as usize;
        if s > GDSMC_MAX_SPECIES {
            return invalid(msg!(
                "config.species = {} is more than GDSMC_MAX_SPECIES = {GDSMC_MAX_SPECIES}",
                self.species
            ));
        }
        let mut total: u64 = 0;
        // A species' own rotation only where there is one (the core refuses it otherwise).
        let own = self.rough != 0 && self.species_rotation_set != 0;
        for k in 0..s {
            let Ok(count) = usize::try_from(self.species_count[k]) else {
                return invalid(msg!("config.species_count[{k}] is too large"));
            };
            total = total.saturating_add(self.species_count[k]);
            // Capacity GDSMC_MAX_SPECIES = MAX_SPECIES: cannot fail.
            let _ = physics.species.push(SpeciesChoice {
                count,
                mass: self.species_mass[k],
                temperature: self.species_temperature[k],
                diameter: self.species_diameter[k],
                beta: self.species_beta[k],
                inertia: own.then_some(self.species_inertia[k]),
                rotation_temperature: own.then_some(self.species_rotation_temperature[k]),
                rotation_noise: own.then_some(self.species_rotation_noise[k]),
            });
            if count == 0 {
                return invalid(msg!("config.species_count[{k}] must be >= 1, got 0"));
            }
        }
        if s > 0 && total != self.n {
            return invalid(msg!(
                "config.n = {} must equal the sum of config.species_count, {total}",
                self.n
            ));
        }
        if s > 0 && self.pair_restitution_set != 0 {
            physics.restitution = RestitutionLaw::Constant(1.0);
            for &alpha in &self.pair_restitution[..s * (s + 1) / 2] {
                let _ = physics.pair_restitution.push(alpha);
            }
        }
        if s > 0 && self.rough != 0 && self.pair_tangential_restitution_set != 0 {
            for &beta in &self.pair_tangential_restitution[..s * (s + 1) / 2] {
                let _ = physics.pair_tangential_restitution.push(beta);
            }
        }
        Ok(())
    }

    /// The validated model of this configuration.
    pub(crate) fn model(&self) -> Result<Model, Failure> {
        self.physics()?
            .validate()
            .map_err(|e| physics_failure(e, self.species as usize))
    }

    /// The configuration of a physics (seed 1, stream 0; fields it does not use keep the
    /// defaults of [`gdsmc_config::example3`]). A mixture of Maxwellians cannot be expressed.
    #[cfg(feature = "std")]
    pub(crate) fn from_physics(p: &Physics) -> Result<Self, Failure> {
        let mut cfg = Self::from_one_species(p)?;
        cfg.species = p.species.len() as u32;
        for (k, s) in p.species.iter().enumerate() {
            cfg.species_count[k] = s.count as u64;
            cfg.species_mass[k] = s.mass;
            cfg.species_temperature[k] = s.temperature;
            cfg.species_diameter[k] = s.diameter;
            cfg.species_beta[k] = s.beta;
        }
        cfg.dimension = p.dimension.d() as u32;
        cfg.exact_momentum = u32::from(p.momentum == Momentum::Exact);
        if let Some(r) = p.rotation {
            cfg.rough = 1;
            cfg.tangential_restitution = r.beta;
            cfg.inertia = r.kappa;
            cfg.rotation_temperature = r.temperature;
            cfg.rotation_noise = r.noise;
            // A species without its own value takes the rotation's: the same physics.
            for (k, s) in p.species.iter().enumerate() {
                cfg.species_inertia[k] = s.inertia.unwrap_or(r.kappa);
                cfg.species_rotation_temperature[k] =
                    s.rotation_temperature.unwrap_or(r.temperature);
                cfg.species_rotation_noise[k] = s.rotation_noise.unwrap_or(r.noise);
            }
            cfg.species_rotation_set = p.species.iter().any(|s| {
                s.inertia.is_some()
                    || s.rotation_temperature.is_some()
                    || s.rotation_noise.is_some()
            }) as u32;
        }
        if !p.pair_tangential_restitution.is_empty() {
            cfg.pair_tangential_restitution_set = 1;
            cfg.pair_tangential_restitution[..p.pair_tangential_restitution.len()]
                .copy_from_slice(&p.pair_tangential_restitution);
        }
        if !p.pair_restitution.is_empty() {
            cfg.pair_restitution_set = 1;
            cfg.pair_restitution[..p.pair_restitution.len()].copy_from_slice(&p.pair_restitution);
        }
        Ok(cfg)
    }

    /// [`gdsmc_config::from_physics`] without the species.
    #[cfg(feature = "std")]
    fn from_one_species(p: &Physics) -> Result<Self, Failure> {
        let [only] = p.initial[..] else {
            return invalid(msg!(
                "<toml>: `particles.initial` must be a single Maxwellian for gdsmc_config"
            ));
        };
        let mut cfg = gdsmc_config {
            n: p.n as u64,
            mass: only.mass,
            temperature: only.temperature,
            drift: only.drift,
            beta: 0.0,
            ..gdsmc_config::example3()
        };
        // The codes from the kinds; the parameters by variant (every match exhaustive).
        cfg.kernel = p.kernel.kind().c_code();
        cfg.restitution_law = p.restitution.kind().c_code();
        cfg.drive = p.drive.kind().c_code();
        cfg.scheme = p.scheme.kind().c_code();
        (cfg.gamma, cfg.c) = (p.kernel.gamma(), p.kernel.c());
        cfg.kernel_params[..p.kernel.values().len()].copy_from_slice(p.kernel.values());
        match p.restitution {
            RestitutionLaw::Constant(alpha) => cfg.restitution = alpha,
            RestitutionLaw::ImpactSpeed { beta0, delta } => {
                (cfg.impact_beta0, cfg.impact_delta) = (beta0, delta);
            }
        }
        match p.drive {
            DriveChoice::None => {}
            DriveChoice::WhiteNoise(b) => cfg.beta = b,
            DriveChoice::Declared(d) => {
                cfg.drive_params[..d.values().len()].copy_from_slice(d.values());
            }
            DriveChoice::HostMedium {
                kernel,
                c1,
                density,
                mass,
                temperature,
                drift,
            } => {
                cfg.background_kernel = match kernel {
                    BackgroundKernel::Maxwell => GDSMC_BACKGROUND_MAXWELL,
                    BackgroundKernel::HardSpheres => GDSMC_BACKGROUND_HARD_SPHERES,
                };
                cfg.background_c = c1;
                cfg.background_density = density;
                cfg.background_mass = mass;
                cfg.background_temperature = temperature;
                cfg.background_drift = drift;
            }
        }
        match p.scheme {
            SchemeChoice::NoSplitting => {}
            SchemeChoice::Euler(dt) | SchemeChoice::Strang(dt) => cfg.dt = dt,
            SchemeChoice::TimeStepped(f) => cfg.step_factor = f,
            SchemeChoice::Weighted(v) => cfg.scheme_params = v,
        }
        Ok(cfg)
    }
}
