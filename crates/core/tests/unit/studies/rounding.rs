//! Tests of `orthocheck_core::studies::rounding`.

use orthocheck_core::derivations::rounding::RoundingBox;
use orthocheck_core::studies::rounding::*;

#[test]
fn the_ladder_stops_at_the_first_failure() {
    let a = acceptance(&|s| s.abs() < 20.0);
    assert_eq!(a.accepted, [10.0, 10.0]);
    assert_eq!(a.rejected, [Some(30.0), Some(30.0)]);
    assert_eq!(a.interval(5.0, 0.5), (-10.0, 20.0));
    assert_eq!(a.outer(), 30.0);
    let never = acceptance(&|_| true);
    assert!(never.outer().is_infinite());
}

#[test]
fn a_witness_is_found_only_inside_the_box() {
    let b = RoundingBox {
        center: vec![0.0],
        half: vec![0.5],
    };
    // x = 0.3 is inside, x = 3 is not
    let near = |x: &[f64]| Some(vec![(x[0] - 0.3) / 1e-9]);
    let far = |x: &[f64]| Some(vec![(x[0] - 3.0) / 1e-9]);
    assert!(reproduce(&b, &near).is_some());
    assert!(reproduce(&b, &far).is_none());
}

/// Two printed rows, x₀ + x₁ and x₁ + x₂ against their targets, each moved by two of three
/// rounded coordinates: fewer targets than coordinates, one direction (x₀ − x₁ + x₂) neither
/// sees.
struct TwoRows([f64; 2]);

impl TwoRows {
    /// Both rows' scaled residuals at `x`.
    fn all(&self, x: &[f64]) -> Option<Vec<f64>> {
        let mut out = Vec::new();
        for g in 0..self.groups() {
            self.group(g, x, &mut out);
        }
        Some(out)
    }
}

impl GroupedResiduals for TwoRows {
    fn groups(&self) -> usize {
        2
    }
    fn group(&self, g: usize, x: &[f64], out: &mut Vec<f64>) {
        out.push((x[g] + x[g + 1] - self.0[g]) / 1e-3);
    }
    fn moves(&self, i: usize, g: usize) -> bool {
        i == g || i == g + 1
    }
}

#[test]
fn the_grouped_search_takes_the_gauged_search_s_steps() {
    let b = RoundingBox {
        center: vec![0.0; 3],
        half: vec![0.5; 3],
    };
    // the grouped Jacobian is the central differences entry for entry: the same steps, the
    // same witness to the bit
    let near = TwoRows([0.2, 0.1]);
    let gauged = reproduce_gauged(&b, &|x| near.all(x)).expect("a witness inside the box");
    let grouped = reproduce_grouped(&b, &near).expect("a witness inside the box");
    assert_eq!(gauged.point, grouped.point);
    assert!(gauged.residual <= 1.0 && gauged.shift_ratio <= 1.0);
    // targets out of the box's reach (x₀ + x₁ = 2 needs a shift of 2 half-widths) give none
    let far = TwoRows([2.0, 0.0]);
    assert!(reproduce_gauged(&b, &|x| far.all(x)).is_none());
    assert!(reproduce_grouped(&b, &far).is_none());
}
