//! The polygon support scan against exact integer arithmetic. Small
//! capacities scan every slot on hosts (the unused ones copy vertex 0), eight
//! slots in SIMD on x86-64, and keep the leader by a select; larger ones scan
//! the vertices alone or walk.
//! Each must give a vertex of exactly the largest dot product, for every
//! vertex count up to the capacity; without a hint (a full scan, which keeps
//! the first of tied vertices) both capacities give the same vertex and id.

#[path = "common/geo.rs"]
mod geo;

use gjk2d::glam::{DVec2, Vec2};
use gjk2d::{Polygon, SupportMap, NO_FEATURE};
use proptest::prelude::*;

/// Integer points (exact in f32 and f64), their hull, and integer directions:
/// every dot product below is exact in i64.
type Points = Vec<(i64, i64)>;

fn hull_and_directions() -> impl Strategy<Value = (Points, Points)> {
    (prop::collection::vec((-40i64..=40, -40i64..=40), 3..24), prop::collection::vec((-9i64..=9, -9i64..=9), 1..24))
        .prop_map(|(points, dirs)| {
            let hull = geo::integer_hull(points);
            let dirs: Points = dirs.into_iter().filter(|&d| d != (0, 0)).collect();
            (hull, dirs)
        })
        .prop_filter("a polygon of at most 8 vertices", |(h, d)| (3..=8).contains(&h.len()) && !d.is_empty())
}

macro_rules! scan_suite {
    ($name:ident, $r:ty, $vec:ident) => {
        proptest! {
            #![proptest_config(ProptestConfig::with_cases(400))]
            #[test]
            fn $name((hull, dirs) in hull_and_directions()) {
                let pts: Vec<$vec> = hull.iter().map(|&(x, y)| $vec::new(x as $r, y as $r)).collect();
                let small = Polygon::<$r, 8>::new(&pts).unwrap();
                let large = Polygon::<$r, 64>::new(&pts).unwrap();
                let origin = small.reference_point();
                for &(dx, dy) in &dirs {
                    let d = $vec::new(dx as $r, dy as $r);
                    let best = hull.iter().map(|&(x, y)| x * dx + y * dy).max().unwrap();
                    for near in [NO_FEATURE, 0, 2, 7] {
                        let (p, id) = small.support_feature(d, near);
                        let (q, jd) = large.support_feature(d, near);
                        if near == NO_FEATURE {
                            prop_assert_eq!((p, id), (q, jd), "capacities disagree along {:?}", d);
                        }
                        for (v, i) in [(p, id), (q, jd)] {
                            prop_assert!((i as usize) < hull.len());
                            let w = v + origin;
                            let dot = w.x as i64 * dx + w.y as i64 * dy;
                            prop_assert_eq!(dot, best, "not the exact support along {:?}", d);
                        }
                    }
                    prop_assert_eq!(small.support(d), large.support(d));
                }
            }
        }
    };
}

scan_suite!(scan_matches_exact_support_f32, f32, Vec2);
scan_suite!(scan_matches_exact_support_f64, f64, DVec2);
