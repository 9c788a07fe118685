//! EPA's polish for curved cores, which runs when EPA stops short (here: at
//! a low iteration limit). A disk inside an ellipse, centred on the minor
//! axis: the nearest boundary point is then the minor vertex (the axis point
//! lies above the vertex's center of curvature), so the exact depth is
//! `b - |y0| + r` and the exact normal the minor axis. The values are chosen
//! so that depth is a float sum without rounding.
//!
//! The scene is turned through many angles, so EPA's closest edge ends up on
//! either side of the minimum and the polish must bracket it walking forward
//! in some cases and backward in others.

use gjk2d::glam::DVec2;
use gjk2d::{Circle, Ellipse, Epa, EpaConfig, Gjk, GjkConfig, Status, Transform};

const SEMI_MAJOR: f64 = 2.0;
const SEMI_MINOR: f64 = 1.0;

/// The penetration of a disk of radius `r` centred at `(0, y0)` in the
/// ellipse's frame, the whole scene turned by `angle` and moved to `at`,
/// with EPA allowed `epa_iterations`. Returns (depth error, normal error,
/// the solver's status, its error bound).
fn polished(y0: f64, r: f64, angle: f64, at: DVec2, epa_iterations: u32) -> (f64, f64, Status, f64) {
    let mut config = EpaConfig::default();
    config.set_max_iterations(epa_iterations).unwrap();
    let gjk = Gjk::with_solver(GjkConfig::default(), Epa::<f64>::new(config));
    let ellipse = Ellipse::new(2.0 * SEMI_MAJOR, 2.0 * SEMI_MINOR).unwrap();
    let disk = Circle::new(r).unwrap();
    let turn = DVec2::from_angle(angle);
    let ta = Transform::new(at, angle).unwrap();
    let tb = Transform::new(at + turn.rotate(DVec2::new(0.0, y0)), angle).unwrap();
    let p = gjk.penetration(&ellipse, &ta, &disk, &tb).expect("the disk is inside the ellipse");
    let exact_depth = SEMI_MINOR - y0.abs() + r;
    // Moving B (the disk) along the normal separates: away from the centre.
    let exact_normal = turn.rotate(DVec2::new(0.0, y0.signum()));
    let normal = p.normal;
    (
        (p.depth - exact_depth).abs(),
        normal.perp_dot(exact_normal).abs() + (normal.dot(exact_normal) - 1.0).abs(),
        p.status,
        p.error_bound,
    )
}

#[test]
fn polish_finds_the_depth_from_either_side() {
    let mut worst = (0.0f64, 0.0f64);
    for &(y0, r) in &[(0.25, 0.5), (0.5, 0.25), (-0.25, 0.5), (-0.5, 0.125), (0.75, 0.0625)] {
        for k in 0..40 {
            let angle = -3.0 + 0.15 * k as f64;
            let (depth_error, normal_error, status, error_bound) = polished(y0, r, angle, DVec2::new(3.0, -1.0), 5);
            // Relative to L = the ellipse's bounding radius (2).
            assert!(
                depth_error <= 1e-12 * SEMI_MAJOR,
                "y0 {y0}, r {r}, angle {angle}: depth off by {depth_error:e} ({status:?})"
            );
            assert!(normal_error <= 1e-8, "y0 {y0}, r {r}, angle {angle}: normal off by {normal_error:e}");
            // A local minimum of the support function is not a certified
            // depth: the answer keeps EPA's status, and its error bound
            // (the gap to EPA's lower bound) covers the error.
            assert_eq!(status, Status::IterationLimit, "y0 {y0}, angle {angle}: EPA's status");
            assert!(depth_error <= error_bound, "y0 {y0}, angle {angle}: error bound {error_bound:e} below the error");
            worst = (worst.0.max(depth_error), worst.1.max(normal_error));
        }
    }
    println!("worst depth error {:e}, worst normal error {:e}", worst.0, worst.1);
}

/// After five EPA iterations (the least a user can set) its own bounds are
/// still far apart, so EPA has not converged by itself: the accuracy checked
/// above is the polish's. (Walking the polish's bracket the wrong way, in
/// either direction, leaves the depth 6.5e-2 off and fails the test above.)
#[test]
fn five_iterations_alone_are_far_off() {
    let mut config = EpaConfig::default();
    config.set_max_iterations(5).unwrap();
    let gjk = Gjk::with_solver(GjkConfig::default(), Epa::<f64>::new(config));
    let ellipse = Ellipse::new(2.0 * SEMI_MAJOR, 2.0 * SEMI_MINOR).unwrap();
    let disk = Circle::new(0.5).unwrap();
    let tb = Transform::new(DVec2::new(0.0, 0.25), 0.0).unwrap();
    let p = gjk.penetration(&ellipse, &Transform::IDENTITY, &disk, &tb).unwrap();
    // error_bound stays EPA's certified gap (upper bound found - lower bound).
    assert!(p.error_bound > 1e-6, "EPA alone would already be close: {:e}", p.error_bound);
}
