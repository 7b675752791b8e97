//! Samplers, each exact in distribution (up to floating-point rounding).
//!
//! One file per distribution, as in rand_distr. Every sampler is a small `Copy` value with a
//! `sample(&self, rng)` method generic over [`crate::rng::Rng`]; parameters are validated by a
//! fallible constructor that names the bad parameter.

pub mod circle;
pub mod exponential;
pub mod impact;
pub mod maxwellian;
pub mod mixture;
pub mod normal;
pub mod partner;
pub mod poisson;
pub mod sphere;
mod squeeze;
#[allow(missing_docs)]
pub mod ziggurat_tables;

pub use circle::unit_circle;
pub use exponential::{exponential_from_half, standard_exponential};
pub use impact::impact_direction;
pub use maxwellian::Maxwellian;
pub use mixture::MaxwellianMixture;
pub use normal::{
    standard_normal, standard_normal_pair, standard_normal3, standard_normal3x4, standard_normals,
};
pub use partner::BackgroundPartner;
pub use poisson::poisson;
pub use sphere::unit_sphere;

/// A parameter of a sampler that is out of its domain.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum ParamError {
    /// A mass that is not finite and positive.
    Mass,
    /// A temperature that is not finite and non-negative.
    Temperature,
    /// A drift velocity with a non-finite component.
    Drift,
    /// A mixture weight that is not finite and non-negative, or weights summing to zero.
    Weight,
    /// More mixture components than the mixture's capacity.
    Capacity,
    /// `2 T / m` overflows: the thermal speeds (and BRS (28)'s `b`) would be infinite.
    ThermalSpeed,
}

impl core::fmt::Display for ParamError {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        f.write_str(match self {
            ParamError::Mass => "mass must be finite and > 0",
            ParamError::Temperature => "temperature must be finite and >= 0",
            ParamError::Drift => "drift velocity must be finite",
            ParamError::Weight => "mixture weights must be finite, >= 0 and not all 0",
            ParamError::Capacity => "too many mixture components",
            ParamError::ThermalSpeed => "2 temperature / mass must be finite",
        })
    }
}
