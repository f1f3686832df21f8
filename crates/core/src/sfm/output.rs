//! What `orthocheck reconstruct` prints: JSON and a plain-text table.
//!
//! A reconstruction in JSON: `points` by name in the tracks' order, `frames` (each its
//! `frame`, the input's number from 1, `rotation` and `translation`), `rms`, `mirror`,
//! `method`; in robust mode `inliers` and `rejected` (point names), `threshold` (`value`,
//! `from`: `"data"` or `"--threshold"`, and for the data its `median`, `sigma`, `shrink`,
//! `floor`, `observations`, `freedom` (σ's residual degrees of freedom, null for a RANSAC
//! sample's and for a fit without residual freedom), `multiple` (the threshold in σ), and `relative` and `unit` (the mix of noise
//! scales residuals were weighed by, λ and u²)) and `dropped` (`point`, `frame` counted from 1, `residual`);
//! after a bundle adjustment `iterations`, `points_std` (each point's standard errors by
//! name), `depth_barely_determined` (the names of the points whose depth's standard error
//! exceeds a tenth of the body's size) and `frames_std` (each frame's `frame`,
//! `rotation_deg`: the standard errors of its rotation relative to the group's first
//! frame's, about that frame's camera axes, in degrees, and `translation`), or
//! `no_standard_errors` (why there are none).
//! The document: with one group of frames, its reconstruction's fields; with several,
//! `components`, one reconstruction each (its own frame of reference); and always
//! `warnings` (strings), `dropped_points` (`name`, `why`) and `dropped_frames` (`frame`,
//! `why`).

use std::fmt::Write as _;

use serde::ser::{SerializeMap, SerializeStruct};
use serde::{Serialize, Serializer};

use super::groups::LINK;
use super::judge::MIN_IMAGES;
use super::pipeline::{group_label, Component};
use super::robust::{Dropped, RobustReport};
use super::threshold::{Mix, Source, Threshold, RAYLEIGH_MEDIAN};
use super::{Frame, FrameStd, Outcome, Reconstruction};
use crate::numfmt::sig;

/// Dropped observations, points and frames the text lists by name (the JSON lists every
/// one).
const TEXT_DROPPED: usize = 20;

/// Points by name, in the tracks' order (a streamed map keeps the order).
struct Points<'a>(&'a Reconstruction);

impl Serialize for Points<'_> {
    fn serialize<S: Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        let mut m = s.serialize_map(Some(self.0.points.len()))?;
        for (n, x) in self.0.names.iter().zip(&self.0.points) {
            m.serialize_entry(n, &[x.x, x.y, x.z])?;
        }
        m.end()
    }
}

/// One frame: its number in the input, `rotation` (rows) and `translation`.
struct FrameJson<'a>(usize, &'a Frame);

impl Serialize for FrameJson<'_> {
    fn serialize<S: Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        let r = &self.1.rotation;
        let rows: [[f64; 3]; 3] = std::array::from_fn(|i| std::array::from_fn(|j| r[(i, j)]));
        let mut st = s.serialize_struct("Frame", 3)?;
        st.serialize_field("frame", &self.0)?;
        st.serialize_field("rotation", &rows)?;
        st.serialize_field("translation", &[self.1.translation.x, self.1.translation.y])?;
        st.end()
    }
}

/// The frames of a reconstruction, with their numbers in the input.
fn frames<'a>(r: &'a Reconstruction, numbers: &[usize]) -> Vec<FrameJson<'a>> {
    numbers
        .iter()
        .zip(&r.frames)
        .map(|(&n, f)| FrameJson(n, f))
        .collect()
}

/// The mirror twin: its points and frames (with their numbers in the input).
struct Mirror<'a>(&'a Reconstruction, &'a [usize]);

impl Serialize for Mirror<'_> {
    fn serialize<S: Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        let mut st = s.serialize_struct("Mirror", 2)?;
        st.serialize_field("points", &Points(self.0))?;
        st.serialize_field("frames", &frames(self.0, self.1))?;
        st.end()
    }
}

