//! Tests of `orthocheck_core::numfmt`.

use orthocheck_core::numfmt::*;

/// Each table pairs every character with its glyph (one for one), and a monomial reads
/// as a reader writes it.
#[test]
fn scripts_line_up_and_monomials_read_as_written() {
    assert_eq!(superscript('7'), Some('⁷'));
    assert_eq!(superscript('i'), Some('ⁱ'));
    assert_eq!(subscript('v'), Some('ᵥ'));
    assert_eq!(subscript('9'), Some('₉'));
    assert_eq!((superscript('b'), subscript('b')), (None, None));
    assert_eq!(monomial(&[("a", 2), ("a_i", 2), ("c_12", 1)]), "a²·aᵢ²·c₁₂");
    assert_eq!(monomial(&[("f_cb", 1), ("x_y", 3)]), "f_cb·x_y³");
    assert_eq!(monomial(&[]), "1");
}

#[test]
fn every_formatter_counts_the_non_finite_values_it_formats() {
    // other tests may format non-finite values at the same time: the count only grows
    for f in [sig, |x| sig_digits(x, 3), below, round_trip] {
        let before = non_finite_formatted();
        assert_eq!(f(f64::NAN), "NaN");
        assert!(non_finite_formatted() > before);
    }
    assert_eq!(round_trip(0.1), "0.1");
}
