//! The `std` layer: batch queries agree with one-at-a-time queries, all ray
//! hits come nearest first, and the uncapped EPA converges where a tiny fixed
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
fn uncapped_epa_converges_where_a_tiny_polytope_cannot() {
    // Two overlapping ellipses: a smooth Minkowski difference that needs many
    // polytope vertices to certify its depth to the default 1e-12.
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
    // The fixed polytope cannot certify as tightly.
    assert!(tiny.error_bound > uncapped.error_bound, "{tiny:?}");
}
