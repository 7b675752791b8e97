//! Configuration: a plain C struct with a defaults function, or a scene given as TOML text.

use crate::codes::*;
use crate::guard::{check_ptr, guard};
use crate::status::gdsmc_status;

/// Host-medium kernel `B_1 = C_1` (BRS (11)).
pub const GDSMC_BACKGROUND_MAXWELL: u32 = 0;
/// Host-medium kernel `B_1 = C_1 |g|` (BRS (19)).
pub const GDSMC_BACKGROUND_HARD_SPHERES: u32 = 1;

/// Everything a simulation needs. Fill it with gdsmc_config_default (GRW Example 3) or
/// gdsmc_config_from_toml, then change fields. Enumerations are plain integers
/// (`GDSMC_KERNEL_*`, `GDSMC_DRIVE_*`, `GDSMC_SCHEME_*`) checked on use.
#[repr(C)]
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct gdsmc_config {
    /// Number of particles, >= 2.
    pub n: u64,
    /// Seed of the Xoshiro256++ generator.
    pub seed: u64,
    /// Stream: the seed's generator is jumped this many times (2^128 draws each), so streams
    /// 0, 1, 2, ... of one seed are independent ensembles, exactly those of `gdsmc run`. At
    /// most GDSMC_MAX_STREAM (stream k costs k jumps).
    pub stream: u64,
    /// One of `GDSMC_KERNEL_*`.
    pub kernel: u32,
    /// One of `GDSMC_DRIVE_*`.
    pub drive: u32,
    /// One of `GDSMC_SCHEME_*`.
    pub scheme: u32,
    /// One of `GDSMC_RESTITUTION_*`.
    pub restitution_law: u32,
    /// Collision-rate constant gamma of GRW (1), > 0.
    pub gamma: f64,
    /// Kernel constant C_lambda, > 0.
    pub c: f64,
    /// The kernel's parameters beyond gamma and C, in its order (GDSMC_KERNEL_VHS:
    /// `kernel_params[GDSMC_VHS_LAMBDA]`, the exponent in [0, 1]); the rest unused.
    pub kernel_params: [f64; GDSMC_MAX_KERNEL_PARAMS],
    /// Restitution coefficient alpha in (0, 1] (GDSMC_RESTITUTION_CONSTANT only).
    pub restitution: f64,
    /// `beta_0 >= 0` of the impact-speed law (GDSMC_RESTITUTION_IMPACT_SPEED only).
    pub impact_beta0: f64,
    /// `delta >= 0` of the impact-speed law (GDSMC_RESTITUTION_IMPACT_SPEED only; 1/5:
    /// viscoelastic spheres).
    pub impact_delta: f64,
    /// White-noise strength beta >= 0 (used with GDSMC_DRIVE_WHITE_NOISE only).
    pub beta: f64,
    /// The parameters of a drive declared by its type, in its order (GDSMC_DRIVE_GAUSSIAN,
    /// GDSMC_DRIVE_CONSTANT_FORCE, GDSMC_DRIVE_LANGEVIN, ...: `GDSMC_<DRIVE>_<PARAMETER>` is
    /// each one's place, e.g. `drive_params[GDSMC_LANGEVIN_FRICTION]`); the rest unused.
    pub drive_params: [f64; GDSMC_MAX_DRIVE_PARAMS],
    /// Mass of the initial Maxwellian, > 0.
    pub mass: f64,
    /// Temperature of the initial Maxwellian, >= 0.
    pub temperature: f64,
    /// Drift velocity of the initial Maxwellian.
    pub drift: [f64; 3],
    /// Time step of the splitting schemes, > 0; times passed to gdsmc_sim_advance must be
    /// multiples of it. Used by GDSMC_SCHEME_EULER and GDSMC_SCHEME_STRANG only.
    pub dt: f64,
    /// Step factor of GDSMC_SCHEME_TIME_STEPPED, > 0: `h = step_factor lambda / v0` (MS: 0.01).
    pub step_factor: f64,
    /// Host medium (GDSMC_DRIVE_HOST_MEDIUM): one of `GDSMC_BACKGROUND_*`.
    pub background_kernel: u32,
    /// Host medium: kernel constant C_1 > 0.
    pub background_c: f64,
    /// Host medium: number density rho^B > 0.
    pub background_density: f64,
    /// Host medium: background particle mass m^B > 0 (grains have unit mass).
    pub background_mass: f64,
    /// Host medium: background temperature T^B >= 0.
    pub background_temperature: f64,
    /// Host medium: background drift u^B.
    pub background_drift: [f64; 3],
    /// Species of a granular mixture: 0 for one species (the gas above), else 1 to
    /// GDSMC_MAX_SPECIES (Garzó and Dufty 1999). With species, their counts add up to `n`,
    /// each starts from a Maxwellian at rest at its own temperature (mass, temperature and
    /// drift above are not used), the drive is none or white noise (each species its own
    /// `species_beta`), the scheme no splitting and the restitution constant.
    pub species: u32,
    /// Particles of each species (>= 1 each; they add up to `n`).
    pub species_count: [u64; GDSMC_MAX_SPECIES],
    /// Mass of each species (> 0).
    pub species_mass: [f64; GDSMC_MAX_SPECIES],
    /// Start temperature of each species (>= 0).
    pub species_temperature: [f64; GDSMC_MAX_SPECIES],
    /// Diameter of each species (> 0): the pair (s, t) collides with `c ((d_s + d_t)/2)^2`.
    pub species_diameter: [f64; GDSMC_MAX_SPECIES],
    /// White-noise strength of each species (>= 0; with GDSMC_DRIVE_WHITE_NOISE).
    pub species_beta: [f64; GDSMC_MAX_SPECIES],
    /// Nonzero: `pair_restitution` holds the restitution of every species pair; 0: every pair
    /// has `restitution`.
    pub pair_restitution_set: u32,
    /// Restitution of each species pair (s, t), s <= t, in the order (0,0), (0,1), ..,
    /// (0,S-1), (1,1), ..: the first S (S + 1)/2 entries are used.
    pub pair_restitution: [f64; GDSMC_MAX_PAIRS],
    /// Nonzero: rough particles (Huthmann and Zippelius 1997): each has a rim velocity
    /// `w = (sigma/2) omega` beside its velocity, and `restitution` is the normal restitution.
    /// The drive is none or white noise, the scheme no splitting, the restitution constant.
    /// With species, a rough mixture: every species and pair takes the values below unless
    /// `species_rotation_set` and `pair_tangential_restitution_set` give their own. A caller
    /// buffer needs room for the spins: gdsmc_config_footprint.
    pub rough: u32,
    /// Rough particles: tangential restitution beta in [-1, 1] (-1: smooth, rotation untouched;
    /// 1: perfectly rough).
    pub tangential_restitution: f64,
    /// Rough particles: reduced moment of inertia `kappa = 4 I/(m sigma^2)` in (0, 2/3] (2/5:
    /// uniform spheres).
    pub inertia: f64,
    /// Rough particles: start rotational temperature >= 0.
    pub rotation_temperature: f64,
    /// Rough particles: white-noise strength on rotation >= 0 (`dT_rot/dt = 2 rotation_noise`
    /// from it alone).
    pub rotation_noise: f64,
    /// A rough mixture: nonzero, each species takes its own `species_inertia`,
    /// `species_rotation_temperature` and `species_rotation_noise`; 0: every species takes
    /// `inertia`, `rotation_temperature` and `rotation_noise`.
    pub species_rotation_set: u32,
    /// A rough mixture: each species' reduced moment of inertia (as `inertia`).
    pub species_inertia: [f64; GDSMC_MAX_SPECIES],
    /// A rough mixture: each species' start rotational temperature (>= 0).
    pub species_rotation_temperature: [f64; GDSMC_MAX_SPECIES],
    /// A rough mixture: each species' white noise on rotation (>= 0; `dT_rot,s/dt =
    /// 2 m_s species_rotation_noise[s]` from it alone).
    pub species_rotation_noise: [f64; GDSMC_MAX_SPECIES],
    /// A rough mixture: nonzero, `pair_tangential_restitution` holds the tangential
    /// restitution of every species pair; 0: every pair has `tangential_restitution`.
    pub pair_tangential_restitution_set: u32,
    /// Tangential restitution of each species pair (s, t), s <= t, in `pair_restitution`'s
    /// order: the first S (S + 1)/2 entries are used.
    pub pair_tangential_restitution: [f64; GDSMC_MAX_PAIRS],
    /// The dimension: 3 (spheres, the default) or 2 (disks: velocities in the (x, y) plane,
    /// `z` components zero; a rough disk's rim velocity along z, `inertia` in (0, 1], 1/2 for
    /// uniform disks). Disks take the schemes, laws and drives spheres take (MS's time-stepped
    /// scheme: one species), one species or a mixture, with the start and
    /// background drifts in the plane.
    pub dimension: u32,
    /// Nonzero: the sample's mean velocity (each species') starts at the distribution's
    /// exactly, the draws shifted onto it (zero total momentum about the drift); 0: `n`
    /// independent draws (the default, GRW (27), which GRW's finite-n means assume).
    pub exact_momentum: u32,
    /// The parameters of GDSMC_SCHEME_WEIGHTED in its order (`GDSMC_WEIGHTED_<PARAMETER>` is
    /// each one's place, e.g. `scheme_params[GDSMC_WEIGHTED_SPLIT]`; the defaults are the
    /// scene's); the other schemes' are `dt` and `step_factor`.
    pub scheme_params: [f64; GDSMC_MAX_SCHEME_PARAMS],
}

