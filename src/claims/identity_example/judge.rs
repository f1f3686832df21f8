//! Claims of §5.2's example: the point order behind the printed frames, the hidden table,
//! the two "correct" attempts, every number of the debug printouts, the error lines and the
//! figure panels. The computation lives in `author_program`, `panels` and
//! `study`; here each result is judged.

use nalgebra::Vector2;
use num_rational::BigRational;

use crate::algebra::{exact_rank, permutations4};
use crate::cases::Printed;
use crate::check::{ClaimResult, Power, ResultBuilder, Tolerance, ToleranceSource, Value, Verdict};
use crate::claims::identity_example::author_program::{matching_assignments, Example, Num};
use crate::claims::identity_example::{DebugAttempt, IdentityExampleCase};
use crate::derivations::p4f3::{edge_index, realize};
use crate::error::{Error, Result};

mod blocks;
mod choice;
mod correct;
mod debug;
mod panels;
mod program;

/// A printed number for the studies. `%g` prints an exact zero as "0" (anything else shows
/// its digits), so a printed zero has no rounding; other numbers carry half a unit in the
/// `digits`-th significant digit.
fn printed_num(p: &Printed, digits: u32) -> Num {
    let half = if num_traits::Zero::is_zero(&p.value) {
        0.0
    } else {
        p.half_unit_significant(digits)
    };
    Num {
        value: p.to_f64(),
        half,
    }
}

/// A printed number with fixed decimals (the frames, the panels).
fn num_f(p: &Printed) -> Num {
    Num {
        value: p.to_f64(),
        half: p.half_unit(),
    }
}

fn pair(p: &[Printed; 2]) -> Vector2<f64> {
    Vector2::new(p[0].to_f64(), p[1].to_f64())
}

fn example(case: &IdentityExampleCase) -> Result<Example> {
    let f = &case.frames;
    let four = |v: &[[Printed; 2]]| -> [Vector2<f64>; 4] { std::array::from_fn(|i| pair(&v[i])) };
    let exact = |v: &[[Printed; 2]]| -> [[BigRational; 2]; 4] {
        std::array::from_fn(|i| [v[i][0].value.clone(), v[i][1].value.clone()])
    };
    let names = &case.table.point_names;
    let mut paper_of_program = [0; 4];
    for (j, n) in case.debug.program_order.iter().enumerate() {
        paper_of_program[j] = names.iter().position(|m| m == n).ok_or_else(|| {
            Error::InvalidInput(format!(
                "program order names '{n}', not one of the table's points"
            ))
        })?;
    }
    Ok(Example {
        frame1: four(&f.frame1),
        frame2: four(&f.frame2),
        exact: [exact(&f.frame1), exact(&f.frame2)],
        coord_half: f.frame1[0][0].half_unit(),
        paper_of_program,
    })
}

/// The assignment of a printed block: its T₂, Q₂, P₂ matched against frame 2 re-centred.
fn block_assignments(ex: &Example, a: &DebugAttempt, digits: u32) -> Vec<[usize; 4]> {
    let g = |p: &[Printed; 2]| [printed_num(&p[0], digits), printed_num(&p[1], digits)];
    matching_assignments(ex, &[g(&a.t2), g(&a.q2), g(&a.p2)])
}

pub(super) fn results(b: &ResultBuilder, case: &IdentityExampleCase) -> Result<Vec<ClaimResult>> {
    let ex = example(case)?;
    let fit = names_fit(case, &ex);
    let mut out = vec![frames_result(b, case, &fit), labels_result(b, case, &fit)];
    out.push(table_result(b, case, &fit));
    let blocks = blocks::blocks(case, &ex, &fit.perm);
    // in the report's order: the numbers, the program, the rule for d, the error lines
    out.extend(debug::number_results(b, case, &ex, &fit.perm, &blocks));
    out.extend(program::results(b, case, &blocks));
    out.push(choice::result(b, case, &ex, &fit.perm, &blocks));
    out.extend(debug::error_results(b, case, &ex, &fit.perm, &blocks));
    out.extend(correct::results(b, case, &ex, &fit.perm, &blocks));
    out.extend(panels::results(b, case, &ex, &fit.perm, &blocks));
    Ok(out)
}

/// Which listed point is which, by the table's projected distances.
struct NamesFit {
    /// perm[k] = the listed index of the table's k-th point name.
    perm: [usize; 4],
    /// Columns matched in both frames for `perm`, and the best of any other order.
    matched: usize,
    runner_up: usize,
    /// For a column whose letter is none of the names: the name it turns out to be.
    resolved: Vec<(usize, usize, usize)>,
}

