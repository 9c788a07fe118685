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

// Not every suite places its polygons with these.
#[allow(dead_code)]
impl Spec {
    /// The length unit of the suites' placements: the hull's scale over 8.
    pub fn scale(&self) -> f64 {
        2.0f64.powi(self.scale_exp - 3)
    }

    /// The vertices, scaled.
    pub fn points(&self) -> Vec<[f64; 2]> {
        let scale = self.scale();
        self.hull.iter().map(|&(x, y)| [x as f64 * scale, y as f64 * scale]).collect()
    }

    /// Far from the origin (2^16 and -2^15 units), or at it.
    pub fn origin(&self, far: bool) -> [f64; 2] {
        let scale = self.scale();
        if far {
            [(1 << 16) as f64 * scale, -((1 << 15) as f64) * scale]
        } else {
            [0.0, 0.0]
        }
    }
}

/// 3 to 8 hull vertices, at scales 2^-40 to 2^13.
pub fn polygon() -> impl Strategy<Value = Spec> {
    (prop::collection::vec((-20i64..=20, -20i64..=20), 3..14), -40i32..=13)
        .prop_map(|(points, scale_exp)| Spec { hull: geo::integer_hull(points), scale_exp })
        .prop_filter("3 to 8 vertices", |s| (3..=8).contains(&s.hull.len()))
}
