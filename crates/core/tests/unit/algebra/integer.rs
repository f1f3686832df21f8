//! Tests of `orthocheck_core::algebra::integer`: the gcd and lcm are num-bigint's, on
//! operands of equal and of very different lengths, signs and zeros.

use num_bigint::BigInt;
use num_integer::Integer;
use num_traits::Zero;
use orthocheck_core::algebra::integer::{content, gcd, lcm};

#[test]
fn the_gcd_is_num_bigints_on_operands_of_any_lengths() {
    let big = BigInt::from(3u8).pow(200) * BigInt::from(7u8) * BigInt::from(-1);
    let cases = [
        (BigInt::zero(), BigInt::zero()),
        (big.clone(), BigInt::zero()),
        (big.clone(), BigInt::from(21)),
        (BigInt::from(-14), big.clone()),
        (
            big.clone(),
            BigInt::from(3u8).pow(150) * BigInt::from(2u8).pow(90),
        ),
        (big.clone() + 1, big.clone()),
    ];
    for (a, b) in cases {
        assert_eq!(gcd(&a, &b), a.gcd(&b), "gcd({a}, {b})");
        assert_eq!(lcm(&a, &b), a.lcm(&b), "lcm({a}, {b})");
    }
}

#[test]
fn the_content_stops_at_one_and_is_zero_for_nothing() {
    let v = [BigInt::from(6), BigInt::from(-10), BigInt::from(15)];
    assert_eq!(content(&v), BigInt::from(1));
    assert_eq!(
        content(&[BigInt::from(6), BigInt::from(-10)]),
        BigInt::from(2)
    );
    assert_eq!(content(&[]), BigInt::zero());
}