/// A threshold: `value`, `from`, and the scale behind one from the data.
struct ThresholdJson<'a>(&'a Threshold);

impl Serialize for ThresholdJson<'_> {
    fn serialize<S: Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        let t = self.0;
        let mut m = s.serialize_map(None)?;
        m.serialize_entry("value", &t.value)?;
        match t.source {
            Source::Given => m.serialize_entry("from", "--threshold")?,
            Source::Data(d) => {
                m.serialize_entry("from", "data")?;
                m.serialize_entry("median", &d.median)?;
                m.serialize_entry("observations", &d.observations)?;
                m.serialize_entry("shrink", &d.shrink)?;
                m.serialize_entry("sigma", &d.sigma)?;
                m.serialize_entry("floor", &d.floor)?;
                m.serialize_entry("floored", &t.floored())?;
                m.serialize_entry("freedom", &d.freedom)?;
                m.serialize_entry("multiple", &d.multiple)?;
                m.serialize_entry("relative", &d.mix.relative)?;
                m.serialize_entry("unit", &d.mix.unit)?;
            }
        }
        m.end()
    }
}

/// One dropped observation: `point`, `frame` (from 1), `residual` (null when unknown).
struct DroppedJson<'a>(&'a Dropped);

impl Serialize for DroppedJson<'_> {
    fn serialize<S: Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        let mut st = s.serialize_struct("Dropped", 3)?;
        st.serialize_field("point", &self.0.point)?;
        st.serialize_field("frame", &self.0.frame)?;
        st.serialize_field("residual", &self.0.residual)?;
        st.end()
    }
}

/// Each kept point's inlier frames, by name in the tracks' order.
struct InlierFrames<'a>(&'a super::robust::RobustReport);

impl Serialize for InlierFrames<'_> {
    fn serialize<S: Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        use serde::ser::SerializeMap as _;
        let mut m = s.serialize_map(Some(self.0.kept.len()))?;
        for (name, frames) in self.0.kept.iter().zip(&self.0.inlier_frames) {
            m.serialize_entry(name, frames)?;
        }
        m.end()
    }
}

/// One component's fields (a reconstruction in JSON, see the module).
fn component_fields<M: SerializeMap>(m: &mut M, c: &Component) -> Result<(), M::Error> {
    let r = &c.reconstruction;
    m.serialize_entry("points", &Points(r))?;
    m.serialize_entry("frames", &frames(r, &c.frames))?;
    m.serialize_entry("rms", &c.rms)?;
    m.serialize_entry("mirror", &Mirror(&c.mirror, &c.frames))?;
    m.serialize_entry("method", &r.method.join("; "))?;
    if let Some(i) = &c.inliers {
        m.serialize_entry("inliers", i)?;
    }
    if let Some(rb) = &c.robust {
        m.serialize_entry(
            "robust_start",
            if rb.whole_fit {
                "fit of every observation"
            } else {
                "sample"
            },
        )?;
        m.serialize_entry("inlier_frames", &InlierFrames(rb))?;
        m.serialize_entry("rejected", &rb.rejected)?;
        m.serialize_entry("threshold", &ThresholdJson(&rb.threshold))?;
        let dropped: Vec<DroppedJson<'_>> = rb.dropped.iter().map(DroppedJson).collect();
        m.serialize_entry("dropped", &dropped)?;
    }
    if let Some(b) = &c.bundle {
        m.serialize_entry("iterations", &b.iterations)?;
    }
    if let Some(sd) = points_std(c) {
        m.serialize_entry("points_std", &Named(&r.names, sd))?;
        m.serialize_entry("depth_barely_determined", &poor_depths(c))?;
    }
    if let Some(sd) = frames_std(c) {
        let numbered: Vec<FrameStdJson<'_>> = c
            .frames
            .iter()
            .zip(sd)
            .map(|(&n, e)| FrameStdJson(n, e))
            .collect();
        m.serialize_entry("frames_std", &numbered)?;
    }
    if let Some(why) = c.bundle.as_ref().and_then(|b| b.no_standard_errors) {
        m.serialize_entry("no_standard_errors", why)?;
    }
    Ok(())
}

