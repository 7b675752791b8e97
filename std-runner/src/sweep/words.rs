//! A varied key in words, for a sweep chart's x axis: what the key is (its symbol in the
//! papers), then the key itself, so that a reader who has not seen the scene knows the axis.
//! A parameter declared by its variant (a kernel's, drive's, law's or scheme's) is read from
//! its declaration; the keys every scene has are named here.

use crate::scene::Scene;
use gdsmc_core::physics::{DriveKind, KernelKind, LawKind, SchemeKind};

/// The words of the keys every scene has (not declared by a variant).
const KEYS: &[(&str, &str)] = &[
    ("collisions.restitution", "restitution coefficient alpha"),
    ("collisions.gamma", "kernel constant gamma"),
    ("collisions.c", "kernel constant C"),
    ("particles.n", "particles n"),
    ("particles.dimension", "dimension d"),
    ("drive.beta", "white-noise strength beta"),
    ("drive.temperature", "bath temperature T_b"),
    ("drive.density", "background density rho^B"),
    ("drive.mass", "background mass m^B"),
    (
        "rotation.tangential_restitution",
        "tangential restitution beta",
    ),
    ("rotation.inertia", "reduced moment of inertia kappa"),
    ("rotation.temperature", "initial rotational temperature"),
    ("rotation.noise", "rotational white noise"),
    ("observe.t_end", "final time t_end"),
    ("run.ensembles", "ensembles"),
];

/// The words a variant's declaration gives the parameter `name` under `table`.
fn declared(table: &str, name: &str) -> Option<&'static str> {
    let specs = match table {
        "collisions" => KernelKind::ALL
            .iter()
            .flat_map(|k| k.params())
            .chain(LawKind::ALL.iter().flat_map(|k| k.params()))
            .find(|p| p.name == name),
        "drive" => DriveKind::ALL
            .iter()
            .filter_map(|k| k.params())
            .flatten()
            .find(|p| p.name == name),
        "scheme" => SchemeKind::ALL
            .iter()
            .flat_map(|k| k.params())
            .find(|p| p.name == name),
        _ => None,
    };
    specs.map(|p| p.words)
}

/// A species key `species[k].what` in words; a mass against a unit mass of the only other
/// species is the mass ratio.
fn species(key: &str, scene: &Scene) -> Option<String> {
    let rest = key.strip_prefix("species[")?;
    let (k, what) = rest.split_once("].")?;
    let k: usize = k.parse().ok()?;
    let sp = &scene.physics().species;
    let who = crate::run::columns::species_who(k, scene.species_names());
    Some(match what {
        "mass" if sp.len() == 2 && sp[1 - k.min(1)].mass == 1.0 => {
            format!(
                "mass ratio m_{k}/m_{} ({who}'s mass, the other's 1)",
                1 - k.min(1)
            )
        }
        "mass" => format!("{who}'s mass"),
        "diameter" => format!("{who}'s diameter"),
        "fraction" => format!("{who}'s mole fraction"),
        "temperature" => format!("{who}'s initial temperature"),
        "beta" => format!("{who}'s white-noise strength"),
        other => format!("{who}'s {other}"),
    })
}

/// The x axis' words for the varied `key` of a sweep of `scene`: "restitution coefficient
/// alpha (collisions.restitution)"; the key alone when nothing here knows it.
pub fn key_label(key: &str, scene: &Scene) -> String {
    let words = KEYS
        .iter()
        .find(|(k, _)| *k == key)
        .map(|(_, w)| w.to_string())
        .or_else(|| species(key, scene))
        .or_else(|| {
            let (table, name) = key.split_once('.')?;
            declared(table, name).map(str::to_string)
        });
    match words {
        Some(w) => format!("{w} ({key})"),
        None => key.to_string(),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn scene(text: &str) -> Scene {
        crate::scene::parse(std::path::Path::new("k.toml"), text).expect("a valid scene")
    }

    #[test]
    fn keys_are_named_in_words() {
        let s = scene(
            "[particles]\nn = 8\n[[species]]\nname = \"heavy\"\nfraction = 0.5\nmass = 4.0\n[[species]]\nfraction = 0.5\nmass = 1.0\n[collisions]\nkernel = \"hard-spheres\"\nrestitution = 0.9\n[observe]\nt_end = 1.0\n",
        );
        assert_eq!(
            key_label("collisions.restitution", &s),
            "restitution coefficient alpha (collisions.restitution)"
        );
        assert_eq!(
            key_label("species[0].mass", &s),
            "mass ratio m_0/m_1 (heavy (species 0)'s mass, the other's 1) (species[0].mass)"
        );
        assert_eq!(
            key_label("species[1].diameter", &s),
            "species 1's diameter (species[1].diameter)"
        );
        // A declared drive parameter is read from its declaration.
        let friction = key_label("drive.friction", &s);
        assert!(
            friction.ends_with("(drive.friction)") && friction.len() > 30,
            "{friction}"
        );
        assert_eq!(key_label("something.else", &s), "something.else");
    }
}
