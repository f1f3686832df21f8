//! The author's program as its printouts pin it down. Program naming: the tested point P and
//! the triangle R, T, Q, each frame shifted so that R is at the origin; Appendix A's
//! (a, b, c) are the program's (g, b, d) = (|TQ|, |QR|, |RT|), so its P, Q, R are the
//! program's T, Q, R.
//!
//! The conventions, each fixed by the printouts (and judged against them in `check`):
//! - b² is the Appendix A root with the block's `version` as the sign of √Δ_b, g² follows
//!   from the frame difference;
//! - in both frames T's depth is +√(d² − |T|²) (flag 1) and Q's depth is s·√(b² − |Q|²), the
//!   flag s the sign that closes the triangle (|z_T − z_Q|² nearest g² − |T − Q|²);
//! - frame 1's basis e₁ = (T₁, z_T), e₂ = (Q₁, z_Q), e₃ = e₁ × e₂; PaK = (α, β, 0) with
//!   α T₁ + β Q₁ = P₁, PbK = (α′, β′, 1) with α′ T₁ + β′ Q₁ = P₁ − e₃.xy;
//! - frame 2's E₁, E₂, E₃ likewise with the signed depths: Pa.xy, Pb.xy are those
//!   combinations; the printed third coordinates use the *unsigned* depths |z_T|, |z_Q|
//!   (E₃.z = T₂ × Q₂ has none);
//! - `(Linie) L = R (diff L − R)` with L = (P2.y − Pa.y)(P2.x − Pb.x),
//!   R = (P2.x − Pa.x)(P2.y − Pb.y).

use nalgebra::{Matrix2, Vector2, Vector3};

use crate::algebra::NEGLIGIBLE_ULPS;
use crate::derivations::identity::b_squared;
use crate::derivations::rounding::first_order_bound;

/// How many numbers a block prints besides its flags and version, in print order: b, b0,
/// d, d0, T1 (2), Q1 (2), T2 (2), Q2 (2), PaK (3), PbK (3), Pa (3), Pb (3), P2 (2), P1 (2),
/// and the (Linie) L, R, diff.
pub const PRINTED: usize = 31;

/// Index of Pa.z among the printed numbers.
pub const PA_Z: usize = 20;
/// Index of Pb.z.
pub const PB_Z: usize = 23;
/// Index of P2.x.
pub const P2_X: usize = 24;
/// Index of the (Linie) left side L.
pub const LINE_L: usize = 28;
/// Index of the (Linie) right side R.
pub const LINE_R: usize = 29;
/// Index of the (Linie) difference.
pub const LINE_DIFF: usize = 30;

/// One block as the program computes it.
#[derive(Clone, Debug, PartialEq)]
pub struct ProgramBlock {
    /// The printed numbers, in print order (see [`PRINTED`]).
    pub values: [f64; PRINTED],
    /// The flags printed after T1, Q1, T2, Q2.
    pub flags: [i8; 4],
    /// Pa.z and Pb.z with the signed depths (the alternative the printouts reject).
    pub z_signed: [f64; 2],
    /// The factors of L and R: P2.y − Pa.y, P2.x − Pb.x, P2.x − Pa.x, P2.y − Pb.y.
    pub factors: [f64; 4],
    /// The distance of P2 from the line Pa Pb (what the text says is minimised).
    pub distance: f64,
    /// |Pb − Pa| in the image.
    pub segment: f64,
    /// |Pa.xy − P2|: zero for every c and b when P lies in the plane RTQ.
    pub pa_off: f64,
    /// Δ_b at the block's d.
    pub delta_b: f64,
}

/// The depths of T and Q in one frame and Q's flag (T's is always 1).
fn depths(d2: f64, b2: f64, g2: f64, t: Vector2<f64>, q: Vector2<f64>) -> (f64, f64, i8) {
    let zt = (d2 - t.norm_squared()).max(0.0).sqrt();
    let aq = (b2 - q.norm_squared()).max(0.0).sqrt();
    let gz2 = g2 - (t - q).norm_squared();
    let (plus, minus) = (
        ((zt - aq).powi(2) - gz2).abs(),
        ((zt + aq).powi(2) - gz2).abs(),
    );
    (zt, aq, if plus <= minus { 1 } else { -1 })
}

