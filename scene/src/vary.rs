//! What a sweep varies: `KEY=VALUES` (a list `0.5,0.7,0.9`, a linear range `0.3:0.9:7` or a
//! logarithmic one `log:0.01:1:5`), and the points several of them make (a grid, or zipped):
//! the one syntax of `gdsmc sweep --vary` and of a scene file's `[sweep]` table. Errors are the
//! rule's words; the caller names where the text came from (the flag, or the file's line).

/// One varied key and its values, each as the text of a scene value (TOML, or a bare word).
#[derive(Clone, Debug, PartialEq)]
pub struct Vary {
    /// The scene key, e.g. `collisions.restitution`.
    pub key: String,
    /// Its values in order.
    pub values: Vec<String>,
    /// Whether the values were given as a logarithmic range (the charts then draw the
    /// references on a logarithmic grid).
    pub log: bool,
}

/// Most points a sweep may have (a typo in a range's count should not start a week of runs;
/// the work estimate then bounds what the points cost).
pub const MAX_POINTS: usize = 10_000;

/// Significant digits a range's values are rounded to, so that `0.3:0.9:7` gives `0.4`, not
/// `0.39999999999999997`.
const RANGE_DIGITS: usize = 12;

fn bad(spec: &str, message: String) -> String {
    format!("{spec}: {message}")
}

/// A range's value `x` rounded to [`RANGE_DIGITS`] significant digits, as scene text: an
/// integer without a decimal point (so that integer keys such as `particles.n` take it), any
/// other number as Rust prints it shortest.
fn range_value(x: f64) -> String {
    let rounded: f64 = format!("{x:.*e}", RANGE_DIGITS - 1)
        .parse()
        .expect("a formatted float parses");
    if rounded.fract() == 0.0 && rounded.abs() < 1e15 {
        format!("{}", rounded as i64)
    } else {
        format!("{rounded:?}")
    }
}

/// A range's number (`start`, `stop`): finite.
fn number(spec: &str, what: &str, text: &str) -> Result<f64, String> {
    match text.trim().parse::<f64>() {
        Ok(x) if x.is_finite() => Ok(x),
        _ => Err(bad(
            spec,
            format!("the range's {what} must be a finite number, got {text:?}"),
        )),
    }
}

/// A range's values as scene text ([`range_value`]), each a finite number, else the refusal
/// (a value would overflow, or be rounded out of the range of f64).
fn finite(spec: &str, xs: impl Iterator<Item = f64>) -> Result<Vec<String>, String> {
    xs.map(|x| {
        let v = range_value(x);
        match v.parse::<f64>() {
            Ok(y) if y.is_finite() && x.is_finite() => Ok(v),
            _ => Err(bad(
                spec,
                format!(
                    "the range gives a value beyond the largest number ({x:e}); choose ends of \
                     smaller magnitude"
                ),
            )),
        }
    })
    .collect()
}

/// A range's count: an integer >= 2 and at most [`MAX_POINTS`].
fn count(spec: &str, text: &str) -> Result<usize, String> {
    match text.trim().parse::<usize>() {
        Ok(k) if (2..=MAX_POINTS).contains(&k) => Ok(k),
        _ => Err(bad(
            spec,
            format!("the range's count must be an integer from 2 to {MAX_POINTS}, got {text:?}"),
        )),
    }
}

impl Vary {
    /// Parses `KEY=VALUES`: `KEY=a,b,c` (each a scene value: a number, a TOML value, a bare
    /// word), `KEY=start:stop:count` (`count` values evenly spaced from `start` to `stop`,
    /// both included) or `KEY=log:start:stop:count` (evenly spaced in `log`, `start` and
    /// `stop` > 0). Range values are rounded to 12 significant digits.
    pub fn parse(spec: &str) -> Result<Self, String> {
        let Some((key, values)) = spec.split_once('=') else {
            return Err(bad(
                spec,
                "must be KEY=VALUES, e.g. collisions.restitution=0.5,0.7,0.9".into(),
            ));
        };
        let key = key.trim();
        if key.is_empty() || key.contains(char::is_whitespace) {
            return Err(bad(
                spec,
                format!("the key must be a scene key such as collisions.restitution, got {key:?}"),
            ));
        }
        let values = values.trim();
        let parts: Vec<&str> = values.split(':').collect();
        let values: Vec<String> = match parts.as_slice() {
            ["log", start, stop, k] => {
                let (a, b, k) = (
                    number(spec, "start", start)?,
                    number(spec, "stop", stop)?,
                    count(spec, k)?,
                );
                if a <= 0.0 || b <= 0.0 {
                    return Err(bad(
                        spec,
                        "a logarithmic range needs start > 0 and stop > 0".into(),
                    ));
                }
                let (la, lb) = (libm::log(a), libm::log(b));
                finite(
                    spec,
                    (0..k).map(|i| match i {
                        0 => a,
                        _ if i == k - 1 => b,
                        _ => libm::exp(la + (lb - la) * i as f64 / (k - 1) as f64),
                    }),
                )?
            }
            [start, stop, k] => {
                let (a, b, k) = (
                    number(spec, "start", start)?,
                    number(spec, "stop", stop)?,
                    count(spec, k)?,
                );
                // Halves first: `b - a` overflows for ends near the largest number.
                finite(
                    spec,
                    (0..k).map(|i| {
                        let f = i as f64 / (k - 1) as f64;
                        2.0 * (a / 2.0 + (b / 2.0 - a / 2.0) * f)
                    }),
                )?
            }
            [_] => values.split(',').map(|v| v.trim().to_string()).collect(),
            _ => {
                return Err(bad(
                    spec,
                    "VALUES must be a list (a,b,c), a range (start:stop:count) or a logarithmic range (log:start:stop:count)".into(),
                ));
            }
        };
        if values.iter().any(String::is_empty) {
            return Err(bad(spec, "a value is empty".into()));
        }
        if values.len() > MAX_POINTS {
            return Err(bad(
                spec,
                format!("has {} values, more than {MAX_POINTS}", values.len()),
            ));
        }
        Ok(Vary {
            key: key.to_string(),
            values,
            log: parts.first() == Some(&"log"),
        })
    }
}

