//! Users' tracks files: YAML (`frames:` lists of `[x, y]`, optional `points:` names) or CSV
//! (header `frame,point,x,y`). Every error names the file, the line and the field.

use std::collections::{HashMap, HashSet};
use std::fmt::Write as _;
use std::io::Read as _;
use std::path::Path;

use nalgebra::Vector2;
use serde::Deserialize;

use crate::cases::{line_of, parse_yaml_limited};
use crate::error::{Error, InputLocation, Result};
use crate::model::{default_names, Tracks};
use crate::numfmt::round_trip;

mod gaps;
pub use gaps::{load_observations, parse_observations};

/// How frames are matched point by point.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum PointOrder {
    /// The same points in every frame: CSV rows are matched by point name.
    ByName,
    /// Each frame's points as listed (frame 2's order may be unknown, as for `identify`);
    /// names are taken from the first frame.
    AsListed,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct YamlTracks {
    #[serde(default)]
    points: Option<Vec<String>>,
    frames: Vec<Vec<[f64; 2]>>,
}

fn located(path: &Path, line: Option<u64>, field: &str, message: String) -> Error {
    Error::Input {
        location: InputLocation {
            file: path.to_path_buf(),
            line,
            column: None,
            field: Some(field.to_string()),
        },
        message,
    }
}

pub use crate::limits::INPUT_BYTES as MAX_TRACKS_BYTES;

/// Read a tracks file; the extension (`.csv`, otherwise YAML) picks the format.
///
/// # Example
/// ```
/// use orthocheck::input::{parse_tracks, PointOrder};
/// let t = parse_tracks("frame,point,x,y\n1,P,0,0\n1,Q,1,0\n2,Q,0,1\n2,P,0,0\n",
///     std::path::Path::new("t.csv"), PointOrder::ByName).unwrap();
/// assert_eq!(t.names, ["P", "Q"]);
/// assert_eq!(t.frames[1][1].y, 1.0);
/// ```
pub fn load_tracks(path: &Path, order: PointOrder) -> Result<Tracks> {
    parse_tracks(&read_text(path)?, path, order)
}

/// A tracks file's text, read through the size limit (never more than the limit plus one
/// byte is read, so `/dev/zero` is refused, not exhausted).
pub(crate) fn read_text(path: &Path) -> Result<String> {
    let io = |source| Error::Io {
        path: path.to_path_buf(),
        source,
    };
    let file = std::fs::File::open(path).map_err(io)?;
    let mut bytes = Vec::new();
    file.take(MAX_TRACKS_BYTES + 1)
        .read_to_end(&mut bytes)
        .map_err(io)?;
    if bytes.len() as u64 > MAX_TRACKS_BYTES {
        return Err(located(
            path,
            None,
            "file",
            format!("larger than the limit of {MAX_TRACKS_BYTES} bytes"),
        ));
    }
    String::from_utf8(bytes).map_err(|_| located(path, None, "file", "not UTF-8 text".into()))
}

/// The names a CSV tracks file gives each frame's points, frame by frame in the order the
/// rows list them (what [`PointOrder::AsListed`] keeps of them is frame 1's); `None` for a
/// YAML file, whose `points:` name frame 1's points only.
///
/// # Example
/// ```
/// let dir = tempfile::tempdir().unwrap();
/// let path = dir.path().join("t.csv");
/// std::fs::write(&path, "frame,point,x,y\n1,P,0,0\n1,Q,1,0\n2,B,0,1\n2,A,1,1\n").unwrap();
/// let names = orthocheck::input::listed_names(&path).unwrap().unwrap();
/// assert_eq!(names, [["P", "Q"], ["B", "A"]]);
/// ```
pub fn listed_names(path: &Path) -> Result<Option<Vec<Vec<String>>>> {
    let raw = read_text(path)?;
    let (text, is_csv) = text_and_format(&raw, path)?;
    if !is_csv {
        return Ok(None);
    }
    let (_, _, rows) = csv_table(text, path)?;
    Ok(Some(
        rows.iter()
            .map(|r| r.iter().map(|(n, _, _)| n.clone()).collect())
            .collect(),
    ))
}

/// The text without a byte-order mark (no data, in either format) and whether the file is
/// CSV (by its extension; YAML otherwise); an empty file is an error.
pub(crate) fn text_and_format<'t>(text: &'t str, path: &Path) -> Result<(&'t str, bool)> {
    let text = text.strip_prefix('\u{feff}').unwrap_or(text);
    if text.trim().is_empty() {
        return Err(located(path, Some(1), "frames", "the file is empty".into()));
    }
    let is_csv = path
        .extension()
        .is_some_and(|e| e.eq_ignore_ascii_case("csv"));
    Ok((text, is_csv))
}

