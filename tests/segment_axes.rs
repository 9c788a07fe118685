//! A capsule or a segment against a polygon of at most eight vertices, both
//! types known when the program is compiled, is answered on hosts by the
//! separating axes of the segment core and the polygon: the intersection
//! test of a segment, and the penetration (EPA as the solver) of both
//! wherever the axes decide: cores that overlap, or an axis that parts them
//! by more than the radius. Checked here against the exact oracle: random
//! polygons of 3 to 8 vertices and random segments at scales from 2^-40 to
//! 2^13, near the origin and far from it, placed with and without rotation,
//! either shape as A, radii from zero (segments) to twice the polygon's
//! size. Every verdict beyond 8 eps L must be right, every depth within
//! 8 eps L (plus the placement's rounding) of the exact one, and the normal
//! must give that depth. The same pairs through `dyn SupportMap` (GJK and
//! EPA) must agree with them. The distance of the same pairs, both ways,
//! must be within the bound (and its error bound) of the exact distance,
//! its normal must part the shapes by it and its points lie that far apart
//! along it.

#[path = "common/geo.rs"]
mod geo;
#[path = "common/penetration_check.rs"]
mod penetration_check;
#[path = "common/small_polygon.rs"]
mod small_polygon;
use penetration_check::{check_penetration, reach};
use small_polygon::{polygon, Spec};

use gjk2d::glam::{DVec2, Vec2};
use gjk2d::{Capsule, Gjk, Polygon, Segment, SupportMap, Transform};
use gjk2d_oracle::{pair, transform_shape, Shape};
use proptest::prelude::*;

type Pt = [f64; 2];

/// The segment's ends (units of the polygon's scale), its radius (0: a
/// segment; else eighths of the scale), B's shift, its angle (or none), far
/// from the origin or not, and whether the segment is A.
#[allow(clippy::type_complexity)]
fn segment_and_placement() -> impl Strategy<Value = ((i64, i64, i64, i64), u32, (i64, i64), Option<f64>, bool, bool)> {
    (
        (-12i64..=12, -12i64..=12, -12i64..=12, -12i64..=12),
        prop_oneof![Just(0u32), 1u32..=16],
        (-30i64..=30, -30i64..=30),
        prop::option::of(0.0f64..6.3),
        prop::bool::ANY,
        prop::bool::ANY,
    )
}

