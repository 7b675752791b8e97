//! The particle system: velocities and last-kick times in a caller-owned buffer.
//!
//! One [`Particle`] per particle, 32 bytes aligned to 32: the collision loop touches particles
//! at random, and this layout makes each touch a single cache line (with four separate arrays
//! it would be four). The batch kernels load four particles as four `f64x4` rows and transpose
//! them into lanes. The core never allocates: the caller hands in the slice.

use crate::math::Real;
use crate::vec3::Vec3;

/// One particle: velocity and the time it was last kicked (RW Algorithm 3's `sigma_j`, GRW's
/// `t_j`). `#[repr(C)]` for the C ABI; 32 bytes, aligned to 32.
#[repr(C, align(32))]
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Particle {
    /// Velocity, x.
    pub vx: Real,
    /// Velocity, y.
    pub vy: Real,
    /// Velocity, z.
    pub vz: Real,
    /// Time of the last kick.
    pub t_kick: Real,
}

impl Particle {
    /// A particle with velocity `v` last kicked at `t`.
    #[inline(always)]
    pub const fn new(v: Vec3, t: Real) -> Self {
        Particle {
            vx: v.x,
            vy: v.y,
            vz: v.z,
            t_kick: t,
        }
    }

    /// The velocity.
    #[inline(always)]
    pub fn velocity(&self) -> Vec3 {
        Vec3::new(self.vx, self.vy, self.vz)
    }

    /// Sets the velocity.
    #[inline(always)]
    pub fn set_velocity(&mut self, v: Vec3) {
        self.vx = v.x;
        self.vy = v.y;
        self.vz = v.z;
    }
}

/// The rotation of one rough particle: its rim velocity `w = (sigma/2) omega` (the angular
/// velocity times the radius, [`crate::rough`]). A rough gas keeps one [`Spin`] per particle
/// in a second caller slice beside the [`Particle`]s, so that everything reading translation
/// (moments, histograms, the SIMD kicks, the C ABI's velocities) reads the same 32-byte
/// records as for a smooth gas. 32 bytes, aligned to 32: one cache line, like a particle.
#[repr(C, align(32))]
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Spin {
    /// Rim velocity, x.
    pub wx: Real,
    /// Rim velocity, y.
    pub wy: Real,
    /// Rim velocity, z.
    pub wz: Real,
    /// Unused (keeps the record one aligned half line).
    pub spare: Real,
}

impl Spin {
    /// The spin with rim velocity `w`.
    #[inline(always)]
    pub const fn new(w: Vec3) -> Self {
        Spin {
            wx: w.x,
            wy: w.y,
            wz: w.z,
            spare: 0.0,
        }
    }

    /// The rim velocity.
    #[inline(always)]
    pub fn rim_velocity(&self) -> Vec3 {
        Vec3::new(self.wx, self.wy, self.wz)
    }
}

/// Why a buffer cannot hold a particle system.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum ParticlesError {
    /// Fewer than two particles: no pair can collide.
    TooFew,
    /// More particles than a slice can address (`n * 32` bytes above `isize::MAX`).
    TooMany,
    /// A rough gas's spins are not one per particle.
    SpinCount,
    /// Weighted particles' weights are not one per record, or more in use than the buffers hold.
    WeightCount,
    /// A weight in use that is not finite and > 0.
    Weight,
    /// The buffers of weighted particles are full (reduce them first), or the particles are
    /// not weighted.
    Full,
}

impl core::fmt::Display for ParticlesError {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        f.write_str(match self {
            ParticlesError::TooFew => "a particle system needs n >= 2 particles",
            ParticlesError::TooMany => "n particles of 32 bytes exceed the address space",
            ParticlesError::SpinCount => "a rough gas needs one spin per particle",
            ParticlesError::WeightCount => "one weight per record, len <= buffer",
            ParticlesError::Weight => "a weight not finite and > 0",
            ParticlesError::Full => "weighted buffers full",
        })
    }
}