/// One frame's standard errors: its number in the input, `rotation_deg` (about the group's
/// first frame's camera axes, relative to that frame) and `translation` (the points
/// centred).
struct FrameStdJson<'a>(usize, &'a FrameStd);

impl Serialize for FrameStdJson<'_> {
    fn serialize<S: Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        let (r, t) = (self.1.rotation.map(f64::to_degrees), self.1.translation);
        let mut st = s.serialize_struct("FrameStd", 3)?;
        st.serialize_field("frame", &self.0)?;
        st.serialize_field("rotation_deg", &[r.x, r.y, r.z])?;
        st.serialize_field("translation", &[t.x, t.y])?;
        st.end()
    }
}

/// The frames' standard errors from the bundle adjustment, when it gave them for these
/// frames.
fn frames_std(c: &Component) -> Option<&[FrameStd]> {
    let sd = c.bundle.as_ref()?.frames_std.as_deref()?;
    (sd.len() == c.reconstruction.frames.len()).then_some(sd)
}

/// Each point's standard errors, by name in the tracks' order.
struct Named<'a>(&'a [String], &'a [nalgebra::Vector3<f64>]);

impl Serialize for Named<'_> {
    fn serialize<S: Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        let mut m = s.serialize_map(Some(self.1.len()))?;
        for (n, x) in self.0.iter().zip(self.1) {
            m.serialize_entry(n, &[x.x, x.y, x.z])?;
        }
        m.end()
    }
}

/// The points' standard errors from the bundle adjustment, when it gave them for these
/// points.
fn points_std(c: &Component) -> Option<&[nalgebra::Vector3<f64>]> {
    let sd = c.bundle.as_ref()?.points_std.as_deref()?;
    (sd.len() == c.reconstruction.points.len()).then_some(sd)
}

/// A depth whose standard error exceeds this share of the body's size (the rms distance of
/// its points from their centroid) is reported as barely determined: its sign is clear, its
/// value is not a measurement.
const POOR_DEPTH: f64 = 0.1;

/// The points whose depth is barely determined ([`POOR_DEPTH`]).
fn poor_depths(c: &Component) -> Vec<&str> {
    let Some(sd) = points_std(c) else {
        return Vec::new();
    };
    let r = &c.reconstruction;
    let size = (r.points.iter().map(|x| x.norm_squared()).sum::<f64>()
        / r.points.len().max(1) as f64)
        .sqrt();
    r.names
        .iter()
        .zip(sd)
        .filter(|(_, e)| e.z > POOR_DEPTH * size)
        .map(|(n, _)| n.as_str())
        .collect()
}

/// One component as a JSON object.
struct ComponentJson<'a>(&'a Component);

impl Serialize for ComponentJson<'_> {
    fn serialize<S: Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        let mut m = s.serialize_map(None)?;
        component_fields(&mut m, self.0)?;
        m.end()
    }
}

/// The JSON document of an outcome (see the module).
pub struct Json<'a>(pub &'a Outcome);

impl Serialize for Json<'_> {
    fn serialize<S: Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        let o = self.0;
        let mut m = s.serialize_map(None)?;
        match o.components.as_slice() {
            [one] => component_fields(&mut m, one)?,
            many => {
                let all: Vec<ComponentJson<'_>> = many.iter().map(ComponentJson).collect();
                m.serialize_entry("components", &all)?;
            }
        }
        m.serialize_entry("warnings", &o.warnings())?;
        m.serialize_entry("dropped_points", &o.dropped_points)?;
        m.serialize_entry("dropped_frames", &o.dropped_frames)?;
        m.end()
    }
}

