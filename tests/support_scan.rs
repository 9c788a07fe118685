//! The polygon support scan against exact integer arithmetic. Small
//! capacities scan every slot on hosts (the unused ones copy vertex 0), eight
//! slots in SIMD on x86-64, up to 64 vertices four or two at a time; the rest
//! keep the leader by a select, or walk and search. Each must give a vertex
//! of exactly the largest dot product, for every vertex count up to the
//! capacity; without a hint a scan keeps the first of tied vertices, so
//! capacities 8 and 64 give the same vertex and id, and where 64 vertices or
//! fewer are scanned, the first in the polygon's order.

#[path = "common/geo.rs"]
mod geo;

use gjk2d::glam::{DVec2, Vec2};
use gjk2d::{Polygon, SupportMap, NO_FEATURE};
use proptest::prelude::*;

/// Integer points (exact in f32 and f64), their hull, and integer directions:
/// every dot product below is exact in i64.
type Points = Vec<(i64, i64)>;

/// A polygon's vertices as it stores them, as integers (exact: the inputs
/// are integers).
macro_rules! stored {
    ($polygon:expr) => {
        (0..$polygon.len()).map(|i| $polygon.vertex(i).unwrap()).map(|v| (v.x as i64, v.y as i64)).collect::<Points>()
    };
}

/// Each point's dot product with `(dx, dy)`, exact in i64, and the largest.
fn dots_and_top(points: &[(i64, i64)], (dx, dy): (i64, i64)) -> (Vec<i64>, i64) {
    let dots: Vec<i64> = points.iter().map(|&(x, y)| x * dx + y * dy).collect();
    let top = dots.iter().copied().max().unwrap_or(i64::MIN);
    (dots, top)
}

fn hull_and_directions(max_vertices: usize) -> impl Strategy<Value = (Points, Points)> {
    // Scattered points give few hull vertices; points near a circle, many.
    let scattered = prop::collection::vec((-40i64..=40, -40i64..=40), 3..24);
    let round = prop::collection::vec((0.0f64..std::f64::consts::TAU, 0.9f64..1.0), 3..120).prop_map(|p| {
        p.into_iter().map(|(t, r)| ((300.0 * r * t.cos()) as i64, (300.0 * r * t.sin()) as i64)).collect()
    });
    (prop_oneof![scattered, round], prop::collection::vec((-9i64..=9, -9i64..=9), 1..24))
        .prop_map(|(points, dirs): (Points, Points)| {
            let hull = geo::integer_hull(points);
            let dirs: Points = dirs.into_iter().filter(|&d| d != (0, 0)).collect();
            (hull, dirs)
        })
        .prop_filter("a polygon within the capacity", move |(h, d)| {
            (3..=max_vertices).contains(&h.len()) && !d.is_empty()
        })
}

