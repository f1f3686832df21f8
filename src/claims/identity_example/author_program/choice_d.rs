//! The program's choice of d (= c, the length of RT in program naming; the paper's "a priori
//! selected value for c"): the rules tried against the printed d of each assignment, and
//! the reason the choice cannot change a verdict (the distance does not depend on d).

use std::cell::RefCell;
use std::collections::HashMap;

use nalgebra::Vector2;

use super::program::replay;
use crate::derivations::identity::smallest_c;
use crate::derivations::rounding::first_order_bound;

/// A rule for d² tried against the printouts.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Rule {
    /// d² = the longest squared projection of RT (the text's minimum).
    Longest,
    /// d² = longest + 1 (T one unit deep in the frame with the longest projection).
    LongestPlusOne,
    /// d = longest projection + 0.1.
    LongestPlusTenth,
    /// d = 1.1 × longest projection.
    TenPercentLonger,
    /// d² = 2 × longest − shorter squared projection.
    TwiceLongestMinusShorter,
    /// d² = longest + shorter squared projection.
    LongestPlusShorter,
    /// d² = longest + the longest squared projection of QR.
    PlusLongestB,
    /// d² = longest + the longest squared projection of TQ.
    PlusLongestG,
    /// d² = longest + both.
    PlusLongestBAndG,
    /// d² = −f_b / f_cb.
    RatioFbFcb,
    /// d² = −f_c / (2 f_c²), the vertex of the constant term.
    VertexFc,
    /// d² = longest squared projection of QR / t, t the smaller asymptotic slope of b²/d².
    AsymptoteSmall,
    /// … the larger slope.
    AsymptoteLarge,
    /// d = the smallest admissible value (a and b at least their projections, Δ_b ≥ 0), on
    /// a grid of relative step 10⁻³.
    SmallestAdmissible,
    /// d² where b² of the − root is smallest (b² touching its longest projection), on a
    /// geometric grid of d² above the longest projection.
    MinimumBMinus,
    /// … of the + root.
    MinimumBPlus,
    /// d² where g² of the − root is smallest.
    MinimumGMinus,
    /// … of the + root.
    MinimumGPlus,
}

impl Rule {
    /// Every rule, in report order.
    pub const ALL: [Rule; 18] = [
        Rule::Longest,
        Rule::LongestPlusOne,
        Rule::LongestPlusTenth,
        Rule::TenPercentLonger,
        Rule::TwiceLongestMinusShorter,
        Rule::LongestPlusShorter,
        Rule::PlusLongestB,
        Rule::PlusLongestG,
        Rule::PlusLongestBAndG,
        Rule::RatioFbFcb,
        Rule::VertexFc,
        Rule::AsymptoteSmall,
        Rule::AsymptoteLarge,
        Rule::SmallestAdmissible,
        Rule::MinimumBMinus,
        Rule::MinimumBPlus,
        Rule::MinimumGMinus,
        Rule::MinimumGPlus,
    ];
}

/// Squared projections (g², b², d²) = (|TQ|², |QR|², |RT|²) of a frame in program order.
fn squares(f: &[Vector2<f64>; 4]) -> [f64; 3] {
    [
        (f[3] - f[1]).norm_squared(),
        (f[1] - f[2]).norm_squared(),
        (f[3] - f[2]).norm_squared(),
    ]
}

/// The Appendix A coefficients (f_b², f_cb, f_c², f_b, f_c, f_Cst) from the squared
/// projections (a², b², c²) of two frames, as the appendix prints them: with
/// A = 2(−a² + b² + c²), B = 2(a² − b² + c²), C = 2(a² + b² − c²), K the Heron term and
/// p, q, r the frame differences over A₁ − A₂. `None` when A₁ = A₂.
pub fn appendix_coefficients(s1: [f64; 3], s2: [f64; 3]) -> Option<[f64; 6]> {
    let abck = |[a, b, c]: [f64; 3]| {
        [
            2.0 * (-a + b + c),
            2.0 * (a - b + c),
            2.0 * (a + b - c),
            a * a + b * b + c * c - 2.0 * (a * b + a * c + b * c),
        ]
    };
    let ([a1, b1, c1, k1], [a2, b2, c2, k2]) = (abck(s1), abck(s2));
    let den = a1 - a2;
    if den == 0.0 {
        return None;
    }
    let (p, q, r) = ((b2 - b1) / den, (c2 - c1) / den, (k2 - k1) / den);
    Some([
        (1.0 - p).powi(2),
        2.0 * (p * q - p - q - 1.0),
        (1.0 - q).powi(2),
        p * a1 + b1 - 2.0 * r + 2.0 * r * p,
        q * a1 + c1 - 2.0 * r + 2.0 * r * q,
        r * r + r * a1 + k1,
    ])
}