/// Most species a mixture may have (the core's `mixture::MAX_SPECIES`, written out for the
/// header).
pub const GDSMC_MAX_SPECIES: usize = 4;

/// Most species pairs, `GDSMC_MAX_SPECIES (GDSMC_MAX_SPECIES + 1) / 2`.
pub const GDSMC_MAX_PAIRS: usize = 10;

const _: () = assert!(
    GDSMC_MAX_SPECIES == gdsmc_core::mixture::MAX_SPECIES
        && GDSMC_MAX_PAIRS == gdsmc_core::mixture::MAX_PAIRS
);

/// The core's defaults of a rough gas (uniform spheres, `T_rot` 1, no noise on rotation) with
/// tangential restitution -1: switching `rough` on alone gives the smooth gas with spins.
const SMOOTH: gdsmc_core::physics::RotationChoice =
    gdsmc_core::physics::RotationChoice::spheres(-1.0);

/// The weighted scheme's declared defaults in `scheme_params`' order (zeros in a build
/// without it).
fn scheme_defaults() -> [f64; GDSMC_MAX_SCHEME_PARAMS] {
    let mut v = [0.0; GDSMC_MAX_SCHEME_PARAMS];
    let params = gdsmc_core::physics::SchemeKind::Weighted.params();
    for (x, p) in v.iter_mut().zip(params) {
        *x = p.default.unwrap_or(p.example);
    }
    v
}

