//! §5: two frames. Two orthographic views of any number of points leave a one-parameter
//! family of bodies (the angle between the views about the axis orthogonal to both viewing
//! directions); the paper's counterexample; curves; and the fourth relation of four points.
//!
//! With the affine epipolar constraint a·x₁ + b·y₁ + c·x₂ + d·y₂ + e = 0 and the equal scale of
//! orthographic views, a² + b² = c² + d², both images turn into coordinates (x′, y′) with equal
//! y′. For every angle β ∈ (0, π) the depths Z = (x₂′ − cos β · x₁′)/sin β give a body that
//! projects exactly onto both images: the family.

use nalgebra::{Matrix3, Matrix4, Rotation3, SymmetricEigen, Vector2, Vector3};

pub use super::fourth_relation::{fourth_relation, FourthRelation, TRIANGLES};

/// The affine epipolar geometry of two orthographic views, from point correspondences.
#[derive(Clone, Copy, Debug, PartialEq, serde::Serialize)]
pub struct Epipolar {
    /// Whether the null space is one-dimensional (the epipolar geometry is determined).
    pub determined: bool,
    /// (a, b, c, d) of a·x₁ + b·y₁ + c·x₂ + d·y₂ + e = 0, unit length, for centred points.
    pub coefficients: [f64; 4],
    /// The eigenvalues of the centred design's Gram matrix, ascending: the first is the
    /// affine residual (zero for consistent data), a zero second means undetermined.
    pub eigenvalues: [f64; 4],
    /// (a² + b²) − (c² + d²): zero for two orthographic views of one rigid body.
    pub scale_residual: f64,
    /// √(smallest eigenvalue / largest): how far the points are from any affine epipolar
    /// geometry (zero whenever there are four points or fewer).
    pub affine_residual: f64,
}

fn centred(f: &[Vector2<f64>]) -> Vec<Vector2<f64>> {
    let c = f.iter().sum::<Vector2<f64>>() / f.len().max(1) as f64;
    f.iter().map(|p| p - c).collect()
}

/// The affine epipolar constraint of two frames of corresponding points: the least-squares
/// null vector of the centred rows (x₁, y₁, x₂, y₂), and the equal-scale residual.
///
/// # Example
/// ```
/// use orthocheck_core::derivations::two_frames::epipolar;
/// let t = orthocheck_core::model::Scene::random(4, 2, 7).tracks();
/// let e = epipolar(&t.frames[0], &t.frames[1]);
/// assert!(e.scale_residual.abs() < 1e-9);
/// ```
pub fn epipolar(f1: &[Vector2<f64>], f2: &[Vector2<f64>]) -> Epipolar {
    let size = centred(f1)
        .iter()
        .chain(&centred(f2))
        .map(|p| p.norm())
        .fold(f64::MIN_POSITIVE, f64::max);
    epipolar_with_rounding(
        f1,
        f2,
        crate::algebra::NEGLIGIBLE_ULPS * f64::EPSILON * size,
    )
}

/// [`epipolar`] for coordinates known to ±`rounding`. Eigenvalues up to 4n·rounding² (what
/// the rounding of n rows can leave in the null direction), or 64ε of the largest, count as
/// zero. A two-dimensional
/// null space (four or more points of a planar body, related by an affine map) leaves the
/// epipolar geometry undetermined: the vector kept is the one of that space closest to equal
/// scale, and the residual is the smallest |a² + b² − c² − d²| there.
pub fn epipolar_with_rounding(f1: &[Vector2<f64>], f2: &[Vector2<f64>], rounding: f64) -> Epipolar {
    let g = centred_gram(f1, f2);
    let eig = SymmetricEigen::new(g);
    let mut order = [0usize, 1, 2, 3];
    order.sort_by(|&i, &j| eig.eigenvalues[i].total_cmp(&eig.eigenvalues[j]));
    let eigenvalues = order.map(|i| eig.eigenvalues[i].max(0.0));
    let q = |v: &nalgebra::Vector4<f64>| (v[0] * v[0] + v[1] * v[1]) - (v[2] * v[2] + v[3] * v[3]);
    let v1: nalgebra::Vector4<f64> = eig.eigenvectors.column(order[0]).into();
    // what the data's rounding, or the floating-point eigensolver (64ε of the largest),
    // can leave in a null direction
    let zero = (4.0 * f1.len() as f64 * rounding * rounding)
        .max(crate::algebra::NEGLIGIBLE_ULPS * f64::EPSILON * eigenvalues[3]);
    let v = if eigenvalues[1] <= zero {
        let v2: nalgebra::Vector4<f64> = eig.eigenvectors.column(order[1]).into();
        equal_scale_in_span(&v1, &v2)[0]
    } else {
        v1
    };
    Epipolar {
        determined: eigenvalues[1] > zero,
        coefficients: [v[0], v[1], v[2], v[3]],
        eigenvalues,
        scale_residual: q(&v),
        affine_residual: (eigenvalues[0] / eigenvalues[3].max(f64::MIN_POSITIVE)).sqrt(),
    }
}