/// A table column matches two listed points when both frames' distances agree: the printed
/// distance is the program's value to `digits` significant digits, ours moves by at most
/// 2√2 × the coordinates' half unit (two points, each off by √2 × half).
fn column_matches(
    ex: &Example,
    i: usize,
    j: usize,
    p1: &Printed,
    p2: &Printed,
    digits: u32,
) -> bool {
    let tol = |p: &Printed| {
        p.half_unit_significant(digits) + 2.0 * std::f64::consts::SQRT_2 * ex.coord_half
    };
    ((ex.frame1[i] - ex.frame1[j]).norm() - p1.to_f64()).abs() <= tol(p1)
        && ((ex.frame2[i] - ex.frame2[j]).norm() - p2.to_f64()).abs() <= tol(p2)
}

fn names_fit(case: &IdentityExampleCase, ex: &Example) -> NamesFit {
    let t = &case.table;
    let name = |c: char| t.point_names.iter().position(|n| n.starts_with(c));
    let fits = |perm: &[usize; 4]| {
        let mut resolved = Vec::new();
        let mut ok = 0;
        for (col, head) in t.columns.iter().enumerate() {
            let ch: Vec<Option<usize>> = head.chars().map(name).collect();
            let pairs: Vec<(usize, usize)> = match (ch[0], ch[1]) {
                (Some(x), Some(y)) => vec![(x, y)],
                (Some(x), None) | (None, Some(x)) => {
                    (0..4).filter(|y| *y != x).map(|y| (x, y)).collect()
                }
                (None, None) => vec![],
            };
            let hit = pairs.iter().find(|(x, y)| {
                column_matches(
                    ex,
                    perm[*x],
                    perm[*y],
                    &t.projected1[col],
                    &t.projected2[col],
                    t.significant_digits,
                )
            });
            if let Some(&(x, y)) = hit {
                ok += 1;
                if pairs.len() > 1 {
                    resolved.push((col, x, y));
                }
            }
        }
        (ok, resolved)
    };
    type Fit = ([usize; 4], usize, Vec<(usize, usize, usize)>);
    let mut all: Vec<Fit> = permutations4()
        .into_iter()
        .map(|p| {
            let (ok, r) = fits(&p);
            (p, ok, r)
        })
        .collect();
    all.sort_by_key(|a| std::cmp::Reverse(a.1));
    let runner_up = all.get(1).map_or(0, |x| x.1);
    let (perm, matched, resolved) = all.swap_remove(0);
    NamesFit {
        perm,
        matched,
        runner_up,
        resolved,
    }
}

/// Reproduced when one order matches every column and no other order does.
fn judge_names(matched: usize, runner_up: usize, columns: usize) -> Verdict {
    Verdict::holds(matched == columns && runner_up < columns)
}

fn frames_result(b: &ResultBuilder, case: &IdentityExampleCase, fit: &NamesFit) -> ClaimResult {
    let t = &case.table;
    let n = t.columns.len();
    let order: Vec<usize> = (0..4)
        .filter_map(|i| fit.perm.iter().position(|p| *p == i))
        .collect();
    let mut c = b
        .claim(&case.frames.claim)
        .printed("listed points", Value::count(case.frames.frame1.len()))
        .computed("table names of the listed points", Value::label(order.iter().map(|k| t.point_names[*k].as_str()).collect::<Vec<_>>().join(", ")))
        .computed("columns matched in both frames", Value::count_of(fit.matched, n))
        .computed("best other order matches", Value::count_of(fit.runner_up, n))
        .tolerance(Tolerance::bound(2.0 * std::f64::consts::SQRT_2 * case.frames.frame1[0][0].half_unit(), ToleranceSource::PrintedPrecision, "half a unit in the table's sixth significant digit plus 2√2 × the coordinates' half unit"))
        .power(Power::mutant(fit.runner_up < n, "every other assignment of the names to the listed points, run through the same column test"))
        .method("every assignment of the table's names to the listed points against the projected distances of both frames");
    for (col, x, y) in &fit.resolved {
        c = c.detail(
            &format!("column {} is", t.columns[*col]),
            Value::label(crate::derivations::solver::edge_name(
                &t.point_names[*x],
                &t.point_names[*y],
            )),
        );
    }
    c.verdict(judge_names(fit.matched, fit.runner_up, n))
}

