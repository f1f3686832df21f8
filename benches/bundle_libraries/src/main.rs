//! orthocheck's bundle adjustment beside two Rust libraries on one seeded problem, from the
//! same Tomasi–Kanade start: tiny-solver (a sparse factor-graph solver, Levenberg–Marquardt
//! on a sparse Cholesky of JᵀJ, automatic derivatives) and levenberg-marquardt (rust-cv,
//! MINPACK's dense QR of the Jacobian). Prints each one's median wall time over a few runs
//! and its final cost ½ Σ ‖r‖², computed by one function for all three.
//!
//! Usage: `cargo run --release --manifest-path benches/bundle_libraries/Cargo.toml -- P K
//! [--repeat R] [--no-dense]`. Set RAYON_NUM_THREADS=1 to hold tiny-solver to one thread, as
//! orthocheck's adjustment is.

use std::collections::HashMap;
use std::time::Instant;

use nalgebra::{Matrix3, Vector2, Vector3};
use orthocheck_core::model::{rng, NoiseModel, Scene};
use orthocheck_core::sfm::{
    bundle_adjust, tomasi_kanade, BundleOptions, Observations, Reconstruction,
};
use tiny_solver::na as na34;
use tiny_solver::Optimizer as _;

/// The adjustment alone: the peers compute no standard errors.
fn loop_only() -> BundleOptions {
    BundleOptions {
        standard_errors: false,
        ..BundleOptions::default()
    }
}

/// One observation: frame, point, image.
type Obs = (usize, usize, Vector2<f64>);
/// A camera and point state: rotations, translations, points.
type Parts = (Vec<Matrix3<f64>>, Vec<Vector2<f64>>, Vec<Vector3<f64>>);

/// The problem: observations and the start, in one parametrisation for all three solvers:
/// per frame R = R₀ exp([w]×) (frame 1's w held at 0) and a translation, per point its
/// position.
struct Problem {
    obs: Vec<Obs>,
    start: Reconstruction,
}

/// R₀ exp([w]×) for any real field (Rodrigues; the series below 1e-8 rad², where the
/// derivative of √ would not be finite).
fn rotate<T: na34::RealField>(r0: &Matrix3<f64>, w: [T; 3]) -> na34::Matrix3<T> {
    let c = |v: f64| T::from_f64(v).unwrap();
    let [w0, w1, w2] = w;
    let t2 = w0.clone() * w0.clone() + w1.clone() * w1.clone() + w2.clone() * w2.clone();
    let k = na34::Matrix3::new(
        T::zero(),
        -w2.clone(),
        w1.clone(), //
        w2,
        T::zero(),
        -w0.clone(), //
        -w1,
        w0,
        T::zero(),
    );
    let k2 = &k * &k;
    let (a, b) = if t2 < c(1e-8) {
        (T::one() - t2.clone() / c(6.0), c(0.5) - t2 / c(24.0))
    } else {
        let t = t2.clone().sqrt();
        (t.clone().sin() / t.clone(), (T::one() - t.cos()) / t2)
    };
    let e = na34::Matrix3::identity() + k * a + k2 * b;
    let r = na34::Matrix3::from_fn(|i, j| c(r0[(i, j)]));
    r * e
}

/// The residual of one observation: rows(R) X + t − y.
fn residual<T: na34::RealField>(
    r0: &Matrix3<f64>,
    w: [T; 3],
    t: [T; 2],
    x: [T; 3],
    y: &Vector2<f64>,
) -> [T; 2] {
    let r = rotate(r0, w);
    let [x0, x1, x2] = x;
    let q = r.fixed_rows::<2>(0) * na34::Vector3::new(x0, x1, x2);
    let [t0, t1] = t;
    [
        q[0].clone() + t0 - T::from_f64(y.x).unwrap(),
        q[1].clone() + t1 - T::from_f64(y.y).unwrap(),
    ]
}

