//! Tests of `orthocheck_core::sfm::gaps`.

use orthocheck_core::model::Scene;
use orthocheck_core::sfm::gaps::*;
use orthocheck_core::sfm::Observations;

#[test]
fn the_block_drops_the_sparsest_frame_and_point() {
    let mut o = Observations::from_tracks(&Scene::random(6, 5, 1).tracks());
    // frame 5 misses three points, point 6 misses one frame
    for j in 0..3 {
        o.frames[4][j] = None;
    }
    o.frames[1][5] = None;
    let (f, p) = largest_complete_block(&o);
    assert_eq!(f, [0, 1, 2, 3]);
    assert_eq!(p, [0, 1, 2, 3, 4]);
}