/// The Gram matrix of the centred rows (x₁, y₁, x₂, y₂) of two frames.
pub(crate) fn centred_gram(f1: &[Vector2<f64>], f2: &[Vector2<f64>]) -> Matrix4<f64> {
    let (c1, c2) = (centred(f1), centred(f2));
    let mut g = Matrix4::zeros();
    for (p, q) in c1.iter().zip(&c2) {
        let r = nalgebra::Vector4::new(p.x, p.y, q.x, q.y);
        g += r * r.transpose();
    }
    g
}

/// The unit vectors of span{v1, v2} (orthonormal) closest to equal scale: both zeros of
/// q = a² + b² − c² − d² there when q is indefinite on the span, else the one vector where
/// |q| is least. The first is the one [`epipolar`] keeps for an undetermined geometry.
pub fn equal_scale_in_span(
    v1: &nalgebra::Vector4<f64>,
    v2: &nalgebra::Vector4<f64>,
) -> Vec<nalgebra::Vector4<f64>> {
    let bil = |a: &nalgebra::Vector4<f64>, b: &nalgebra::Vector4<f64>| {
        a[0] * b[0] + a[1] * b[1] - a[2] * b[2] - a[3] * b[3]
    };
    let (q11, q12, q22) = (bil(v1, v1), bil(v1, v2), bil(v2, v2));
    // q on the span is the 2×2 form [q11 q12; q12 q22]: its eigenvector of smallest
    // modulus minimises |q| on the unit circle, and an indefinite form vanishes twice
    let e2 = nalgebra::Matrix2::new(q11, q12, q12, q22).symmetric_eigen();
    let (l0, l1) = (e2.eigenvalues[0], e2.eigenvalues[1]);
    let (w0, w1) = (
        e2.eigenvectors.column(0).into_owned(),
        e2.eigenvectors.column(1).into_owned(),
    );
    let within = |u: nalgebra::Vector2<f64>| v1 * u[0] + v2 * u[1];
    if l0 * l1 < 0.0 {
        // q = l0 x² + l1 y² = 0 at x/y = ±√(−l1/l0)
        let (x, y) = ((l1.abs()).sqrt(), (l0.abs()).sqrt());
        vec![
            within((w0 * x + w1 * y).normalize()),
            within((w0 * x - w1 * y).normalize()),
        ]
    } else if l0.abs() <= l1.abs() {
        vec![within(w0)]
    } else {
        vec![within(w1)]
    }
}

/// One member of the two-view family.
#[derive(Clone, Debug, PartialEq)]
pub struct Member {
    /// The angle between the two views about the common axis.
    pub beta: f64,
    /// The body in frame 1's camera coordinates (image x, y and a depth).
    pub points: Vec<Vector3<f64>>,
    /// The rotation from frame 1's camera coordinates to frame 2's.
    pub rotation: Rotation3<f64>,
    /// Largest reprojection error in either frame, relative to the image size.
    pub reprojection: f64,
    /// First-order bound on the reprojection error rounding alone can cause, relative to the
    /// image size (see [`family`]).
    pub error_bound: f64,
}