/// The grid minima of frames (b² of the − and + roots, then g²), by the bits of their
/// coordinates: the four grid rules of one assignment, and of each rounding probe, share one
/// scan of the grid.
#[derive(Default)]
struct Minima(RefCell<HashMap<[u64; 16], Option<[f64; 4]>>>);

impl Minima {
    fn get(&self, f1: &[Vector2<f64>; 4], f2: &[Vector2<f64>; 4], lo: f64) -> Option<[f64; 4]> {
        let key = std::array::from_fn(|i| {
            let p = if i < 8 { f1[i / 2] } else { f2[(i - 8) / 2] };
            p[i % 2].to_bits()
        });
        *self
            .0
            .borrow_mut()
            .entry(key)
            .or_insert_with(|| minima(f1, f2, lo))
    }
}

/// The d² a rule gives for frames `f1`, `f2` (program order P, Q, R, T); `None` when it
/// does not exist (no real slope, no admissible d).
pub fn predict(rule: Rule, f1: &[Vector2<f64>; 4], f2: &[Vector2<f64>; 4]) -> Option<f64> {
    predict_with(rule, f1, f2, &Minima::default())
}

/// [`predict`], the grid rules' minima looked up in `memo`.
fn predict_with(
    rule: Rule,
    f1: &[Vector2<f64>; 4],
    f2: &[Vector2<f64>; 4],
    memo: &Minima,
) -> Option<f64> {
    let (s1, s2) = (squares(f1), squares(f2));
    let lo = s1[2].max(s2[2]);
    let hi = s1[2].min(s2[2]);
    let mb = s1[1].max(s2[1]);
    let mg = s1[0].max(s2[0]);
    let [fb2, fcb, fc2, fb, fc, _] = appendix_coefficients(s1, s2)?;
    let slopes = || {
        let disc = fcb * fcb - 4.0 * fb2 * fc2;
        (disc >= 0.0 && fb2 != 0.0).then(|| {
            let r = disc.sqrt();
            let (u, v) = ((-fcb - r) / (2.0 * fb2), (-fcb + r) / (2.0 * fb2));
            (u.min(v), u.max(v))
        })
    };
    let value = match rule {
        Rule::Longest => lo,
        Rule::LongestPlusOne => lo + 1.0,
        Rule::LongestPlusTenth => (lo.sqrt() + 0.1).powi(2),
        Rule::TenPercentLonger => 1.21 * lo,
        Rule::TwiceLongestMinusShorter => 2.0 * lo - hi,
        Rule::LongestPlusShorter => lo + hi,
        Rule::PlusLongestB => lo + mb,
        Rule::PlusLongestG => lo + mg,
        Rule::PlusLongestBAndG => lo + mb + mg,
        Rule::RatioFbFcb => -fb / fcb,
        Rule::VertexFc => -fc / (2.0 * fc2),
        Rule::AsymptoteSmall => mb / slopes()?.0,
        Rule::AsymptoteLarge => mb / slopes()?.1,
        Rule::SmallestAdmissible => {
            let a = |f: &[Vector2<f64>; 4]| [f[3], f[1], f[2], f[0]];
            smallest_c(&a(f1), &a(f2))?.powi(2)
        }
        Rule::MinimumBMinus => memo.get(f1, f2, lo)?[0],
        Rule::MinimumBPlus => memo.get(f1, f2, lo)?[1],
        Rule::MinimumGMinus => memo.get(f1, f2, lo)?[2],
        Rule::MinimumGPlus => memo.get(f1, f2, lo)?[3],
    };
    value.is_finite().then_some(value)
}

/// Grid points of d² = lo (1 + t), t from 10⁻⁶ to 100 geometrically.
const GRID: usize = 4000;

/// The grid's t = 10⁻⁶ e^(i ln 10⁸ / (GRID − 1)), i = 0 … GRID − 1, computed once (the
/// rules' fit evaluates it for every assignment and each of its rounding probes).
fn grid() -> &'static [f64] {
    static GRID_T: std::sync::OnceLock<Vec<f64>> = std::sync::OnceLock::new();
    GRID_T.get_or_init(|| {
        let step = (1e8_f64).ln() / (GRID - 1) as f64;
        (0..GRID).map(|i| 1e-6 * (step * i as f64).exp()).collect()
    })
}

