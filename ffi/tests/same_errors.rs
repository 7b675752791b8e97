//! The C ABI and the command give the same error for the same bad value: both pass on the
//! core's one validation, each naming the parameter in its own words (`config.restitution`,
//! `collisions.restitution`), with the same description of what is wrong.

use gdsmc::{gdsmc_config, gdsmc_last_error, gdsmc_sim, gdsmc_sim_create, gdsmc_status};
use std::path::Path;

const SCENE: &str = r#"
[particles]
n = 64
[collisions]
kernel = "hard-spheres"
gamma = 1.0
c = 1.0
restitution = 0.5
[drive]
kind = "white-noise"
beta = 1.0
[observe]
t_end = 1.0
"#;

/// The C message of creating a simulation from `c`.
fn c_error(c: &gdsmc_config) -> String {
    let mut sim: *mut gdsmc_sim = std::ptr::null_mut();
    // SAFETY: valid pointers to a config and an out-pointer.
    let status = unsafe { gdsmc_sim_create(c, &mut sim) };
    assert_eq!(status, gdsmc_status::GDSMC_INVALID_ARGUMENT);
    assert!(sim.is_null());
    let mut buf = vec![0u8; 512];
    // SAFETY: a writable buffer of its length.
    let len = unsafe { gdsmc_last_error(buf.as_mut_ptr().cast(), buf.len()) };
    String::from_utf8(buf[..len].to_vec()).unwrap()
}

/// The command's message for the scene with `from` replaced by `to` (and `--set`s).
fn scene_error(from: &str, to: &str, sets: &[&str]) -> String {
    let sets: Vec<String> = sets.iter().map(|s| s.to_string()).collect();
    let text = if from.is_empty() {
        SCENE.to_string()
    } else {
        SCENE.replace(from, to)
    };
    gdsmc_scene::parse_with_overrides(Path::new("s.toml"), &text, &sets)
        .unwrap_err()
        .to_string()
}

type Edit = fn(&mut gdsmc_config);
/// Scene text replaced (from, to), `--set`s, scene key, C field, the same change in C.
type Case = (
    &'static str,
    &'static str,
    &'static [&'static str],
    &'static str,
    &'static str,
    Edit,
);

