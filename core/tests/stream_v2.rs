//! Stream version 2's draws (`gdsmc_core::rng::STREAM_VERSION`) against version 1's, which are
//! kept here as the reference, and against the exact laws: a candidate pair from one word,
//! a direction on the sphere or the circle from one word per try, two normals from one word,
//! an event's waiting time and acceptance uniform from one word, and the undriven Maxwell
//! gas's events counted by a Poisson draw per interval. Each check is
//! two-sample (Kolmogorov-Smirnov or a chi-square test of homogeneity) at sizes of 2^20 to
//! 2^22 draws per side, so a difference in a CDF of about 2e-3 (a cell's probability off by
//! about 1%) would fail it; the checks of one test hold together at the 99.9% level
//! (Bonferroni, `gdsmc_stats::joint`). Fixed seeds.

use crate::common::{ks_statistic, normal_cdf};
use gdsmc_core::rng::{
    Rng, halves, seeded, uniform_index, uniform_index2, uniform_pair, uniform01, unit_open32,
};
use gdsmc_core::sample::{
    exponential_from_half, poisson, standard_exponential, standard_normal, standard_normal_pair,
    unit_circle, unit_sphere,
};
use gdsmc_core::vec3::Vec3;
use gdsmc_stats::{KNOWN, joint, miss, quantile_t};

/// The two-sample Kolmogorov-Smirnov statistic (both sorted in place).
fn ks_two_sample(a: &mut [f64], b: &mut [f64]) -> f64 {
    a.sort_by(f64::total_cmp);
    b.sort_by(f64::total_cmp);
    let (n, m) = (a.len() as f64, b.len() as f64);
    let (mut i, mut j, mut d) = (0, 0, 0.0f64);
    while i < a.len() && j < b.len() {
        let x = a[i].min(b[j]);
        while i < a.len() && a[i] <= x {
            i += 1;
        }
        while j < b.len() && b[j] <= x {
            j += 1;
        }
        d = d.max((i as f64 / n - j as f64 / m).abs());
    }
    d
}

/// The two-sample KS critical value for sizes `n`, `m` at a miss of `miss / k` (asymptotic:
/// `sqrt(-ln(alpha/2)/2) sqrt((n + m)/(n m))`).
fn ks_two_critical(n: usize, m: usize, k: usize) -> f64 {
    let alpha = miss() / k as f64;
    let (n, m) = (n as f64, m as f64);
    (-(alpha / 2.0).ln() / 2.0).sqrt() * ((n + m) / (n * m)).sqrt()
}

/// The one-sample KS critical value for `n` draws at a miss of `miss / k`.
fn ks_critical(n: usize, k: usize) -> f64 {
    let alpha = miss() / k as f64;
    (-(alpha / 2.0).ln() / 2.0).sqrt() / (n as f64).sqrt()
}

/// The chi-square quantile with `dof` degrees of freedom exceeded with probability
/// `miss / k` (Wilson-Hilferty: within 1% of the exact quantile from 10 degrees of freedom;
/// at 2 a few percent above it, 17.4 against 16.8 at the residues' level: conservative).
fn chi2_critical(dof: usize, k: usize) -> f64 {
    let z = quantile_t(KNOWN / 2, 1.0 - 2.0 * miss() / k as f64);
    let v = dof as f64;
    let h = 2.0 / (9.0 * v);
    v * (1.0 - h + z * h.sqrt()).powi(3)
}

/// The chi-square statistic of homogeneity of two count vectors over the same cells (cells
/// empty in both skipped) and its degrees of freedom.
fn chi2_two_sample(a: &[u64], b: &[u64]) -> (f64, usize) {
    let (na, nb) = (a.iter().sum::<u64>() as f64, b.iter().sum::<u64>() as f64);
    let (ka, kb) = ((nb / na).sqrt(), (na / nb).sqrt());
    let mut cells = 0;
    let mut chi2 = 0.0;
    for (&x, &y) in a.iter().zip(b) {
        if x + y > 0 {
            let d = ka * x as f64 - kb * y as f64;
            chi2 += d * d / (x + y) as f64;
            cells += 1;
        }
    }
    (chi2, cells - 1)
}

