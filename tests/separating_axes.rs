//! Two polygons of at most eight vertices whose types are known when the
//! program is compiled are answered by their separating axes on hosts (the
//! intersection test, and penetration with EPA as the solver); up to 64
//! vertices, penetration walks them. Checked here against the exact oracle,
//! as the GJK and EPA path is in tests/properties.rs: random convex polygons
//! of 3 to 8 vertices, and of 9 to 64 (near an ellipse, many edges nearly
//! parallel, some vertices exactly on an edge between two others), at
//! scales from 1e-13 to 1e4, near the origin and far from it, placed with
//! and without rotation, about half of them overlapping and many touching. Every verdict beyond 8 eps L must
//! be right, every depth within 8 eps L (plus the placement's rounding) of
//! the exact one, and the normal must give that depth: the overlap of the
//! two placed polygons along it equals the depth. The same pairs through
//! `dyn SupportMap` (GJK and EPA) must agree with them within those bounds.

#[path = "common/geo.rs"]
mod geo;
#[path = "common/penetration_check.rs"]
mod penetration_check;
#[path = "common/small_polygon.rs"]
mod small_polygon;
use penetration_check::{check_penetration, reach};
use small_polygon::{polygon, Spec};

/// 9 to 64 vertices: the integer hull of points near an ellipse of radius
/// 1000 (so neighbouring edges are nearly parallel), with the midpoints of
/// some edges added where they are integer points (vertices exactly
/// collinear with their neighbours), at scales 2^-40 to 2^13.
fn medium_polygon() -> impl Strategy<Value = Spec> {
    let points = prop::collection::vec((0.0f64..std::f64::consts::TAU, -40i64..=40), 12..90);
    let splits = prop::collection::vec(prop::bool::weighted(0.3), 64);
    (points, splits, 0.3f64..1.0, -40i32..=13)
        .prop_map(|(points, splits, aspect, scale_exp)| {
            let near = points.iter().map(|&(t, r)| {
                let radius = (1000 + r) as f64;
                ((radius * t.cos()).round() as i64, (radius * aspect * t.sin()).round() as i64)
            });
            let hull = geo::integer_hull(near.collect());
            let mut split = Vec::new();
            for (k, &p) in hull.iter().enumerate() {
                let q = hull[(k + 1) % hull.len()];
                split.push(p);
                if splits[k % splits.len()] && (p.0 + q.0) % 2 == 0 && (p.1 + q.1) % 2 == 0 {
                    split.push(((p.0 + q.0) / 2, (p.1 + q.1) / 2));
                }
            }
            Spec { hull: split, scale_exp }
        })
        .prop_filter("9 to 64 vertices", |s| (9..=64).contains(&s.hull.len()))
}

use gjk2d::glam::{DVec2, Vec2};
use gjk2d::{Gjk, Polygon, SupportMap, Transform};
use gjk2d_oracle::{pair, transform_shape, Shape};
use proptest::prelude::*;

type Pt = [f64; 2];

/// Placement of B: a shift (in units of A's size), an angle (or none), an
/// origin far away or not.
fn placement() -> impl Strategy<Value = (i64, i64, Option<f64>, bool)> {
    (-30i64..=30, -30i64..=30, prop::option::of(0.0f64..6.3), prop::bool::ANY)
}

