//! The gcd of big integers, Euclid's remainder first.
//!
//! num-bigint's gcd is binary (Stein's): each step subtracts and shifts, so the gcd of a
//! long integer and a short one takes about one step per bit of the long one. The contents
//! of polynomials meet that case at every coefficient once the running gcd is small. One
//! remainder brings the long operand down to the short one's length first; the gcd is the
//! same number.

use num_bigint::BigInt;
use num_integer::Integer;
use num_traits::{One, Signed, Zero};

/// Operands whose lengths differ by more than this many bits are reduced by a remainder
/// before the binary gcd: a division costs about as much as a few dozen of its steps.
const REMAINDER_BITS: u64 = 64;

/// The non-negative gcd of `a` and `b` (gcd(0, 0) = 0).
pub fn gcd(a: &BigInt, b: &BigInt) -> BigInt {
    let (mut x, mut y) = (a.abs(), b.abs());
    loop {
        if x < y {
            std::mem::swap(&mut x, &mut y);
        }
        if y.is_zero() {
            return x;
        }
        if x.bits() - y.bits() <= REMAINDER_BITS {
            return x.gcd(&y);
        }
        x = &x % &y;
    }
}

/// The non-negative lcm of `a` and `b` (zero when either is).
pub fn lcm(a: &BigInt, b: &BigInt) -> BigInt {
    if a.is_zero() || b.is_zero() {
        return BigInt::zero();
    }
    (a / gcd(a, b) * b).abs()
}

/// The gcd of every entry of `values`, stopping early at one (zero for none).
pub fn content<'a>(values: impl IntoIterator<Item = &'a BigInt>) -> BigInt {
    let mut g = BigInt::zero();
    for v in values {
        g = gcd(&g, v);
        if g.is_one() {
            break;
        }
    }
    g
}
