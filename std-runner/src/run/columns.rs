//! The observables written per time point: a fixed list of named columns.

use gdsmc_core::moments::Observables;
pub use gdsmc_theory::columns::{
    CLOSING_COLUMNS, COLLISIONAL, COOLING_COLUMNS, LITERATURE_ZETA_STAR, MIXTURE_TEMPERATURE,
    ROUGH_COLUMNS, ROUGH_MIXTURE_TEMPERATURE, ROUGH_SPECIES_COLUMNS, SPECIES_COLUMNS, name,
};

/// One observable column of observables.csv.
#[derive(Clone, Copy, Debug)]
pub struct Column {
    /// Column name.
    pub name: &'static str,
    /// What it is, with its paper and equation.
    pub doc: &'static str,
    /// How to read it from the observables.
    pub get: fn(&Observables) -> f64,
}

/// Every observable column, in file order.
pub const COLUMNS: &[Column] = &[
    Column {
        name: name::T,
        doc: "temperature (1/3n) sum |v|^2 as GRW/RW use it (RW (23))",
        get: |o| o.t_raw,
    },
    Column {
        name: name::T_BULK,
        doc: "temperature about the bulk velocity, GRW (11), BRS (8)",
        get: |o| o.t_bulk,
    },
    Column {
        name: name::V_X,
        doc: "bulk velocity, x (GRW (10))",
        get: |o| o.bulk.x,
    },
    Column {
        name: name::V_Y,
        doc: "bulk velocity, y",
        get: |o| o.bulk.y,
    },
    Column {
        name: name::V_Z,
        doc: "bulk velocity, z",
        get: |o| o.bulk.z,
    },
    Column {
        name: name::V_NORM,
        doc: "|V|, the bulk speed (GRW Tables 1-2 report its maximum)",
        get: |o| o.bulk.norm(),
    },
    Column {
        name: name::P,
        doc: "pressure rho T_bulk (GRW Section 1)",
        get: |o| o.pressure,
    },
    Column {
        name: name::Q_NORM,
        doc: "|q|, the heat flux (GRW Section 1)",
        get: |o| o.heat_flux.norm(),
    },
    Column {
        name: name::V4,
        doc: "<|v|^4>, raw",
        get: |o| o.v4,
    },
    Column {
        name: name::V6,
        doc: "<|v|^6>, raw",
        get: |o| o.v6,
    },
    Column {
        name: name::A2,
        doc: "fourth cumulant, MS (3)",
        get: |o| o.a2,
    },
    Column {
        name: name::A3,
        doc: "sixth cumulant, MS (70)",
        get: |o| o.a3,
    },
    Column {
        name: name::C1,
        doc: "<c> with c = |v - V| / v0, v0 = sqrt(2 T_bulk) (MS (4); enters MS (44) and (52))",
        get: |o| o.c1 / (2.0 * o.t_bulk).sqrt(),
    },
    Column {
        name: name::C3,
        doc: "<c^3> with c = |v - V| / v0 (MS (4); enters MS (44))",
        get: |o| o.c3 / libm::pow(2.0 * o.t_bulk, 1.5),
    },
    Column {
        name: name::LOG10_T_BULK,
        doc: "log10 T_bulk, finite where a cooling gas's temperature underflows (HCS, Haff's law)",
        get: |o| o.log10_t_bulk,
    },
    Column {
        name: name::CRIT,
        doc: "deviation-from-Maxwell criterion, RW (29)",
        get: |o| o.crit,
    },
];

/// Index of the column named `name`.
pub fn index(name: &str) -> Option<usize> {
    COLUMNS.iter().position(|c| c.name == name)
}

/// The rough columns' values of one observation, in [`ROUGH_COLUMNS`] order (for disks,
/// `T_total = (2 T_bulk + T_rot)/3` and `cw2` as [`gdsmc_core::rough::RoughObservables`]
/// defines it).
pub fn rough_values(
    r: &gdsmc_core::rough::RoughObservables,
    dim: gdsmc_core::physics::DimensionChoice,
) -> [f64; 5] {
    [r.t_rot, r.theta(), r.t_total_in(dim), r.a2_rot, r.cw2]
}

/// The mixture columns' values of one observation, in [`names`] order.
pub fn mixture_values(m: &gdsmc_core::mixture::MixtureObservables) -> Vec<f64> {
    let t = m.mixture_temperature();
    let u = m.flow_velocity();
    let mut v = vec![t];
    for s in 0..m.len {
        let ts = m.temperature(s);
        v.extend([ts, ts / t, m.species[s].a2, (m.species[s].bulk - u).norm()]);
    }
    if let (Some(rot), Some(t_rot)) = (m.rotation, m.mixture_rotational_temperature()) {
        v.push(t_rot);
        for (s, r) in rot.iter().enumerate().take(m.len) {
            let tr = m.masses[s] * r.t_rot;
            v.extend([tr, tr / m.temperature(s), r.a2_rot]);
        }
    }
    v
}

