//! A sweep's charts: each observable against the first numeric varied key, the points with
//! their 99.9% intervals (one series per combination of the other keys' values), and every
//! reference that applies drawn as a continuous curve, evaluated at 101 values across the
//! range (on a logarithmic grid for a logarithmic range), not only at the points.

use super::point::{PointResult, PointScene, references};
use super::vary::Vary;
use crate::report::charts::{Chart, Residuals, Series, Style, profile_with_residuals};
use crate::scene::{Override, Sourced};
use gdsmc_theory::curves::Kind;
use plotters::style::RGBColor;

/// Colours of the series, one per combination of the other keys (dark enough for grey scale).
const COLORS: [RGBColor; 6] = [
    RGBColor(31, 90, 180),
    RGBColor(190, 30, 30),
    RGBColor(20, 120, 50),
    RGBColor(120, 40, 160),
    RGBColor(160, 90, 0),
    RGBColor(60, 60, 60),
];

/// Values a reference curve is evaluated at across the range.
const FINE: usize = 101;

/// The values `v` takes, as numbers, when every one is a finite number.
fn numeric(v: &Vary) -> Option<Vec<f64>> {
    v.values
        .iter()
        .map(|s| s.parse::<f64>().ok().filter(|x| x.is_finite()))
        .collect()
}

/// `FINE` values from `lo` to `hi`, evenly spaced (in `log` when `log`).
fn grid(lo: f64, hi: f64, log: bool) -> Vec<f64> {
    (0..FINE)
        .map(|i| {
            let f = i as f64 / (FINE - 1) as f64;
            if log {
                libm::exp(libm::log(lo) + (libm::log(hi) - libm::log(lo)) * f)
            } else {
                lo + (hi - lo) * f
            }
        })
        .collect()
}

/// The words of a run's chart title ([`crate::report::charts::title`]: the physics, n, the
/// ensembles) that every point shares; what a point's values change is left out, and a varied
/// n or ensemble count is said to vary.
fn common_title(points: &[PointScene]) -> String {
    let titles: Vec<String> = points
        .iter()
        .map(|p| crate::report::charts::title(&p.source.scene, p.source.scene.ensembles()))
        .collect();
    let parts: Vec<&str> = titles[0].split(", ").collect();
    let mut kept: Vec<String> = parts
        .iter()
        .filter(|part| titles.iter().all(|t| t.split(", ").any(|q| q == **part)))
        .map(|part| part.to_string())
        .collect();
    // The particles (the first words) are named even when the points differ in them.
    if kept.first().map(String::as_str) != Some(parts[0]) {
        let mut kinds: Vec<&str> = Vec::new();
        for t in &titles {
            let k = t.split(", ").next().unwrap_or_default();
            if !kinds.contains(&k) {
                kinds.push(k);
            }
        }
        kept.insert(0, either(&kinds));
    }
    if !kept.iter().any(|p| p.starts_with("n = ")) {
        kept.push("n varied".into());
    }
    match kept.iter_mut().find(|p| p.ends_with(" ensembles")) {
        Some(m) => m.push_str(" per point"),
        None => kept.push("ensembles varied".into()),
    }
    kept.join(", ")
}

/// The particles of points that differ in them, the words they share said once: "Smooth
/// spheres or disks", not "Smooth spheres or Smooth disks".
fn either(kinds: &[&str]) -> String {
    let words: Vec<Vec<&str>> = kinds.iter().map(|k| k.split(' ').collect()).collect();
    let shared = (0..words[0].len())
        .take_while(|&i| words.iter().all(|w| w.len() > i + 1 && w[i] == words[0][i]))
        .count();
    let rests: Vec<String> = words.iter().map(|w| w[shared..].join(" ")).collect();
    let head = words[0][..shared].join(" ");
    if head.is_empty() {
        rests.join(" or ")
    } else {
        format!("{head} {}", rests.join(" or "))
    }
}

/// The shift of group `gi` of `groups` along x, so that points of several groups at the same x
/// stand side by side (their error bars not hidden behind one another): `x` moved by a small
/// fraction of the range (a factor on a log axis).
fn dodge(x: f64, gi: usize, groups: usize, (lo, hi): (f64, f64), log: bool) -> f64 {
    let k = gi as f64 - (groups as f64 - 1.0) / 2.0;
    if groups < 2 {
        x
    } else if log {
        x * libm::pow(hi / lo, 0.006 * k)
    } else {
        x + 0.006 * k * (hi - lo)
    }
}

