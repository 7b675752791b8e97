//! The species of a mixture: how many particles of each, their masses, and the pair types
//! `(s, t)`, `s <= t`, with their pair counts.
//!
//! The particles of species `s` occupy the contiguous range `offset(s) .. offset(s) + count(s)`
//! of the caller's buffer, so choosing a particle uniformly within a species is one uniform
//! index: the pair type is chosen by its majorant rate, the particles uniformly within their
//! species (the DSMC of granular mixtures, Montanero and Garzó 2002).

use crate::math::Real;

/// The largest number of species a mixture may have (the core keeps per-species state in
/// fixed arrays: no allocation).
pub const MAX_SPECIES: usize = 4;

/// The largest number of pair types `(s, t)`, `s <= t`: `MAX_SPECIES (MAX_SPECIES + 1) / 2`.
pub const MAX_PAIRS: usize = MAX_SPECIES * (MAX_SPECIES + 1) / 2;

/// The index of the pair of species `(s, t)` (either order) among `species` species, in the
/// order `(0,0), (0,1), .., (0,S-1), (1,1), ..` of every per-pair array (the core's, the C
/// struct's `pair_restitution`, the references').
pub fn pair_index(species: usize, s: usize, t: usize) -> usize {
    let (s, t) = if s <= t { (s, t) } else { (t, s) };
    // Rows 0..s hold S, S-1, .., S-s+1 entries.
    s * species - s * s.saturating_sub(1) / 2 + (t - s)
}

/// A mixture description that cannot be simulated.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum MixtureError {
    /// No species, or more than [`MAX_SPECIES`].
    SpeciesCount(usize),
    /// A species has no particle.
    EmptySpecies(usize),
    /// Fewer than two particles in all.
    TooFewParticles,
    /// More particles in all than memory can address (the counts' sum overflows).
    TooManyParticles,
    /// A species' mass is not finite and positive.
    Mass(usize),
    /// The per-pair data (kernels, restitution) do not hold one entry per pair type.
    PairCount {
        /// Entries expected: `S (S + 1) / 2`.
        expected: usize,
        /// Entries given.
        got: usize,
    },
    /// The particle buffer does not hold the species' total count.
    ParticleCount,
}

impl core::fmt::Display for MixtureError {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        match self {
            MixtureError::SpeciesCount(s) => {
                write!(f, "a mixture has 1 to {MAX_SPECIES} species, got {s}")
            }
            MixtureError::EmptySpecies(s) => write!(f, "species {s} has no particle"),
            MixtureError::TooFewParticles => f.write_str("a mixture needs at least 2 particles"),
            MixtureError::TooManyParticles => {
                f.write_str("the species' counts add up to more particles than memory can address")
            }
            MixtureError::Mass(s) => write!(f, "the mass of species {s} must be finite and > 0"),
            MixtureError::PairCount { expected, got } => write!(
                f,
                "one entry per pair of species is needed ({expected}), got {got}"
            ),
            MixtureError::ParticleCount => {
                f.write_str("the particle buffer does not hold the species' particles")
            }
        }
    }
}

impl core::error::Error for MixtureError {}

/// Species counts and masses, and the pair types in the order `(0,0), (0,1), .., (0,S-1),
/// (1,1), .., (S-1,S-1)` (the order of every per-pair array).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Species {
    count: [usize; MAX_SPECIES],
    offset: [usize; MAX_SPECIES],
    mass: [Real; MAX_SPECIES],
    species: usize,
    total: usize,
}

impl Species {
    /// Species `s` with `counts[s]` particles of mass `masses[s]`.
    pub fn new(counts: &[usize], masses: &[Real]) -> Result<Self, MixtureError> {
        let s = counts.len();
        if s == 0 || s > MAX_SPECIES || masses.len() != s {
            return Err(MixtureError::SpeciesCount(s.max(masses.len())));
        }
        let mut sp = Species {
            count: [0; MAX_SPECIES],
            offset: [0; MAX_SPECIES],
            mass: [1.0; MAX_SPECIES],
            species: s,
            total: 0,
        };
        for k in 0..s {
            if counts[k] == 0 {
                return Err(MixtureError::EmptySpecies(k));
            }
            if !(masses[k].is_finite() && masses[k] > 0.0) {
                return Err(MixtureError::Mass(k));
            }
            sp.count[k] = counts[k];
            sp.offset[k] = sp.total;
            sp.mass[k] = masses[k];
            sp.total = sp
                .total
                .checked_add(counts[k])
                .ok_or(MixtureError::TooManyParticles)?;
        }
        // The particle count's one rule (crate::particles::check_count).
        crate::particles::check_count(sp.total).map_err(|e| match e {
            crate::particles::ParticlesError::TooFew => MixtureError::TooFewParticles,
            _ => MixtureError::TooManyParticles,
        })?;
        Ok(sp)
    }

    /// Number of species `S`.
    pub fn len(&self) -> usize {
        self.species
    }

    /// Always false: a mixture has at least one species.
    pub fn is_empty(&self) -> bool {
        false
    }

    /// Total number of particles `N`.
    pub fn total(&self) -> usize {
        self.total
    }

    /// Particles of species `s`, `N_s`.
    #[inline(always)]
    pub fn count(&self, s: usize) -> usize {
        self.count[s]
    }

    /// Index of the first particle of species `s`.
    #[inline(always)]
    pub fn offset(&self, s: usize) -> usize {
        self.offset[s]
    }

    /// The index range of species `s`.
    pub fn range(&self, s: usize) -> core::ops::Range<usize> {
        self.offset[s]..self.offset[s] + self.count[s]
    }

    /// Mass of species `s`.
    #[inline(always)]
    pub fn mass(&self, s: usize) -> Real {
        self.mass[s]
    }

    /// Mole (number) fraction `x_s = N_s / N`.
    pub fn fraction(&self, s: usize) -> Real {
        self.count[s] as Real / self.total as Real
    }

    /// Number of pair types, `S (S + 1) / 2`.
    pub fn pair_types(&self) -> usize {
        self.species * (self.species + 1) / 2
    }

    /// The species `(s, t)`, `s <= t`, of pair type `k`.
    pub fn pair(&self, k: usize) -> (usize, usize) {
        let mut k = k;
        for s in 0..self.species {
            let row = self.species - s;
            if k < row {
                return (s, s + k);
            }
            k -= row;
        }
        (self.species, self.species)
    }

    /// The pair type of species `s` and `t` (in either order).
    pub fn pair_index(&self, s: usize, t: usize) -> usize {
        pair_index(self.species, s, t)
    }

    /// Unordered pairs of type `(s, t)`: `N_s N_t` for `s != t`, `N_s (N_s - 1) / 2` for
    /// `s = t`.
    pub fn pairs(&self, s: usize, t: usize) -> Real {
        if s == t {
            0.5 * self.count[s] as Real * (self.count[s] - 1) as Real
        } else {
            self.count[s] as Real * self.count[t] as Real
        }
    }
}
