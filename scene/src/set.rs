//! The scene's setters: each validated as the file's key it stands for (`--n`, `--set`, a
//! sweep's point), so a changed scene is as valid as a read one.

use crate::{Error, Physics, Scene, Shells, validate};
use std::path::PathBuf;

impl Scene {
    /// Sets the number of ensembles, validated as `run.ensembles` is (at least 1).
    pub fn set_ensembles(&mut self, m: u64) -> Result<(), Error> {
        let as_file = i64::try_from(m).unwrap_or(i64::MAX);
        if let Some(why) = validate::observe::ensembles_problem(as_file) {
            return Err(self.invalid("run.ensembles", why));
        }
        self.ensembles = m;
        Ok(())
    }

    /// Sets the seed (any value).
    pub fn set_seed(&mut self, seed: u64) {
        self.seed = seed;
    }

    /// Sets the start time of the steady-state average (`None`: no average), validated as
    /// `observe.steady_from` is: the window begins at the first observation time at or after
    /// it and must hold at least two.
    pub fn set_steady_from(&mut self, from: Option<f64>) -> Result<(), Error> {
        self.steady_from = match from {
            None => None,
            Some(x) => Some(
                validate::observe::steady_index(&self.times, x)
                    .map_err(|why| self.invalid("observe.steady_from", why))?,
            ),
        };
        Ok(())
    }

    /// Sets the random pairs per observation for the collisional cooling (0: off), as the
    /// file's `observe.collisional_pairs` does (every physics has them).
    pub fn set_collisional_pairs(&mut self, pairs: u64) -> Result<(), Error> {
        self.collisional_pairs = pairs;
        Ok(())
    }

    /// Sets the radial-shell histogram (`None`: none), validated as `[histogram]` is.
    pub fn set_histogram(&mut self, h: Option<Shells>) -> Result<(), Error> {
        if let Some(h) = h {
            let shells = i64::try_from(h.shells).unwrap_or(i64::MAX);
            if let Some(why) = validate::observe::count_problem(shells) {
                return Err(self.invalid("histogram.shells", why));
            }
            if let Some(why) = validate::observe::positive_problem(h.radius) {
                return Err(self.invalid("histogram.radius", why));
            }
        }
        self.histogram = h;
        Ok(())
    }

    /// Removes the marginal histogram (a scene without one is always valid).
    pub fn clear_marginal_histogram(&mut self) {
        self.marginal_histogram = None;
    }

    /// The `Debug` text of the scene with its seed and ensemble count cleared: what makes two
    /// runs' ensembles the same process (a journal's fingerprint).
    #[must_use]
    pub fn fingerprint(&self) -> String {
        let mut s = self.clone();
        s.seed = 0;
        s.ensembles = 0;
        format!("{s:?}")
    }

    /// Changes the physics through `f` and validates the result as a scene file's would be:
    /// the core's one validation, then the scene's rules that depend on the physics (every
    /// observation time on a splitting scheme's grid, what collisional pairs and disks allow).
    /// On error the scene is unchanged; the error names the key.
    pub fn with_physics(&mut self, f: impl FnOnce(&mut Physics)) -> Result<(), Error> {
        let mut physics = self.physics.clone();
        f(&mut physics);
        let model = physics.validate().map_err(|e| {
            let key = self.keys.iter().find(|(p, _)| *p == e.param);
            let key = key.map_or_else(|| e.param.to_string(), |(_, k)| k.clone());
            self.invalid(&key, e.problem.to_string())
        })?;
        self.rules(&physics, &self.times)?;
        self.physics = physics;
        self.model = model;
        Ok(())
    }

    /// An error of a change made in code (no line), at `key`.
    fn invalid(&self, key: &str, message: String) -> Error {
        Error::Invalid {
            path: PathBuf::from(format!("scene {}", self.name)),
            line: 0,
            key: key.to_string(),
            message,
        }
    }

    /// The scene's rules that depend on the physics ([`validate::physics_rules`]) for
    /// `physics` observed at `times`.
    fn rules(&self, physics: &Physics, times: &[f64]) -> Result<(), Error> {
        let histograms = (
            self.reduced_histogram.is_some(),
            self.marginal_histogram.is_some(),
        );
        match validate::physics_rules(physics, times, histograms) {
            Some((key, message)) => Err(self.invalid(key, message)),
            None => Ok(()),
        }
    }

    /// Sets the observation times (finite, from 0 on, increasing), validated against the
    /// physics as [`Scene::with_physics`] does (a splitting scheme's grid). The steady-state
    /// window keeps its start time (`steady_from` becomes the first new time at or after it),
    /// or is dropped (`None`) when fewer than two new times lie in it. Set the times
    /// first when both change. On error the scene is unchanged.
    pub fn set_times(&mut self, times: Vec<f64>) -> Result<(), Error> {
        let ordered = times.windows(2).all(|w| w[0] < w[1]);
        if times.is_empty() || !ordered || !times.iter().all(|t| t.is_finite() && *t >= 0.0) {
            return Err(self.invalid(
                "observe.times",
                "must be finite, from 0 on and increasing".to_string(),
            ));
        }
        self.rules(&self.physics, &times)?;
        if let Some(why) = (self.snapshots.iter())
            .find_map(|&x| validate::observe::snapshot_index(&times, x).err())
        {
            return Err(self.invalid("observe.snapshots", why));
        }
        // The steady window starts at the same time: its first new observation at or after
        // the old start (an index into the old times means nothing in the new ones). Times that
        // leave it fewer than two observations have no steady window.
        let steady_from = self.steady_from.and_then(|k| {
            let start = self.times.get(k).copied().unwrap_or(f64::INFINITY);
            let first = times.iter().position(|&t| t >= start)?;
            (first + 2 <= times.len()).then_some(first)
        });
        self.times = times;
        self.steady_from = steady_from;
        Ok(())
    }

    /// Sets the particle count, and a mixture's species counts from their fractions as the
    /// file's `particles.n` does (`validate::species::counts`), validated as
    /// [`Scene::with_physics`] does (a species left without a particle is refused).
    pub fn set_n(&mut self, n: usize) -> Result<(), Error> {
        let fractions = self.species_fractions.clone();
        self.with_physics(|ph| {
            ph.n = n;
            if !fractions.is_empty() {
                let counts = validate::species::counts(&fractions, n);
                for (s, c) in ph.species.iter_mut().zip(counts) {
                    s.count = c;
                }
            }
        })
    }
}