/// Three numbers in brackets.
fn triple(v: impl IntoIterator<Item = f64>) -> String {
    let parts: Vec<String> = v.into_iter().map(sig).collect();
    format!("[{}]", parts.join(", "))
}

/// The text line of a threshold.
fn threshold_line(t: &Threshold) -> String {
    let why = match t.source {
        Source::Given => "--threshold".to_string(),
        Source::Data(d) if t.floored() => format!(
            "from the data: the median residual {} of {} observations is rounding, so the floor, 2^10 ε × the image size × the fit's rounding factor; --threshold sets it",
            sig(d.median),
            d.observations
        ),
        Source::Data(d) => format!(
            "from the data: {} σ, the 99 % point of a 2-D normal error's norm{}; σ = median residual {} of {} observations / {}{}{}; --threshold sets it",
            sig(d.multiple),
            d.freedom.map_or(String::new(), |nu| format!(
                " with σ known to {nu} degrees of freedom"
            )),
            sig(d.median),
            d.observations,
            sig(RAYLEIGH_MEDIAN),
            if d.shrink < 1.0 {
                format!(" / {} (the fit's parameters)", sig(d.shrink))
            } else {
                String::new()
            },
            mix_clause(&d.mix)
        ),
    };
    format!("threshold {} image units ({why})", sig(t.value))
}

/// How residuals were weighed, when the noise grows with the coordinates.
fn mix_clause(mix: &Mix) -> String {
    if mix.relative == 0.0 {
        return String::new();
    }
    format!(
        "; each residual coordinate x divided by √((1 − λ) + λ x²/u²), at least √(1/8), λ = {} (noise growing with the coordinates), u = {}",
        sig(mix.relative),
        sig(mix.unit.sqrt())
    )
}

/// The text lines of robust mode: the threshold, the dropped observations, the rejected
/// points.
fn robust_lines(s: &mut String, r: &RobustReport) {
    let _ = writeln!(s, "{}", threshold_line(&r.threshold));
    let listed: Vec<String> = r
        .dropped
        .iter()
        .take(TEXT_DROPPED)
        .map(|d| format!("{} in frame {}", d.point, d.frame))
        .collect();
    let more = if r.dropped.len() > TEXT_DROPPED {
        ", …"
    } else {
        ""
    };
    let _ = writeln!(
        s,
        "dropped observations ({} of {}; --json lists each with its residual){}{}{}",
        r.dropped.len(),
        r.observations,
        if listed.is_empty() { "" } else { ": " },
        listed.join(", "),
        more
    );
    if !r.rejected.is_empty() {
        let _ = writeln!(
            s,
            "rejected points ({}; fewer than {MIN_IMAGES} images within the threshold, or not both of two): {}",
            r.rejected.len(),
            r.rejected.join(", ")
        );
    }
}

/// Lines of `items` (at most [`TEXT_DROPPED`], then how many more).
fn capped<T>(s: &mut String, items: &[T], what: &str, line: impl Fn(&T) -> String) {
    for item in items.iter().take(TEXT_DROPPED) {
        let _ = writeln!(s, "{}", line(item));
    }
    if items.len() > TEXT_DROPPED {
        let _ = writeln!(
            s,
            "… and {} more {what} (--json lists each)",
            items.len() - TEXT_DROPPED
        );
    }
}

