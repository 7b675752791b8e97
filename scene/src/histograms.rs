//! The histograms a scene asks for, validated: speeds in equal shells ([`Shells`]) and one
//! velocity component in equal bins ([`Marginal`]).

/// A histogram of a speed in equal shells: `shells` shells on [0, `radius`) and one beyond
/// (the keys `shells` and `radius` of `[histogram]` and `[reduced_histogram]`).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Shells {
    /// Shells inside the radius (K).
    pub shells: usize,
    /// Their outer radius (R; `c_max` for the reduced speed).
    pub radius: f64,
}

impl Shells {
    /// Weights the histogram holds: the K shells and the one beyond.
    #[must_use]
    pub fn weights(&self) -> usize {
        self.shells + 1
    }
}

/// A histogram of one velocity component (`[marginal_histogram]`): `bins` equal bins on
/// [-`radius`, `radius`) and one beyond each end.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Marginal {
    /// The component, 0..=2 (the file's 1..=3).
    pub axis: usize,
    /// Bins inside [-R, R).
    pub bins: usize,
    /// R.
    pub radius: f64,
}

impl Marginal {
    /// Weights one observation's histogram holds: the bins and one beyond each end.
    #[must_use]
    pub fn weights(&self) -> usize {
        self.bins + 2
    }
}
