//! The adaptive Dormand-Prince 5(4) integrator the reference curves are solved with (the BRS
//! closures of [`super::hydro`], the rough-particle approximation of [`super::rough`]).
//!
//! The method is Dormand and Prince's embedded Runge-Kutta pair (J. R. Dormand, P. J. Prince,
//! "A family of embedded Runge-Kutta formulae", J. Comput. Appl. Math. 6 (1980) 19-26): a
//! fifth-order step, a fourth-order estimate of its error, and the error-per-step control,
//! starting step and fourth-order dense output of Hairer, Norsett and Wanner, "Solving Ordinary
//! Differential Equations I" (2nd ed., Springer 1993), II.4 (eq. 4.12, the starting step) and
//! II.6 (Table 6.2 and the coefficients of `DOPRI5`'s `CONTD5`). Written here because what the
//! references need (fixed-size states, an equally spaced output grid) is a hundred lines, and
//! the crates that offer it bring a linear-algebra stack (nalgebra, simba, a second `wide`).

/// Nodes `c_i` of the Dormand-Prince tableau (Hairer et al. II, Table 5.2).
const C: [f64; 7] = [0.0, 1.0 / 5.0, 3.0 / 10.0, 4.0 / 5.0, 8.0 / 9.0, 1.0, 1.0];

/// Rows `a_ij` of the Dormand-Prince tableau; the last row is also the fifth-order weights `b`.
const A: [[f64; 6]; 7] = [
    [0.0; 6],
    [1.0 / 5.0, 0.0, 0.0, 0.0, 0.0, 0.0],
    [3.0 / 40.0, 9.0 / 40.0, 0.0, 0.0, 0.0, 0.0],
    [44.0 / 45.0, -56.0 / 15.0, 32.0 / 9.0, 0.0, 0.0, 0.0],
    [
        19372.0 / 6561.0,
        -25360.0 / 2187.0,
        64448.0 / 6561.0,
        -212.0 / 729.0,
        0.0,
        0.0,
    ],
    [
        9017.0 / 3168.0,
        -355.0 / 33.0,
        46732.0 / 5247.0,
        49.0 / 176.0,
        -5103.0 / 18656.0,
        0.0,
    ],
    [
        35.0 / 384.0,
        0.0,
        500.0 / 1113.0,
        125.0 / 192.0,
        -2187.0 / 6784.0,
        11.0 / 84.0,
    ],
];

/// The error weights `b_i - b^_i` (fifth minus fourth order) of the seven stages.
const E: [f64; 7] = [
    71.0 / 57600.0,
    0.0,
    -71.0 / 16695.0,
    71.0 / 1920.0,
    -17253.0 / 339200.0,
    22.0 / 525.0,
    -1.0 / 40.0,
];

/// The dense-output weights `d_i` of `DOPRI5` (Hairer et al., the code's `CONTD5`).
const D: [f64; 7] = [
    -12715105075.0 / 11282082432.0,
    0.0,
    87487479700.0 / 32700410799.0,
    -10690763975.0 / 1880347072.0,
    701980252875.0 / 199316789632.0,
    -1453857185.0 / 822651844.0,
    69997945.0 / 29380423.0,
];

/// How many steps (accepted or rejected) an integration may take before it is called stiff or
/// singular and refused.
pub const MAX_STEPS: usize = 1_000_000;

/// The relative and absolute tolerance of every reference curve (per step, per component).
pub const TOLERANCES: (f64, f64) = (1e-10, 1e-12);

/// Why an integration stopped.
#[derive(Clone, Debug, PartialEq)]
pub enum OdeError {
    /// The right side or the state became NaN or infinite at `x`.
    NonFinite {
        /// Where.
        x: f64,
    },
    /// The step fell below the resolution of `x` (a singularity near `x`).
    StepTooSmall {
        /// Where.
        x: f64,
    },
    /// More than [`MAX_STEPS`] steps (stiff, or a far end).
    TooManySteps {
        /// Where it stopped.
        x: f64,
    },
}

impl std::fmt::Display for OdeError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            OdeError::NonFinite { x } => write!(f, "the solution is not finite at {x}"),
            OdeError::StepTooSmall { x } => write!(f, "the step size vanished at {x}"),
            OdeError::TooManySteps { x } => {
                write!(f, "more than {MAX_STEPS} steps, stopped at {x}")
            }
        }
    }
}

impl std::error::Error for OdeError {}

