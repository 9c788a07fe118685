//! `SupportMap::is_polytope` only lets code drop out; it never changes an
//! answer. Two checks, in f32 and f64:
//! - every shape that claims a polytope core gives a vertex id for every
//!   support direction (with and without a walking hint), and every curved
//!   one gives `NO_FEATURE` somewhere, so no claim is wrong either way (and
//!   the point, hinted or not, is as far along the direction as `support`);
//! - penetration of polytope pairs is bit-identical with the claim hidden
//!   behind a wrapper that keeps the default (false).

use gjk2d::glam::{DVec2, Vec2};
use gjk2d::*;

/// Forwards everything but `is_polytope`, which keeps the default (false).
struct Unclaimed<'s, R: Real>(&'s dyn SupportMap<R>);

impl<R: Real> SupportMap<R> for Unclaimed<'_, R> {
    fn support(&self, d: R::Vector) -> R::Vector {
        self.0.support(d)
    }
    fn support_feature(&self, d: R::Vector, near: u32) -> (R::Vector, u32) {
        self.0.support_feature(d, near)
    }
    fn center(&self) -> R::Vector {
        self.0.center()
    }
    fn bounding_radius(&self) -> R {
        self.0.bounding_radius()
    }
    fn radius(&self) -> R {
        self.0.radius()
    }
    fn reference_point(&self) -> R::Vector {
        self.0.reference_point()
    }
}

macro_rules! hint_suite {
    ($modname:ident, $r:ty, $vec:ident) => {
        mod $modname {
            use super::*;
            type R = $r;

            fn v(x: f64, y: f64) -> $vec {
                $vec::new(x as R, y as R)
            }

            /// Every built-in shape kind, with whether its core is a polytope.
            fn shapes() -> Vec<(&'static str, Box<dyn SupportMap<R>>, bool)> {
                let hexagon = Polygon::<R, 8>::regular(6, 0.9).unwrap();
                let sliver = Polygon::<R, 4>::new(&[v(0.0, 0.0), v(2.0, 0.0), v(2.0, 1e-3)]).unwrap();
                vec![
                    ("hexagon", Box::new(hexagon) as Box<dyn SupportMap<R>>, true),
                    ("sliver", Box::new(sliver), true),
                    ("circle", Box::new(Circle::at(v(0.1, -0.2), 0.7).unwrap()), true),
                    ("rectangle", Box::new(Rectangle::new(1.5, 0.5).unwrap()), true),
                    ("triangle", Box::new(Triangle::new(v(0.0, 0.0), v(1.0, 0.1), v(0.3, 0.8)).unwrap()), true),
                    ("segment", Box::new(Segment::new(v(-0.5, 0.2), v(0.6, -0.1)).unwrap()), true),
                    ("capsule", Box::new(Capsule::new(v(-0.5, 0.0), v(0.5, 0.0), 0.3).unwrap()), true),
                    ("rounded", Box::new(Rounded::new(Rectangle::new(1.0, 0.6).unwrap(), 0.2).unwrap()), true),
                    ("ellipse", Box::new(Ellipse::new(1.6, 0.8).unwrap()), false),
                    ("half ellipse", Box::new(HalfEllipse::new(1.6, 0.6).unwrap()), false),
                    ("slice", Box::new(Slice::new(1.0, 1.2).unwrap()), false),
                    ("rounded ellipse", Box::new(Rounded::new(Ellipse::new(1.0, 0.5).unwrap(), 0.1).unwrap()), false),
                ]
            }

            fn directions() -> impl Iterator<Item = $vec> {
                (0..720).map(|i| {
                    let a = i as f64 * core::f64::consts::TAU / 720.0;
                    v(a.cos(), a.sin())
                })
            }

            #[test]
            fn claims_match_the_support_ids() {
                for (name, shape, polytope) in shapes() {
                    assert_eq!(shape.is_polytope(), polytope, "{name}");
                    let mut previous = NO_FEATURE;
                    let mut curve_seen = false;
                    for d in directions() {
                        let (cold, id) = shape.support_feature(d, NO_FEATURE);
                        let (walked, near) = shape.support_feature(d, previous);
                        previous = near;
                        // With or without the hint, a point as far along d
                        // as `support`'s (ties may pick another vertex).
                        let top = shape.support(d).dot(d);
                        assert_eq!((cold.dot(d), walked.dot(d)), (top, top), "{name}");
                        curve_seen |= id == NO_FEATURE || near == NO_FEATURE;
                    }
                    assert_eq!(curve_seen, !polytope, "{name}: a support on a curve");
                }
            }

            #[test]
            fn the_claim_changes_no_penetration() {
                let gjk = Gjk::<R>::new();
                let shapes: Vec<_> = shapes().into_iter().filter(|s| s.2).collect();
                let mut compared = 0;
                for (name_a, a, _) in &shapes {
                    for (name_b, b, _) in &shapes {
                        for k in 0..24 {
                            let angle = k as f64 * 0.7;
                            let offset = v(0.05 * k as f64 - 0.6, 0.3 * (k as f64).sin());
                            let tb = Transform::new(offset, angle as R).unwrap();
                            let ta = Transform::IDENTITY;
                            let claimed = gjk.penetration(a.as_ref(), &ta, b.as_ref(), &tb);
                            let hidden = gjk.penetration(&Unclaimed(a.as_ref()), &ta, &Unclaimed(b.as_ref()), &tb);
                            assert_eq!(claimed, hidden, "{name_a} vs {name_b}, placement {k}");
                            compared += claimed.is_some() as u32;
                        }
                    }
                }
                // Most placements overlap: the comparison is not vacuous.
                assert!(compared > 1000, "{compared} overlapping placements");
            }
        }
    };
}

hint_suite!(f32_suite, f32, Vec2);
hint_suite!(f64_suite, f64, DVec2);