/// How several varied keys make points.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Combine {
    /// Every combination (the first key varies slowest).
    Grid,
    /// The k-th value of every key together (the lists must be of one length).
    Zip,
}

/// What a sweep varies and how its keys combine (a scene file's `[sweep]`, or the command's
/// `--vary` and `--zip`).
#[derive(Clone, Debug, PartialEq)]
pub struct Plan {
    /// The varied keys.
    pub vary: Vec<Vary>,
    /// How several keys make points.
    pub combine: Combine,
}

/// One point of a sweep: a value for each varied key, in the order of the keys.
pub type Point = Vec<(String, String)>;

/// The points of `vary` combined by `how`. Refuses no key, a key given twice, zipped lists of
/// different lengths and more than [`MAX_POINTS`] points.
pub fn points(vary: &[Vary], how: Combine) -> Result<Vec<Point>, String> {
    if vary.is_empty() {
        return Err("needs at least one KEY=VALUES".into());
    }
    for (i, a) in vary.iter().enumerate() {
        if vary[..i].iter().any(|b| b.key == a.key) {
            return Err(format!("varies {} twice: give each key once", a.key));
        }
    }
    match how {
        Combine::Zip => {
            let len = vary[0].values.len();
            if let Some(v) = vary.iter().find(|v| v.values.len() != len) {
                return Err(format!(
                    "zips lists of different lengths: {} has {} values, {} has {}; zipped lists must be of one length",
                    vary[0].key,
                    len,
                    v.key,
                    v.values.len()
                ));
            }
            Ok((0..len)
                .map(|k| {
                    vary.iter()
                        .map(|v| (v.key.clone(), v.values[k].clone()))
                        .collect()
                })
                .collect())
        }
        Combine::Grid => {
            let total = vary
                .iter()
                .try_fold(1usize, |acc, v| acc.checked_mul(v.values.len()))
                .filter(|&t| t <= MAX_POINTS)
                .ok_or_else(|| format!("makes a grid of more than {MAX_POINTS} points"))?;
            Ok((0..total)
                .map(|mut k| {
                    // The last key varies fastest.
                    let mut point = vec![(String::new(), String::new()); vary.len()];
                    for (slot, v) in point.iter_mut().zip(vary).rev() {
                        let i = k % v.values.len();
                        k /= v.values.len();
                        *slot = (v.key.clone(), v.values[i].clone());
                    }
                    point
                })
                .collect())
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn values(spec: &str) -> Vec<String> {
        Vary::parse(spec).unwrap().values
    }

    #[test]
    fn lists_and_ranges_give_the_values_asked_for() {
        assert_eq!(values("a.b=0.5, 0.7,0.9"), ["0.5", "0.7", "0.9"]);
        assert_eq!(values("collisions.kernel=maxwell,vhs"), ["maxwell", "vhs"]);
        assert_eq!(
            values("a.b=0.3:0.9:7"),
            ["0.3", "0.4", "0.5", "0.6", "0.7", "0.8", "0.9"]
        );
        assert_eq!(values("a.b=log:0.01:1:3"), ["0.01", "0.1", "1"]);
        assert_eq!(values("particles.n=1000:3000:3"), ["1000", "2000", "3000"]);
        assert_eq!(values("a.b=0:1:3"), ["0", "0.5", "1"]);
    }

    #[test]
    fn bad_specs_are_refused_with_the_rule() {
        for (spec, words) in [
            ("a.b", "must be KEY=VALUES"),
            ("=1,2", "the key must be"),
            ("a.b=0:1:1", "count must be an integer from 2"),
            ("a.b=0:1:x", "count must be an integer from 2"),
            ("a.b=0:nan:3", "stop must be a finite number"),
            ("a.b=log:0:1:3", "start > 0"),
            ("a.b=1:2", "VALUES must be a list"),
            ("a.b=1,,2", "a value is empty"),
        ] {
            let e = Vary::parse(spec).unwrap_err();
            assert!(e.contains(words) && e.starts_with(spec), "{spec}: {e}");
        }
    }

    #[test]
    fn a_grid_varies_the_last_key_fastest_and_zip_pairs() {
        let v = [
            Vary::parse("a=1,2").unwrap(),
            Vary::parse("b=x,y,z").unwrap(),
        ];
        let g = points(&v, Combine::Grid).unwrap();
        let text: Vec<String> = g
            .iter()
            .map(|p| {
                p.iter()
                    .map(|(_, v)| v.as_str())
                    .collect::<Vec<_>>()
                    .join("")
            })
            .collect();
        assert_eq!(text, ["1x", "1y", "1z", "2x", "2y", "2z"]);
        assert!(
            points(&v, Combine::Zip)
                .unwrap_err()
                .to_string()
                .contains("one length")
        );
        let w = [Vary::parse("a=1,2").unwrap(), Vary::parse("b=x,y").unwrap()];
        assert_eq!(
            points(&w, Combine::Zip).unwrap()[1],
            [("a".into(), "2".into()), ("b".into(), "y".into())]
        );
        let twice = [Vary::parse("a=1").unwrap(), Vary::parse("a=2").unwrap()];
        assert!(
            points(&twice, Combine::Grid)
                .unwrap_err()
                .to_string()
                .contains("twice")
        );
        assert!(points(&[], Combine::Grid).is_err());
    }
}
