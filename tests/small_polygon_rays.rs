//! A ray at a polygon of at most eight vertices, its type known when the
//! program is compiled, is clipped by every edge at once on hosts. Checked
//! here against the exact oracle: random convex polygons of 3 to 8 vertices
//! at scales 2^-40 to 2^13, near the origin and far from it, placed with and
//! without rotation; rays from inside and outside, aimed at the centre, at a
//! vertex, along an edge's line and nearly so, bounded and not. A verdict
//! the exact answer keeps under a shift of the ray by the bound must be
//! right, a hit within the bound of the exact distance (the conditioning of
//! grazing hits aside), its normal the unit outward normal of a face
//! through the hit point, and `Inside` only for an origin within the bound
//! of the polygon. The same rays through `dyn SupportMap` (the clip every
//! target takes) must agree with it, and so must the polygon's own
//! `cast_local_ray`.

#[path = "common/geo.rs"]
mod geo;
#[path = "common/small_polygon.rs"]
mod small_polygon;
use small_polygon::polygon;

use gjk2d::glam::{DVec2, Vec2};
use gjk2d::{Gjk, Polygon, Ray, RayOutcome, SupportMap, Transform};
use gjk2d_oracle::{pair, ray as oracle_ray, transform_shape, ExactShape, RayStatus, Shape};
use proptest::prelude::*;

type Pt = [f64; 2];

/// The ray: where it starts (units of the polygon's scale, from inside to
/// well outside), what it aims at (0: the centroid, 1: a vertex, 2: along
/// an edge, 3: an edge's line turned by a hair, 4: anywhere), which vertex
/// or edge, a jitter of the aim, its length (0: unbounded), an angle for the
/// polygon's placement (or none), an origin far away or not.
#[allow(clippy::type_complexity)]
fn ray_and_placement() -> impl Strategy<Value = ((i64, i64), u8, usize, f64, u32, Option<f64>, bool)> {
    (
        (-60i64..=60, -60i64..=60),
        0u8..5,
        0usize..8,
        -1.0f64..1.0,
        prop_oneof![Just(0u32), 1u32..=80],
        prop::option::of(0.0f64..6.3),
        prop::bool::ANY,
    )
}

