//! Student's t quantiles against the printed tables (Abramowitz & Stegun, table 26.10).

use orthocheck_core::algebra::student::{two_sided, two_sided_quantile};

#[test]
fn quantiles_match_the_tables() {
    // (ν, two-sided probability, t) to the tables' three decimals
    let table = [
        (1, 0.99, 63.657),
        (2, 0.99, 9.925),
        (3, 0.99, 5.841),
        (5, 0.99, 4.032),
        (10, 0.99, 3.169),
        (30, 0.99, 2.750),
        (1, 0.95, 12.706),
        (4, 0.95, 2.776),
        (120, 0.95, 1.980),
    ];
    for (nu, p, t) in table {
        let q = two_sided_quantile(p, nu);
        assert!(
            (q - t).abs() <= 0.0005 * 1.0001,
            "ν = {nu}, p = {p}: {q} for {t}"
        );
        // and the probability at the printed t is p within the table's rounding
        assert!((two_sided(q, nu) - p).abs() < 1e-12);
    }
    // large ν tends to the normal: 2.5758 at 99 %
    assert!((two_sided_quantile(0.99, 100_000) - 2.5758).abs() < 1e-3);
}