/// The text of one component: method, error, points and frames (by their input numbers).
fn component_text(s: &mut String, c: &Component) {
    let r = &c.reconstruction;
    let _ = writeln!(s, "method: {}", r.method.join("; "));
    let _ = writeln!(s, "rms reprojection error: {} image units", sig(c.rms));
    if let Some(i) = c.inliers.as_ref().filter(|i| !i.is_empty()) {
        let _ = writeln!(s, "inliers ({}): {}", i.len(), i.join(", "));
    }
    if let Some(r) = &c.robust {
        robust_lines(s, r);
    }
    if let Some(why) = c.bundle.as_ref().and_then(|b| b.no_standard_errors) {
        let _ = writeln!(s, "no standard errors: {why}");
    }
    let sd = points_std(c);
    let _ = writeln!(
        s,
        "points (frame {}'s camera coordinates, centred{}):",
        c.frames[0],
        if sd.is_some() {
            "; ± standard errors"
        } else {
            ""
        }
    );
    let width = r.names.iter().map(|n| n.chars().count()).max().unwrap_or(1);
    for (i, (n, x)) in r.names.iter().zip(&r.points).enumerate() {
        let err = sd.map_or(String::new(), |e| {
            format!("  ± {}", triple([e[i].x, e[i].y, e[i].z]))
        });
        let _ = writeln!(s, "  {n:<width$}  {}{err}", triple([x.x, x.y, x.z]));
    }
    let poor = poor_depths(c);
    if !poor.is_empty() {
        let _ = writeln!(
            s,
            "depth barely determined ({} point{}: standard error above {} of the body's size): {}",
            poor.len(),
            if poor.len() == 1 { "" } else { "s" },
            sig(POOR_DEPTH),
            poor.join(", ")
        );
    }
    frames_text(s, c);
    let _ = writeln!(
        s,
        "mirror (Necker) solution: every point's z and every rotation R ↦ DRD, D = diag(1, 1, −1), give the same images"
    );
}

/// The frames of one component's text: rotation rows, translation and their standard errors
/// (or why there are none).
fn frames_text(s: &mut String, c: &Component) {
    let r = &c.reconstruction;
    let fsd = frames_std(c);
    let _ = writeln!(
        s,
        "frames (rotation rows; translation{}):",
        if fsd.is_some() {
            format!(
                "; ± standard errors of the rotation relative to frame {first}'s, degrees about frame {first}'s camera axes, and of the translation",
                first = c.frames[0]
            )
        } else {
            String::new()
        }
    );
    for (i, (number, fr)) in c.frames.iter().zip(&r.frames).enumerate() {
        let rows: Vec<String> = (0..3)
            .map(|i| triple((0..3).map(|j| fr.rotation[(i, j)])))
            .collect();
        let err = fsd.map_or(String::new(), |e| {
            let d = e[i].rotation.map(f64::to_degrees);
            format!(
                "  ± {}°  ± {}",
                triple([d.x, d.y, d.z]),
                triple([e[i].translation.x, e[i].translation.y])
            )
        });
        let _ = writeln!(
            s,
            "  {number:>3}  {}  {}{err}",
            rows.join(" "),
            triple([fr.translation.x, fr.translation.y])
        );
    }
}

/// The plain-text table of an outcome: a `warning:` line each, the dropped points and
/// frames, then each group's reconstruction (labelled when there are several).
pub fn text(o: &Outcome) -> String {
    let mut s = String::new();
    for w in o.warnings() {
        let _ = writeln!(s, "warning: {w}");
    }
    capped(&mut s, &o.dropped_points, "dropped points", |d| {
        format!("dropped point {}: {}", d.name, d.why)
    });
    capped(&mut s, &o.dropped_frames, "dropped frames", |d| {
        format!("dropped frame {}: {}", d.frame, d.why)
    });
    match o.components.as_slice() {
        [one] => component_text(&mut s, one),
        many => {
            let n = many.len();
            let _ = writeln!(
                s,
                "the frames kept form {n} groups (no frame of one shares {LINK} points with a frame of another): each is reconstructed in its own frame of reference, and their bodies are not one"
            );
            for (i, c) in many.iter().enumerate() {
                let _ = writeln!(
                    s,
                    "{}, {} points:",
                    group_label(i, n, &c.frames),
                    c.reconstruction.points.len()
                );
                component_text(&mut s, c);
            }
        }
    }
    s
}
