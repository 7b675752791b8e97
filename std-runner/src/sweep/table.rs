//! A sweep's tables: sweep.csv (one row per point) and sweep.json (the same, with the varied
//! keys, the windows and what each reference is). Neither holds a timing, so an interrupted
//! and continued sweep writes the same bytes as an uninterrupted one.

use super::point::{PointResult, Window};
use super::vary::{Combine, Vary};
use gdsmc_theory::curves::Kind;
use serde_json::{Value, json};

/// The names of `items` of every point, in the order first met.
fn union<'a>(
    points: &'a [PointResult],
    items: impl Fn(&'a PointResult) -> Vec<&'static str>,
) -> Vec<&'static str> {
    let mut out: Vec<&'static str> = Vec::new();
    for p in points {
        for name in items(p) {
            if !out.contains(&name) {
                out.push(name);
            }
        }
    }
    out
}

/// A number as observables.csv writes it (shortest round-trip text); a missing value empty.
fn num(x: Option<f64>) -> String {
    x.map_or(String::new(), |x| format!("{x:?}"))
}

/// Every observable of the points, in the order first met.
pub fn observable_names(points: &[PointResult]) -> Vec<&'static str> {
    union(points, |p| p.observables.iter().map(|o| o.0).collect())
}

/// sweep.csv: `point`, each varied key, `seed`, `ensembles`, `window_from`, `window_points`
/// (the steady window; the end time and 1 without one), then each observable's window mean
/// and `_ci` (the half-width of its 99.9% interval), then each reference's window mean; a
/// cell is empty where a point has no such column.
pub fn csv(vary: &[Vary], points: &[PointResult]) -> Result<Vec<u8>, csv::Error> {
    let observables = observable_names(points);
    let references = union(points, |p| p.references.iter().map(|r| r.name).collect());
    let mut w = csv::Writer::from_writer(Vec::new());
    let mut header: Vec<String> = vec!["point".into()];
    header.extend(vary.iter().map(|v| v.key.clone()));
    header.extend(["seed", "ensembles", "window_from", "window_points"].map(String::from));
    for o in &observables {
        header.push(o.to_string());
        header.push(format!("{o}_ci"));
    }
    header.extend(references.iter().map(|r| r.to_string()));
    w.write_record(&header)?;
    for p in points {
        let mut rec = vec![p.index.to_string()];
        rec.extend(p.values.iter().map(|(_, v)| v.clone()));
        let (from, count) = match p.window {
            Window::Steady { from, points } => (from, points),
            Window::End { t } => (t, 1),
        };
        rec.extend([
            p.seed.to_string(),
            p.ensembles.to_string(),
            format!("{from:?}"),
            count.to_string(),
        ]);
        for o in &observables {
            let found = p.observables.iter().find(|x| x.0 == *o);
            rec.push(num(found.map(|x| x.1)));
            rec.push(num(found.map(|x| x.2)));
        }
        for r in &references {
            rec.push(num(p
                .references
                .iter()
                .find(|x| x.name == *r)
                .map(|x| x.value)));
        }
        w.write_record(&rec)?;
    }
    w.into_inner().map_err(|e| e.into_error().into())
}

/// The words sweep.json gives a reference's kind.
fn kind(k: Kind) -> &'static str {
    match k {
        Kind::MeanAtN => "exact mean at n",
        Kind::Limit => "n -> infinity limit",
        Kind::Approximation => "approximation",
    }
}

/// A JSON number, or null for a value that is not finite.
fn jnum(x: f64) -> Value {
    if x.is_finite() { json!(x) } else { Value::Null }
}

/// sweep.json: the scene, the varied keys and how they combine, each point's values, seed,
/// window, observables (mean and ci) and references (value, what it is of, kind and
/// source), and the verdict ([`super::verdict`]): per observable with an exact mean at n, the
/// points checked together, the largest deviation in widened half-widths and the points
/// outside.
pub fn json(
    scene: &str,
    vary: &[Vary],
    combine: Combine,
    complete: bool,
    points: &[PointResult],
) -> Value {
    json!({
        "scene": scene,
        "vary": vary.iter().map(|v| json!({ "key": v.key, "values": v.values })).collect::<Vec<_>>(),
        "combine": match combine { Combine::Grid => "grid", Combine::Zip => "zip" },
        "complete": complete,
        "gdsmc_version": env!("CARGO_PKG_VERSION"),
        "stream_version": gdsmc_core::rng::STREAM_VERSION,
        "verdict": super::verdict::checks(points).iter().map(|c| json!({
            "of": c.of,
            "reference": c.reference,
            "points": c.points,
            "level": "99.9% for the family of points (Bonferroni)",
            "worst": jnum(c.worst),
            "outside": c.outside,
            "inside": c.outside.is_empty(),
        })).collect::<Vec<_>>(),
        "points": points.iter().map(|p| {
            let window = match p.window {
                Window::Steady { from, points } => json!({ "steady_from": from, "points": points }),
                Window::End { t } => json!({ "end": t }),
            };
            let observables: serde_json::Map<String, Value> = p
                .observables
                .iter()
                .map(|(name, mean, ci)| (name.to_string(), json!({ "mean": jnum(*mean), "ci": jnum(*ci) })))
                .collect();
            let references: serde_json::Map<String, Value> = p
                .references
                .iter()
                .map(|r| {
                    (
                        r.name.to_string(),
                        json!({ "value": jnum(r.value), "of": r.of, "kind": kind(r.kind), "source": r.source }),
                    )
                })
                .collect();
            json!({
                "point": p.index,
                "values": p.values.iter().map(|(k, v)| (k.clone(), Value::String(v.clone()))).collect::<serde_json::Map<_, _>>(),
                "seed": p.seed,
                "ensembles": p.ensembles,
                "window": window,
                "observables": observables,
                "references": references,
            })
        }).collect::<Vec<_>>(),
    })
}