/// The chi-square statistic of counts against expected counts (each expected >= 5).
fn chi2_exact(counts: &[u64], expected: &[f64]) -> f64 {
    counts
        .iter()
        .zip(expected)
        .map(|(&c, &e)| (c as f64 - e).powi(2) / e)
        .sum()
}

/// Version 1's pair: two 64-bit Lemire draws.
fn pair_v1<R: Rng>(rng: &mut R, n: usize) -> (usize, usize) {
    let i = uniform_index(rng, n);
    let mut j = uniform_index(rng, n - 1);
    if j >= i {
        j += 1;
    }
    (i, j)
}

/// Version 1's point of Marsaglia's disk: two 53-bit uniforms per try.
fn disk_v1<R: Rng>(rng: &mut R) -> (f64, f64, f64) {
    loop {
        let a = 2.0 * uniform01(rng) - 1.0;
        let b = 2.0 * uniform01(rng) - 1.0;
        let s = a * a + b * b;
        if s < 1.0 && s > 1e-300 {
            return (a, b, s);
        }
    }
}

/// Version 1's direction on the sphere.
fn sphere_v1<R: Rng>(rng: &mut R) -> Vec3 {
    let (a, b, s) = disk_v1(rng);
    let r = 2.0 * (1.0 - s).sqrt();
    Vec3::new(a * r, b * r, 1.0 - 2.0 * s)
}

/// Version 1's count of a unit-rate process's events before `mu`: waiting times.
fn count_v1<R: Rng>(rng: &mut R, mu: f64) -> u64 {
    let (mut t, mut k) = (0.0, 0);
    loop {
        t += standard_exponential(rng);
        if t >= mu {
            return k;
        }
        k += 1;
    }
}

#[test]
fn normals_two_per_word_have_the_law_of_one_per_word() {
    const M: usize = 1 << 21;
    let mut rng = seeded(201);
    let mut pairs: Vec<(f64, f64)> = (0..M).map(|_| standard_normal_pair(&mut rng)).collect();
    let mut new: Vec<f64> = pairs.iter().flat_map(|&(x, y)| [x, y]).collect();
    let mut old: Vec<f64> = (0..2 * M).map(|_| standard_normal(&mut rng)).collect();
    // Five checks: two-sample KS, one-sample KS, the mass beyond 3.5 (both tails, a Poisson
    // count against the exact mass), and independence within a pair by the correlations of
    // x with y and of x^2 with y^2 (each r sqrt(M) is standard normal when independent).
    let k = 5;
    let z = joint(k, KNOWN);
    let far = new.iter().filter(|x| x.abs() > 3.5).count() as f64;
    let expect = 2.0 * M as f64 * 2.0 * (1.0 - normal_cdf(3.5));
    assert!(
        (far - expect).abs() < z * expect.sqrt(),
        "beyond 3.5: {far} vs {expect}"
    );
    let corr = |f: &dyn Fn(f64) -> f64, mean: f64, var: f64| {
        pairs
            .iter()
            .map(|&(x, y)| (f(x) - mean) * (f(y) - mean))
            .sum::<f64>()
            / (M as f64 * var)
    };
    let r1 = corr(&|x| x, 0.0, 1.0);
    let r2 = corr(&|x| x * x, 1.0, 2.0);
    for (what, r) in [("x, y", r1), ("x^2, y^2", r2)] {
        assert!(
            r.abs() * (M as f64).sqrt() < z,
            "correlation of {what}: {r}"
        );
    }
    pairs.clear();
    let mut copy = new.clone();
    let d1 = ks_statistic(&mut copy, normal_cdf);
    assert!(d1 < ks_critical(2 * M, k), "one-sample KS D = {d1}");
    let d2 = ks_two_sample(&mut new, &mut old);
    assert!(
        d2 < ks_two_critical(2 * M, 2 * M, k),
        "two-sample KS D = {d2}"
    );
}

