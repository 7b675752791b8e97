//! The weight transfer of a collision (Rjasanow and Wagner 1996): how much weight moves from a
//! colliding pair to its post-collision velocities, and the jump itself.

use crate::math::Real;
use crate::particles::{Particle, Particles, ParticlesError};
use crate::vec3::Vec3;

/// The weight transfer function `gamma(g_i, g_j) = min(g_i, g_j) / (1 + kappa)`, `kappa >= 0`
/// (Rjasanow and Wagner 1996): `kappa = 0` moves the lighter partner whole (equal weights stay
/// equal: GRW's process), `kappa > 0` leaves a share `kappa/(1 + kappa)` of it behind.
///
/// With a tail ([`Transfer::with_tail`]) `kappa` depends on the collision's outcome: a
/// collision that sends a partner beyond `speed sqrt(T)` from the flow moves
/// `min(g_i, g_j)/(1 + kappa_tail)`, any other `min/(1 + kappa)`. The rate of each outcome is
/// then `(1 + kappa(outcome)) max(g_i, g_j) B / n0`, so the rate times the weight moved stays
/// `g_i g_j B / n0` outcome by outcome: the same Boltzmann operator, with the tail reached by
/// more, lighter particles (the importance sampling of Rjasanow and Wagner 2001's rare
/// events), while a collision in the core moves whole weights and makes no new particle.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Transfer {
    kappa: Real,
    /// `(kappa_tail, speed)`: the tail's `kappa` and where it starts, in units of `sqrt(T)`.
    tail: Option<(Real, Real)>,
}

impl Transfer {
    /// The transfer with parameter `kappa`: finite and >= 0, else `None`.
    pub fn new(kappa: Real) -> Option<Self> {
        (kappa.is_finite() && kappa >= 0.0).then_some(Transfer { kappa, tail: None })
    }

    /// `kappa` in the core and `kappa_tail >= kappa` for a collision that sends a partner
    /// beyond `speed > 0` `sqrt(T)` from the flow (finite values), else `None`.
    pub fn with_tail(kappa: Real, kappa_tail: Real, speed: Real) -> Option<Self> {
        let ok = kappa_tail.is_finite() && kappa_tail >= kappa && speed.is_finite() && speed > 0.0;
        if !ok {
            return None;
        }
        let mut t = Transfer::new(kappa)?;
        t.tail = Some((kappa_tail, speed));
        Some(t)
    }

    /// `kappa` (in the core, with a tail).
    pub fn kappa(&self) -> Real {
        self.kappa
    }

    /// The tail's `(kappa_tail, speed)`, if any.
    pub fn tail(&self) -> Option<(Real, Real)> {
        self.tail
    }

    /// The largest `kappa` of any outcome: the majorant's.
    pub fn kappa_max(&self) -> Real {
        self.tail.map_or(self.kappa, |(k, _)| k)
    }

    /// `gamma(g_i, g_j)`.
    #[inline(always)]
    pub fn gamma(&self, gi: Real, gj: Real) -> Real {
        let m = if gi < gj { gi } else { gj };
        if self.kappa == 0.0 {
            m
        } else {
            m / (1.0 + self.kappa)
        }
    }

    /// The pair's rate factor `g_i g_j / gamma(g_i, g_j) = (1 + kappa) max(g_i, g_j)`: the
    /// pair collides at `int B de` times it over `n0`, so that rate times `gamma` is
    /// `g_i g_j int B de / n0` (module docs of [`super`]).
    #[inline(always)]
    pub fn rate_factor(&self, gi: Real, gj: Real) -> Real {
        let m = if gi < gj { gj } else { gi };
        (1.0 + self.kappa) * m
    }
}

/// The collision at time `t` of the weighted particles `i != j` of `p` (both last kicked at
/// `t`) with post-collision velocities `(vi, vj)` under `transfer`: both lose `gamma`, and
/// `gamma` appears at `vi` and at `vj` (in place of a partner whose weight is used up, else as
/// a new particle last kicked at `t`); returns `gamma`. [`ParticlesError::Full`] (and nothing
/// changed) when the new particles do not fit.
pub fn collide(
    p: &mut Particles<'_>,
    pair: (usize, usize),
    (velocities, t): ((Vec3, Vec3), Real),
    transfer: &Transfer,
) -> Result<Real, ParticlesError> {
    collide_with(p, pair, (velocities, t), transfer.kappa)
}

