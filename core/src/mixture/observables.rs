//! What is observed of a mixture: the whole gas's moments and each species' own, and the
//! species temperatures `T_s = (m_s / 3) <|v - U|^2>_s` about the mixture's flow velocity
//! `U = sum_s m_s N_s V_s / sum_s m_s N_s` (Garzó and Dufty 1999, (5)-(6)).

use super::species::{MAX_SPECIES, Species};
use crate::math::Real;
use crate::moments::Observables;
use crate::particles::Particle;
use crate::vec3::Vec3;

/// The observables of a mixture at one time, in physical units.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct MixtureObservables {
    /// The moments of all particles together (velocities unweighted by mass).
    pub all: Observables,
    /// The moments of each species (about its own bulk velocity); entries past the species
    /// count are default.
    pub species: [Observables; MAX_SPECIES],
    /// Particles of each species.
    pub counts: [usize; MAX_SPECIES],
    /// Mass of each species.
    pub masses: [Real; MAX_SPECIES],
    /// Number of species.
    pub len: usize,
}

impl MixtureObservables {
    /// The observables of the particles `q` (all at one time) of the species `sp`.
    pub fn of(q: &[Particle], sp: &Species) -> Self {
        let all = Observables::from_sums(&crate::batch::sums::accumulate(q));
        let mut species = [Observables::default(); MAX_SPECIES];
        let mut counts = [0; MAX_SPECIES];
        let mut masses = [1.0; MAX_SPECIES];
        for s in 0..sp.len() {
            species[s] = if sp.len() == 1 {
                all
            } else {
                Observables::from_sums(&crate::batch::sums::accumulate(&q[sp.range(s)]))
            };
            counts[s] = sp.count(s);
            masses[s] = sp.mass(s);
        }
        MixtureObservables {
            all,
            species,
            counts,
            masses,
            len: sp.len(),
        }
    }

    /// The same observables for velocities `offset + scale v` ([`Observables::in_units`]).
    pub fn in_units(&self, scale: Real, offset: Vec3) -> Self {
        let mut o = *self;
        o.all = self.all.in_units(scale, offset);
        for s in 0..self.len {
            o.species[s] = self.species[s].in_units(scale, offset);
        }
        o
    }

    /// The mixture's flow velocity `U = sum_s m_s N_s V_s / sum_s m_s N_s`.
    pub fn flow_velocity(&self) -> Vec3 {
        let (mut p, mut m) = (Vec3::ZERO, 0.0);
        for s in 0..self.len {
            let w = self.masses[s] * self.counts[s] as Real;
            p += w * self.species[s].bulk;
            m += w;
        }
        (1.0 / m) * p
    }

    /// The temperature of species `s` about the flow velocity,
    /// `T_s = m_s (T_bulk,s + |V_s - U|^2 / 3)` (Garzó and Dufty 1999, (6)).
    pub fn temperature(&self, s: usize) -> Real {
        let d = self.species[s].bulk - self.flow_velocity();
        self.masses[s] * (self.species[s].t_bulk + d.norm2() / 3.0)
    }

    /// The mixture temperature `T = sum_s x_s T_s` (Garzó and Dufty 1999, (6)).
    pub fn mixture_temperature(&self) -> Real {
        let n: usize = self.counts[..self.len].iter().sum();
        (0..self.len)
            .map(|s| self.counts[s] as Real / n as Real * self.temperature(s))
            .sum()
    }
}