fn labels_result(b: &ResultBuilder, case: &IdentityExampleCase, fit: &NamesFit) -> ClaimResult {
    let t = &case.table;
    // the paper's name of listed point i: the program's name (the table's), then the paper's
    let paper_name = |i: usize| {
        let j = fit.perm.iter().position(|p| *p == i).unwrap_or(0);
        case.debug.program_order[j].clone()
    };
    let program: Vec<String> = (0..4)
        .map(|i| t.point_names[fit.perm.iter().position(|p| *p == i).unwrap_or(0)].clone())
        .collect();
    let paper: Vec<String> = (0..4).map(paper_name).collect();
    let agree = paper == case.frames.figure_labels;
    b.claim(&case.frames.claim)
        .suffix("labels")
        .printed("figure labels of #1 … #4", Value::label(case.frames.figure_labels.join(", ")))
        .computed("paper's names of the listed points", Value::label(paper.join(", ")))
        .computed("the hidden table's names of them", Value::label(program.join(", ")))
        .tolerance(Tolerance::exact("names compared as names"))
        .power(Power::exact_value("only the paper's names in the data's order pass; any other labelling is an erratum"))
        .method("the labels of \\DreieckUndPunkt against the names the data decide: the table's (the program's, which tests its P) mapped to the paper's (which tests T)")
        .verdict(if agree { Verdict::Reproduced } else { Verdict::Erratum })
}

/// Squares in the paper's edge order (PQ, QR, RP, TP, TQ, TR) from the table's columns, the
/// letters as the names fit resolved them.
fn squares(case: &IdentityExampleCase, fit: &NamesFit) -> Vec<(usize, usize)> {
    let t = &case.table;
    let name = |c: char| t.point_names.iter().position(|n| n.starts_with(c));
    t.columns
        .iter()
        .enumerate()
        .filter_map(|(col, head)| {
            if let Some((_, x, y)) = fit.resolved.iter().find(|r| r.0 == col) {
                return Some((col, edge_index(*x, *y)));
            }
            let ch: Vec<Option<usize>> = head.chars().map(name).collect();
            Some((col, edge_index(ch[0]?, ch[1]?)))
        })
        .collect()
}

/// A length agrees with its square when |r² − s| ≤ 2r·h_r + h_s (h: half units).
fn length_matches_square(r: f64, hr: f64, s: f64, hs: f64) -> bool {
    (r * r - s).abs() <= 2.0 * r * hr + hs
}

fn table_result(b: &ResultBuilder, case: &IdentityExampleCase, fit: &NamesFit) -> ClaimResult {
    let t = &case.table;
    let d = t.significant_digits;
    let check = |real: &[f64]| {
        (0..t.columns.len()).all(|k| {
            length_matches_square(
                real[k],
                t.real[k].half_unit_significant(d),
                t.squared[k].to_f64(),
                t.squared[k].half_unit_significant(d),
            )
        })
    };
    let real: Vec<f64> = t.real.iter().map(Printed::to_f64).collect();
    let same = t.real == t.real2;
    // the mutant: each length moved by the mutant's half units must fail the square test
    let k = case.debug.mutant_half_units;
    let rejected = (0..real.len()).all(|i| {
        let mut m = real.clone();
        m[i] += k * t.real[i].half_unit_significant(d);
        !check(&m)
    });
    let (mut sq, mut exact) = ([0.0; 6], vec![BigRational::from_integer(0.into()); 6]);
    for (col, e) in squares(case, fit) {
        sq[e] = t.squared[col].to_f64();
        exact[e] = t.squared[col].value.clone();
    }
    let half = BigRational::new(1.into(), 2.into());
    let s = |a: usize, c: usize| {
        if a == c {
            BigRational::from_integer(0.into())
        } else {
            exact[edge_index(a, c)].clone()
        }
    };
    let gram: Vec<Vec<BigRational>> = (1..4)
        .map(|i| {
            (1..4)
                .map(|j| (s(0, i) + s(0, j) - s(i, j)) * &half)
                .collect()
        })
        .collect();
    let (rank, _) = exact_rank(&gram);
    let (points, height2) = placed(&gram);
    let mut r = b.claim(&t.claim);
    for (name, p) in ["Q", "R", "T"].iter().zip(&points) {
        r = r.computed_cell(
            name,
            "placed from the printed squares (P at the origin, Q on the x axis, R in the xy plane)",
            Value::reals(p),
        );
    }
    r.computed("T's squared height above the plane PQR (exact: det G over its leading 2×2 minor)", Value::exact(&height2))
        .printed("columns", Value::count(t.columns.len()))
        .computed("real = real2", Value::flag(same))
        .computed("every length squared is its square", Value::flag(check(&real)))
        .computed("exact rank of the Gram matrix of the squares", Value::count(rank))
        .computed("Gram eigenvalues", Value::reals(&realize(&sq, 4).eigenvalues))
        .tolerance(Tolerance::bound(0.0, ToleranceSource::PrintedPrecision, "|r² − s| ≤ 2r·h_r + h_s, h the half units of the sixth significant digit"))
        .power(Power::mutant(rejected, "each printed length moved by the mutant's half units fails the same square test"))
        .method("lengths against squares; exact rank over ℚ of the Gram matrix of the edges from P (rank 2: the four points are coplanar, not a generic body); the projected rows are the frames' distances (ex5-frames)")
        .verdict(Verdict::holds(same && check(&real)))
}

