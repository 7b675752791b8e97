//! A weighted particle and a system of them over a caller buffer (Rjasanow and Wagner 1996):
//! the buffer's length is the capacity the collisions may fill, `len` the particles in use.

use crate::math::Real;
use crate::vec3::Vec3;

/// One weighted particle: velocity and weight `g > 0`. `#[repr(C)]`, 32 bytes, aligned to 32
/// like [`crate::particles::Particle`].
#[repr(C, align(32))]
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct WeightedParticle {
    /// Velocity, x.
    pub vx: Real,
    /// Velocity, y.
    pub vy: Real,
    /// Velocity, z.
    pub vz: Real,
    /// Weight.
    pub g: Real,
}

impl WeightedParticle {
    /// A particle of velocity `v` and weight `g`.
    #[inline(always)]
    pub const fn new(v: Vec3, g: Real) -> Self {
        WeightedParticle {
            vx: v.x,
            vy: v.y,
            vz: v.z,
            g,
        }
    }

    /// The velocity.
    #[inline(always)]
    pub fn velocity(&self) -> Vec3 {
        Vec3::new(self.vx, self.vy, self.vz)
    }
}

/// What a weighted system refuses.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum WeightedError {
    /// Fewer than two particles, or more in use than the buffer holds.
    Count,
    /// A weight that is not finite and > 0.
    Weight,
    /// The buffer is full: a collision needs room for its new particles (reduce first).
    Full,
}

impl core::fmt::Display for WeightedError {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        f.write_str(match self {
            WeightedError::Count => {
                "a weighted system needs at least 2 particles, and no more than its buffer holds"
            }
            WeightedError::Weight => "every weight must be finite and > 0",
            WeightedError::Full => "the weighted particles fill their buffer: reduce them first",
        })
    }
}

/// A system of weighted particles: the first `len` records of the caller's buffer, and under
/// a drive each one's last-kick time (GRW's `t_j`) in a second caller slice of the same length.
pub struct WeightedSystem<'a> {
    p: &'a mut [WeightedParticle],
    times: &'a mut [Real],
    len: usize,
}

impl<'a> WeightedSystem<'a> {
    /// The first `len >= 2` particles of `buf` (each weight finite and > 0); the rest of the
    /// buffer is room for the particles collisions create.
    pub fn new(buf: &'a mut [WeightedParticle], len: usize) -> Result<Self, WeightedError> {
        if len < 2 || len > buf.len() {
            return Err(WeightedError::Count);
        }
        if !buf[..len].iter().all(|p| p.g.is_finite() && p.g > 0.0) {
            return Err(WeightedError::Weight);
        }
        Ok(WeightedSystem {
            p: buf,
            times: &mut [],
            len,
        })
    }

    /// As [`WeightedSystem::new`], with the last-kick times a drive needs: `times` as long as
    /// `buf` ([`WeightedError::Count`] otherwise), every particle's set to `t0`.
    pub fn with_times(
        buf: &'a mut [WeightedParticle],
        times: &'a mut [Real],
        len: usize,
        t0: Real,
    ) -> Result<Self, WeightedError> {
        if times.len() != buf.len() {
            return Err(WeightedError::Count);
        }
        let mut sys = WeightedSystem::new(buf, len)?;
        times.fill(t0);
        sys.times = times;
        Ok(sys)
    }

    /// Whether the system keeps last-kick times ([`WeightedSystem::with_times`]).
    pub fn has_times(&self) -> bool {
        !self.times.is_empty()
    }

    /// Particle `i`'s last-kick time (a system with times only).
    #[inline(always)]
    pub fn time(&self, i: usize) -> Real {
        self.times[i]
    }

    /// Sets particle `i`'s last-kick time (a system with times only).
    #[inline(always)]
    pub fn set_time(&mut self, i: usize, t: Real) {
        self.times[i] = t;
    }

    /// Every particle in use last kicked at `t` (after they were all brought there, or after
    /// a reduction of particles all at `t`); nothing without times.
    pub fn set_all_times(&mut self, t: Real) {
        let len = self.len;
        if let Some(ts) = self.times.get_mut(..len) {
            ts.fill(t);
        }
    }

    /// Particles in use.
    pub fn len(&self) -> usize {
        self.len
    }

    /// Never: a system holds at least two particles (the collisions keep every weight > 0).
    pub fn is_empty(&self) -> bool {
        self.len == 0
    }

    /// The particles the buffer can hold.
    pub fn capacity(&self) -> usize {
        self.p.len()
    }

    /// The particles in use.
    pub fn particles(&self) -> &[WeightedParticle] {
        &self.p[..self.len]
    }

    /// The particles in use, to change (their number stays).
    pub fn particles_mut(&mut self) -> &mut [WeightedParticle] {
        &mut self.p[..self.len]
    }

    /// Appends `q`; [`WeightedError::Full`] when the buffer is full.
    pub fn push(&mut self, q: WeightedParticle) -> Result<(), WeightedError> {
        let slot = self.p.get_mut(self.len).ok_or(WeightedError::Full)?;
        *slot = q;
        self.len += 1;
        Ok(())
    }

    /// Keeps the first `len` particles (`2 <= len <= self.len()`): what a reduction leaves.
    pub(crate) fn truncate(&mut self, len: usize) {
        debug_assert!((2..=self.len).contains(&len));
        self.len = len;
    }

    /// The buffer's records `0..capacity`, for a reduction that rewrites them in place.
    pub(crate) fn buffer(&mut self) -> &mut [WeightedParticle] {
        self.p
    }

    /// Total weight `sum g_i`.
    pub fn mass(&self) -> Real {
        self.particles().iter().map(|p| p.g).sum()
    }

    /// Total momentum `sum g_i v_i`.
    pub fn momentum(&self) -> Vec3 {
        (self.particles().iter()).fold(Vec3::ZERO, |m, p| m + p.g * p.velocity())
    }

    /// Total kinetic energy `sum g_i |v_i|^2 / 2`.
    pub fn energy(&self) -> Real {
        (self.particles().iter())
            .map(|p| 0.5 * p.g * p.velocity().norm2())
            .sum()
    }
}
