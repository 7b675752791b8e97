//! The registry asks a drive what it declares (issue 78): every drive of the combination
//! matrix gets the Maxwell gas's exact temperature references exactly when it declares a
//! linear temperature law.

use super::combinations::{Block, LAWS, drives, kernels, scene_of};
use gdsmc_core::physics::{DimensionChoice, KernelKind, SchemeChoice};
use gdsmc_theory::curves::registry::REFERENCES;

/// Every drive the matrix runs gets the Maxwell gas's exact temperature references (GRW
/// (13)-(14), at finite n and n -> infinity) exactly when it declares a linear temperature law
/// (`Model::heating`), in d = 2 and 3: the registry asks the drive, it keeps no list of kinds
/// (issue 78: a drag drive that declared its heating as Langevin does got nothing until a hand
/// list was edited).
#[test]
fn every_drive_that_declares_linear_heating_gets_the_exact_temperature() {
    let maxwell = kernels()
        .into_iter()
        .find(|(_, k)| k.kind() == KernelKind::Maxwell)
        .expect("the Maxwell kernel")
        .1;
    for dim in [DimensionChoice::Three, DimensionChoice::Two] {
        let b = Block {
            rough: false,
            mixture: false,
            dim,
        };
        for (name, drive) in drives() {
            let ph = b.physics(maxwell, LAWS[0].1, drive, SchemeChoice::NoSplitting);
            let (Ok(model), Some(s)) = (ph.validate(), scene_of(&ph)) else {
                continue;
            };
            let ids: Vec<&str> = REFERENCES
                .iter()
                .filter(|r| r.holds.of(&s) && !(r.curves)(&s).is_empty())
                .map(|r| r.id)
                .collect();
            let linear = model.heating().is_some();
            for id in ["GRW (13)-(14)", "GRW (13)-(14) at finite n"] {
                assert_eq!(
                    ids.contains(&id),
                    linear,
                    "{name} in d = {}: {id} attached {}, heating declared {linear}",
                    dim.d(),
                    ids.contains(&id)
                );
            }
        }
    }
}