/// Parse tracks text; `path` names the file in errors and its extension picks the format.
pub fn parse_tracks(text: &str, path: &Path, order: PointOrder) -> Result<Tracks> {
    let (text, is_csv) = text_and_format(text, path)?;
    if is_csv {
        parse_csv(text, path, order)
    } else {
        parse_yaml_tracks(text, path)
    }
}

fn parse_yaml_tracks(text: &str, path: &Path) -> Result<Tracks> {
    let data = text
        .lines()
        .any(|l| !l.trim().is_empty() && !l.trim_start().starts_with('#'));
    if !data {
        return Err(located(
            path,
            Some(1),
            "frames",
            "the file has no data".into(),
        ));
    }
    // a point is three YAML values (its pair and two numbers): the byte limit bounds the rest
    let y: YamlTracks = parse_yaml_limited(text, path, MAX_TRACKS_BYTES as usize / 4)?;
    // serde has checked the shapes; what is left is found by its field path
    let bad = |field: String, message: String| {
        let line = line_of(text, &field).or_else(|| line_of(text, "frames"));
        Err(located(path, line, &field, message))
    };
    if y.frames.is_empty() {
        return bad("frames".into(), "no frames".into());
    }
    let p = y.frames[0].len();
    let names = match y.points {
        Some(n) => {
            if n.len() != p {
                return bad(
                    "points".into(),
                    format!("{} names for {p} points per frame", n.len()),
                );
            }
            if let Some(message) = name_problem(&n) {
                return bad("points".into(), message);
            }
            n
        }
        None => default_names(p),
    };
    let mut frames = Vec::with_capacity(y.frames.len());
    for (i, f) in y.frames.iter().enumerate() {
        if f.len() != p {
            return bad(
                format!("frames[{i}]"),
                format!("{} points, but frame 1 has {p}", f.len()),
            );
        }
        for (j, xy) in f.iter().enumerate() {
            if let Some(c) = xy.iter().position(|v| !v.is_finite()) {
                return bad(
                    format!("frames[{i}][{j}][{c}]"),
                    "coordinate is not a finite number".into(),
                );
            }
        }
        frames.push(f.iter().map(|xy| Vector2::new(xy[0], xy[1])).collect());
    }
    Tracks::new(names, frames)
        .map_err(|e| located(path, line_of(text, "frames"), "frames", e.to_string()))
}

/// What is wrong with a list of point names, if anything: an empty name, or one used twice.
fn name_problem(names: &[String]) -> Option<String> {
    if names.is_empty() {
        return Some("no points are named".into());
    }
    let mut seen = HashSet::new();
    for n in names {
        if n.trim().is_empty() {
            return Some("empty point name".into());
        }
        if !seen.insert(n.as_str()) {
            return Some(format!("point `{n}` is named twice"));
        }
    }
    None
}

fn parse_csv(text: &str, path: &Path, order: PointOrder) -> Result<Tracks> {
    let (hline, frame_ids, rows) = csv_table(text, path)?;
    csv_frames(&frame_ids, &rows, path, hline, order)
}

/// A CSV tracks file read as a table: the header's line (checked to be `frame,point,x,y`),
/// the frame ids in order of first appearance, and each frame's rows. Blank lines and `#`
/// comments are skipped.
fn csv_table(text: &str, path: &Path) -> Result<(u64, Vec<String>, Vec<Vec<CsvRow>>)> {
    let mut lines = text
        .lines()
        .enumerate()
        .map(|(i, l)| (i as u64 + 1, l.trim()))
        .filter(|(_, l)| !l.is_empty() && !l.starts_with('#'));
    let Some((hline, header)) = lines.next() else {
        return Err(located(path, Some(1), "header", "the file is empty".into()));
    };
    let cols: Vec<&str> = header.split(',').map(str::trim).collect();
    if cols != ["frame", "point", "x", "y"] {
        return Err(located(
            path,
            Some(hline),
            "header",
            format!("expected `frame,point,x,y`, found `{header}`"),
        ));
    }
    let (frame_ids, rows) = csv_rows(lines, path)?;
    Ok((hline, frame_ids, rows))
}

/// One CSV row: a point's name, its image position and its line.
type CsvRow = (String, Vector2<f64>, u64);

