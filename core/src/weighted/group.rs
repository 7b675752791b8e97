//! The replacement of a cell of weighted particles by a sample of its own velocities, and the
//! one correction that keeps the weight, momentum and energy of everything a reduction
//! replaced (Rjasanow and Wagner 1996's reduction step, made unbiased).
//!
//! A cell of weight `W` becomes two particles of weight `W/2` at the velocities of two of its
//! members drawn by systematic sampling in order of their speed about the flow (one from the
//! slower half of the weight, one from the faster), each member `2 g_k / W` times on average (one
//! particle of weight `W` when a member heavier than half is drawn twice), so the expected
//! measure after the draw is the cell's measure: `E[W/2 (phi(v_i) + phi(v_j))] = sum_k g_k phi(v_k)` for every `phi`, the
//! histograms and the tail included. The draw keeps each cell's weight exactly, its momentum
//! and energy only on average; the representatives of all cells of one reduction are then
//! moved together by the affine map `v -> U + lambda (v - U')` (`U`, `U'` the replaced and the
//! drawn mean velocity, `lambda^2` the ratio of their spreads about them), which makes the
//! replaced set's weight, momentum and energy those it had, to rounding. `lambda - 1` is of
//! order `h / sqrt(cells)` (`h` a cell's width over the distribution's), so the correction
//! moves the sample far less than its own noise.
//!
//! Why not the deterministic replacement (two points `V +- sigma e` that keep each cell's
//! momentum and energy): any such pair puts the cell at two points a fixed `sigma` from its
//! mean, a bias in every quantity finer than the cell, and the collisions carry it from
//! reduction to reduction. In the Maxwell gas's cooling state (alpha = 1/2, `n0 = 256`, `kappa
//! = 1`, a reduction from 8 to 2 `n0` particles, t = 10-20) that replacement (principal axis,
//! leaning to keep the fourth moment about the flow) left the scaled density 12% high at `c =
//! 0`, 18% low at `c = 1` and 35-41% high at `c = 2.25-2.75` against equal weights at `n =
//! 4096` (chi^2 per shell 400); along a uniform direction, the principal axis alone, or a
//! member's own difference direction, 340-400; sampled cells 1.1 without the correction, and
//! with it 0.9 at `n0 = 1024` (at 256 a few percent of the small system's own, docs/weighted.md).

use super::packed::{packed, weight};
use crate::geometry::DimensionChoice;
use crate::math::{Real, sqrt};
use crate::particles::Particle;
use crate::rng::{Rng, uniform01};
use crate::sample::{unit_circle, unit_sphere};
use crate::vec3::Vec3;

/// Two members of `group` (packed records, weights > 0, total `w`) by systematic sampling:
/// the members at the points `u w/2` and `(u + 1) w/2` of their cumulative weight, `u`
/// uniform on [0, 1), so member `k` is drawn `2 g_k / w` times on average (each of the two
/// draws weighs `w/2`: the expected measure is the group's), and a member of at most half the
/// weight at most once: the two are different unless one weighs more than half.
fn draw_two<R: Rng + ?Sized>(group: &[Particle], w: Real, rng: &mut R) -> (usize, usize) {
    let u = uniform01(rng);
    let (at, mut found) = ([u * 0.5 * w, (u + 1.0) * 0.5 * w], [group.len() - 1; 2]);
    let mut sum = 0.0;
    let mut next = 0;
    for (k, p) in group.iter().enumerate() {
        sum += weight(p);
        while next < 2 && at[next] < sum {
            found[next] = k;
            next += 1;
        }
        if next == 2 {
            break;
        }
    }
    (found[0], found[1])
}

/// Puts `group` in order of speed about `flow` (ties as they were): a cell of at most 20 by
/// an insertion sort on the squared speeds computed once (the order the standard library's
/// unstable sort gives such short slices, by the same comparison), a longer one by that sort.
fn by_speed(group: &mut [Particle], flow: Vec3) {
    const SHORT: usize = 20;
    let speed2 = |x: &Particle| (x.velocity() - flow).norm2();
    if group.len() > SHORT {
        group.sort_unstable_by(|p, q| speed2(p).total_cmp(&speed2(q)));
        return;
    }
    let mut keys = [0.0; SHORT];
    for (k, p) in keys.iter_mut().zip(group.iter()) {
        *k = speed2(p);
    }
    for i in 1..group.len() {
        let (key, record) = (keys[i], group[i]);
        let mut j = i;
        while j > 0 && key.total_cmp(&keys[j - 1]).is_lt() {
            keys[j] = keys[j - 1];
            group[j] = group[j - 1];
            j -= 1;
        }
        keys[j] = key;
        group[j] = record;
    }
}