/// `$polygon` generates the shapes, of at most `$capacity` vertices, and
/// `$spread` scales the placement's shift to their size.
macro_rules! sat_suite {
    ($name:ident, $r:ty, $vec:ident, $polygon:expr, $capacity:literal, $spread:literal, $cases:literal) => {
        proptest! {
            #![proptest_config(ProptestConfig::with_cases($cases))]
            #[test]
            fn $name(a in $polygon, b in $polygon, (sx, sy, angle, far) in placement()) {
                type R = $r;
                let eps = R::EPSILON as f64;
                // Both at A's scale, so they meet; B's own scale only sets its
                // size relative to A's (within a factor 8).
                let scale = (2.0f64).powi(a.scale_exp - 3);
                let b_scale = scale * (2.0f64).powi((b.scale_exp % 4) - 1);
                let origin: Pt = if far { [(1 << 16) as f64 * scale, -((1 << 15) as f64) * scale] } else { [0.0, 0.0] };
                let pts = |s: &Spec, k: f64| -> Vec<Pt> { s.hull.iter().map(|&(x, y)| [x as f64 * k, y as f64 * k]).collect() };
                let (pa, pb) = (pts(&a, scale), pts(&b, b_scale));
                let v = |p: Pt| $vec::new(p[0] as R, p[1] as R);
                let poly_a = Polygon::<R, $capacity>::new(&pa.iter().map(|&p| v(p)).collect::<Vec<_>>()).unwrap();
                // B of a larger capacity: the axes take polygons by their vertex count.
                let poly_b = Polygon::<R, { 2 * $capacity }>::new(&pb.iter().map(|&p| v(p)).collect::<Vec<_>>()).unwrap();
                let ta = Transform::<R>::from_translation(v(origin)).unwrap();
                let shift = [origin[0] + (sx * $spread) as f64 * scale, origin[1] + (sy * $spread) as f64 * scale];
                let tb = match angle {
                    Some(t) => Transform::<R>::new(v(shift), t as R).unwrap(),
                    None => Transform::<R>::from_translation(v(shift)).unwrap(),
                };
                let exact = |poly: &[Pt], t: &Transform<R>| {
                    let (c, s) = (t.cos() as f64, t.sin() as f64);
                    let tr = t.translation();
                    (transform_shape(&Shape::Polygon(poly.to_vec()), c, s, tr.x as f64, tr.y as f64), (c, s, [tr.x as f64, tr.y as f64]))
                };
                let (ea, fa) = exact(&pa, &ta);
                let (eb, fb) = exact(&pb, &tb);
                let truth = pair(&ea, &eb);
                // World vertices, in f64 (the rotation's rounding is in the bound).
                let world = |poly: &[Pt], (c, s, t): (f64, f64, Pt)| -> Vec<Pt> {
                    poly.iter().map(|p| [c * p[0] - s * p[1] + t[0], s * p[0] + c * p[1] + t[1]]).collect()
                };
                let (wa, wb) = (world(&pa, fa), world(&pb, fb));
                let extent = |w: &[Pt]| w.iter().map(|p| (p[0] - w[0][0]).hypot(p[1] - w[0][1])).fold(0.0, f64::max);
                let l = extent(&wa).max(extent(&wb)).max((wb[0][0] - wa[0][0]).hypot(wb[0][1] - wa[0][1]));
                let rotated = angle.is_some();
                let placement = if rotated { 4.0 * eps * (l + extent(&wa) + extent(&wb)) } else { 0.0 };
                let bound = 8.0 * eps * l + placement + 4.0 * f64::EPSILON * (l + origin[0].abs() + origin[1].abs());

                let gjk = Gjk::<R>::new();
                let (da, db): (&dyn SupportMap<R>, &dyn SupportMap<R>) = (&poly_a, &poly_b);
                for (det, path) in [(gjk.intersects(&poly_a, &ta, &poly_b, &tb), "axes"), (gjk.intersects(da, &ta, db, &tb), "gjk")] {
                    if truth.signed_distance > bound {
                        prop_assert!(!det.intersecting, "{path}: says overlap, exact distance {}", truth.signed_distance);
                    }
                    if truth.signed_distance < -bound {
                        prop_assert!(det.intersecting, "{path}: says apart, exact depth {}", -truth.signed_distance);
                    }
                }
                let fast = gjk.penetration(&poly_a, &ta, &poly_b, &tb);
                let slow = gjk.penetration(da, &ta, db, &tb);
                for (pen, path) in [(fast, "axes"), (slow, "epa")] {
                    let answer = pen.map(|p| (p.depth as f64, [p.normal.x as f64, p.normal.y as f64], p.status.is_converged()));
                    check_penetration(path, answer, truth.signed_distance, truth.depth, bound, |n| reach(&wa, 0.0, n), |n| reach(&wb, 0.0, n))
                        .map_err(TestCaseError::fail)?;
                }
                if let (Some(f), Some(s)) = (fast, slow) {
                    prop_assert!((f.depth as f64 - s.depth as f64).abs() <= 2.0 * bound);
                }
            }
        }
    };
}

sat_suite!(separating_axes_match_the_oracle_f32, f32, Vec2, polygon(), 8, 1, 3000);
sat_suite!(separating_axes_match_the_oracle_f64, f64, DVec2, polygon(), 8, 1, 3000);
sat_suite!(walked_axes_match_the_oracle_f32, f32, Vec2, medium_polygon(), 64, 70, 1000);
sat_suite!(walked_axes_match_the_oracle_f64, f64, DVec2, medium_polygon(), 64, 70, 1000);

macro_rules! tiny_suite {
    ($name:ident, $r:ty, $vec:ident) => {
        proptest! {
            #![proptest_config(ProptestConfig::with_cases(500))]
            /// Polygons so small that their edges' squares underflow: the
            /// answers stay finite, the depth non-negative, the normal unit.
            #[test]
            fn $name(a in polygon(), b in polygon(), exp in -150i32..=-60, sx in -3i64..=3, sy in -3i64..=3) {
                type R = $r;
                let k = (2.0f64).powi(exp);
                let pts = |s: &Spec| -> Vec<$vec> { s.hull.iter().map(|&(x, y)| $vec::new((x as f64 * k) as R, (y as f64 * k) as R)).collect() };
                let (Ok(pa), Ok(pb)) = (Polygon::<R, 8>::new(&pts(&a)), Polygon::<R, 8>::new(&pts(&b))) else {
                    return Ok(()); // rounded to no area: refused, rightly
                };
                let tb = Transform::<R>::from_translation($vec::new((sx as f64 * k) as R, (sy as f64 * k) as R)).unwrap();
                let gjk = Gjk::<R>::new();
                let _ = gjk.intersects(&pa, &Transform::IDENTITY, &pb, &tb);
                if let Some(p) = gjk.penetration(&pa, &Transform::IDENTITY, &pb, &tb) {
                    prop_assert!(p.depth.is_finite() && p.depth >= 0.0, "depth {}", p.depth);
                    prop_assert!(p.normal.is_finite() && (p.normal.length() - 1.0).abs() < 1e-5, "normal {:?}", p.normal);
                }
            }
        }
    };
}

tiny_suite!(tiny_polygons_stay_finite_f32, f32, Vec2);
tiny_suite!(tiny_polygons_stay_finite_f64, f64, DVec2);
