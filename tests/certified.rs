//! A certified answer must be right: every answer that says
//! `Status::Converged` is within README's guarantee of the exact one, and an
//! answer stopped at its limit carries an `error_bound` that holds. In f32
//! and f64 (one macro, one suite per precision).
//!
//! Three families:
//! - dense polygons: 256 to 4096 vertices on ellipses and circles of many
//!   aspect ratios (nearly round ones have long, nearly collinear runs of
//!   vertices whose dot products tie to rounding), exact in f32, in world
//!   coordinates with identity transforms; intersection, distance,
//!   penetration and ray casts against the exact oracle (`gjk2d_oracle`),
//!   within `8 eps L`;
//! - large polygons (33 to 200 vertices) with their types known, where the
//!   penetration query starts from four supports: against the oracle, and
//!   against the same query through trait objects (GJK's start);
//! - the round-ellipse cases: an ellipse of equal axes (a disk, so
//!   the exact oracle answers it) around a circle's centre. Curved shapes
//!   at large, against every shape, are `tests/curved.rs`.
//!
//! The default case counts find a failure of one pair in 400 with
//! probability above 0.95. `GJK2D_LONG=N` multiplies every count by N (for
//! example `GJK2D_LONG=10 cargo test --release --features std --test certified`).

// `!(err <= allowed)`: a NaN error must fail the check.
#![allow(clippy::neg_cmp_op_on_partial_ord)]

use gjk2d::glam::{DVec2, Vec2};
use gjk2d::*;
use gjk2d_oracle::{pair, ray as oracle_ray, ExactShape, RayStatus, Shape};
use proptest::prelude::*;
use std::f64::consts::TAU;

#[path = "common/geo.rs"]
mod geo;
use geo::{integer_hull, norm, sub, Pt};

#[path = "common/rng.rs"]
mod rng;
use rng::{cases, Rng};

/// Aspect ratios of the dense polygons: round, nearly round (long nearly
/// collinear runs), and flat.
const ASPECTS: [f64; 8] = [1.0, 1.0 - 1e-6, 1.0 - 1e-4, 0.999, 0.9, 0.5, 0.1, 0.01];

/// Grid step of the dense polygons: coordinates are integers (below 2^24)
/// times this, exact in f32.
const STEP: f64 = 1.0 / (1u64 << 20) as f64;

/// A convex polygon of about `n` vertices on an ellipse of semi-axes
/// `2^20 * (1, aspect)` grid steps, turned by `phi`, centred at grid point
/// `c`: the integer hull of the rounded points, in world units.
fn dense_polygon(rng: &mut Rng, n: usize, aspect: f64, c: (i64, i64)) -> Vec<Pt> {
    let (a, b) = ((1u64 << 20) as f64, (1u64 << 20) as f64 * aspect);
    let phi = rng.range(0.0, TAU);
    let (cp, sp) = (phi.cos(), phi.sin());
    let jitter = rng.range(0.0, 0.9);
    let start = rng.range(0.0, TAU);
    let pts: Vec<(i64, i64)> = (0..n)
        .map(|i| {
            let t = start + TAU * (i as f64 + jitter * rng.range(-0.5, 0.5)) / n as f64;
            let (x, y) = (a * t.cos(), b * t.sin());
            (c.0 + (cp * x - sp * y).round() as i64, c.1 + (sp * x + cp * y).round() as i64)
        })
        .collect();
    integer_hull(pts).into_iter().map(|(x, y)| [x as f64 * STEP, y as f64 * STEP]).collect()
}

