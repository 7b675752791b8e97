//! The short text summary `gdsmc run` prints.

use super::verdict::num;
use crate::run::RunStats;
use crate::run::columns::name;
use crate::scene::Scene;
use gdsmc_theory::curves::ReferenceCurve;
use std::fmt::Write;

/// The summary: scene, sizes, timing, counts, and a table of T, T_bulk, a2 and crit at up to
/// nine observation times, with the references beside them.
pub fn text(scene: &Scene, stats: &RunStats, refs: &[ReferenceCurve]) -> String {
    let mut s = String::new();
    let c = stats.counts;
    let _ = writeln!(s, "scene      {}", scene.name());
    if !scene.description().is_empty() {
        let _ = writeln!(s, "           {}", scene.description());
    }
    let _ = writeln!(
        s,
        "run        n = {}, ensembles = {}, seed = {} (streams v{}), threads = {}, wall = {:.2} s, cpu = {:.2} s",
        scene.n(),
        stats.ensembles,
        scene.seed(),
        gdsmc_core::rng::STREAM_VERSION,
        stats.threads,
        stats.wall.as_secs_f64(),
        stats.cpu.as_secs_f64()
    );
    let _ = writeln!(
        s,
        "events     {} collisions, {} fictitious, {} majorant overshoots, {} restitution clamped to [0, 1] ({:.3e} collisions/s)",
        c.collisions,
        c.fictitious,
        c.overshoots,
        c.clamped,
        c.collisions as f64 / stats.wall.as_secs_f64().max(1e-9)
    );
    let _ = writeln!(s, "{}", units(scene, stats));
    for d in scene.derived() {
        let _ = writeln!(s, "derived    {d}");
    }
    if c.background > 0 {
        let _ = writeln!(
            s,
            "background {} grain-background collisions (host medium, BRS (26)), {:.1} per grain-grain collision",
            c.background,
            c.background as f64 / c.collisions.max(1) as f64
        );
    }
    if scene.is_disks() {
        let _ = writeln!(
            s,
            "particles  disks (d = 2): velocities in a plane, T per degree of freedom = <|c|^2>/2, a2 = <c^4>/(8 T^2) - 1"
        );
    }
    let momentum = scene.physics().momentum;
    if momentum == gdsmc_core::physics::Momentum::Exact {
        let _ = writeln!(
            s,
            "start      {} (particles.momentum = \"{}\")",
            momentum.words(),
            momentum.scene_name()
        );
    }
    let mixture = !scene.physics().species.is_empty();
    // The granular temperature is the one about the flow (`T_bulk`): it leads. The raw `T`
    // (about zero velocity) of a drawn start keeps the sample's centre-of-mass energy, frozen
    // while a cooling gas's `T_bulk` falls by decades (6.3e-4 against 1e-10 in hcs-hard-spheres
    // before it started with exact momentum): it is shown only where a reference is of it, a
    // paper's estimator defined on it (GRW's).
    let raw_judged = refs.iter().any(|r| r.of == name::T);
    let mut shown = vec![name::T_BULK, name::A2, name::CRIT];
    if raw_judged {
        shown.insert(1, name::T);
    }
    if mixture {
        let cols = crate::run::columns::SPECIES_COLUMNS;
        let _ = write!(s, "species   ");
        for (k, sp) in scene.physics().species.iter().enumerate() {
            let _ = write!(
                s,
                " s{k} = {} ({} particles, mass {}){}",
                scene.species_names()[k],
                sp.count,
                sp.mass,
                if k + 1 < scene.physics().species.len() {
                    ","
                } else {
                    "\n"
                }
            );
        }
        shown = vec![crate::run::columns::MIXTURE_TEMPERATURE];
        shown.extend(cols[..scene.physics().species.len()].iter().map(|c| c[0]));
        shown.push(cols[0][1]);
    }
    if let Some(r) = scene.physics().rotation {
        if mixture {
            let _ = writeln!(
                s,
                "rotation   rough mixture: tangential restitution beta = {} unless a pair names its own; T_sk is species k's translational temperature, T_rot_sk its rotational one, theta_sk their ratio",
                r.beta
            );
            let species = scene.physics().species.len();
            let rough = crate::run::columns::ROUGH_SPECIES_COLUMNS;
            shown = vec![
                crate::run::columns::MIXTURE_TEMPERATURE,
                crate::run::columns::ROUGH_MIXTURE_TEMPERATURE,
            ];
            shown.extend(rough[..species].iter().map(|c| c[1]));
            shown.push(crate::run::columns::SPECIES_COLUMNS[0][1]);
        } else {
            let _ = writeln!(
                s,
                "rotation   rough particles: tangential restitution beta = {}, kappa = {}; T_bulk is the translational temperature",
                r.beta, r.kappa
            );
            shown = vec![
                name::T_BULK,
                name::T_ROT,
                name::THETA,
                name::A2,
                name::A2_ROT,
            ];
        }
    }
    let _ = write!(s, "\n{:>8}", "t");
    for &name in &shown {
        let _ = write!(s, " {:>24}", format!("{name} +- 99.9% CI"));
        for r in refs.iter().filter(|r| r.of == name) {
            let _ = write!(s, " {:>13}", r.name);
        }
    }
    let _ = writeln!(s);
    let nt = stats.times.len();
    let step = nt.div_ceil(9).max(1);
    let mut rows: Vec<usize> = (0..nt).step_by(step).collect();
    if *rows.last().unwrap() != nt - 1 {
        rows.push(nt - 1);
    }
    for ti in rows {
        let _ = write!(s, "{:>8.4}", stats.times[ti]);
        for &name in &shown {
            let col = stats.col(name).unwrap();
            let _ = write!(
                s,
                " {:>13} +- {:<8.2e}",
                num(stats.mean(ti, col)),
                stats.ci(ti, col)
            );
            for r in refs.iter().filter(|r| r.of == name) {
                let _ = write!(s, " {:>13}", num((r.curve)(stats.times[ti])));
            }
        }
        let _ = writeln!(s);
    }
    if let Some(crate::run::ShellHistogram { radius, weights: h }) = &stats.histogram {
        match crate::analysis::tails::fit(*radius, h, stats.dimension) {
            Some(f) => {
                let _ = writeln!(
                    s,
                    "\ntail (GRW Section 4.3, k0 = 1, {} shells): exponent {:.3} +- {:.3}; {} (the interval is the fit's; whether the shells reach the asymptote is checked below)",
                    f.points.len(),
                    f.slope,
                    f.slope_ci,
                    match crate::analysis::tails::reference_exponent(scene) {
                        Some(e) =>
                            format!("GRW (16), the asymptote of the heated gas: 1 + lambda/2 = {e}"),
                        None => "GRW (16) is of a power-law kernel, which this one is not".into(),
                    }
                );
            }
            None => {
                let _ = writeln!(s, "\ntail: too few resolved shells for a fit");
            }
        }
    }
    if let Some(r) = crate::analysis::distribution::reduced(scene, stats) {
        let _ = writeln!(
            s,
            "\nreduced distribution (MS), c = |v - V| / v0, a2 = {:.5} +- {:.1e}:",
            r.a2.0, r.a2.1
        );
        if let Some(t) = &r.tail {
            let _ = writeln!(
                s,
                "  tail law {}: f(c) ~ K exp(-A c^{}), A = {:.4} (mu2 from {})",
                t.equation, t.power, t.amplitude, t.mu2_source
            );
        }
        let _ = writeln!(
            s,
            "  {:>6} {:>22} {:>22} {:>9} {:>11}",
            "c", "f/phi", "Delta (MS (45))", "S2(c^2)", "G(c)"
        );
        let k = r.shells.len() - 1;
        let c_max = r.shells[k].c_lo;
        for target in [0.25, 0.5, 1.0, 1.5, 2.0, 3.0, 4.0, 5.0] {
            if target >= c_max {
                break;
            }
            let i = ((target / c_max * k as f64) as usize).min(k - 1);
            let sh = &r.shells[i];
            let mid = 0.5 * (sh.c_lo + sh.c_hi);
            let _ = writeln!(
                s,
                "  {:>6.3} {:>11.4} +- {:<8.1e} {:>11.4} +- {:<8.1e} {:>9.4} {:>11.4}",
                mid, sh.ratio.0, sh.ratio.1, sh.delta.0, sh.delta.1, sh.s2, sh.g
            );
        }
    }
    if let Some(t) = crate::analysis::power_tail::measure(scene, stats) {
        let _ = writeln!(s, "  {}", t.words());
    }
    if let Some(m) = crate::analysis::distribution::marginal(stats) {
        let _ = writeln!(
            s,
            "\nmarginal distribution of v_{} (BRS Figure 4) at t = {} and t = {}: marginal.csv, marginal.svg",
            m.axis + 1,
            m.times.0,
            m.times.1
        );
    }
    if let Some(b) = gdsmc_theory::thermostat::GaussianBalance::of(scene) {
        let _ = writeln!(s, "\ndrive: {}", b.describe());
    }
    if let Some(note) = crate::analysis::warnings::no_intervals(stats) {
        let _ = writeln!(s, "\nnote: {note}");
    }
    let warnings = crate::analysis::warnings::check(scene, stats);
    if !warnings.is_empty() {
        let _ = writeln!(
            s,
            "\nWARNINGS (the diagnostics say these numbers need care):"
        );
        for w in &warnings {
            let _ = writeln!(s, "  [{}] {}", w.code, w.message);
        }
    }
    if let Some(st) = &stats.steady {
        let _ = writeln!(
            s,
            "\nsteady state: averages over the {} observation times t >= {} (RW Section 4.2)",
            st.points, stats.times[st.first]
        );
        // A freely cooling gas's temperatures (and cooling rates, which scale with them) keep
        // falling: a window mean of them is no state; only the scale-free quantities settle.
        let cooling = scene.physics().cools_freely();
        let mut names = vec![
            name::T_BULK,
            name::T,
            name::A2,
            name::A3,
            name::CRIT,
            name::MU2,
            name::MU4,
        ];
        if mixture {
            names = vec![crate::run::columns::MIXTURE_TEMPERATURE];
            for c in &crate::run::columns::SPECIES_COLUMNS[..scene.physics().species.len()] {
                names.extend([c[1], c[2]]);
            }
            names.extend(&crate::run::columns::COOLING_COLUMNS[..=scene.physics().species.len()]);
        }
        if let (Some(_), true) = (scene.physics().rotation, mixture) {
            // The rough mixture's ratios beside the species' (its temperatures are above).
            for c in &crate::run::columns::ROUGH_SPECIES_COLUMNS[..scene.physics().species.len()] {
                names.extend([c[1], c[2]]);
            }
        } else if scene.physics().rotation.is_some() {
            names = if !cooling {
                vec![
                    name::T_BULK,
                    name::T_ROT,
                    name::THETA,
                    name::T_TOTAL,
                    name::A2,
                    name::A2_ROT,
                    name::CW2,
                ]
            } else {
                vec![name::THETA, name::A2, name::A2_ROT, name::CW2]
            };
        }
        if cooling {
            let scaled = [
                name::T,
                name::T_BULK,
                crate::run::columns::MIXTURE_TEMPERATURE,
            ];
            names.retain(|n| !scaled.contains(n) && !n.starts_with("zeta_"));
        }
        let names: Vec<&str> = names
            .into_iter()
            .filter(|n| stats.col(n).is_some() && (*n != name::T || raw_judged))
            .collect();
        let width = names.iter().map(|n| n.len()).max().unwrap_or(0).max(8);
        let window = &stats.times[st.first..];
        for name in names {
            let Some(col) = stats.col(name) else { continue };
            let (m, ci) = st.steady_mean_ci(stats, col);
            let _ = write!(s, "  {name:<width$} {:>13} +- {ci:.2e}", num(m));
            // References beside it: their mean over the same observation times (what the
            // window mean estimates, whether or not the reference has settled).
            for r in refs.iter().filter(|r| r.of == name) {
                let mean = window.iter().map(|&t| (r.curve)(t)).sum::<f64>() / window.len() as f64;
                let _ = write!(s, "   {} {}", r.name, num(mean));
            }
            let _ = writeln!(s);
        }
    }
    super::verdict::verdict(&mut s, stats, refs);
    s
}