/// The points of a body from the Gram matrix `g` of its edges from P (3×3, exact): Q on the
/// x axis, R in the xy plane, T above it, and T's squared height, exact (the Schur
/// complement det G / det G₂, zero for a planar body).
fn placed(g: &[Vec<BigRational>]) -> ([[f64; 3]; 3], BigRational) {
    use num_traits::{ToPrimitive, Zero};
    let f = |x: &BigRational| x.to_f64().unwrap_or(f64::NAN);
    let minor = |r: [usize; 2], c: [usize; 2]| {
        &g[r[0]][c[0]] * &g[r[1]][c[1]] - &g[r[0]][c[1]] * &g[r[1]][c[0]]
    };
    let det2 = minor([0, 1], [0, 1]);
    let det3 = &g[0][0] * minor([1, 2], [1, 2]) - &g[0][1] * minor([1, 2], [0, 2])
        + &g[0][2] * minor([1, 2], [0, 1]);
    let height2 = if det2.is_zero() {
        det2.clone()
    } else {
        &det3 / &det2
    };
    let xq = f(&g[0][0]).sqrt();
    let (xr, xt) = (f(&g[0][1]) / xq, f(&g[0][2]) / xq);
    let yr = (f(&det2) / f(&g[0][0])).sqrt();
    let yt = (f(&g[1][2]) - xr * xt) / yr;
    let zt = f(&height2).max(0.0).sqrt();
    ([[xq, 0.0, 0.0], [xr, yr, 0.0], [xt, yt, zt]], height2)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_planar_body_is_placed_with_no_height() {
        let q = |n: i64| BigRational::from_integer(n.into());
        // P = 0, Q = (3, 0, 0), R = (0, 4, 0), T = (3, 4, h): Gram of Q, R, T from P
        let gram = |h2: i64| {
            vec![
                vec![q(9), q(0), q(9)],
                vec![q(0), q(16), q(16)],
                vec![q(9), q(16), q(25 + h2)],
            ]
        };
        let (p, h) = placed(&gram(0));
        assert!(num_traits::Zero::is_zero(&h) && p[2][2] == 0.0);
        assert_eq!(p[1], [0.0, 4.0, 0.0]);
        let (p, h) = placed(&gram(4));
        assert_eq!(h, q(4));
        assert_eq!(p[2], [3.0, 4.0, 2.0]);
    }

    #[test]
    fn names_judge_both_sides() {
        assert_eq!(judge_names(6, 4, 6), Verdict::Reproduced);
        assert_eq!(judge_names(6, 6, 6), Verdict::Contradicted);
        assert_eq!(judge_names(5, 4, 6), Verdict::Contradicted);
    }

    #[test]
    fn square_judge_both_sides() {
        // 5.47723² = 30.00004… against 30 with six significant digits
        assert!(length_matches_square(5.47723, 5e-6, 30.0, 5e-5));
        assert!(!length_matches_square(5.4775, 5e-6, 30.0, 5e-5));
        assert!(!length_matches_square(
            5.19615 + 100.0 * 5e-6,
            5e-6,
            27.0,
            0.0
        ));
    }

    #[test]
    fn printed_zero_has_no_rounding_in_g_format() {
        let z = Printed::parse("-0").unwrap();
        assert_eq!(printed_num(&z, 6).half, 0.0);
        let x = Printed::parse("12.3456").unwrap();
        assert!((printed_num(&x, 6).half - 5e-5).abs() < 1e-18);
    }
}
