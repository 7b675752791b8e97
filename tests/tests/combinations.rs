//! The combination matrix of docs/combinations.md, generated from the code: every combination
//! of particle model (smooth, rough), species (one, two), dimension (3, 2), kernel (every kernel
//! the core declares), restitution law (constant, impact speed), drive (none, white noise,
//! every drive declared by its type, host medium) and scheme (no-splitting, Euler, Strang,
//! time-stepped, weighted) is described as a core `Physics` and validated. A combination the core takes
//! is launched and advanced here (n = 16, to t = 0.5) and must give finite observables: that is
//! the test behind each "runs". A refused one shows the core's own refusal (the parameter and
//! its rule, one place for each rule). The checked-in table must equal the generated one;
//! `GDSMC_UPDATE_DOCS=1 cargo test --release -p gdsmc-validation --test all combinations` rewrites it.
//! With `GDSMC_COMBO_DUMP=FILE` it also appends every run's observables and counts to `FILE`:
//! the bits of all 912 combinations before and after a change of the engine's composition.

use gdsmc_core::engine::EventLoop;
use gdsmc_core::particles::{Particle, Particles, Spin};
use gdsmc_core::physics::{
    BackgroundKernel, DimensionChoice, DriveChoice, DriveKind, DriveParams, KernelChoice,
    KernelKind, LawKind, Physics, RestitutionLaw, RotationChoice, SchemeChoice, SchemeKind,
    SpeciesChoice,
};
use gdsmc_core::rng::stream;
use gdsmc_theory::curves::registry::REFERENCES;
use std::collections::BTreeMap;
use std::fmt::Write as _;
use std::io::Write as _;
use std::path::PathBuf;

const N: usize = 16;
const T_END: f64 = 0.5;

/// The kernels of the matrix: every kernel the core declares, `gamma = 1`, `C = 0.1` and its
/// own parameters' example values (from its declaration), named by its title ("hard-sphere").
pub(super) fn kernels() -> Vec<(&'static str, KernelChoice)> {
    KernelKind::ALL
        .iter()
        .map(|&k| {
            let name = k.title().strip_suffix(" kernel").unwrap_or(k.title());
            (name, KernelChoice::example(k, 1.0, 0.1))
        })
        .collect()
}

pub(super) const LAWS: [(&str, RestitutionLaw); 2] = [
    ("constant", RestitutionLaw::Constant(0.8)),
    (
        "impact speed",
        RestitutionLaw::ImpactSpeed {
            beta0: 0.1,
            delta: 0.2,
        },
    ),
];

/// The drives of the matrix: the cooling gas, white noise, every drive declared by its type
/// with its parameters' example values (from its declaration in the core, named by its title),
/// the host medium last.
pub(super) fn drives() -> Vec<(&'static str, DriveChoice)> {
    let mut drives = vec![
        ("none", DriveChoice::None),
        ("white noise", DriveChoice::WhiteNoise(0.5)),
    ];
    for &k in DriveKind::ALL {
        if let (Some(title), Some(d)) = (k.title(), DriveParams::example(k)) {
            drives.push((title, DriveChoice::Declared(d)));
        }
    }
    drives.push((
        "host medium",
        DriveChoice::HostMedium {
            kernel: BackgroundKernel::HardSpheres,
            c1: 1.0,
            density: 1.0,
            mass: 1.0,
            temperature: 1.0,
            drift: [0.0; 3],
        },
    ));
    drives
}

