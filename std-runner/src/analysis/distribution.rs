//! The velocity distribution beyond its moments: MS's reduced distribution `f(c)` with
//! `Delta(c)` (MS (45)) and `G(c)` (MS (69), (71), (77)), and BRS's marginal distribution
//! `f_1(v_1)` (BRS Figure 4), from the histograms a scene asks for.

use crate::run::RunStats;
use crate::run::columns::name;
use crate::scene::{DriveKind, KernelKind, Scene};
use gdsmc_theory::exact::sonine::mu2_maxwellian;
use gdsmc_theory::exact::tail;

/// Mean and 99.9% half-width of a column: the steady-state average when the scene has one,
/// else the last observation.
pub fn settled(stats: &RunStats, name: &str) -> Option<(f64, f64)> {
    let col = stats.col(name)?;
    Some(match &stats.steady {
        Some(st) => st.steady_mean_ci(stats, col),
        None => {
            let ti = stats.times.len() - 1;
            (stats.mean(ti, col), stats.ci(ti, col))
        }
    })
}

/// The asymptotic tail law MS derive for the scene's thermostat: `f(c) ~ K exp(-A c^p)`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct TailLaw {
    /// MS's equation.
    pub equation: &'static str,
    /// Amplitude `A`.
    pub amplitude: f64,
    /// Power `p` of `c`.
    pub power: f64,
    /// Where `mu_2` came from: the pairs (MS (67)) or the first Sonine approximation.
    pub mu2_source: &'static str,
}

/// One shell of the reduced distribution.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ReducedShell {
    /// Inner radius in `c`.
    pub c_lo: f64,
    /// Outer radius (infinite for the last).
    pub c_hi: f64,
    /// Weight of the shell and its 99.9% half-width.
    pub f: (f64, f64),
    /// `f~(c)`: weight over shell volume (0 for the unbounded shell).
    pub density: f64,
    /// `phi` averaged over the shell (its exact weight over the volume).
    pub phi: f64,
    /// `f / phi` on the shell (weights' ratio) and its half-width.
    pub ratio: (f64, f64),
    /// `Delta(c) = (f/phi - 1) / a2` (MS (45)) and its half-width (for the estimated `a2`;
    /// the uncertainty of `a2` itself is not included).
    pub delta: (f64, f64),
    /// `S_2(c^2)` at the shell's centre.
    pub s2: f64,
    /// `G(c) = exp(A c^p) f~(c)` at the centre (MS (69), (71), (77)); NaN without a tail law.
    pub g: f64,
    /// The same with `phi` for `f~` (MS's dashed Maxwell-Boltzmann lines).
    pub g_maxwell: f64,
}

/// The reduced distribution of a run.
#[derive(Clone, Debug)]
pub struct Reduced {
    /// The shells, the last one `[c_max, inf)`.
    pub shells: Vec<ReducedShell>,
    /// The fourth cumulant used for `Delta`.
    pub a2: (f64, f64),
    /// The tail law, for hard spheres under one of MS's thermostats (or cooling).
    pub tail: Option<TailLaw>,
}

/// The tail law of MS for this scene, with `mu_2` from the run (pairs) or, without pairs,
/// the first Sonine approximation `mu_2^(0) (1 + 3 a2 / 16)` (MS (26), (28)).
pub fn tail_law(scene: &Scene, stats: &RunStats, a2: f64) -> Option<TailLaw> {
    if scene.physics().kernel.kind() != KernelKind::HardSpheres
        || !scene.translation_is_smooth()
        || scene.dimension() != 3
    {
        return None; // MS's laws: smooth hard spheres
    }
    // MS's tail laws assume a constant restitution coefficient.
    let alpha = scene.physics().restitution.constant()?;
    let (mu2, mu2_source) = match settled(stats, name::MU2) {
        Some((m, _)) => (m, "pairs, MS (67)"),
        None => (
            mu2_maxwellian(alpha) * (1.0 + 3.0 * a2 / 16.0),
            "first Sonine, MS (26)",
        ),
    };
    // MS's tails of its own drives; none for another drive (a host medium, a Langevin bath).
    let (equation, amplitude, power) = match scene.physics().drive.kind() {
        DriveKind::WhiteNoise => ("MS (36)", tail::a_white_noise_36(mu2), 1.5),
        DriveKind::Gaussian | DriveKind::None => ("MS (42)", tail::a_gaussian_42(mu2), 1.0),
        DriveKind::ConstantForce => {
            let (c1, _) = settled(stats, name::C1)?;
            ("MS (52)", tail::a_constant_force_52(mu2, c1), 2.0)
        }
        _ => return None,
    };
    Some(TailLaw {
        equation,
        amplitude,
        power,
        mu2_source,
    })
}

