//! The replacement of a group of weighted particles by two (Rjasanow and Wagner 1996's
//! reduction step), keeping the group's weight, momentum, energy and fourth moment about the
//! flow.

use super::packed::{packed, weight};
use crate::geometry::DimensionChoice;
use crate::math::{Real, sqrt};
use crate::particles::Particle;
use crate::rng::Rng;
use crate::sample::{unit_circle, unit_sphere};
use crate::vec3::Vec3;

/// Two particles in place of `group` (packed records, [`super::packed`]: at least one, each
/// weight positive): weight `W/2` each at `V + d` and `V - d`, `W = sum g`, `V = sum g v / W`, `|d|^2 = sigma^2 =
/// sum g |v - V|^2 / W`. The group's weight, momentum `W V` and energy
/// `sum g |v|^2 / 2 = W (|V|^2 + sigma^2) / 2` are kept to rounding. The direction of `d`
/// keeps the spread of the squared speeds about the flow `flow` too: with `A = V - flow`, the
/// two squared speeds are `|A|^2 + sigma^2 +- 2 A . d`, so `d` leans toward `A` by the angle
/// whose cosine is `sqrt(Var |v - flow|^2) / (2 |A| sigma)` (at most 1) and lies otherwise
/// along the group's principal axis across `A`; then `sum g |v - flow|^4` is kept as well
/// (the fourth moment, so `a2`), unless the cosine had to be cut at 1. Two points symmetric
/// about `V` along one fixed direction would put the whole group at one speed (across `A`) or
/// spread it over twice its width (along a uniform direction); repeated, either moves the tail
/// where the density falls (docs/weighted.md).
pub(crate) fn reduce_group<R: Rng + ?Sized>(
    group: &[Particle],
    flow: Vec3,
    dim: DimensionChoice,
    rng: &mut R,
) -> [Particle; 2] {
    let w: Real = group.iter().map(weight).sum();
    let m = (group.iter()).fold(Vec3::ZERO, |m, p| m + weight(p) * p.velocity());
    let v = (1.0 / w) * m;
    let s2: Real = group
        .iter()
        .map(|p| weight(p) * (p.velocity() - v).norm2())
        .sum::<Real>()
        / w;
    let start = match dim {
        DimensionChoice::Three => unit_sphere(rng),
        DimensionChoice::Two => unit_circle(rng),
    };
    let axis = principal_axis(group, v, start);
    let a = v - flow;
    let (na, sigma) = (a.norm(), sqrt(s2));
    let e = if na > 0.0 && sigma > 0.0 {
        let radial = (1.0 / na) * a;
        let mean_r: Real = s2 + na * na;
        let var_r: Real = (group.iter())
            .map(|p| {
                let x = (p.velocity() - flow).norm2() - mean_r;
                weight(p) * x * x
            })
            .sum::<Real>()
            / w;
        let cos = sqrt(var_r) / (2.0 * na * sigma);
        let cos = if cos < 1.0 { cos } else { 1.0 };
        // The principal axis across A (or the random start's part across it).
        let across = |x: Vec3| x - x.dot(radial) * radial;
        let t = match across(axis) {
            t if t.norm() > 1e-12 => (1.0 / t.norm()) * t,
            _ => {
                let t = across(start);
                if t.norm() > 1e-12 {
                    (1.0 / t.norm()) * t
                } else {
                    Vec3::ZERO
                }
            }
        };
        cos * radial + sqrt(1.0 - cos * cos) * t
    } else {
        axis
    };
    let d = sigma * e;
    [packed(v + d, 0.5 * w), packed(v - d, 0.5 * w)]
}

/// The unit principal axis of the weighted covariance of `group` about `v`: the covariance
/// summed in one pass and squared four times (each square scaled by its trace), so that two
/// products with `start` (a unit vector) are 32 steps of power iteration; `start` when the
/// group has no spread.
fn principal_axis(group: &[Particle], v: Vec3, start: Vec3) -> Vec3 {
    // C = sum g c c^T, c = v_k - v, as a full symmetric 3 x 3.
    let mut m = [[0.0; 3]; 3];
    for p in group {
        let c = p.velocity() - v;
        let (cv, gc) = ([c.x, c.y, c.z], weight(p) * c);
        for (row, gk) in m.iter_mut().zip([gc.x, gc.y, gc.z]) {
            for (e, ck) in row.iter_mut().zip(cv) {
                *e += gk * ck;
            }
        }
    }
    for _ in 0..4 {
        let trace = m[0][0] + m[1][1] + m[2][2];
        if !(trace > 0.0 && trace.is_finite()) {
            return start;
        }
        let s = 1.0 / trace;
        let a = m.map(|row| row.map(|e| s * e));
        m = core::array::from_fn(|i| {
            core::array::from_fn(|j| (0..3).map(|k| a[i][k] * a[k][j]).sum())
        });
    }
    let apply = |x: Vec3| {
        Vec3::new(
            m[0][0] * x.x + m[0][1] * x.y + m[0][2] * x.z,
            m[1][0] * x.x + m[1][1] * x.y + m[1][2] * x.z,
            m[2][0] * x.x + m[2][1] * x.y + m[2][2] * x.z,
        )
    };
    let mut x = start;
    for _ in 0..2 {
        let y = apply(x);
        let norm = y.norm();
        if !(norm > 0.0 && norm.is_finite()) {
            return x;
        }
        x = (1.0 / norm) * y;
    }
    x
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A group's two replacements keep its weight, momentum, energy and, while the lean toward the
    /// flow is below its limit, the fourth moment `sum g |v - flow|^4` (module docs of
    /// [`reduce_group`]): a cell of five unequal particles around (2, 1, 0), flow (0.1, 0, 0).
    #[test]
    fn a_group_keeps_its_fourth_moment_about_the_flow() {
        let flow = Vec3::new(0.1, 0.0, 0.0);
        let group = [
            packed(Vec3::new(2.1, 1.0, 0.1), 0.3),
            packed(Vec3::new(1.9, 1.2, -0.1), 0.1),
            packed(Vec3::new(2.0, 0.8, 0.2), 0.25),
            packed(Vec3::new(2.2, 1.1, -0.2), 0.05),
            packed(Vec3::new(1.8, 0.9, 0.0), 0.3),
        ];
        let sums = |ps: &[Particle]| {
            ps.iter()
                .fold((0.0, Vec3::ZERO, 0.0, 0.0), |(w, m, e, f), p| {
                    let c2 = (p.velocity() - flow).norm2();
                    (
                        w + weight(p),
                        m + weight(p) * p.velocity(),
                        e + weight(p) * p.velocity().norm2(),
                        f + weight(p) * c2 * c2,
                    )
                })
        };
        let mut rng = crate::rng::Streams::new(50).next().unwrap();
        for dim in [DimensionChoice::Three, DimensionChoice::Two] {
            let mut g = group;
            if dim == DimensionChoice::Two {
                for p in &mut g {
                    p.vz = 0.0;
                }
            }
            let two = reduce_group(&g, flow, dim, &mut rng);
            let (a, b) = (sums(&g), sums(&two));
            assert!((a.0 - b.0).abs() < 1e-14);
            assert!((a.1 - b.1).norm() < 1e-13);
            assert!((a.2 - b.2).abs() < 1e-13 * a.2);
            assert!(
                (a.3 - b.3).abs() < 1e-12 * a.3,
                "{dim:?}: {} vs {}",
                a.3,
                b.3
            );
            if dim == DimensionChoice::Two {
                assert!(two.iter().all(|p| p.vz == 0.0));
            }
        }
    }
}