/// Members of the family of bodies that two frames of corresponding points allow, one per
/// angle in `betas` (each in (0, π)); `None` when the epipolar geometry is undetermined
/// (fewer than four points, or a planar body).
pub fn family(f1: &[Vector2<f64>], f2: &[Vector2<f64>], betas: &[f64]) -> Option<Vec<Member>> {
    let e = epipolar(f1, f2);
    // noisy views still give members; their reprojection error tells how well they fit
    if f1.len() < 4 || !e.determined {
        return None;
    }
    let [a, b, c, d] = e.coefficients;
    let (s1, s2) = ((a * a + b * b).sqrt(), (c * c + d * d).sqrt());
    // proper in-plane rotations taking each image to (x′, y′) with y′₁ = y′₂
    let q1 = Matrix3::new(b / s1, -a / s1, 0.0, a / s1, b / s1, 0.0, 0.0, 0.0, 1.0);
    let q2 = Matrix3::new(-d / s2, c / s2, 0.0, -c / s2, -d / s2, 0.0, 0.0, 0.0, 1.0);
    let (c1, c2) = (centred(f1), centred(f2));
    let size = c1
        .iter()
        .chain(&c2)
        .map(|p| p.norm())
        .fold(f64::MIN_POSITIVE, f64::max);
    let m1 = f1.iter().sum::<Vector2<f64>>() / f1.len() as f64;
    let m2 = f2.iter().sum::<Vector2<f64>>() / f2.len() as f64;
    // Rounding bound. With u = 64ε, the Gram matrix G of the centred rows carries an error
    // ‖δG‖ ≤ u·λ₃, so its null vector (a, b, c, d) moves by δv ≤ u·λ₃/(λ₁ − λ₀) (Davis–Kahan);
    // Q₁, Q₂ are built from it over √(a² + b²) = √(c² + d²) = 1/√2, so their angles move by at
    // most 2√2·δv each. A point's depth Z = (x₂′ − cos β·x₁′)/sin β, of size up to
    // 2·size/sin β, is then off by 2√2·δv·2·size/sin β, and the rotation Q₂ᵀR_y(β)Q₁ by 4√2·δv
    // applied to points of size up to (1 + 2/sin β)·size. Together, relative to the size, with
    // u for the arithmetic of each of the few steps:
    // (4√2·δv + 2u)·(1 + 2/sin β) + 2√2·δv·2/sin β ≤ (8√2·δv + 2u)·(1 + 2/sin β).
    let [l0, l1, _, l3] = e.eigenvalues;
    let u = crate::algebra::NEGLIGIBLE_ULPS * f64::EPSILON;
    let dv = u * l3 / (l1 - l0).max(f64::MIN_POSITIVE);
    Some(
        betas
            .iter()
            .map(|&beta| {
                let (sb, cb) = beta.sin_cos();
                let points: Vec<Vector3<f64>> = c1
                    .iter()
                    .zip(&c2)
                    .zip(f1)
                    .map(|((p, q), orig)| {
                        let x1 = (q1 * Vector3::new(p.x, p.y, 0.0)).x;
                        let x2 = (q2 * Vector3::new(q.x, q.y, 0.0)).x;
                        Vector3::new(orig.x, orig.y, (x2 - cb * x1) / sb)
                    })
                    .collect();
                // frame 2 = Q₂ᵀ · R_y(β) · Q₁ in camera coordinates
                let ry = Matrix3::new(cb, 0.0, sb, 0.0, 1.0, 0.0, -sb, 0.0, cb);
                let rotation = Rotation3::from_matrix_unchecked(q2.transpose() * ry * q1);
                let mut worst: f64 = 0.0;
                let centre = Vector3::new(m1.x, m1.y, 0.0);
                let shift = rotation * points.iter().map(|x| x - centre).sum::<Vector3<f64>>()
                    / points.len() as f64;
                for (x, q) in points.iter().zip(f2) {
                    let y = rotation * (x - centre) - shift;
                    worst = worst.max(
                        ((y.x + m2.x - q.x).powi(2) + (y.y + m2.y - q.y).powi(2)).sqrt() / size,
                    );
                }
                Member {
                    beta,
                    points,
                    rotation,
                    reprojection: worst,
                    error_bound: (8.0 * std::f64::consts::SQRT_2 * dv + 2.0 * u) * (1.0 + 2.0 / sb),
                }
            })
            .collect(),
    )
}

