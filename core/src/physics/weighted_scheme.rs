//! The validated weighted scheme ([`super::SchemeKind::Weighted`]): its transfer, its
//! buffers' room, the reduction's aim and shares and the weight windows, from the values of
//! its declared parameters (`super::schemes`), each refused with the rule it breaks.

use super::error::{Param, PhysicsError, Problem};
use super::{DriveChoice, DriveKind, SchemeKind, WEIGHTED_PARAMS};
use crate::math::Real;

/// The validated weighted scheme: its transfer, and its buffers' room and the reduction's aim
/// in multiples of the particles a run starts with.
#[derive(Clone, Copy, Debug, PartialEq)]
#[cfg_attr(not(feature = "weighted"), allow(dead_code))]
pub(super) struct WeightedModel {
    pub(super) transfer: crate::weighted::Transfer,
    pub(super) capacity: Real,
    pub(super) target: Real,
    pub(super) exponent: Real,
    /// The share of a reduction's particles spread equally over the occupied shells.
    pub(super) floor: Real,
    /// The weight windows' split ([`crate::weighted::windows`]; 0: none).
    pub(super) split: Real,
}

/// The speed shells of the weighted scheme's reduction (`exponent`'s words say 32).
#[cfg_attr(not(feature = "weighted"), allow(dead_code))]
const WEIGHTED_SHELLS: usize = 32;

impl WeightedModel {
    /// The particles the buffers of a run of `n` hold.
    #[cfg_attr(not(feature = "weighted"), allow(dead_code))]
    pub(super) fn capacity(&self, n: usize) -> usize {
        libm::ceil(self.capacity * n as Real) as usize
    }

    /// The reduction of a run of `n` particles.
    #[cfg_attr(not(feature = "weighted"), allow(dead_code))]
    pub(super) fn reduction(&self, n: usize) -> crate::weighted::Reduction {
        crate::weighted::Reduction::Allocated {
            target: (libm::round(self.target * n as Real) as usize).max(2),
            shells: WEIGHTED_SHELLS,
            exponent: self.exponent,
            floor: self.floor,
        }
    }
}

/// The weighted scheme of the parameter values `values` (in the order of
/// [`SchemeKind::params`], each already within its rule) under the drive `d`: refused for a
/// drive no exact loop runs or the host medium, a tail transfer below the core's, a target not
/// below the capacity.
#[cfg_attr(not(feature = "weighted"), allow(dead_code))]
pub(super) fn validate(
    [
        kappa,
        tail_kappa,
        tail_speed,
        capacity,
        target,
        exponent,
        floor,
        split,
    ]: [Real; WEIGHTED_PARAMS],
    d: DriveChoice,
) -> Result<WeightedModel, PhysicsError> {
    let kind = SchemeKind::Weighted;
    let refuse = |param, problem| Err(PhysicsError { param, problem });
    if let Some(why) = d.kind().stepped_only() {
        return refuse(Param::Scheme, Problem::DoesNotFit(why));
    }
    if d.kind() == DriveKind::HostMedium {
        return refuse(
            Param::Scheme,
            Problem::DoesNotFit(
                "runs drives that act on each particle in closed form, not the host medium's \
                 collisions",
            ),
        );
    }
    let Some(transfer) = crate::weighted::Transfer::with_tail(kappa, tail_kappa, tail_speed) else {
        return refuse(
            Param::Step(kind, 1),
            Problem::DoesNotFit("must be at least kappa"),
        );
    };
    if target >= capacity {
        return refuse(
            Param::Step(kind, 4),
            Problem::DoesNotFit("must be below capacity"),
        );
    }
    Ok(WeightedModel {
        transfer,
        capacity,
        target,
        exponent,
        floor,
        split,
    })
}