#[test]
fn waiting_times_and_acceptance_uniforms_from_one_word_have_version_1s_laws() {
    // The exact loops' event word: the waiting time from its low half, the acceptance uniform
    // from its high half. Two-sample KS of each against version 1's (a whole word each), the
    // one-sample KS of each against its law, and their independence (the correlation of the
    // uniform with the waiting time's CDF, r sqrt(M) standard normal when independent).
    const M: usize = 1 << 21;
    let mut rng = seeded(206);
    let (mut wait, mut unif): (Vec<f64>, Vec<f64>) = (0..M)
        .map(|_| {
            let (hi, lo) = halves(rng.next_u64());
            (exponential_from_half(&mut rng, lo), unit_open32(hi))
        })
        .unzip();
    let k = 5;
    let r = wait
        .iter()
        .zip(&unif)
        .map(|(&w, &u)| ((1.0 - (-w).exp()) - 0.5) * (u - 0.5))
        .sum::<f64>()
        / (M as f64 / 12.0);
    assert!(
        r.abs() * (M as f64).sqrt() < joint(k, KNOWN),
        "correlation {r}"
    );
    let mut old_wait: Vec<f64> = (0..M).map(|_| standard_exponential(&mut rng)).collect();
    let mut old_unif: Vec<f64> = (0..M).map(|_| uniform01(&mut rng)).collect();
    let d = ks_two_sample(&mut wait.clone(), &mut old_wait);
    assert!(
        d < ks_two_critical(M, M, k),
        "waiting times: two-sample KS D = {d}"
    );
    let d = ks_two_sample(&mut unif.clone(), &mut old_unif);
    assert!(
        d < ks_two_critical(M, M, k),
        "uniforms: two-sample KS D = {d}"
    );
    let d = ks_statistic(&mut wait, |x| 1.0 - (-x).exp());
    assert!(d < ks_critical(M, k), "waiting times: KS D = {d}");
    let d = ks_statistic(&mut unif, |x| x);
    assert!(d < ks_critical(M, k), "uniforms: KS D = {d}");
}

#[test]
fn pairs_from_one_word_have_the_law_of_two_words() {
    // n = 7: the 42 ordered pairs i != j, 2^21 draws by each version (about 50,000 per cell),
    // homogeneity of the two versions and each against the uniform law.
    const M: usize = 1 << 21;
    let n = 7;
    let (mut new, mut old) = (vec![0u64; n * n], vec![0u64; n * n]);
    let mut rng = seeded(202);
    for _ in 0..M {
        let (i, j) = uniform_pair(&mut rng, n);
        assert_ne!(i, j);
        new[i * n + j] += 1;
        let (i, j) = pair_v1(&mut rng, n);
        old[i * n + j] += 1;
    }
    let k = 3;
    let (chi2, dof) = chi2_two_sample(&new, &old);
    assert_eq!(dof, 41);
    assert!(chi2 < chi2_critical(dof, k), "homogeneity: chi2 {chi2}");
    let cells = |c: &[u64]| -> Vec<u64> {
        (0..n * n)
            .filter(|&c| c / n != c % n)
            .map(|x| c[x])
            .collect()
    };
    let expected = vec![M as f64 / 42.0; 42];
    for (what, c) in [("version 2", &new), ("version 1", &old)] {
        let chi2 = chi2_exact(&cells(c), &expected);
        assert!(
            chi2 < chi2_critical(41, k),
            "{what} against uniform: chi2 {chi2}"
        );
    }
}

