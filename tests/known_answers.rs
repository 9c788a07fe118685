//! Known answers for every shape pair, under rotated transforms.
//!
//! Every shape here is symmetric about its local x axis (the half ellipse
//! is turned a quarter so it is), so when B lies on A's x axis the closest
//! points of the two are on that axis: the exact distance is the gap between
//! A's rightmost and B's leftmost extent, read from the shapes' own stored
//! geometry. The whole configuration is then rotated by an arbitrary angle;
//! the distance stays, the normal turns with it.
//!
//! Penetration: any shape pushed by `delta` into a block much larger than it
//! (a flat face): the exact depth is `delta`, along the face normal.

use gjk2d::glam::{DVec2, Vec2};
use gjk2d::*;

/// One shape and where its extreme points along local +x and -x are.
struct Case<R: Real> {
    name: &'static str,
    shape: Box<dyn SupportMap<R>>,
    /// Extra rotation of the shape in its own frame (cos, sin).
    turn: (R, R),
    right: R,
    left: R,
    /// Curved at the +x/-x extreme points: accurate to the epsilon, not exact.
    curved_right: bool,
    curved_left: bool,
}

macro_rules! known_answer_suite {
    ($modname:ident, $r:ty, $vec:ident) => {
        mod $modname {
            use super::*;
            type R = $r;

            fn v(x: R, y: R) -> $vec {
                $vec::new(x, y)
            }

            fn cases() -> Vec<Case<R>> {
                let one = (1.0 as R, 0.0 as R);
                let poly = Polygon::<R, 16>::regular(7, 0.9).unwrap();
                let xs: Vec<R> = (0..poly.len()).map(|i| poly.vertex(i).unwrap().x).collect();
                let pmax = xs.iter().cloned().fold(R::MIN, R::max);
                let pmin = xs.iter().cloned().fold(R::MAX, R::min);
                vec![
                    Case {
                        name: "circle",
                        shape: Box::new(Circle::new(0.75).unwrap()),
                        turn: one,
                        right: 0.75,
                        left: 0.75,
                        curved_right: false,
                        curved_left: false,
                    },
                    Case {
                        name: "polygon",
                        shape: Box::new(poly),
                        turn: one,
                        right: pmax,
                        left: -pmin,
                        curved_right: false,
                        curved_left: false,
                    },
                    Case {
                        name: "rectangle",
                        shape: Box::new(Rectangle::new(1.5, 0.5).unwrap()),
                        turn: one,
                        right: 0.75,
                        left: 0.75,
                        curved_right: false,
                        curved_left: false,
                    },
                    Case {
                        name: "triangle",
                        shape: Box::new(Triangle::new(v(1.0, 0.0), v(-0.5, 0.8), v(-0.5, -0.8)).unwrap()),
                        turn: one,
                        right: 1.0,
                        left: 0.5,
                        curved_right: false,
                        curved_left: false,
                    },
                    Case {
                        name: "segment",
                        shape: Box::new(Segment::new(v(-0.625, 0.0), v(0.625, 0.0)).unwrap()),
                        turn: one,
                        right: 0.625,
                        left: 0.625,
                        curved_right: false,
                        curved_left: false,
                    },
                    Case {
                        name: "capsule",
                        shape: Box::new(Capsule::from_size(2.0, 0.5).unwrap()),
                        turn: one,
                        right: 1.0,
                        left: 1.0,
                        curved_right: false,
                        curved_left: false,
                    },
                    Case {
                        name: "ellipse",
                        shape: Box::new(Ellipse::new(2.0, 1.0).unwrap()),
                        turn: one,
                        right: 1.0,
                        left: 1.0,
                        curved_right: true,
                        curved_left: true,
                    },
                    Case {
                        name: "half-ellipse",
                        // Turned -90 degrees: the flat side faces -x, the dome +x.
                        shape: Box::new(HalfEllipse::new(1.5, 0.75).unwrap()),
                        turn: (0.0, -1.0),
                        right: 0.75,
                        left: 0.0,
                        curved_right: true,
                        curved_left: false,
                    },
                    Case {
                        name: "slice",
                        shape: Box::new(Slice::new(1.25, 1.0).unwrap()),
                        turn: one,
                        right: 1.25,
                        left: 0.0,
                        curved_right: true,
                        curved_left: false,
                    },
                ]
            }

            fn rotate(c: R, s: R, p: (R, R)) -> (R, R) {
                (c * p.0 - s * p.1, s * p.0 + c * p.1)
            }

            /// A transform: the configuration's rotation by `angle`, then the
            /// shape's own turn, placed at `at` along the rotated x axis.
            fn place(angle: R, turn: (R, R), at: R) -> Transform<R> {
                let (c, s) = (angle.cos(), angle.sin());
                let (tc, ts) = (c * turn.0 - s * turn.1, s * turn.0 + c * turn.1);
                let (x, y) = rotate(c, s, (at, 0.0));
                Transform::from_cos_sin(v(x, y), tc, ts).unwrap()
            }

            fn tolerance(curved: bool, scale: R) -> R {
                let eps = R::EPSILON;
                if curved {
                    // Default epsilon 1e-6 (f32) / 1e-12 (f64) relative, plus rounding.
                    (if eps > 1e-10 { 1e-6 } else { 1e-12 }) * scale * 4.0 + 32.0 * eps * scale
                } else {
                    // Exact shapes: rounding only; the rotated placement itself
                    // rounds the positions by a few ulps of the offset.
                    32.0 * eps * scale
                }
            }

            const ANGLES: [R; 5] = [0.0, 0.3, 1.7, -2.4, 3.0];

            #[test]
            fn distance_every_pair() {
                let gjk = Gjk::<R>::new();
                let mut checked = 0;
                for a in cases() {
                    for b in cases() {
                        for &angle in ANGLES.iter() {
                            let gap = 0.375 as R;
                            let at = a.right + gap + b.left;
                            let ta = place(angle, a.turn, 0.0);
                            let tb = place(angle, b.turn, at);
                            let scale = at + a.left + b.right;
                            let tol = tolerance(a.curved_right || b.curved_left, scale);
                            let what = format!("{} vs {} at angle {angle}", a.name, b.name);
                            let sep = gjk
                                .distance(&*a.shape, &ta, &*b.shape, &tb)
                                .unwrap_or_else(|| panic!("{what}: reported overlapping"));
                            assert!(sep.status.is_converged(), "{what}: {:?}", sep.status);
                            assert!((sep.distance - gap).abs() <= tol, "{what}: distance {} vs {gap}", sep.distance);
                            let expected_normal = v(angle.cos(), angle.sin());
                            assert!((sep.normal - expected_normal).length() <= 1e-3, "{what}: normal {:?}", sep.normal);
                            // Closest points: on the rotated axis, gap apart.
                            assert!(
                                ((sep.point_b - sep.point_a).length() - gap).abs() <= tol * 4.0,
                                "{what}: points {:?} {:?}",
                                sep.point_a,
                                sep.point_b
                            );
                            let det = gjk.intersects(&*a.shape, &ta, &*b.shape, &tb);
                            assert!(!det.intersecting && det.status.is_converged(), "{what}: {det:?}");
                            assert!(
                                gjk.penetration(&*a.shape, &ta, &*b.shape, &tb).is_none(),
                                "{what}: penetration reported"
                            );
                            checked += 1;
                        }
                    }
                }
                assert_eq!(checked, 81 * ANGLES.len());
            }

            /// With a detect margin, shapes count as intersecting up to
            /// `epsilon` times the pair's size (the larger bounding radius)
            /// apart: a gap a tenth inside the margin intersects, a tenth
            /// outside does not; with the default (no margin) a gap of a
            /// millionth of the size does not either. Sharp pairs take the
            /// margin alone, rounded and curved ones add it to their radii.
            #[test]
            fn detect_margin_every_pair() {
                let epsilon = 0.01 as R;
                let mut config = GjkConfig::<R>::default();
                config.set_detect_epsilon(epsilon).unwrap();
                let with_margin = Gjk::with_solver(config, Epa::default());
                let without = Gjk::<R>::new();
                for a in cases() {
                    for b in cases() {
                        let margin = epsilon * a.shape.bounding_radius().max(b.shape.bounding_radius());
                        for &angle in ANGLES.iter() {
                            let what = format!("{} vs {} at angle {angle}", a.name, b.name);
                            let ta = place(angle, a.turn, 0.0);
                            let test = |gjk: &Gjk<R>, gap: R| {
                                let tb = place(angle, b.turn, a.right + gap + b.left);
                                let det = gjk.intersects(&*a.shape, &ta, &*b.shape, &tb);
                                assert!(det.status.is_converged(), "{what}, gap {gap}: {det:?}");
                                det.intersecting
                            };
                            assert!(test(&with_margin, 0.9 * margin), "{what}: a gap inside the margin");
                            assert!(!test(&with_margin, 1.1 * margin), "{what}: a gap beyond the margin");
                            assert!(!test(&without, 1e-6 * margin / epsilon), "{what}: a gap with no margin");
                        }
                    }
                }
            }

            #[test]
            fn penetration_every_shape_into_a_block() {
                let gjk = Gjk::<R>::new();
                let block = Rectangle::new(40.0, 40.0).unwrap();
                for a in cases() {
                    for &angle in ANGLES.iter() {
                        let delta = 0.125 as R;
                        // The block's left face sits `delta` inside A's rightmost point.
                        let at = a.right - delta + 20.0;
                        let ta = place(angle, a.turn, 0.0);
                        let tb = place(angle, (1.0, 0.0), at);
                        let tol = tolerance(a.curved_right, 40.0);
                        let what = format!("{} into block at angle {angle}", a.name);
                        let p = gjk.penetration(&*a.shape, &ta, &block, &tb).unwrap_or_else(|| panic!("{what}: apart"));
                        assert!(p.status.is_converged(), "{what}: {:?}", p.status);
                        assert!((p.depth - delta).abs() <= tol, "{what}: depth {} vs {delta}", p.depth);
                        assert!(
                            (p.normal - v(angle.cos(), angle.sin())).length() <= 1e-3,
                            "{what}: normal {:?}",
                            p.normal
                        );
                        assert!(gjk.intersects(&*a.shape, &ta, &block, &tb).intersecting, "{what}");
                        assert!(gjk.distance(&*a.shape, &ta, &block, &tb).is_none(), "{what}");
                        // And the other way round: the normal flips.
                        let q = gjk.penetration(&block, &tb, &*a.shape, &ta).unwrap();
                        assert!((q.depth - delta).abs() <= tol, "{what} swapped: depth {}", q.depth);
                        assert!(
                            (q.normal + v(angle.cos(), angle.sin())).length() <= 1e-3,
                            "{what} swapped: normal {:?}",
                            q.normal
                        );
                    }
                }
            }

            #[test]
            fn rays_at_every_shape() {
                let gjk = Gjk::<R>::new();
                for b in cases() {
                    for &angle in ANGLES.iter() {
                        for closed_form in [true, false] {
                            let mut gjk = gjk;
                            gjk.closed_form_rays = closed_form;
                            let at = 3.0 as R;
                            let tb = place(angle, b.turn, at);
                            let (c, s) = (angle.cos(), angle.sin());
                            let ray = Ray::new(v(0.0, 0.0), v(c, s)).unwrap();
                            let what = format!("ray at {} (angle {angle}, closed form {closed_form})", b.name);
                            let cast = gjk.raycast(&ray, 0.0, &*b.shape, &tb);
                            let hit = cast.hit().unwrap_or_else(|| panic!("{what}: {cast:?}"));
                            let expected = at - b.left;
                            let curved = b.curved_left || !closed_form;
                            let tol = tolerance(curved, at + b.right) * 4.0;
                            assert!((hit.distance - expected).abs() <= tol, "{what}: t {} vs {expected}", hit.distance);
                            // Faces and smooth points have a definite normal; the
                            // slice's apex and the triangle's... left side is a face.
                            if b.name != "slice" && b.name != "polygon" {
                                assert!((hit.normal + v(c, s)).length() <= 2e-3, "{what}: normal {:?}", hit.normal);
                            }
                            // Too short: a miss. Starting inside: inside.
                            let short = gjk.raycast(&ray, expected * 0.5, &*b.shape, &tb);
                            assert_eq!(short.outcome, RayOutcome::Miss, "{what}: short ray");
                            // From the shape's center: inside.
                            let center = tb.transform_point(b.shape.reference_point() + b.shape.center());
                            let from_center = Ray::new(center, v(c, s)).unwrap();
                            let inside = gjk.raycast(&from_center, 0.0, &*b.shape, &tb);
                            assert_eq!(inside.outcome, RayOutcome::Inside, "{what}: from the center");
                        }
                    }
                }
            }
        }
    };
}

known_answer_suite!(f32_suite, f32, Vec2);
known_answer_suite!(f64_suite, f64, DVec2);
