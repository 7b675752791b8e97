//! The validated dimension of a [`super::Physics`]: disks (`d = 2`, [`crate::geometry`]) run
//! the loops composed for them: the no-splitting scheme, the Euler and Strang splittings
//! (RW Algorithms 1-2) and MS's time-stepped scheme, with either
//! restitution law (BRS (10)'s normal speed follows from the map GRW (3) in any dimension),
//! and every drive (white noise in the plane; the thermostats about the peculiar velocity,
//! which stays in the plane; the host medium of disks, [`crate::drive::host_medium`]), as in
//! three dimensions, and start and background drifts in the plane.

use super::error::{Param, PhysicsError, Problem};
use super::parts::DriveModel;
use super::{DimensionChoice, Physics};

fn refuse<T>(param: Param, why: &'static str) -> Result<T, PhysicsError> {
    Err(PhysicsError {
        param,
        problem: Problem::DoesNotFit(why),
    })
}

/// Refuses a host medium's drift out of the plane of disks.
fn in_plane(drift: crate::vec3::Vec3) -> Result<(), PhysicsError> {
    if drift.z != 0.0 {
        return refuse(
            Param::BackgroundDrift,
            "must lie in the plane (z = 0) for disks",
        );
    }
    Ok(())
}

/// Validates the dimension of `physics` against the drive already validated (every scheme runs
/// on disks: MS's time-stepped one as `TimeStepped<K, D, A, Disks>`; a mixture refuses it on
/// its own account).
pub(super) fn dimension(
    physics: &Physics,
    drive: DriveModel,
) -> Result<DimensionChoice, PhysicsError> {
    if physics.dimension == DimensionChoice::Three {
        return Ok(DimensionChoice::Three);
    }
    // The thermostats act about the peculiar velocity, `v - V` (MS (61), (14)), which stays
    // in the plane; the host medium's partners, directions and majorant are the plane's
    // (`drive::host_medium`), about a drift in the plane.
    if let DriveModel::HostMaxwell(h) = drive {
        in_plane(h.params.background.drift())?;
    }
    if let DriveModel::HostHardSpheres(h) = drive {
        in_plane(h.params.background.drift())?;
    }
    for (k, c) in physics.initial.iter().enumerate() {
        if c.drift[2] != 0.0 {
            return refuse(Param::Drift(k), "must lie in the plane (z = 0) for disks");
        }
    }
    Ok(DimensionChoice::Two)
}