/// Every chart of the sweep, `(file stem, chart)`: none when no varied key is numeric.
pub fn charts(
    base: &Sourced,
    vary: &[Vary],
    points: &[PointScene],
    results: &[PointResult],
) -> Vec<(String, Result<Chart, String>)> {
    let Some((xi, xs)) = vary
        .iter()
        .enumerate()
        .find_map(|(i, v)| numeric(v).map(|x| (i, x)))
    else {
        return Vec::new();
    };
    let xkey = &vary[xi].key;
    let (lo, hi) = xs
        .iter()
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), &x| {
            (a.min(x), b.max(x))
        });
    let log = vary[xi].log && lo > 0.0;
    // The series: each combination of the other keys' values, in the order first met.
    let others = |values: &[(String, String)]| -> Vec<(String, String)> {
        values
            .iter()
            .enumerate()
            .filter(|(i, _)| *i != xi)
            .map(|(_, kv)| kv.clone())
            .collect()
    };
    let mut groups: Vec<Vec<(String, String)>> = Vec::new();
    for p in points {
        let g = others(&p.values);
        if !groups.contains(&g) {
            groups.push(g);
        }
    }
    // Each group's references across the range: (x, every reference's window average).
    let fine: Vec<Vec<(f64, Vec<super::point::ReferenceValue>)>> = groups
        .iter()
        .map(|g| {
            grid(lo, hi, log)
                .into_iter()
                .filter_map(|x| {
                    let mut s = base.clone();
                    for (k, v) in g.iter().cloned().chain([(xkey.clone(), format!("{x:?}"))]) {
                        s = s.with(Override::set(format!("{k}={v}"))).ok()?;
                    }
                    Some((x, references(&s.scene)))
                })
                .collect()
        })
        .collect();
    let common = common_title(points);
    let x_label = super::words::key_label(xkey, &base.scene);
    // An observable some points lack (the power-law exponent where no window is resolved)
    // is drawn where at least two points have it.
    let names = super::table::observable_names(results);
    let drawn = |name: &&'static str| {
        let has = |r: &&PointResult| {
            r.observables
                .iter()
                .any(|o| o.0 == *name && o.1.is_finite())
        };
        results.iter().filter(has).count() >= 2
    };
    names
        .into_iter()
        .filter(drawn)
        .map(|name| {
            let mut series = Vec::new();
            let mut residuals = Vec::new();
            let mut residual_of = None;
            let mut cited_refs: Vec<&'static str> = Vec::new();
            for (gi, g) in groups.iter().enumerate() {
                let color = COLORS[gi % COLORS.len()];
                let suffix = if g.is_empty() {
                    String::new()
                } else {
                    let words: Vec<String> = g.iter().map(|(k, v)| format!("{k} = {v}")).collect();
                    format!(", {}", words.join(", "))
                };
                let pts: Vec<(f64, f64, f64)> = results
                    .iter()
                    .filter(|r| others(&r.values) == *g)
                    .filter_map(|r| {
                        let x = r.values[xi].1.parse::<f64>().ok()?;
                        let o = r.observables.iter().find(|o| o.0 == name)?;
                        Some((dodge(x, gi, groups.len(), (lo, hi), log), o.1, o.2))
                    })
                    .collect();
                // The exact mean at this n, where one applies, judges each point: its residual
                // (mean - exact) / half-width, inside the interval within +-1.
                let exact: Vec<(f64, f64, &'static str)> = results
                    .iter()
                    .filter(|r| others(&r.values) == *g)
                    .filter_map(|r| {
                        let x = r.values[xi].1.parse::<f64>().ok()?;
                        let o = r.observables.iter().find(|o| o.0 == name)?;
                        let e = r
                            .references
                            .iter()
                            .find(|e| e.of == name && e.kind == Kind::MeanAtN)?;
                        let x = dodge(x, gi, groups.len(), (lo, hi), log);
                        (o.2 > 0.0).then(|| (x, (o.1 - e.value) / o.2, e.name))
                    })
                    .collect();
                if let Some(&(_, _, rname)) = exact.first() {
                    residual_of = Some(rname);
                    residuals.push(Residuals {
                        label: format!(
                            "residual (lower panel): (mean - {rname}) / 99.9% half-width{suffix}"
                        ),
                        points: exact.iter().map(|e| (e.0, e.1)).collect(),
                        color,
                    });
                }
                series.push(Series {
                    label: format!("mean and 99.9% interval{suffix}"),
                    points: pts,
                    style: Style::Points,
                    color,
                });
                let mut refs: Vec<(&'static str, &'static str)> = Vec::new();
                for (_, rs) in &fine[gi] {
                    for r in rs.iter().filter(|r| r.of == name) {
                        if !refs.iter().any(|x| x.0 == r.name) {
                            refs.push((r.name, r.source));
                        }
                    }
                }
                for (rname, source) in refs {
                    let line: Vec<(f64, f64, f64)> = fine[gi]
                        .iter()
                        .filter_map(|(x, rs)| {
                            rs.iter()
                                .find(|r| r.name == rname)
                                .map(|r| (*x, r.value, 0.0))
                        })
                        .collect();
                    // The source once, with the first group's curve of it.
                    let cited = !cited_refs.contains(&rname);
                    cited_refs.push(rname);
                    series.push(Series {
                        label: if cited {
                            format!("{rname} ({source}){suffix}")
                        } else {
                            format!("{rname}{suffix}")
                        },
                        points: line,
                        style: Style::Dashed,
                        color,
                    });
                }
            }
            // The axes name the observable and the key; the title is the physics.
            let title = common.clone();
            let y = crate::run::columns::axis_label(name);
            // The legend says what the residual is; the panel is too short for the words.
            let residual_desc = residual_of
                .map(|_| "residual".to_string())
                .unwrap_or_default();
            (
                name.to_string(),
                profile_with_residuals(
                    &title,
                    &x_label,
                    &y,
                    (log, false),
                    &series,
                    &residuals,
                    &residual_desc,
                ),
            )
        })
        .collect()
}
