//! Contact manifolds ([`Gjk::manifold`]) against the exact rational oracle
//! (`gjk2d_oracle`), in f32 and f64 (one macro, one suite per precision).
//!
//! What a manifold promises, and what is checked:
//! - every point lies on A's boundary, and `point + separation * normal` on
//!   B's, within `8 eps L` (the oracle's exact distance from the point to the
//!   boundary);
//! - the least separation is the exact signed distance (distance apart,
//!   minus the depth overlapping), within `8 eps L`;
//! - no separation exceeds the margin; a pair farther apart than the margin
//!   gives no point, one within it at least one;
//! - the normal is unit, and the exact one where that is unique;
//! - two faces that meet give the two ends of the region where they face
//!   each other, exactly, for inputs where every value is representable;
//! - the feature ids stay the same under a small motion.
//!
//! `L` is the pair's size: the larger bounding radius, or the distance of the
//! centers if larger (as in `tests/properties.rs`). Shapes are given in world
//! coordinates with identity transforms, every coordinate rounded to f32 so
//! the oracle sees exactly what gjk2d sees (the f64 suite widens the same
//! values); in the placed runs the placement's rounding comes on top,
//! `4 eps (|t_B - t_A| + e_A + e_B)`, and world points round by `4 eps |p|`
//! more. The seeded sweeps print the worst errors in units of `eps L`.

use gjk2d::glam::{DVec2, Vec2};
use gjk2d::*;
use gjk2d_oracle::{pair, transform_shape, ExactShape, Shape};
use proptest::prelude::*;
use std::f64::consts::TAU;

#[path = "common/geo.rs"]
mod geo;
#[path = "common/rng.rs"]
mod rng;
use geo::{norm, sub, Geo, Pt};
use rng::{cases, Rng};

fn r32(x: f64) -> f64 {
    x as f32 as f64
}
fn rp(p: Pt) -> Pt {
    [r32(p[0]), r32(p[1])]
}

/// The exact distance from `p` to the boundary of `shape` (inside or out):
/// the distance of a point core to it plus its depth in it.
fn boundary_distance(shape: &ExactShape, p: Pt) -> f64 {
    let answer = pair(&ExactShape::point(p), shape);
    answer.distance + answer.depth
}

/// A random shape of `kind` (0, 1: polygon; 2: circle; 3: capsule; 4:
/// segment) of about `size`, centered at `c`, every coordinate rounded to
/// f32.
fn random_shape(rng: &mut Rng, kind: u32, c: Pt, size: f64) -> Option<Geo> {
    let (a, b, phi) = (rng.range(0.2, 1.0) * size, rng.range(0.05, 1.0) * size, rng.range(0.0, TAU));
    let (cp, sp) = (phi.cos(), phi.sin());
    let place = |x: f64, y: f64| rp([c[0] + cp * x - sp * y, c[1] + sp * x + cp * y]);
    match kind {
        0 | 1 => {
            let count = 3 + (rng.next() % 7) as usize;
            let mut angles: Vec<f64> = (0..count).map(|_| rng.range(0.0, TAU)).collect();
            angles.sort_by(|x, y| x.partial_cmp(y).unwrap());
            let mut kept: Vec<f64> = Vec::new();
            for th in angles {
                if kept.last().is_none_or(|&l| th - l >= 0.1) {
                    kept.push(th);
                }
            }
            if kept.len() >= 2 && kept[0] + TAU - kept[kept.len() - 1] < 0.1 {
                kept.pop();
            }
            (kept.len() >= 3).then(|| Geo::Poly(kept.iter().map(|&th| place(a * th.cos(), b * th.sin())).collect()))
        }
        2 => Some(Geo::Circle(rp(c), r32(a))),
        3 => Some(Geo::Capsule(place(-a, 0.0), place(a, 0.0), r32(0.5 * b))),
        _ => Some(Geo::Segment(place(-a, 0.0), place(a, 0.0))),
    }
}

/// A fixed seed so CI is reproducible; `PROPTEST_RNG_SEED=<u64>` explores
/// other cases, `GJK2D_LONG=<n>` runs n times as many.
fn config(seed: u64) -> ProptestConfig {
    let seed = std::env::var("PROPTEST_RNG_SEED").ok().and_then(|s| s.parse().ok()).unwrap_or(seed);
    let cases = cases(200);
    // About a third of the parallel faces' draws are rejected: the cap
    // grows with the cases, so a long run is not cut short by it.
    ProptestConfig {
        cases,
        max_global_rejects: cases.max(1024),
        rng_seed: proptest::test_runner::RngSeed::Fixed(seed),
        ..ProptestConfig::default()
    }
}

/// Worst errors of a family, in units of `eps L`.
#[derive(Clone, Copy, Debug, Default)]
struct Worst {
    /// Distance of a point from A's boundary, and of its partner from B's.
    on_a: f64,
    on_b: f64,
    /// The least separation against the exact signed distance.
    separation: f64,
    /// The normal against the exact unique one (radians, not in eps L).
    normal: f64,
    pairs: u32,
    points: u32,
    /// Pairs with two points.
    two: u32,
}

impl Worst {
    fn merge(&mut self, o: Worst) {
        self.on_a = self.on_a.max(o.on_a);
        self.on_b = self.on_b.max(o.on_b);
        self.separation = self.separation.max(o.separation);
        self.normal = self.normal.max(o.normal);
        self.pairs += o.pairs;
        self.points += o.points;
        self.two += o.two;
    }
}