/// As [`collide`] with the transfer's `kappa` of this outcome (a tail's, [`Transfer::with_tail`]).
pub fn collide_with(
    p: &mut Particles<'_>,
    (i, j): (usize, usize),
    ((vi, vj), t): ((Vec3, Vec3), Real),
    kappa: Real,
) -> Result<Real, ParticlesError> {
    let (gi, gj) = (p.weight(i), p.weight(j));
    let gamma = Transfer { kappa, tail: None }.gamma(gi, gj);
    // `g - gamma` is exactly 0 when gamma is that weight (kappa = 0, the lighter partner).
    let (ri, rj) = (gi - gamma, gj - gamma);
    let needed = usize::from(ri > 0.0) + usize::from(rj > 0.0);
    if p.len() + needed > p.capacity() || !p.is_weighted() {
        return Err(ParticlesError::Full);
    }
    for (k, rest, v) in [(i, ri, vi), (j, rj, vj)] {
        if rest > 0.0 {
            p.set_weight(k, rest);
        } else {
            *p.get_mut(k) = Particle::new(v, t);
            p.set_weight(k, gamma);
        }
    }
    for (rest, v) in [(ri, vi), (rj, vj)] {
        if rest > 0.0 {
            p.push(v, gamma, t)?;
        }
    }
    Ok(gamma)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::collision::inelastic;
    use crate::weighted::moments::{energy, momentum};

    fn sums(s: &Particles<'_>) -> (Real, Vec3, Real) {
        (s.mass(), momentum(s), energy(s))
    }

    /// Records of velocities `vs` in a buffer of 6, with room for 4 more.
    fn records(vs: &[Vec3]) -> [Particle; 6] {
        core::array::from_fn(|k| Particle::new(vs.get(k).copied().unwrap_or(Vec3::ZERO), 0.0))
    }

    /// With `kappa = 0` and equal weights a collision is GRW's: the pair replaced, no particle
    /// added. With `kappa > 0` the jump moves `gamma` to the new velocities: the weighted sums
    /// of `1`, `v` and `|v|^2/2` change by `gamma` times the pair's change, and the rate factor
    /// times `gamma` is `g_i g_j` (the Boltzmann operator's weight of the pair).
    #[test]
    fn a_collision_moves_gamma_to_the_new_velocities() {
        let (v, w) = (Vec3::new(1.0, 0.5, -0.2), Vec3::new(-0.3, 0.1, 0.8));
        let e = Vec3::new(0.0, 0.6, 0.8);
        let (a, b) = inelastic(v, w, e, 0.7);
        let pair_loss = 0.5 * (a.norm2() + b.norm2() - v.norm2() - w.norm2());
        let mut buf = records(&[v, w]);
        let mut g = [1.0; 6];
        let mut sys = Particles::weighted(&mut buf, &mut g, 2).unwrap();
        let t0 = Transfer::new(0.0).unwrap();
        collide(&mut sys, (0, 1), ((a, b), 0.5), &t0).unwrap();
        assert_eq!(sys.weight(1), 1.0);
        assert_eq!(sys.len(), 2);
        assert_eq!(
            (sys.as_slice()[0], sys.weight(0)),
            (Particle::new(a, 0.5), 1.0)
        );

        let t = Transfer::new(1.0).unwrap();
        let (gi, gj) = (1.0, 0.25);
        let mut buf = records(&[v, w]);
        let mut g = [gi, gj, 0.0, 0.0, 0.0, 0.0];
        let mut sys = Particles::weighted(&mut buf, &mut g, 2).unwrap();
        let (m0, p0, e0) = sums(&sys);
        collide(&mut sys, (0, 1), ((a, b), 0.5), &t).unwrap();
        let gamma = t.gamma(gi, gj);
        assert_eq!(gamma, 0.125);
        assert_eq!(t.rate_factor(gi, gj) * gamma, gi * gj);
        assert_eq!(sys.len(), 4);
        assert_eq!(
            sys.kick_time(3),
            0.5,
            "a new particle starts at the collision"
        );
        let (m1, p1, e1) = sums(&sys);
        assert!((m1 - m0).abs() < 1e-15);
        assert!((p1 - p0).norm() < 1e-15);
        assert!((e1 - e0 - gamma * pair_loss).abs() < 1e-15);
    }

    /// A collision that does not fit changes nothing; particles without weights refuse.
    #[test]
    fn a_full_buffer_refuses_and_changes_nothing() {
        let v = Vec3::new(1.0, 0.0, 0.0);
        let mut buf = [Particle::new(v, 0.0), Particle::new(-v, 0.0)];
        let mut g = [1.0, 0.5];
        let mut sys = Particles::weighted(&mut buf, &mut g, 2).unwrap();
        let t = Transfer::new(0.0).unwrap();
        let before = [sys.as_slice()[0], sys.as_slice()[1]];
        assert_eq!(
            collide(&mut sys, (0, 1), ((v, v), 0.0), &t),
            Err(ParticlesError::Full)
        );
        assert_eq!(sys.as_slice(), &before);
        assert_eq!(sys.weights(), &[1.0, 0.5]);
        let mut plain = [Particle::new(v, 0.0), Particle::new(-v, 0.0)];
        let mut p = Particles::new(&mut plain).unwrap();
        assert_eq!(
            collide(&mut p, (0, 1), ((v, v), 0.0), &t),
            Err(ParticlesError::Full)
        );
        assert!(Transfer::new(-1.0).is_none() && Transfer::new(Real::NAN).is_none());
    }

    /// A tail's `kappa` is at least the core's and its speed > 0; the majorant takes the
    /// larger, and an outcome's own `kappa` sets the weight it moves.
    #[test]
    fn a_tail_transfer_keeps_its_rules() {
        let t = Transfer::with_tail(0.0, 7.0, 3.0).unwrap();
        assert_eq!(
            (t.kappa(), t.kappa_max(), t.tail()),
            (0.0, 7.0, Some((7.0, 3.0)))
        );
        assert_eq!(Transfer::new(1.0).unwrap().kappa_max(), 1.0);
        for (k, kt, c) in [
            (1.0, 0.5, 3.0),
            (0.0, 7.0, 0.0),
            (0.0, Real::INFINITY, 3.0),
            (-1.0, 1.0, 3.0),
        ] {
            assert!(Transfer::with_tail(k, kt, c).is_none(), "{k} {kt} {c}");
        }
        let v = Vec3::new(1.0, 0.0, 0.0);
        let mut buf = records(&[v, -v]);
        let mut g = [1.0; 6];
        let mut sys = Particles::weighted(&mut buf, &mut g, 2).unwrap();
        collide_with(&mut sys, (0, 1), ((-v, v), 0.0), 7.0).unwrap();
        assert_eq!(sys.len(), 4);
        assert_eq!((sys.velocity(2), sys.weight(2)), (-v, 0.125));
    }
}