/// A mixture's bad value (`--set`s on the scene text `text`, scene key, C field, the same
/// change in C on `base`).
type MixtureCase<'a> = (&'a [&'a str], &'a str, &'a str, Edit);

/// Each case gives the same words from the scene (at its key) and from C (at its field).
fn same_words(base: &gdsmc_config, text: &str, cases: &[MixtureCase<'_>]) {
    for &(sets, key, field, edit) in cases {
        let sets: Vec<String> = sets.iter().map(|s| s.to_string()).collect();
        let s = gdsmc_scene::parse_with_overrides(Path::new("s.toml"), text, &sets)
            .unwrap_err()
            .to_string();
        let mut c = *base;
        edit(&mut c);
        let cmsg = c_error(&c);
        let problem = cmsg
            .strip_prefix(&format!("config.{field} "))
            .unwrap_or_else(|| panic!("{cmsg}"));
        assert!(
            s.ends_with(&format!("`{key}` {problem}")),
            "scene: {s}\nC:     {cmsg}"
        );
    }
}

#[test]
fn the_same_bad_value_gets_the_same_words() {
    let mut base = gdsmc_config::example3();
    base.kernel = gdsmc::GDSMC_KERNEL_HARD_SPHERES;
    (base.gamma, base.c, base.n) = (1.0, 1.0, 64);
    let cases: [Case; 13] = [
        (
            "[observe]",
            "[rotation]\ntangential_restitution = 1.5\n[observe]",
            &[],
            "rotation.tangential_restitution",
            "tangential_restitution",
            |c| {
                c.rough = 1;
                c.tangential_restitution = 1.5;
            },
        ),
        (
            "[observe]",
            "[rotation]\ntangential_restitution = 0.0\ninertia = 0.0\n[observe]",
            &[],
            "rotation.inertia",
            "inertia",
            |c| {
                (c.rough, c.tangential_restitution, c.inertia) = (1, 0.0, 0.0);
            },
        ),
        (
            "[observe]",
            "[rotation]\ntangential_restitution = 0.0\nnoise = -1.0\n[observe]",
            &[],
            "rotation.noise",
            "rotation_noise",
            |c| {
                (c.rough, c.tangential_restitution, c.rotation_noise) = (1, 0.0, -1.0);
            },
        ),
        (
            "restitution = 0.5",
            "restitution = 1.5",
            &[],
            "collisions.restitution",
            "restitution",
            |c| c.restitution = 1.5,
        ),
        ("n = 64", "n = 1", &[], "particles.n", "n", |c| c.n = 1),
        (
            "n = 64",
            "n = 64\ndimension = 2\ninitial = { kind = \"maxwellian\", drift = [0.0, 0.0, 1.0] }",
            &[],
            "particles.initial.drift",
            "drift",
            |c| {
                c.dimension = 2;
                c.drift = [0.0, 0.0, 1.0];
            },
        ),
        (
            "n = 64",
            "n = 64\ndimension = 2",
            &[
                "drive.kind=host-medium",
                "drive.kernel=maxwell",
                "drive.beta=",
                "drive.drift=[0.0, 0.0, 1.0]",
            ],
            "drive.drift",
            "background_drift",
            |c| {
                c.dimension = 2;
                c.drive = gdsmc::GDSMC_DRIVE_HOST_MEDIUM;
                c.background_drift = [0.0, 0.0, 1.0];
            },
        ),
        (
            "beta = 1.0",
            "beta = -0.5",
            &[],
            "drive.beta",
            "beta",
            |c| c.beta = -0.5,
        ),
        (
            "gamma = 1.0",
            "gamma = 0.0",
            &[],
            "collisions.gamma",
            "gamma",
            |c| c.gamma = 0.0,
        ),
        ("c = 1.0", "c = inf", &[], "collisions.c", "c", |c| {
            c.c = f64::INFINITY
        }),
        (
            "",
            "",
            &["scheme.kind=time-stepped", "scheme.step_factor=-1"],
            "scheme.step_factor",
            "step_factor",
            |c| {
                c.scheme = gdsmc::GDSMC_SCHEME_TIME_STEPPED;
                c.step_factor = -1.0;
            },
        ),
        (
            "restitution = 0.5",
            "impact_speed_law = { beta0 = -0.25, delta = 0.2 }",
            &[],
            "collisions.impact_speed_law.beta0",
            "impact_beta0",
            |c| {
                c.restitution_law = gdsmc::GDSMC_RESTITUTION_IMPACT_SPEED;
                (c.impact_beta0, c.impact_delta) = (-0.25, 0.2);
            },
        ),
        (
            "",
            "",
            &[
                "drive.kind=host-medium",
                "drive.kernel=maxwell",
                "drive.beta=",
                "drive.density=0",
            ],
            "drive.density",
            "background_density",
            |c| {
                c.drive = gdsmc::GDSMC_DRIVE_HOST_MEDIUM;
                c.background_density = 0.0;
            },
        ),
    ];
    for (from, to, sets, key, field, edit) in cases {
        let scene = scene_error(from, to, sets);
        let mut c = base;
        edit(&mut c);
        let cmsg = c_error(&c);
        let prefix = format!("config.{field} ");
        let problem = cmsg
            .strip_prefix(&prefix)
            .unwrap_or_else(|| panic!("{cmsg}"));
        assert!(
            scene.ends_with(&format!("`{key}` {problem}")),
            "scene: {scene}\nC:     {cmsg}"
        );
    }
}

/// A mixture's bad values: the same words from the scene (at the species' key) and from C (at
/// the array field with its index); the species observables only for a mixture's species.
#[test]
fn a_mixture_gets_the_same_words() {
    let mut base = gdsmc_config::example3();
    base.kernel = gdsmc::GDSMC_KERNEL_HARD_SPHERES;
    (base.gamma, base.c, base.n, base.species) = (1.0, 1.0, 64, 2);
    base.species_count[..2].copy_from_slice(&[32, 32]);
    base.species_mass[..2].copy_from_slice(&[1.0, 2.0]);
    let mix = SCENE.replace(
        "[collisions]",
        "[[species]]\nfraction = 1.0\n[[species]]\nfraction = 1.0\nmass = 2.0\n[collisions]",
    );
    let cases: [MixtureCase<'_>; 4] = [
        (
            &["species[1].mass=-2"],
            "species[1].mass",
            "species_mass[1]",
            |c| c.species_mass[1] = -2.0,
        ),
        (
            &["species[0].temperature=-1"],
            "species[0].temperature",
            "species_temperature[0]",
            |c| c.species_temperature[0] = -1.0,
        ),
        (
            &["species[1].diameter=0"],
            "species[1].diameter",
            "species_diameter[1]",
            |c| c.species_diameter[1] = 0.0,
        ),
        (
            &[
                "collisions.restitution=",
                "collisions.pair_restitution=[[0.9, 0.8], [0.8, 1.5]]",
            ],
            "collisions.pair_restitution",
            "pair_restitution[2]",
            |c| {
                c.pair_restitution_set = 1;
                c.pair_restitution[..3].copy_from_slice(&[0.9, 0.8, 1.5]);
            },
        ),
    ];
    same_words(&base, &mix, &cases);
    // Counts that do not add up to n, and a species with none.
    let mut c = base;
    c.species_count[1] = 31;
    assert_eq!(
        c_error(&c),
        "config.n = 64 must equal the sum of config.species_count, 63"
    );
    c.species_count[..2].copy_from_slice(&[64, 0]);
    assert_eq!(c_error(&c), "config.species_count[1] must be >= 1, got 0");
}

/// A rough mixture's own rotation per species and pair: the same words from the scene (at the
/// species' or the rotation's key) and from C (at the array field with its index); and a scene
/// read by `gdsmc_config_from_toml` keeps every species' and pair's rotation.
#[test]
fn a_rough_mixture_gets_the_same_words() {
    let mut base = gdsmc_config::example3();
    base.kernel = gdsmc::GDSMC_KERNEL_HARD_SPHERES;
    (base.gamma, base.c, base.n, base.species, base.rough) = (1.0, 1.0, 64, 2, 1);
    base.tangential_restitution = 0.5;
    base.species_count[..2].copy_from_slice(&[32, 32]);
    base.species_mass[..2].copy_from_slice(&[1.0, 2.0]);
    base.species_rotation_set = 1;
    let mix = SCENE.replace(
        "[collisions]",
        "[[species]]\nfraction = 1.0\n[[species]]\nfraction = 1.0\nmass = 2.0\n[rotation]\ntangential_restitution = 0.5\n[collisions]",
    );
    let cases: [MixtureCase<'_>; 4] = [
        (
            &["species[1].inertia=0.9"],
            "species[1].inertia",
            "species_inertia[1]",
            |c| c.species_inertia[1] = 0.9,
        ),
        (
            &["species[0].rotation_temperature=-1"],
            "species[0].rotation_temperature",
            "species_rotation_temperature[0]",
            |c| c.species_rotation_temperature[0] = -1.0,
        ),
        (
            &["species[1].rotation_noise=-1"],
            "species[1].rotation_noise",
            "species_rotation_noise[1]",
            |c| c.species_rotation_noise[1] = -1.0,
        ),
        (
            &["rotation.pair_tangential_restitution=[[0.5, 0.2], [0.2, 1.5]]"],
            "rotation.pair_tangential_restitution",
            "pair_tangential_restitution[2]",
            |c| {
                c.pair_tangential_restitution_set = 1;
                c.pair_tangential_restitution[..3].copy_from_slice(&[0.5, 0.2, 1.5]);
            },
        ),
    ];
    same_words(&base, &mix, &cases);
    // The shipped rough disk mixture through gdsmc_config_from_toml: each species' inertia and
    // each pair's tangential restitution arrive.
    let text = std::fs::read_to_string(
        Path::new(env!("CARGO_MANIFEST_DIR")).join("../scenes/rough-disk-mixture-white-noise.toml"),
    )
    .unwrap();
    let toml = std::ffi::CString::new(text).unwrap();
    let mut c = gdsmc_config::example3();
    // SAFETY: a NUL-terminated string and a writable config.
    let status = unsafe { gdsmc::gdsmc_config_from_toml(toml.as_ptr(), &mut c) };
    assert_eq!(status, gdsmc_status::GDSMC_OK);
    assert_eq!((c.species, c.rough, c.dimension), (2, 1, 2));
    assert_eq!(c.species_rotation_set, 1);
    assert_eq!(&c.species_inertia[..2], &[0.5, 1.0]);
    assert_eq!(c.pair_tangential_restitution_set, 1);
    assert_eq!(&c.pair_tangential_restitution[..3], &[0.5, 0.0, 0.5]);
    // Its rotation per species (gdsmc_sim_species), and gdsmc_sim_rotation's refusal naming it.
    use gdsmc::{
        gdsmc_rotation_observables, gdsmc_sim_destroy, gdsmc_sim_rotation, gdsmc_sim_species,
        gdsmc_species_observables,
    };
    let mut good = base;
    good.species_inertia[..2].copy_from_slice(&[0.4, 0.2]);
    good.species_rotation_temperature[..2].copy_from_slice(&[1.0, 3.0]);
    let mut sim: *mut gdsmc_sim = std::ptr::null_mut();
    // SAFETY: valid pointers; the handle is destroyed below.
    unsafe {
        assert_eq!(gdsmc_sim_create(&good, &mut sim), gdsmc_status::GDSMC_OK);
        let mut so = gdsmc_species_observables::default();
        for k in 0..2 {
            assert_eq!(gdsmc_sim_species(sim, k, &mut so), gdsmc_status::GDSMC_OK);
            assert!(so.rotational_temperature > 0.0, "{so:?}");
            assert_eq!(so.theta, so.rotational_temperature / so.temperature);
        }
        let mut r = gdsmc_rotation_observables::default();
        assert_eq!(
            gdsmc_sim_rotation(sim, &mut r),
            gdsmc_status::GDSMC_INVALID_ARGUMENT
        );
        let mut buf = vec![0u8; 512];
        let len = gdsmc_last_error(buf.as_mut_ptr().cast(), buf.len());
        assert_eq!(
            std::str::from_utf8(&buf[..len]).unwrap(),
            "a rough mixture's rotation is per species: gdsmc_sim_species"
        );
        assert_eq!(gdsmc_sim_destroy(&mut sim), gdsmc_status::GDSMC_OK);
    }
}

/// `gdsmc_sim_species` reads a mixture's species and refuses anything else by name.
#[test]
fn species_observables_only_for_a_mixture() {
    use gdsmc::{gdsmc_sim_destroy, gdsmc_sim_species, gdsmc_species_observables};
    let read = |c: &gdsmc_config, k: u32| {
        let mut sim: *mut gdsmc_sim = std::ptr::null_mut();
        // SAFETY: valid pointers.
        assert_eq!(
            unsafe { gdsmc_sim_create(c, &mut sim) },
            gdsmc_status::GDSMC_OK
        );
        let mut o = gdsmc_species_observables::default();
        // SAFETY: a live handle and a writable struct.
        let status = unsafe { gdsmc_sim_species(sim, k, &mut o) };
        let mut buf = vec![0u8; 512];
        // SAFETY: a writable buffer of its length.
        let len = unsafe { gdsmc_last_error(buf.as_mut_ptr().cast(), buf.len()) };
        // SAFETY: the handle from create.
        unsafe { gdsmc_sim_destroy(&mut sim) };
        (status, o, String::from_utf8(buf[..len].to_vec()).unwrap())
    };
    let one = gdsmc_config::example3();
    let (status, _, msg) = read(&one, 0);
    assert_eq!(status, gdsmc_status::GDSMC_INVALID_ARGUMENT);
    assert_eq!(msg, "the simulation is not a mixture (config.species = 0)");
    let mut mix = one;
    mix.species = 2;
    mix.species_count[..2].copy_from_slice(&[512, 512]);
    mix.species_mass[..2].copy_from_slice(&[1.0, 3.0]);
    mix.species_temperature[..2].copy_from_slice(&[1.0, 3.0]);
    let (status, o, _) = read(&mix, 1);
    assert_eq!(status, gdsmc_status::GDSMC_OK);
    assert_eq!(o.count, 512);
    // Start temperature 3 with 512 particles: within its 99.9% interval (sd 3 sqrt(2/3)/sqrt(512)).
    assert!(
        (o.temperature - 3.0).abs() < gdsmc_stats::LAMBDA_999 * 3.0 * (2.0f64 / 3.0 / 512.0).sqrt(),
        "{o:?}"
    );
    assert!((o.temperature_ratio - o.temperature / o.mixture_temperature).abs() < 1e-15);
    let (status, _, msg) = read(&mix, 2);
    assert_eq!(status, gdsmc_status::GDSMC_INVALID_ARGUMENT);
    assert_eq!(msg, "k = 2 is not a species: the mixture has 2");
}