/// The summary's line on units: the scene's, and the gas's own at the first observation (the
/// thermal speed and, for one species, the Maxwellian collision rate and mean free time,
/// `gdsmc_theory::balance::collision_rate`), and the collisions per particle by the last.
fn units(scene: &Scene, stats: &RunStats) -> String {
    use crate::run::columns::name;
    let at = |c: &str, i: usize| stats.col(c).map(|k| stats.mean(i, k));
    let last = stats.times.len() - 1;
    let mut line =
        "units      scene units (particle mass 1; the kernel's gamma and C set time)".to_string();
    if let Some(t) = at(name::T_BULK, 0).filter(|t| *t > 0.0) {
        line.push_str(&format!(
            "; at t = {}: thermal speed sqrt(2 T) = {:.4}",
            stats.times[0],
            (2.0 * t).sqrt()
        ));
        // The Maxwellian collision rate of a power-law kernel.
        if let (true, Some((gc, lambda))) = (
            scene.physics().species.is_empty(),
            scene.physics().kernel.power_law(),
        ) {
            let omega = gdsmc_theory::balance::collision_rate(scene.dimension(), gc, lambda, t);
            line.push_str(&format!(
                ", collision rate {omega:.4} per particle (Maxwellian), mean free time {:.4}",
                1.0 / omega
            ));
        }
    }
    if let Some(s) = at(name::S, last) {
        line.push_str(&format!(
            "; {s:.2} collisions per particle by t = {}",
            stats.times[last]
        ));
    }
    line
}
