//! Tests of `orthocheck_core::studies::joint_fit`.

mod jacobian;

use orthocheck_core::studies::joint_fit::*;

#[test]
fn the_tetrahedron_has_its_edges() {
    let s = [4.0, 9.0, 12.0, 20.0, 21.0, 18.0];
    let b = tetrahedron(&s).unwrap_or_else(|| unreachable!());
    let e = orthocheck_core::model::edges(4);
    for (k, (i, j)) in e.iter().enumerate() {
        approx::assert_relative_eq!((b[*i] - b[*j]).norm_squared(), s[k], max_relative = 1e-12);
    }
    assert!(tetrahedron(&[1.0, 1.0, 9.0, 1.0, 1.0, 1.0]).is_none());
}
