//! §5.1's family member: the one the printed points P, Q, R, Q′, R′ are, and the one the
//! figures draw. In the frame of the printed points the frame-1 rays run along x (Q and Q′
//! differ only in x) and n along z through P; frame 2 looks along u = (cos φ, sin φ, 0), and
//! turning the frame-2 rays by θ about n makes Q′ = q₁ ∩ R_z(θ)q₂: R_z(−θ)Q′ − Q ∥ u.

use nalgebra::{Matrix2, Vector2, Vector3};

use crate::algebra::central_jacobian;

/// Scan points of θ over (−π, π) when looking for the member's angle.
const SCAN: usize = 3600;

/// Bisection steps (far below one ulp of an angle).
const BISECTIONS: usize = 80;

fn rot(t: f64) -> Matrix2<f64> {
    Matrix2::new(t.cos(), -t.sin(), t.sin(), t.cos())
}

fn cross(a: Vector2<f64>, b: Vector2<f64>) -> f64 {
    a.x * b.y - a.y * b.x
}

/// An angle modulo π, in [0, π).
fn mod_pi(a: f64) -> f64 {
    a.rem_euclid(std::f64::consts::PI)
}

/// The member of the printed points.
#[derive(Clone, Copy, Debug)]
pub struct Member {
    /// The turn about n, radians (the non-trivial root).
    pub theta: f64,
    /// Frame 2's viewing direction before the turn, radians modulo π.
    pub phi: f64,
    /// After the turn (φ + θ modulo π).
    pub phi_turned: f64,
    /// The frame-2 image abscissae X·(sin φ, −cos φ) of Q, R (at φ) and Q′, R′ (at φ′).
    pub abscissae: [f64; 4],
}

/// The non-trivial θ of `[Q, R, Q′, R′]` (P at the origin): the root of
/// (R(−θ)Q′ − Q) × (R(−θ)R′ − R) = 0 away from θ = 0 nearest to it.
fn theta_of(p: &[Vector3<f64>; 4]) -> Option<f64> {
    let xy = |v: &Vector3<f64>| Vector2::new(v.x, v.y);
    let f = |t: f64| {
        cross(
            rot(-t) * xy(&p[2]) - xy(&p[0]),
            rot(-t) * xy(&p[3]) - xy(&p[1]),
        )
    };
    let pi = std::f64::consts::PI;
    let grid = |k: usize| -pi + 2.0 * pi * k as f64 / SCAN as f64;
    let mut roots = Vec::new();
    for k in 0..SCAN {
        let (mut a, mut b) = (grid(k), grid(k + 1));
        let (mut fa, fb) = (f(a), f(b));
        if fa * fb > 0.0 {
            continue;
        }
        for _ in 0..BISECTIONS {
            let m = 0.5 * (a + b);
            let fm = f(m);
            if fa * fm <= 0.0 {
                b = m;
            } else {
                (a, fa) = (m, fm);
            }
        }
        roots.push(0.5 * (a + b));
    }
    // θ = 0 is always a root (the body itself); the member is the nearest other root
    let trivial = 2.0 * pi / SCAN as f64;
    roots
        .into_iter()
        .filter(|t| t.abs() > trivial)
        .min_by(|a, b| a.abs().total_cmp(&b.abs()))
}

/// The member of the printed `[Q, R, Q′, R′]` (P at the origin).
pub fn member(p: &[Vector3<f64>; 4]) -> Option<Member> {
    let theta = theta_of(p)?;
    let v = rot(-theta) * Vector2::new(p[2].x, p[2].y) - Vector2::new(p[0].x, p[0].y);
    let phi = mod_pi(v.y.atan2(v.x));
    let phi_turned = mod_pi(phi + theta);
    let s = |x: &Vector3<f64>, a: f64| x.x * a.sin() - x.y * a.cos();
    Some(Member {
        theta,
        phi,
        phi_turned,
        abscissae: [
            s(&p[0], phi),
            s(&p[1], phi),
            s(&p[2], phi_turned),
            s(&p[3], phi_turned),
        ],
    })
}

