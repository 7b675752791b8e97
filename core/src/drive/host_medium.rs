//! A host medium: elastic collisions of each grain with a fixed Maxwellian background
//! (BRS Section 2, `J_EL`; the map BRS (2) with the mass ratio BRS (3)).
//!
//! Each grain meets the background independently of the others, so its background collisions
//! form a Poisson process of its own, with rate `E_1(v)` of BRS (26). This drive simulates that
//! process lazily, grain by grain, from the grain's last-kick time to the time it is needed,
//! exactly as the white-noise kicks are (GRW Section 3): there is no time step and no particle
//! choice by weights at all. The superposition of the grains' independent processes is the
//! background part of BRS's Algorithms 1 and 2 (total rate `pi_1 = sum_i E_1(v_i)`, grain `i`
//! chosen with probability `E_1(v_i) / pi_1`), so the choice BRS makes with an alias table,
//! rebuilt after every collision, costs nothing here: O(1) per event, exact.
//!
//! - Maxwell background kernel `B_1 = C_1` (BRS (11)): rate `4 pi C_1 rho^B`, partner from
//!   `M^B`, direction uniform (BRS Algorithm 1, steps 2.3.1-2.3.4).
//! - Hard-sphere background kernel `B_1 = C_1 |g|` (BRS (19)): thinning against the majorant
//!   `E_1max(v) = C_1 rho^B (4 pi a + 8 pi^{1/2} b)`, `a = |v - u^B|`, `b = (2 T^B/m^B)^{1/2}`
//!   (BRS (28)); the partner from the mixture `a/(a + 2b/sqrt(pi))` of `M^B` and the density
//!   BRS (29) (both from the same four normals, see [`HardSphereBackground`]); rejected with
//!   probability `1 - |v - w| / (|v - u^B| + |w - u^B|)` (BRS
//!   Algorithm 2). The majorant is recomputed after each background event, when `v` changes.
//!
//! Grains have unit mass (a mixture's species their own: [`HostMediumParams::for_grain`]);
//! `T^B`, `m^B` are the background's temperature and mass.
//!
//! Disks (`d = 2`, [`crate::geometry`]): BRS writes spheres; in the plane the kernels keep
//! their total rate (`int B_1 domega = 4 pi C_1 |g|^lambda`, the grains' own convention), the
//! partners are the planar Maxwellian's, the directions the circle's (uniform for the Maxwell
//! kernel; for hard disks the hard-disk scattering law, [`Geometry::scattering`]), and the
//! majorant and partner density follow BRS (28)-(29) with the planar mean speed
//! `E|w - u^B| = b sqrt(pi)/2`: the weighted partner `|x| M^B(x)` has the radius of a chi law
//! with 3 degrees of freedom (`s^2 e^{-s^2/b^2}`) in a uniform direction of the plane, so the
//! four normals of spheres become three. The same code for both dimensions (`G`), the
//! spheres' draws unchanged.

use super::Drive;
use crate::collision::{MassRatio, elastic_background, grain_after_background};
use crate::geometry::{DimensionChoice, Geometry, Spheres};
use crate::kernel::{HardSpheres, Maxwell};
use crate::math::{PI, Real, SQRT_PI, sqrt};
use crate::rng::{Rng, uniform01};
use crate::sample::{BackgroundPartner, Maxwellian, standard_exponential, standard_normal};
use crate::vec3::Vec3;

/// The grain-background collision kernel `B_1`.
pub trait BackgroundKernel: Copy + core::fmt::Debug {
    /// Draws the next real background collision of a grain at velocity `v` within `dt` in
    /// dimension `G`: the post-collisional velocity and the time used, or `None` if none
    /// happens in `dt`.
    fn next<G: Geometry, R: Rng + ?Sized>(
        &self,
        m: &HostMediumParams,
        v: Vec3,
        dt: Real,
        rng: &mut R,
    ) -> Option<(Vec3, Real)>;

    /// The candidate rate of background events of a grain at distance `a` from the
    /// background's drift velocity, `|v - u^B| = a`, in dimension `G` (the majorant
    /// [`BackgroundKernel::next`] draws its waiting times from).
    fn rate_bound<G: Geometry>(&self, m: &HostMediumParams, a: Real) -> Real;
}

/// The background Maxwellian and the constants derived from it.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct HostMediumParams {
    /// Background Maxwellian `M^B` (mass, temperature, drift).
    pub background: Maxwellian,
    /// Number density `rho^B`.
    pub density: Real,
    /// Kernel constant `C_1`.
    pub c1: Real,
    ratio: MassRatio,
    partner: BackgroundPartner,
}

/// A host-medium parameter out of its domain.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum HostMediumError {
    /// The density is not finite and positive.
    Density,
    /// `C_1` is not finite and positive.
    Strength,
}