macro_rules! ray_suite {
    ($name:ident, $r:ty, $vec:ident) => {
        proptest! {
            #![proptest_config(ProptestConfig::with_cases(4000))]
            #[test]
            fn $name(poly in polygon(), ((ox, oy), aim, pick, jitter, length, angle, far) in ray_and_placement()) {
                type R = $r;
                let eps = R::EPSILON as f64;
                let (scale, origin, pts) = (poly.scale(), poly.origin(far), poly.points());
                let v = |p: Pt| $vec::new(p[0] as R, p[1] as R);
                let polygon = Polygon::<R, 8>::new(&pts.iter().map(|&p| v(p)).collect::<Vec<_>>()).unwrap();
                let tp = match angle {
                    Some(t) => Transform::<R>::new(v(origin), t as R).unwrap(),
                    None => Transform::<R>::from_translation(v(origin)).unwrap(),
                };
                // The polygon in world coordinates, exactly as placed.
                let tr = tp.translation();
                let exact: ExactShape = transform_shape(&Shape::Polygon(pts.clone()), tp.cos() as f64, tp.sin() as f64, tr.x as f64, tr.y as f64);
                let (c, s) = (tp.cos() as f64, tp.sin() as f64);
                let world = |p: Pt| [c * p[0] - s * p[1] + tr.x as f64, s * p[0] + c * p[1] + tr.y as f64];
                let wv: Vec<Pt> = pts.iter().map(|&p| world(p)).collect();
                let n = wv.len();
                let centroid = [wv.iter().map(|p| p[0]).sum::<f64>() / n as f64, wv.iter().map(|p| p[1]).sum::<f64>() / n as f64];
                let start = world([ox as f64 * scale * 0.5, oy as f64 * scale * 0.5]);
                let (p0, p1) = (wv[pick % n], wv[(pick + 1) % n]);
                let target = match aim {
                    0 => centroid,
                    1 => p0,
                    _ => [p0[0] + jitter * scale * 0.01, p0[1] - jitter * scale * 0.01],
                };
                let (from, dir) = match aim {
                    // Along an edge's line, or turned by a hair, from beyond its end.
                    2 | 3 => {
                        let e = [p1[0] - p0[0], p1[1] - p0[1]];
                        let turn = if aim == 3 { jitter * 1e-4 } else { 0.0 };
                        let d = [e[0] - turn * e[1], e[1] + turn * e[0]];
                        ([p0[0] - 2.0 * d[0], p0[1] - 2.0 * d[1]], d)
                    }
                    4 => (start, [jitter, 1.0 - jitter.abs()]),
                    _ => (start, [target[0] - start[0], target[1] - start[1]]),
                };
                if dir[0] == 0.0 && dir[1] == 0.0 {
                    return Err(TestCaseError::reject("no direction"));
                }
                let Ok(ray) = Ray::<R>::new(v(from), v(dir)) else { return Err(TestCaseError::reject("direction rounds to zero")) };
                let (o, d) = (ray.origin(), ray.direction());
                let (o, d): (Pt, Pt) = ([o.x as f64, o.y as f64], [d.x as f64, d.y as f64]);
                let max = (length as f64 * scale * 0.25) as R;
                let exact_ray = oracle_ray(o, d, max as f64, &exact);

                let extent = wv.iter().map(|p| (p[0] - wv[0][0]).hypot(p[1] - wv[0][1])).fold(0.0, f64::max);
                let l = extent.max((o[0] - wv[0][0]).hypot(o[1] - wv[0][1]));
                let t_far = if exact_ray.t.is_finite() { exact_ray.t } else { 0.0 };
                let placement = if angle.is_some() { 4.0 * eps * (l + extent + t_far) } else { 0.0 };
                let bound = 8.0 * eps * l + placement + 4.0 * f64::EPSILON * (l + origin[0].abs() + origin[1].abs());
                let shifted = |sh: Pt| oracle_ray([o[0] + sh[0], o[1] + sh[1]], d, max as f64, &exact);
                let perturbed: Vec<_> = [[-d[1], d[0]], [d[1], -d[0]], d, [-d[0], -d[1]]]
                    .iter()
                    .map(|u| shifted([u[0] * bound, u[1] * bound]))
                    .collect();
                let robust = exact_ray.margin > bound && perturbed.iter().all(|q| q.status == exact_ray.status);

                let gjk = Gjk::<R>::new();
                let dynamic: &dyn SupportMap<R> = &polygon;
                let fast = gjk.raycast(&ray, max, &polygon, &tp);
                let clip = gjk.raycast(&ray, max, dynamic, &tp);
                for (cast, path) in [(clip, "clip"), (fast, "all edges at once")] {
                    let ctx = || format!("{path}: ray {o:?} -> {d:?} max {max:e} at {pts:?} placed {tp:?} (world {wv:?}); oracle {exact_ray:?}; bound {bound:e}; {cast:?}");
                    prop_assert!(cast.status.is_converged() && cast.iterations == 0, "{}", ctx());
                    let got = match cast.outcome {
                        RayOutcome::Hit(_) => RayStatus::Hit,
                        RayOutcome::Miss => RayStatus::Miss,
                        RayOutcome::Inside => RayStatus::Inside,
                    };
                    if robust {
                        prop_assert_eq!(got, exact_ray.status, "{}", ctx());
                    }
                    if got == RayStatus::Inside {
                        let outside = pair(&ExactShape::point(o), &exact).signed_distance;
                        prop_assert!(outside <= bound, "{}: inside, but the origin is {outside:e} outside", ctx());
                    }
                    if let RayOutcome::Hit(h) = cast.outcome {
                        let t = h.distance as f64;
                        let (nrm, p) = ([h.normal.x as f64, h.normal.y as f64], [h.point.x as f64, h.point.y as f64]);
                        prop_assert!(t.is_finite() && t >= 0.0 && (max <= 0.0 || t <= max as f64), "{}", ctx());
                        prop_assert!(((nrm[0].hypot(nrm[1])) - 1.0).abs() <= 4.0 * eps, "{}: normal not unit", ctx());
                        let pr = bound + 4.0 * eps * (p[0].abs() + p[1].abs());
                        let on = pair(&ExactShape::point(p), &exact).signed_distance;
                        prop_assert!(on.abs() <= pr + 4.0 * eps * t, "{}: hit point {on:e} off the boundary", ctx());
                        // Head-on within the bound (or the spread of the
                        // exact hit under a shift by it); towards tangency
                        // within the hit's own error bound.
                        if exact_ray.status == RayStatus::Hit {
                            let error = (t - exact_ray.t).abs();
                            let spread = perturbed.iter().filter(|q| q.status == RayStatus::Hit).map(|q| (q.t - exact_ray.t).abs()).fold(0.0, f64::max);
                            prop_assert!(error <= h.error_bound as f64, "{}: t {t:e}, exact {:e}, beyond its error bound", ctx(), exact_ray.t);
                            // Head-on within 8 eps L, but for rays along an
                            // edge's line or nearly so: at the vertex they
                            // pass within rounding, the face beyond grazes
                            // (see `grazing_past_a_vertex`).
                            let along_an_edge = aim == 2 || aim == 3;
                            let head_on = -(nrm[0] * d[0] + nrm[1] * d[1]) >= 0.5;
                            prop_assert!(along_an_edge || !head_on || error <= bound + 1.5 * spread, "{}: t {t:e}, exact {:e}", ctx(), exact_ray.t);
                        }
                        // A face's outward normal: the polygon lies behind its plane through the hit.
                        let reach = wv.iter().map(|q| q[0] * nrm[0] + q[1] * nrm[1]).fold(f64::MIN, f64::max);
                        let behind = reach - (nrm[0] * p[0] + nrm[1] * p[1]);
                        prop_assert!(behind.abs() <= pr + 8.0 * eps * (l + p[0].abs() + p[1].abs()), "{}: polygon reaches {behind:e} beyond the normal's plane", ctx());
                        prop_assert!(nrm[0] * d[0] + nrm[1] * d[1] <= 4.0 * eps, "{}: normal faces away from the ray", ctx());
                    }
                }
                // The polygon's own local cast, placed by hand where the
                // placement is a translation: the hit the ray cast places,
                // with a unit normal and a gap across the face that the
                // world bound covers at the hit's incidence.
                if angle.is_none() {
                    let local_origin = ray.origin() - tp.translation() - polygon.reference_point();
                    let limit = if max > 0.0 { max } else { R::INFINITY };
                    let local = polygon.cast_local_ray(local_origin, ray.direction(), limit).unwrap();
                    if robust {
                        prop_assert_eq!(core::mem::discriminant(&local.outcome), core::mem::discriminant(&clip.outcome));
                    }
                    if let (RayOutcome::Hit(l), RayOutcome::Hit(w)) = (local.outcome, clip.outcome) {
                        let ctx = || format!("local {l:?} against placed {w:?}");
                        prop_assert!((l.distance as f64 - w.distance as f64).abs() <= w.error_bound as f64, "{}", ctx());
                        prop_assert!((l.normal.length() as f64 - 1.0).abs() <= 4.0 * eps, "{}: normal not unit", ctx());
                        prop_assert!((l.normal - w.normal).length() as f64 <= 4.0 * eps, "{}", ctx());
                        let cos = l.normal.dot(ray.direction()).abs() as f64;
                        let covered = w.error_bound as f64 * cos * (1.0 + 1e-3);
                        prop_assert!(l.error_bound >= 0.0 && l.error_bound as f64 <= covered, "{}: gap beyond the bound", ctx());
                    }
                }
                // Both paths clip by the same quotients: where the verdict is
                // certain they agree, and the distances to rounding.
                if let (RayOutcome::Hit(f), RayOutcome::Hit(s)) = (fast.outcome, clip.outcome) {
                    prop_assert!((f.distance as f64 - s.distance as f64).abs() <= 2.0 * bound);
                }
                if robust {
                    prop_assert_eq!(core::mem::discriminant(&fast.outcome), core::mem::discriminant(&clip.outcome));
                }
            }
        }
    };
}

