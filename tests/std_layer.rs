//! The `std` layer: batch queries agree with one-at-a-time queries, all ray
//! hits come nearest first, and the uncapped EPA converges where a fixed
//! polytope cannot.
#![cfg(feature = "std")]

use gjk2d::glam::DVec2;
use gjk2d::*;

fn ring() -> Vec<(Circle<f64>, Transform<f64>)> {
    // Circles of radius 0.5 along +x at 1, 2.5, 4, ... : some overlap the probe.
    (0..6)
        .map(|i| {
            (Circle::new(0.5).unwrap(), Transform::from_translation(DVec2::new(1.0 + 1.5 * i as f64, 0.0)).unwrap())
        })
        .collect()
}

#[test]
fn batches_match_single_queries() {
    let gjk = Gjk::<f64>::new();
    let probe = Rectangle::new(2.0, 2.0).unwrap();
    let at = Transform::IDENTITY;
    let others = ring();
    let distances = gjk.distances(&probe, &at, &others);
    let penetrations = gjk.penetrations(&probe, &at, &others);
    assert_eq!(distances.len(), others.len());
    for (i, (b, tb)) in others.iter().enumerate() {
        assert_eq!(distances[i], gjk.distance(&probe, &at, b, tb));
        assert_eq!(penetrations[i], gjk.penetration(&probe, &at, b, tb));
        // Exactly one of them answers for each pair.
        assert!(distances[i].is_some() != penetrations[i].is_some(), "pair {i}");
    }
    // The first circle (center 1, radius 0.5) overlaps the 2x2 box by 0.5.
    assert!((penetrations[0].unwrap().depth - 0.5).abs() < 1e-15);
    // The second (center 2.5) is 1 away.
    assert!((distances[1].unwrap().distance - 1.0).abs() < 1e-15);
}

#[test]
fn raycast_all_lists_every_hit_nearest_first() {
    let gjk = Gjk::<f64>::new();
    let mut shapes = ring();
    shapes.reverse();
    let ray = Ray::new(DVec2::new(-1.0, 0.0), DVec2::X).unwrap();
    let hits = gjk.raycast_all(&ray, 0.0, &shapes);
    assert_eq!(hits.len(), shapes.len());
    // Nearest first: the circle at x = 1 (last in the reversed list) at distance 1.5.
    assert_eq!(hits[0].0, shapes.len() - 1);
    assert!((hits[0].1.distance - 1.5).abs() < 1e-15);
    assert!(hits.windows(2).all(|w| w[0].1.distance < w[1].1.distance));
    // Bounded: only the hits within 4 units.
    let near = gjk.raycast_all(&ray, 4.0, &shapes);
    assert_eq!(near.len(), 2);
}

#[test]
fn uncapped_epa_converges_where_a_fixed_polytope_cannot() {
    // A nearly round 100-gon around a small square at its center: the depth
    // is nearly the same in four directions. The default 32 corners
    // converge (a full polytope merges the corner whose merged edge keeps
    // the largest bound); 16 are too few, and EPA goes round the tied
    // faces until the iteration limit. The uncapped polytope converges.
    let points: Vec<DVec2> = (0..100)
        .map(|i| {
            let angle = 0.1 + i as f64 * core::f64::consts::TAU / 100.0;
            DVec2::new(angle.cos(), angle.sin())
        })
        .collect();
    let round = Polygon::<f64, 100>::new(&points).unwrap();
    let square = Rectangle::new(0.02, 0.02).unwrap();
    let at = Transform::IDENTITY;
    // The oracle's exact depth, the shapes taken as placed (no transform).
    let exact_polygon = |points: Vec<[f64; 2]>| {
        gjk2d_oracle::transform_shape(&gjk2d_oracle::Shape::Polygon(points), 1.0, 0.0, 0.0, 0.0)
    };
    let exact = gjk2d_oracle::pair(
        &exact_polygon(points.iter().map(|p| [p.x, p.y]).collect()),
        &exact_polygon(vec![[-0.01, -0.01], [0.01, -0.01], [0.01, 0.01], [-0.01, 0.01]]),
    )
    .depth;
    let default = Gjk::<f64>::new().penetration(&round, &at, &square, &at).unwrap();
    assert_eq!(default.status, Status::Converged, "{default:?}");
    assert!((default.depth - exact).abs() <= 1e-12, "{default:?} against {exact}");
    let small = Gjk::with_solver(GjkConfig::default(), Epa::<f64, 16>::default())
        .penetration(&round, &at, &square, &at)
        .unwrap();
    assert_eq!(small.status, Status::IterationLimit, "{small:?}");
    // Stopped short, the answer is still sound: an achievable depth, and
    // its error bound reaches down to the exact one.
    assert!(small.depth >= exact && small.depth - small.error_bound <= exact, "{small:?} against {exact}");
    let mut epa = EpaVec::<f64>::default();
    epa.config.set_max_iterations(10_000).unwrap();
    let uncapped = Gjk::with_solver(GjkConfig::default(), epa).penetration(&round, &at, &square, &at).unwrap();
    assert_eq!(uncapped.status, Status::Converged, "{uncapped:?}");
    assert!((uncapped.depth - exact).abs() <= 1e-12, "{uncapped:?} against {exact}");
    assert!(uncapped.error_bound <= 1e-12, "{uncapped:?}");
}

#[test]
fn a_tiny_polytope_certifies_smooth_shapes_as_tightly_as_an_uncapped_one() {
    // Two overlapping ellipses: a smooth Minkowski difference that needs many
    // polytope vertices to certify its depth to the default 1e-12, but only
    // a few at a time: the faces already certified merge away.
    let a = Ellipse::new(4.0, 2.0).unwrap();
    let b = Ellipse::new(2.0, 4.0).unwrap();
    let (ta, tb) = (Transform::IDENTITY, Transform::from_translation(DVec2::new(2.75, 0.0)).unwrap());
    let mut epa = EpaVec::<f64>::default();
    epa.config.set_max_iterations(10_000).unwrap();
    let uncapped = Gjk::with_solver(GjkConfig::default(), epa).penetration(&a, &ta, &b, &tb).unwrap();
    assert_eq!(uncapped.status, Status::Converged);
    // Exact: the ellipses' x extents overlap by 2 + 1 - 2.75 = 0.25 (by
    // symmetry the minimum translation is along x).
    assert!((uncapped.depth - 0.25).abs() <= 1e-11, "{uncapped:?}");
    assert!(uncapped.error_bound <= 1e-11, "{uncapped:?}");
    let tiny = Gjk::with_solver(GjkConfig::default(), Epa::<f64, 4>::default()).penetration(&a, &ta, &b, &tb).unwrap();
    assert_eq!(tiny.status, Status::Converged, "{tiny:?}");
    assert!((tiny.depth - 0.25).abs() <= 1e-11, "{tiny:?}");
    assert!(tiny.error_bound <= 1e-11, "{tiny:?}");
}