/// Σₖ |∂θ/∂cₖ| hₖ over the printed x and y of Q, R, Q′, R′ (`half` per point: x, y).
pub fn theta_bound(p: &[Vector3<f64>; 4], half: &[[f64; 2]; 4]) -> Option<f64> {
    let flat: Vec<f64> = p.iter().flat_map(|v| [v.x, v.y]).collect();
    let f = |c: &[f64]| {
        let q: [Vector3<f64>; 4] =
            std::array::from_fn(|k| Vector3::new(c[2 * k], c[2 * k + 1], 0.0));
        theta_of(&q).map(|t| vec![t])
    };
    let j = central_jacobian(&f, &flat, |k, _| 1e-3 * half[k / 2][k % 2].max(1e-9))?;
    Some(
        (0..flat.len())
            .map(|k| j[(0, k)].abs() * half[k / 2][k % 2])
            .sum(),
    )
}

/// Q′ₓ and R′ₓ rebuilt from Q and R by the member (φ, θ): the point of Q's frame-1 ray
/// (along x) on R_z(θ) of Q's frame-2 ray.
pub fn rebuild(q: &Vector3<f64>, r: &Vector3<f64>, phi: f64, theta: f64) -> [f64; 2] {
    let u = Vector2::new(phi.cos(), phi.sin());
    let one = |x: &Vector3<f64>| {
        let w = rot(theta) * u;
        let base = rot(theta) * Vector2::new(x.x, x.y);
        base.x + (x.y - base.y) / w.y * w.x
    };
    [one(q), one(r)]
}

/// One picture, in drawing units: the cube's hidden corner and the ends of its three thin
/// edges, the labels of P and two body points, n, one frame-1 ray, the frame-2 rays.
#[derive(Clone, Debug)]
pub struct Picture {
    /// Flat: corner (2), edge ends (6), labels (6), n (4), frame-1 ray (4), frame-2 rays (4 each).
    pub flat: Vec<f64>,
}

/// What a picture shows.
#[derive(Clone, Copy, Debug)]
pub struct DrawnReading {
    /// Which body the labels sit on (0: the first, 1: the second of those offered).
    pub body: usize,
    /// Label misfit against each body, relative to the drawing's scale.
    pub misfit: [f64; 2],
    /// The frame-2 rays' direction in the scene, radians modulo π (mean over the rays).
    pub phi: f64,
    /// Σₖ |∂φ/∂cₖ| · h: φ's change over the drawing's rounding (h per coordinate).
    pub phi_bound: f64,
    /// Angle between n and the cube's z edge, radians.
    pub n_tilt: f64,
}

fn at(v: &[f64], k: usize) -> Vector2<f64> {
    Vector2::new(v[2 * k], v[2 * k + 1])
}

fn unit_cos(a: Vector2<f64>, b: Vector2<f64>) -> f64 {
    (a.dot(&b) / (a.norm() * b.norm())).abs()
}

/// The cube's edges as the scene's x, y, z: x the edge along the frame-1 ray, z the one
/// along n, y the other (indices into the three edges).
fn axes(v: &[f64]) -> [usize; 3] {
    let e: Vec<Vector2<f64>> = (1..4).map(|k| at(v, k) - at(v, 0)).collect();
    let (ray, n) = (at(v, 10) - at(v, 9), at(v, 8) - at(v, 7));
    let best = |d: Vector2<f64>, skip: Option<usize>| {
        (0..3)
            .filter(|k| Some(*k) != skip)
            .max_by(|a, b| unit_cos(e[*a], d).total_cmp(&unit_cos(e[*b], d)))
            .unwrap_or(0)
    };
    let x = best(ray, None);
    let z = best(n, Some(x));
    [x, 3 - x - z, z]
}

/// The signed drawing map of scene x, y, z, for edge signs `s`.
fn map(v: &[f64], ax: [usize; 3], s: [f64; 3]) -> [Vector2<f64>; 3] {
    std::array::from_fn(|k| s[k] * (at(v, ax[k] + 1) - at(v, 0)))
}

