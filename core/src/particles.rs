//! The particle system: velocities and last-kick times in caller-owned buffers.
//!
//! Structure of arrays (`vx`, `vy`, `vz`, `t_kick`), so that the batch kernels (kicks, moments)
//! run over contiguous lanes. The core never allocates: the caller hands in the slices, either
//! four separate ones or one buffer of `4 n` reals ([`Particles::from_buffer`]).

use crate::math::Real;
use crate::vec3::Vec3;

/// Why a set of buffers cannot hold a particle system.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum ParticlesError {
    /// Fewer than two particles: no pair can collide.
    TooFew,
    /// The four buffers differ in length (or a single buffer is not `4 n` long).
    LengthMismatch,
}

impl core::fmt::Display for ParticlesError {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        f.write_str(match self {
            ParticlesError::TooFew => "a particle system needs n >= 2 particles",
            ParticlesError::LengthMismatch => "velocity and time buffers differ in length",
        })
    }
}

/// `n >= 2` particles: velocity components and the time each was last kicked (RW Algorithm 3's
/// `sigma_j`; GRW's `t_j`).
#[derive(Debug)]
pub struct Particles<'a> {
    vx: &'a mut [Real],
    vy: &'a mut [Real],
    vz: &'a mut [Real],
    t_kick: &'a mut [Real],
}

impl<'a> Particles<'a> {
    /// A system over four caller buffers of equal length `n >= 2`.
    pub fn new(
        vx: &'a mut [Real],
        vy: &'a mut [Real],
        vz: &'a mut [Real],
        t_kick: &'a mut [Real],
    ) -> Result<Self, ParticlesError> {
        let n = vx.len();
        if vy.len() != n || vz.len() != n || t_kick.len() != n {
            return Err(ParticlesError::LengthMismatch);
        }
        if n < 2 {
            return Err(ParticlesError::TooFew);
        }
        Ok(Particles { vx, vy, vz, t_kick })
    }

    /// A system of `n` particles in one caller buffer of exactly `4 n` reals, laid out as
    /// `[vx; n][vy; n][vz; n][t_kick; n]`.
    pub fn from_buffer(buf: &'a mut [Real], n: usize) -> Result<Self, ParticlesError> {
        if n.checked_mul(4) != Some(buf.len()) {
            return Err(ParticlesError::LengthMismatch);
        }
        let (vx, rest) = buf.split_at_mut(n);
        let (vy, rest) = rest.split_at_mut(n);
        let (vz, t_kick) = rest.split_at_mut(n);
        Self::new(vx, vy, vz, t_kick)
    }

    /// Number of particles.
    #[inline(always)]
    pub fn len(&self) -> usize {
        self.vx.len()
    }

    /// Always false: a system holds at least two particles.
    #[inline(always)]
    pub fn is_empty(&self) -> bool {
        false
    }

    /// Velocity of particle `i`.
    #[inline(always)]
    pub fn velocity(&self, i: usize) -> Vec3 {
        Vec3::new(self.vx[i], self.vy[i], self.vz[i])
    }

    /// Sets the velocity of particle `i`.
    #[inline(always)]
    pub fn set_velocity(&mut self, i: usize, v: Vec3) {
        self.vx[i] = v.x;
        self.vy[i] = v.y;
        self.vz[i] = v.z;
    }

    /// Time particle `i` was last kicked.
    #[inline(always)]
    pub fn kick_time(&self, i: usize) -> Real {
        self.t_kick[i]
    }

    /// Sets the time particle `i` was last kicked.
    #[inline(always)]
    pub fn set_kick_time(&mut self, i: usize, t: Real) {
        self.t_kick[i] = t;
    }

    /// Sets every particle's last-kick time to `t` (start of a run).
    pub fn reset_kick_times(&mut self, t: Real) {
        self.t_kick.fill(t);
    }

    /// The velocity components, read-only.
    pub fn components(&self) -> (&[Real], &[Real], &[Real]) {
        (self.vx, self.vy, self.vz)
    }

    /// All four buffers, mutable: for the batch kernels.
    pub fn lanes_mut(&mut self) -> (&mut [Real], &mut [Real], &mut [Real], &mut [Real]) {
        (self.vx, self.vy, self.vz, self.t_kick)
    }

    /// Fills the velocities from a sampler and sets every last-kick time to `t0`.
    pub fn fill_with(&mut self, t0: Real, mut sample: impl FnMut() -> Vec3) {
        for i in 0..self.len() {
            let v = sample();
            self.set_velocity(i, v);
        }
        self.reset_kick_times(t0);
    }
}