macro_rules! segment_suite {
    ($name:ident, $r:ty, $vec:ident) => {
        proptest! {
            #![proptest_config(ProptestConfig::with_cases(3000))]
            #[test]
            fn $name(poly in polygon(), ((x0, y0, x1, y1), eighths, (sx, sy), angle, far, segment_is_a) in segment_and_placement()) {
                type R = $r;
                let eps = R::EPSILON as f64;
                if (x0, y0) == (x1, y1) {
                    return Err(TestCaseError::reject("a point, not a segment"));
                }
                let scale = (2.0f64).powi(poly.scale_exp - 3);
                let origin: Pt = if far { [(1 << 16) as f64 * scale, -((1 << 15) as f64) * scale] } else { [0.0, 0.0] };
                let pts = |s: &Spec| -> Vec<Pt> { s.hull.iter().map(|&(x, y)| [x as f64 * scale, y as f64 * scale]).collect() };
                let pp = pts(&poly);
                let (s0, s1): (Pt, Pt) = ([x0 as f64 * scale, y0 as f64 * scale], [x1 as f64 * scale, y1 as f64 * scale]);
                let radius = eighths as f64 * scale * 0.125;
                let v = |p: Pt| $vec::new(p[0] as R, p[1] as R);
                let polygon = Polygon::<R, 8>::new(&pp.iter().map(|&p| v(p)).collect::<Vec<_>>()).unwrap();
                let segment = Segment::<R>::new(v(s0), v(s1)).unwrap();
                let capsule = (eighths > 0).then(|| Capsule::<R>::new(v(s0), v(s1), radius as R).unwrap());
                let rounded: &dyn SupportMap<R> = match capsule { Some(ref c) => c, None => &segment };

                let t_first = Transform::<R>::from_translation(v(origin)).unwrap();
                let shift = [origin[0] + sx as f64 * scale * 0.5, origin[1] + sy as f64 * scale * 0.5];
                let t_second = match angle {
                    Some(t) => Transform::<R>::new(v(shift), t as R).unwrap(),
                    None => Transform::<R>::from_translation(v(shift)).unwrap(),
                };
                let (t_segment, t_polygon) = if segment_is_a { (t_first, t_second) } else { (t_second, t_first) };
                let exact = |shape: Shape, t: &Transform<R>| {
                    let tr = t.translation();
                    transform_shape(&shape, t.cos() as f64, t.sin() as f64, tr.x as f64, tr.y as f64)
                };
                let e_segment = exact(Shape::Capsule { a: s0, b: s1, radius }, &t_segment);
                let e_polygon = exact(Shape::Polygon(pp.clone()), &t_polygon);
                let truth = if segment_is_a { pair(&e_segment, &e_polygon) } else { pair(&e_polygon, &e_segment) };
                // World points, in f64 (the rotation's rounding is in the bound).
                let world = |p: Pt, t: &Transform<R>| {
                    let (c, s, tr) = (t.cos() as f64, t.sin() as f64, t.translation());
                    [c * p[0] - s * p[1] + tr.x as f64, s * p[0] + c * p[1] + tr.y as f64]
                };
                let wp: Vec<Pt> = pp.iter().map(|&p| world(p, &t_polygon)).collect();
                let ws = [world(s0, &t_segment), world(s1, &t_segment)];
                let extent = |w: &[Pt]| w.iter().map(|p| (p[0] - w[0][0]).hypot(p[1] - w[0][1])).fold(0.0, f64::max);
                let l = (extent(&wp) + radius).max(extent(&ws) + radius).max((ws[0][0] - wp[0][0]).hypot(ws[0][1] - wp[0][1]) + radius);
                let placement = if angle.is_some() { 4.0 * eps * (l + extent(&wp) + extent(&ws)) } else { 0.0 };
                let bound = 8.0 * eps * l + placement + 4.0 * f64::EPSILON * (l + origin[0].abs() + origin[1].abs());

                let gjk = Gjk::<R>::new();
                let dynamic: &dyn SupportMap<R> = &polygon;
                // A query of the known types (fast paths on hosts) and the
                // same through `dyn SupportMap`, the segment A or B.
                macro_rules! both {
                    ($query:ident) => {
                        match (&capsule, segment_is_a) {
                            (Some(c), true) => (gjk.$query(c, &t_segment, &polygon, &t_polygon), gjk.$query(rounded, &t_segment, dynamic, &t_polygon)),
                            (Some(c), false) => (gjk.$query(&polygon, &t_polygon, c, &t_segment), gjk.$query(dynamic, &t_polygon, rounded, &t_segment)),
                            (None, true) => (gjk.$query(&segment, &t_segment, &polygon, &t_polygon), gjk.$query(rounded, &t_segment, dynamic, &t_polygon)),
                            (None, false) => (gjk.$query(&polygon, &t_polygon, &segment, &t_segment), gjk.$query(dynamic, &t_polygon, rounded, &t_segment)),
                        }
                    };
                }
                let (fast, slow) = both!(intersects);
                for (det, path) in [(fast, "axes"), (slow, "gjk")] {
                    if truth.signed_distance > bound {
                        prop_assert!(!det.intersecting, "{path}: says overlap, exact distance {}", truth.signed_distance);
                    }
                    if truth.signed_distance < -bound {
                        prop_assert!(det.intersecting, "{path}: says apart, exact depth {}", -truth.signed_distance);
                    }
                }
                let (fast, slow) = both!(penetration);
                let (wa, wb, ra, rb) = if segment_is_a { (&ws[..], &wp[..], radius, 0.0) } else { (&wp[..], &ws[..], 0.0, radius) };
                for (pen, path) in [(fast, "axes"), (slow, "epa")] {
                    let answer = pen.map(|p| (p.depth as f64, [p.normal.x as f64, p.normal.y as f64], p.status.is_converged()));
                    check_penetration(path, answer, truth.signed_distance, truth.depth, bound, |n| reach(wa, ra, n), |n| reach(wb, rb, n))
                        .map_err(TestCaseError::fail)?;
                }
                if let (Some(f), Some(s)) = (fast, slow) {
                    prop_assert!((f.depth as f64 - s.depth as f64).abs() <= 2.0 * bound);
                }
                let (fast, slow) = both!(distance);
                for (separation, path) in [(fast, "known types"), (slow, "dyn")] {
                    let Some(sep) = separation else {
                        prop_assert!(truth.signed_distance <= bound, "{path}: no distance, exact {}", truth.signed_distance);
                        continue;
                    };
                    let (got, allowed) = (sep.distance as f64, bound + sep.error_bound as f64);
                    prop_assert!(truth.signed_distance >= -bound, "{path}: distance {got}, exact depth {}", -truth.signed_distance);
                    prop_assert!((got - truth.signed_distance).abs() <= allowed, "{path}: distance {got}, exact {}, bound {allowed}", truth.signed_distance);
                    // The normal parts them by the distance, and the points
                    // lie that far apart along it.
                    let n = [sep.normal.x as f64, sep.normal.y as f64];
                    let gap = -reach(wb, rb, [-n[0], -n[1]]) - reach(wa, ra, n);
                    prop_assert!((gap - got).abs() <= 2.0 * allowed, "{path}: gap {gap} along the normal, distance {got}");
                    // World points round at the scale of where they are.
                    let (pa, pb) = (sep.point_a, sep.point_b);
                    let where_ = 4.0 * eps * (pa.x.abs() + pa.y.abs()) as f64;
                    let apart = [pb.x as f64 - pa.x as f64 - got * n[0], pb.y as f64 - pa.y as f64 - got * n[1]];
                    prop_assert!(apart[0].hypot(apart[1]) <= 4.0 * allowed + where_, "{path}: points {:?} {:?}, distance {got}", pa, pb);
                }
            }
        }
    };
}