/// ½ Σ ‖r‖² at rotations `rots`, translations `trans`, points `pts`.
fn cost(obs: &[Obs], rots: &[Matrix3<f64>], trans: &[Vector2<f64>], pts: &[Vector3<f64>]) -> f64 {
    obs.iter()
        .map(|(f, j, y)| (rots[*f].fixed_rows::<2>(0) * pts[*j] + trans[*f] - y).norm_squared())
        .sum::<f64>()
        / 2.0
}

/// One observation's factor for tiny-solver: frame 1 has only its translation.
struct Factor {
    r0: Matrix3<f64>,
    y: Vector2<f64>,
    first: bool,
}

impl<T: na34::RealField> tiny_solver::factors::Factor<T> for Factor {
    fn residual_func(&self, params: &[na34::DVector<T>]) -> na34::DVector<T> {
        let (cam, x) = (&params[0], &params[1]);
        let g = |v: &na34::DVector<T>, i: usize| v[i].clone();
        let (w, t) = if self.first {
            ([T::zero(), T::zero(), T::zero()], [g(cam, 0), g(cam, 1)])
        } else {
            ([g(cam, 0), g(cam, 1), g(cam, 2)], [g(cam, 3), g(cam, 4)])
        };
        let r = residual(&self.r0, w, t, [g(x, 0), g(x, 1), g(x, 2)], &self.y);
        na34::DVector::from_vec(r.to_vec())
    }
}

fn tiny(p: &Problem) -> (f64, usize) {
    let mut problem = tiny_solver::Problem::new();
    let mut init = HashMap::new();
    for (f, fr) in p.start.frames.iter().enumerate() {
        let t = fr.translation;
        let v = if f == 0 {
            vec![t.x, t.y]
        } else {
            vec![0.0, 0.0, 0.0, t.x, t.y]
        };
        init.insert(format!("c{f}"), na34::DVector::from_vec(v));
    }
    for (j, x) in p.start.points.iter().enumerate() {
        init.insert(
            format!("x{j}"),
            na34::DVector::from_vec(vec![x.x, x.y, x.z]),
        );
    }
    for (f, j, y) in &p.obs {
        let factor = Factor {
            r0: p.start.frames[*f].rotation,
            y: *y,
            first: *f == 0,
        };
        problem.add_residual_block(
            2,
            &[&format!("c{f}"), &format!("x{j}")],
            Box::new(factor),
            None,
        );
    }
    let options = tiny_solver::OptimizerOptions {
        max_iteration: 100,
        ..Default::default()
    };
    let out = tiny_solver::LevenbergMarquardtOptimizer::default()
        .optimize(&problem, &init, Some(options))
        .expect("tiny-solver returns a solution");
    let k = p.start.frames.len();
    let mut rots = Vec::with_capacity(k);
    let mut trans = Vec::with_capacity(k);
    for (f, fr) in p.start.frames.iter().enumerate() {
        let c = &out[&format!("c{f}")];
        let (w, t) = if f == 0 {
            ([0.0; 3], [c[0], c[1]])
        } else {
            ([c[0], c[1], c[2]], [c[3], c[4]])
        };
        let r = rotate(&fr.rotation, w);
        rots.push(Matrix3::from_fn(|i, j| r[(i, j)]));
        trans.push(Vector2::new(t[0], t[1]));
    }
    let pts: Vec<Vector3<f64>> = (0..p.start.points.len())
        .map(|j| {
            let x = &out[&format!("x{j}")];
            Vector3::new(x[0], x[1], x[2])
        })
        .collect();
    (cost(&p.obs, &rots, &trans, &pts), 0)
}

/// The dense problem for levenberg-marquardt: parameters [w₂…w_k, t₁…t_k, X₁…X_p].
struct Dense<'a> {
    p: &'a Problem,
    x: na34::DVector<f64>,
}