/// The d² on the grid where b² of the − root, b² of the +, g² of the −, g² of the + is
/// smallest (each the first grid point of its least value); `None` where no grid point has
/// real roots.
fn minima(f1: &[Vector2<f64>; 4], f2: &[Vector2<f64>; 4], lo: f64) -> Option<[f64; 4]> {
    let a = |f: &[Vector2<f64>; 4]| [f[3], f[1], f[2], f[0]];
    let (a1, a2) = (a(f1), a(f2));
    let at = crate::derivations::identity::b_squared_in(&a1, &a2)?;
    let mut best: Option<[(f64, f64); 4]> = None;
    for t in grid() {
        let x = lo * (1.0 + t);
        let Some([(bm, gm), (bp, gp)]) = at(x) else {
            continue;
        };
        let values = [bm, bp, gm, gp];
        let b = best.get_or_insert(values.map(|v| (x, v)));
        for (m, v) in b.iter_mut().zip(values) {
            if m.1.total_cmp(&v).is_gt() {
                *m = (x, v);
            }
        }
    }
    best.map(|b| b.map(|m| m.0))
}

/// How far a rule misses over the assignments.
#[derive(Clone, Debug, PartialEq)]
pub struct RuleFit {
    /// The rule.
    pub rule: Rule,
    /// Assignments where it gives the printed d² within its tolerance.
    pub hits: usize,
    /// Assignments where it gives a value at all.
    pub defined: usize,
    /// The largest and the median |predicted − printed| / printed over those.
    pub worst: f64,
    /// The median.
    pub median: f64,
}

/// One assignment as the rules see it: frame 1 and frame 2 in program order, the printed
/// d² and its rounding.
pub type PrintedD = ([Vector2<f64>; 4], [Vector2<f64>; 4], f64, f64);

/// A rule's first-order bound over the frames' rounding (±`half` on every coordinate): 0
/// where a probe is undefined.
fn rounding_bound(
    rule: Rule,
    f1: &[Vector2<f64>; 4],
    f2: &[Vector2<f64>; 4],
    half: f64,
    memo: &Minima,
) -> f64 {
    let x: Vec<f64> = f1.iter().chain(f2).flat_map(|p| [p.x, p.y]).collect();
    let f = |v: &[f64]| {
        let g = |o: usize| std::array::from_fn(|i| Vector2::new(v[o + 2 * i], v[o + 2 * i + 1]));
        predict_with(rule, &g(0), &g(8), memo).map(|y| vec![y])
    };
    first_order_bound(&f, &x, &[half; 16]).map_or(0.0, |b| b[0])
}

/// Every rule against `printed`, the frames' coordinates rounded to ±`half`: a hit is a
/// prediction within the printed d²'s rounding plus the prediction's propagated bound.
pub fn fit_rules(printed: &[PrintedD], half: f64) -> Vec<RuleFit> {
    let memo = Minima::default();
    Rule::ALL
        .iter()
        .map(|&rule| {
            let mut rel = Vec::new();
            let mut hits = 0;
            for (f1, f2, d2, tol) in printed {
                if let Some(y) = predict_with(rule, f1, f2, &memo) {
                    // the bound is never NaN and at least 0: only a miss by the printed
                    // rounding alone needs it
                    let off = (y - d2).abs();
                    hits += usize::from(
                        off <= *tol || off <= *tol + rounding_bound(rule, f1, f2, half, &memo),
                    );
                    rel.push((y - d2).abs() / d2);
                }
            }
            rel.sort_by(f64::total_cmp);
            RuleFit {
                rule,
                hits,
                defined: rel.len(),
                worst: rel.last().copied().unwrap_or(f64::INFINITY),
                median: rel.get(rel.len() / 2).copied().unwrap_or(f64::INFINITY),
            }
        })
        .collect()
}

/// The program's distance of P₂ from its line at d0 × each of `factors`, as the largest
/// relative change from its value at d0 (`None` when b is not real at some d).
pub fn distance_spread(
    f1: &[Vector2<f64>; 4],
    f2: &[Vector2<f64>; 4],
    d0: f64,
    version: f64,
    factors: &[f64],
) -> Option<f64> {
    let base = replay(f1, f2, d0, version)?.distance;
    factors.iter().try_fold(0.0_f64, |m, k| {
        let d = replay(f1, f2, d0 * k, version)?.distance;
        Some(m.max((d - base).abs() / base.max(f64::MIN_POSITIVE)))
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn rules_are_scored_against_the_printed_value() {
        let f1 = [
            Vector2::new(1.0, 2.0),
            Vector2::new(2.0, 1.0),
            Vector2::zeros(),
            Vector2::new(3.0, 0.0),
        ];
        let f2 = [
            Vector2::new(1.5, 1.0),
            Vector2::new(2.5, 0.5),
            Vector2::zeros(),
            Vector2::new(2.0, 0.5),
        ];
        // the longest squared projection of RT is 9: the first rule hits, the second misses
        let fits = fit_rules(&[(f1, f2, 9.0, 0.01)], 0.0);
        assert_eq!(fits[0].hits, 1);
        assert_eq!(fits[1].hits, 0);
        assert!((fits[1].worst - 1.0 / 9.0).abs() < 1e-12);
    }
}