/// Marked records farther than this many standard deviations of the draws from their mean
/// keep their velocities, and the rest carry the correction ([`Tally::conserve`]): a global
/// scale about the mean moves a far, light record by its distance times `lambda - 1`, and
/// repeated reductions walked such records of a cooling hard-sphere gas (a light particle
/// at a few times `sqrt(T)`, kept there by the weight transfer) out to overflow.
const FAR: Real = 3.0;

/// A weighted mean and spread accumulated one point at a time (West's weighted form of
/// Welford's update, Comm. ACM 22 (1979) 532): the weight `w`, the mean `mean` and `m2 = sum
/// g |c - mean|^2`, without the cancellation of `sum g |c|^2 - w |mean|^2` (which, for a set
/// whose spread is far below its distance from the flow, left rounding noise as the spread of
/// the draws: a scale factor of 1e4-1e7, and a cooling gas of hard spheres blew up).
#[derive(Clone, Copy, Debug, Default)]
struct Spread {
    w: Real,
    mean: Vec3,
    m2: Real,
}

impl Spread {
    /// The point `c` of weight `g > 0` added.
    fn add(&mut self, g: Real, c: Vec3) {
        self.w += g;
        let d = c - self.mean;
        self.mean += (g / self.w) * d;
        self.m2 += g * d.dot(c - self.mean);
    }

    /// The spread `m2 / w` (0 for nothing, never below 0).
    fn s2(&self) -> Real {
        if self.w > 0.0 && self.m2 > 0.0 {
            self.m2 / self.w
        } else {
            0.0
        }
    }
}

/// What one reduction replaced and what it drew in its place, about the system's flow: the
/// weight, mean and spread of `c = v - flow` before and after.
#[derive(Clone, Copy, Debug)]
pub(crate) struct Tally {
    flow: Vec3,
    before: Spread,
    after: Spread,
}

impl Tally {
    /// Nothing replaced yet, about the system's flow velocity `flow`.
    pub(crate) fn new(flow: Vec3) -> Self {
        Tally {
            flow,
            before: Spread::default(),
            after: Spread::default(),
        }
    }

    /// The sample in place of `group` (at least one packed record, each weight positive):
    /// one or two packed records, their weights negated to mark them for [`Tally::conserve`];
    /// `None` in the second slot when the same member was drawn twice. The members are put in
    /// order of speed about the flow first, so the systematic sample takes one from the slower
    /// half of the weight and one from the faster (a sample stratified by speed, as unbiased
    /// as any order, with less noise in what depends on the speed: the tail probabilities).
    pub(crate) fn replace<R: Rng + ?Sized>(
        &mut self,
        group: &mut [Particle],
        rng: &mut R,
    ) -> (Particle, Option<Particle>) {
        by_speed(group, self.flow);
        let w: Real = group.iter().map(weight).sum();
        for p in group.iter() {
            self.before.add(weight(p), p.velocity() - self.flow);
        }
        let (i, j) = draw_two(group, w, rng);
        let (a, b) = (group[i].velocity(), group[j].velocity());
        for v in [a, b] {
            self.after.add(0.5 * w, v - self.flow);
        }
        if i == j {
            (packed(a, -w), None)
        } else {
            (packed(a, -0.5 * w), Some(packed(b, -0.5 * w)))
        }
    }