impl Dense<'_> {
    fn parts(&self) -> Parts {
        let k = self.p.start.frames.len();
        let (w0, t0, x0) = (0, 3 * (k - 1), 3 * (k - 1) + 2 * k);
        let rots = (0..k)
            .map(|f| {
                let w = if f == 0 {
                    [0.0; 3]
                } else {
                    [
                        self.x[w0 + 3 * (f - 1)],
                        self.x[w0 + 3 * (f - 1) + 1],
                        self.x[w0 + 3 * (f - 1) + 2],
                    ]
                };
                let r = rotate(&self.p.start.frames[f].rotation, w);
                Matrix3::from_fn(|i, j| r[(i, j)])
            })
            .collect();
        let trans = (0..k)
            .map(|f| Vector2::new(self.x[t0 + 2 * f], self.x[t0 + 2 * f + 1]))
            .collect();
        let pts = (0..self.p.start.points.len())
            .map(|j| {
                Vector3::new(
                    self.x[x0 + 3 * j],
                    self.x[x0 + 3 * j + 1],
                    self.x[x0 + 3 * j + 2],
                )
            })
            .collect();
        (rots, trans, pts)
    }
}

impl levenberg_marquardt::LeastSquaresProblem<f64, na34::Dyn, na34::Dyn> for Dense<'_> {
    type ResidualStorage = na34::VecStorage<f64, na34::Dyn, na34::U1>;
    type JacobianStorage = na34::VecStorage<f64, na34::Dyn, na34::Dyn>;
    type ParameterStorage = na34::VecStorage<f64, na34::Dyn, na34::U1>;

    fn set_params(&mut self, x: &na34::DVector<f64>) {
        self.x.copy_from(x);
    }

    fn params(&self) -> na34::DVector<f64> {
        self.x.clone()
    }

    fn residuals(&self) -> Option<na34::DVector<f64>> {
        let (rots, trans, pts) = self.parts();
        let mut r = na34::DVector::zeros(2 * self.p.obs.len());
        for (i, (f, j, y)) in self.p.obs.iter().enumerate() {
            let e = rots[*f].fixed_rows::<2>(0) * pts[*j] + trans[*f] - y;
            r[2 * i] = e.x;
            r[2 * i + 1] = e.y;
        }
        Some(r)
    }

    fn jacobian(&self) -> Option<na34::DMatrix<f64>> {
        let k = self.p.start.frames.len();
        let (w0, t0, x0) = (0, 3 * (k - 1), 3 * (k - 1) + 2 * k);
        let (rots, _, pts) = self.parts();
        let mut jac = na34::DMatrix::zeros(2 * self.p.obs.len(), self.x.len());
        for (i, (f, j, _)) in self.p.obs.iter().enumerate() {
            let c = rots[*f].fixed_rows::<2>(0).into_owned();
            let x = pts[*j];
            // ∂/∂w of rows(R₀ exp([w]×)) X = −C [X]× J_r(w), J_r SO(3)'s right Jacobian
            let w = if *f == 0 {
                Vector3::zeros()
            } else {
                Vector3::new(
                    self.x[w0 + 3 * (f - 1)],
                    self.x[w0 + 3 * (f - 1) + 1],
                    self.x[w0 + 3 * (f - 1) + 2],
                )
            };
            let dw = -(c * x.cross_matrix()) * right_jacobian(&w);
            for row in 0..2 {
                if *f > 0 {
                    for col in 0..3 {
                        jac[(2 * i + row, w0 + 3 * (f - 1) + col)] = dw[(row, col)];
                    }
                }
                jac[(2 * i + row, t0 + 2 * f + row)] = 1.0;
                for col in 0..3 {
                    jac[(2 * i + row, x0 + 3 * j + col)] = c[(row, col)];
                }
            }
        }
        Some(jac)
    }
}

/// SO(3)'s right Jacobian: J_r(w) = I − (1 − cos θ)/θ² [w]× + (θ − sin θ)/θ³ [w]×².
fn right_jacobian(w: &Vector3<f64>) -> Matrix3<f64> {
    let t2 = w.norm_squared();
    let k = w.cross_matrix();
    let (a, b) = if t2 < 1e-8 {
        (0.5 - t2 / 24.0, 1.0 / 6.0 - t2 / 120.0)
    } else {
        let t = t2.sqrt();
        ((1.0 - t.cos()) / t2, (t - t.sin()) / (t2 * t))
    };
    Matrix3::identity() - k * a + k * k * b
}

