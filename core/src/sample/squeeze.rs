//! Squeezes for the ziggurat wedges (Marsaglia 1977's squeeze idea; the chord and tangent
//! bounds of Marsaglia and Tsang 2000, Section 2): the wedge test `y < f(x)` decided from the
//! table values alone, without `exp`, whenever the decision is certain.
//!
//! A wedge spans `x` in `[a, b]` (`a = x_{i+1} < b = x_i`) and `y` between `f(b)` and `f(a)`.
//! Where `f` is convex on `[a, b]` it lies below its chord and above its tangents at `a` and
//! `b`; where it is concave, the other way round. A point below the lower bound is accepted and
//! one above the upper bound rejected, each with a margin of `1e-12 f(a)`: far above the
//! rounding of the bounds (a few ulps of `f(a)`) and of the `exp` it replaces (the argument's
//! rounding and one ulp of `exp`, about `2e-15` relative), so every decided point gets the
//! decision the `exp` test gives, bit for bit, and the samplers' draws are unchanged. Only
//! points within the margin of the bounds fall through to `exp`.

use crate::math::{Real, max, min};

/// The margin of a decision, relative to `f(a)` (module docs).
const MARGIN: Real = 1e-12;

/// The shape of `f` on a wedge's interval.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum Shape {
    /// `f'' >= 0` on the interval: below the chord, above the tangents.
    Convex,
    /// `f'' <= 0` on the interval: above the chord, below the tangents.
    Concave,
}

/// A wedge `x in [a, b]` of a decreasing density `f` with `fa = f(a) >= fb = f(b)` and slopes
/// `da = f'(a)`, `db = f'(b)`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct Wedge {
    pub a: Real,
    pub b: Real,
    pub fa: Real,
    pub fb: Real,
    pub da: Real,
    pub db: Real,
    pub shape: Shape,
}

impl Wedge {
    /// `Some(y < f(x))` when the bounds decide it (module docs), `None` when `f(x)` itself is
    /// needed. `x` in `[a, b]`.
    #[inline(always)]
    pub(crate) fn decide(&self, x: Real, y: Real) -> Option<bool> {
        let m = MARGIN * self.fa;
        let chord = self.fa + (self.fb - self.fa) * ((x - self.a) / (self.b - self.a));
        let ta = self.fa + self.da * (x - self.a);
        let tb = self.fb + self.db * (x - self.b);
        let (lower, upper) = match self.shape {
            Shape::Convex => (max(ta, tb), chord),
            Shape::Concave => (chord, min(ta, tb)),
        };
        if y < lower - m {
            Some(true)
        } else if y >= upper + m {
            Some(false)
        } else {
            None
        }
    }
}

#[cfg(test)]
mod tests {
    //! The squeezed samplers against their `exp`-only twins (the code before the squeeze),
    //! draw for draw from the same seeds, and the squeeze's decisions against `exp` at points
    //! crowded near every wedge's bounds.
    use super::super::ziggurat_tables::{EXP_F, EXP_R, EXP_X, NORM_F, NORM_R, NORM_X};
    use crate::math::{Real, abs, exp, ln, one_to_two};
    use crate::rng::{Rng, seeded, uniform_open01, uniform01};
    use crate::sample::{standard_exponential, standard_normal};

    fn normal_exp_only<R: Rng + ?Sized>(rng: &mut R) -> Real {
        loop {
            let bits = rng.next_u64();
            let i = (bits & 0xff) as usize;
            let u = 2.0 * one_to_two(bits) - 3.0;
            let x = u * NORM_X[i];
            if abs(x) < NORM_X[i + 1] {
                return x;
            }
            if i == 0 {
                loop {
                    let x = ln(uniform_open01(rng)) / NORM_R;
                    let y = ln(uniform_open01(rng));
                    if -2.0 * y >= x * x {
                        return if u < 0.0 { x - NORM_R } else { NORM_R - x };
                    }
                }
            }
            let y = NORM_F[i + 1] + (NORM_F[i] - NORM_F[i + 1]) * uniform01(rng);
            if y < exp(-0.5 * x * x) {
                return x;
            }
        }
    }

    fn exponential_exp_only<R: Rng + ?Sized>(rng: &mut R) -> Real {
        loop {
            let bits = rng.next_u64();
            let i = (bits & 0xff) as usize;
            let x = (one_to_two(bits) - 1.0) * EXP_X[i];
            if x < EXP_X[i + 1] {
                return x;
            }
            if i == 0 {
                return EXP_R - ln(uniform_open01(rng));
            }
            let y = EXP_F[i + 1] + (EXP_F[i] - EXP_F[i + 1]) * uniform01(rng);
            if y < exp(-x) {
                return x;
            }
        }
    }

    #[test]
    fn samplers_draw_the_same_bits_as_without_the_squeeze() {
        for seed in 0..4 {
            let (mut r1, mut r2) = (seeded(seed), seeded(seed));
            for k in 0..500_000 {
                let (a, b) = (standard_normal(&mut r1), normal_exp_only(&mut r2));
                assert_eq!(a.to_bits(), b.to_bits(), "normal, seed {seed}, draw {k}");
                let (a, b) = (standard_exponential(&mut r1), exponential_exp_only(&mut r2));
                assert_eq!(
                    a.to_bits(),
                    b.to_bits(),
                    "exponential, seed {seed}, draw {k}"
                );
            }
        }
    }

    /// Every layer's wedge, `x` on a grid and `y` crowded within `1e-9 f(a)` of the chord and
    /// the tangents (where a wrong margin would show): every decision equals `exp`'s, and the
    /// squeeze decides most uniform points of the wedge (else it would save nothing).
    #[test]
    fn decisions_equal_the_exp_test() {
        let mut rng = seeded(7);
        let (mut decided, mut uniform) = (0u32, 0u32);
        for (normal, i) in (1..256)
            .map(|i| (true, i))
            .chain((1..256).map(|i| (false, i)))
        {
            let f = |x: Real| if normal { exp(-0.5 * x * x) } else { exp(-x) };
            // The samplers' own wedges (`None`: the normal layer that straddles 1).
            let w = if normal {
                match super::super::normal::wedge(i) {
                    Some(w) => w,
                    None => continue,
                }
            } else {
                super::super::exponential::wedge(i)
            };
            let (a, b, fa, fb, da, db) = (w.a, w.b, w.fa, w.fb, w.da, w.db);
            for k in 0..=64 {
                let x = a + (b - a) * (k as Real / 64.0);
                let chord = fa + (fb - fa) * ((x - a) / (b - a));
                let (ta, tb) = (fa + da * (x - a), fb + db * (x - b));
                for centre in [chord, ta, tb, f(x)] {
                    for s in -20..=20 {
                        let y = centre + fa * 1e-9 * (s as Real / 20.0);
                        if let Some(d) = w.decide(x, y) {
                            assert_eq!(d, y < f(x), "layer {i} (normal {normal}) x {x} y {y}");
                        }
                    }
                }
                let y = fb + (fa - fb) * uniform01(&mut rng);
                uniform += 1;
                if let Some(d) = w.decide(x, y) {
                    decided += 1;
                    assert_eq!(d, y < f(x), "layer {i} (normal {normal}) x {x} y {y}");
                }
            }
        }
        assert!(
            decided as Real > 0.9 * uniform as Real,
            "the squeeze decided {decided} of {uniform} uniform wedge points"
        );
    }
}