impl gdsmc_config {
    /// GRW Example 3 with 1024 particles.
    pub fn example3() -> Self {
        gdsmc_config {
            n: 1024,
            seed: 1,
            stream: 0,
            kernel: GDSMC_KERNEL_MAXWELL,
            drive: GDSMC_DRIVE_WHITE_NOISE,
            scheme: GDSMC_SCHEME_NO_SPLITTING,
            restitution_law: GDSMC_RESTITUTION_CONSTANT,
            gamma: 4.0,
            c: 1.0 / (4.0 * core::f64::consts::PI),
            kernel_params: [0.0; GDSMC_MAX_KERNEL_PARAMS],
            restitution: 0.5,
            impact_beta0: 0.0,
            impact_delta: 0.0,
            beta: 1.0,
            drive_params: [0.0; GDSMC_MAX_DRIVE_PARAMS],
            mass: 1.0,
            temperature: 1.0,
            drift: [0.0; 3],
            dt: 0.25,
            step_factor: gdsmc_core::physics::DEFAULT_STEP_FACTOR,
            background_kernel: GDSMC_BACKGROUND_MAXWELL,
            background_c: 1.0,
            background_density: 1.0,
            background_mass: 1.0,
            background_temperature: 1.0,
            background_drift: [0.0; 3],
            species: 0,
            species_count: [0; GDSMC_MAX_SPECIES],
            species_mass: [1.0; GDSMC_MAX_SPECIES],
            species_temperature: [1.0; GDSMC_MAX_SPECIES],
            species_diameter: [1.0; GDSMC_MAX_SPECIES],
            species_beta: [0.0; GDSMC_MAX_SPECIES],
            pair_restitution_set: 0,
            pair_restitution: [1.0; GDSMC_MAX_PAIRS],
            rough: 0,
            tangential_restitution: SMOOTH.beta,
            inertia: SMOOTH.kappa,
            rotation_temperature: SMOOTH.temperature,
            rotation_noise: SMOOTH.noise,
            species_rotation_set: 0,
            species_inertia: [SMOOTH.kappa; GDSMC_MAX_SPECIES],
            species_rotation_temperature: [SMOOTH.temperature; GDSMC_MAX_SPECIES],
            species_rotation_noise: [SMOOTH.noise; GDSMC_MAX_SPECIES],
            pair_tangential_restitution_set: 0,
            pair_tangential_restitution: [SMOOTH.beta; GDSMC_MAX_PAIRS],
            dimension: 3,
            exact_momentum: 0,
            scheme_params: scheme_defaults(),
        }
    }
}

/// Fills `*out` with the defaults: GRW Example 3 (Maxwell kernel, gamma = 4, C = 1/(4 pi),
/// alpha = 1/2, white noise beta = 1, standard Maxwellian start, no splitting) with n = 1024,
/// seed 1, stream 0; dt = 1/4, step_factor = 0.01 (MS), a unit host medium, and smooth
/// uniform spheres' rotation (tangential restitution -1, inertia 2/5, rotational temperature 1)
/// for when those are switched on; dimension 3.
///
/// # Safety
/// `out` must be NULL or point to writable memory for one gdsmc_config.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn gdsmc_config_default(out: *mut gdsmc_config) -> gdsmc_status {
    guard(|| {
        check_ptr(out, "out")?;
        // SAFETY: checked non-null and aligned; the caller provides writable memory.
        unsafe { out.write(gdsmc_config::example3()) };
        Ok(())
    })
}
