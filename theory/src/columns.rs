//! The names of the observables a run writes and its references are of: each spelt once, so
//! that a reference's `of` and the runner's columns cannot drift apart (a misspelt name fails
//! to compile). The runner's table of how each is read (`gdsmc::run::columns`) uses these.

/// Every base column's name, spelled once: code that reads a column by name uses these
/// (`stats.col(name::T_BULK)`), so that a misspelt name fails to compile.
pub mod name {
    /// `T`: raw temperature (RW (23)).
    pub const T: &str = "T";
    /// `T_bulk`: temperature about the bulk velocity (GRW (11)).
    pub const T_BULK: &str = "T_bulk";
    /// `V_x`: bulk velocity, x.
    pub const V_X: &str = "V_x";
    /// `V_y`: bulk velocity, y.
    pub const V_Y: &str = "V_y";
    /// `V_z`: bulk velocity, z.
    pub const V_Z: &str = "V_z";
    /// `V_norm`: bulk speed.
    pub const V_NORM: &str = "V_norm";
    /// `p`: pressure.
    pub const P: &str = "p";
    /// `q_norm`: heat-flux magnitude.
    pub const Q_NORM: &str = "q_norm";
    /// `v4`: raw fourth moment.
    pub const V4: &str = "v4";
    /// `v6`: raw sixth moment.
    pub const V6: &str = "v6";
    /// `a2`: fourth cumulant (MS (3)).
    pub const A2: &str = "a2";
    /// `a3`: sixth cumulant (MS (70)).
    pub const A3: &str = "a3";
    /// `c1`: reduced first moment (MS (4)).
    pub const C1: &str = "c1";
    /// `c3`: reduced third moment (MS (4)).
    pub const C3: &str = "c3";
    /// `log10_T_bulk`: log10 of T_bulk.
    pub const LOG10_T_BULK: &str = "log10_T_bulk";
    /// `crit`: deviation-from-Maxwell criterion (RW (29)).
    pub const CRIT: &str = "crit";
    /// `mu2`: collisional moment mu_2 (MS (44)).
    pub const MU2: &str = "mu2";
    /// `mu4`: collisional moment mu_4 (MS (52)).
    pub const MU4: &str = "mu4";
    /// `s`: collisions per particle so far, `2 (grain-grain collisions) / n`.
    pub const S: &str = "s";
    /// `T_rot`: rotational temperature of a rough gas (`ROUGH_COLUMNS`).
    pub const T_ROT: &str = "T_rot";
    /// `theta`: rotational-to-translational temperature ratio (`ROUGH_COLUMNS`).
    pub const THETA: &str = "theta";
    /// `T_total`: total temperature of a rough gas (`ROUGH_COLUMNS`).
    pub const T_TOTAL: &str = "T_total";
    /// `a2_rot`: fourth cumulant of the angular velocities (`ROUGH_COLUMNS`).
    pub const A2_ROT: &str = "a2_rot";
    /// `cw2`: translational-rotational correlation (`ROUGH_COLUMNS`).
    pub const CW2: &str = "cw2";
    /// `tail_exponent`: the power-law tail's exponent `s` of `P(c >= x) ~ x^-s` (the runner's
    /// power-tail analysis; MS's Maxwell gas has it exact).
    pub const TAIL_EXPONENT: &str = "tail_exponent";
}

/// The extra columns a scene can ask for, computed by the runner beside the core observables.
pub const COLLISIONAL: [&str; 2] = [name::MU2, name::MU4];

/// A mixture's columns: the mixture temperature `T_mix = sum_s x_s T_s`, then per species
/// (labelled `s0`, `s1`, .. in file order) [`SPECIES_COLUMNS`].
pub const MIXTURE_TEMPERATURE: &str = "T_mix";

