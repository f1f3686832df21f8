//! Tests of `orthocheck_core::sfm::robust`.

use orthocheck_core::model::rng;
use orthocheck_core::sfm::robust::*;

#[test]
fn the_sample_count_follows_the_inlier_share() {
    // 0.999 confidence at share 0.8: 1 − 0.8⁴ = 0.5904, ln(0.001)/ln(0.5904) = 13.1…
    assert_eq!(samples_needed(0.8, 10_000), 14);
    assert_eq!(samples_needed(1.0, 10_000), 1);
    assert_eq!(samples_needed(0.0, 500), 500);
    assert_eq!(samples_needed(0.05, 500), 500);
    // the least-median search draws at least ln(0.001)/ln(1 − 1/16) = 107.03… samples
    assert_eq!(samples_needed(LMEDS_SHARE, 10_000), 108);
}

#[test]
fn distinct_indices_are_distinct() {
    let mut g = rng(3);
    for _ in 0..100 {
        let d: [usize; 4] = distinct(&mut g, 5);
        assert!((0..4).all(|i| (i + 1..4).all(|j| d[i] != d[j])));
    }
}