impl HostMediumParams {
    /// The background `bg` with density `density` and kernel constant `c1`, for unit-mass
    /// grains.
    pub fn new(bg: Maxwellian, density: Real, c1: Real) -> Result<Self, HostMediumError> {
        if !(density.is_finite() && density > 0.0) {
            return Err(HostMediumError::Density);
        }
        if !(c1.is_finite() && c1 > 0.0) {
            return Err(HostMediumError::Strength);
        }
        let ratio = MassRatio::new(1.0, bg.mass()).expect("Maxwellian mass is positive");
        Ok(HostMediumParams {
            background: bg,
            density,
            c1,
            ratio,
            partner: BackgroundPartner::new(&bg),
        })
    }

    /// The mass ratio `alpha = m^B / (m + m^B)` of BRS (3) (unit grain mass unless
    /// [`HostMediumParams::for_grain`] set it).
    pub fn mass_ratio(&self) -> Real {
        self.ratio.get()
    }

    /// The same background met by grains of mass `m` (a mixture's species): the mass ratio of
    /// BRS (3) becomes `m^B / (m + m^B)`, the rest (density, `C_1`, partners) is the
    /// background's. `None` unless `m` is finite and positive.
    pub fn for_grain(self, m: Real) -> Option<Self> {
        let ratio = MassRatio::new(m, self.background.mass())?;
        Some(HostMediumParams { ratio, ..self })
    }
}

/// Maxwell background kernel `B_1 = C_1`.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct MaxwellBackground;

impl BackgroundKernel for MaxwellBackground {
    #[inline]
    fn next<G: Geometry, R: Rng + ?Sized>(
        &self,
        m: &HostMediumParams,
        v: Vec3,
        dt: Real,
        rng: &mut R,
    ) -> Option<(Vec3, Real)> {
        let tau = standard_exponential(rng) / self.rate_bound::<G>(m, 0.0);
        if tau >= dt {
            return None;
        }
        // `M^B` in the dimension (spheres: `Maxwellian::sample`'s very draws).
        let w = m.background.drift() + m.background.thermal_scale() * G::normal(rng);
        let omega = G::scattering::<Maxwell, R>(v - w, rng);
        Some((elastic_background(v, w, omega, m.ratio).0, tau))
    }

    /// `4 pi C_1 rho^B`, whatever the grain's speed (disks: the same total rate).
    #[inline]
    fn rate_bound<G: Geometry>(&self, m: &HostMediumParams, _a: Real) -> Real {
        4.0 * PI * m.c1 * m.density
    }
}

/// Hard-sphere background kernel `B_1 = C_1 |g|`.
///
/// Candidates at BRS (28)'s rate; the partner `w = u^B + x` from the mixture of `M^B` and BRS
/// (29) drawn from four normals `N, N_4` whichever is picked: `x = sigma N` (`sigma^2 =
/// T^B/m^B`) for `M^B`, `x = sigma sqrt(|N|^2 + N_4^2) N/|N|` for BRS (29) (its `|x|^2/b^2`
/// is half a chi-squared with 4 degrees of freedom, Gamma(2), in a uniform direction), so the
/// choice is a select, not a branch; the thinning test without a root; the direction of the
/// collision drawn only when it is real.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct HardSphereBackground;

impl BackgroundKernel for HardSphereBackground {
    #[inline]
    fn next<G: Geometry, R: Rng + ?Sized>(
        &self,
        m: &HostMediumParams,
        v: Vec3,
        dt: Real,
        rng: &mut R,
    ) -> Option<(Vec3, Real)> {
        // Everything about the drift: `c = v - u^B`, the partner `x = w - u^B`, `g = c - x`.
        let c = v - m.background.drift();
        // Waiting times in units of the majorant: the candidates come while the sum `e` of
        // standard exponentials is below `dt (k0 a + k1)`. Every kick's last call ends at a
        // time test, mostly at its first draw; that one needs no root: `e - dt k1 >= dt k0 a`
        // as squares. (No time, or a time a rounding left below 0, has no candidate.)
        let (k0, k1) = rate_terms::<G>(m);
        let mut e = standard_exponential(rng);
        let y = e - dt * k1;
        if dt.is_nan() || dt <= 0.0 || (y >= 0.0 && y * y >= (dt * k0) * (dt * k0) * c.norm2()) {
            return None;
        }
        let a = c.norm();
        let budget = dt * (k0 * a + k1);
        let mixture = a + mean_speed::<G>(m);
        let sigma = m.background.thermal_scale();
        loop {
            // The partner from the mixture `a/(a + 2b/sqrt(pi))` of `M^B` and BRS (29), with
            // its speed `s` about the drift, one construction for both (no branch to
            // mispredict): `x = sigma N` with `N` three normals is `M^B`'s; stretched to the
            // length `sigma sqrt(|N|^2 + N_4^2)` it is BRS (29)'s, whose `s^2/b^2` is
            // Gamma(2) (`|N|^2 + N_4^2` is chi-squared with 4 degrees of freedom, halved: `b^2
            // = 2 sigma^2`) in the uniform direction of `N`.
            // (Disks: `N` two normals in the plane and one more, `chi(2)` or `chi(3)`.)
            let pick_bg = uniform01(rng) * mixture < a;
            let n = G::normal(rng);
            let n4 = standard_normal(rng);
            let q = n.norm2();
            let s = sigma * sqrt(if pick_bg { q } else { q + n4 * n4 });
            // `q = 0` needs three exact zeros (about 2^-156): `x = 0` then.
            let x = if q > 0.0 { s / sqrt(q) } else { 0.0 } * n;
            let g = c - x;
            let g2 = g.norm2();
            // `r < |g| / (a + s)` as `(r (a + s))^2 < |g|^2`: no root for a rejection. The
            // direction is drawn only for a real collision.
            let r = uniform01(rng) * (a + s);
            if r * r < g2 {
                let omega = G::scattering::<HardSpheres, R>(g, rng);
                let used = e / (k0 * a + k1);
                return Some((grain_after_background(v, g, sqrt(g2), omega, m.ratio), used));
            }
            e += standard_exponential(rng);
            if e >= budget {
                return None;
            }
        }
    }