#[test]
fn indices_from_half_words_are_exact_where_a_quarter_is_rejected() {
    // n = 3 * 2^30: 2^32 mod n = 2^30, so a quarter of the halves are rejected, and without
    // the rejection the values divisible by 3 would be twice as likely as the rest. Each
    // index's 64 equal bins and its residue mod 3, and the joint bins (8 x 8 of the values,
    // 3 x 3 of the residues), against the uniform law.
    const M: usize = 1 << 21;
    let n = 3usize << 30;
    let mut bins = [vec![0u64; 64], vec![0u64; 64], vec![0u64; 64]];
    let mut residues = [vec![0u64; 3], vec![0u64; 3], vec![0u64; 9]];
    let mut rng = seeded(203);
    for _ in 0..M {
        let (i, j) = uniform_index2(&mut rng, n, n);
        assert!(i < n && j < n);
        let (a, b) = (i / (n / 64), j / (n / 64));
        bins[0][a] += 1;
        bins[1][b] += 1;
        bins[2][(a / 8) * 8 + b / 8] += 1;
        residues[0][i % 3] += 1;
        residues[1][j % 3] += 1;
        residues[2][(i % 3) * 3 + j % 3] += 1;
    }
    let k = 6;
    for (what, c) in ["i", "j", "(i, j)"].iter().zip(&bins) {
        let chi2 = chi2_exact(c, &[M as f64 / 64.0; 64]);
        assert!(chi2 < chi2_critical(63, k), "{what}: chi2 {chi2}");
    }
    for (what, c) in ["i mod 3", "j mod 3", "(i, j) mod 3"].iter().zip(&residues) {
        let cells = c.len();
        let chi2 = chi2_exact(c, &vec![M as f64 / cells as f64; cells]);
        assert!(chi2 < chi2_critical(cells - 1, k), "{what}: chi2 {chi2}");
    }
}

#[test]
fn directions_from_one_word_have_the_law_of_two_words() {
    // The sphere: z (uniform on [-1, 1], Archimedes) and the azimuth, two-sample against
    // version 1 and one-sample against the law; the circle: its angle, the same.
    const M: usize = 1 << 20;
    let mut rng = seeded(204);
    let new: Vec<Vec3> = (0..M).map(|_| unit_sphere(&mut rng)).collect();
    let old: Vec<Vec3> = (0..M).map(|_| sphere_v1(&mut rng)).collect();
    let circle: Vec<Vec3> = (0..M).map(|_| unit_circle(&mut rng)).collect();
    let circle_v1: Vec<Vec3> = (0..M)
        .map(|_| {
            let (a, b, s) = disk_v1(&mut rng);
            Vec3::new((a * a - b * b) / s, 2.0 * a * b / s, 0.0)
        })
        .collect();
    let k = 6;
    let pi = std::f64::consts::PI;
    let azimuth = |v: &[Vec3]| -> Vec<f64> { v.iter().map(|e| e.y.atan2(e.x)).collect() };
    let zs = |v: &[Vec3]| -> Vec<f64> { v.iter().map(|e| e.z).collect() };
    for (what, mut a, mut b, cdf) in [
        (
            "sphere z",
            zs(&new),
            zs(&old),
            &(|x: f64| (x + 1.0) / 2.0) as &dyn Fn(f64) -> f64,
        ),
        ("sphere azimuth", azimuth(&new), azimuth(&old), &|x: f64| {
            (x + pi) / (2.0 * pi)
        }),
        (
            "circle angle",
            azimuth(&circle),
            azimuth(&circle_v1),
            &|x: f64| (x + pi) / (2.0 * pi),
        ),
    ] {
        let d = ks_two_sample(&mut a.clone(), &mut b);
        assert!(
            d < ks_two_critical(M, M, k),
            "{what}: two-sample KS D = {d}"
        );
        let d = ks_statistic(&mut a, cdf);
        assert!(d < ks_critical(M, k), "{what}: KS D = {d}");
    }
    assert!(
        new.iter()
            .chain(&circle)
            .all(|e| (e.norm() - 1.0).abs() < 1e-14)
    );
}

/// `ln P(k)` of the Poisson law of mean `mu`, directly.
fn ln_pmf(k: u64, mu: f64) -> f64 {
    -mu + k as f64 * mu.ln() - libm::lgamma(k as f64 + 1.0)
}

