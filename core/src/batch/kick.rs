//! The white-noise kick of every particle to an observation time (GRW Section 3 step 3.1,
//! RW Algorithm 3 step 3.1): `v_i += sqrt(2 beta (t - t_i)) xi_i`, `t_i := t`.
//!
//! The SIMD kernel draws its normals four lanes at a time by the Box-Muller transform
//! (`r = sqrt(-2 ln u1)`, `(r cos 2 pi u2, r sin 2 pi u2)`, exact in distribution), with `u1` in
//! the open interval (0, 1). Eight particles take three Box-Muller batches (24 normals).
//! The remainder (`n mod 8` particles) uses the scalar ziggurat.

use crate::math::{PI, Real, sqrt};
use crate::particles::Particles;
use crate::rng::{Rng, uniform_open01, uniform01};
use crate::sample::standard_normal3;
use wide::f64x4;

/// Kicks every particle to time `t` with strength `two_beta = 2 beta` (SIMD unless the
/// `scalar` feature is on).
#[inline]
pub fn white_noise_kick_all<R: Rng + ?Sized>(
    two_beta: Real,
    p: &mut Particles<'_>,
    t: Real,
    rng: &mut R,
) {
    if cfg!(feature = "scalar") {
        white_noise_kick_all_scalar(two_beta, p, t, rng);
    } else {
        white_noise_kick_all_simd(two_beta, p, t, rng);
    }
}

/// Scalar twin: particle by particle, ziggurat normals.
pub fn white_noise_kick_all_scalar<R: Rng + ?Sized>(
    two_beta: Real,
    p: &mut Particles<'_>,
    t: Real,
    rng: &mut R,
) {
    for i in 0..p.len() {
        let s = sqrt(two_beta * (t - p.kick_time(i)));
        let v = p.velocity(i) + s * standard_normal3(rng);
        p.set_velocity(i, v);
        p.set_kick_time(i, t);
    }
}

/// Four pairs of independent standard normals by Box-Muller.
#[inline(always)]
pub fn box_muller4<R: Rng + ?Sized>(rng: &mut R) -> (f64x4, f64x4) {
    let u1 = f64x4::from([
        uniform_open01(rng),
        uniform_open01(rng),
        uniform_open01(rng),
        uniform_open01(rng),
    ]);
    let u2 = f64x4::from([
        uniform01(rng),
        uniform01(rng),
        uniform01(rng),
        uniform01(rng),
    ]);
    let r = (f64x4::splat(-2.0) * u1.ln()).sqrt();
    let (s, c) = (f64x4::splat(2.0 * PI) * u2).sin_cos();
    (r * c, r * s)
}

#[inline(always)]
fn load(s: &[Real]) -> f64x4 {
    f64x4::from([s[0], s[1], s[2], s[3]])
}

#[inline(always)]
fn store(d: &mut [Real], v: f64x4) {
    d[..4].copy_from_slice(&v.to_array());
}

/// SIMD kernel: eight particles per step, three Box-Muller batches.
pub fn white_noise_kick_all_simd<R: Rng + ?Sized>(
    two_beta: Real,
    p: &mut Particles<'_>,
    t: Real,
    rng: &mut R,
) {
    let n = p.len();
    let blocks = n / 8;
    {
        let (vx, vy, vz, tk) = p.lanes_mut();
        let tb = f64x4::splat(two_beta);
        let tt = f64x4::splat(t);
        for b in 0..blocks {
            let o = 8 * b;
            let (gx0, gx1) = box_muller4(rng);
            let (gy0, gy1) = box_muller4(rng);
            let (gz0, gz1) = box_muller4(rng);
            for (k, gx, gy, gz) in [(o, gx0, gy0, gz0), (o + 4, gx1, gy1, gz1)] {
                let s = (tb * (tt - load(&tk[k..k + 4]))).sqrt();
                let new_vx = load(&vx[k..k + 4]) + s * gx;
                store(&mut vx[k..k + 4], new_vx);
                let new_vy = load(&vy[k..k + 4]) + s * gy;
                store(&mut vy[k..k + 4], new_vy);
                let new_vz = load(&vz[k..k + 4]) + s * gz;
                store(&mut vz[k..k + 4], new_vz);
            }
            tk[o..o + 8].fill(t);
        }
    }
    for i in 8 * blocks..n {
        let s = sqrt(two_beta * (t - p.kick_time(i)));
        let v = p.velocity(i) + s * standard_normal3(rng);
        p.set_velocity(i, v);
        p.set_kick_time(i, t);
    }
}