    /// BRS (28): `C_1 rho^B (4 pi a + 8 sqrt(pi) b)` with the partner scale `b` (disks:
    /// `4 pi C_1 rho^B (a + b sqrt(pi)/2)`).
    #[inline]
    fn rate_bound<G: Geometry>(&self, m: &HostMediumParams, a: Real) -> Real {
        let (k0, k1) = rate_terms::<G>(m);
        k0 * a + k1
    }
}

/// BRS (28)'s majorant as `k0 a + k1`: `k0 = 4 pi C_1 rho^B`, `k1 = k0 E|w - u^B|`, which is
/// `8 sqrt(pi) C_1 rho^B b` for spheres and `2 pi^{3/2} C_1 rho^B b` for disks.
#[inline(always)]
fn rate_terms<G: Geometry>(m: &HostMediumParams) -> (Real, Real) {
    let s = m.c1 * m.density;
    let k1 = match G::CHOICE {
        DimensionChoice::Three => s * 8.0 * SQRT_PI * m.partner.b(),
        DimensionChoice::Two => s * 2.0 * PI * SQRT_PI * m.partner.b(),
    };
    (s * 4.0 * PI, k1)
}

/// The background's mean speed about its drift, `E|w - u^B|`: `2 b / sqrt(pi)` for spheres
/// (BRS, before (29)), `b sqrt(pi) / 2` for disks.
#[inline(always)]
fn mean_speed<G: Geometry>(m: &HostMediumParams) -> Real {
    match G::CHOICE {
        DimensionChoice::Three => m.partner.mean_relative_speed(),
        DimensionChoice::Two => 0.5 * SQRT_PI * m.partner.b(),
    }
}

/// The host-medium drive with background kernel `B` in dimension `G` (spheres by default).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct HostMedium<B, G = Spheres> {
    /// Background parameters.
    pub params: HostMediumParams,
    kernel: B,
    dimension: core::marker::PhantomData<G>,
}

impl<B: BackgroundKernel> HostMedium<B> {
    /// A host medium of spheres with these parameters and kernel.
    pub fn new(params: HostMediumParams, kernel: B) -> Self {
        HostMedium {
            params,
            kernel,
            dimension: core::marker::PhantomData,
        }
    }
}

impl<B: BackgroundKernel, G: Geometry> HostMedium<B, G> {
    /// The same host medium in dimension `H` (disks: the background's drift must lie in the
    /// plane, which the physics validation checks).
    pub fn in_dim<H: Geometry>(self) -> HostMedium<B, H> {
        HostMedium {
            params: self.params,
            kernel: self.kernel,
            dimension: core::marker::PhantomData,
        }
    }
}

impl<B: BackgroundKernel, G: Geometry> Drive for HostMedium<B, G> {
    const ACTS: bool = true;
    const COUNTS_EVENTS: bool = true;

    /// The background majorant at the farthest a grain of speed `speed` can be from the drift.
    #[inline]
    fn event_rate(&self, speed: Real) -> Real {
        let a = speed + self.params.background.drift().norm();
        self.kernel.rate_bound::<G>(&self.params, a)
    }

    #[inline]
    fn evolve<R: Rng + ?Sized>(&self, v: Vec3, dt: Real, rng: &mut R) -> Vec3 {
        self.evolve_counting(v, dt, rng, &mut 0)
    }

    /// Counts the grain's real background collisions (BRS (26)'s events; candidates the
    /// hard-sphere kernel rejects are not collisions and are not counted).
    #[inline]
    fn evolve_counting<R: Rng + ?Sized>(
        &self,
        mut v: Vec3,
        dt: Real,
        rng: &mut R,
        events: &mut u64,
    ) -> Vec3 {
        let mut left = dt;
        while let Some((v1, used)) = self.kernel.next::<G, R>(&self.params, v, left, rng) {
            v = v1;
            left -= used;
            *events += 1;
        }
        v
    }
}
