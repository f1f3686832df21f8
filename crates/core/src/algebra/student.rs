//! Student's t distribution with a whole number of degrees of freedom: its two-sided
//! probability in closed form (a finite trigonometric series), and its quantile by
//! bisection on it. The scale of a least-squares fit with ν residual degrees of freedom is
//! known to a factor that this distribution gives; the calibrated tolerances use it.

use std::f64::consts::FRAC_2_PI;

/// P(|T| ≤ t) for T with `nu` ≥ 1 degrees of freedom (Abramowitz & Stegun 26.7.3–4): with
/// θ = atan(t/√ν), for odd ν (2/π)(θ + sin θ (cos θ + 2/3 cos³θ + … + (2·4⋯(ν−3))/(1·3⋯(ν−2))
/// cos^(ν−2)θ)), for even ν sin θ (1 + 1/2 cos²θ + … + (1·3⋯(ν−3))/(2·4⋯(ν−2)) cos^(ν−2)θ).
pub fn two_sided(t: f64, nu: u32) -> f64 {
    if t <= 0.0 {
        return 0.0;
    }
    if t.is_infinite() {
        return 1.0;
    }
    let theta = (t / f64::from(nu.max(1)).sqrt()).atan();
    let (s, c) = theta.sin_cos();
    let odd = nu % 2 == 1;
    // the series' terms: the first is cos θ (odd) or 1 (even), each next one times
    // cos²θ · k/(k+1) with k = 2, 4, … (odd) or 1, 3, … (even)
    let (mut term, mut k) = if odd { (c, 2.0) } else { (1.0, 1.0) };
    let mut sum = 0.0;
    let last = nu.saturating_sub(2);
    let mut power = u32::from(odd);
    while power <= last {
        sum += term;
        term *= c * c * k / (k + 1.0);
        k += 2.0;
        power += 2;
    }
    let p = if odd {
        FRAC_2_PI * (theta + s * sum)
    } else {
        s * sum
    };
    p.clamp(0.0, 1.0)
}

/// The t with P(|T| ≤ t) = `p` for `nu` degrees of freedom (0 < p < 1), by bisection to the
/// last bit.
pub fn two_sided_quantile(p: f64, nu: u32) -> f64 {
    let (mut lo, mut hi) = (0.0f64, 1.0f64);
    while two_sided(hi, nu) < p && hi < 1e300 {
        hi *= 2.0;
    }
    for _ in 0..200 {
        let mid = 0.5 * (lo + hi);
        if mid <= lo || mid >= hi {
            break;
        }
        if two_sided(mid, nu) < p {
            lo = mid;
        } else {
            hi = mid;
        }
    }
    hi
}