macro_rules! scan_suite {
    ($name:ident, $r:ty, $vec:ident) => {
        proptest! {
            #![proptest_config(ProptestConfig::with_cases(400))]
            #[test]
            fn $name((hull, dirs) in hull_and_directions(8)) {
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

macro_rules! first_of_ties_suite {
    ($name:ident, $r:ty, $vec:ident) => {
        proptest! {
            #![proptest_config(ProptestConfig::with_cases(400))]
            #[test]
            fn $name((hull, dirs) in hull_and_directions(64)) {
                let pts: Vec<$vec> = hull.iter().map(|&(x, y)| $vec::new(x as $r, y as $r)).collect();
                let polygon = Polygon::<$r, 64>::new(&pts).unwrap();
                let stored = stored!(polygon);
                for &(dx, dy) in &dirs {
                    let d = $vec::new(dx as $r, dy as $r);
                    let (dots, best) = dots_and_top(&stored, (dx, dy));
                    let first = dots.iter().position(|&x| x == best).unwrap();
                    let (_, id) = polygon.support_feature(d, NO_FEATURE);
                    prop_assert_eq!(dots[id as usize], best, "not the exact support along {:?}", d);
                    // x86-64 scans up to 64 vertices; elsewhere more than 24
                    // are searched, which may land on any of tied vertices.
                    if cfg!(target_arch = "x86_64") || stored.len() <= 24 {
                        prop_assert_eq!(id as usize, first, "not the first of tied vertices along {:?}", d);
                    }
                    for near in [0, 5, 17, 40] {
                        let (_, id) = polygon.support_feature(d, near);
                        prop_assert_eq!(dots[id as usize], best, "hinted {}: not the exact support along {:?}", near, d);
                    }
                }
            }
        }
    };
}

first_of_ties_suite!(scan_keeps_first_of_ties_f32, f32, Vec2);
first_of_ties_suite!(scan_keeps_first_of_ties_f64, f64, DVec2);

/// A convex polygon with collinear runs: `corners` (integers, counter-clockwise,
/// strictly convex) with each edge cut into `cuts` equal integer steps.
fn with_collinear_runs(corners: &[(i64, i64)], cuts: i64) -> Points {
    let n = corners.len();
    (0..n)
        .flat_map(|i| {
            let ((x0, y0), (x1, y1)) = (corners[i], corners[(i + 1) % n]);
            (0..cuts).map(move |k| (x0 + (x1 - x0) * k / cuts, y0 + (y1 - y0) * k / cuts))
        })
        .collect()
}

macro_rules! collinear_runs_suite {
    ($name:ident, $r:ty, $vec:ident) => {
        /// A hint inside a flat run is at a top or at a bottom: the walk from
        /// it must tell which. Every hint, along directions perpendicular to
        /// the runs and others, against the exact integer support; capacities
        /// that walk and search on every host.
        #[test]
        fn $name() {
            let corners: [&[(i64, i64)]; 3] = [
                &[(0, 0), (1200, 0), (1200, 1200), (0, 1200)],
                &[(0, 0), (600, 0), (900, 300), (900, 900), (600, 1200), (0, 1200), (-300, 900), (-300, 300)],
                &[(0, 0), (1200, 600), (0, 1200)],
            ];
            let directions = [(0, 1), (0, -1), (1, 0), (-1, 0), (1, 1), (-1, -1), (1, -1), (-1, 1), (2, 1), (-1, 3)];
            let mut checked = 0;
            for corners in corners {
                for cuts in [3, 12, 40] {
                    let points = with_collinear_runs(corners, cuts);
                    let pts: Vec<$vec> = points.iter().map(|&(x, y)| $vec::new(x as $r, y as $r)).collect();
                    let polygon = Polygon::<$r, 512>::new(&pts).unwrap();
                    let stored = stored!(polygon);
                    for &(dx, dy) in &directions {
                        let d = $vec::new(dx as $r, dy as $r);
                        let (dots, best) = dots_and_top(&stored, (dx, dy));
                        for near in (0..stored.len() as u32).chain([NO_FEATURE]) {
                            let (_, id) = polygon.support_feature(d, near);
                            assert_eq!(
                                dots[id as usize],
                                best,
                                "{} vertices, hint {near}: not the exact support along {:?}",
                                stored.len(),
                                (dx, dy)
                            );
                            checked += 1;
                        }
                    }
                }
            }
            assert!(checked > 8_000, "{checked}");
        }
    };
}

collinear_runs_suite!(hints_in_flat_runs_find_the_top_f32, f32, Vec2);
collinear_runs_suite!(hints_in_flat_runs_find_the_top_f64, f64, DVec2);

macro_rules! dense_hull_suite {
    ($name:ident, $r:ty, $vec:ident) => {
        proptest! {
            #![proptest_config(ProptestConfig::with_cases(60))]
            /// Hulls of hundreds of integer points near a circle: long runs
            /// of nearly parallel edges, which the walks and the angular
            /// search of large polygons (more than 64 vertices on x86-64,
            /// 24 elsewhere) go along. Every third vertex as a hint, and
            /// none, along integer directions, against the exact support.
            #[test]
            fn $name(
                points in prop::collection::vec((0.0f64..std::f64::consts::TAU, 0.995f64..1.0), 400..2000),
                dirs in prop::collection::vec((-9i64..=9, -9i64..=9), 1..12),
            ) {
                let hull = geo::integer_hull(
                    points.iter().map(|&(t, r)| ((3000.0 * r * t.cos()) as i64, (3000.0 * r * t.sin()) as i64)).collect(),
                );
                prop_assume!(hull.len() > 64);
                let pts: Vec<$vec> = hull.iter().map(|&(x, y)| $vec::new(x as $r, y as $r)).collect();
                let polygon = Polygon::<$r, 1024>::new(&pts).unwrap();
                let stored = stored!(polygon);
                for &(dx, dy) in dirs.iter().filter(|&&d| d != (0, 0)) {
                    let d = $vec::new(dx as $r, dy as $r);
                    let (dots, best) = dots_and_top(&stored, (dx, dy));
                    for near in (0..stored.len() as u32).step_by(3).chain([NO_FEATURE]) {
                        let (_, id) = polygon.support_feature(d, near);
                        prop_assert_eq!(dots[id as usize], best, "{} vertices, hint {}: not the exact support along {:?}", stored.len(), near, (dx, dy));
                    }
                }
            }
        }
    };
}

dense_hull_suite!(dense_hulls_hinted_f32, f32, Vec2);
dense_hull_suite!(dense_hulls_hinted_f64, f64, DVec2);

/// A support of dot exactly zero among the last vertices, which the scan
/// checks one by one after its vector blocks: the blocks' unused slots hold
/// zero dots too, and must not be taken for it. The points are not exact
/// offsets of one another, so the polygon keeps them about the origin,
/// where the lowest lies, at y = 0: along -y every other dot is negative.
macro_rules! zero_top_suite {
    ($name:ident, $r:ty, $vec:ident) => {
        #[test]
        fn $name() {
            for count in 9..=64usize {
                let pts: Vec<$vec> = (1..=count)
                    .map(|k| {
                        let t = -std::f64::consts::FRAC_PI_2 + std::f64::consts::TAU * k as f64 / count as f64;
                        $vec::new((1.3 * t.cos()) as $r, (1.3 + 1.3 * t.sin()) as $r)
                    })
                    .collect();
                let polygon = Polygon::<$r, 64>::new(&pts).unwrap();
                let lowest = (0..count).find(|&i| polygon.vertex(i).unwrap().y == 0.0).expect("a vertex at y = 0");
                assert!(polygon.reference_point() == $vec::ZERO, "{count} vertices: kept about the origin");
                let (_, id) = polygon.support_feature($vec::new(0.0, -1.0), NO_FEATURE);
                assert_eq!(id as usize, lowest, "{count} vertices");
            }
        }
    };
}

zero_top_suite!(zero_top_past_the_blocks_f32, f32, Vec2);
zero_top_suite!(zero_top_past_the_blocks_f64, f64, DVec2);