/// The schemes of the matrix; the weighted scheme with its parameters' example values (from
/// its declaration in the core).
fn schemes() -> [(&'static str, SchemeChoice); 5] {
    let weighted = gdsmc_core::declared::examples::<{ gdsmc_core::physics::WEIGHTED_PARAMS }>(
        SchemeKind::Weighted.params(),
    );
    [
        ("no-splitting", SchemeChoice::NoSplitting),
        ("Euler", SchemeChoice::Euler(0.125)),
        ("Strang", SchemeChoice::Strang(0.125)),
        ("time-stepped", SchemeChoice::TimeStepped(0.01)),
        (
            "weighted",
            SchemeChoice::new(SchemeKind::Weighted, &weighted).expect("its examples make it"),
        ),
    ]
}

/// The matrix holds every kind the core declares, in the core's order: a kernel, law, drive or
/// scheme added to the core and not here fails this test (and is then missing from the table
/// and the 912-combination dump).
#[test]
fn the_matrix_holds_every_kind() {
    assert_eq!(
        kernels().iter().map(|k| k.1.kind()).collect::<Vec<_>>(),
        KernelKind::ALL
    );
    assert_eq!(LAWS.map(|l| l.1.kind()), LawKind::ALL);
    assert_eq!(drives().iter().map(|d| d.1.kind()).collect::<Vec<_>>(), {
        // The table's order: the cooling gas, then the heating drives, the host medium last.
        let mut k = DriveKind::ALL.to_vec();
        k.sort_by_key(|k| matches!(k, DriveKind::HostMedium));
        k
    });
    assert_eq!(schemes().map(|s| s.1.kind()), SchemeKind::ALL);
}

/// One block of the table: particle model, species, dimension.
#[derive(Clone, Copy)]
pub(super) struct Block {
    pub(super) rough: bool,
    pub(super) mixture: bool,
    pub(super) dim: DimensionChoice,
}

impl Block {
    fn title(&self) -> String {
        format!(
            "{}, {}, {}",
            if self.rough { "Rough" } else { "Smooth" },
            if self.mixture {
                "two species"
            } else {
                "one species"
            },
            match self.dim {
                DimensionChoice::Three => "spheres (d = 3)",
                DimensionChoice::Two => "disks (d = 2)",
            }
        )
    }

    pub(super) fn physics(
        &self,
        kernel: KernelChoice,
        law: RestitutionLaw,
        drive: DriveChoice,
        scheme: SchemeChoice,
    ) -> Physics {
        let mut ph = Physics::new(N, kernel, law, drive, scheme);
        ph.dimension = self.dim;
        if self.mixture {
            for (count, mass) in [(N / 2, 1.0), (N / 2, 2.0)] {
                ph.species
                    .push(SpeciesChoice {
                        beta: 0.5,
                        ..SpeciesChoice::new(count, mass, 1.0)
                    })
                    .expect("two species fit");
            }
        }
        if self.rough {
            ph.rotation = Some(RotationChoice {
                temperature: 1.0,
                ..RotationChoice::uniform(self.dim, 0.5)
            });
        }
        ph
    }
}

/// `Ok(())` when the combination validates, launches and advances to finite observables;
/// `Err(reason)` with the core's refusal otherwise. A combination that validates but fails to
/// run panics: the core took it, so it must run.
fn outcome(ph: &Physics, what: &str) -> Result<(), String> {
    let model = ph.validate().map_err(|e| e.to_string())?;
    let mut buf = vec![Particle::default(); model.capacity()];
    let mut spins = vec![Spin::default(); N];
    let mut weights = vec![1.0; model.capacity()];
    let mut p = if model.weighted() {
        Particles::weighted(&mut buf, &mut weights, N).expect("n weights of 1")
    } else if model.rotates() {
        Particles::with_spins(&mut buf, &mut spins).expect("equal lengths")
    } else {
        Particles::new(&mut buf).expect("n >= 2")
    };
    let mut rng = stream(7, 0);
    let (mut e, _) = model
        .launch(&mut p, 0.0, &mut rng)
        .unwrap_or_else(|err| panic!("{what}: validated but does not start: {err:?}"));
    let obs = e
        .advance_to(&mut p, T_END, &mut rng)
        .unwrap_or_else(|err| panic!("{what}: validated but does not run: {err:?}"));
    assert!(
        obs.non_finite().is_none() && obs.t_bulk > 0.0,
        "{what}: {obs:?}"
    );
    if let Some(path) = std::env::var_os("GDSMC_COMBO_DUMP") {
        // Every combination's observables and counts, for a refactor's before/after
        // comparison of the bits (the file is appended to).
        let mut f = std::fs::OpenOptions::new()
            .create(true)
            .append(true)
            .open(path)
            .expect("the dump file opens");
        writeln!(f, "{what}: {obs:?} {:?}", e.counts()).expect("the dump is written");
    }
    Ok(())
}

/// GRW Example 3's scene given the physics `ph` (its 17 observation times over [0, 8], no
/// steady window), or `None` where the scene's rules refuse it.
pub(super) fn scene_of(ph: &Physics) -> Option<gdsmc_runner::scene::Scene> {
    let mut s = gdsmc_validation::shipped("grw-example3", N, 1, 1);
    s.set_steady_from(None).expect("no steady window");
    s.with_physics(|p| *p = ph.clone()).ok()?;
    Some(s)
}

/// The numbers (from 1, in the registry's order) of the references whose curves the runner
/// attaches to the physics `ph`.
fn references_of(ph: &Physics) -> Vec<String> {
    let Some(s) = scene_of(ph) else {
        return Vec::new();
    };
    REFERENCES
        .iter()
        .enumerate()
        .filter(|(_, r)| r.holds.of(&s) && !(r.curves)(&s).is_empty())
        .map(|(k, _)| (k + 1).to_string())
        .collect()
}

/// The markdown of docs/combinations.md.
fn generate() -> String {
    let mut reasons: BTreeMap<String, usize> = BTreeMap::new();
    let mut body = String::new();
    let mut runs = 0;
    let mut total = 0;
    for rough in [false, true] {
        for mixture in [false, true] {
            for dim in [DimensionChoice::Three, DimensionChoice::Two] {
                let b = Block {
                    rough,
                    mixture,
                    dim,
                };
                writeln!(body, "\n## {}\n", b.title()).unwrap();
                let head: Vec<&str> = schemes().iter().map(|s| s.0).collect();
                writeln!(body, "| drive | law | {} |", head.join(" | ")).unwrap();
                writeln!(body, "|---|---|{}", "---|".repeat(head.len())).unwrap();
                for (dname, drive) in drives() {
                    for (lname, law) in LAWS {
                        let mut cells = Vec::new();
                        for (sname, scheme) in schemes() {
                            // Per kernel: "runs" or the refusal's footnote number.
                            let mut by_outcome: Vec<(String, Vec<&str>)> = Vec::new();
                            for (kname, kernel) in kernels() {
                                let what =
                                    format!("{}; {kname}; {lname}; {dname}; {sname}", b.title());
                                let ph = b.physics(kernel, law, drive, scheme);
                                total += 1;
                                let cell = match outcome(&ph, &what) {
                                    Ok(()) => {
                                        runs += 1;
                                        let refs = references_of(&ph);
                                        if refs.is_empty() {
                                            "runs".to_string()
                                        } else {
                                            format!("runs [{}]", refs.join(", "))
                                        }
                                    }
                                    Err(r) => {
                                        let k = reasons.len() + 1;
                                        format!("({})", *reasons.entry(r).or_insert(k))
                                    }
                                };
                                match by_outcome.iter_mut().find(|(c, _)| *c == cell) {
                                    Some((_, ks)) => ks.push(kname),
                                    None => by_outcome.push((cell, vec![kname])),
                                }
                            }
                            cells.push(if by_outcome.len() == 1 {
                                by_outcome[0].0.clone()
                            } else {
                                by_outcome
                                    .iter()
                                    .map(|(c, ks)| format!("{}: {c}", ks.join(", ")))
                                    .collect::<Vec<_>>()
                                    .join("; ")
                            });
                        }
                        writeln!(body, "| {dname} | {lname} | {} |", cells.join(" | ")).unwrap();
                    }
                }
            }
        }
    }
    let mut out = String::new();
    let kernels: Vec<&str> = KernelKind::ALL.iter().map(|k| k.title()).collect();
    let kernels = kernels.join(", ");
    writeln!(out, "# Combinations of the physics").unwrap();
    writeln!(
        out,
        "\nGenerated by tests/tests/combinations.rs from the core's validation (do not edit; \
         `GDSMC_UPDATE_DOCS=1 cargo test --release -p gdsmc-validation --test all combinations` rewrites \
         it, and CI fails when it differs). Every combination of particle model, species, \
         dimension, kernel ({kernels}), restitution \
         law, drive and scheme is described and validated; each cell marked \"runs\" was \
         launched and advanced by that test (n = {N}, to t = {T_END}) to finite observables, and \
         each refused one shows the core's refusal, numbered below. Where the kernels differ \
         the cell names them.\n\n{runs} of {total} combinations run."
    )
    .unwrap();
    out.push_str(&body);
    writeln!(
        out,
        "\n## References\n\nThe references the runner attaches to a run (the numbers in \
         brackets above: every reference whose declaration in \
         theory/src/curves/registry/ holds for the combination and gives a \
         curve, for GRW Example 3's scene given that physics), each with what it is to the \
         run: the exact ensemble mean at n is judged by the verdict; a Boltzmann limit or an \
         approximation is shown beside the run, not judged.\n"
    )
    .unwrap();
    for (k, r) in REFERENCES.iter().enumerate() {
        writeln!(
            out,
            "{}. {} ({}): {}; holds for {}.",
            k + 1,
            r.id,
            r.kind.words(),
            r.columns.join(", "),
            r.holds.words()
        )
        .unwrap();
    }
    writeln!(out, "\n## Refusals\n").unwrap();
    let mut by_number: Vec<(usize, String)> = reasons.into_iter().map(|(r, k)| (k, r)).collect();
    by_number.sort();
    for (k, r) in by_number {
        writeln!(out, "{k}. {}", r.replace('\n', " ")).unwrap();
    }
    out
}

fn doc_path() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../docs/combinations.md")
}

