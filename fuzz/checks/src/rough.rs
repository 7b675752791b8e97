//! The rough-sphere map (`gdsmc_core::rough::RoughMap`, Huthmann and Zippelius 1997) for any
//! finite inputs (magnitudes up to 1e150) and any valid coefficients: finite outputs; momentum
//! and angular momentum about the contact kept; the energy change equal to its closed form
//! `-(1/4)[(1 - alpha^2) g_n^2 + (1 - beta^2) kappa/(1 + kappa) |g_t|^2]` and never positive;
//! alpha = |beta| = 1 keeps the energy; beta = -1 returns the rim velocities bit for bit. And
//! the impact direction for any finite relative velocity: a unit vector on the approaching
//! hemisphere. Rounding bounds as in core/tests/rough_maps.rs (k ulps of the magnitudes, the
//! rotational ones divided by kappa). Disks (`gdsmc_core::geometry::Disks`): the same map on
//! velocities in the plane and spins along z keeps them there exactly, and the disks' impact and
//! hard-disk scattering directions are unit vectors in the plane (the impact approaching).

use crate::bounded;
use arbitrary::Unstructured;
use gdsmc_core::geometry::{Disks, Geometry};
use gdsmc_core::kernel::HardSpheres;
use gdsmc_core::rng::seeded;
use gdsmc_core::rough::{RoughMap, impact_direction};
use gdsmc_core::vec3::Vec3;

const MAX: f64 = 1e150;

fn vector(u: &mut Unstructured<'_>) -> Option<Vec3> {
    Some(Vec3::new(
        bounded(u, MAX)?,
        bounded(u, MAX)?,
        bounded(u, MAX)?,
    ))
}

/// Coefficients the map accepts, with the edges (1, -1, 2/3) often.
fn map(u: &mut Unstructured<'_>) -> Option<RoughMap> {
    let pick = |u: &mut Unstructured<'_>, edge: f64| -> Option<f64> {
        if u.ratio(1u8, 4u8).ok()? {
            Some(edge)
        } else {
            bounded(u, 1.0)
        }
    };
    let alpha = pick(u, 1.0)?.abs();
    let beta = if u.ratio(1u8, 4u8).ok()? {
        -1.0
    } else {
        pick(u, 1.0)?
    };
    let kappa = pick(u, 2.0 / 3.0)?.abs();
    RoughMap::new(alpha, beta, kappa).ok()
}

fn unit(u: &mut Unstructured<'_>) -> Option<Vec3> {
    let v = Vec3::new(bounded(u, 1.0)?, bounded(u, 1.0)?, bounded(u, 1.0)?);
    let n = v.norm();
    (n > 1e-3).then(|| (1.0 / n) * v)
}

/// The properties of the module docs for one input.
pub fn rough_maps(data: &[u8]) {
    let mut u = Unstructured::new(data);
    let (Some(m), Some(v1), Some(w1), Some(v2), Some(w2), Some(n)) = (
        map(&mut u),
        vector(&mut u),
        vector(&mut u),
        vector(&mut u),
        vector(&mut u),
        unit(&mut u),
    ) else {
        return;
    };
    let k = m.kappa();
    let (a1, b1, a2, b2) = m.collide(v1, w1, v2, w2, n);
    let what = || format!("{m:?} {v1:?} {w1:?} {v2:?} {w2:?} {n:?}");
    assert!(
        a1.is_finite() && b1.is_finite() && a2.is_finite() && b2.is_finite(),
        "not finite: {}",
        what()
    );
    let eps = f64::EPSILON;
    // Floored at the smallest normal number: below it the absolute rounding of subnormal
    // results dominates (as in `maps.rs`).
    let s = (v1.norm() + v2.norm() + w1.norm() + w2.norm()).max(f64::MIN_POSITIVE);
    assert!(
        ((a1 + a2) - (v1 + v2)).norm() <= 64.0 * eps * s,
        "momentum: {}",
        what()
    );
    let l =
        |v1: Vec3, w1: Vec3, v2: Vec3, w2: Vec3| k * (w1 + w2) + (-1.0 * n).cross(v1) + n.cross(v2);
    let dl = l(a1, b1, a2, b2) - l(v1, w1, v2, w2);
    assert!(
        dl.norm() <= 256.0 * eps * s,
        "angular momentum about the contact changes by {dl:?}: {}",
        what()
    );
    let energy = |v1: Vec3, w1: Vec3, v2: Vec3, w2: Vec3| {
        v1.norm2() + v2.norm2() + k * (w1.norm2() + w2.norm2())
    };
    let de = 0.5 * (energy(a1, b1, a2, b2) - energy(v1, w1, v2, w2));
    let g = RoughMap::contact_velocity(v1, w1, v2, w2, n);
    let closed = m.energy_change(g, n);
    let scale = (s * s / k).max(f64::MIN_POSITIVE);
    assert!(
        (de - closed).abs() <= 1024.0 * eps * scale,
        "energy change {de} vs its closed form {closed}: {}",
        what()
    );
    assert!(closed <= 0.0, "energy gained: {closed}: {}", what());
    if m.alpha() == 1.0 && m.beta().abs() == 1.0 {
        assert!(
            de.abs() <= 1024.0 * eps * scale,
            "elastic: {de}: {}",
            what()
        );
    }
    if m.beta() == -1.0 {
        assert_eq!((b1, b2), (w1, w2), "beta = -1 moved a spin: {}", what());
    }
    // The impact direction from a seed in the input.
    if let Ok(seed) = u.arbitrary::<u64>() {
        let mut rng = seeded(seed);
        let uu = v1 - v2;
        let d = impact_direction(uu, &mut rng);
        assert!(
            d.is_finite() && (d.norm() - 1.0).abs() <= 1e-12,
            "impact direction not a unit vector: {d:?} for {uu:?}"
        );
        assert!(
            d.dot(uu) >= -1e-12 * uu.norm(),
            "impact direction receding: {d:?} for {uu:?}"
        );
    }
    // Disks: planar velocities, spins along z, an in-plane contact direction.
    let planar = |v: Vec3| Vec3::new(v.x, v.y, 0.0);
    let axial = |w: Vec3| Vec3::new(0.0, 0.0, w.z);
    let np = planar(n);
    if np.norm() > 1e-3 {
        let np = (1.0 / np.norm()) * np;
        let (p1, q1, p2, q2) = (planar(v1), axial(w1), planar(v2), axial(w2));
        let (a1, b1, a2, b2) = m.collide(p1, q1, p2, q2, np);
        assert!(
            a1.z == 0.0 && a2.z == 0.0 && b1.x == 0.0 && b1.y == 0.0 && b2.x == 0.0 && b2.y == 0.0,
            "disks left their axes: {a1:?} {b1:?} {a2:?} {b2:?}: {}",
            what()
        );
    }
    if let Ok(seed) = u.arbitrary::<u64>() {
        let mut rng = seeded(seed);
        let uu = planar(v1 - v2);
        let d = Disks::impact(uu, &mut rng);
        let e = Disks::scattering::<HardSpheres, _>(uu, &mut rng);
        for (name, x) in [("impact", d), ("scattering", e)] {
            assert!(
                x.is_finite() && x.z == 0.0 && (x.norm() - 1.0).abs() <= 1e-12,
                "disks' {name} direction not a unit vector of the plane: {x:?} for {uu:?}"
            );
        }
        assert!(
            d.dot(uu) >= -1e-12 * uu.norm(),
            "disks' impact direction receding: {d:?} for {uu:?}"
        );
    }
}