    /// Moves the marked records of `buf[..*len]` ([`Tally::replace`]) by the module's affine
    /// map and unmarks them, so that together they have the weight, momentum and energy of
    /// what they replaced. When the draws have no spread to scale (every marked record at
    /// one velocity: a single cell drawn to one member) while the replaced set had one, the
    /// heaviest of them is split into two of half its weight symmetric about it along a uniform
    /// direction (written at `buf[*len]`, which the reduction has freed), as far apart as
    /// keeps the energy.
    pub(crate) fn conserve<R: Rng + ?Sized>(
        &self,
        buf: &mut [Particle],
        len: &mut usize,
        dim: DimensionChoice,
        rng: &mut R,
    ) {
        if self.before.w <= 0.0 {
            return;
        }
        // About the drawn mean `u1`: the replaced set's mean `du` and spread `s2`.
        let u1 = self.after.mean;
        let (du, s2) = (self.before.mean - u1, self.before.s2());
        let spread = s2 > 0.0 && s2.is_finite();
        let marked = |q: &Particle| (weight(q) < 0.0).then(|| (-weight(q), q.velocity()));
        let radius2 = FAR * FAR * self.after.s2();
        let (mut near, mut far, mut every) =
            (Spread::default(), Spread::default(), Spread::default());
        for (g, v) in buf[..*len].iter().filter_map(marked) {
            let c = v - self.flow - u1;
            every.add(g, c);
            if c.norm2() > radius2 {
                far.add(g, c);
            } else {
                near.add(g, c);
            }
        }
        // The map of the near records `c -> m + lambda (c - near.mean)`, the far ones kept:
        // the near records' mean and spread that give the whole set its momentum and energy.
        let fit = |near: &Spread, far: &Spread| {
            let w_near = self.before.w - far.w;
            let m = (1.0 / w_near) * (self.before.w * du - far.w * far.mean);
            let energy = self.before.w * (s2 + du.norm2()) - far.m2 - far.w * far.mean.norm2();
            let s2_near = energy / w_near - m.norm2();
            (s2_near > 0.0 && near.s2() > 0.0 && s2_near.is_finite())
                .then(|| (m, sqrt(s2_near / near.s2()), near.mean))
        };
        let (m, lambda, center, keep_far) = match (far.w > 0.0, near.w > 0.0) {
            (true, true) => fit(&near, &far).map(|(m, l, c)| (m, l, c, true)),
            _ => None,
        }
        .or_else(|| fit(&every, &Spread::default()).map(|(m, l, c)| (m, l, c, false)))
        .unwrap_or((du, 0.0, every.mean, false));
        // The heaviest marked record (the one the degenerate case below splits: the lightest
        // would have to move farthest to carry the spread).
        let mut heaviest: Option<(usize, Real)> = None;
        for (k, q) in buf[..*len].iter_mut().enumerate() {
            if let Some((g, v)) = marked(q) {
                let c = v - self.flow - u1;
                let v = if keep_far && c.norm2() > radius2 {
                    v
                } else {
                    self.flow + u1 + m + lambda * (c - center)
                };
                *q = packed(v, g);
                if heaviest.is_none_or(|(_, h)| g > h) {
                    heaviest = Some((k, g));
                }
            }
        }
        if let (true, true, Some((k, _))) = (spread, lambda == 0.0, heaviest) {
            // One record (all marked ones coincide): two at U +- sigma e.
            let e = match dim {
                DimensionChoice::Three => unit_sphere(rng),
                DimensionChoice::Two => unit_circle(rng),
            };
            let (v, g) = (buf[k].velocity(), 0.5 * weight(&buf[k]));
            // 2 g |d|^2 = W s^2: the replaced set's spread, whatever share of it this is.
            let d = sqrt(s2 * self.before.w / (2.0 * g)) * e;
            buf[k] = packed(v + d, g);
            buf[*len] = packed(v - d, g);
            *len += 1;
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::rng::Streams;

    /// The weight, momentum and energy of packed records (weights taken as they are).
    fn sums(ps: &[Particle]) -> (Real, Vec3, Real) {
        ps.iter().fold((0.0, Vec3::ZERO, 0.0), |(w, m, e), p| {
            let g = weight(p).abs();
            (w + g, m + g * p.velocity(), e + g * p.velocity().norm2())
        })
    }

    /// A cell's sample is unbiased: over 40,000 samples of a cell of four unequal weights
    /// (0.1 to 0.4, none above half), each member receives on average its own weight, within
    /// the 99.9% interval jointly over the four (Bonferroni; each sample gives a member `W/2`
    /// with probability `2 g/W`, a binomial standard error). A sampler that drew members
    /// uniformly, not by weight, would give each 0.25 and fail.
    #[test]
    fn a_cells_sample_is_unbiased() {
        let g = [0.1, 0.2, 0.3, 0.4];
        let group: [Particle; 4] =
            core::array::from_fn(|k| packed(Vec3::new(k as Real, 0.0, 0.0), g[k]));
        let mut rng = Streams::new(11).next().unwrap();
        let m = 40_000;
        let mut got = [0.0; 4];
        let mut tally = Tally::new(Vec3::ZERO);
        for _ in 0..m {
            let (a, b) = tally.replace(&mut group.clone(), &mut rng);
            for p in [Some(a), b].into_iter().flatten() {
                got[p.vx as usize] += -weight(&p);
            }
        }
        let z = 3.94; // two-sided 99.9% jointly over 4: the normal quantile of 1 - 0.001/8
        for k in 0..4 {
            let p = 2.0 * g[k];
            let se = 0.5 * (2.0 * p * (1.0 - p) / m as Real).sqrt();
            let mean = got[k] / m as Real;
            assert!(
                (mean - g[k]).abs() <= z * se,
                "member {k}: {mean} vs {}",
                g[k]
            );
        }
    }

    /// [`by_speed`] orders a cell as the standard library's unstable sort by the same
    /// comparison does (the order the reduction had before it computed each speed once), for
    /// every length up to past the insertion sort's 20, with ties: copies at one velocity (the
    /// windows' pieces) and records of one speed in different directions. A sort that was not
    /// stable on ties, or a comparison of the wrong speed, fails.
    #[test]
    fn cells_are_ordered_as_the_library_sort_orders_them() {
        let mut rng = Streams::new(13).next().unwrap();
        let flow = Vec3::new(0.25, -0.5, 0.125);
        for len in 1..=26 {
            for _ in 0..200 {
                let mut cell = [Particle::default(); 26];
                for (k, record) in cell[..len].iter_mut().enumerate() {
                    let x = (uniform01(&mut rng) * 4.0) as usize as Real;
                    *record = match (uniform01(&mut rng) * 3.0) as usize {
                        // Speed x about the flow along x or along y: a tie of speeds.
                        0 => packed(flow + Vec3::new(x, 0.0, 0.0), k as Real + 1.0),
                        1 => packed(flow + Vec3::new(0.0, x, 0.0), k as Real + 1.0),
                        _ => packed(flow + Vec3::new(x, 0.5, 0.0), k as Real + 1.0),
                    };
                }
                let mut ours = cell;
                by_speed(&mut ours[..len], flow);
                let mut library = cell;
                library[..len].sort_unstable_by(|p, q| {
                    let s = |x: &Particle| (x.velocity() - flow).norm2();
                    s(p).total_cmp(&s(q))
                });
                assert_eq!(&ours[..len], &library[..len], "length {len}");
            }
        }
    }

    /// [`Tally::conserve`] gives the samples of several cells the weight, momentum and energy
    /// of what they replaced, to rounding, and unmarks them; a single cell drawn to one member
    /// (a member of 0.9 of its weight) is split into two along a line so that it keeps them too.
    #[test]
    fn the_samples_keep_what_they_replaced() {
        let mut rng = Streams::new(12).next().unwrap();
        let flow = Vec3::new(0.3, -0.1, 0.2);
        let cells: [[Particle; 3]; 3] = core::array::from_fn(|c| {
            core::array::from_fn(|k| {
                let x = (3 * c + k) as Real;
                packed(
                    Vec3::new(libm::sin(x), libm::cos(x), 0.1 * x),
                    0.2 + 0.1 * k as Real,
                )
            })
        });
        let heavy = [[
            packed(Vec3::new(1.0, 0.0, 0.0), 0.9),
            packed(Vec3::new(0.0, 1.0, 0.0), 0.05),
            packed(Vec3::new(0.0, 0.0, 1.0), 0.05),
        ]];
        for (set, dim) in [
            (&cells[..], DimensionChoice::Three),
            (&heavy[..], DimensionChoice::Three),
        ] {
            for _ in 0..20 {
                let before = set
                    .iter()
                    .map(|c| sums(c))
                    .fold((0.0, Vec3::ZERO, 0.0), |a, b| {
                        (a.0 + b.0, a.1 + b.1, a.2 + b.2)
                    });
                let mut tally = Tally::new(flow);
                let mut buf = [Particle::default(); 8];
                let mut len = 0;
                for c in set {
                    let (a, b) = tally.replace(&mut c.clone(), &mut rng);
                    for p in [Some(a), b].into_iter().flatten() {
                        buf[len] = p;
                        len += 1;
                    }
                }
                tally.conserve(&mut buf, &mut len, dim, &mut rng);
                let after = sums(&buf[..len]);
                assert!(buf[..len].iter().all(|p| weight(p) > 0.0), "unmarked");
                assert!(len >= 2);
                assert!((after.0 - before.0).abs() < 1e-14);
                assert!((after.1 - before.1).norm() < 1e-13);
                assert!((after.2 - before.2).abs() < 1e-13 * before.2);
            }
        }
    }
}
