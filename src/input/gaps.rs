//! Tracks files with gaps, for `reconstruct`: in YAML a missing point is `null` (or `~`) in
//! its frame's list; in CSV a frame simply has no row for it. Names: the `points:` list
//! (YAML), or the order of first appearance over all rows (CSV). Complete files read as
//! [`load_tracks`](super::load_tracks) reads them.

use std::collections::HashMap;
use std::path::Path;

use nalgebra::Vector2;
use serde::Deserialize;

use super::{located, name_problem, MAX_TRACKS_BYTES};
use crate::cases::{line_of, parse_yaml_limited};
use crate::error::Result;
use crate::model::default_names;
use crate::sfm::Observations;

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct YamlGaps {
    #[serde(default)]
    points: Option<Vec<String>>,
    frames: Vec<Vec<Option<[f64; 2]>>>,
}

/// Read a tracks file that may have gaps; the extension (`.csv`, otherwise YAML) picks the
/// format. Every error names the file, the line and the field.
pub fn load_observations(path: &Path) -> Result<Observations> {
    parse_observations(&super::read_text(path)?, path)
}

/// Parse tracks text that may have gaps; `path` names the file in errors.
///
/// # Example
/// ```
/// let o = orthocheck::input::parse_observations(
///     "frames:\n  - [[0, 0], [1, 0]]\n  - [[0, 1], null]\n",
///     std::path::Path::new("t.yaml"),
/// ).unwrap();
/// assert_eq!(o.frames[1][1], None);
/// ```
pub fn parse_observations(text: &str, path: &Path) -> Result<Observations> {
    let (text, is_csv) = super::text_and_format(text, path)?;
    if is_csv {
        parse_csv(text, path)
    } else {
        parse_yaml(text, path)
    }
}

fn parse_yaml(text: &str, path: &Path) -> Result<Observations> {
    let y: YamlGaps = parse_yaml_limited(text, path, MAX_TRACKS_BYTES as usize / 4)?;
    let bad = |field: String, message: String| {
        let line = line_of(text, &field).or_else(|| line_of(text, "frames"));
        Err(located(path, line, &field, message))
    };
    let Some(first) = y.frames.first() else {
        return bad("frames".into(), "no frames".into());
    };
    let p = first.len();
    let names = match y.points {
        Some(n) if n.len() != p => {
            return bad(
                "points".into(),
                format!("{} names for {p} points per frame", n.len()),
            )
        }
        Some(n) => match name_problem(&n) {
            Some(message) => return bad("points".into(), message),
            None => n,
        },
        None => default_names(p),
    };
    let mut frames = Vec::with_capacity(y.frames.len());
    for (i, f) in y.frames.iter().enumerate() {
        if f.len() != p {
            return bad(
                format!("frames[{i}]"),
                format!(
                    "{} entries, but frame 1 has {p} (write `null` for a missing point)",
                    f.len()
                ),
            );
        }
        for (j, xy) in f.iter().enumerate() {
            if let Some(c) = xy.and_then(|xy| xy.iter().position(|v| !v.is_finite())) {
                return bad(
                    format!("frames[{i}][{j}][{c}]"),
                    "coordinate is not a finite number".into(),
                );
            }
        }
        frames.push(
            f.iter()
                .map(|xy| xy.map(|v| Vector2::new(v[0], v[1])))
                .collect(),
        );
    }
    Ok(Observations { names, frames })
}

fn parse_csv(text: &str, path: &Path) -> Result<Observations> {
    let (hline, _, rows) = super::csv_table(text, path)?;
    if rows.is_empty() {
        return Err(located(path, Some(hline), "frame", "no rows".into()));
    }
    let mut index: HashMap<String, usize> = HashMap::new();
    let mut names: Vec<String> = Vec::new();
    for (n, _, _) in rows.iter().flatten() {
        if !index.contains_key(n) {
            index.insert(n.clone(), names.len());
            names.push(n.clone());
        }
    }
    // the dense table's size, checked before it is made
    let cells = rows.len().saturating_mul(names.len());
    if cells > crate::limits::OBSERVATION_CELLS {
        return Err(located(
            path,
            Some(hline),
            "frame",
            format!(
                "{} frames × {} points = {cells} cells, more than the limit of {} (docs/limits.md)",
                rows.len(),
                names.len(),
                crate::limits::OBSERVATION_CELLS
            ),
        ));
    }
    let frames = rows
        .iter()
        .map(|r| {
            let mut f = vec![None; names.len()];
            for (n, y, _) in r {
                if let Some(&j) = index.get(n) {
                    f[j] = Some(*y);
                }
            }
            f
        })
        .collect();
    Ok(Observations { names, frames })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::input::{parse_tracks, tracks_to_csv, tracks_to_yaml, PointOrder};
    use crate::model::Scene;

    #[test]
    fn complete_files_read_as_tracks_in_both_formats() {
        let t = Scene::random(5, 3, 9).tracks();
        for (text, name) in [(tracks_to_yaml(&t), "t.yaml"), (tracks_to_csv(&t), "t.csv")] {
            let o = parse_observations(&text, Path::new(name)).unwrap();
            let back = parse_tracks(&text, Path::new(name), PointOrder::ByName).unwrap();
            assert_eq!(o.complete().unwrap(), back);
        }
    }

    #[test]
    fn gaps_are_read_and_errors_name_line_and_field() {
        let csv = "frame,point,x,y\n1,P,0,0\n1,Q,1,0\n2,Q,0,1\n2,R,2,2\n";
        let o = parse_observations(csv, Path::new("t.csv")).unwrap();
        assert_eq!(o.names, ["P", "Q", "R"]);
        assert_eq!(o.frames[0][2], None);
        assert_eq!(o.frames[1][0], None);
        let e = parse_observations("frame,point,x,y\n1,P,0,0\n1,Q,zz,0\n", Path::new("t.csv"))
            .unwrap_err();
        assert_eq!(
            e.to_string(),
            "t.csv:3: field `x`: `zz` is not a finite number"
        );
        let e = parse_observations(
            "frames:\n  - [[0, 0], null]\n  - [[0, 0]]\n",
            Path::new("t.yaml"),
        )
        .unwrap_err();
        assert!(
            e.to_string()
                .starts_with("t.yaml:3: field `frames[1]`: 1 entries"),
            "{e}"
        );
    }
}
