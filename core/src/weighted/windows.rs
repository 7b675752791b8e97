//! Weight windows: a particle heavier than its speed shell's share is split into pieces of
//! about the share, so that the thin tail is carried by many light particles however a
//! particle got there (a collision, or a drive's kicks), the splitting of Monte Carlo
//! transport's weight windows (Booth, "A weight window/importance generator for Monte Carlo
//! streaming problems", LA-UR 1983; Rjasanow and Wagner 2001's rare events ask the same of
//! the particle system: particles where the quantity of interest is, lighter).
//!
//! The shares are the allocated reduction's ([`super::reduce::reduce_allocated`]): the speed
//! shells of equal width about the flow up to the fastest particle (or to [`REACH`] thermal
//! speeds, the last shell holding every particle beyond), shell `s` of weight `W_s`
//! given `K_s = target (phi / S + (1 - phi) W_s^q / sum W^q)` particles (`S` the occupied
//! shells: a share `phi` of the particles spread equally, so that the thin tail keeps some
//! however light it is, the rest by a power of the weight, so that the core keeps most),
//! each about `w_s = W_s / K_s`. Splitting a
//! particle of weight `g` into `m` copies of `g/m` at its velocity keeps the measure `sum g
//! delta_v` itself (not only in expectation): every weighted sum, the mass, momentum and
//! energy, to rounding. The copies then part by their own collisions and kicks. A split is a
//! change of state at an event's instant, after the event (the next waiting time is drawn at
//! the new rate, as after a reduction), so the process stays exact. The loop also passes every
//! particle through the windows at every refresh, where they are measured again
//! ([`super::nosplit`]'s `split` module).

use crate::math::{Real, sqrt};
use crate::vec3::Vec3;

/// The most speed shells an allocation cuts ([`Allocation`]).
pub const MAX_SHELLS: usize = 64;

/// How far the speed shells reach about the flow, in units of `sqrt(T) = sqrt(<|v - V|^2>/d)`
/// (the weighted mean): the shells are of equal width up to the fastest particle or to this,
/// whichever is nearer, and a particle beyond is in the last shell.
///
/// Up to the fastest alone, the shells were as wide as the tail was long. In the inelastic
/// Maxwell gas's cooling state, whose tail is a power law `c^-(d + s)` (Ernst and Brito 2002),
/// the light particles the windows make reach far beyond the speeds a run observes (the weight
/// beyond 28 sqrt(T) was about 3e-10 of the whole), and the 32 shells then put the
/// tail's first decades of probability into one or two shells of one share each: the local
/// slope over `[x, 2x]` was resolved only to `x = 3` (`c = |v - V|/sqrt(2 T)`; at alpha = 1/2,
/// d = 3), 8% below the exact root, and 15-80 times less efficient than equal weights. Up to
/// 32 sqrt(T) (the shells `sqrt(T)` wide) it is resolved to `x = 10`, and the
/// exponent extrapolated from it is within 0.3% of the root (docs/weighted.md "The cooling
/// state's tail exponent"). Runs whose fastest particle stays within 32 sqrt(T) are
/// unchanged bit for bit (GRW Example 3's heated tail; Example 6's reaches beyond).
pub const REACH: Real = 32.0;

/// The most pieces one split makes (a particle still heavier than its window is split again
/// when it is next touched).
pub const MAX_PIECES: usize = 64;

/// The allocated reduction's shells and each shell's particle weight `w_s = W_s / K_s`
/// (module docs), measured from one set of particles.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Allocation {
    /// The flow the speeds are taken about.
    pub flow: Vec3,
    /// Shells per unit of speed (0 when every particle sits at the flow).
    pub per: Real,
    /// The shells in use (at most [`MAX_SHELLS`]).
    pub shells: usize,
    /// Each shell's weight `W_s`.
    pub weights: [Real; MAX_SHELLS],
    /// Each shell's particle weight `w_s` (an empty shell: the nearest slower shell's, or the
    /// nearest faster one's below the slowest occupied shell).
    pub each: [Real; MAX_SHELLS],
}