/// The weighted RMS norm of Hairer et al. II (4.11): `sqrt(mean((v_i / sk_i)^2))` with
/// `sk_i = atol + rtol max(|a_i|, |b_i|)`.
fn norm<const N: usize>(v: &[f64; N], a: &[f64; N], b: &[f64; N], tol: (f64, f64)) -> f64 {
    let sum: f64 = (0..N)
        .map(|i| {
            let sk = tol.1 + tol.0 * a[i].abs().max(b[i].abs());
            (v[i] / sk).powi(2)
        })
        .sum();
    (sum / N as f64).sqrt()
}

/// Solves `y' = f(x, y)`, `y(x0) = y0` on `[x0, x_end]` (`x_end > x0`) with the per-step
/// tolerances `tol = (rtol, atol)`, returning the solution at the `outputs + 1` equally spaced
/// points `x0 + k (x_end - x0) / outputs`, `k = 0..=outputs` (between steps by the dense
/// output, which is of fourth order; the last point is the last step's).
pub fn solve<const N: usize>(
    f: impl Fn(f64, &[f64; N]) -> [f64; N],
    x0: f64,
    x_end: f64,
    y0: [f64; N],
    tol: (f64, f64),
    outputs: usize,
) -> Result<Vec<(f64, [f64; N])>, OdeError> {
    let outputs = outputs.max(1);
    let span = x_end - x0;
    let grid = |k: usize| {
        if k == outputs {
            x_end
        } else {
            x0 + span * k as f64 / outputs as f64
        }
    };
    let finite = |y: &[f64; N]| y.iter().all(|v| v.is_finite());
    let mut out = Vec::with_capacity(outputs + 1);
    out.push((x0, y0));
    let (mut x, mut y) = (x0, y0);
    let mut k1 = f(x, &y);
    if !finite(&k1) || !finite(&y) {
        return Err(OdeError::NonFinite { x });
    }
    let mut h = initial_step(&f, x, &y, &k1, span, tol);
    let mut next = 1;
    let mut steps = 0;
    while next <= outputs {
        steps += 1;
        if steps > MAX_STEPS {
            return Err(OdeError::TooManySteps { x });
        }
        let last = x + h >= x_end;
        if last {
            h = x_end - x;
        }
        if h <= f64::EPSILON * x.abs().max(1.0) * 4.0 && !last {
            return Err(OdeError::StepTooSmall { x });
        }
        let mut k = [[0.0; N]; 7];
        k[0] = k1;
        let stage = |s: usize, k: &[[f64; N]; 7]| -> [f64; N] {
            std::array::from_fn(|i| y[i] + h * (0..s).map(|j| A[s][j] * k[j][i]).sum::<f64>())
        };
        for s in 1..6 {
            k[s] = f(x + C[s] * h, &stage(s, &k));
        }
        // The seventh stage is evaluated at the fifth-order solution (first same as last).
        let y1 = stage(6, &k);
        k[6] = f(x + h, &y1);
        let err_v: [f64; N] =
            std::array::from_fn(|i| h * (0..7).map(|j| E[j] * k[j][i]).sum::<f64>());
        let err = norm(&err_v, &y, &y1, tol);
        if !err.is_finite() || !finite(&y1) {
            // Retry with a much smaller step before calling it a singularity.
            h *= 0.1;
            if h <= f64::EPSILON * x.abs().max(1.0) {
                return Err(OdeError::NonFinite { x });
            }
            continue;
        }
        let factor = (0.9 * libm::pow(err, -0.2)).clamp(0.2, 10.0);
        if err > 1.0 {
            h *= factor.min(1.0);
            continue;
        }
        // Accepted: the dense output between x and x + h (Hairer et al., CONTD5).
        let x1 = if last { x_end } else { x + h };
        let ydiff: [f64; N] = std::array::from_fn(|i| y1[i] - y[i]);
        let bspl: [f64; N] = std::array::from_fn(|i| h * k[0][i] - ydiff[i]);
        let r4: [f64; N] = std::array::from_fn(|i| ydiff[i] - h * k[6][i] - bspl[i]);
        let r5: [f64; N] = std::array::from_fn(|i| h * (0..7).map(|j| D[j] * k[j][i]).sum::<f64>());
        while next <= outputs && grid(next) <= x1 {
            let xo = grid(next);
            let yo = if next == outputs && last {
                y1
            } else {
                let th = (xo - x) / h;
                let th1 = 1.0 - th;
                std::array::from_fn(|i| {
                    y[i] + th * (ydiff[i] + th1 * (bspl[i] + th * (r4[i] + th1 * r5[i])))
                })
            };
            out.push((xo, yo));
            next += 1;
        }
        x = x1;
        y = y1;
        k1 = k[6];
        h *= factor;
    }
    Ok(out)
}