/// How different two bodies of corresponding points are: the largest change of a pairwise
/// distance, and the root-mean-square residual after the best rigid alignment (Kabsch),
/// both relative to the first body's diameter.
pub fn shape_difference(a: &[Vector3<f64>], b: &[Vector3<f64>]) -> (f64, f64) {
    let n = a.len();
    let mut diam: f64 = 0.0;
    let mut worst: f64 = 0.0;
    for i in 0..n {
        for j in i + 1..n {
            let (da, db) = ((a[i] - a[j]).norm(), (b[i] - b[j]).norm());
            diam = diam.max(da);
            worst = worst.max((da - db).abs());
        }
    }
    let ca = a.iter().sum::<Vector3<f64>>() / n as f64;
    let cb = b.iter().sum::<Vector3<f64>>() / n as f64;
    let h: Matrix3<f64> = a
        .iter()
        .zip(b)
        .map(|(x, y)| (y - cb) * (x - ca).transpose())
        .sum();
    let svd = h.svd(true, true);
    let rms = match (svd.u, svd.v_t) {
        (Some(u), Some(vt)) => {
            let dsign = (u * vt).determinant().signum();
            let r = u * Matrix3::from_diagonal(&Vector3::new(1.0, 1.0, dsign)) * vt;
            (a.iter()
                .zip(b)
                .map(|(x, y)| (r * (x - ca) - (y - cb)).norm_squared())
                .sum::<f64>()
                / n as f64)
                .sqrt()
        }
        _ => f64::NAN,
    };
    let d = diam.max(f64::MIN_POSITIVE);
    (worst / d, rms / d)
}

/// §5.1's counterexample rebuilt: two triangles PQR and PQ′R′ that differ only along the
/// first viewing direction, and second views of each that agree.
#[derive(Clone, Debug, PartialEq)]
pub struct Counterexample {
    /// Side lengths PQ, QR, RP of the first triangle.
    pub sides: [f64; 3],
    /// Side lengths PQ′, Q′R′, R′P of the second.
    pub sides_prime: [f64; 3],
    /// The first viewing direction (along which Q′ − Q and R′ − R lie), unit.
    pub u1: Vector3<f64>,
    /// The second view of PQR, unit, orthogonal to the axis.
    pub u2: Vector3<f64>,
    /// The second view of the primed triangle.
    pub u2_prime: Vector3<f64>,
    /// The axis of the paper's rotation.
    pub axis: Vector3<f64>,
    /// The rotation angle about n from u₂ to u₂′.
    pub angle: f64,
    /// Largest difference of a projected squared side between the two views 2, and of the
    /// views 1, relative to the largest squared side.
    pub image_mismatch: f64,
    /// Q′ and R′ rebuilt by the construction (q₁ ∩ q₂′, r₁ ∩ r₂′).
    pub rebuilt: [Vector3<f64>; 2],
}

/// Rebuild the construction of §5.1 from the printed P, Q, R, Q′, R′. The first view u₁
/// is along Q′ − Q. The construction's unknowns are the axis n ⟂ u₁ through P (angle φ), the
/// second view u₂ ⟂ n (angle ψ) and the rotation θ about n: Q′ must lie on the line through
/// P + rot(Q − P) along rot(u₂), and likewise R′. Two conditions on three unknowns: the
/// printed points fix the construction up to one parameter; minimum-norm Newton from a fixed
/// grid of starts finds a member. Then Q′, R′ are rebuilt as q₁ ∩ q₂′, r₁ ∩ r₂′, and the
/// two pairs of views are compared.
pub fn counterexample(pts: [Vector3<f64>; 5]) -> Option<Counterexample> {
    let [p, q, r, q2, r2] = pts;
    let c = Construction::new(pts)?;
    let sides = [(q - p).norm(), (r - q).norm(), (p - r).norm()];
    let sides_prime = [(q2 - p).norm(), (r2 - q2).norm(), (p - r2).norm()];
    let x = c.solve()?;
    let (axis, u2, rot) = c.setup(&x);
    let u2_prime = rot * u2;
    Some(Counterexample {
        sides,
        sides_prime,
        u1: c.u1,
        u2,
        u2_prime,
        axis,
        angle: x[2].sin().atan2(x[2].cos()),
        image_mismatch: c.image_mismatch(&u2, &u2_prime),
        rebuilt: [
            c.rebuild(&q, &rot, &u2_prime),
            c.rebuild(&r, &rot, &u2_prime),
        ],
    })
}

