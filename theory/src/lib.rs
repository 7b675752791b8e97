//! gdsmc's theory: the values a run is compared with: exact solutions ([`exact`]: GRW (13), BRS (14)-(17),
//! MS's Sonine estimates and tail amplitudes; [`maxwell_cumulant`]: the Maxwell gas's `a2(t)`), the BRS hydrodynamic closures ([`hydro`]) and the integrator they are solved with ([`ode`]), and
//! which of them apply to a scene, as curves beside the observables ([`curves`], each
//! reference declared once in [`curves::registry`] with the physics it holds for); the energy
//! balance of a smooth gas, Haff's law and its heated forms ([`balance`]), and the balance of
//! the Gaussian thermostat ([`thermostat`]); [`impact_speed`]: the exact initial
//! cooling rate under the impact-speed law; [`mutation`]: the hook that perturbs
//! one exact reference on purpose, for the mutation check.

#![deny(unsafe_code)]

pub mod balance;
pub mod columns;
pub mod curves;
pub mod exact;
pub mod hydro;
pub mod impact_speed;
pub mod initial;
pub mod maxwell_cumulant;
pub mod maxwell_form;
pub mod maxwell_impact;
pub mod maxwell_temperature;
pub mod mixture;
pub mod mutation;
pub mod ode;
pub mod pairs;
pub mod rough;
pub mod rough_mixture;
pub mod steady;
pub mod thermostat;