#[test]
fn the_combination_table_is_the_codes() {
    let generated = generate();
    let path = doc_path();
    if std::env::var_os("GDSMC_UPDATE_DOCS").is_some() {
        std::fs::write(&path, &generated).expect("docs/combinations.md is writable");
        return;
    }
    let checked_in = std::fs::read_to_string(&path).unwrap_or_default();
    assert!(
        checked_in == generated,
        "docs/combinations.md is not the code's table: rerun with GDSMC_UPDATE_DOCS=1\n{generated}"
    );
}

/// Every reference gives its curves wherever its declaration holds, only the columns and kind
/// it declares, and a reference is a number or is absent, never NaN: every reference curve the runner attaches
/// to every combination the core takes (the scene of GRW Example 3 given that physics, its 17
/// observation times over [0, 8]) is finite at every time, and so are those of the elastic
/// cases where a state search has nothing to relax (an elastic perfectly rough mixture, whose
/// Maxwellian approximation was NaN, and an elastic smooth one).
#[test]
fn every_reference_of_every_combination_is_a_number() {
    let mut checked = 0;
    let mut check = |ph: &Physics, what: &str| {
        let Some(s) = scene_of(ph) else {
            return; // refused by the scene's rules (the table shows why)
        };
        for r in REFERENCES.iter().filter(|r| r.holds.of(&s)) {
            let curves = (r.curves)(&s);
            // A reference gives its curves wherever its declaration holds (but for a
            // condition its axes do not show, which its builder checks).
            assert!(
                !curves.is_empty() || r.holds.when.is_some(),
                "{what}: {} is declared to hold but gives no curve",
                r.id
            );
            for c in curves {
                assert!(
                    r.columns.contains(&c.name) && c.kind == r.kind,
                    "{what}: {} gives {} ({:?}), not declared",
                    r.id,
                    c.name,
                    c.kind
                );
                for &t in s.times() {
                    let v = (c.curve)(t);
                    assert!(v.is_finite(), "{what}: {} = {v} at t = {t}", c.name);
                }
            }
        }
        checked += 1;
    };
    let blocks = [false, true].into_iter().flat_map(|rough| {
        [false, true].into_iter().flat_map(move |mixture| {
            [DimensionChoice::Three, DimensionChoice::Two].map(|dim| Block {
                rough,
                mixture,
                dim,
            })
        })
    });
    for b in blocks {
        let (drives, kernels, schemes) = (drives(), kernels(), schemes());
        let (kernels, schemes) = (&kernels, &schemes);
        let cells = drives.iter().flat_map(|d| {
            LAWS.iter().flat_map(move |l| {
                schemes
                    .iter()
                    .flat_map(move |s| kernels.iter().map(move |k| (d, l, s, *k)))
            })
        });
        for ((dname, drive), (lname, law), (sname, scheme), (kname, kernel)) in cells {
            let ph = b.physics(kernel, *law, *drive, *scheme);
            if ph.validate().is_ok() {
                check(
                    &ph,
                    &format!("{}; {kname}; {lname}; {dname}; {sname}", b.title()),
                );
            }
        }
        // Elastic (and perfectly rough) cooling: nothing dissipates.
        let mut ph = b.physics(
            KernelChoice::hard_spheres(1.0, 0.1),
            RestitutionLaw::Constant(1.0),
            DriveChoice::None,
            SchemeChoice::NoSplitting,
        );
        if let Some(r) = ph.rotation.as_mut() {
            r.beta = 1.0;
        }
        check(&ph, &format!("{}; elastic", b.title()));
    }
    assert!(
        checked >= 900,
        "only {checked} combinations reached the runner"
    );
}