/// The column names of a scene's observables.csv, in order: [`COLUMNS`], `s` (collisions per
/// particle), then `mu2`, `mu4`
/// (MS (67)) where [`super::collisional::Collisional::moments`], then a rough gas's [`ROUGH_COLUMNS`],
/// then a mixture's columns
/// ([`MIXTURE_TEMPERATURE`], [`SPECIES_COLUMNS`] per species; for rough particles
/// [`ROUGH_MIXTURE_TEMPERATURE`] and [`ROUGH_SPECIES_COLUMNS`] per species instead of the rough
/// gas's; and where [`super::collisional::Collisional::mixture_rates`] the [`COOLING_COLUMNS`]), then with
/// `observe.collisional_pairs` the [`CLOSING_COLUMNS`].
pub fn names(scene: &crate::scene::Scene) -> Vec<&'static str> {
    let mut v: Vec<&'static str> = COLUMNS.iter().map(|c| c.name).collect();
    v.push(name::S);
    let species = scene.physics().species.len();
    let coll = super::collisional::collisional(scene);
    if coll.moments {
        v.extend(COLLISIONAL);
    }
    let rough = scene.physics().rotation.is_some();
    if rough && species == 0 {
        v.extend(ROUGH_COLUMNS);
    }
    if species > 0 {
        v.push(MIXTURE_TEMPERATURE);
        for cols in &SPECIES_COLUMNS[..species] {
            v.extend(cols);
        }
        if rough {
            v.push(ROUGH_MIXTURE_TEMPERATURE);
            for cols in &ROUGH_SPECIES_COLUMNS[..species] {
                v.extend(cols);
            }
        }
        if coll.mixture_rates {
            v.extend(&COOLING_COLUMNS[..species + 1]);
        }
    }
    if coll.cooling {
        v.extend(CLOSING_COLUMNS);
    }
    if coll.nu0 {
        v.push(LITERATURE_ZETA_STAR);
    }
    v
}

/// The time axis' label: name, symbol and unit.
pub const TIME_LABEL: &str = "time t (scene units)";

/// The label of the collisions-per-particle axis (`observe.time_axis = "collisions"`).
pub const COLLISIONS_LABEL: &str = "collisions per particle s (dimensionless)";

/// The axis label of column `name`: the quantity in words, its symbol and its unit, for a
/// reader who has not seen this file. Quantities with a dimension are in the scene's units
/// (particle mass 1, or the species' masses as given; the kernel's `gamma` and `C` fix the
/// time unit); ratios and cumulants are dimensionless. A column this table does not know keeps
/// its name.
pub fn axis_label(name: &str) -> String {
    axis_label_in(name, &[])
}

/// [`axis_label`] with a mixture's species called by their names (`species`, from the scene's
/// `[[species]] name`; an empty or missing name keeps "species k").
pub fn axis_label_in(name: &str, species: &[String]) -> String {
    const DIM: &str = "(scene units)";
    const NONE: &str = "(dimensionless)";
    let (words, unit) = match name {
        name::T => ("temperature T", DIM),
        name::T_BULK => ("temperature about the flow T_bulk", DIM),
        name::V_X => ("bulk velocity V_x", DIM),
        name::V_Y => ("bulk velocity V_y", DIM),
        name::V_Z => ("bulk velocity V_z", DIM),
        name::V_NORM => ("bulk speed V_norm = |V|", DIM),
        name::P => ("pressure p", DIM),
        name::Q_NORM => ("heat flux q_norm = |q|", DIM),
        name::V4 => ("fourth moment v4 = <|v|^4>", DIM),
        name::V6 => ("sixth moment v6 = <|v|^6>", DIM),
        name::A2 => ("fourth cumulant a2", NONE),
        name::A3 => ("sixth cumulant a3", NONE),
        name::C1 => ("reduced mean speed c1 = <c>", NONE),
        name::C3 => ("reduced third moment c3 = <c^3>", NONE),
        name::LOG10_T_BULK => (
            "log10_T_bulk, the temperature's decimal logarithm",
            "(of scene units)",
        ),
        name::CRIT => ("distance from the Maxwellian, crit (RW (29))", NONE),
        name::S => (
            "collisions per particle s = 2 (collisions so far) / n",
            NONE,
        ),
        name::MU2 => ("collisional moment mu2 (MS (44))", NONE),
        name::MU4 => ("collisional moment mu4 (MS (52))", NONE),
        name::T_ROT => ("rotational temperature T_rot", DIM),
        name::THETA => ("temperature ratio theta = T_rot/T_bulk", NONE),
        name::T_TOTAL => ("mean energy per degree of freedom T_total", DIM),
        name::A2_ROT => ("fourth cumulant of the rim velocities a2_rot", NONE),
        name::CW2 => ("translation-rotation correlation cw2", NONE),
        MIXTURE_TEMPERATURE => ("mixture temperature T_mix", DIM),
        ROUGH_MIXTURE_TEMPERATURE => ("mixture rotational temperature T_rot_mix", DIM),
        "zeta_mix" => ("mixture cooling rate zeta_mix", "(1/scene time unit)"),
        "nu" => ("collision frequency nu = ds/dt", "(1/scene time unit)"),
        "zeta" => ("cooling rate zeta = -(dE/dt)_coll/E", "(1/scene time unit)"),
        "zeta_star" => ("reduced cooling rate zeta* = zeta/nu", NONE),
        LITERATURE_ZETA_STAR => (
            "reduced cooling rate zeta* = zeta/nu_0 (Garzó and Dufty's nu_0)",
            NONE,
        ),
        name::TAIL_EXPONENT => ("power-law tail exponent s of P(c >= x) ~ x^-s", NONE),
        _ => return species_label(name, species).unwrap_or_else(|| name.to_string()),
    };
    format!("{words} {unit}")
}

