//! The validated dimension of a [`super::Physics`]: disks (`d = 2`, [`crate::geometry`]) run
//! the loops composed for them: the no-splitting scheme, the Euler and Strang splittings
//! (RW Algorithms 1-2) and, for smooth hard disks of one species, MS's time-stepped scheme, with either
//! restitution law (BRS (10)'s normal speed follows from the map GRW (3) in any dimension),
//! and every drive but the host medium (white noise in the plane; the thermostats about the
//! peculiar velocity, which stays in the plane), as in three dimensions, and start drifts in
//! the plane.

use super::error::{Param, PhysicsError, Problem};
use super::parts::DriveModel;
use super::{DimensionChoice, Physics};

fn refuse<T>(param: Param, why: &'static str) -> Result<T, PhysicsError> {
    Err(PhysicsError {
        param,
        problem: Problem::DoesNotFit(why),
    })
}

/// Validates the dimension of `physics` against the drive already validated (every scheme runs
/// on disks: MS's time-stepped one on smooth hard disks, `TimeStepped<D, A, Disks>`; a rough
/// gas or a mixture refuses it on its own account).
pub(super) fn dimension(
    physics: &Physics,
    drive: DriveModel,
) -> Result<DimensionChoice, PhysicsError> {
    if physics.dimension == DimensionChoice::Three {
        return Ok(DimensionChoice::Three);
    }
    // The Gaussian thermostat scales the peculiar velocity, `v - V` (MS (61)), and the
    // constant force pushes along it (MS (14)): both stay in the plane. The host medium's
    // partners and impact directions are drawn in three dimensions (BRS (29)).
    if matches!(
        drive,
        DriveModel::HostMaxwell(_) | DriveModel::HostHardSpheres(_)
    ) {
        return refuse(
            Param::Dimension,
            "of 2 (disks) takes no host medium (BRS's background kernels, rates and partner \
             density (28)-(29) are written for spheres)",
        );
    }
    for (k, c) in physics.initial.iter().enumerate() {
        if c.drift[2] != 0.0 {
            return refuse(Param::Drift(k), "must lie in the plane (z = 0) for disks");
        }
    }
    Ok(DimensionChoice::Two)
}