ray_suite!(small_polygon_rays_match_the_oracle_f32, f32, Vec2);
ray_suite!(small_polygon_rays_match_the_oracle_f64, f64, DVec2);

/// A ray that passes a vertex within rounding, along the line of the edge
/// beyond it (or 1e-4 rad off it), may in exact arithmetic enter through that
/// grazing edge rather than at the vertex, far later, or miss: the hit's
/// error bound must cover it, which the entered face's incidence alone did
/// not (found by the suite above, through both paths). Each case: the
/// polygon, its placement's angle, the ray, and the oracle's exact distance.
#[test]
fn grazing_past_a_vertex() {
    // Each case: the polygon, its placement's angle, the ray, the exact
    // distance; cast through the concrete type and through `dyn`.
    macro_rules! check {
        ($r:ty, $vec:ident, $vertices:expr, $angle:expr, $origin:expr, $direction:expr, $exact:expr) => {{
            let polygon = Polygon::<$r, 8>::new(&$vertices.map(|p: [$r; 2]| $vec::new(p[0], p[1]))).unwrap();
            let placed = Transform::<$r>::new($vec::ZERO, $angle).unwrap();
            let ray = Ray::new($vec::new($origin[0], $origin[1]), $vec::new($direction[0], $direction[1])).unwrap();
            let dynamic: &dyn SupportMap<$r> = &polygon;
            for cast in [
                Gjk::<$r>::new().raycast(&ray, 0.0, &polygon, &placed),
                Gjk::<$r>::new().raycast(&ray, 0.0, dynamic, &placed),
            ] {
                let RayOutcome::Hit(hit) = cast.outcome else { panic!("a hit: {cast:?}") };
                let error = (hit.distance as f64 - $exact).abs();
                assert!(error <= hit.error_bound as f64, "error {error:e}, error_bound {:e}", hit.error_bound);
            }
        }};
    }
    check!(
        f64,
        DVec2,
        [[-1.5, 0.0], [1.5, -0.375], [-1.5, 1.0]],
        0.616226895087313f64.atan2(-0.7875686724159677),
        [-3.981151045338925, 7.082804681608274],
        [0.45921153808182985, -0.8883269461704514],
        6.600189392095721
    );
    check!(
        f32,
        Vec2,
        [[-1.625, -1.25], [-0.25, -0.625], [0.0, 0.0]],
        0.9824928f32.atan2(-0.1863004),
        [3.271_362_8_f32, -3.832_608],
        [-0.576_182_1_f32, 0.817_321_4],
        3.0208476869397503
    );
}