/// Points P, Q, T of one frame relative to R (program order P, Q, R, T in `f`).
fn relative(f: &[Vector2<f64>; 4]) -> [Vector2<f64>; 3] {
    [f[0] - f[2], f[1] - f[2], f[3] - f[2]]
}

/// The program on frames `f1`, `f2` (program order P, Q, R, T), at d = `d0` and the sign
/// `version` of √Δ_b. `None` when Δ_b < 0 at d0 or T₁, Q₁ are parallel.
pub fn replay(
    f1: &[Vector2<f64>; 4],
    f2: &[Vector2<f64>; 4],
    d0: f64,
    version: f64,
) -> Option<ProgramBlock> {
    let ([p1, q1, t1], [p2, q2, t2]) = (relative(f1), relative(f2));
    // Appendix A's P, Q, R, T are the program's T, Q, R, P
    let (a1, a2) = (
        [t1, q1, Vector2::zeros(), p1],
        [t2, q2, Vector2::zeros(), p2],
    );
    let d2 = d0 * d0;
    let delta_b = crate::derivations::identity::float_delta_b(&a1, &a2, d2);
    let roots = b_squared(&a1, &a2, d2)?;
    let (b2, g2) = roots[usize::from(version > 0.0)];
    let (zt1, aq1, s1) = depths(d2, b2, g2, t1, q1);
    let (zt2, aq2, s2) = depths(d2, b2, g2, t2, q2);
    let e1 = Vector3::new(t1.x, t1.y, zt1);
    let e2 = Vector3::new(q1.x, q1.y, f64::from(s1) * aq1);
    let e3 = e1.cross(&e2);
    let m = Matrix2::from_columns(&[t1, q1]).try_inverse()?;
    let ab = m * p1;
    let ab_b = m * (p1 - e3.xy());
    let (pak, pbk) = (
        Vector3::new(ab.x, ab.y, 0.0),
        Vector3::new(ab_b.x, ab_b.y, 1.0),
    );
    let big1 = Vector3::new(t2.x, t2.y, zt2);
    let big2 = Vector3::new(q2.x, q2.y, f64::from(s2) * aq2);
    let big3 = big1.cross(&big2);
    let map = |k: &Vector3<f64>| k.x * big1 + k.y * big2 + k.z * big3;
    let unsigned = |k: &Vector3<f64>| k.x * zt2 + k.y * aq2 + k.z * big3.z;
    let (pa, pb) = (map(&pak), map(&pbk));
    let factors = [p2.y - pa.y, p2.x - pb.x, p2.x - pa.x, p2.y - pb.y];
    let (l, r) = (factors[0] * factors[1], factors[2] * factors[3]);
    let values = [
        b2,
        b2.sqrt(),
        d2,
        d0,
        t1.x,
        t1.y,
        q1.x,
        q1.y,
        t2.x,
        t2.y,
        q2.x,
        q2.y,
        pak.x,
        pak.y,
        pak.z,
        pbk.x,
        pbk.y,
        pbk.z,
        pa.x,
        pa.y,
        unsigned(&pak),
        pb.x,
        pb.y,
        unsigned(&pbk),
        p2.x,
        p2.y,
        p1.x,
        p1.y,
        l,
        r,
        l - r,
    ];
    Some(ProgramBlock {
        values,
        flags: [1, s1, 1, s2],
        z_signed: [pa.z, pb.z],
        factors,
        distance: crate::model::point_line_distance(p2, pa.xy(), pb.xy()),
        segment: (pb.xy() - pa.xy()).norm(),
        pa_off: (pa.xy() - p2).norm(),
        delta_b,
    })
}