/// Label misfit of `body` (P, and two points) under map `m`, the scale fitted.
fn label_misfit(v: &[f64], m: &[Vector2<f64>; 3], body: &[Vector3<f64>; 3]) -> f64 {
    let img = |x: &Vector3<f64>| m[0] * x.x + m[1] * x.y + m[2] * x.z;
    let (d, p): (Vec<Vector2<f64>>, Vec<Vector2<f64>>) = (1..3)
        .map(|k| (at(v, 4 + k) - at(v, 4), img(&(body[k] - body[0]))))
        .unzip();
    let s = d.iter().zip(&p).map(|(a, b)| a.dot(b)).sum::<f64>()
        / p.iter().map(|b| b.norm_squared()).sum::<f64>();
    let r: f64 = d
        .iter()
        .zip(&p)
        .map(|(a, b)| (a - b * s).norm_squared())
        .sum();
    r.sqrt() / d.iter().map(|a| a.norm()).sum::<f64>()
}

/// φ of the frame-2 rays under the fixed axes and signs.
fn phi_with(v: &[f64], ax: [usize; 3], s: [f64; 3]) -> Option<f64> {
    let m = map(v, ax, s);
    let inv = Matrix2::from_columns(&[m[0], m[1]]).try_inverse()?;
    let rays = (v.len() - 22) / 4;
    // mean of the doubled angles: directions are defined modulo π
    let (c, sn) = (0..rays).fold((0.0, 0.0), |(c, sn), k| {
        let w = inv * (at(v, 12 + 2 * k) - at(v, 11 + 2 * k));
        let a = 2.0 * w.y.atan2(w.x);
        (c + a.cos(), sn + a.sin())
    });
    Some(mod_pi(0.5 * sn.atan2(c)))
}

/// Read one picture against two candidate bodies (P, and two points each); `h` is half a
/// unit of the drawing's last digit.
pub fn read(pic: &Picture, bodies: &[[Vector3<f64>; 3]; 2], h: f64) -> Option<DrawnReading> {
    let v = &pic.flat;
    let ax = axes(v);
    let signs: Vec<[f64; 3]> = (0..8)
        .map(|k| std::array::from_fn(|i| if k >> i & 1 == 1 { -1.0 } else { 1.0 }))
        .collect();
    let best = |b: &[Vector3<f64>; 3]| {
        signs
            .iter()
            .map(|s| (label_misfit(v, &map(v, ax, *s), b), *s))
            .min_by(|a, c| a.0.total_cmp(&c.0))
    };
    let (m0, s0) = best(&bodies[0])?;
    let (m1, s1) = best(&bodies[1])?;
    let (body, s) = if m1 < m0 { (1, s1) } else { (0, s0) };
    let phi = phi_with(v, ax, s)?;
    let f = |c: &[f64]| phi_with(c, ax, s).map(|p| vec![p]);
    let j = central_jacobian(&f, v, |_, _| 1e-3 * h)?;
    let phi_bound = (0..v.len()).map(|k| j[(0, k)].abs() * h).sum();
    let (n, ez) = (at(v, 8) - at(v, 7), at(v, ax[2] + 1) - at(v, 0));
    Some(DrawnReading {
        body,
        misfit: [m0, m1],
        phi,
        phi_bound,
        n_tilt: unit_cos(n, ez).min(1.0).acos(),
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_member_is_found_and_rebuilds_its_points() {
        let (phi, theta) = (2.0_f64, -0.6_f64);
        let q = Vector3::new(3.0, 2.0, -1.0);
        let r = Vector3::new(0.5, 4.0, 3.0);
        let [qx, rx] = rebuild(&q, &r, phi, theta);
        let pts = [q, r, Vector3::new(qx, q.y, q.z), Vector3::new(rx, r.y, r.z)];
        let m = member(&pts).unwrap_or_else(|| unreachable!());
        assert!((m.theta - theta).abs() < 1e-9 && (m.phi - phi).abs() < 1e-9);
        assert!((m.abscissae[0] - m.abscissae[2]).abs() < 1e-9);
    }
}
