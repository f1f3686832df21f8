//! The gcd that always answers: primitive polynomial remainder sequences (Collins, Brown).
//!
//! The inputs are read as polynomials in one variable xᵢ over ℤ[the others]. Each is split
//! into its content (the gcd of its coefficients in xᵢ, found recursively in fewer
//! variables) and its primitive part; the primitive parts run through pseudo-remainders,
//! each remainder made primitive again, until one divides the previous:
//! gcd = gcd(contents) · pp(last non-zero remainder). Every step is exact arithmetic and the
//! degree in xᵢ drops each step, so it terminates with the right answer; it is slower than
//! the heuristic gcd, which is why it only runs when that gives up.

use super::coeff::Coef;
use super::MPoly;

/// gcd of two polynomials (either may be zero), positive leading coefficient, integer
/// content included.
pub(super) fn gcd_prs(a: &MPoly, b: &MPoly) -> MPoly {
    let n = a.nvars();
    if a.is_zero() || b.is_zero() {
        let p = if a.is_zero() { b } else { a };
        let (c, pp) = p.primitive();
        return pp.scale(&c.gcd(&Coef::Small(0)));
    }
    if a.degree() == 0 || b.degree() == 0 {
        return MPoly::constant(n, a.content().gcd(&b.content()));
    }
    let (ua, ub) = (a.used(), b.used());
    // a variable only one side uses: the gcd is free of it, so only that side's content in
    // it can share a factor with the other side
    if let Some(i) = (0..n).find(|&i| ua[i] != ub[i]) {
        return if ua[i] {
            gcd_prs(&content_in(a, i), b)
        } else {
            gcd_prs(a, &content_in(b, i))
        };
    }
    // the common variable of lowest degree: the shortest remainder sequence
    let Some(i) = (0..n)
        .filter(|&i| ua[i])
        .min_by_key(|&i| a.degree_in(i).max(b.degree_in(i)))
    else {
        return MPoly::constant(n, a.content().gcd(&b.content()));
    };
    let (ca, cb) = (content_in(a, i), content_in(b, i));
    let (pa, pb) = (exact(a, &ca), exact(b, &cb));
    // the contents are free of xᵢ: their gcd recurses on fewer variables
    let g = &ca.gcd(&cb) * &primitive_sequence(pa, pb, i);
    let (c, pp) = g.primitive();
    pp.scale(&c.gcd(&Coef::Small(0)))
}

/// `p / d`, `d` known to divide `p` (a content): the quotient, or `p` if the division
/// failed, which exact arithmetic rules out.
fn exact(p: &MPoly, d: &MPoly) -> MPoly {
    p.div_exact(d).unwrap_or_else(|| p.clone())
}

/// The content of `p` in variable `i`: the gcd of its coefficients (sign of `p`'s leading
/// coefficient dropped: positive).
fn content_in(p: &MPoly, i: usize) -> MPoly {
    let mut parts = p.coefficients_in(i).into_iter().filter(|c| !c.is_zero());
    let Some(first) = parts.next() else {
        return MPoly::zero(p.nvars());
    };
    let mut g = first.gcd(&MPoly::zero(p.nvars()));
    for c in parts {
        if g.degree() == 0 && g.coef(0).is_unit() {
            break;
        }
        g = g.gcd(&c);
    }
    g
}

/// gcd of `f` and `g`, both primitive in variable `i` and of positive degree in it.
fn primitive_sequence(f: MPoly, g: MPoly, i: usize) -> MPoly {
    let (mut f, mut g) = if f.degree_in(i) >= g.degree_in(i) {
        (f, g)
    } else {
        (g, f)
    };
    loop {
        let r = pseudo_remainder(&f, &g, i);
        if r.is_zero() {
            return g;
        }
        if r.degree_in(i) == 0 {
            return MPoly::constant(f.nvars(), Coef::Small(1));
        }
        let pr = exact(&r, &content_in(&r, i));
        f = g;
        g = pr;
    }
}

/// A remainder of `lc(g)ᵏ · f` by `g` in variable `i`: each step cancels the leading
/// coefficient of r in xᵢ, by `r − (lc(r)/lc(g))·xᵢᵐ·g` when lc(g) divides lc(r) exactly
/// (no growth), else by `lc(g)·r − lc(r)·xᵢᵐ·g`; until deg r < deg g.
fn pseudo_remainder(f: &MPoly, g: &MPoly, i: usize) -> MPoly {
    let n = f.nvars();
    let d = g.degree_in(i);
    let lg = g.coefficients_in(i).pop().unwrap_or_else(|| MPoly::zero(n));
    let mut r = f.clone();
    while !r.is_zero() && r.degree_in(i) >= d {
        let k = r.degree_in(i);
        let lr = r.coefficients_in(i).pop().unwrap_or_else(|| MPoly::zero(n));
        let mut e = vec![0u32; n];
        e[i] = k - d;
        let shift = MPoly::from_terms(n, vec![(e, Coef::Small(1))]);
        r = match lr.div_exact(&lg) {
            Some(q) => &r - &(&(&q * &shift) * g),
            None => &(&lg * &r) - &(&(&lr * &shift) * g),
        };
    }
    r
}
