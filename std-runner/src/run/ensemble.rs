//! One ensemble: a particle system drawn from the scene's initial distribution, its engine
//! started through the core's one dispatch ([`Model::launch`]), observed at every observation
//! time; the histograms a scene asks for ride at the end of its row.

use crate::run::columns::COLUMNS;
use crate::run::cooling::CoolingRates;
use crate::scene::Scene;
use gdsmc_core::collisional::collisional_moments;
use gdsmc_core::engine::{Counts, EngineError, EventLoop, Frame};
use gdsmc_core::histogram::{component_bins, radial_shells_mapped};
use gdsmc_core::moments::Observables;
use gdsmc_core::particles::{Particle, Particles, Spin};
use gdsmc_core::physics::Model;
use gdsmc_core::rng::Xoshiro256PlusPlus;
use gdsmc_core::vec3::Vec3;

use super::state::{StateReader, StateWriter, continued};

/// Why an ensemble stopped: the engine's error and the observation time it was advancing to.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct EnsembleError {
    /// The observation time (0 while starting).
    pub t: f64,
    /// What the engine reported.
    pub error: EngineError,
}

impl std::fmt::Display for EnsembleError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(f, "on the way to t = {}: {}", self.t, self.error)
    }
}

/// Room for the `n` particles of one system, asked of the allocator fallibly: a count that
/// passed the limits but not the machine is an error naming `particles.n`, never an abort.
/// One buffer serves every ensemble a worker runs (each ensemble overwrites it whole).
pub fn particle_buffer(n: usize) -> Result<Vec<Particle>, crate::Error> {
    let mut buf = Vec::new();
    buf.try_reserve_exact(n)
        .map_err(|_| crate::Error::OutOfMemory {
            what: format!("`particles.n` = {n} particles"),
            bytes: n.saturating_mul(std::mem::size_of::<Particle>()),
        })?;
    // Before the first write, so that the kernel can back it with huge pages from the start.
    crate::run::pages::advise_huge(buf.spare_capacity_mut());
    buf.resize(n, Particle::default());
    Ok(buf)
}

/// Room for the spins of a rough gas's `n` particles (empty for smooth particles), asked of
/// the allocator fallibly as [`particle_buffer`] does.
pub fn spin_buffer(model: &Model) -> Result<Vec<Spin>, crate::Error> {
    let n = if model.rotates() { model.n() } else { 0 };
    let mut buf = Vec::new();
    buf.try_reserve_exact(n)
        .map_err(|_| crate::Error::OutOfMemory {
            what: format!("the spins of `particles.n` = {n} rough particles"),
            bytes: n.saturating_mul(std::mem::size_of::<Spin>()),
        })?;
    crate::run::pages::advise_huge(buf.spare_capacity_mut());
    buf.resize(n, Spin::default());
    Ok(buf)
}

/// One worker's memory for a system: the particles (for the weighted scheme, with room for
/// what its collisions create), for a rough gas their spins, for the weighted scheme their
/// weights (empty otherwise).
pub type SystemBuffer = (Vec<Particle>, Vec<Spin>, Vec<f64>);

/// The [`SystemBuffer`] of `model`'s systems ([`Model::capacity`] particles).
pub fn system_buffer(model: &Model) -> Result<SystemBuffer, crate::Error> {
    let weights = if model.weighted() {
        let n = model.capacity();
        let mut w = Vec::new();
        w.try_reserve_exact(n)
            .map_err(|_| crate::Error::OutOfMemory {
                what: format!("the weights of {n} weighted particles (`scheme.capacity`)"),
                bytes: n.saturating_mul(8),
            })?;
        w.resize(n, 1.0);
        w
    } else {
        Vec::new()
    };
    Ok((
        particle_buffer(model.capacity())?,
        spin_buffer(model)?,
        weights,
    ))
}

/// The state files of a run: the one it starts from and the one it saves, when asked.
#[derive(Clone, Copy, Default)]
pub struct StateIo<'a> {
    /// Each ensemble starts from this state's record at its time (`--initial-state`).
    pub initial: Option<&'a StateReader>,
    /// Each ensemble's particles at the last observation go here (`--save-state`).
    pub save: Option<&'a StateWriter>,
    /// Each ensemble's particles at the scene's snapshot observations ([`Scene::snapshots`],
    /// one writer each, in order) go here; empty: none taken.
    pub snapshots: &'a [StateWriter],
}

