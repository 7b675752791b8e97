//! `collisions.diameter` and `collisions.density` (`validate/size.rs`): the strength they
//! derive in each dimension and for a mixture, and every refusal at its key.

use super::refused;

fn scene(dimension: u32, collisions: &str) -> String {
    format!(
        "[particles]\nn = 64\ndimension = {dimension}\n[collisions]\n{collisions}\nrestitution = 0.9\n\
         [drive]\nkind = \"none\"\n[observe]\nt_end = 1.0\nintervals = 1\n"
    )
}

fn strength(text: &str) -> (f64, Vec<String>) {
    let s = gdsmc_scene::parse(std::path::Path::new("size.toml"), text).unwrap();
    (s.physics().kernel.strength(), s.derived().to_vec())
}

#[test]
fn hard_particles_take_their_diameter_and_density() {
    let hs = "kernel = \"hard-spheres\"\ndiameter = 2.0\ndensity = 0.5";
    // Spheres: 4 pi gamma C = pi sigma^2 n; disks: 4 pi gamma C = 2 sigma n.
    let (g3, w3) = strength(&scene(3, hs));
    assert_eq!(g3, 2.0 * 2.0 * 0.5 / 4.0);
    assert!(
        w3[0].contains("pi sigma^2 n") && w3[0].contains("collisions.diameter"),
        "{w3:?}"
    );
    let (g2, w2) = strength(&scene(2, hs));
    assert_eq!(g2, 2.0 * 0.5 / (2.0 * std::f64::consts::PI));
    assert!(w2[0].contains("2 sigma n"), "{w2:?}");
    // Without them nothing is derived and gamma C is the file's.
    let (g, w) = strength(&scene(3, "kernel = \"hard-spheres\"\ngamma = 2.0\nc = 0.5"));
    assert_eq!((g, w.len()), (1.0, 0));
}

#[test]
fn a_mixture_takes_the_density_and_its_species_diameters() {
    let text = "[particles]\nn = 64\n[collisions]\nkernel = \"hard-spheres\"\ndensity = 2.0\nrestitution = 0.9\n\
        [[species]]\nname = \"a\"\nfraction = 0.5\nmass = 1.0\ntemperature = 1.0\ndiameter = 1.0\n\
        [[species]]\nname = \"b\"\nfraction = 0.5\nmass = 2.0\ntemperature = 1.0\ndiameter = 2.0\n\
        [drive]\nkind = \"none\"\n[observe]\nt_end = 1.0\nintervals = 1\n";
    let (g, w) = strength(text);
    assert_eq!(g, 0.5);
    assert!(w[0].contains("((d_s + d_t)/2)^2"), "{w:?}");
    refused(
        &text.replace("density = 2.0", "density = 2.0\ndiameter = 1.0"),
        "collisions.diameter",
    );
}

#[test]
fn the_keys_are_refused_where_they_do_not_set_the_rate() {
    refused(
        &scene(3, "kernel = \"maxwell\"\ndiameter = 1.0\ndensity = 1.0"),
        "kernel = \"maxwell\" takes gamma and c",
    );
    refused(
        &scene(
            3,
            "kernel = \"hard-spheres\"\ngamma = 2.0\ndiameter = 1.0\ndensity = 1.0",
        ),
        "bad.toml:6: `collisions.gamma` and collisions.diameter/density exclude",
    );
    refused(
        &scene(3, "kernel = \"hard-spheres\"\ndiameter = 1.0"),
        "`collisions.density` is required with collisions.diameter",
    );
    refused(
        &scene(3, "kernel = \"hard-spheres\"\ndensity = 1.0"),
        "`collisions.diameter` is required with collisions.density",
    );
    refused(
        &scene(
            3,
            "kernel = \"hard-spheres\"\ndiameter = -1.0\ndensity = 1.0",
        ),
        "`collisions.diameter` must be a finite number > 0, got -1",
    );
}