fn dense(p: &Problem) -> (f64, usize) {
    let k = p.start.frames.len();
    let mut x = na34::DVector::zeros(3 * (k - 1) + 2 * k + 3 * p.start.points.len());
    for (f, fr) in p.start.frames.iter().enumerate() {
        x[3 * (k - 1) + 2 * f] = fr.translation.x;
        x[3 * (k - 1) + 2 * f + 1] = fr.translation.y;
    }
    for (j, pt) in p.start.points.iter().enumerate() {
        for c in 0..3 {
            x[3 * (k - 1) + 2 * k + 3 * j + c] = pt[c];
        }
    }
    let (done, report) = levenberg_marquardt::LevenbergMarquardt::new().minimize(Dense { p, x });
    let (rots, trans, pts) = done.parts();
    (
        cost(&p.obs, &rots, &trans, &pts),
        report.number_of_evaluations,
    )
}

fn ours(p: &Problem, obs: &Observations) -> (f64, usize) {
    let a = bundle_adjust(obs, &p.start, &loop_only()).expect("an adjustment");
    let r = &a.reconstruction;
    let rots: Vec<Matrix3<f64>> = r.frames.iter().map(|f| f.rotation).collect();
    let trans: Vec<Vector2<f64>> = r.frames.iter().map(|f| f.translation).collect();
    (cost(&p.obs, &rots, &trans, &r.points), a.report.iterations)
}

/// The median seconds of `runs` calls and the last call's answer.
fn timed(runs: usize, mut f: impl FnMut() -> (f64, usize)) -> (f64, f64, usize) {
    let mut secs = Vec::new();
    let mut last = (0.0, 0);
    for _ in 0..runs {
        let t = Instant::now();
        last = f();
        secs.push(t.elapsed().as_secs_f64());
    }
    secs.sort_by(f64::total_cmp);
    (secs[secs.len() / 2], last.0, last.1)
}

fn main() {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let num = |i: usize, d: usize| args.get(i).and_then(|a| a.parse().ok()).unwrap_or(d);
    let (np, nk) = (num(0, 250), num(1, 200));
    let repeat = args
        .iter()
        .position(|a| a == "--repeat")
        .map_or(3, |i| num(i + 1, 3));
    let clean = Scene::random(np, nk, 4).tracks();
    let noisy = NoiseModel::RelativeCoordinate { eps: 0.01 }.perturb_tracks(&clean, &mut rng(5));
    let start = tomasi_kanade(&noisy).expect("a generic scene");
    let obs = Observations::from_tracks(&noisy);
    let list: Vec<Obs> = obs.seen().collect();
    let p = Problem { obs: list, start };
    let rots: Vec<Matrix3<f64>> = p.start.frames.iter().map(|f| f.rotation).collect();
    let trans: Vec<Vector2<f64>> = p.start.frames.iter().map(|f| f.translation).collect();
    println!(
        "{np} points, {nk} frames, 1 % noise; start cost {:.10e}",
        cost(&p.obs, &rots, &trans, &p.start.points)
    );
    let (s, c, it) = timed(repeat, || ours(&p, &obs));
    println!("orthocheck bundle_adjust: {s:.3} s, cost {c:.10e}, {it} iterations");
    let (s, c, _) = timed(repeat, || tiny(&p));
    println!("tiny-solver LevenbergMarquardtOptimizer: {s:.3} s, cost {c:.10e}");
    if !args.iter().any(|a| a == "--no-dense") {
        let (s, c, ev) = timed(1, || dense(&p));
        println!("levenberg-marquardt (dense QR): {s:.3} s, cost {c:.10e}, {ev} evaluations");
    }
}