impl Allocation {
    /// The allocation of the `(speed about flow, weight)` of every particle, the fastest at
    /// `fastest` and their `sqrt(T)`, `thermal` (the shells reach the nearer of `fastest`
    /// and [`REACH`] `thermal`).
    pub(crate) fn measure(
        particles: impl Iterator<Item = (Real, Real)>,
        flow: Vec3,
        (fastest, thermal): (Real, Real),
        (target, shells, q, floor): (usize, usize, Real, Real),
    ) -> Self {
        let reach = REACH * thermal;
        let top = if fastest > reach { reach } else { fastest };
        let shells = shells.clamp(1, MAX_SHELLS);
        let per = if top > 0.0 { shells as Real / top } else { 0.0 };
        let mut a = Allocation {
            flow,
            per,
            shells,
            weights: [0.0; MAX_SHELLS],
            each: [0.0; MAX_SHELLS],
        };
        for (c, g) in particles {
            a.weights[a.shell(c)] += g;
        }
        let norm: Real = (a.weights[..shells].iter())
            .filter(|&&w| w > 0.0)
            .map(|&w| libm::pow(w, q))
            .sum();
        let occupied = a.weights[..shells].iter().filter(|&&w| w > 0.0).count() as Real;
        let (even, by_weight) = (
            floor * target as Real / occupied,
            (1.0 - floor) * target as Real,
        );
        let mut last = None;
        for s in 0..shells {
            let ws = a.weights[s];
            if ws > 0.0 {
                let keep = even + by_weight * libm::pow(ws, q) / norm;
                a.each[s] = ws / keep;
                last = Some(a.each[s]);
            } else if let Some(w) = last {
                a.each[s] = w;
            }
        }
        // Empty shells below the slowest occupied one take its share.
        if let Some(first) = (0..shells).find(|&s| a.weights[s] > 0.0) {
            let w = a.each[first];
            a.each[..first].fill(w);
        }
        a
    }

    /// The shell of speed `c` (the last beyond the fastest).
    #[inline(always)]
    pub fn shell(&self, c: Real) -> usize {
        shell_of(c, self.per, self.shells)
    }
}

/// The shell of speed `c` among `shells` of `per` to the unit of speed (the last beyond).
#[inline(always)]
fn shell_of(c: Real, per: Real, shells: usize) -> usize {
    ((c * per) as usize).min(shells - 1)
}

/// The weight windows of a weighted loop: a particle heavier than `split` times its shell's
/// share ([`Allocation::each`]) is cut into `round(g / w_s)` pieces (module docs).
/// Only the shares are kept (not the shells' weights: a loop holds one, and the C ABI's
/// handles and the firmwares hold the loop).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Windows {
    flow: Vec3,
    per: Real,
    shells: usize,
    each: [Real; MAX_SHELLS],
    split: Real,
}

impl Windows {
    /// Windows of the allocation `allocation`, splitting a particle heavier than `split > 0`
    /// times its shell's share.
    pub fn new(allocation: Allocation, split: Real) -> Self {
        let Allocation {
            flow,
            per,
            shells,
            each,
            ..
        } = allocation;
        Windows {
            flow,
            per,
            shells,
            each,
            split,
        }
    }