/// The construction of §5.1 over the printed points, as a function of its unknowns (φ, ψ, θ).
struct Construction {
    /// P, Q, R, Q′, R′.
    pts: [Vector3<f64>; 5],
    /// The first view, along Q′ − Q.
    u1: Vector3<f64>,
    /// With `eb`, an orthonormal basis of the plane orthogonal to u₁.
    ea: Vector3<f64>,
    /// u₁ × ea.
    eb: Vector3<f64>,
    /// The longest side of either triangle: residuals are relative to it.
    size: f64,
}

impl Construction {
    fn new(pts: [Vector3<f64>; 5]) -> Option<Self> {
        let [p, q, r, q2, r2] = pts;
        let u1 = (q2 - q).try_normalize(f64::EPSILON)?;
        let sides = [(q - p).norm(), (r - q).norm(), (p - r).norm()];
        let sides_prime = [(q2 - p).norm(), (r2 - q2).norm(), (p - r2).norm()];
        // an orthonormal basis of the plane orthogonal to u₁
        let ea = u1
            .cross(&Vector3::z())
            .try_normalize(1e-6)
            .unwrap_or_else(|| u1.cross(&Vector3::y()).normalize());
        let eb = u1.cross(&ea);
        let size = sides
            .iter()
            .chain(&sides_prime)
            .fold(f64::MIN_POSITIVE, |a, b| a.max(*b));
        Some(Self {
            pts,
            u1,
            ea,
            eb,
            size,
        })
    }

    /// The axis n (angle φ about u₁), the second view u₂ ⟂ n (angle ψ) and the rotation θ
    /// about n.
    fn setup(&self, x: &[f64]) -> (Vector3<f64>, Vector3<f64>, Rotation3<f64>) {
        let n = self.ea * x[0].cos() + self.eb * x[0].sin();
        let m = n.cross(&self.u1);
        let u2 = self.u1 * x[1].cos() + m * x[1].sin();
        let rot = Rotation3::from_axis_angle(&nalgebra::Unit::new_normalize(n), x[2]);
        (n, u2, rot)
    }

    /// Q′ and R′ off the lines through P + rot(X − P) along rot(u₂), relative to the size.
    fn residual(&self, x: &[f64]) -> Option<Vec<f64>> {
        let [p, q, r, q2, r2] = self.pts;
        let (_, u2, rot) = self.setup(x);
        let w = rot * u2;
        let mut out = Vec::with_capacity(6);
        for (orig, moved) in [(q, q2), (r, r2)] {
            let c = (moved - p - rot * (orig - p)).cross(&w) / self.size;
            out.extend([c.x, c.y, c.z]);
        }
        Some(out)
    }

    /// A member of the construction's family: minimum-norm Newton from a fixed grid of starts.
    fn solve(&self) -> Option<Vec<f64>> {
        let residual = |x: &[f64]| self.residual(x);
        for i in 0..6 {
            for j in 0..6 {
                for k in 0..12 {
                    let start = [
                        0.25 + 0.5 * i as f64,
                        0.2 + 0.5 * j as f64,
                        -3.0 + 0.5 * k as f64,
                    ];
                    let Some((x, res)) =
                        crate::algebra::min_norm_newton(&residual, &start, 1e-15, 50)
                    else {
                        continue;
                    };
                    let (_, u2, rot) = self.setup(&x);
                    // a genuine construction: a second view away from the first, a real rotation
                    if res <= 1e-15
                        && u2.cross(&self.u1).norm() > 0.1
                        && (rot * u2 - u2).norm() > 1e-3
                    {
                        return Some(x);
                    }
                }
            }
        }
        None
    }