segment_suite!(segment_axes_match_the_oracle_f32, f32, Vec2);
segment_suite!(segment_axes_match_the_oracle_f64, f64, DVec2);

#[path = "common/rng.rs"]
mod rng;

/// The capsule's closed-form intersection test against the exact verdict
/// where it is decided: segments all around 3- to 8-gons (ends beside edges
/// and in corner regions, crossing, end-on, parallel to an edge), radii
/// within a few percent of the exact distance between the cores either way,
/// the capsule as A and as B, placed with and without rotation, f32 and
/// f64. The same pairs through `dyn SupportMap` (GJK) must agree wherever
/// the verdict is decided.
#[test]
fn capsule_intersection_test_matches_the_exact_verdict() {
    use rng::{cases, polygon_about_origin, Rng};
    use std::f64::consts::TAU;
    macro_rules! run {
        ($r:ty, $vec:ident) => {{
            type R = $r;
            let eps = R::EPSILON as f64;
            let v = |p: Pt| $vec::new(p[0] as R, p[1] as R);
            let gjk = Gjk::<R>::new();
            let mut rng = Rng(0x6361_7073_756c_65 ^ eps.to_bits());
            let (mut apart, mut touching) = (0, 0);
            for i in 0..cases(20_000) {
                let n = 3 + (i % 6) as usize;
                let pts: Vec<Pt> = polygon_about_origin(&mut rng, n, |x| x as R as f64);
                let Ok(polygon) = Polygon::<R, 8>::new(&pts.iter().map(|&p| v(p)).collect::<Vec<_>>()) else {
                    continue;
                };
                // One end around the polygon; the other along a random
                // direction, or along one of its edges (parallel faces).
                let round = |p: Pt| [p[0] as R as f64, p[1] as R as f64];
                let (t, reach) = (rng.range(0.0, TAU), rng.range(0.0, 3.0));
                let s0 = round([reach * t.cos(), reach * t.sin()]);
                let length = rng.range(0.05, 3.0);
                let heading = if i % 4 == 0 {
                    let k = (rng.next() % n as u64) as usize;
                    let (p, q) = (pts[k], pts[(k + 1) % n]);
                    (q[1] - p[1]).atan2(q[0] - p[0])
                } else {
                    rng.range(0.0, TAU)
                };
                let s1 = round([s0[0] + length * heading.cos(), s0[1] + length * heading.sin()]);
                if s0 == s1 {
                    continue;
                }
                let ep = transform_shape(&Shape::Polygon(pts.clone()), 1.0, 0.0, 0.0, 0.0);
                let core = transform_shape(&Shape::Capsule { a: s0, b: s1, radius: 0.0 }, 1.0, 0.0, 0.0, 0.0);
                let d = pair(&core, &ep).signed_distance;
                let radius = ((d.max(0.0) * rng.range(0.95, 1.05)).max(1e-3)) as R as f64;
                let capsule = Capsule::<R>::new(v(s0), v(s1), radius as R).unwrap();
                let truth = pair(&transform_shape(&Shape::Capsule { a: s0, b: s1, radius }, 1.0, 0.0, 0.0, 0.0), &ep);
                // Both shapes turned and moved alike: the verdict is the same.
                let (angle, shift) = if i % 2 == 0 { (0.0, [0.0, 0.0]) } else { (rng.range(0.0, TAU), [0.75, -2.5]) };
                let place = Transform::<R>::new(v(shift), angle as R).unwrap();
                let l = 6.0f64.max(radius);
                let bound = 8.0 * eps * l;
                let dynamic: (&dyn SupportMap<R>, &dyn SupportMap<R>) = (&capsule, &polygon);
                let verdicts = [
                    gjk.intersects(&capsule, &place, &polygon, &place).intersecting,
                    gjk.intersects(&polygon, &place, &capsule, &place).intersecting,
                    gjk.intersects(dynamic.0, &place, dynamic.1, &place).intersecting,
                    gjk.intersects(dynamic.1, &place, dynamic.0, &place).intersecting,
                ];
                let case = format!("{pts:?} {s0:?} {s1:?} {radius} {angle}");
                if truth.signed_distance > bound {
                    apart += 1;
                    assert!(
                        verdicts.iter().all(|&x| !x),
                        "{verdicts:?}, exact distance {}: {case}",
                        truth.signed_distance
                    );
                } else if truth.signed_distance < -bound {
                    touching += 1;
                    assert!(verdicts.iter().all(|&x| x), "{verdicts:?}, exact depth {}: {case}", truth.depth);
                }
            }
            assert!(apart > cases(20_000) / 5 && touching > cases(20_000) / 5, "{apart} apart, {touching} overlapping");
        }};
    }
    run!(f32, Vec2);
    run!(f64, DVec2);
}