/// Decimals that show a half-width `ci` to two significant digits.
fn decimals(ci: f64) -> usize {
    if ci.is_finite() && ci > 0.0 {
        (1 - libm::log10(ci).floor() as i64).clamp(0, 12) as usize
    } else {
        6
    }
}

/// How a point's numbers are written: fixed with the decimals that show its half-width to two
/// digits, or, for a half-width below 1e-4, a mean and half-width both below 1e-3, or a mean
/// from 1e6 (a cooling gas's temperature at 1e-45), in scientific notation with the mean's mantissa to the half-width's second digit.
#[derive(Clone, Copy)]
enum Digits {
    Fixed(usize),
    Scientific(usize),
}

impl Digits {
    fn of(mean: f64, ci: f64) -> Digits {
        let small = !(ci.is_finite() && ci >= 1e-4) || mean.abs().max(ci) < 1e-3;
        if !small && mean.abs() < 1e6 {
            return Digits::Fixed(decimals(ci));
        }
        let exp = |x: f64| libm::log10(x.abs()).floor() as i64;
        let k = if ci.is_finite() && ci > 0.0 && mean != 0.0 {
            (exp(mean) - exp(ci) + 1).clamp(1, 12) as usize
        } else {
            3
        };
        Digits::Scientific(k)
    }

    fn write(self, x: f64) -> String {
        match self {
            Digits::Fixed(d) => format!("{x:.d$}"),
            Digits::Scientific(k) => format!("{x:.k$e}"),
        }
    }

    /// The half-width: to two digits.
    fn write_ci(self, ci: f64) -> String {
        match self {
            Digits::Fixed(d) => format!("{ci:.d$}"),
            Digits::Scientific(_) => format!("{ci:.1e}"),
        }
    }
}

/// sweep.md: for each observable that has a reference at some point, a table of the points:
/// the varied values, the window mean with its 99.9% half-width, every reference, and the
/// mean's difference from the first reference (in the observable's units and in half-widths)
/// with whether that reference lies within the interval (the docs' tables are these).
pub fn markdown(scene: &str, vary: &[Vary], points: &[PointResult]) -> String {
    let mut out = format!(
        "# Sweep of {scene}\n\nEach observable that has a reference: per point its window mean with the half-width of its 99.9% interval, every reference averaged over the same window, and the difference from the first reference (in its units and in half-widths of the interval).\n"
    );
    let references = union(points, |p| p.references.iter().map(|r| r.name).collect());
    for name in observable_names(points) {
        let refs: Vec<&'static str> = references
            .iter()
            .copied()
            .filter(|r| {
                points
                    .iter()
                    .any(|p| p.references.iter().any(|x| x.name == *r && x.of == name))
            })
            .collect();
        let Some(first) = refs.first() else { continue };
        out.push_str(&format!("\n## {name}\n\n|"));
        for v in vary {
            out.push_str(&format!(" {} |", v.key));
        }
        out.push_str(&format!(" {name} (99.9%) |"));
        for r in &refs {
            out.push_str(&format!(" {r} |"));
        }
        out.push_str(&format!(
            " mean - {first} | in half-widths | {first} within the interval |\n|"
        ));
        out.push_str(&"---|".repeat(vary.len() + refs.len() + 4));
        out.push('\n');
        for p in points {
            let Some(&(_, mean, ci)) = p.observables.iter().find(|o| o.0 == name) else {
                continue;
            };
            let digits = Digits::of(mean, ci);
            out.push('|');
            for (_, v) in &p.values {
                out.push_str(&format!(" {v} |"));
            }
            out.push_str(&format!(
                " {} +- {} |",
                digits.write(mean),
                digits.write_ci(ci)
            ));
            let value = |r: &str| p.references.iter().find(|x| x.name == r).map(|x| x.value);
            for r in &refs {
                match value(r) {
                    Some(x) => out.push_str(&format!(" {} |", digits.write(x))),
                    None => out.push_str(" |"),
                }
            }
            // One measure for every row: the difference in the observable's units and in
            // half-widths of the interval (a percentage says nothing against a value near 0).
            match value(first) {
                Some(x) if x.is_finite() => {
                    let inside = if (mean - x).abs() <= ci { "yes" } else { "no" };
                    let sign = if mean >= x { "+" } else { "" };
                    let widths = if ci > 0.0 {
                        format!("{:+.2}", (mean - x) / ci)
                    } else {
                        String::new()
                    };
                    out.push_str(&format!(
                        " {sign}{} | {widths} | {inside} |\n",
                        digits.write(mean - x)
                    ));
                }
                _ => out.push_str(" | | |\n"),
            }
        }
    }
    out
}