    /// X′ = q₁ ∩ q₂′: X + s u₁ = P + rot(X − P) + t u₂′, least squares in (s, t).
    fn rebuild(
        &self,
        x: &Vector3<f64>,
        rot: &Rotation3<f64>,
        u2_prime: &Vector3<f64>,
    ) -> Vector3<f64> {
        let p = self.pts[0];
        let a = nalgebra::Matrix3x2::from_columns(&[self.u1, -u2_prime]);
        let b = p + rot * (x - p) - x;
        let st = (a.transpose() * a)
            .try_inverse()
            .map(|m| m * a.transpose() * b);
        st.map_or(*x, |st| x + self.u1 * st[0])
    }

    /// Largest difference of a projected squared side between the views 2 and between the
    /// views 1, relative to the largest squared side.
    fn image_mismatch(&self, u2: &Vector3<f64>, u2_prime: &Vector3<f64>) -> f64 {
        let [p, q, r, q2, r2] = self.pts;
        let u1 = self.u1;
        let e = [q - p, r - q, p - r];
        let e2 = [q2 - p, r2 - q2, p - r2];
        let proj = |d: &Vector3<f64>, u: &Vector3<f64>| d.norm_squared() - d.dot(u).powi(2);
        e.iter()
            .zip(&e2)
            .map(|(a, b)| {
                (proj(a, u2) - proj(b, u2_prime))
                    .abs()
                    .max((proj(a, &u1) - proj(b, &u1)).abs())
                    / (self.size * self.size)
            })
            .fold(0.0, f64::max)
    }
}

/// The orthographic image of `points` along the unit direction `u`, in a basis of the plane
/// orthogonal to it.
pub fn view(points: &[Vector3<f64>], u: &Vector3<f64>) -> Vec<[f64; 2]> {
    let e1 = u
        .cross(&Vector3::z())
        .try_normalize(1e-9)
        .unwrap_or_else(|| u.cross(&Vector3::x()).normalize());
    let e2 = u.cross(&e1);
    points.iter().map(|p| [p.dot(&e1), p.dot(&e2)]).collect()
}

/// `b` moved onto `a` by the proper plane rotation and translation that fit best (2-D
/// Procrustes): congruent images then coincide.
pub fn align(a: &[[f64; 2]], b: &[[f64; 2]]) -> Vec<[f64; 2]> {
    let n = a.len().max(1) as f64;
    let ca = a
        .iter()
        .fold([0.0, 0.0], |s, p| [s[0] + p[0] / n, s[1] + p[1] / n]);
    let cb = b
        .iter()
        .fold([0.0, 0.0], |s, p| [s[0] + p[0] / n, s[1] + p[1] / n]);
    // the angle maximising Σ (R(bᵢ − cb))·(aᵢ − ca)
    let (mut sc, mut ss) = (0.0, 0.0);
    for (p, q) in a.iter().zip(b) {
        let (x, y) = (p[0] - ca[0], p[1] - ca[1]);
        let (u, v) = (q[0] - cb[0], q[1] - cb[1]);
        sc += u * x + v * y;
        ss += u * y - v * x;
    }
    let t = ss.atan2(sc);
    let (st, ct) = t.sin_cos();
    b.iter()
        .map(|q| {
            let (u, v) = (q[0] - cb[0], q[1] - cb[1]);
            [ca[0] + ct * u - st * v, ca[1] + st * u + ct * v]
        })
        .collect()
}

/// A smooth closed 3-D curve (a trefoil knot, scaled), sampled at `n` points.
pub fn trefoil(n: usize) -> Vec<Vector3<f64>> {
    (0..n)
        .map(|i| {
            let t = std::f64::consts::TAU * i as f64 / n as f64;
            Vector3::new(
                t.sin() + 2.0 * (2.0 * t).sin(),
                t.cos() - 2.0 * (2.0 * t).cos(),
                -(3.0 * t).sin(),
            )
        })
        .collect()
}
