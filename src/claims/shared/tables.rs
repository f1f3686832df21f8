//! Printed tables more than one kind reads: a body's edges, a figure's frames, solutions.

use serde::Deserialize;

use crate::cases::{ClaimRef, Printed, Validator};
use crate::error::Result;

/// A printed edge table: lengths and their squares.
#[derive(Clone, Debug, Deserialize, PartialEq)]
#[serde(deny_unknown_fields)]
pub struct BodyTable {
    /// The claim.
    pub claim: ClaimRef,
    /// Printed lengths, in the paper's edge order.
    pub lengths: Vec<Printed>,
    /// Printed squares.
    pub squares: Vec<Printed>,
    /// Significant digits the program printed with (trailing zeros dropped), when the
    /// numbers are not exact.
    #[serde(default)]
    pub significant_digits: Option<u32>,
}

/// Figure coordinates: frames of points, each `[x, y]` as printed.
#[derive(Clone, Debug, Deserialize, PartialEq)]
#[serde(deny_unknown_fields)]
pub struct FigureFrames {
    /// The claim.
    pub claim: ClaimRef,
    /// `frames[i][j] = [x, y]`.
    pub frames: Vec<Vec<[Printed; 2]>>,
    /// Whether the first point of each frame is the shifted origin (exact, not rounded).
    #[serde(default)]
    pub origin_exact: bool,
}

impl FigureFrames {
    /// Flat coordinates and their rounding half-widths (`(center, half)`).
    pub fn rounding_box(&self) -> (Vec<f64>, Vec<f64>) {
        let mut center = Vec::new();
        let mut half = Vec::new();
        for frame in &self.frames {
            for (j, p) in frame.iter().enumerate() {
                for c in p {
                    center.push(c.to_f64());
                    half.push(if j == 0 && self.origin_exact {
                        0.0
                    } else {
                        c.half_unit()
                    });
                }
            }
        }
        (center, half)
    }
}

/// Printed solutions (squared edges).
#[derive(Clone, Debug, Deserialize, PartialEq)]
#[serde(deny_unknown_fields)]
pub struct PrintedSolutions {
    /// The claim.
    pub claim: ClaimRef,
    /// Significant digits the program printed (trailing zeros dropped).
    pub significant_digits: u32,
    /// The solutions, each in the paper's edge order.
    pub values: Vec<Vec<Printed>>,
}

/// The digits a body table was printed with, when given, within the limit.
pub fn body_digits(v: &Validator, field: &str, b: &BodyTable) -> Result<()> {
    b.significant_digits.map_or(Ok(()), |d| v.digits(field, d))
}
