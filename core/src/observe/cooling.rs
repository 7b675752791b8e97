//! The collisional cooling of any gas at an observation: the collision frequency `nu` and the
//! reduced cooling rate `zeta* = zeta / nu`, `zeta = -(dE/dt)_coll / E` of the energy `E`
//! about the bulk velocity (translation and, for rough particles, rotation), estimated from
//! random pairs collided by the loop's own kernel, direction law and collision map.
//!
//! Every pair `(i, j)` collides at `int B de / n` (GRW Section 3), its energy changing by
//! `Delta E_ij` (the map's draw of the direction included). Over `K` uniform pairs `i != j`,
//! with `r = int B de` of the pair and `e = E / n`:
//!
//! ```text
//! nu    = (n - 1)/n <r>                       (collisions per particle per unit time: ds/dt)
//! zeta* = -<r Delta E> / (2 e <r>)            (= -(d ln E / ds)_coll)
//! ```
//!
//! both unbiased in their sums given the velocities (the ratio is consistent: its bias is
//! `O(1/K)`). `zeta*` is a ratio of energies and rates, so it is the same in stored and
//! physical units; the collisions conserve momentum, so a frame's offset drops out of
//! `Delta E`. The pairs collide in a scratch system of two particles: the gas is untouched
//! and the loop's counts too. Checked against exact and Maxwellian values in
//! tests/tests/cooling_rate.rs: for the Maxwell kernel `zeta* = (1 - alpha^2)/4 n/(n - 1)`
//! for every state (GRW (3) with `e` uniform: `<Delta E> = -(1 - alpha^2)|u|^2/8`), for hard
//! particles at a Maxwellian `(1 - alpha^2)/d` (`<(u . n)^2>` over collisions is `4 T`).

use crate::math::Real;
use crate::particles::{Particle, Particles, Spin};
use crate::rng::{Rng, uniform_pair};
use crate::vec3::Vec3;

/// The collisional cooling of a gas now (module docs).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Cooling {
    /// `nu`: collisions per particle per unit time (physical), the rate of `s`.
    pub frequency: Real,
    /// `zeta* = zeta / nu` of the whole energy about the bulk velocity (translation and
    /// rotation).
    pub zeta_star: Real,
}

impl Cooling {
    /// `zeta = zeta* nu`, per unit time: for a gas heated by nothing, `-(d ln T/dt)`.
    pub fn zeta(&self) -> Real {
        self.zeta_star * self.frequency
    }
}

/// Kinetic energy `m |v|^2 / 2` (`m` a mass or a mass times `kappa`).
#[inline(always)]
fn kinetic(m: Real, v: Vec3) -> Real {
    0.5 * m * v.norm2()
}

/// The cooling of the synchronized particles `p` (stored velocities: a frame's scale and
/// offset drop out, module docs) from `pairs >= 1` uniform pairs drawn from `rng`. `inertia(i)`
/// is particle `i`'s `(m, m kappa)` (`kappa` 0 for smooth particles); `collide((i, j), s,
/// rng)` collides the scratch system `s` (particle 0 holding `i`, 1 holding `j`, spins
/// beside them when `p` has spins) as the loop collides `i` with `j`, and returns the pair's
/// `int B de` at its physical relative velocity. Weighted particles ([`Particles::weighted`])
/// count each particle by its weight and each pair by `g_i g_j` (the pairs it stands for), the
/// rates per unit weight.
pub fn estimate<R: Rng + ?Sized>(
    p: &Particles<'_>,
    pairs: u64,
    rng: &mut R,
    inertia: impl Fn(usize) -> (Real, Real),
    mut collide: impl FnMut((usize, usize), &mut Particles<'_>, &mut R) -> Real,
) -> Cooling {
    let n = p.len();
    let spins = p.has_spins();
    let (mut mass, mut momentum) = (0.0, Vec3::ZERO);
    for i in 0..n {
        let m = inertia(i).0;
        let m = m * p.weight(i);
        mass += m;
        momentum += m * p.velocity(i);
    }
    let bulk = (1.0 / mass) * momentum;
    let mut energy = 0.0;
    for i in 0..n {
        let (m, mk) = inertia(i);
        let w = p.weight(i);
        energy += w * kinetic(m, p.velocity(i) - bulk);
        if spins {
            energy += w * kinetic(mk, p.spin(i));
        }
    }
    let (mut rate, mut loss) = (0.0, 0.0);
    for _ in 0..pairs {
        let (i, j) = uniform_pair(rng, n);
        let ((mi, ki), (mj, kj)) = (inertia(i), inertia(j));
        let (vi, vj) = (p.velocity(i), p.velocity(j));
        let (wi, wj) = if spins {
            (p.spin(i), p.spin(j))
        } else {
            (Vec3::ZERO, Vec3::ZERO)
        };
        let before = kinetic(mi, vi) + kinetic(mj, vj) + kinetic(ki, wi) + kinetic(kj, wj);
        let mut buf = [Particle::new(vi, 0.0), Particle::new(vj, 0.0)];
        let mut rims = [Spin::new(wi), Spin::new(wj)];
        let mut s = if spins {
            Particles::with_spins(&mut buf, &mut rims)
        } else {
            Particles::new(&mut buf)
        }
        .expect("two particles and two spins make a system");
        let r = collide((i, j), &mut s, rng);
        let (a, b) = (s.velocity(0), s.velocity(1));
        let (wa, wb) = if spins {
            (s.spin(0), s.spin(1))
        } else {
            (Vec3::ZERO, Vec3::ZERO)
        };
        let after = kinetic(mi, a) + kinetic(mj, b) + kinetic(ki, wa) + kinetic(kj, wb);
        // Weighted particles: the pair stands for g_i g_j physical pairs (1 otherwise).
        let r = r * (p.weight(i) * p.weight(j));
        rate += r;
        loss += r * (after - before);
    }
    let (frequency, per) = if p.is_weighted() {
        // nu = (2 / n0^2) sum_{i<j} g_i g_j r_ij over the N particles in use, n0 = sum g.
        let w0 = p.mass();
        let nn = n as Real;
        (nn * (nn - 1.0) / (w0 * w0) * rate / pairs as Real, w0)
    } else {
        (
            (n - 1) as Real / n as Real * rate / pairs as Real,
            n as Real,
        )
    };
    // e = energy / n, in stored units as the changes are.
    let zeta_star = -loss / (2.0 * (energy / per) * rate);
    Cooling {
        frequency,
        zeta_star,
    }
}