/// The reduced distribution, when the scene asks for `[reduced_histogram]`.
pub fn reduced(scene: &Scene, stats: &RunStats) -> Option<Reduced> {
    let crate::run::ShellHistogram {
        radius: c_max,
        weights: h,
    } = stats.reduced.as_ref()?;
    let a2 = settled(stats, name::A2)?;
    let tail = tail_law(scene, stats, a2.0);
    let k = h.len() - 1;
    let d = stats.dimension;
    let shells = (0..=k)
        .map(|i| {
            let c_lo = c_max * i as f64 / k as f64;
            let c_hi = if i == k {
                f64::INFINITY
            } else {
                c_max * (i + 1) as f64 / k as f64
            };
            let vol = tail::shell_volume_in(d, c_lo, c_hi);
            let w_phi = tail::phi_shell_in(d, c_lo, c_hi);
            let f = (h.mean(i), h.ci(i));
            let bounded = vol.is_finite();
            let density = if bounded { f.0 / vol } else { 0.0 };
            let phi = if bounded { w_phi / vol } else { 0.0 };
            let ratio = (f.0 / w_phi, f.1 / w_phi);
            let mid = if bounded { 0.5 * (c_lo + c_hi) } else { c_lo };
            let (g, g_maxwell) = match tail {
                Some(t) if bounded => {
                    let e = libm::exp(t.amplitude * libm::pow(mid, t.power));
                    (e * density, e * phi)
                }
                _ => (f64::NAN, f64::NAN),
            };
            ReducedShell {
                c_lo,
                c_hi,
                f,
                density,
                phi,
                ratio,
                delta: ((ratio.0 - 1.0) / a2.0, ratio.1 / a2.0.abs()),
                s2: tail::sonine_s2_in(d, mid * mid),
                g,
                g_maxwell,
            }
        })
        .collect();
    Some(Reduced { shells, a2, tail })
}

/// One bin of the marginal distribution at the first and last observation.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct MarginalBin {
    /// Left edge.
    pub v_lo: f64,
    /// Right edge.
    pub v_hi: f64,
    /// Density (weight over width) at the first observation and its half-width.
    pub first: (f64, f64),
    /// The Maxwellian with the first observation's mean bulk velocity and temperature.
    pub first_maxwell: f64,
    /// Density at the last observation and its half-width.
    pub last: (f64, f64),
    /// The Maxwellian of the last observation.
    pub last_maxwell: f64,
}

/// The marginal distribution of one component (BRS Figure 4).
#[derive(Clone, Debug)]
pub struct Marginal {
    /// Component, 0..=2.
    pub axis: usize,
    /// Times of the two histograms.
    pub times: (f64, f64),
    /// The bins.
    pub bins: Vec<MarginalBin>,
    /// Weight outside `[-R, R)` at the first and at the last observation.
    pub outside: (f64, f64),
}

/// The marginal distribution, when the scene asks for `[marginal_histogram]`.
pub fn marginal(stats: &RunStats) -> Option<Marginal> {
    let crate::run::MarginalHistogram {
        axis,
        radius,
        first,
        last,
    } = stats.marginal.as_ref()?;
    let k = first.len() - 2;
    let width = 2.0 * radius / k as f64;
    let comp = [name::V_X, name::V_Y, name::V_Z][*axis];
    let params = |ti: usize| {
        let m = |c: &str| stats.mean(ti, stats.col(c).expect("a column"));
        (m(comp), m(name::T_BULK))
    };
    let nt = stats.times.len();
    let (u0, t0) = params(0);
    let (u1, t1) = params(nt - 1);
    let bins = (0..k)
        .map(|i| {
            let v_lo = -radius + width * i as f64;
            let v_hi = v_lo + width;
            MarginalBin {
                v_lo,
                v_hi,
                first: (first.mean(i) / width, first.ci(i) / width),
                first_maxwell: tail::normal_bin(u0, t0, v_lo, v_hi) / width,
                last: (last.mean(i) / width, last.ci(i) / width),
                last_maxwell: tail::normal_bin(u1, t1, v_lo, v_hi) / width,
            }
        })
        .collect();
    Some(Marginal {
        axis: *axis,
        times: (stats.times[0], stats.times[nt - 1]),
        bins,
        outside: (
            first.mean(k) + first.mean(k + 1),
            last.mean(k) + last.mean(k + 1),
        ),
    })
}
