//! Tests of `orthocheck_core::algebra::mpoly::monomial`.

use orthocheck_core::algebra::mpoly::monomial::*;

#[test]
fn packing_orders_by_degree_then_lex() {
    let p = Packing::for_degree(3, 10);
    assert_eq!((p.bits, p.words), (8, 1));
    let pack = |e: [u32; 3]| {
        let mut w = vec![0; p.words];
        p.pack_into(&e, &mut w);
        w
    };
    assert!(pack([0, 0, 2]) > pack([1, 0, 0]), "degree first");
    assert!(pack([1, 1, 0]) > pack([1, 0, 1]), "then the first variable");
    assert_eq!(p.unpack(&pack([3, 0, 7])), vec![3, 0, 7]);
    assert_eq!(p.degree(&pack([3, 0, 7])), 10);
}

#[test]
fn division_detects_borrows_through_the_guard_bits() {
    let p = Packing::for_degree(10, 100); // 11 fields of 8 bits: two words
    assert_eq!(p.words, 2);
    let mask = p.guard_mask();
    let mut a = vec![0; 2];
    let mut b = vec![0; 2];
    let mut q = vec![0; 2];
    p.pack_into(&[1, 0, 0, 0, 0, 0, 0, 0, 2, 3], &mut a);
    p.pack_into(&[1, 0, 0, 0, 0, 0, 0, 0, 0, 3], &mut b);
    assert!(div_into(&a, &b, &mask, &mut q));
    assert_eq!(p.unpack(&q), vec![0, 0, 0, 0, 0, 0, 0, 0, 2, 0]);
    let mut back = vec![0; 2];
    mul_into(&q, &b, &mut back);
    assert_eq!(back, a);
    assert!(!div_into(&b, &a, &mask, &mut q));
}