/// The rule for a particle count: `n >= 2` (a pair is needed to collide) and `n` particles fit
/// in memory. The one place this is checked: [`Particles::new`] and
/// [`crate::physics::Physics::validate`] call it.
pub fn check_count(n: usize) -> Result<(), ParticlesError> {
    if n < 2 {
        return Err(ParticlesError::TooFew);
    }
    if n > isize::MAX as usize / core::mem::size_of::<Particle>() {
        return Err(ParticlesError::TooMany);
    }
    Ok(())
}

/// `n >= 2` particles in a caller-owned slice, and for a rough gas their spins in a second one.
/// Weighted particles ([`Particles::weighted`], Rjasanow and Wagner's SWPM,
/// [`crate::weighted`]) carry a weight each in a third slice, and use the first `len` records
/// of buffers whose rest is room for the particles their collisions create.
#[derive(Debug)]
pub struct Particles<'a> {
    p: &'a mut [Particle],
    spins: &'a mut [Spin],
    /// The weights of weighted particles, as long as `p`; empty: every weight 1.
    weights: &'a mut [Real],
    /// The particles in use: `p.len()` unless weighted.
    len: usize,
}

impl<'a> Particles<'a> {
    /// A system over a caller buffer of `n >= 2` particles (no spins: a smooth gas).
    pub fn new(p: &'a mut [Particle]) -> Result<Self, ParticlesError> {
        check_count(p.len())?;
        let len = p.len();
        Ok(Particles {
            p,
            spins: &mut [],
            weights: &mut [],
            len,
        })
    }

    /// Weighted particles: the first `len >= 2` records of `p` in use with the weights
    /// `weights[..len]` (each finite and > 0; [`ParticlesError::Weight`] otherwise), the rest of
    /// both buffers (of one length, [`ParticlesError::WeightCount`] otherwise) room for the
    /// particles collisions create ([`Particles::push`]).
    pub fn weighted(
        p: &'a mut [Particle],
        weights: &'a mut [Real],
        len: usize,
    ) -> Result<Self, ParticlesError> {
        check_count(len)?;
        if weights.len() != p.len() || len > p.len() {
            return Err(ParticlesError::WeightCount);
        }
        if !weights[..len].iter().all(|g| g.is_finite() && *g > 0.0) {
            return Err(ParticlesError::Weight);
        }
        Ok(Particles {
            p,
            spins: &mut [],
            weights,
            len,
        })
    }

    /// Whether the particles carry weights ([`Particles::weighted`]).
    #[inline(always)]
    pub fn is_weighted(&self) -> bool {
        !self.weights.is_empty()
    }

    /// The weight of particle `i` (1 unless weighted).
    #[inline(always)]
    pub fn weight(&self, i: usize) -> Real {
        if self.weights.is_empty() {
            1.0
        } else {
            self.weights[i]
        }
    }

    /// The weights of the particles in use (empty unless weighted).
    pub fn weights(&self) -> &[Real] {
        let len = self.len.min(self.weights.len());
        &self.weights[..len]
    }

    /// Every weight in use set to 1 (the start of a weighted run; nothing unless weighted).
    pub fn reset_weights(&mut self) {
        let len = self.len.min(self.weights.len());
        self.weights[..len].fill(1.0);
    }

    /// Sets the weight of particle `i` (weighted particles only).
    #[inline(always)]
    pub fn set_weight(&mut self, i: usize, g: Real) {
        self.weights[i] = g;
    }

    /// The particles the buffers hold (`len()` unless weighted).
    pub fn capacity(&self) -> usize {
        self.p.len()
    }

    /// The total weight `sum g` (the number of particles unless weighted).
    pub fn mass(&self) -> Real {
        if self.weights.is_empty() {
            self.len as Real
        } else {
            self.weights().iter().sum()
        }
    }

    /// Appends a weighted particle of velocity `v`, weight `g`, last kicked at `t`;
    /// [`ParticlesError::Full`] (nothing changed) when the buffers are full or the particles
    /// are not weighted.
    pub fn push(&mut self, v: Vec3, g: Real, t: Real) -> Result<(), ParticlesError> {
        if !self.is_weighted() || self.len == self.p.len() {
            return Err(ParticlesError::Full);
        }
        self.p[self.len] = Particle::new(v, t);
        self.weights[self.len] = g;
        self.len += 1;
        Ok(())
    }

