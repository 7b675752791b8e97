//! The registry's tests: citation words, every reference declared once and on axes that
//! hold for something, none for a kernel without an exponent.

use super::*;

#[test]
fn a_citation_is_a_whole_name() {
    assert!(cites("against MS (10), mu4", "MS (10)"));
    assert!(!cites("T_bulk_exact here", "T_exact"));
    assert!(!cites("MS (100)", "MS (10)"));
    assert!(cites("the exact T_bulk_mean_n.", "T_bulk_mean_n"));
    assert!(!cites("a2_sonine_x", "a2_sonine"));
}

/// No reference holds for a kernel that is not a power law: each declares a kernel axis,
/// and none of those takes a kernel without an exponent ([`Kernels::holds`]).
#[test]
fn no_reference_holds_for_a_kernel_without_an_exponent() {
    for r in REFERENCES {
        for (hard, impact) in [(false, false), (true, false), (false, true)] {
            assert!(!r.holds.kernels.holds(hard, impact, None), "{}", r.id);
        }
    }
}

#[test]
fn every_reference_is_declared_once() {
    let mut ids: Vec<&str> = REFERENCES.iter().map(|r| r.id).collect();
    ids.sort_unstable();
    ids.dedup();
    assert_eq!(ids.len(), REFERENCES.len());
    for r in REFERENCES {
        for axis in [
            r.holds.drives.is_empty(),
            r.holds.dimensions.is_empty(),
            r.columns.is_empty(),
        ] {
            assert!(!axis, "{}: an empty axis holds for nothing", r.id);
        }
    }
}