/// The rows of a CSV tracks file, grouped by frame in order of first appearance.
fn csv_rows<'t>(
    lines: impl Iterator<Item = (u64, &'t str)>,
    path: &Path,
) -> Result<(Vec<String>, Vec<Vec<CsvRow>>)> {
    // frames in order of first appearance; each a list of (name, point, line)
    let mut frame_ids: Vec<String> = Vec::new();
    let mut rows: Vec<Vec<CsvRow>> = Vec::new();
    // hashed look-ups keep reading linear in the number of rows
    let mut frame_index: HashMap<String, usize> = HashMap::new();
    let mut seen: HashSet<(usize, String)> = HashSet::new();
    for (line, l) in lines {
        let f: Vec<&str> = l.split(',').map(str::trim).collect();
        if f.len() != 4 {
            return Err(located(
                path,
                Some(line),
                "row",
                format!("{} fields, expected 4 (frame,point,x,y)", f.len()),
            ));
        }
        let mut xy = [0.0; 2];
        for (k, name) in ["x", "y"].iter().enumerate() {
            xy[k] = match f[2 + k].parse::<f64>() {
                Ok(v) if v.is_finite() => v,
                _ => {
                    return Err(located(
                        path,
                        Some(line),
                        name,
                        format!("`{}` is not a finite number", f[2 + k]),
                    ))
                }
            };
        }
        if f[1].is_empty() {
            return Err(located(
                path,
                Some(line),
                "point",
                "empty point name".into(),
            ));
        }
        let idx = *frame_index.entry(f[0].to_string()).or_insert_with(|| {
            frame_ids.push(f[0].to_string());
            rows.push(Vec::new());
            rows.len() - 1
        });
        if !seen.insert((idx, f[1].to_string())) {
            return Err(located(
                path,
                Some(line),
                "point",
                format!("point `{}` appears twice in frame `{}`", f[1], f[0]),
            ));
        }
        rows[idx].push((f[1].to_string(), Vector2::new(xy[0], xy[1]), line));
    }
    Ok((frame_ids, rows))
}

/// The frames of grouped CSV rows, every frame with the points of the first.
fn csv_frames(
    frame_ids: &[String],
    rows: &[Vec<CsvRow>],
    path: &Path,
    hline: u64,
    order: PointOrder,
) -> Result<Tracks> {
    let Some(first) = rows.first() else {
        return Err(located(path, Some(hline), "frame", "no rows".into()));
    };
    let names: Vec<String> = first.iter().map(|(n, _, _)| n.clone()).collect();
    let mut frames = Vec::with_capacity(rows.len());
    for (i, r) in rows.iter().enumerate() {
        let last_line = r.last().map(|x| x.2);
        if r.len() != names.len() {
            return Err(located(
                path,
                last_line,
                "point",
                format!(
                    "frame `{}` has {} points, but frame `{}` has {}",
                    frame_ids[i],
                    r.len(),
                    frame_ids[0],
                    names.len()
                ),
            ));
        }
        let frame = match order {
            PointOrder::AsListed => r.iter().map(|x| x.1).collect(),
            PointOrder::ByName => {
                let by_name: HashMap<&str, Vector2<f64>> =
                    r.iter().map(|x| (x.0.as_str(), x.1)).collect();
                let mut f = Vec::with_capacity(names.len());
                for n in &names {
                    let Some(x) = by_name.get(n.as_str()) else {
                        return Err(located(
                            path,
                            last_line,
                            "point",
                            format!("frame `{}` lacks point `{n}`", frame_ids[i]),
                        ));
                    };
                    f.push(*x);
                }
                f
            }
        };
        frames.push(frame);
    }
    Tracks::new(names, frames).map_err(|e| located(path, None, "frame", e.to_string()))
}

/// Tracks as YAML, in the format [`load_tracks`] reads (shortest round-trip floats).
pub fn tracks_to_yaml(t: &Tracks) -> String {
    observations_to_yaml(&crate::sfm::Observations::from_tracks(t))
}

/// Tracks as CSV with the header `frame,point,x,y` (frames numbered from 1).
pub fn tracks_to_csv(t: &Tracks) -> String {
    observations_to_csv(&crate::sfm::Observations::from_tracks(t))
}

/// Observations with gaps as CSV (`frame,point,x,y`, a missing point has no row), in the
/// format `reconstruct` reads.
pub fn observations_to_csv(o: &crate::sfm::Observations) -> String {
    let mut s = String::from("frame,point,x,y\n");
    for (f, j, y) in o.seen() {
        let (x, y) = (round_trip(y.x), round_trip(y.y));
        let _ = writeln!(s, "{},{},{x},{y}", f + 1, o.names[j]);
    }
    s
}

