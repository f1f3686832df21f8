//! What `orthocheck reconstruct` prints: JSON (`points` by name in the tracks' order,
//! `frames` with `rotation` and `translation`, `rms`, `mirror`, `method`, `inliers` in robust
//! mode) and a plain-text table.

use std::fmt::Write as _;

use serde::ser::{SerializeMap, SerializeStruct};
use serde::{Serialize, Serializer};

use super::{Frame, Outcome, Reconstruction};
use crate::numfmt::sig;

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

/// One frame: `rotation` (rows) and `translation`.
struct FrameJson<'a>(&'a Frame);

impl Serialize for FrameJson<'_> {
    fn serialize<S: Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        let r = &self.0.rotation;
        let rows: [[f64; 3]; 3] = std::array::from_fn(|i| std::array::from_fn(|j| r[(i, j)]));
        let mut st = s.serialize_struct("Frame", 2)?;
        st.serialize_field("rotation", &rows)?;
        st.serialize_field("translation", &[self.0.translation.x, self.0.translation.y])?;
        st.end()
    }
}

/// The frames of a reconstruction.
fn frames(r: &Reconstruction) -> Vec<FrameJson<'_>> {
    r.frames.iter().map(FrameJson).collect()
}

/// The mirror twin: its points and frames.
struct Mirror<'a>(&'a Reconstruction);

impl Serialize for Mirror<'_> {
    fn serialize<S: Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        let mut st = s.serialize_struct("Mirror", 2)?;
        st.serialize_field("points", &Points(self.0))?;
        st.serialize_field("frames", &frames(self.0))?;
        st.end()
    }
}

/// The JSON document of an outcome.
pub struct Json<'a>(pub &'a Outcome);

impl Serialize for Json<'_> {
    fn serialize<S: Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        let o = self.0;
        let r = &o.reconstruction;
        let mut st = s.serialize_struct("Reconstruction", 7)?;
        st.serialize_field("points", &Points(r))?;
        st.serialize_field("frames", &frames(r))?;
        st.serialize_field("rms", &o.rms)?;
        st.serialize_field("mirror", &Mirror(&o.mirror))?;
        st.serialize_field("method", &r.method.join("; "))?;
        if let Some(i) = &o.inliers {
            st.serialize_field("inliers", i)?;
        }
        if let Some(b) = &o.bundle {
            st.serialize_field("iterations", &b.iterations)?;
        }
        st.end()
    }
}

/// Three numbers in brackets.
fn triple(v: impl IntoIterator<Item = f64>) -> String {
    let parts: Vec<String> = v.into_iter().map(sig).collect();
    format!("[{}]", parts.join(", "))
}

/// The plain-text table of an outcome.
pub fn text(o: &Outcome) -> String {
    let r = &o.reconstruction;
    let mut s = String::new();
    let _ = writeln!(s, "method: {}", r.method.join("; "));
    let _ = writeln!(s, "rms reprojection error: {} image units", sig(o.rms));
    if let Some(i) = &o.inliers {
        let _ = writeln!(s, "inliers ({}): {}", i.len(), i.join(", "));
    }
    let _ = writeln!(s, "points (frame 1's camera coordinates, centred):");
    let width = r.names.iter().map(|n| n.chars().count()).max().unwrap_or(1);
    for (n, x) in r.names.iter().zip(&r.points) {
        let _ = writeln!(s, "  {n:<width$}  {}", triple([x.x, x.y, x.z]));
    }
    let _ = writeln!(s, "frames (rotation rows; translation):");
    for (f, fr) in r.frames.iter().enumerate() {
        let rows: Vec<String> = (0..3)
            .map(|i| triple((0..3).map(|j| fr.rotation[(i, j)])))
            .collect();
        let _ = writeln!(
            s,
            "  {:>3}  {}  {}",
            f + 1,
            rows.join(" "),
            triple([fr.translation.x, fr.translation.y])
        );
    }
    let _ = writeln!(
        s,
        "mirror (Necker) solution: every point's z and every rotation R ↦ DRD, D = diag(1, 1, −1), give the same images"
    );
    s
}