/// A ray along a sliver's face, outside it by 4.5e-8 (less than rounding),
/// passes its sharp tip: the clip enters through the other face at the tip,
/// whose line the ray crosses 2.4e-5 beyond the tip. The hit may stand (its
/// bound covers the miss), but its point must be on the polygon: the tip,
/// not a point on the line past it (found by the f32 suite above).
#[test]
fn along_a_sliver_past_its_tip() {
    let vertices = [[0.25f32, -1.5], [1.5, 1.875], [0.375, -1.125]];
    let polygon = Polygon::<f32, 8>::new(&vertices.map(|p| Vec2::new(p[0], p[1]))).unwrap();
    let ray = Ray::new(Vec2::new(3.75, 7.875), Vec2::new(-0.351_123_45, -0.936_329_2)).unwrap();
    let exact = Shape::Polygon(vertices.iter().map(|p| [p[0] as f64, p[1] as f64]).collect());
    let exact = transform_shape(&exact, 1.0, 0.0, 0.0, 0.0);
    let dynamic: &dyn SupportMap<f32> = &polygon;
    for cast in [
        Gjk::<f32>::new().raycast(&ray, 0.0, &polygon, &Transform::IDENTITY),
        Gjk::<f32>::new().raycast(&ray, 0.0, dynamic, &Transform::IDENTITY),
    ] {
        if let RayOutcome::Hit(hit) = cast.outcome {
            let off = pair(&ExactShape::point([hit.point.x as f64, hit.point.y as f64]), &exact).signed_distance;
            assert!(off.abs() <= 8.0 * f32::EPSILON as f64 * 10.0, "{cast:?}: the point is {off:e} off the boundary");
        }
    }
}
