//! What is observed of a mixture: the whole gas's moments and each species' own, and the
//! species temperatures `T_s = (m_s / d) <|v - U|^2>_s` about the mixture's flow velocity
//! `U = sum_s m_s N_s V_s / sum_s m_s N_s` (Garzó and Dufty 1999, (5)-(6)); for rough
//! particles each species' rotational observables and temperature
//! `T_rot,s = m_s kappa_s <|w|^2>_s / d_rot` (Santos, Kremer and Garzó 2010, (2.9)).

use super::rotation::RoughObservables;
use crate::geometry::DimensionChoice;
use crate::math::Real;
use crate::moments::Observables;
use crate::particles::{Particle, Spin};
use crate::species::{MAX_SPECIES, Species};
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
    /// The dimension (temperatures count its degrees of freedom).
    pub dim: DimensionChoice,
    /// Rough particles: each species' rotational observables, per unit mass (entries past the
    /// species count repeat the last); `None` for smooth particles.
    pub rotation: Option<[RoughObservables; MAX_SPECIES]>,
}

impl MixtureObservables {
    /// The observables of the particles `q` (all at one time) of the species `sp`, spheres.
    pub fn of(q: &[Particle], sp: &Species) -> Self {
        Self::of_dim(q, sp, DimensionChoice::Three)
    }

    /// As [`MixtureObservables::of`] in dimension `dim`.
    pub fn of_dim(q: &[Particle], sp: &Species, dim: DimensionChoice) -> Self {
        let d = dim.d();
        let all = Observables::from_sums_dim(&crate::batch::sums::accumulate(q), d);
        let mut species = [Observables::default(); MAX_SPECIES];
        let mut counts = [0; MAX_SPECIES];
        let mut masses = [1.0; MAX_SPECIES];
        for s in 0..sp.len() {
            species[s] = if sp.len() == 1 {
                all
            } else {
                Observables::from_sums_dim(&crate::batch::sums::accumulate(&q[sp.range(s)]), d)
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
            dim,
            rotation: None,
        }
    }

    /// With each species' rotational observables: the rim velocities `spins` (beside the
    /// particles, stored `w_phys = scale w`) and the species' reduced moments of inertia.
    #[must_use]
    pub fn with_rotation(
        mut self,
        q: &[Particle],
        spins: &[Spin],
        sp: &Species,
        kappa: &[Real],
        scale: Real,
    ) -> Self {
        let mut rot = [RoughObservables::default(); MAX_SPECIES];
        for s in 0..sp.len() {
            let r = sp.range(s);
            rot[s] =
                RoughObservables::of_parts(&q[r.clone()], &spins[r], kappa[s], scale, self.dim);
        }
        for s in sp.len()..MAX_SPECIES {
            rot[s] = rot[sp.len() - 1];
        }
        self.rotation = Some(rot);
        self
    }

    /// The same observables for velocities `offset + scale v` ([`Observables::in_units`]); the
    /// rotation is left as it is (it is computed in physical units).
    pub fn in_units(&self, scale: Real, offset: Vec3) -> Self {
        let d = self.dim.d();
        let mut o = *self;
        o.all = self.all.in_units_dim(scale, offset, d);
        for s in 0..self.len {
            o.species[s] = self.species[s].in_units_dim(scale, offset, d);
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
    /// `T_s = m_s (T_bulk,s + |V_s - U|^2 / d)` (Garzó and Dufty 1999, (6)).
    pub fn temperature(&self, s: usize) -> Real {
        let d = self.species[s].bulk - self.flow_velocity();
        self.masses[s] * (self.species[s].t_bulk + d.norm2() / self.dim.d() as Real)
    }

    /// The rotational temperature of species `s`, `T_rot,s = m_s kappa_s <|w|^2>_s / d_rot`;
    /// `None` for smooth particles.
    pub fn rotational_temperature(&self, s: usize) -> Option<Real> {
        self.rotation.map(|r| self.masses[s] * r[s].t_rot)
    }

    /// The mixture's rotational temperature `sum_s x_s T_rot,s`; `None` for smooth particles.
    pub fn mixture_rotational_temperature(&self) -> Option<Real> {
        let n: usize = self.counts[..self.len].iter().sum();
        let mut t = 0.0;
        for s in 0..self.len {
            t += self.counts[s] as Real / n as Real * self.rotational_temperature(s)?;
        }
        Some(t)
    }

    /// The mixture temperature `T = sum_s x_s T_s` (Garzó and Dufty 1999, (6)).
    pub fn mixture_temperature(&self) -> Real {
        let n: usize = self.counts[..self.len].iter().sum();
        (0..self.len)
            .map(|s| self.counts[s] as Real / n as Real * self.temperature(s))
            .sum()
    }
}

impl From<MixtureObservables> for Observables {
    /// The whole gas's moments.
    fn from(m: MixtureObservables) -> Observables {
        m.all
    }
}
