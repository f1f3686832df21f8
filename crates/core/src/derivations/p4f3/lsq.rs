//! §4's least-squares form for p ≥ 4 points: the triangles through points 1 and 2 (linear
//! in the unknowns), solved by the normal equations without building the system.

use super::*;

/// Points the least-squares form takes: its p(p − 1)/2 unknowns make a dense normal matrix
/// of (p(p − 1)/2)² entries factorised in O(p⁶); 60 points are 1770 unknowns, a 25 MB matrix
/// and about 2·10⁹ operations (well under a second).
pub const MAX_LSQ_POINTS: usize = 60;

/// The triangles the least-squares form uses: every triangle through point 0 or point 1,
/// (p − 1)(p − 2)/2 + (p − 2)(p − 3)/2 of them, linear in the p(p − 1)/2 unknowns (every
/// triangle would be O(p³)). Every edge is in one at least; the edges from point 0 (and 1)
/// tie the triangles together as T's edges do in the paper's PQT, QRT, RPT.
pub fn lsq_triangles(p: usize) -> Vec<Triangle> {
    let mut t = Vec::new();
    for a in 0..p.min(2) {
        for i in a + 1..p {
            for j in i + 1..p {
                t.push([edge_index(a, i), edge_index(i, j), edge_index(j, a)]);
            }
        }
    }
    t
}

/// The least-squares solver for p ≥ 4 points in k ≥ 3 frames over the triangles of
/// [`lsq_triangles`] and every later frame: the normal equations, assembled row by row (each
/// row has three entries, no row is stored), solved by Cholesky; rank and condition from the
/// eigenvalues of AᵀA (σᵢ = √λᵢ). More than [`MAX_LSQ_POINTS`] points are refused.
pub fn solve_least_squares(input: &SquaredLengths) -> Result<SolverOutput> {
    let (p, k) = (input.names.len(), input.frames.len());
    if p < 4 || k < 3 {
        return Err(Error::InvalidInput(format!(
            "the least-squares form needs at least 4 points in 3 frames, got {p} points in {k} frames"
        )));
    }
    if p > MAX_LSQ_POINTS {
        return Err(Error::InvalidInput(format!(
            "{p} points: the least-squares form solves for every one of the p(p − 1)/2 squared edges and takes at most {MAX_LSQ_POINTS} points"
        )));
    }
    if let Some(d) = crate::derivations::degenerate::classify(input, 3) {
        return Ok(SolverOutput::degenerate("lsq", input, d));
    }
    let n = input.edges.len();
    let tris = lsq_triangles(p);
    let rows = tris.len() * (k - 1);
    let pick = |f: &[f64], t: &Triangle| FrameCoefficients::new([f[t[0]], f[t[1]], f[t[2]]]);
    let base: Vec<FrameCoefficients> = tris.iter().map(|t| pick(&input.frames[0], t)).collect();
    // every row (three coefficients, a constant, the triangle), computed when visited
    let each_row = |visit: &mut dyn FnMut(&[f64; 3], f64, &Triangle)| {
        for frame in &input.frames[1..] {
            for (t, b0) in tris.iter().zip(&base) {
                let (c, kc) = pick(frame, t).difference(b0);
                visit(&c, kc, t);
            }
        }
    };
    // AᵀA by rows of three entries: the upper triangle (column-major), then mirrored
    let mut upper = vec![0.0; n * n];
    let mut atb = DVector::<f64>::zeros(n);
    each_row(&mut |c, kc, tri| {
        for a in 0..3 {
            for b in 0..3 {
                let (i, j) = (tri[a], tri[b]);
                if i <= j {
                    upper[j * n + i] += c[a] * c[b];
                }
            }
            atb[tri[a]] += c[a] * kc;
        }
    });
    let ata = DMatrix::from_fn(n, n, |i, j| upper[i.max(j) * n + i.min(j)]);
    drop(upper);
    let (noise_m, noise_b) = noise(input, rows);
    let chol = ata.clone().cholesky();
    let rank = lsq_rank(&ata, chol.as_ref(), noise_m);
    let x = chol.map(|c| c.solve(&(-&atb)));
    // the residual row by row: the dense system is never built
    let residual = |x: &DVector<f64>| {
        let mut worst: f64 = 0.0;
        each_row(&mut |c, kc, t| {
            worst = worst.max((c[0] * x[t[0]] + c[1] * x[t[1]] + c[2] * x[t[2]] + kc).abs());
        });
        worst
    };
    let mut b2 = 0.0;
    each_row(&mut |_, kc, _| b2 += kc * kc);
    let (trace, smin) = (ata.trace(), rank.smin);
    let mut out = finish(input, "lsq", n, x, residual, rank, noise_m, noise_b);
    for s in &mut out.solutions {
        let xn = s.squared_edges.iter().map(|v| v * v).sum::<f64>().sqrt();
        if let Some(b) = &mut s.error_bound {
            *b += normal_equations_error(rows, n, trace, b2.sqrt(), xn, smin);
        }
    }
    Ok(out)
}

