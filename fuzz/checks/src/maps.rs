//! The collision maps for any finite inputs (magnitudes up to 1e150, so that squares stay
//! finite): finite outputs; the conserved quantities conserved and the energy change equal to
//! its closed form, both within a rounding bound of `k` ulps of the largest magnitude involved
//! (each output is a few additions and multiplications of the inputs, each contributing half an
//! ulp of its result; `k` is a generous count of them, as in core/tests/collision_maps.rs).

use crate::bounded;
use arbitrary::Unstructured;
use gdsmc_core::collision::{
    MassRatio, elastic_background, energy_change, inelastic, scattering_direction_from_impact,
};
use gdsmc_core::restitution::{ImpactSpeed, Restitution};
use gdsmc_core::vec3::Vec3;

/// Largest input magnitude: `|v|^2` of three such components stays finite.
const MAX: f64 = 1e150;

fn tol(scale: f64, k: f64) -> f64 {
    k * f64::EPSILON * scale.max(f64::MIN_POSITIVE)
}

/// The rounding bound of a check's own mass-weighted sums of products, such as `m |v|^2 + m_B
/// |w|^2` or `m v + m_B w`, below the normal range: a product or a square that underflows is
/// off by up to half the smallest subnormal in absolute terms, not relatively, and the mass then
/// multiplies that error. `k` counts such products (BRS (2)'s energy has twelve squares).
fn underflow(mass: f64, k: f64) -> f64 {
    k * mass * f64::from_bits(1)
}

fn vector(u: &mut Unstructured<'_>) -> Option<Vec3> {
    Some(Vec3::new(
        bounded(u, MAX)?,
        bounded(u, MAX)?,
        bounded(u, MAX)?,
    ))
}

fn unit(u: &mut Unstructured<'_>) -> Option<Vec3> {
    let v = Vec3::new(bounded(u, 1.0)?, bounded(u, 1.0)?, bounded(u, 1.0)?);
    let n = v.norm();
    (n > 1e-3).then(|| (1.0 / n) * v)
}

/// An alpha in (0, 1], with 1 (elastic) often.
fn alpha(u: &mut Unstructured<'_>) -> Option<f64> {
    if u.ratio(1u8, 4u8).ok()? {
        return Some(1.0);
    }
    let a = bounded(u, 1.0)?.abs();
    (a > 0.0).then_some(a)
}

/// GRW (3), its MS impact form, BRS (2) and the impact-speed law.
pub fn collision_maps(data: &[u8]) {
    let mut u = Unstructured::new(data);
    let (Some(v), Some(w), Some(e), Some(a)) =
        (vector(&mut u), vector(&mut u), unit(&mut u), alpha(&mut u))
    else {
        return;
    };
    // GRW (3).
    let (v1, w1) = inelastic(v, w, e, a);
    assert!(
        v1.is_finite() && w1.is_finite(),
        "GRW (3) not finite: {v:?} {w:?} {e:?} {a}"
    );
    let s = v.norm() + w.norm();
    assert!(
        ((v1 + w1) - (v + w)).norm() <= tol(s, 16.0),
        "GRW (3) momentum: {v:?} {w:?} {e:?} {a}"
    );
    let s2 = v.norm2() + w.norm2();
    let de = v1.norm2() + w1.norm2() - s2;
    let formula = energy_change(v - w, e, a);
    assert!(
        (de - formula).abs() <= tol(s2, 64.0),
        "GRW (3) energy change {de} vs its closed form {formula}: {v:?} {w:?} {e:?} {a}"
    );
    assert!(
        de <= tol(s2, 64.0),
        "GRW (3) gains energy {de}: {v:?} {w:?} {e:?} {a}"
    );
    if a == 1.0 {
        assert!(
            de.abs() <= tol(s2, 64.0),
            "elastic GRW (3) changes energy by {de}"
        );
    }
    // MS's impact form equals GRW (3) with e from the line of centres s.
    if let Some(sdir) = unit(&mut u) {
        let uu = v - w;
        let e2 = scattering_direction_from_impact(uu, sdir);
        let (g1, h1) = inelastic(v, w, e2, a);
        let k = 0.5 * (1.0 + a) * uu.dot(sdir);
        let (m1, n1) = (v - k * sdir, w + k * sdir);
        assert!(
            (g1 - m1).norm() <= tol(s, 32.0) && (h1 - n1).norm() <= tol(s, 32.0),
            "MS impact form differs from GRW (3): {v:?} {w:?} {sdir:?} {a}"
        );
    }
    // BRS (2): m v + m_B w and m |v|^2 + m_B |w|^2 kept.
    if let (Some(m), Some(mb)) = (bounded(&mut u, 1e6), bounded(&mut u, 1e6))
        && let Some(ratio) = MassRatio::new(m.abs(), mb.abs())
    {
        let (m, mb) = (m.abs(), mb.abs());
        let (v2, w2) = elastic_background(v, w, e, ratio);
        assert!(v2.is_finite() && w2.is_finite(), "BRS (2) not finite");
        let p0 = m * v + mb * w;
        let p1 = m * v2 + mb * w2;
        // The terms of m v' + m_B w' are as large as (m + m_B)(|v| + |w| + |g|), not m |v| +
        // m_B |w|: with m >> m_B and |v| << |w| the sum cancels large terms.
        let ps = (m + mb) * 2.0 * (v.norm() + w.norm());
        assert!(
            (p1 - p0).norm() <= tol(ps, 64.0) + underflow(m + mb, 64.0),
            "BRS (2) momentum: {p0:?} -> {p1:?} (m {m:e}, m_B {mb:e}): {v:?} {w:?} {e:?}"
        );
        let e0 = m * v.norm2() + mb * w.norm2();
        let e1 = m * v2.norm2() + mb * w2.norm2();
        let es = (m + mb) * (v.norm() + w.norm()).powi(2);
        // A grain of 1e-156 against a light background: squares of 1e-162 underflow to zero in
        // `e1` while their mass-weighted sum is 1e-319 (fuzzer find, regressions/collision_maps).
        assert!(
            (e1 - e0).abs() <= tol(es, 64.0) + underflow(m + mb, 64.0),
            "BRS (2) energy: {e0:e} -> {e1:e} (m {m:e}, m_B {mb:e}): {v:?} {w:?} {e:?}"
        );
    }
    // The impact-speed law BRS (9)-(10): the normal impact speed lies in [0, |u|] and the
    // coefficient is finite for any law the constructor accepts.
    if let (Some(b0), Some(d)) = (bounded(&mut u, 1e3), bounded(&mut u, 10.0))
        && let Ok(law) = ImpactSpeed::new(b0.abs(), d.abs())
    {
        let uu = v - w;
        let g = ImpactSpeed::normal_speed(uu, e);
        assert!(
            g >= 0.0 && g <= uu.norm() * (1.0 + 4.0 * f64::EPSILON),
            "|g . n| = {g} outside [0, |u|]"
        );
        let c = law.coefficient(uu, e);
        assert!(!c.is_nan() && c <= 1.0, "impact-speed coefficient {c}");
    }
}