/// Per species `k`: its temperature `T_sk` about the mixture's flow velocity (Garzó and Dufty
/// 1999, (6)), its ratio to `T_mix` (`T_sk_ratio`), its fourth cumulant `a2_sk` (MS (3), about its own bulk
/// velocity) and the speed `dV_sk = |V_s - U|` of its bulk velocity relative to the flow.
pub const SPECIES_COLUMNS: [[&str; 4]; gdsmc_core::mixture::MAX_SPECIES] = [
    ["T_s0", "T_s0_ratio", "a2_s0", "dV_s0"],
    ["T_s1", "T_s1_ratio", "a2_s1", "dV_s1"],
    ["T_s2", "T_s2_ratio", "a2_s2", "dV_s2"],
    ["T_s3", "T_s3_ratio", "a2_s3", "dV_s3"],
];

/// A mixture's cooling rates, with `observe.collisional_pairs`: the mixture's
/// `zeta_mix = -(dT_mix/dt)/T_mix`, then per species `zeta_sk = -(dT_sk/dt)/T_sk`, from the
/// collisions (the runner's run/cooling.rs).
pub const COOLING_COLUMNS: [&str; gdsmc_core::mixture::MAX_SPECIES + 1] =
    ["zeta_mix", "zeta_s0", "zeta_s1", "zeta_s2", "zeta_s3"];

/// The collisional cooling of every gas with `observe.collisional_pairs`, after every other
/// column (gdsmc_core::observe::cooling): the collision frequency `nu` (collisions per
/// particle per unit time, the rate of `s`), `zeta = -(dE/dt)_coll / E` of the energy about
/// the flow (translation and rotation) and `zeta_star = zeta / nu`.
pub const CLOSING_COLUMNS: [&str; 3] = ["nu", "zeta", "zeta_star"];

/// After [`CLOSING_COLUMNS`], for smooth hard spheres of one species: the cooling rate reduced
/// as the kinetic-theory literature reduces it, `zeta_star_nu0 = zeta / nu_0` with `nu_0 =
/// (16/5) sqrt(pi) n sigma^2 sqrt(T_bulk/m)` (Garzó and Dufty 1999; `balance::nu0_hard_spheres`)
/// at the observation's `T_bulk`: `5/12 (1 - alpha^2)(1 + 3 a2/16)` to first Sonine order, where
/// `zeta_star` (by the measured collision frequency) is `(1 - alpha^2)/3` at a Maxwellian.
pub const LITERATURE_ZETA_STAR: &str = "zeta_star_nu0";

/// A rough mixture's rotational temperature `T_rot_mix = sum_s x_s T_rot,s` (after the
/// species' translational columns).
pub const ROUGH_MIXTURE_TEMPERATURE: &str = "T_rot_mix";

/// Per species `k` of a rough mixture: its rotational temperature
/// `T_rot_sk = m_s kappa_s <|w|^2>_s / d_rot`, its ratio `theta_sk = T_rot_sk / T_sk` to its
/// translational temperature (Santos, Kremer and Garzó 2010), and its rim velocities' fourth
/// cumulant `a2_rot_sk`.
pub const ROUGH_SPECIES_COLUMNS: [[&str; 3]; gdsmc_core::mixture::MAX_SPECIES] = [
    ["T_rot_s0", "theta_s0", "a2_rot_s0"],
    ["T_rot_s1", "theta_s1", "a2_rot_s1"],
    ["T_rot_s2", "theta_s2", "a2_rot_s2"],
    ["T_rot_s3", "theta_s3", "a2_rot_s3"],
];

/// A rough gas's columns (Huthmann and Zippelius 1997): the rotational temperature
/// `T_rot = kappa <|w|^2>/3`, `theta = T_rot / T_bulk` (`T_bulk` is the translational
/// temperature `T_tr`), the mean energy per degree of freedom `T_total = (T_bulk + T_rot)/2`,
/// the rim velocities' fourth cumulant `a2_rot` and the translation-rotation correlation
/// `cw2 = 3 <(c . w)^2> / (<c^2> <w^2>) - 1` (Brilliantov et al. 2007).
pub const ROUGH_COLUMNS: [&str; 5] = [
    name::T_ROT,
    name::THETA,
    name::T_TOTAL,
    name::A2_ROT,
    name::CW2,
];
