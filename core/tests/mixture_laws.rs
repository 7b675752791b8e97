//! A mixture under BRS's impact-speed law (9)-(10), one law for every pair: with `delta = 0`
//! the law is the constant `alpha = 1 - 2 beta0` (BRS (10)), so the mixture follows the
//! constant law's trajectory to the last bit (the same draws, the same coefficient), for both
//! kernels, spheres and disks, cooling, heated and split; with `delta > 0` it does not. The
//! rules of the combination are refused by their keys.

use crate::common;

use common::kernels::{HARD, MAXWELL};

use gdsmc_core::physics::{
    DimensionChoice, DriveChoice, KernelChoice, Physics, RestitutionLaw, RotationChoice,
    SchemeChoice, SpeciesChoice,
};

fn mixture(
    kernel: KernelChoice,
    law: RestitutionLaw,
    how: (DimensionChoice, DriveChoice, SchemeChoice),
) -> Physics {
    let (dimension, drive, scheme) = how;
    let mut ph = Physics::new(96, kernel, law, drive, scheme);
    for (k, &(count, mass)) in [(64usize, 1.0), (32, 3.0)].iter().enumerate() {
        ph.species
            .push(SpeciesChoice {
                beta: 0.5 + 0.5 * k as f64,
                ..SpeciesChoice::new(count, mass, 1.0 + k as f64)
            })
            .unwrap();
    }
    ph.dimension = dimension;
    ph
}

/// `T_raw` at four times and every final velocity's bits, with the collision count.
fn trajectory(ph: &Physics) -> (Vec<u64>, u64) {
    common::trajectory_bits(ph, 43, &[0.5, 1.0, 2.0, 4.0])
}

#[test]
fn a_mixture_under_the_impact_speed_law_of_delta_0_is_the_constant_law_to_the_last_bit() {
    use DimensionChoice::{Three, Two};
    let beta0 = 0.05;
    let (none, hot) = (DriveChoice::None, DriveChoice::WhiteNoise(0.0));
    let euler = SchemeChoice::Euler(0.5);
    let exact = SchemeChoice::NoSplitting;
    for (kernel, how) in [
        (HARD, (Three, none, exact)),
        (HARD, (Three, hot, exact)),
        (MAXWELL, (Three, hot, exact)),
        (HARD, (Two, none, exact)),
        (
            MAXWELL,
            (
                Two,
                DriveChoice::declared(gdsmc_core::physics::DriveKind::Gaussian, &[0.2]).unwrap(),
                exact,
            ),
        ),
        (HARD, (Three, hot, euler)),
    ] {
        let constant = mixture(kernel, RestitutionLaw::Constant(1.0 - 2.0 * beta0), how);
        let impact = mixture(
            kernel,
            RestitutionLaw::ImpactSpeed { beta0, delta: 0.0 },
            how,
        );
        let (a, ca) = trajectory(&constant);
        let (b, cb) = trajectory(&impact);
        assert!(ca > 100, "{kernel:?}, {how:?}: {ca} collisions");
        assert_eq!((&a, ca), (&b, cb), "{kernel:?}, {how:?}");
        // The law acts: a velocity-dependent coefficient leaves the constant's trajectory.
        let moving = mixture(
            kernel,
            RestitutionLaw::ImpactSpeed { beta0, delta: 0.5 },
            how,
        );
        assert_ne!(
            trajectory(&moving).0,
            a,
            "{kernel:?}, {how:?}: delta = 0.5 changed nothing"
        );
    }
}

#[test]
fn the_impact_speed_laws_mixture_rules_are_refused_by_their_keys() {
    let how = (
        DimensionChoice::Three,
        DriveChoice::None,
        SchemeChoice::NoSplitting,
    );
    let law = RestitutionLaw::ImpactSpeed {
        beta0: 0.05,
        delta: 0.2,
    };
    let mut per_pair = mixture(HARD, law, how);
    per_pair
        .pair_restitution
        .extend_from_slice(&[0.9, 0.8, 0.7])
        .unwrap();
    assert_eq!(
        per_pair.validate().unwrap_err().to_string(),
        "restitution of species pair (0, 0) is not used with the impact-speed law, which is one \
         law for every pair"
    );
    // Rough mixtures take the law (core/tests/rough_laws.rs runs them).
    let mut rough = mixture(HARD, law, how);
    rough.rotation = Some(RotationChoice::spheres(0.0));
    assert!(rough.validate().unwrap().rotates());
}