macro_rules! certified_suite {
    ($modname:ident, $r:ty, $vec:ident) => {
        mod $modname {
            use super::*;
            type R = $r;
            const EPS: f64 = <$r>::EPSILON as f64;

            fn v(p: Pt) -> $vec {
                $vec::new(p[0] as R, p[1] as R)
            }
            fn pt(p: $vec) -> Pt {
                [p.x as f64, p.y as f64]
            }
            fn q(x: f64) -> f64 {
                x as R as f64
            }

            /// What one answer is checked against.
            struct Truth {
                /// Exact signed distance: the distance apart, minus the depth.
                signed: f64,
                /// README's guarantee for this pair, absolute.
                bound: f64,
            }

            /// Checks `intersects`, `distance` and `penetration` of A and B
            /// (identity transforms) against the exact signed distance:
            /// through trait objects (`&dyn SupportMap`) or with the shapes'
            /// types known, whose paths differ.
            fn check_pair<A: SupportMap<R> + ?Sized, B: SupportMap<R> + ?Sized>(
                what: &str,
                a: &A,
                b: &B,
                truth: &Truth,
            ) -> Result<(), String> {
                let gjk = Gjk::<R>::new();
                let id = Transform::IDENTITY;
                let (signed, bound) = (truth.signed, truth.bound);
                let fail = |m: String| Err(format!("{what}: {m} (exact signed distance {signed:e}, bound {bound:e})"));
                let detection = gjk.intersects(a, &id, b, &id);
                if detection.status.is_converged() && signed.abs() > bound && detection.intersecting != (signed <= 0.0)
                {
                    return fail(format!("wrong verdict {detection:?}"));
                }
                match gjk.distance(a, &id, b, &id) {
                    Some(s) => {
                        let err = (s.distance as f64 - signed.max(0.0)).abs();
                        let allowed = if s.status.is_converged() { bound } else { s.error_bound as f64 + bound };
                        if !(err <= allowed) || (s.status.is_converged() && signed < -bound) {
                            return fail(format!("distance {s:?}: error {err:e}"));
                        }
                    }
                    None if signed > bound => return fail("distance None".into()),
                    None => {}
                }
                match gjk.penetration(a, &id, b, &id) {
                    Some(p) => {
                        let err = (p.depth as f64 - (-signed).max(0.0)).abs();
                        let allowed = if p.status.is_converged() { bound } else { p.error_bound as f64 + bound };
                        if !(err <= allowed) || (p.status.is_converged() && signed > bound) {
                            return fail(format!("penetration {p:?}: error {err:e}"));
                        }
                    }
                    None if signed < -bound => return fail("penetration None".into()),
                    None => {}
                }
                Ok(())
            }

            fn polygon(points: &[Pt]) -> Box<Polygon<R, 4096>> {
                let vs: Vec<$vec> = points.iter().map(|&p| v(p)).collect();
                Box::new(Polygon::new(&vs).expect("convex"))
            }

            /// One pair of dense polygons from a seed, checked with every
            /// query, and two rays at A.
            fn dense_pair(seed: u64) -> Result<(), String> {
                let mut rng = Rng(seed);
                let pick = |rng: &mut Rng| {
                    // Log-uniform: as many pairs of 256 to 1024 vertices as of 1024 to 4096.
                    let n = (256.0 * 16f64.powf(rng.unit())) as usize;
                    let aspect = ASPECTS[(rng.next() % ASPECTS.len() as u64) as usize];
                    (n, aspect)
                };
                let (na, aa) = pick(&mut rng);
                let (nb, ab) = pick(&mut rng);
                // Centres in world coordinates, up to 4 units out; B from A
                // at 0.6 to 2.3 times the semi-major axis.
                let ca = ((rng.range(-4.0, 4.0) / STEP) as i64, (rng.range(-4.0, 4.0) / STEP) as i64);
                let (angle, reach) = (rng.range(0.0, TAU), rng.range(0.6, 2.3) / STEP);
                let cb = (ca.0 + (reach * angle.cos()) as i64, ca.1 + (reach * angle.sin()) as i64);
                let pa = dense_polygon(&mut rng, na, aa, ca);
                let pb = dense_polygon(&mut rng, nb, ab, cb);
                let (a, b) = (polygon(&pa), polygon(&pb));
                let centers = norm(sub(pt(b.reference_point() + b.center()), pt(a.reference_point() + a.center())));
                let l = (a.bounding_radius() as f64).max(b.bounding_radius() as f64).max(centers);
                let exact = pair(&ExactShape::from(&Shape::Polygon(pa.clone())), &ExactShape::from(&Shape::Polygon(pb)));
                let truth = Truth { signed: exact.signed_distance, bound: 8.0 * EPS * l };
                let what = format!("seed {seed:#x}: {na} (aspect {aa}) against {nb} (aspect {ab}) vertices");
                check_pair::<dyn SupportMap<R>, dyn SupportMap<R>>(&what, &*a, &*b, &truth)?;
                // Rays from up to 3 units away, aimed within half the minor
                // axis of A's reference point's side of its centre.
                let exact_a = ExactShape::from(&Shape::Polygon(pa));
                let center = pt(a.reference_point() + a.center());
                for k in 0..2 {
                    let from = rng.range(0.0, TAU);
                    let o = [q(center[0] + 3.0 * from.cos()), q(center[1] + 3.0 * from.sin())];
                    let spread = 0.5 * aa.min(1.0);
                    let target = [center[0] + rng.range(-spread, spread), center[1] + rng.range(-spread, spread)];
                    let ray = Ray::new(v(o), v(sub(target, o))).unwrap();
                    let d = pt(ray.direction());
                    let exact = oracle_ray(o, d, 0.0, &exact_a);
                    let cast = Gjk::<R>::new().raycast(&ray, 0.0, &*a, &Transform::IDENTITY);
                    let l = (a.bounding_radius() as f64).max(norm(sub(o, center)));
                    // The clip divides by the entered face's normal along the
                    // ray: its rounding grows as the ray turns parallel to the face.
                    let incidence = (exact.normal[0] * d[0] + exact.normal[1] * d[1]).abs() / norm(d);
                    let bound = 8.0 * EPS * l / incidence.max(1e-300);
                    match (exact.status, cast.outcome) {
                        (RayStatus::Hit, RayOutcome::Hit(h)) => {
                            // Every hit within its own error bound; head-on
                            // (cos >= 0.5, where README promises 8 eps L)
                            // within the clip's model too. Nearer a tangent the
                            // model is no guarantee (`dense_pairs_found` has a
                            // seed beyond it, within the hit's error bound).
                            let err = (h.distance as f64 - exact.t / norm(d)).abs();
                            if !(err <= h.error_bound as f64) || (incidence >= 0.5 && !(err <= bound)) {
                                return Err(format!("{what}: ray {k} {o:?} -> {d:?}: {h:?}, exact {}, error {err:e}, bound {bound:e}", exact.t));
                            }
                        }
                        (RayStatus::Hit, other) if exact.margin > bound => {
                            return Err(format!("{what}: ray {k} {o:?} -> {d:?}: {other:?}, exact hit at {}", exact.t));
                        }
                        _ => {}
                    }
                }
                Ok(())
            }

            /// One pair of polygons too large for the walked axes (33 to 200
            /// vertices), their types known when compiled: the penetration
            /// query starts from four supports where they decide (apart, or
            /// enclosing the origin), else from GJK, as the manifold does.
            /// Deep, shallow, touching and apart; every query against the
            /// oracle, then the penetration against the same query through
            /// trait objects (GJK's start): the same verdict beyond the bound
            /// and, on the same face, the same depth within it; and the
            /// manifold's normal the penetration's.
            fn large_pair(seed: u64) -> Result<(), String> {
                let mut rng = Rng(seed);
                let pick = |rng: &mut Rng| {
                    let n = 33 + (rng.next() % 168) as usize;
                    (n, ASPECTS[(rng.next() % ASPECTS.len() as u64) as usize])
                };
                let ((na, aa), (nb, ab)) = (pick(&mut rng), pick(&mut rng));
                let ca = ((rng.range(-4.0, 4.0) / STEP) as i64, (rng.range(-4.0, 4.0) / STEP) as i64);
                // A quarter deep, the rest around touching (the reach of two
                // such ellipses along a line lies between 2 aspect and 2).
                let gap = if rng.next() % 4 == 0 { rng.range(0.0, 0.6) } else { rng.range(0.6, 2.2) };
                let angle = rng.range(0.0, TAU);
                let cb = (ca.0 + (gap * angle.cos() / STEP) as i64, ca.1 + (gap * angle.sin() / STEP) as i64);
                let (pa, pb) = (dense_polygon(&mut rng, na, aa, ca), dense_polygon(&mut rng, nb, ab, cb));
                let vertices = |points: &[Pt]| points.iter().map(|&p| v(p)).collect::<Vec<$vec>>();
                let a = Polygon::<R, 256>::new(&vertices(&pa)).expect("convex");
                let b = Polygon::<R, 256>::new(&vertices(&pb)).expect("convex");
                let centers = norm(sub(pt(b.reference_point() + b.center()), pt(a.reference_point() + a.center())));
                let l = (a.bounding_radius() as f64).max(b.bounding_radius() as f64).max(centers);
                let exact = pair(&ExactShape::from(&Shape::Polygon(pa)), &ExactShape::from(&Shape::Polygon(pb)));
                let truth = Truth { signed: exact.signed_distance, bound: 8.0 * EPS * l };
                let what = format!("seed {seed:#x}: {na} (aspect {aa}) against {nb} (aspect {ab}), gap {gap}");
                check_pair(&what, &a, &b, &truth)?;
                let (gjk, id) = (Gjk::<R>::new(), Transform::IDENTITY);
                let known = gjk.penetration(&a, &id, &b, &id);
                let (da, db): (&dyn SupportMap<R>, &dyn SupportMap<R>) = (&a, &b);
                let through_dyn = gjk.penetration(da, &id, db, &id);
                match (known, through_dyn) {
                    (Some(k), Some(d)) if k.normal == d.normal && (k.depth as f64 - d.depth as f64).abs() > truth.bound => {
                        return Err(format!("{what}: depth {} known, {} through dyn, same normal", k.depth, d.depth));
                    }
                    (Some(_), None) | (None, Some(_)) if exact.signed_distance.abs() > truth.bound => {
                        return Err(format!("{what}: {known:?} known, {through_dyn:?} through dyn"));
                    }
                    _ => {}
                }
                if let (Some(p), Ok(m)) = (known, gjk.manifold(&a, &id, &b, &id, 0.0)) {
                    if !m.points().is_empty() && (m.normal, m.iterations) != (p.normal, p.iterations) {
                        return Err(format!("{what}: manifold {m:?}, penetration {p:?}"));
                    }
                }
                Ok(())
            }

            /// The hinted support of a dense polygon along slowly turning
            /// directions (as GJK and EPA turn theirs), against the exact top:
            /// integer directions and grid vertices, dot products in i128. A
            /// vertex may fall short of the top only by an edge perpendicular
            /// to the direction within rounding: `2 eps |d|` times the longest
            /// edge.
            fn support_walk(seed: u64) -> Result<(), String> {
                let mut rng = Rng(seed);
                let n = (256.0 * 16f64.powf(rng.unit())) as usize;
                let aspect = ASPECTS[(rng.next() % ASPECTS.len() as u64) as usize];
                let c = ((rng.range(-4.0, 4.0) / STEP) as i64, (rng.range(-4.0, 4.0) / STEP) as i64);
                let pts = dense_polygon(&mut rng, n, aspect, c);
                let p = polygon(&pts);
                let grid = |i: u32| {
                    let w = pt(p.vertex(i as usize).unwrap());
                    ((w[0] / STEP) as i128, (w[1] / STEP) as i128)
                };
                let longest = (0..p.len())
                    .map(|i| norm(sub(pt(p.vertex((i + 1) % p.len()).unwrap()), pt(p.vertex(i).unwrap()))))
                    .fold(0.0, f64::max);
                let mut angle = rng.range(0.0, TAU);
                let mut hint = NO_FEATURE;
                for k in 0..400 {
                    angle += rng.range(-0.02, 0.02);
                    let m = 1i64 << 20;
                    let d = ((angle.cos() * m as f64) as i64, (angle.sin() * m as f64) as i64);
                    let (_, id) = p.support_feature(v([d.0 as f64, d.1 as f64]) - $vec::ZERO, hint);
                    hint = id;
                    let dot = |g: (i128, i128)| g.0 * d.0 as i128 + g.1 * d.1 as i128;
                    let top = (0..p.len() as u32).map(|i| dot(grid(i))).max().unwrap();
                    let miss = (top - dot(grid(id))) as f64 * STEP;
                    let allowed = 2.0 * EPS * norm([d.0 as f64, d.1 as f64]) * longest;
                    if !(miss <= allowed) {
                        return Err(format!(
                            "seed {seed:#x}: {} vertices (aspect {aspect}), direction {k} {d:?}: vertex {id} is {:e} L below the top (allowed {:e} L)",
                            p.len(), miss / m as f64 / p.bounding_radius() as f64, allowed / m as f64 / p.bounding_radius() as f64
                        ));
                    }
                }
                Ok(())
            }

            /// The cases: an ellipse of equal axes (a disk, so the
            /// oracle answers exactly) around a circle's centre, where GJK
            /// ran to its limit and penetration answered the circle's radius.
            #[test]
            fn round_ellipse_around_circle() {
                let curved = if EPS > 1e-10 { 1e-6 } else { 1e-12 };
                let cases = [
                    (0.28880954, 0.036373023, 0.16243558, 0.26654297),
                    (0.66774517, 0.022626728, -0.33718711, 0.087133542),
                    (0.80206865, 0.34119135, 0.40310079, 0.20586264),
                ];
                let mut failures = Vec::new();
                for (a, x, y, r) in cases {
                    let (a, c, r) = (q(a), [q(x), q(y)], q(r));
                    let ellipse = Ellipse::<R>::new((2.0 * a) as R, (2.0 * a) as R).unwrap();
                    let circle = Circle::<R>::at(v(c), r as R).unwrap();
                    let exact = pair(
                        &ExactShape::from(&Shape::Circle { center: [0.0, 0.0], radius: a }),
                        &ExactShape::from(&Shape::Circle { center: c, radius: r }),
                    );
                    let l = a.max(r + norm(c));
                    let truth = Truth { signed: exact.signed_distance, bound: curved * l + 8.0 * EPS * l };
                    let what = format!("ellipse {a} around circle {c:?} r {r}");
                    if let Err(e) = check_pair::<dyn SupportMap<R>, dyn SupportMap<R>>(&what, &ellipse, &circle, &truth) {
                        failures.push(e);
                    }
                }
                assert!(failures.is_empty(), "{}", failures.join("\n"));
            }

            /// Seeds random runs found; each must pass every check above.
            #[test]
            fn dense_pairs_found() {
                for seed in [0x3d69_3092_2836_5309u64] {
                    dense_pair(seed).unwrap();
                }
            }

            proptest! {
                #![proptest_config(ProptestConfig { cases: cases(600), failure_persistence: None, ..ProptestConfig::default() })]

                /// Dense polygons: 600 pairs per precision.
                #[test]
                fn dense_polygons(seed in any::<u64>()) {
                    let result = dense_pair(seed);
                    prop_assert!(result.is_ok(), "{}", result.unwrap_err());
                }

                /// Large polygons, types known: 600 pairs per precision.
                #[test]
                fn large_polygons_known(seed in any::<u64>()) {
                    let result = large_pair(seed);
                    prop_assert!(result.is_ok(), "{}", result.unwrap_err());
                }

                /// The walk itself, on 600 polygons per precision.
                #[test]
                fn dense_support_walk(seed in any::<u64>()) {
                    let result = support_walk(seed);
                    prop_assert!(result.is_ok(), "{}", result.unwrap_err());
                }
            }
        }
    };
}

certified_suite!(single, f32, Vec2);
certified_suite!(double, f64, DVec2);