/// Observations with gaps as YAML (`null` for a missing point), in the format `reconstruct`
/// reads.
pub fn observations_to_yaml(o: &crate::sfm::Observations) -> String {
    let mut s = String::new();
    let _ = writeln!(s, "points: [{}]", o.names.join(", "));
    let _ = writeln!(s, "frames:");
    for f in &o.frames {
        let pts: Vec<String> = f
            .iter()
            .map(|p| {
                p.map_or("null".into(), |p| {
                    format!("[{}, {}]", round_trip(p.x), round_trip(p.y))
                })
            })
            .collect();
        let _ = writeln!(s, "  - [{}]", pts.join(", "));
    }
    s
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::model::Scene;

    fn csv(text: &str) -> Result<Tracks> {
        parse_tracks(text, Path::new("t.csv"), PointOrder::ByName)
    }

    #[test]
    fn both_formats_round_trip() {
        let t = Scene::random(4, 3, 5).tracks();
        let y = parse_tracks(&tracks_to_yaml(&t), Path::new("t.yaml"), PointOrder::ByName);
        assert_eq!(y.unwrap(), t);
        assert_eq!(csv(&tracks_to_csv(&t)).unwrap(), t);
    }

    #[test]
    fn a_byte_order_mark_is_read_in_both_formats() {
        let t = Scene::random(3, 3, 2).tracks();
        let y = format!("\u{feff}{}", tracks_to_yaml(&t));
        assert_eq!(
            parse_tracks(&y, Path::new("t.yaml"), PointOrder::ByName).unwrap(),
            t
        );
        assert_eq!(csv(&format!("\u{feff}{}", tracks_to_csv(&t))).unwrap(), t);
    }

    #[test]
    fn parser_messages_are_in_plain_words() {
        let y = |text: &str| {
            parse_tracks(text, Path::new("t.yaml"), PointOrder::ByName)
                .unwrap_err()
                .to_string()
        };
        let dup = y("points: [P, Q]\npoints: [P, Q]\nframes: []\n");
        assert!(dup.ends_with("key `points` appears twice"), "{dup}");
        let deep = y(&format!("frames: {}{}\n", "[".repeat(200), "]".repeat(200)));
        assert!(
            !deep.contains("Options") && !deep.contains("budget"),
            "{deep}"
        );
    }

    #[test]
    fn many_yaml_frames_are_read() {
        let t = Scene::random(4, 10_000, 3).tracks();
        let y = parse_tracks(&tracks_to_yaml(&t), Path::new("t.yaml"), PointOrder::ByName);
        assert_eq!(y.unwrap().frames.len(), 10_000);
    }

    #[test]
    fn names_must_be_distinct_and_not_empty() {
        let y = |names: &str| {
            parse_tracks(
                &format!("points: {names}\nframes:\n  - [[0, 0], [1, 0]]\n"),
                Path::new("t.yaml"),
                PointOrder::ByName,
            )
            .unwrap_err()
            .to_string()
        };
        assert_eq!(
            y("[P, P]"),
            "t.yaml:1: field `points`: point `P` is named twice"
        );
        assert_eq!(y("[P, '']"), "t.yaml:1: field `points`: empty point name");
    }

    #[test]
    fn many_frames_read_in_linear_time() {
        // 200,000 rows: a quadratic search over frame ids would take minutes
        let mut text = String::from("frame,point,x,y\n");
        for f in 0..50_000 {
            for (n, x) in [("P", 0.0), ("Q", 1.0), ("R", 2.0), ("T", 3.0)] {
                let _ = writeln!(text, "{f},{n},{x},{}", f % 7);
            }
        }
        assert_eq!(csv(&text).unwrap().frames.len(), 50_000);
    }

    #[test]
    fn errors_name_line_and_field() {
        let e = csv("frame,point,x,y\n1,P,0,0\n1,Q,abc,0\n").unwrap_err();
        assert_eq!(
            e.to_string(),
            "t.csv:3: field `x`: `abc` is not a finite number"
        );
        let e = csv("frame,point,x,y\n1,P,0,NaN\n").unwrap_err();
        assert_eq!(
            e.to_string(),
            "t.csv:2: field `y`: `NaN` is not a finite number"
        );
        let e = csv("frame,point,x,y\n1,P,0,0\n1,Q,1,0\n2,P,0,0\n").unwrap_err();
        assert!(e.to_string().contains("frame `2` has 1 points"), "{e}");
        let e = parse_tracks(
            "frames:\n  - [[0, 0], [1, 0]]\n  - [[0, 0]]\n",
            Path::new("t.yaml"),
            PointOrder::ByName,
        )
        .unwrap_err();
        assert_eq!(
            e.to_string(),
            "t.yaml:3: field `frames[1]`: 1 points, but frame 1 has 2"
        );
    }
}