/// One block recomputed, with first-order bounds over the rounding of its inputs.
#[derive(Clone, Debug, PartialEq)]
pub struct Bounded {
    /// The block at the printed inputs.
    pub block: ProgramBlock,
    /// First-order bounds of the printed numbers over the frames' and d0's rounding.
    pub bounds: [f64; PRINTED],
    /// Bounds of the signed-depth alternatives of Pa.z, Pb.z.
    pub z_signed_bounds: [f64; 2],
    /// Bounds of the four factors of L and R.
    pub factor_bounds: [f64; 4],
    /// Bound of |Pa.xy − P2|.
    pub pa_off_bound: f64,
    /// Bound of |Pb − Pa|.
    pub segment_bound: f64,
    /// The floating-point error bound: 64ε × the largest magnitude in the block (a few
    /// dozen operations on numbers of that size).
    pub float_bound: f64,
    /// Whether a flag changes inside the rounding box's first-order probe (the bounds then
    /// straddle two branches of the program).
    pub flags_stable: bool,
}

fn unflat(x: &[f64]) -> ([Vector2<f64>; 4], [Vector2<f64>; 4]) {
    (
        std::array::from_fn(|i| Vector2::new(x[2 * i], x[2 * i + 1])),
        std::array::from_fn(|i| Vector2::new(x[8 + 2 * i], x[9 + 2 * i])),
    )
}

fn extras(b: &ProgramBlock) -> Vec<f64> {
    let mut v = b.values.to_vec();
    v.extend(b.z_signed);
    v.extend(b.factors);
    v.push(b.pa_off);
    v.push(b.segment);
    v.extend(b.flags.map(f64::from));
    v
}

/// [`replay`] with first-order bounds: every coordinate of both frames ±`coord_half`, d0 ±
/// `d0_half`.
pub fn run_bounded(
    f1: &[Vector2<f64>; 4],
    f2: &[Vector2<f64>; 4],
    d0: f64,
    d0_half: f64,
    version: f64,
    coord_half: f64,
) -> Option<Bounded> {
    let block = replay(f1, f2, d0, version)?;
    let mut x: Vec<f64> = f1.iter().chain(f2).flat_map(|p| [p.x, p.y]).collect();
    x.push(d0);
    let mut half = vec![coord_half; 16];
    half.push(d0_half);
    let f = |y: &[f64]| {
        let (g1, g2) = unflat(y);
        replay(&g1, &g2, y[16], version).map(|b| extras(&b))
    };
    let bound = first_order_bound(&f, &x, &half)?;
    let n = PRINTED;
    let magnitude = block.values.iter().fold(0.0_f64, |m, v| m.max(v.abs()));
    Some(Bounded {
        bounds: std::array::from_fn(|k| bound[k]),
        z_signed_bounds: [bound[n], bound[n + 1]],
        factor_bounds: std::array::from_fn(|k| bound[n + 2 + k]),
        pa_off_bound: bound[n + 6],
        segment_bound: bound[n + 7],
        flags_stable: bound[n + 8..].iter().all(|b| *b == 0.0),
        float_bound: NEGLIGIBLE_ULPS * f64::EPSILON * magnitude,
        block,
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::model::Scene;

    /// On an exact rigid scene at the true d, the program's Pa and Pb lie on P₂'s epipolar
    /// line for one version, and the printed identities hold.
    #[test]
    fn the_program_on_a_rigid_scene() {
        let s = Scene::random(4, 2, 7);
        let t = s.tracks();
        let f1: [Vector2<f64>; 4] = std::array::from_fn(|i| t.frames[0][i]);
        let f2: [Vector2<f64>; 4] = std::array::from_fn(|i| t.frames[1][i]);
        let x = &s.body.points;
        let d0 = (x[3] - x[2]).norm();
        let size = 4.0;
        let on: Vec<bool> = [-1.0, 1.0]
            .iter()
            .filter_map(|v| replay(&f1, &f2, d0, *v))
            .map(|b| {
                let v = &b.values;
                assert!((v[LINE_DIFF] - (v[LINE_L] - v[LINE_R])).abs() <= 1e-12 * size);
                assert!((v[LINE_DIFF].abs() - b.distance * b.segment).abs() <= 1e-9 * size);
                b.distance <= 1e-7 * size
            })
            .collect();
        assert_eq!(on.iter().filter(|o| **o).count(), 1);
    }
}