macro_rules! manifold_suite {
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

            fn build(g: &Geo) -> Option<Box<dyn SupportMap<R>>> {
                Some(match g {
                    Geo::Poly(pts) => {
                        let pts: Vec<$vec> = pts.iter().map(|&p| v(p)).collect();
                        if pts.len() > 16 {
                            Box::new(Polygon::<R, 64>::new(&pts).ok()?)
                        } else {
                            Box::new(Polygon::<R, 16>::new(&pts).ok()?)
                        }
                    }
                    Geo::Circle(c, r) => Box::new(Circle::at(v(*c), *r as R).ok()?),
                    Geo::Capsule(a, b, r) => Box::new(Capsule::new(v(*a), v(*b), *r as R).ok()?),
                    Geo::Segment(a, b) => Box::new(Segment::new(v(*a), v(*b)).ok()?),
                    Geo::Rounded(p, r) => Box::new(Rounded::new(Polygon::<R, 16>::new(&p.iter().map(|&q| v(q)).collect::<Vec<_>>()).ok()?, *r as R).ok()?),
                })
            }

            /// A shape placed by a transform, with its exact counterpart.
            struct Placed {
                shape: Box<dyn SupportMap<R>>,
                tf: Transform<R>,
                exact: ExactShape,
                /// Largest local coordinate, radius included.
                extent: f64,
            }

            impl Placed {
                fn new(geo: &Geo, tf: Transform<R>) -> Option<Self> {
                    let (cs, t) = ((tf.cos() as f64, tf.sin() as f64), pt(tf.translation()));
                    let exact = transform_shape(&geo.oracle(), cs.0, cs.1, t[0], t[1]);
                    Some(Self { shape: build(geo)?, tf, exact, extent: geo.extent() })
                }
                fn world(geo: &Geo) -> Option<Self> {
                    Self::new(geo, Transform::IDENTITY)
                }
                fn center(&self) -> Pt {
                    pt(self.tf.transform_point(self.shape.reference_point() + self.shape.center()))
                }
            }

            /// Checks the manifold of `a` and `b` within `margin` against the
            /// oracle; the errors it measured.
            fn check(a: &Placed, b: &Placed, margin: f64, what: &str) -> Result<Worst, TestCaseError> {
                let gjk = Gjk::<R>::new();
                let m = gjk
                    .manifold(&*a.shape, &a.tf, &*b.shape, &b.tf, margin as R)
                    .map_err(|e| TestCaseError::fail(format!("{what}: {e}")))?;
                check_manifold(&m, a, b, margin, what)
            }

            /// Checks a manifold of `a` and `b` within `margin`, however it
            /// was asked for (through trait objects or the shapes' types).
            fn check_manifold(m: &Manifold<R>, a: &Placed, b: &Placed, margin: f64, what: &str) -> Result<Worst, TestCaseError> {
                let exact = pair(&a.exact, &b.exact);
                let size = (a.shape.bounding_radius() as f64)
                    .max(b.shape.bounding_radius() as f64)
                    .max(norm(sub(b.center(), a.center())));
                // The placement's rounding, where there is one.
                let placed = if a.tf == Transform::IDENTITY && b.tf == Transform::IDENTITY {
                    0.0
                } else {
                    4.0 * EPS * (norm(sub(pt(b.tf.translation()), pt(a.tf.translation()))) + a.extent + b.extent)
                };
                let tol = 8.0 * EPS * size + placed;
                let n = pt(m.normal);
                let ctx = || format!("{what}: margin {margin:e}, exact {exact:?}, manifold {m:?}");
                prop_assert!(m.len <= 2 && m.points().len() == m.len, "{}", ctx());
                prop_assert!((norm(n) - 1.0).abs() <= 4.0 * EPS, "{}: normal not unit", ctx());
                prop_assert!(m.status.is_converged(), "{}", ctx());
                let sd = exact.signed_distance;
                if sd > margin + tol {
                    prop_assert!(m.is_empty(), "{}: apart beyond the margin, yet points", ctx());
                }
                if sd < margin - tol {
                    prop_assert!(!m.is_empty(), "{}: within the margin, yet no point", ctx());
                }
                let mut worst = Worst { pairs: 1, two: (m.len == 2) as u32, ..Worst::default() };
                let mut least = f64::INFINITY;
                for p in m.points() {
                    let (x, s) = (pt(p.point), p.separation as f64);
                    prop_assert!(x[0].is_finite() && x[1].is_finite() && s.is_finite(), "{}", ctx());
                    prop_assert!(s <= margin, "{}: separation {s:e} beyond the margin", ctx());
                    let across = [x[0] + s * n[0], x[1] + s * n[1]];
                    let rounding = tol + 4.0 * EPS * (norm(x) + s.abs());
                    let (da, db) = (boundary_distance(&a.exact, x), boundary_distance(&b.exact, across));
                    prop_assert!(da <= rounding, "{}: point {x:?} is {da:e} off A", ctx());
                    prop_assert!(db <= rounding, "{}: point {across:?} is {db:e} off B", ctx());
                    worst.on_a = worst.on_a.max(da / (EPS * size));
                    worst.on_b = worst.on_b.max(db / (EPS * size));
                    worst.points += 1;
                    least = least.min(s);
                }
                if !m.is_empty() {
                    let e = (least - sd).abs();
                    prop_assert!(e <= tol, "{}: least separation {least:e}, exact {sd:e}", ctx());
                    worst.separation = e / (EPS * size);
                    if exact.normal_unique {
                        // The query's normal, as its own suite bounds it: apart,
                        // the closest points' rounding over the distance.
                        let e = norm(sub(n, exact.normal));
                        prop_assert!(e <= 1e3 * EPS + 8.0 * tol / sd.abs(), "{}: normal off by {e:e}", ctx());
                        worst.normal = e;
                    }
                }
                Ok(worst)
            }

            /// How a random pair is placed.
            #[derive(Clone, Copy, Debug)]
            enum Family {
                /// In world coordinates, identity transforms.
                World,
                /// Both turned and moved together, B turned a little more.
                Placed,
                /// B is A turned half round: every edge of B is parallel to
                /// one of A, so faces meet often, as boxes resting do.
                Mirrored,
            }

            /// A random pair near contact: kinds, sizes and placement from `rng`.
            fn random_pair(rng: &mut Rng, scale: f64, family: Family) -> Option<(Placed, Placed, f64)> {
                let (ka, kb) = ((rng.next() % 5) as u32, (rng.next() % 5) as u32);
                let (sa, sb) = (scale * rng.range(0.3, 3.0), scale * rng.range(0.3, 3.0));
                let ga = random_shape(rng, ka, [0.0, 0.0], sa)?;
                let angle = rng.range(0.0, TAU);
                let reach = rng.range(0.3, 1.3) * (sa + sb);
                let towards = rp([reach * angle.cos(), reach * angle.sin()]);
                let gb = random_shape(rng, kb, towards, sb)?;
                let margin = r32(rng.range(0.0, 0.5) * scale);
                match family {
                    Family::World => Some((Placed::world(&ga)?, Placed::world(&gb)?, margin)),
                    Family::Placed => {
                        // Up to eight sizes away from the origin.
                        let (turn, t) = (rng.range(-4.0, 4.0), [rng.range(-8.0, 8.0) * scale, rng.range(-8.0, 8.0) * scale]);
                        let tf = Transform::new(v(t), turn as R).ok()?;
                        let turn_b = turn + rng.range(-0.01, 0.01);
                        let tb = Transform::new(v(t), turn_b as R).ok()?;
                        Some((Placed::new(&ga, tf)?, Placed::new(&gb, tb)?, margin))
                    }
                    Family::Mirrored => {
                        // A's own reach along `angle`, about: B's copy of A
                        // then comes near contact.
                        let half = Transform::from_cos_sin(v([towards[0] * 0.6, towards[1] * 0.6]), -1.0, 0.0).ok()?;
                        Some((Placed::world(&ga)?, Placed::new(&ga, half)?, margin))
                    }
                }
            }

            fn sweep(seed: u64, count: u32, scale: f64, family: Family) -> Worst {
                let mut rng = Rng(seed);
                let mut worst = Worst::default();
                for i in 0..count {
                    let Some((a, b, margin)) = random_pair(&mut rng, scale, family) else { continue };
                    match check(&a, &b, margin, &format!("case {i}")) {
                        Ok(w) => worst.merge(w),
                        Err(e) => panic!("{e}"),
                    }
                }
                worst
            }

            /// Random pairs of every kind near contact: the measured worst
            /// errors are printed (`--nocapture`).
            #[test]
            fn sweep_worst_errors() {
                for (name, scale, family) in [
                    ("unit", 1.0, Family::World),
                    ("tiny (2^-20)", 2f64.powi(-20), Family::World),
                    ("huge (2^20)", 2f64.powi(20), Family::World),
                    ("placed", 1.0, Family::Placed),
                    ("mirrored", 1.0, Family::Mirrored),
                    ("mirrored tiny (2^-20)", 2f64.powi(-20), Family::Mirrored),
                ] {
                    let w = sweep(0x6d61_6e69 ^ scale.to_bits(), cases(300), scale, family);
                    eprintln!("{} {name}: {w:?}", stringify!($r));
                }
            }

            proptest! {
                #![proptest_config(config(0x6a6b_3264))]

                #[test]
                fn random_pairs_match_the_oracle(seed in any::<u64>(), family in prop_oneof![Just(Family::World), Just(Family::Placed), Just(Family::Mirrored)]) {
                    let mut rng = Rng(seed);
                    if let Some((a, b, margin)) = random_pair(&mut rng, 1.0, family) {
                        check(&a, &b, margin, "random")?;
                    }
                }

                /// Two small polygons of known types: the queries' separating
                /// axes and closed forms give the normal, not GJK and EPA.
                #[test]
                fn small_polygons_by_type_match_the_oracle(seed in any::<u64>()) {
                    let mut rng = Rng(seed);
                    let (sa, sb) = (rng.range(0.3, 3.0), rng.range(0.3, 3.0));
                    let angle = rng.range(0.0, TAU);
                    let reach = rng.range(0.3, 1.3) * (sa + sb);
                    let ga = random_shape(&mut rng, 0, [0.0, 0.0], sa);
                    let gb = random_shape(&mut rng, 0, [reach * angle.cos(), reach * angle.sin()], sb);
                    let (Some(Geo::Poly(va)), Some(Geo::Poly(vb))) = (&ga, &gb) else { return Ok(()) };
                    let to = |p: &Vec<Pt>| p.iter().map(|&q| v(q)).collect::<Vec<$vec>>();
                    let (Ok(pa), Ok(pb)) = (Polygon::<R, 16>::new(&to(va)), Polygon::<R, 16>::new(&to(vb))) else { return Ok(()) };
                    let (a, b) = (Placed::world(ga.as_ref().unwrap()).unwrap(), Placed::world(gb.as_ref().unwrap()).unwrap());
                    let margin = r32(rng.range(0.0, 0.5));
                    let id = Transform::IDENTITY;
                    let m = Gjk::<R>::new().manifold(&pa, &id, &pb, &id, margin as R).unwrap();
                    check_manifold(&m, &a, &b, margin, "typed polygons")?;
                }

                /// Polygons of 9 to 64 vertices of known types, half of them
                /// boxes with up to four vertices on each side: the manifold
                /// finds a support vertex's edges by index (the polygon lends
                /// its vertices), not by asking the support function around.
                #[test]
                fn dense_polygons_by_type_match_the_oracle(seed in any::<u64>()) {
                    let mut rng = Rng(seed);
                    let dense = |rng: &mut Rng, c: Pt, size: f64| -> Vec<Pt> {
                        let (a, b, phi) = (rng.range(0.2, 1.0) * size, rng.range(0.3, 1.0) * size, rng.range(0.0, TAU));
                        let (cp, sp) = (phi.cos(), phi.sin());
                        let place = |x: f64, y: f64| rp([c[0] + cp * x - sp * y, c[1] + sp * x + cp * y]);
                        if rng.next() % 2 == 0 {
                            // An axis-aligned box (so that its split sides
                            // stay exactly straight in f32), each side split
                            // at random fractions.
                            let (x0, x1, y0, y1) = (r32(c[0] - a), r32(c[0] + a), r32(c[1] - b), r32(c[1] + b));
                            let corners = [[x0, y0], [x1, y0], [x1, y1], [x0, y1]];
                            let mut p = Vec::new();
                            for k in 0..4 {
                                let (s, e) = (corners[k], corners[(k + 1) % 4]);
                                let mut f: Vec<f64> = (0..1 + rng.next() % 4).map(|_| rng.range(0.1, 0.9)).collect();
                                f.sort_by(|x, y| x.partial_cmp(y).unwrap());
                                p.push(s);
                                p.extend(f.iter().map(|&t| rp([s[0] + (e[0] - s[0]) * t, s[1] + (e[1] - s[1]) * t])));
                            }
                            p
                        } else {
                            let count = 9 + (rng.next() % 56) as usize;
                            let phase = rng.unit();
                            (0..count).map(|i| {
                                let th = (i as f64 + phase + 0.3 * rng.unit()) / count as f64 * TAU;
                                place(a * th.cos(), b * th.sin())
                            }).collect()
                        }
                    };
                    let (sa, sb) = (rng.range(0.3, 3.0), rng.range(0.3, 3.0));
                    let angle = rng.range(0.0, TAU);
                    let reach = rng.range(0.3, 1.3) * (sa + sb);
                    let va = dense(&mut rng, [0.0, 0.0], sa);
                    let vb = dense(&mut rng, [reach * angle.cos(), reach * angle.sin()], sb);
                    let to = |p: &Vec<Pt>| p.iter().map(|&q| v(q)).collect::<Vec<$vec>>();
                    let (Ok(pa), Ok(pb)) = (Polygon::<R, 64>::new(&to(&va)), Polygon::<R, 64>::new(&to(&vb))) else { return Ok(()) };
                    let (Some(a), Some(b)) = (Placed::world(&Geo::Poly(va)), Placed::world(&Geo::Poly(vb))) else { return Ok(()) };
                    let margin = r32(rng.range(0.0, 0.5));
                    let id = Transform::IDENTITY;
                    let m = Gjk::<R>::new().manifold(&pa, &id, &pb, &id, margin as R).unwrap();
                    check_manifold(&m, &a, &b, margin, "typed dense polygons")?;
                }

                /// A box, a capsule or a trapezoid resting on a wider box, the
                /// ends of its bottom face well inside the box's top face:
                /// moved by 1e-3 of its size and turned by half a degree,
                /// the manifold keeps its two points and their ids.
                #[test]
                fn resting_ids_stay_under_a_small_motion(
                    wa in 2.0f64..8.0, wb in 0.25f64..1.0, hb in 0.1f64..1.0, x in -0.9f64..0.9,
                    gap in -0.05f64..0.05, kind in 0u32..3, sign in prop_oneof![Just(-1.0), Just(1.0)],
                ) {
                    let gjk = Gjk::<R>::new();
                    let ground = Rectangle::<R>::new(2.0 * wa as R, 1.0).unwrap(); // top face at y = 0.5
                    let (body, bottom): (Box<dyn SupportMap<R>>, f64) = match kind {
                        0 => (Box::new(Rectangle::<R>::new(2.0 * wb as R, 2.0 * hb as R).unwrap()), hb),
                        1 => (Box::new(Capsule::<R>::new(v([-wb, 0.0]), v([wb, 0.0]), hb as R).unwrap()), hb),
                        _ => {
                            let pts = [v([-wb, -hb]), v([wb, -hb]), v([0.5 * wb, hb]), v([-0.5 * wb, hb])];
                            (Box::new(Polygon::<R, 8>::new(&pts).unwrap()), hb)
                        }
                    };
                    // Well inside the ground's top face, at most 0.9 of the
                    // way to its ends.
                    let x = x * (wa - wb);
                    // The ids, the ground as A, then as B.
                    let ids = |dx: f64, dy: f64, turn: f64| {
                        let at = Transform::new(v([x + dx, 0.5 + bottom + gap + dy]), turn as R).unwrap();
                        let id = Transform::IDENTITY;
                        let m = gjk.manifold(&ground, &id, &*body, &at, 0.1).unwrap();
                        let swapped = gjk.manifold(&*body, &at, &ground, &id, 0.1).unwrap();
                        let sorted = |m: &Manifold<R>| {
                            let mut ids: Vec<FeatureId> = m.points().iter().map(|p| p.id).collect();
                            ids.sort_by_key(|id| format!("{id:?}"));
                            ids
                        };
                        (sorted(&m), sorted(&swapped))
                    };
                    let still = ids(0.0, 0.0, 0.0);
                    prop_assert_eq!((still.0.len(), still.1.len()), (2, 2));
                    let (step, half_degree) = (1e-3 * wb.max(hb), sign * 0.5f64.to_radians());
                    for (dx, dy, turn) in [(sign * step, 0.0, 0.0), (0.0, sign * step, 0.0), (0.0, 0.0, half_degree), (step, -step, half_degree)] {
                        prop_assert_eq!(ids(dx, dy, turn), still.clone(), "moved by ({}, {}), turned by {}", dx, dy, turn);
                    }
                }

                /// Axis-aligned boxes and flat capsules on a box, every value
                /// a few-bit dyadic: the points are the ends of the region
                /// where the faces meet, exactly.
                #[test]
                fn parallel_faces_span_the_overlap(
                    wa in 1u32..64, ha in 1u32..64, wb in 1u32..64, hb in 1u32..64,
                    x in -80i32..80, gap in -8i32..16, capsule in any::<bool>(), far in any::<bool>(),
                ) {
                    let unit = 1.0 / 16.0;
                    let (wa, ha, wb, hb) = (wa as f64 * unit, ha as f64 * unit, wb as f64 * unit, hb as f64 * unit);
                    // The vertical overlap must be the least: far enough in x
                    // from either side edge.
                    let (x, gap) = (x as f64 * unit, gap as f64 * unit / 4.0);
                    let (left, right) = ((-wa).max(x - wb), wa.min(x + wb));
                    prop_assume!(right - left > 2.0 * gap.abs().max(unit));
                    let origin = if far { [10240.0, -10240.0] } else { [0.0, 0.0] };
                    let at = |p: Pt| [p[0] + origin[0], p[1] + origin[1]];
                    let ga = Geo::Poly(vec![at([-wa, -ha]), at([wa, -ha]), at([wa, ha]), at([-wa, ha])]);
                    let y = ha + gap + hb;
                    let gb = if capsule {
                        Geo::Capsule(at([x - wb, y]), at([x + wb, y]), hb)
                    } else {
                        Geo::Poly(vec![at([x - wb, y - hb]), at([x + wb, y - hb]), at([x + wb, y + hb]), at([x - wb, y + hb])])
                    };
                    let (a, b) = (Placed::world(&ga).unwrap(), Placed::world(&gb).unwrap());
                    check(&a, &b, 0.5, "parallel")?;
                    let m = Gjk::<R>::new().manifold(&*a.shape, &a.tf, &*b.shape, &b.tf, 0.5).unwrap();
                    prop_assert_eq!(pt(m.normal), [0.0, 1.0]);
                    let mut got: Vec<(Pt, f64)> = m.points().iter().map(|p| (pt(p.point), p.separation as f64)).collect();
                    got.sort_by(|p, q| p.0[0].partial_cmp(&q.0[0]).unwrap());
                    let top = origin[1] + ha;
                    prop_assert_eq!(got, vec![([origin[0] + left, top], gap), ([origin[0] + right, top], gap)]);
                }
            }

            /// A rounded polygon of random vertices and radius, with its exact
            /// counterpart: its faces are the flat sides, its corners arcs.
            fn rounded(rng: &mut Rng, c: Pt, size: f64) -> Option<Placed> {
                let Some(Geo::Poly(vs)) = random_shape(rng, 0, c, size) else { return None };
                let radius = r32(rng.range(0.01, 0.5) * size);
                let pts: Vec<$vec> = vs.iter().map(|&p| v(p)).collect();
                let shape = Rounded::new(Polygon::<R, 16>::new(&pts).ok()?, radius as R).ok()?;
                let exact = transform_shape(&Shape::RoundedPolygon { vertices: vs.clone(), radius }, 1.0, 0.0, 0.0, 0.0);
                let extent = Geo::Poly(vs).extent() + radius;
                Some(Placed { shape: Box::new(shape), tf: Transform::IDENTITY, exact, extent })
            }

            proptest! {
                #![proptest_config(config(0x726f_756e))]

                #[test]
                fn rounded_polygons_match_the_oracle(seed in any::<u64>(), against in 0u32..5) {
                    let mut rng = Rng(seed);
                    let (sa, sb) = (rng.range(0.3, 3.0), rng.range(0.3, 3.0));
                    let angle = rng.range(0.0, TAU);
                    let reach = rng.range(0.3, 1.3) * (sa + sb);
                    let Some(a) = rounded(&mut rng, [0.0, 0.0], sa) else { return Ok(()) };
                    let c = [reach * angle.cos(), reach * angle.sin()];
                    let b = if against == 0 { rounded(&mut rng, c, sb) } else { random_shape(&mut rng, against, c, sb).and_then(|g| Placed::world(&g)) };
                    let Some(b) = b else { return Ok(()) };
                    let margin = r32(rng.range(0.0, 0.5));
                    check(&a, &b, margin, "rounded")?;
                    check(&b, &a, margin, "rounded, swapped")?;
                }

                /// Every shape type, placed anywhere, through trait objects:
                /// finite points, at most two, none beyond the margin, the
                /// least separation the distance or penetration query's.
                #[test]
                fn every_shape_gives_a_sound_manifold(ka in 0usize..10, kb in 0usize..10, x in -3.0f64..3.0, y in -3.0f64..3.0, turn in -4.0f64..4.0, margin in 0.0f64..1.0) {
                    let shapes: Vec<Box<dyn SupportMap<R>>> = vec![
                        Box::new(Circle::<R>::new(0.75).unwrap()),
                        Box::new(Rectangle::<R>::new(2.0, 1.0).unwrap()),
                        Box::new(Triangle::<R>::new(v([-1.0, -0.5]), v([1.0, -0.5]), v([0.0, 1.0])).unwrap()),
                        Box::new(Segment::<R>::new(v([-1.0, 0.0]), v([1.0, 0.5])).unwrap()),
                        Box::new(Capsule::<R>::new(v([-1.0, 0.0]), v([1.0, 0.0]), 0.25).unwrap()),
                        Box::new(Ellipse::<R>::new(2.0, 1.0).unwrap()),
                        Box::new(HalfEllipse::<R>::new(2.0, 1.0).unwrap()),
                        Box::new(Slice::<R>::new(1.0, 1.0).unwrap()),
                        Box::new(Rounded::new(Rectangle::<R>::new(1.0, 1.0).unwrap(), 0.25).unwrap()),
                        Box::new(Polygon::<R, 8>::new(&[v([0.0, -1.0]), v([1.0, 0.0]), v([0.0, 1.0]), v([-1.0, 0.0])]).unwrap()),
                    ];
                    let gjk = Gjk::<R>::new();
                    let (a, b) = (&*shapes[ka], &*shapes[kb]);
                    let (ta, tb) = (Transform::IDENTITY, Transform::new(v([x, y]), turn as R).unwrap());
                    let m = gjk.manifold(a, &ta, b, &tb, margin as R).unwrap();
                    // The query's answer and its certified error bound (curved
                    // shapes iterate to a tolerance).
                    let (signed, bound) = match gjk.distance(a, &ta, b, &tb) {
                        Some(s) => (s.distance as f64, s.error_bound as f64),
                        None => gjk.penetration(a, &ta, b, &tb).map_or((0.0, 0.0), |p| (-(p.depth as f64), p.error_bound as f64)),
                    };
                    prop_assert!(m.len <= 2 && (signed > margin) == m.is_empty(), "{m:?}, signed distance {signed}");
                    let mut least = f64::INFINITY;
                    for p in m.points() {
                        prop_assert!(p.point.is_finite() && p.separation.is_finite() && p.separation as f64 <= margin, "{m:?}");
                        least = least.min(p.separation as f64);
                    }
                    if !m.is_empty() {
                        // Curved shapes iterate to the configured relative
                        // epsilon: the manifold's supports may be that far from
                        // the query's last ones.
                        let size = 3.0 + x.abs() + y.abs();
                        let tol = bound + (4.0 * gjk.config.distance_epsilon() as f64 + 64.0 * EPS) * size;
                        prop_assert!((least - signed).abs() <= tol, "{m:?}, signed distance {signed}, bound {bound:e}");
                    }
                }
            }

            fn rect(w: f64, h: f64, c: Pt) -> Geo {
                Geo::Poly(vec![[c[0] - w, c[1] - h], [c[0] + w, c[1] - h], [c[0] + w, c[1] + h], [c[0] - w, c[1] + h]])
            }

            fn manifold_of(a: &Placed, b: &Placed, margin: f64) -> Manifold<R> {
                Gjk::<R>::new().manifold(&*a.shape, &a.tf, &*b.shape, &b.tf, margin as R).unwrap()
            }

            #[test]
            fn box_resting_on_a_wider_box() {
                let gjk = Gjk::<R>::new();
                // Full widths and heights: the floor's top face at y = 1.
                let floor = Rectangle::<R>::new(8.0, 2.0).unwrap();
                let block = Rectangle::<R>::new(2.0, 2.0).unwrap();
                let at = Transform::from_translation($vec::new(0.5, 1.75)).unwrap();
                let m = gjk.manifold(&floor, &Transform::IDENTITY, &block, &at, 0.1).unwrap();
                assert_eq!(m.normal, $vec::Y);
                assert_eq!(m.len, 2);
                let got: Vec<(Pt, f64)> = m.points().iter().map(|p| (pt(p.point), p.separation as f64)).collect();
                assert!(got.contains(&([-0.5, 1.0], -0.25)) && got.contains(&([1.5, 1.0], -0.25)), "{got:?}");
                for p in m.points() {
                    assert!(matches!(p.id.a, Feature::Edge(_)) && matches!(p.id.b, Feature::Vertex(_)), "{p:?}");
                }
                // Apart by 0.5: within a margin of 1, two points; of 0.4, none.
                let above = Transform::from_translation($vec::new(0.5, 2.5)).unwrap();
                let m = gjk.manifold(&floor, &Transform::IDENTITY, &block, &above, 1.0).unwrap();
                assert_eq!(m.len, 2);
                assert!(m.points().iter().all(|p| p.separation == 0.5));
                let m = gjk.manifold(&floor, &Transform::IDENTITY, &block, &above, 0.4).unwrap();
                assert!(m.is_empty() && m.normal == $vec::Y);
            }

            #[test]
            fn faces_meeting_part_way_give_one_end_of_each() {
                // A spans x in [-1, 1], B in [-0.5, 3.5]: the ends are B's
                // lower-left corner and A's upper-right one.
                let (a, b) = (Placed::world(&rect(1.0, 1.0, [0.0, 0.0])).unwrap(), Placed::world(&rect(2.0, 1.0, [1.5, 1.75])).unwrap());
                let m = manifold_of(&a, &b, 0.0);
                let mut got: Vec<(Pt, f64, FeatureId)> = m.points().iter().map(|p| (pt(p.point), p.separation as f64, p.id)).collect();
                got.sort_by(|p, q| p.0[0].partial_cmp(&q.0[0]).unwrap());
                assert_eq!(got.len(), 2, "{m:?}");
                assert_eq!((got[0].0, got[0].1), ([-0.5, 1.0], -0.25));
                assert_eq!((got[1].0, got[1].1), ([1.0, 1.0], -0.25));
                assert!(matches!(got[0].2, FeatureId { a: Feature::Edge(_), b: Feature::Vertex(_) }), "{got:?}");
                assert!(matches!(got[1].2, FeatureId { a: Feature::Vertex(_), b: Feature::Edge(_) }), "{got:?}");
            }

            /// Vertices on an edge (which polygons accept) do not cut a face
            /// short: the points are still the ends of the whole overlap.
            #[test]
            fn collinear_vertices_keep_whole_faces() {
                // Each listed from a vertex inside the face that meets the
                // other, which is then the first support along it.
                let ground = Geo::Poly(vec![[0.0, 1.0], [-2.0, 1.0], [-4.0, 1.0], [-4.0, -1.0], [4.0, -1.0], [4.0, 1.0], [2.0, 1.0]]);
                let c = [0.5, 1.75];
                let square = [[0.0, -1.0], [1.0, -1.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0], [-1.0, 1.0], [-1.0, 0.0], [-1.0, -1.0]];
                let body = Geo::Poly(square.iter().map(|p| [p[0] + c[0], p[1] + c[1]]).collect());
                let (a, b) = (Placed::world(&ground).unwrap(), Placed::world(&body).unwrap());
                check(&a, &b, 0.0, "collinear").unwrap();
                check(&b, &a, 0.0, "collinear, swapped").unwrap();
                let mut got: Vec<(Pt, f64)> = manifold_of(&a, &b, 0.0).points().iter().map(|p| (pt(p.point), p.separation as f64)).collect();
                got.sort_by(|p, q| p.0[0].partial_cmp(&q.0[0]).unwrap());
                assert_eq!(got, vec![([-0.5, 1.0], -0.25), ([1.5, 1.0], -0.25)]);
                // The same through the shapes' types (the separating axes).
                let to = |g: &Geo| match g {
                    Geo::Poly(p) => Polygon::<R, 8>::new(&p.iter().map(|&q| v(q)).collect::<Vec<_>>()).unwrap(),
                    _ => unreachable!(),
                };
                let id = Transform::IDENTITY;
                let m = Gjk::<R>::new().manifold(&to(&ground), &id, &to(&body), &id, 0.0).unwrap();
                let mut typed: Vec<(Pt, f64)> = m.points().iter().map(|p| (pt(p.point), p.separation as f64)).collect();
                typed.sort_by(|p, q| p.0[0].partial_cmp(&q.0[0]).unwrap());
                assert_eq!(typed, got);
                for p in m.points() {
                    assert!(matches!(p.id, FeatureId { a: Feature::Edge(_), b: Feature::Vertex(_) }), "{m:?}");
                }
                // Flipped: B's whole bottom face rests on A's, whose corners
                // are A's vertices 0 and 2.
                let m = Gjk::<R>::new().manifold(&to(&body), &id, &to(&ground), &id, 0.0).unwrap();
                assert_eq!(m.len, 2, "{m:?}");
            }

            /// Ids under a small motion (1e-3 of the size, half a degree),
            /// for pairs whose faces meet well inside their ends.
            #[test]
            fn ids_stay_under_a_small_motion() {
                let ground = rect(4.0, 0.5, [0.0, -0.5]);
                let bodies = [
                    rect(0.5, 0.25, [0.3, 0.2]),
                    Geo::Poly(vec![[-0.6, 0.0], [0.6, 0.0], [0.9, 0.5], [0.0, 1.0], [-0.9, 0.5]]),
                    Geo::Poly(vec![[-1.0, 0.05], [1.0, 0.05], [0.0, 1.0]]),
                    Geo::Capsule([-1.0, 0.3], [1.0, 0.3], 0.25),
                    Geo::Segment([-1.0, 0.02], [1.0, 0.02]),
                ];
                let gjk = Gjk::<R>::new();
                let floor = build(&ground).unwrap();
                for body in &bodies {
                    let shape = build(body).unwrap();
                    let ids = |dx: f64, turn: f64| {
                        let tf = Transform::new(v([dx, -0.1 + dx]), turn as R).unwrap();
                        let m = gjk.manifold(&*floor, &Transform::IDENTITY, &*shape, &tf, 0.1).unwrap();
                        let mut ids: Vec<FeatureId> = m.points().iter().map(|p| p.id).collect();
                        ids.sort_by_key(|id| format!("{id:?}"));
                        ids
                    };
                    let still = ids(0.0, 0.0);
                    assert_eq!(still.len(), 2, "{body:?}");
                    let half_degree = 0.5f64.to_radians();
                    for (dx, turn) in [(1e-3, 0.0), (-1e-3, 0.0), (0.0, half_degree), (0.0, -half_degree), (1e-3, half_degree)] {
                        assert_eq!(ids(dx, turn), still, "{body:?} moved by {dx}, turned by {turn}");
                    }
                }
            }

            #[test]
            fn curved_shapes_give_one_point() {
                let gjk = Gjk::<R>::new();
                let ball = Circle::<R>::new(0.5).unwrap();
                let block = Rectangle::<R>::new(2.0, 2.0).unwrap();
                let over = Transform::from_translation($vec::new(0.25, 1.25)).unwrap();
                let m = gjk.manifold(&block, &Transform::IDENTITY, &ball, &over, 0.0).unwrap();
                assert_eq!(m.len, 1);
                assert_eq!((pt(m.points[0].point), m.points[0].separation as f64, m.normal), ([0.25, 1.0], -0.25, $vec::Y));
                assert!(matches!(m.points[0].id, FeatureId { a: Feature::Edge(_), b: Feature::Vertex(0) }), "{m:?}");
                let beside = Transform::from_translation($vec::new(0.75, 0.0)).unwrap();
                let m = gjk.manifold(&ball, &Transform::IDENTITY, &ball, &beside, 0.0).unwrap();
                assert_eq!(m.len, 1);
                assert_eq!((pt(m.points[0].point), m.points[0].separation as f64, m.normal), ([0.5, 0.0], -0.25, $vec::X));
                // A circle's core is one point: its vertex 0.
                assert_eq!(m.points[0].id, FeatureId { a: Feature::Vertex(0), b: Feature::Vertex(0) });
                let ellipse = Ellipse::<R>::new(1.0, 0.5).unwrap();
                let m = gjk.manifold(&block, &Transform::IDENTITY, &ellipse, &over, 1.0).unwrap();
                assert_eq!(m.len, 1, "{m:?}");
                assert!(matches!(m.points[0].id, FeatureId { a: Feature::Edge(_), b: Feature::Curve }), "{m:?}");
            }

            #[test]
            fn capsule_on_a_box_gives_two_when_parallel() {
                let (a, b) = (Placed::world(&rect(2.0, 1.0, [0.0, 0.0])).unwrap(), Placed::world(&Geo::Capsule([-1.0, 1.5], [1.0, 1.5], 0.625)).unwrap());
                let m = manifold_of(&a, &b, 0.0);
                let mut got: Vec<(Pt, f64)> = m.points().iter().map(|p| (pt(p.point), p.separation as f64)).collect();
                got.sort_by(|p, q| p.0[0].partial_cmp(&q.0[0]).unwrap());
                assert_eq!(got, vec![([-1.0, 1.0], -0.125), ([1.0, 1.0], -0.125)]);
                check(&a, &b, 0.0, "capsule flat").unwrap();
                // Tilted: the low end's arc touches, the other end hovers.
                let tilted = Geo::Capsule([-1.0, 1.5], [1.0, 1.625], 0.625);
                let b = Placed::world(&tilted).unwrap();
                let m = manifold_of(&a, &b, 0.5);
                assert_eq!(m.len, 2, "{m:?}");
                check(&a, &b, 0.5, "capsule tilted").unwrap();
                // Capsule on capsule, parallel: two points as well.
                let a = Placed::world(&Geo::Capsule([-2.0, 0.0], [2.0, 0.0], 0.5)).unwrap();
                let b = Placed::world(&Geo::Capsule([1.0, 0.75], [3.0, 0.75], 0.5)).unwrap();
                let m = manifold_of(&a, &b, 0.0);
                let mut got: Vec<(Pt, f64)> = m.points().iter().map(|p| (pt(p.point), p.separation as f64)).collect();
                got.sort_by(|p, q| p.0[0].partial_cmp(&q.0[0]).unwrap());
                assert_eq!(got, vec![([1.0, 0.5], -0.25), ([2.0, 0.5], -0.25)]);
            }

            #[test]
            fn far_from_the_origin_and_at_every_scale() {
                for (origin, scale) in [([1e4, -1e4], 1.0), ([0.0, 0.0], 2f64.powi(-40)), ([0.0, 0.0], 2f64.powi(40)), ([3e4, 2e4], 2f64.powi(-4))] {
                    let origin = rp(origin);
                    let at = |x: f64, y: f64| [origin[0] + x * scale, origin[1] + y * scale];
                    let ga = Geo::Poly(vec![at(-2.0, -1.0), at(2.0, -1.0), at(2.0, 1.0), at(-2.0, 1.0)]);
                    let gb = Geo::Poly(vec![at(-0.5, 0.75), at(1.5, 0.75), at(1.5, 2.75), at(-0.5, 2.75)]);
                    let (a, b) = (Placed::world(&ga).unwrap(), Placed::world(&gb).unwrap());
                    check(&a, &b, 0.0, "far or scaled").unwrap();
                    let m = manifold_of(&a, &b, 0.0);
                    let mut got: Vec<(Pt, f64)> = m.points().iter().map(|p| (pt(p.point), p.separation as f64)).collect();
                    got.sort_by(|p, q| p.0[0].partial_cmp(&q.0[0]).unwrap());
                    assert_eq!(got, vec![(at(-0.5, 1.0), -0.25 * scale), (at(1.5, 1.0), -0.25 * scale)], "origin {origin:?}, scale {scale:e}");
                }
            }

            #[test]
            fn bad_margins_are_errors() {
                let gjk = Gjk::<R>::new();
                let block = Rectangle::<R>::new(1.0, 1.0).unwrap();
                let id = Transform::IDENTITY;
                assert_eq!(gjk.manifold(&block, &id, &block, &id, R::NAN), Err(Error::NonFinite));
                assert_eq!(gjk.manifold(&block, &id, &block, &id, R::INFINITY), Err(Error::NonFinite));
                assert_eq!(gjk.manifold(&block, &id, &block, &id, -1.0), Err(Error::OutOfRange));
                // Coincident shapes: a normal and points, all finite.
                let m = gjk.manifold(&block, &id, &block, &id, 0.0).unwrap();
                assert!(!m.is_empty());
                for p in m.points() {
                    assert!(p.point.is_finite() && p.separation.is_finite(), "{m:?}");
                }
            }
        }
    };
}

manifold_suite!(f32_suite, f32, Vec2);
manifold_suite!(f64_suite, f64, DVec2);
