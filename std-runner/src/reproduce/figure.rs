//! How the reproduced tables print a figure.

/// A figure for the tables: four decimals in [0.01, 1e4), scientific notation otherwise.
pub fn fmt(x: f64) -> String {
    if x == 0.0 {
        "0".into()
    } else if x.abs() >= 1e-2 && x.abs() < 1e4 {
        format!("{x:.4}")
    } else {
        format!("{x:.3e}")
    }
}