/// [`run_ensemble`] on `particles`, made by [`system_buffer`] at its first use and kept
/// between the ensembles of one worker (a thread, or a stepped run).
pub fn run_on_buffer(
    scene: &Scene,
    model: &Model,
    rng: Xoshiro256PlusPlus,
    particles: &mut Option<SystemBuffer>,
    at: (u64, &StateIo<'_>),
) -> Result<(Vec<f64>, Counts), crate::Error> {
    let buf = match particles {
        Some(buf) => buf,
        None => particles.insert(system_buffer(model)?),
    };
    run_ensemble(scene, model, rng, buf, at)
}

/// Runs ensemble `k` of `scene` (whose physics `model` is) from the generator `rng` in the
/// buffers `buf` (from [`system_buffer`]; their contents are overwritten), from the scene's
/// initial distribution or the state `io.initial`, saving its last particles to `io.save`:
/// the observables at every observation time, row-major (`times x COLUMNS`), and the event
/// counts.
pub fn run_ensemble(
    scene: &Scene,
    model: &Model,
    mut rng: Xoshiro256PlusPlus,
    buf: &mut SystemBuffer,
    (k, io): (u64, &StateIo<'_>),
) -> Result<(Vec<f64>, Counts), crate::Error> {
    let ensemble = |t0: f64| {
        move |error| crate::Error::Engine {
            ensemble: k,
            message: EnsembleError { t: t0, error }.to_string(),
        }
    };
    let (particles, spins, weights) = buf;
    let mut p = if !weights.is_empty() {
        // Every ensemble starts with n particles of weight 1 (Model::initialize sets them).
        weights.fill(1.0);
        Particles::weighted(particles, weights, model.n())
    } else if spins.is_empty() {
        Particles::new(particles)
    } else {
        Particles::with_spins(particles, spins)
    }
    .map_err(|_| ensemble(0.0)(EngineError::ParticleCount))?;
    // From the scene's initial distribution at t = 0, or from a saved state at its time (its
    // collisions per particle counted on).
    let (t0, s0, (engine, obs0)) = match io.initial {
        None => (
            0.0,
            0.0,
            model.launch(&mut p, 0.0, &mut rng).map_err(ensemble(0.0))?,
        ),
        Some(state) => {
            let t0 = state.header.time;
            let s0 = state.get(k, &mut p)?;
            rng = continued(rng, state.header.segment);
            (t0, s0, model.start(&mut p, t0).map_err(ensemble(t0))?)
        }
    };
    observe(scene, engine, (t0, s0, obs0), &mut p, &mut rng, (k, io))
}

fn observe<E: EventLoop>(
    scene: &Scene,
    mut engine: E,
    (t0, s0, obs0): (f64, f64, Observables),
    p: &mut Particles<'_>,
    rng: &mut Xoshiro256PlusPlus,
    (k, io): (u64, &StateIo<'_>),
) -> Result<(Vec<f64>, Counts), crate::Error> {
    let mut out = Vec::with_capacity(scene.times().len() * (COLUMNS.len() + 3) + 1);
    // Diagnostics draw from their own stream, so they never change the trajectory.
    let mut diag = rng.clone();
    diag.long_jump();
    let nt = scene.times().len();
    let mut reduced = vec![0.0; scene.reduced_histogram().map_or(0, |h| h.weights())];
    let mut reduced_points = 0u32;
    let reduced_from = scene.steady_from().unwrap_or(nt - 1);
    let marginal_len = scene.marginal_histogram().map_or(0, |h| h.weights());
    let (mut marginal_first, mut marginal_last) =
        (vec![0.0; marginal_len], vec![0.0; marginal_len]);
    let coll = crate::run::collisional::collisional(scene);
    let cooling = coll
        .mixture_rates
        .then(|| CoolingRates::new(scene))
        .flatten();
    let mut last_s = s0;
    let snapshots: Vec<(usize, &StateWriter)> =
        scene.snapshots().into_iter().zip(io.snapshots).collect();
    for (ti, &t) in scene.times().iter().enumerate() {
        let obs = if t == t0 {
            obs0
        } else {
            engine
                .advance_to(p, t, rng)
                .map_err(|error| crate::Error::Engine {
                    ensemble: k,
                    message: EnsembleError { t, error }.to_string(),
                })?
        };
        // Bulk velocity and temperature in the stored units, once per observation, for the
        // diagnostics reduced by v0 (exact for a gas stored rescaled, whose physical
        // temperature may have underflowed).
        let wants_reduced = scene.reduced_histogram().is_some() && ti >= reduced_from;
        let stored = (wants_reduced || scene.collisional_pairs() > 0)
            .then(|| stored_bulk_temperature(p, scene.dimension()));
        if let (Some(shells), true, Some((bulk, t_bulk))) =
            (scene.reduced_histogram(), wants_reduced, stored)
        {
            // c = (v - V) / v0.
            let inv = 1.0 / (2.0 * t_bulk).sqrt();
            radial_shells_mapped(
                p,
                shells.radius,
                Frame {
                    scale: inv,
                    offset: -inv * bulk,
                },
                &mut reduced,
            );
            reduced_points += 1;
        }
        if let Some(m) = scene.marginal_histogram() {
            let frame = engine.velocity_map();
            if ti == 0 {
                component_bins(p, m.axis, m.radius, frame, &mut marginal_first);
            }
            if ti == nt - 1 {
                component_bins(p, m.axis, m.radius, frame, &mut marginal_last);
            }
        }
        out.extend(COLUMNS.iter().map(|c| (c.get)(&obs)));
        let s = s0 + engine.collisions_per_particle(scene.n());
        out.push(s);
        last_s = s;
        if let Some((_, w)) = snapshots.iter().find(|(i, _)| *i == ti) {
            w.put(k, p, engine.velocity_map(), s)?;
        }
        if let (true, Some((bulk, t_bulk)), Some(alpha)) =
            (coll.moments, stored, scene.physics().restitution.constant())
        {
            // mu2, mu4 are reduced by v0, so the stored units do.
            let (mu2, mu4) =
                collisional_moments(p, bulk, t_bulk, alpha, scene.collisional_pairs(), &mut diag);
            out.extend([mu2, mu4]);
        }
        if let Some(r) = engine.rough(p) {
            out.extend(crate::run::columns::rough_values(
                &r,
                scene.physics().dimension,
            ));
        }
        if let Some(m) = engine.species(p) {
            out.extend(crate::run::columns::mixture_values(&m));
            if let Some(c) = &cooling {
                out.extend(cooling_rates(
                    c,
                    scene,
                    p,
                    engine.velocity_map().scale,
                    &mut diag,
                ));
            }
        }
        // Last: the draws above keep their bits.
        if coll.cooling {
            let c = engine.cooling(p, scene.collisional_pairs(), &mut diag);
            out.extend([c.frequency, c.zeta(), c.zeta_star]);
            if coll.nu0 {
                let nu0 = gdsmc_theory::balance::nu0_hard(
                    scene.dimension(),
                    scene.physics().kernel.strength(),
                    obs.t_bulk,
                );
                out.push(c.zeta() / nu0);
            }
        }
    }
    // The state at the last observation, for a continuation.
    if let Some(w) = io.save {
        w.put(k, p, engine.velocity_map(), last_s)?;
    }
    // The histogram of the last observation rides at the end of the row (split off in the job).
    if let Some(shells) = scene.histogram() {
        let mut h = vec![0.0; shells.weights()];
        radial_shells_mapped(p, shells.radius, engine.velocity_map(), &mut h);
        out.extend(h);
    }
    if reduced_points > 0 {
        out.extend(reduced.iter().map(|x| x / reduced_points as f64));
    }
    out.extend(marginal_first);
    out.extend(marginal_last);
    Ok((out, engine.counts()))
}

/// A mixture's cooling rates (`zeta_mix`, then one per species) from `scene.collisional_pairs`
/// random pairs per species pair: `-(dT/dt)/T` in stored units times `scale^lambda` (a rate
/// scales with the relative speed's power of the kernel).
fn cooling_rates(
    c: &CoolingRates,
    scene: &Scene,
    p: &Particles<'_>,
    scale: f64,
    rng: &mut Xoshiro256PlusPlus,
) -> Vec<f64> {
    let unit = libm::pow(scale, c.lambda());
    let rates = c.rates(p, scene.collisional_pairs(), rng);
    let n: usize = scene.physics().species.iter().map(|s| s.count).sum();
    let (mut t, mut dt) = (0.0, 0.0);
    for (s, &(ts, dts)) in rates.iter().enumerate() {
        let x = scene.physics().species[s].count as f64 / n as f64;
        t += x * ts;
        dt += x * dts;
    }
    let mut v = vec![-dt / t * unit];
    v.extend(rates.iter().map(|&(ts, dts)| -dts / ts * unit));
    v
}

/// Bulk velocity and temperature (about it, `d` degrees of freedom: disks' velocities have no
/// third component) of the velocities as stored (weighted particles: weighted means).
fn stored_bulk_temperature(p: &Particles<'_>, d: usize) -> (Vec3, f64) {
    let n = p.mass();
    let mut v = Vec3::ZERO;
    for (i, q) in p.as_slice().iter().enumerate() {
        v += p.weight(i) * q.velocity();
    }
    let bulk = (1.0 / n) * v;
    let mut s = 0.0;
    for (i, q) in p.as_slice().iter().enumerate() {
        s += p.weight(i) * (q.velocity() - bulk).norm2();
    }
    (bulk, s / (d as f64 * n))
}
