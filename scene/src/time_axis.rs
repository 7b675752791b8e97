//! What a run's time charts draw against: the scene's time or collisions per particle.

/// What a run's time charts draw against (`observe.time_axis`).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum TimeAxis {
    /// The scene's time `t`.
    #[default]
    Time,
    /// Collisions per particle `s = 2 (collisions so far) / n`, the usual axis of
    /// cooling-state studies (the `s` column).
    Collisions,
}