    /// Keeps the first `len` particles (`2 <= len <= self.len()`): what a reduction of weighted
    /// particles leaves.
    pub(crate) fn truncate(&mut self, len: usize) {
        debug_assert!(self.is_weighted() && (2..=self.len).contains(&len));
        self.len = len;
    }

    /// The whole buffers of weighted particles, records and weights, for a reduction that
    /// rewrites them in place.
    pub(crate) fn buffers_mut(&mut self) -> (&mut [Particle], &mut [Real]) {
        (self.p, self.weights)
    }

    /// A rough gas: `n >= 2` particles and their `n` spins, each in a caller buffer.
    pub fn with_spins(
        p: &'a mut [Particle],
        spins: &'a mut [Spin],
    ) -> Result<Self, ParticlesError> {
        check_count(p.len())?;
        if spins.len() != p.len() {
            return Err(ParticlesError::SpinCount);
        }
        let len = p.len();
        Ok(Particles {
            p,
            spins,
            weights: &mut [],
            len,
        })
    }

    /// Whether the system carries spins (a rough gas).
    #[inline(always)]
    pub fn has_spins(&self) -> bool {
        !self.spins.is_empty()
    }

    /// Rim velocity of particle `i` (a rough gas only).
    #[inline(always)]
    pub fn spin(&self, i: usize) -> Vec3 {
        self.spins[i].rim_velocity()
    }

    /// Sets the rim velocity of particle `i` (a rough gas only).
    #[inline(always)]
    pub fn set_spin(&mut self, i: usize, w: Vec3) {
        self.spins[i] = Spin::new(w);
    }

    /// The spins, read-only (empty for a smooth gas).
    pub fn spins(&self) -> &[Spin] {
        self.spins
    }

    /// The spins, mutable (empty for a smooth gas).
    pub fn spins_mut(&mut self) -> &mut [Spin] {
        self.spins
    }

    /// Number of particles (in use, when weighted).
    #[inline(always)]
    pub fn len(&self) -> usize {
        self.len
    }

    /// Always false: a system holds at least two particles.
    #[inline(always)]
    pub fn is_empty(&self) -> bool {
        false
    }

    /// Velocity of particle `i`.
    #[inline(always)]
    pub fn velocity(&self, i: usize) -> Vec3 {
        self.p[i].velocity()
    }

    /// Hints that particle `i` (and its spin, in a rough gas) will be touched soon
    /// ([`crate::prefetch::prefetch`]).
    #[inline(always)]
    pub fn prefetch(&self, i: usize) {
        crate::prefetch::prefetch(&self.p[i]);
        if let Some(s) = self.spins.get(i) {
            crate::prefetch::prefetch(s);
        }
    }

    /// Sets the velocity of particle `i`.
    #[inline(always)]
    pub fn set_velocity(&mut self, i: usize, v: Vec3) {
        self.p[i].set_velocity(v);
    }

    /// Time particle `i` was last kicked.
    #[inline(always)]
    pub fn kick_time(&self, i: usize) -> Real {
        self.p[i].t_kick
    }

    /// Particle `i`, mutable.
    #[inline(always)]
    pub fn get_mut(&mut self, i: usize) -> &mut Particle {
        &mut self.p[i]
    }

    /// Sets every particle's last-kick time to `t` (start of a run).
    pub fn reset_kick_times(&mut self, t: Real) {
        for q in self.as_mut_slice() {
            q.t_kick = t;
        }
    }

    /// The particles, read-only.
    pub fn as_slice(&self) -> &[Particle] {
        // `len <= p.len()` always (the constructors and `truncate` keep it): no panic path.
        self.p.get(..self.len).unwrap_or(&[])
    }

    /// The particles, mutable: for the batch kernels.
    pub fn as_mut_slice(&mut self) -> &mut [Particle] {
        self.p.get_mut(..self.len).unwrap_or(&mut [])
    }

    /// Fills the velocities from a sampler and sets every last-kick time to `t0`.
    pub fn fill_with(&mut self, t0: Real, mut sample: impl FnMut() -> Vec3) {
        for q in self.as_mut_slice() {
            *q = Particle::new(sample(), t0);
        }
    }
}
