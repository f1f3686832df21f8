//! §2.2's route with the paper's names, for any kind of number ([`Scalar`]): the projected
//! squares of each frame, the differences d of frames 1 and 2 against frame 3, and the affine
//! forms a² = A_c c² + A_Cst, b² = B_c c² + B_Cst. At the printed coordinates in `f64`, over
//! their rounding box in [`Interval`](crate::algebra::Interval)s (an outer bound).

use crate::algebra::enclosure::Scalar;

/// The quantities the paper names, at one set of projections.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Route<S> {
    /// (aᵢ², bᵢ², cᵢ²) per frame: PQ, QR, RP projected.
    pub projections: [[S; 3]; 3],
    /// (d_{a,k}, d_{b,k}, d_{c,k}, d_{Cst,k}) for k = 1, 2.
    pub d: [[S; 4]; 2],
    /// (A_c, A_Cst, B_c, B_Cst).
    pub affine: [S; 4],
}

/// The paper's names of [`Route::affine`], in order.
pub const AFFINE_NAMES: [&str; 4] = ["A_c", "A_Cst", "B_c", "B_Cst"];

/// The paper's names of [`Route::d`]'s columns, frame k's index left out.
pub const D_NAMES: [&str; 4] = ["d_a", "d_b", "d_c", "d_Cst"];

fn squared_distance<S: Scalar>(x: &[S], i: usize, j: usize) -> S {
    let (dx, dy) = (x[2 * j] - x[2 * i], x[2 * j + 1] - x[2 * i + 1]);
    dx * dx + dy * dy
}

/// faca, facb, facc and facCst of one frame: 2(−aᵢ² + bᵢ² + cᵢ²), …, and
/// aᵢ⁴ + bᵢ⁴ + cᵢ⁴ − 2aᵢ²bᵢ² − 2aᵢ²cᵢ² − 2bᵢ²cᵢ².
fn factors<S: Scalar>(l: [S; 3]) -> [S; 4] {
    let [a, b, c] = l;
    let two = S::constant(2.0);
    [
        two * (b + c - a),
        two * (a + c - b),
        two * (a + b - c),
        a * a + b * b + c * c - two * (a * b + a * c + b * c),
    ]
}

/// The route from three frames of (P, Q, R), each point (x, y): `x` holds 18 numbers, frame
/// by frame. `None` where d_{a,1} d_{b,2} − d_{a,2} d_{b,1} may vanish.
pub fn route<S: Scalar>(x: &[S; 18]) -> Option<Route<S>> {
    let projections: [[S; 3]; 3] = std::array::from_fn(|f| {
        let p = &x[6 * f..6 * f + 6];
        [
            squared_distance(p, 0, 1),
            squared_distance(p, 1, 2),
            squared_distance(p, 2, 0),
        ]
    });
    let fac = projections.map(factors);
    let d: [[S; 4]; 2] = std::array::from_fn(|k| std::array::from_fn(|j| fac[k][j] - fac[2][j]));
    let [[da1, db1, dc1, dk1], [da2, db2, dc2, dk2]] = d;
    let inv = (da1 * db2 - da2 * db1).recip()?;
    let affine = [
        (dc2 * db1 - dc1 * db2) * inv,
        (dk2 * db1 - dk1 * db2) * inv,
        (da2 * dc1 - da1 * dc2) * inv,
        (da2 * dk1 - da1 * dk2) * inv,
    ];
    Some(Route {
        projections,
        d,
        affine,
    })
}