#[test]
fn poisson_counts_have_the_law_of_counted_waiting_times() {
    // Each mean against the exact law (cells of expected count >= 5, the tails pooled):
    // Knuth's product below 10, PTRS from 10 (its boundary on both sides), and a mean drawn in
    // pieces of 2^40 by its mean and variance; at mu = 57.3, two-sample against version 1's
    // count of waiting times.
    const M: usize = 1 << 18;
    let means = [0.5, 3.7, 9.99, 10.0, 57.3, 1234.5, 1.0e6];
    let k = means.len() + 3;
    let mut rng = seeded(205);
    let mut at_57 = Vec::new();
    for &mu in &means {
        let draws: Vec<u64> = (0..M).map(|_| poisson(&mut rng, mu)).collect();
        if mu == 57.3 {
            at_57 = draws.clone();
        }
        // Cells: k in [lo, hi] each, below lo and above hi pooled.
        let sd = mu.sqrt();
        let lo = (mu - 6.0 * sd).max(0.0) as u64;
        let hi = (mu + 7.0 * sd) as u64 + 10;
        let mut counts = vec![0u64; (hi - lo + 1) as usize];
        let mut expected: Vec<f64> = (lo..=hi).map(|k| M as f64 * ln_pmf(k, mu).exp()).collect();
        for d in &draws {
            counts[((*d).clamp(lo, hi) - lo) as usize] += 1;
        }
        // The pooled tails: below lo into lo's cell, above hi into hi's.
        let below: f64 = (0..lo).map(|k| ln_pmf(k, mu).exp()).sum::<f64>() * M as f64;
        let above = M as f64 - expected.iter().sum::<f64>() - below;
        expected[0] += below;
        *expected.last_mut().unwrap() += above;
        // Merge cells from each end until each expects at least 5.
        let (mut c, mut e) = (Vec::new(), Vec::new());
        let (mut cc, mut ee) = (0u64, 0.0);
        for (x, y) in counts.iter().zip(&expected) {
            cc += x;
            ee += y;
            if ee >= 5.0 {
                c.push(cc);
                e.push(ee);
                (cc, ee) = (0, 0.0);
            }
        }
        *c.last_mut().unwrap() += cc;
        *e.last_mut().unwrap() += ee;
        let chi2 = chi2_exact(&c, &e);
        assert!(
            chi2 < chi2_critical(c.len() - 1, k),
            "mu {mu}: chi2 {chi2} over {} cells",
            c.len()
        );
    }
    // 3e12 = 2 pieces of 2^40 and the rest: mean and variance against mu.
    let mu = 3.0e12;
    let n = 4096;
    let x: Vec<f64> = (0..n).map(|_| poisson(&mut rng, mu) as f64 - mu).collect();
    let mean = x.iter().sum::<f64>() / n as f64;
    let var = x.iter().map(|d| (d - mean).powi(2)).sum::<f64>() / (n - 1) as f64;
    let z = joint(k, KNOWN);
    assert!(
        mean.abs() < z * (mu / n as f64).sqrt(),
        "mu 3e12: mean off by {mean}"
    );
    // The sample variance's sd is mu sqrt(2/(n-1)) (normal to within mu^-1/2).
    assert!(
        (var - mu).abs() < z * mu * (2.0 / (n - 1) as f64).sqrt(),
        "mu 3e12: var {var}"
    );
    let old: Vec<u64> = (0..M).map(|_| count_v1(&mut rng, 57.3)).collect();
    // Cells 30..=90, the tails pooled into the end cells (about 10 and 40 expected).
    let hist = |v: &[u64]| {
        let mut h = vec![0u64; 61];
        for &x in v {
            h[(x.clamp(30, 90) - 30) as usize] += 1;
        }
        h
    };
    let (chi2, dof) = chi2_two_sample(&hist(&at_57), &hist(&old));
    assert!(
        chi2 < chi2_critical(dof, k),
        "mu 57.3 against version 1: chi2 {chi2}, dof {dof}"
    );
}
