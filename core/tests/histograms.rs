//! The histogram kernels bin exactly where their docs say: bin edges, overflow bins, the
//! physical-velocity map `offset + scale v`, and the refusal of bad arguments.

use gdsmc_core::engine::Frame;
use gdsmc_core::histogram::{component_bins, radial_shells, radial_shells_mapped};
use gdsmc_core::particles::{Particle, Particles};
use gdsmc_core::vec3::Vec3;

fn particles(vs: &[Vec3]) -> Vec<Particle> {
    vs.iter().map(|&v| Particle::new(v, 0.0)).collect()
}

#[test]
fn component_bins_edges_and_overflow() {
    let xs = [-2.5, -1.5, -0.5, 0.0, 0.9, 1.0, 2.0];
    let mut q = particles(&xs.map(|x| Vec3::new(0.0, x, 7.0)));
    let p = Particles::new(&mut q).unwrap();
    let mut out = [0.0; 6];
    assert!(component_bins(&p, 1, 2.0, Frame::IDENTITY, &mut out));
    let g = 1.0 / 7.0;
    // bins [-2,-1), [-1,0), [0,1), [1,2), below -2, at or above 2
    assert_eq!(out, [g, g, 2.0 * g, g, g, g]);
}

#[test]
fn component_bins_maps_stored_velocities() {
    let mut q = particles(&[Vec3::new(1.0, 0.0, 0.0), Vec3::new(-1.0, 0.0, 0.0)]);
    let p = Particles::new(&mut q).unwrap();
    let mut out = [0.0; 6];
    // physical v_x = 1 + 0.5 v: 1.5 and 0.5, both in [0, 2) with R = 2, K = 4: bins 3 and 2.
    assert!(component_bins(
        &p,
        0,
        2.0,
        Frame {
            scale: 0.5,
            offset: Vec3::new(1.0, 0.0, 0.0)
        },
        &mut out
    ));
    assert_eq!(out, [0.0, 0.0, 0.5, 0.5, 0.0, 0.0]);
}

#[test]
fn bad_arguments_add_nothing() {
    let mut q = particles(&[Vec3::ZERO, Vec3::ZERO]);
    let p = Particles::new(&mut q).unwrap();
    let mut out = [0.0; 4];
    assert!(!component_bins(&p, 3, 1.0, Frame::IDENTITY, &mut out));
    assert!(!component_bins(&p, 0, f64::NAN, Frame::IDENTITY, &mut out));
    assert!(!component_bins(&p, 0, 1.0, Frame::IDENTITY, &mut out[..2]));
    assert!(!radial_shells(&p, -1.0, &mut out));
    assert_eq!(out, [0.0; 4]);
}

#[test]
fn reduced_shells_by_the_velocity_map() {
    // c = (v - V) / v0 as the map scale = 1/v0, offset = -V/v0: |c| = 1.25 and 0.25.
    let v0 = 2.0;
    let bulk = Vec3::new(1.0, 0.0, 0.0);
    let mut q = particles(&[Vec3::new(3.5, 0.0, 0.0), Vec3::new(1.0, 0.5, 0.0)]);
    let p = Particles::new(&mut q).unwrap();
    let mut out = [0.0; 3];
    assert!(radial_shells_mapped(
        &p,
        2.0,
        Frame {
            scale: 1.0 / v0,
            offset: (-1.0 / v0) * bulk
        },
        &mut out
    ));
    assert_eq!(out, [0.5, 0.5, 0.0]);
}