/// The forward error the normal equations add (Higham, Accuracy and Stability, §20.4): the
/// computed x solves (AᵀA + E)x = Aᵀb + f with ‖E‖ ≤ (γ_m + n γ_{n+1})‖A‖²_F (forming AᵀA
/// from m rows, then Cholesky) and ‖f‖ ≤ γ_m ‖A‖_F ‖b‖, so ‖Δx‖ ≤ (‖E‖‖x‖ + ‖f‖)/σ_min²:
/// the κ² the least-squares form pays for never building A.
fn normal_equations_error(m: usize, n: usize, trace: f64, b: f64, x: f64, smin: f64) -> f64 {
    let gamma = |k: usize| {
        let ku = k as f64 * f64::EPSILON / 2.0;
        ku / (1.0 - ku)
    };
    let e = (gamma(m) + n as f64 * gamma(n + 1)) * trace;
    let f = gamma(m) * trace.sqrt() * b;
    (e * x + f) / (smin * smin)
}

/// Rank and condition of A from AᵀA and its Cholesky factor, when there is one.
fn lsq_rank(
    ata: &DMatrix<f64>,
    chol: Option<&nalgebra::Cholesky<f64, nalgebra::Dyn>>,
    noise_m: f64,
) -> Rank {
    let n = ata.nrows();
    // σ below the noise of the matrix, or below what squaring into AᵀA can resolve
    let floor_for = |smax: f64| noise_m.max(smax * (n as f64 * f64::EPSILON).sqrt() * 8.0);
    match chol {
        // positive definite: the extreme singular values by Lanczos on AᵀA and on its
        // inverse (Cholesky solves), O(n²) per step instead of a full eigendecomposition
        Some(c) => {
            // 1e-10: the condition number is shown to six digits
            let lmax = largest_eigenvalue(|v| ata * v, n, 1e-10);
            let lmin = 1.0 / largest_eigenvalue(|v| c.solve(v), n, 1e-10);
            let (smax, smin) = (lmax.max(0.0).sqrt(), lmin.max(0.0).sqrt());
            let full = smin > floor_for(smax);
            Rank {
                rank: if full {
                    n
                } else {
                    rank_by_eigen(ata, &floor_for)
                },
                condition: full.then(|| smax / smin),
                smin,
            }
        }
        None => Rank {
            rank: rank_by_eigen(ata, &floor_for),
            condition: None,
            smin: 0.0,
        },
    }
}

/// The rank of AᵀA's square root by a full eigendecomposition (the rank-deficient path).
fn rank_by_eigen(ata: &DMatrix<f64>, floor_for: &dyn Fn(f64) -> f64) -> usize {
    let eig = SymmetricEigen::new(ata.clone());
    let sv: Vec<f64> = eig.eigenvalues.iter().map(|l| l.max(0.0).sqrt()).collect();
    let floor = floor_for(sv.iter().fold(0.0, |a: f64, b| a.max(*b)));
    sv.iter().filter(|s| **s > floor).count()
}