/// The words and unit of each per-species column, in the order of [`SPECIES_COLUMNS`],
/// [`ROUGH_SPECIES_COLUMNS`] and (after `zeta_mix`) [`COOLING_COLUMNS`].
const SPECIES_WORDS: [(&str, &str); 4] = [
    ("temperature", "(scene units)"),
    ("temperature ratio to T_mix", "(dimensionless)"),
    ("fourth cumulant", "(dimensionless)"),
    ("drift |V_s - U| relative to the flow", "(scene units)"),
];
const ROUGH_SPECIES_WORDS: [(&str, &str); 3] = [
    ("rotational temperature", "(scene units)"),
    ("temperature ratio T_rot/T", "(dimensionless)"),
    ("rim velocities' fourth cumulant", "(dimensionless)"),
];
const COOLING_WORDS: (&str, &str) = ("cooling rate", "(1/scene time unit)");

/// Species `k` in words: "heavy (species 0)" where the scene names it, "species 0" where it
/// does not (no name, or the scene's default `s0`).
pub fn species_who(k: usize, species: &[String]) -> String {
    match species
        .get(k)
        .filter(|n| !n.is_empty() && **n != format!("s{k}"))
    {
        Some(n) => format!("{n} (species {k})"),
        None => format!("species {k}"),
    }
}

/// The label of a per-species column (`T_s0`, `theta_s1`, ..), found in the column tables and
/// calling the species by its name in `species` where it has one, or `None`.
fn species_label(name: &str, species: &[String]) -> Option<String> {
    (0..gdsmc_core::mixture::MAX_SPECIES).find_map(|k| {
        let words = SPECIES_COLUMNS[k]
            .iter()
            .zip(SPECIES_WORDS)
            .chain(ROUGH_SPECIES_COLUMNS[k].iter().zip(ROUGH_SPECIES_WORDS))
            .chain(std::iter::once((&COOLING_COLUMNS[k + 1], COOLING_WORDS)))
            .find(|(col, _)| **col == name)?
            .1;
        Some(format!(
            "{}'s {} {name} {}",
            species_who(k, species),
            words.0,
            words.1
        ))
    })
}

#[cfg(test)]
mod label_tests {
    use super::*;

    /// Every column a scene can write has a label naming the quantity in words beside its
    /// symbol.
    #[test]
    fn every_column_has_a_label_in_words() {
        let mut all: Vec<&str> = COLUMNS.iter().map(|c| c.name).collect();
        all.push(name::S);
        all.extend(COLLISIONAL);
        all.extend(ROUGH_COLUMNS);
        all.extend([MIXTURE_TEMPERATURE, ROUGH_MIXTURE_TEMPERATURE]);
        all.extend(SPECIES_COLUMNS.iter().flatten());
        all.extend(ROUGH_SPECIES_COLUMNS.iter().flatten());
        all.extend(COOLING_COLUMNS);
        for name in all {
            let label = axis_label(name);
            assert!(
                label.contains(name) && label.len() > name.len() + 10 && label.ends_with(')'),
                "{name}: {label}"
            );
        }
        assert_eq!(axis_label("unknown_s9"), "unknown_s9");
        let named = ["heavy".to_string(), String::new()];
        assert_eq!(
            axis_label_in("T_s0", &named),
            "heavy (species 0)'s temperature T_s0 (scene units)"
        );
        assert!(axis_label_in("T_s1", &named).starts_with("species 1's"));
    }
}
