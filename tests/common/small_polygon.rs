//! Random small convex polygons for the suites of the closed forms hosts
//! take for polygons of at most eight vertices.

use super::geo;
use proptest::prelude::*;

/// A polygon: integer hull points times a power-of-two scale.
#[derive(Clone, Debug)]
pub struct Spec {
    pub hull: Vec<(i64, i64)>,
    pub scale_exp: i32,
}

/// 3 to 8 hull vertices, at scales 2^-40 to 2^13.
pub fn polygon() -> impl Strategy<Value = Spec> {
    (prop::collection::vec((-20i64..=20, -20i64..=20), 3..14), -40i32..=13)
        .prop_map(|(points, scale_exp)| Spec { hull: geo::integer_hull(points), scale_exp })
        .prop_filter("3 to 8 vertices", |s| (3..=8).contains(&s.hull.len()))
}
