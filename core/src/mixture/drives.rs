//! The species' drives of the mixture loops: every species kicked with its own drive, and
//! what each drive is told at a synchronization.

use crate::drive::Drive;
use crate::math::Real;
use crate::observe::MixtureObservables;
use crate::particles::Particles;
use crate::rng::Rng;
use crate::species::{MAX_SPECIES, Species};

/// Brings every particle of `p` to `t`, each species `s` with `drives[s]` (a one-species
/// mixture with the drive's batch kernel, as the one-species loop), counting a host medium's
/// events in `background`.
pub(super) fn kick_species<D: Drive, R: Rng + ?Sized>(
    drives: &[D; MAX_SPECIES],
    sp: &Species,
    p: &mut Particles<'_>,
    t: Real,
    rng: &mut R,
    background: &mut u64,
) {
    if sp.len() == 1 {
        drives[0].kick_all_counting(p, t, rng, background);
    } else if D::COUPLES {
        // One drive for every species (validated), its correction over all of them.
        let groups: [(core::ops::Range<usize>, Real); MAX_SPECIES] = core::array::from_fn(|s| {
            let s = s.min(sp.len() - 1);
            (sp.range(s), sp.mass(s))
        });
        drives[0].kick_weighted(p, &groups[..sp.len()], t, rng);
    } else {
        for (s, drive) in drives.iter().enumerate().take(sp.len()) {
            for i in sp.range(s) {
                drive.kick_counting(p, i, t, rng, background);
            }
        }
    }
}

/// Tells each species' drive the synchronized observables `obs`: drives that act about a
/// centre (the Gaussian thermostat) get the mixture's flow velocity, which collisions keep
/// (and such a drive too), so that kicks between synchronizations stay exact; each species'
/// own moments otherwise.
pub(super) fn tell_drives<D: Drive>(drives: &mut [D; MAX_SPECIES], obs: &MixtureObservables) {
    let flow = if obs.len == 1 {
        obs.species[0].bulk // the same bits as the one-species loop
    } else {
        obs.flow_velocity()
    };
    for (s, drive) in drives.iter_mut().enumerate().take(obs.len) {
        let mut seen = obs.species[s];
        seen.bulk = flow;
        drive.observe(&seen);
    }
}
