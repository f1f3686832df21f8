//! Which body a perspective drawing of §5.1 labels: each picture draws the cube
//! [−s, s]³ around P (one corner and the three edges leaving it) and puts a label beside the
//! image of each point. The cube fixes the drawing's linear map up to the cube's 48
//! symmetries (signed permutations of the axes); a naming of the labels fits when, for one
//! symmetry, every label sits where its point's image does (relative to P's label), within
//! the rounding of the printed coordinates.

/// One picture, in numbers.
#[derive(Clone, Debug, PartialEq)]
pub struct Picture {
    /// The cube corner the three edges leave.
    pub corner: [f64; 2],
    /// The other ends of the three edges.
    pub ends: [[f64; 2]; 3],
    /// Half a unit of the pictures' printed coordinates.
    pub half_unit: f64,
    /// P's label.
    pub origin_label: [f64; 2],
}

/// A label and the 3-D point a naming says it shows.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Labelled {
    /// The label's printed position.
    pub at: [f64; 2],
    /// The point, relative to P.
    pub point: [f64; 3],
    /// Half a unit of the point's printed coordinates.
    pub point_half_unit: f64,
}

/// The best fit of a naming.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct LabelFit {
    /// The distance (largest coordinate) of the worst label from its point's image, at the
    /// best symmetry; the worst label is the one farthest relative to its bound.
    pub misfit: f64,
    /// What the rounding of the printed numbers allows that label.
    pub bound: f64,
}

impl LabelFit {
    /// The naming fits within the rounding.
    pub fn fits(&self) -> bool {
        self.misfit <= self.bound
    }
}

/// The 48 signed permutations of three axes.
fn symmetries() -> Vec<([usize; 3], [f64; 3])> {
    const PERMS: [[usize; 3]; 6] = [
        [0, 1, 2],
        [0, 2, 1],
        [1, 0, 2],
        [1, 2, 0],
        [2, 0, 1],
        [2, 1, 0],
    ];
    let mut out = Vec::with_capacity(48);
    for p in PERMS {
        for bits in 0..8u8 {
            let s = [0, 1, 2].map(|i| if bits >> i & 1 == 1 { -1.0 } else { 1.0 });
            out.push((p, s));
        }
    }
    out
}

/// The fit of one naming; `half_side` is s of the cube [−s, s]³. `None` without labels.
///
/// The image of X − P is Σᵢ sᵢ X_{σ(i)} eᵢ / (2s), eᵢ = endᵢ − corner. The bound is the
/// first-order propagation of the printed rounding: a label and P's label contribute h each
/// per coordinate, each eᵢ carries 2h, scaled by |X_{σ(i)}| / (2s), and a point coordinate
/// rounded by h₃ moves the image by h₃ |eᵢ| / (2s).
pub fn fit(picture: &Picture, half_side: f64, labels: &[Labelled]) -> Option<LabelFit> {
    if labels.is_empty() || half_side <= 0.0 {
        return None;
    }
    let e: Vec<[f64; 2]> = picture
        .ends
        .iter()
        .map(|end| [end[0] - picture.corner[0], end[1] - picture.corner[1]])
        .collect();
    let h = picture.half_unit;
    let scale = 2.0 * half_side;
    let mut best: Option<LabelFit> = None;
    for (perm, sign) in symmetries() {
        // the worst label: the largest distance relative to what its rounding allows
        let mut worst = LabelFit {
            misfit: 0.0,
            bound: 1.0,
        };
        for l in labels {
            let mut image = [0.0; 2];
            let mut allowed = 2.0 * h;
            for i in 0..3 {
                let x = sign[i] * l.point[perm[i]];
                for (k, img) in image.iter_mut().enumerate() {
                    *img += x * e[i][k] / scale;
                }
                let len = e[i][0].hypot(e[i][1]);
                allowed += (x.abs() * 2.0 * h + l.point_half_unit * len) / scale;
            }
            let dist = (0..2)
                .map(|k| (l.at[k] - picture.origin_label[k] - image[k]).abs())
                .fold(0.0, f64::max);
            if dist * worst.bound > worst.misfit * allowed {
                worst = LabelFit {
                    misfit: dist,
                    bound: allowed,
                };
            }
        }
        if best.is_none_or(|b| worst.misfit * b.bound < b.misfit * worst.bound) {
            best = Some(worst);
        }
    }
    best
}

#[cfg(test)]
mod tests {
    use super::*;

    fn picture() -> Picture {
        // a cube [−1, 1]³ drawn with e₁ = (2, 0), e₂ = (0, 2), e₃ = (1, 1)
        Picture {
            corner: [0.0, 0.0],
            ends: [[2.0, 0.0], [0.0, 2.0], [1.0, 1.0]],
            half_unit: 0.0005,
            origin_label: [1.0, 1.0],
        }
    }

    #[test]
    fn the_true_naming_fits_and_a_moved_point_does_not() {
        let p = [0.5, -0.25, 0.0];
        // image of p: (0.5·e₁ − 0.25·e₂) / (2s) = (0.5, −0.25), relative to P's label
        let at = [1.5, 0.75];
        let ok = fit(
            &picture(),
            1.0,
            &[Labelled {
                at,
                point: p,
                point_half_unit: 0.0,
            }],
        )
        .unwrap();
        assert!(ok.fits(), "{ok:?}");
        let moved = [0.6, -0.25, 0.0];
        let off = fit(
            &picture(),
            1.0,
            &[Labelled {
                at,
                point: moved,
                point_half_unit: 0.0,
            }],
        )
        .unwrap();
        assert!(!off.fits(), "{off:?}");
        assert!(fit(&picture(), 1.0, &[]).is_none());
    }
}
