//! A blocked Cholesky factorisation for the dense systems of bundle adjustment (5k × 5k for k
//! frames): left-looking by block columns, so that nearly all of its n³/3 multiply-adds run
//! in matrix products (nalgebra's, which call `matrixmultiply`), at several times the speed
//! of an unblocked factorisation once n is in the hundreds.

use nalgebra::DMatrix;

/// Columns of a block: the products it makes are large enough to run at speed, the
/// unblocked factorisation of a diagonal block small enough to cost little.
const BLOCK: usize = 64;

/// The lower Cholesky factor L (A = L Lᵀ) of a symmetric matrix whose lower triangle is `a`
/// (the strict upper triangle is never read, and is zero in the result); `None` when `a` is
/// not positive definite (to rounding) or not finite.
pub fn cholesky_lower(mut a: DMatrix<f64>) -> Option<DMatrix<f64>> {
    let n = a.nrows();
    if a.ncols() != n {
        return None;
    }
    if n <= BLOCK {
        // one block: the loop below would factor a copy and copy it back; this is the same
        // factor (nalgebra's, its upper triangle zero) without the copies
        let l = nalgebra::Cholesky::new(a)?.unpack();
        return l.iter().all(|v| v.is_finite()).then_some(l);
    }
    for j0 in (0..n).step_by(BLOCK) {
        let jb = BLOCK.min(n - j0);
        let m = n - j0;
        if j0 > 0 {
            // A[j0.., j0..j0+jb] −= L[j0.., ..j0] · L[j0..j0+jb, ..j0]ᵀ
            let (done, mut rest) = a.columns_range_pair_mut(..j0, j0..);
            let top = done.rows(j0, jb).transpose();
            rest.view_mut((j0, 0), (m, jb))
                .gemm(-1.0, &done.rows(j0, m), &top, 1.0);
        }
        let diag = a.view((j0, j0), (jb, jb)).into_owned();
        let l11 = nalgebra::Cholesky::new(diag)?.unpack();
        if m > jb {
            // L21 = A21 · L11⁻ᵀ, by a product with the small triangle's inverse (a
            // triangular solve column by column runs several times slower)
            let inv_t = l11
                .solve_lower_triangular(&DMatrix::identity(jb, jb))?
                .transpose();
            let a21 = a.view((j0 + jb, j0), (m - jb, jb)).into_owned();
            a.view_mut((j0 + jb, j0), (m - jb, jb))
                .gemm(1.0, &a21, &inv_t, 0.0);
        }
        a.view_mut((j0, j0), (jb, jb)).copy_from(&l11);
    }
    for j in 1..n {
        for i in 0..j {
            a[(i, j)] = 0.0;
        }
    }
    a.iter().all(|v| v.is_finite()).then_some(a)
}

/// The solution x of L Lᵀ x = b for the factor of [`cholesky_lower`].
pub fn cholesky_solve(
    l: &DMatrix<f64>,
    b: &nalgebra::DVector<f64>,
) -> Option<nalgebra::DVector<f64>> {
    let y = l.solve_lower_triangular(b)?;
    l.tr_solve_lower_triangular(&y)
}

/// The inverse of a symmetric positive definite matrix whose lower triangle is `a`: A⁻¹ =
/// L⁻ᵀ L⁻¹ from the blocked factor, the last product in one matrix product; `None` as
/// [`cholesky_lower`].
pub fn cholesky_inverse(a: DMatrix<f64>) -> Option<DMatrix<f64>> {
    let n = a.nrows();
    let l = cholesky_lower(a)?;
    let linv = l.solve_lower_triangular(&DMatrix::identity(n, n))?;
    // an explicit transpose: the product then runs in `matrixmultiply` (gemm_tr does not)
    let inv = linv.transpose() * &linv;
    inv.iter().all(|v| v.is_finite()).then_some(inv)
}