/// The starting step of Hairer et al. II (4.12), at most the whole span.
fn initial_step<const N: usize>(
    f: &impl Fn(f64, &[f64; N]) -> [f64; N],
    x: f64,
    y: &[f64; N],
    f0: &[f64; N],
    span: f64,
    tol: (f64, f64),
) -> f64 {
    let d0 = norm(y, y, y, tol);
    let d1 = norm(f0, y, y, tol);
    let h0 = if d0 < 1e-5 || d1 < 1e-5 {
        1e-6 * span
    } else {
        0.01 * d0 / d1
    };
    let h0 = h0.min(span);
    let y1: [f64; N] = std::array::from_fn(|i| y[i] + h0 * f0[i]);
    let f1 = f(x + h0, &y1);
    let df: [f64; N] = std::array::from_fn(|i| f1[i] - f0[i]);
    let d2 = norm(&df, y, y, tol) / h0;
    let m = d1.max(d2);
    let h1 = if m.is_finite() && m > 1e-15 {
        libm::pow(0.01 / m, 0.2)
    } else {
        (h0 * 1e-3).max(1e-6 * span)
    };
    (100.0 * h0).min(h1).min(span)
}

#[cfg(test)]
mod tests {
    use super::*;

    const TOL: (f64, f64) = TOLERANCES;

    #[test]
    fn decay_is_exact_to_the_tolerance_on_the_grid() {
        let p = solve(|_, y: &[f64; 1]| [-y[0]], 0.0, 10.0, [1.0], TOL, 100).unwrap();
        assert_eq!(p.len(), 101);
        for (k, (x, y)) in p.iter().enumerate() {
            assert_eq!(
                *x,
                if k == 100 {
                    10.0
                } else {
                    10.0 * k as f64 / 100.0
                }
            );
            let exact = libm::exp(-x);
            // Global error: a few hundred steps of local error 1e-10 relative.
            assert!(
                (y[0] - exact).abs() <= 1e-8 * exact + 1e-11,
                "{x}: {}",
                y[0]
            );
        }
    }

    #[test]
    fn haff_cooling_over_decades() {
        // T' = -T^{3/2}: T = 1 / (1 + t/2)^2, eight decades of T, with a purely relative
        // tolerance (atol = 0): each step's relative error stays below rtol = 1e-10, so the
        // global one below the sum over the steps (a few hundred here); 1000 steps' worth.
        let p = solve(
            |_, y: &[f64; 1]| [-libm::pow(y[0], 1.5)],
            0.0,
            2e4,
            [1.0],
            (1e-10, 0.0),
            400,
        )
        .unwrap();
        for (x, y) in p {
            let exact = (1.0 + x / 2.0).powi(-2);
            assert!(
                (y[0] / exact - 1.0).abs() < 1e-7,
                "{x}: {} vs {exact}",
                y[0]
            );
        }
    }

    #[test]
    fn oscillator_dense_output_is_fourth_order_accurate() {
        // y'' = -y over ten periods with output points far denser than the steps: the dense
        // output between steps keeps the tolerance's accuracy, not the linear interpolant's.
        let tau = std::f64::consts::TAU;
        let p = solve(
            |_, y: &[f64; 2]| [y[1], -y[0]],
            0.0,
            10.0 * tau,
            [0.0, 1.0],
            TOL,
            20_000,
        )
        .unwrap();
        let worst = p
            .iter()
            .map(|(x, y)| {
                (y[0] - libm::sin(*x))
                    .abs()
                    .max((y[1] - libm::cos(*x)).abs())
            })
            .fold(0.0, f64::max);
        assert!(worst < 1e-8, "worst {worst}");
        // And a loose tolerance is looser: the test could fail.
        let q = solve(
            |_, y: &[f64; 2]| [y[1], -y[0]],
            0.0,
            10.0 * tau,
            [0.0, 1.0],
            (1e-4, 1e-6),
            20_000,
        )
        .unwrap();
        let worst_loose = q
            .iter()
            .map(|(x, y)| (y[0] - libm::sin(*x)).abs())
            .fold(0.0, f64::max);
        assert!(worst_loose > 100.0 * worst, "{worst_loose} vs {worst}");
    }

    #[test]
    fn blow_up_is_an_error_not_a_value() {
        // y' = y^2, y(0) = 1: y = 1/(1 - x), singular at x = 1.
        let e = solve(|_, y: &[f64; 1]| [y[0] * y[0]], 0.0, 2.0, [1.0], TOL, 10).unwrap_err();
        match e {
            OdeError::StepTooSmall { x }
            | OdeError::NonFinite { x }
            | OdeError::TooManySteps { x } => {
                assert!((x - 1.0).abs() < 1e-3, "stopped at {x}")
            }
        }
    }
}