    /// The pieces a particle of velocity `v` and weight `g` is to be cut into (1: kept whole),
    /// at most [`MAX_PIECES`].
    #[inline(always)]
    pub fn pieces(&self, v: Vec3, g: Real) -> usize {
        let c = sqrt((v - self.flow).norm2());
        let w = self.each[shell_of(c, self.per, self.shells)];
        // `w > 0` for every shell (an occupied one's weight, or a neighbour's share).
        if g <= self.split * w {
            return 1;
        }
        let m = libm::round(g / w);
        if m >= MAX_PIECES as Real {
            MAX_PIECES
        } else {
            m as usize
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Shells of width 1 (4 up to speed 4): weights 8, 0, 2, 1 (the fastest particle in the
    /// last shell). At `q = 0` every occupied shell is given `target / 3` particles, so its
    /// share is its weight over that; the empty shell takes the slower neighbour's. At `q = 1`
    /// every share is `sum W / target`, as equal weights have.
    #[test]
    fn the_shares_are_the_allocated_reductions() {
        let parts = [(0.5, 8.0), (2.5, 2.0), (4.0, 1.0)];
        let a = Allocation::measure(parts.into_iter(), Vec3::ZERO, (4.0, 1.0), (6, 4, 0.0, 0.0));
        assert_eq!(a.per, 1.0);
        assert_eq!(&a.weights[..4], &[8.0, 0.0, 2.0, 1.0]);
        assert_eq!(&a.each[..4], &[4.0, 4.0, 1.0, 0.5]);
        let b = Allocation::measure(parts.into_iter(), Vec3::ZERO, (4.0, 1.0), (11, 4, 1.0, 0.0));
        for s in [0, 2, 3] {
            assert!((b.each[s] - 1.0).abs() < 1e-15, "{s}: {}", b.each[s]);
        }
        // A floor of 1/2 at q = 1: 11/2 particles by weight (each shell's share of them
        // 11/2 W_s/11) and 11/6 to each occupied shell: K = 4 + 11/6, 11/6, 1/2 + 11/6.
        let f = Allocation::measure(parts.into_iter(), Vec3::ZERO, (4.0, 1.0), (11, 4, 1.0, 0.5));
        let k = [4.0 + 11.0 / 6.0, 1.0 + 11.0 / 6.0, 0.5 + 11.0 / 6.0];
        for (s, (w, k)) in [(0, (8.0, k[0])), (2, (2.0, k[1])), (3, (1.0, k[2]))] {
            assert!((f.each[s] - w / k).abs() < 1e-14, "{s}: {}", f.each[s]);
        }
        // Empty shells below the slowest occupied one take its share.
        let c = Allocation::measure(
            [(3.5, 1.0)].into_iter(),
            Vec3::ZERO,
            (4.0, 1.0),
            (2, 4, 0.0, 0.0),
        );
        assert_eq!(&c.each[..4], &[0.5; 4]);
    }

    /// The shells reach [`REACH`] `sqrt(T)` when the fastest particle is farther: a light
    /// particle far out no longer widens every shell, and it shares the last shell's share.
    #[test]
    fn the_shells_reach_so_many_thermal_speeds() {
        let parts = [(0.5, 8.0), (2.5, 2.0), (4.0, 1.0), (1000.0, 1e-9)];
        let a = Allocation::measure(
            parts.into_iter(),
            Vec3::ZERO,
            (1000.0, 1.0),
            (6, 32, 0.0, 0.0),
        );
        assert_eq!(a.per, 32.0 / REACH, "shells sqrt(T) wide");
        assert_eq!(a.shell(2.5), 2);
        assert_eq!(a.shell(1000.0), 31, "beyond the reach: the last shell");
        assert_eq!(a.weights[31], 1e-9);
        let near = Allocation::measure(
            parts.into_iter(),
            Vec3::ZERO,
            (1000.0, 100.0),
            (6, 32, 0.0, 0.0),
        );
        assert_eq!(
            near.per,
            32.0 / 1000.0,
            "within the reach: up to the fastest"
        );
        assert_eq!(near.shell(4.0), 0);
    }

    /// A particle is split when heavier than `split` times its shell's share, into
    /// `round(g / w_s)` pieces, at most [`MAX_PIECES`]; the speed is taken about the flow.
    #[test]
    fn a_particle_heavier_than_its_window_is_cut_to_its_share() {
        let flow = Vec3::new(10.0, 0.0, 0.0);
        let parts = [(0.5, 8.0), (2.5, 2.0), (4.0, 1.0)];
        let w = Windows::new(
            Allocation::measure(parts.into_iter(), flow, (4.0, 1.0), (6, 4, 0.0, 0.0)),
            2.0,
        );
        let at = |c: Real| flow + Vec3::new(0.0, c, 0.0);
        assert_eq!(w.pieces(at(0.5), 8.0), 1, "8 = 2 shares: not above");
        assert_eq!(w.pieces(at(0.5), 8.5), 2);
        assert_eq!(w.pieces(at(2.5), 2.0), 1);
        assert_eq!(w.pieces(at(2.5), 3.0), 3);
        assert_eq!(
            w.pieces(at(9.0), 3.0),
            6,
            "beyond the fastest: the last shell's share"
        );
        assert_eq!(w.pieces(at(3.2), 1e6), MAX_PIECES);
        // 0.5 from zero is 9.5 from the flow: the last shell's share, not the first's.
        assert_eq!(w.pieces(Vec3::new(0.5, 0.0, 0.0), 3.0), 6, "about the flow");
    }
}
