//! Warm starting ([`PairCache`] and the `_cached` queries) on frame-to-frame
//! sequences of random pairs, against the cold queries and the exact
//! rational oracle (`gjk2d_oracle`), in f32 and f64.
//!
//! What is checked, at every step of every sequence:
//! - two polygons of up to eight vertices: the cached intersection verdict
//!   and penetration (depth and normal) are the cold ones, to the bit;
//! - every pair: the cached distance is the exact one within its error
//!   bound and `8 eps L` (a `None` only where the exact distance is within
//!   that of zero), the cached penetration's depth likewise, and the cached
//!   manifold's least separation is the exact signed distance within `8 eps
//!   L`, with points exactly where the margin says;
//! - on polygons, GJK's mean iterations cached are at most the cold ones;
//! - a cache that is stale, from another pair, of other shapes, or garbage
//!   (random bits) gives answers as correct as a cold one.
//!
//! `L` is the pair's size (the larger extent, or the centers' distance if
//! larger); the placement's rounding comes on top, `4 eps (|t_B - t_A| +
//! e_A + e_B)`, as in `tests/manifold.rs`.

use gjk2d::glam::{DVec2, Vec2};
use gjk2d::*;
use gjk2d_oracle::{pair, transform_shape, Shape};
use std::f64::consts::TAU;

#[path = "common/rng.rs"]
mod rng;
use rng::{cases, Rng};

type Pt = [f64; 2];

fn r32(x: f64) -> f64 {
    x as f32 as f64
}

fn norm(p: Pt) -> f64 {
    p[0].hypot(p[1])
}

/// A shape in its local frame, every coordinate an f32 value.
#[derive(Clone, Debug)]
enum Geo {
    /// Up to 8 vertices: the separating-axis paths.
    Small(Vec<Pt>),
    /// 9 to 64 vertices: GJK and EPA (past 32, EPA from four supports,
    /// and six where warm started).
    Large(Vec<Pt>),
    Circle(f64),
    Capsule(Pt, Pt, f64),
    Rounded(Vec<Pt>, f64),
}

impl Geo {
    fn oracle(&self) -> Shape {
        match self {
            Geo::Small(v) | Geo::Large(v) => Shape::Polygon(v.clone()),
            Geo::Circle(r) => Shape::Circle { center: [0.0, 0.0], radius: *r },
            Geo::Capsule(a, b, r) => Shape::Capsule { a: *a, b: *b, radius: *r },
            Geo::Rounded(v, r) => Shape::RoundedPolygon { vertices: v.clone(), radius: *r },
        }
    }
    fn extent(&self) -> f64 {
        let core = |v: &[Pt]| v.iter().map(|&p| norm(p)).fold(0.0, f64::max);
        match self {
            Geo::Small(v) | Geo::Large(v) => core(v),
            Geo::Circle(r) => *r,
            Geo::Capsule(a, b, r) => core(&[*a, *b]) + r,
            Geo::Rounded(v, r) => core(v) + r,
        }
    }
}

/// `count` vertices on a random ellipse about the origin, at sorted random
/// angles at least 0.1 apart.
fn ellipse_polygon(rng: &mut Rng, count: usize) -> Option<Vec<Pt>> {
    let (a, b, phi) = (rng.range(0.3, 1.0), rng.range(0.3, 1.0), rng.range(0.0, TAU));
    let gap = (TAU / count as f64 / 2.0).min(0.1);
    let mut angles: Vec<f64> = (0..count).map(|_| rng.range(0.0, TAU)).collect();
    angles.sort_by(f64::total_cmp);
    let mut kept: Vec<f64> = Vec::new();
    for th in angles {
        if kept.last().is_none_or(|&l| th - l >= gap) {
            kept.push(th);
        }
    }
    if kept.len() >= 2 && kept[0] + TAU - kept[kept.len() - 1] < gap {
        kept.pop();
    }
    let (c, s) = (phi.cos(), phi.sin());
    let place = |x: f64, y: f64| [r32(c * x - s * y), r32(s * x + c * y)];
    (kept.len() >= 3).then(|| kept.iter().map(|&t| place(a * t.cos(), b * t.sin())).collect())
}

fn random_geo(rng: &mut Rng, kind: u64) -> Option<Geo> {
    let (few, many) = (3 + (rng.next() % 6) as usize, 9 + (rng.next() % 56) as usize);
    Some(match kind {
        0..=2 => Geo::Small(ellipse_polygon(rng, few)?),
        3 => {
            // Angles too close are dropped: a few come out small.
            let v = ellipse_polygon(rng, many)?;
            if v.len() > 8 {
                Geo::Large(v)
            } else {
                Geo::Small(v)
            }
        }
        4 => Geo::Circle(r32(rng.range(0.2, 1.0))),
        5 => {
            let (h, t) = (rng.range(0.1, 0.8), rng.range(0.0, TAU));
            let u = [r32(h * t.cos()), r32(h * t.sin())];
            Geo::Capsule([-u[0], -u[1]], u, r32(rng.range(0.05, 0.4)))
        }
        _ => Geo::Rounded(ellipse_polygon(rng, few)?, r32(rng.range(0.02, 0.3))),
    })
}

/// Everything a sequence's step is checked with.
#[derive(Default, Debug)]
struct Tally {
    steps: u64,
    /// GJK iterations of the distance query on polygon pairs (answers
    /// only): cold, cached, and how many.
    cold_iterations: u64,
    warm_iterations: u64,
    answers: u64,
    /// Steps that were decided by the cache alone (0 iterations).
    decided: u64,
}

macro_rules! warm_suite {
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

            /// The shapes by their types (so the small polygons' paths run), held
            /// as a test holds a few: no box.
            #[allow(clippy::large_enum_variant)]
            enum S {
                Small(Polygon<R, 8>),
                Large(Polygon<R, 64>),
                Circle(Circle<R>),
                Capsule(Capsule<R>),
                Rounded(Rounded<R, Polygon<R, 8>>),
            }

            fn build(g: &Geo) -> Option<S> {
                let poly = |p: &[Pt]| p.iter().map(|&p| v(p)).collect::<Vec<_>>();
                Some(match g {
                    Geo::Small(p) => S::Small(Polygon::new(&poly(p)).ok()?),
                    Geo::Large(p) => S::Large(Polygon::new(&poly(p)).ok()?),
                    Geo::Circle(r) => S::Circle(Circle::new(*r as R).ok()?),
                    Geo::Capsule(a, b, r) => S::Capsule(Capsule::new(v(*a), v(*b), *r as R).ok()?),
                    Geo::Rounded(p, r) => S::Rounded(Rounded::new(Polygon::new(&poly(p)).ok()?, *r as R).ok()?),
                })
            }

            macro_rules! with {
                ($s:expr, |$x:ident| $body:expr) => {
                    match $s {
                        S::Small($x) => $body,
                        S::Large($x) => $body,
                        S::Circle($x) => $body,
                        S::Capsule($x) => $body,
                        S::Rounded($x) => $body,
                    }
                };
            }

            /// The caches of one pair: one per query, and one all four share.
            #[derive(Clone, Copy, Default)]
            struct Caches {
                each: [PairCache<R>; 4],
                shared: PairCache<R>,
            }

            /// A cache of random bits: every field a plain integer or float,
            /// so any bits are a value, as a corrupted one could hold.
            fn garbage(rng: &mut Rng) -> PairCache<R> {
                let mut bytes = [0u8; std::mem::size_of::<PairCache<R>>()];
                for b in bytes.iter_mut() {
                    *b = rng.next() as u8;
                }
                // Half the words made ids in range (A's vertex and B's below
                // 8), wherever the fields lie: as a foreign cache's would be.
                for word in bytes.chunks_exact_mut(4) {
                    if rng.next() % 2 == 0 {
                        word.copy_from_slice(&[(rng.next() % 8) as u8, 0, (rng.next() % 8) as u8, 0]);
                    }
                }
                // SAFETY: `PairCache` holds only `u32`, `u64` and floats, for
                // which every bit pattern is a valid value.
                #[allow(unsafe_code)]
                unsafe {
                    std::ptr::read_unaligned(bytes.as_ptr().cast::<PairCache<R>>())
                }
            }

            fn transform(p: &[f64; 3]) -> Transform<R> {
                Transform::new(v([p[0], p[1]]), p[2] as R).unwrap()
            }

            /// One step of a pair: every query cold and cached (from `caches`),
            /// checked as the module's header says.
            #[allow(clippy::too_many_arguments)]
            fn check_step(
                ga: &Geo,
                gb: &Geo,
                a: &S,
                b: &S,
                poses: &[[f64; 3]; 2],
                caches: &mut Caches,
                tally: &mut Tally,
                what: &str,
            ) {
                let (ta, tb) = (transform(&poses[0]), transform(&poses[1]));
                let exact = {
                    let place = |g: &Geo, t: &Transform<R>| {
                        let (c, s, o) = (t.cos() as f64, t.sin() as f64, pt(t.translation()));
                        transform_shape(&g.oracle(), c, s, o[0], o[1])
                    };
                    pair(&place(ga, &ta), &place(gb, &tb))
                };
                let (oa, ob) = (pt(ta.translation()), pt(tb.translation()));
                let apart = norm([ob[0] - oa[0], ob[1] - oa[1]]);
                let size = ga.extent().max(gb.extent()).max(apart);
                let tol = 8.0 * EPS * size + 4.0 * EPS * (apart + ga.extent() + gb.extent());
                let small = matches!((a, b), (S::Small(_), S::Small(_)));
                let polygons = matches!((a, b), (S::Small(_) | S::Large(_), S::Small(_) | S::Large(_)));
                let gjk = Gjk::<R>::new();
                let ctx = |q: &str| {
                    format!("{what}: {q}, {ga:?} at {:?}, {gb:?} at {:?}, exact {exact:?}", poses[0], poses[1])
                };
                let sd = exact.signed_distance;
                tally.steps += 1;
                with!(a, |a| with!(b, |b| {
                    let Caches { each, shared } = caches;
                    for cache in [&mut each[0], &mut *shared] {
                        // Intersection.
                        let cold = gjk.intersects(a, &ta, b, &tb);
                        let warm = gjk.intersects_cached(a, &ta, b, &tb, cache);
                        if small {
                            assert_eq!(warm.intersecting, cold.intersecting, "{}", ctx("intersects"));
                            tally.decided += (warm.iterations == 0) as u64;
                        } else if sd.abs() > tol {
                            assert_eq!(warm.intersecting, sd <= 0.0, "{}", ctx("intersects"));
                        }
                        assert!(warm.status.is_converged(), "{}", ctx("intersects"));
                    }
                    let cold_distance = gjk.distance(a, &ta, b, &tb);
                    for cache in [&mut each[1], &mut *shared] {
                        // Distance: for small polygons, the cold verdict (both
                        // take it from the separating axes).
                        let warm = gjk.distance_cached(a, &ta, b, &tb, cache);
                        if small {
                            assert_eq!(warm.is_some(), cold_distance.is_some(), "{}", ctx("distance verdict"));
                            // Apart by more than rounding: one closest pair's
                            // direction, the cold query's normal.
                            if let (Some(w), Some(c)) = (warm, cold_distance) {
                                let (nw, nc) = (pt(w.normal), pt(c.normal));
                                let (pa, pb) = (pt(w.point_a), pt(w.point_b));
                                let d = w.distance as f64;
                                let off = (pb[0] - pa[0] - d * nw[0]).hypot(pb[1] - pa[1] - d * nw[1]);
                                let where_ = 4.0 * EPS * (norm(pa) + norm(pb));
                                assert!(off <= 4.0 * tol + where_, "{}: points {w:?}", ctx("distance points"));
                                if c.distance as f64 > 1e3 * tol {
                                    let turn = (nw[0] - nc[0]).hypot(nw[1] - nc[1]);
                                    assert!(
                                        turn <= 1e3 * tol / c.distance as f64,
                                        "{}: {w:?} against {c:?}",
                                        ctx("distance normal")
                                    );
                                }
                            }
                        }
                        match warm {
                            Some(s) => {
                                assert!(s.status.is_converged(), "{}", ctx("distance"));
                                let e = (s.distance as f64 - exact.distance).abs();
                                assert!(
                                    e <= s.error_bound as f64 + tol,
                                    "{}: distance {s:?} off by {e:e}",
                                    ctx("distance")
                                );
                                assert!((norm(pt(s.normal)) - 1.0).abs() <= 4.0 * EPS, "{}", ctx("distance normal"));
                            }
                            None => assert!(sd <= tol, "{}: None", ctx("distance")),
                        }
                    }
                    if polygons {
                        let cold = cold_distance;
                        // A copy of the cache, so the probe leaves it as it was.
                        let mut probe = each[1];
                        if let (Some(c), Some(w)) = (cold, gjk.distance_cached(a, &ta, b, &tb, &mut probe)) {
                            tally.cold_iterations += u64::from(c.iterations);
                            tally.warm_iterations += u64::from(w.iterations);
                            tally.answers += 1;
                        }
                    }
                    for cache in [&mut each[2], &mut *shared] {
                        // Penetration.
                        let cold = gjk.penetration(a, &ta, b, &tb);
                        let warm = gjk.penetration_cached(a, &ta, b, &tb, cache);
                        if small {
                            let bits = |p: Option<Penetration<R>>| {
                                p.map(|p| (p.depth.to_bits(), p.normal.x.to_bits(), p.normal.y.to_bits()))
                            };
                            assert_eq!(bits(warm), bits(cold), "{}: {warm:?} against {cold:?}", ctx("penetration"));
                        }
                        match warm {
                            Some(p) => {
                                let e = p.depth as f64 - exact.depth;
                                assert!(
                                    e >= -tol && e <= p.error_bound as f64 + tol,
                                    "{}: {p:?} off by {e:e}",
                                    ctx("penetration")
                                );
                                assert!((norm(pt(p.normal)) - 1.0).abs() <= 4.0 * EPS, "{}", ctx("penetration normal"));
                            }
                            None => assert!(sd >= -tol, "{}: None", ctx("penetration")),
                        }
                    }
                    for cache in [&mut each[3], &mut *shared] {
                        // Manifold, touching and overlapping points only.
                        let m = gjk.manifold_cached(a, &ta, b, &tb, 0.0, cache).unwrap();
                        assert!(m.status.is_converged(), "{}", ctx("manifold"));
                        if sd > tol {
                            assert!(m.is_empty(), "{}: {m:?} apart, yet points", ctx("manifold"));
                        }
                        if sd < -tol {
                            assert!(!m.is_empty(), "{}: {m:?} overlapping, yet no point", ctx("manifold"));
                        }
                        if let Some(least) = m.points().iter().map(|p| p.separation as f64).reduce(f64::min) {
                            assert!((least - sd).abs() <= tol, "{}: {m:?} least {least:e}", ctx("manifold"));
                        }
                    }
                }));
            }

            /// Frame-to-frame sequences: every shape moves by at most 1% of
            /// its size and turns by at most a degree a step, with a jump now
            /// and then; every few steps a cache is swapped for a stale one,
            /// another pair's, or garbage.
            fn sequences(seed: u64, pairs: u32, steps: u32, kinds: &[u64]) -> Tally {
                let mut rng = Rng(seed);
                let mut tally = Tally::default();
                let mut foreign = Caches::default();
                for n in 0..pairs {
                    let pick = |rng: &mut Rng| kinds[(rng.next() % kinds.len() as u64) as usize];
                    let (ka, kb) = (pick(&mut rng), pick(&mut rng));
                    let (Some(ga), Some(gb)) = (random_geo(&mut rng, ka), random_geo(&mut rng, kb)) else { continue };
                    let (Some(a), Some(b)) = (build(&ga), build(&gb)) else { continue };
                    let (d, t) = (rng.range(0.2, 2.2), rng.range(0.0, TAU));
                    let (x, y) = (rng.range(-50.0, 50.0), rng.range(-50.0, 50.0));
                    let mut poses = [
                        [r32(x), r32(y), rng.range(0.0, TAU)],
                        [r32(x + d * t.cos()), r32(y + d * t.sin()), rng.range(0.0, TAU)],
                    ];
                    let mut caches = Caches::default();
                    let mut stale = Caches::default();
                    for k in 0..steps {
                        for p in &mut poses {
                            let jump = if k % 13 == 12 { 20.0 } else { 1.0 };
                            let (r, th) = (0.01 * jump * rng.unit().sqrt(), rng.range(0.0, TAU));
                            p[0] = r32(p[0] + r * th.cos());
                            p[1] = r32(p[1] + r * th.sin());
                            p[2] += (jump * rng.range(-1.0, 1.0)).to_radians();
                        }
                        match k % 11 {
                            3 => caches = foreign,
                            6 => caches = stale,
                            9 => {
                                caches.each = core::array::from_fn(|_| garbage(&mut rng));
                                caches.shared = garbage(&mut rng);
                            }
                            1 => stale = caches,
                            _ => {}
                        }
                        let what = format!("seed {seed} pair {n} step {k}");
                        check_step(&ga, &gb, &a, &b, &poses, &mut caches, &mut tally, &what);
                    }
                    foreign = caches;
                }
                tally
            }

            /// Pairs of polygons of up to eight vertices: the separating-axis
            /// paths, bit for bit, and GJK's distance from its last simplex.
            #[test]
            fn small_polygons() {
                let tally = sequences(1, cases(60), 40, &[0]);
                println!("{}: {tally:?}", stringify!($modname));
                assert!(tally.decided > tally.steps / 4, "{tally:?}: the cache decided too few");
                assert!(tally.warm_iterations <= tally.cold_iterations, "{tally:?}");
            }

            /// Polygons overlapping by about 1% of their size, nudged a little
            /// each step: after its first step, the cached intersection test
            /// decides nearly every overlapping step alone, from a triangle
            /// of B - A around the shallow overlap.
            #[test]
            fn shallow_overlaps_decided() {
                let mut rng = Rng(4);
                let gjk = Gjk::<R>::new();
                let (mut overlapping, mut decided) = (0u64, 0u64);
                for _ in 0..cases(200) {
                    let (Some(ga), Some(gb)) = (random_geo(&mut rng, 0), random_geo(&mut rng, 0)) else { continue };
                    let (Some(S::Small(a)), Some(S::Small(b))) = (build(&ga), build(&gb)) else { continue };
                    let ta = transform(&[0.0, 0.0, rng.range(0.0, TAU)]);
                    let mut pose = [rng.range(-0.3, 0.3), rng.range(-0.3, 0.3), rng.range(0.0, TAU)];
                    let Some(p) = gjk.penetration(&a, &ta, &b, &transform(&pose)) else { continue };
                    // B moved along the normal until it overlaps by 1% of the size.
                    let shift = p.depth as f64 - 0.01 * ga.extent().max(gb.extent());
                    let n = pt(p.normal);
                    (pose[0], pose[1]) = (r32(pose[0] + shift * n[0]), r32(pose[1] + shift * n[1]));
                    let mut cache = PairCache::default();
                    for k in 0..20 {
                        let tb = transform(&pose);
                        let (cold, warm) =
                            (gjk.intersects(&a, &ta, &b, &tb), gjk.intersects_cached(&a, &ta, &b, &tb, &mut cache));
                        assert_eq!(warm.intersecting, cold.intersecting, "{ga:?} {gb:?} at {pose:?}");
                        if k > 0 && cold.intersecting {
                            overlapping += 1;
                            decided += (warm.iterations == 0) as u64;
                        }
                        let (r, th) = (0.0005 * rng.unit().sqrt(), rng.range(0.0, TAU));
                        pose = [
                            r32(pose[0] + r * th.cos()),
                            r32(pose[1] + r * th.sin()),
                            pose[2] + rng.range(-0.02, 0.02).to_radians(),
                        ];
                    }
                }
                println!("{}: {decided} of {overlapping} overlapping steps decided", stringify!($modname));
                assert!(overlapping > 1000 && decided * 10 >= overlapping * 9, "{decided} of {overlapping} decided");
            }

            /// Pairs of small polygons apart, their caches filled a step
            /// before, moved along their normal until they nearly touch (gaps
            /// of 2^j eps either way): every query checked as in the
            /// sequences, so the cached intersection test and distance give
            /// the cold verdicts where a cached axis's margin above rounding
            /// decides or not, and the distance and manifold are the exact
            /// ones within their tolerances.
            #[test]
            fn near_touching() {
                let mut rng = Rng(5);
                let gjk = Gjk::<R>::new();
                let mut tally = Tally::default();
                for _ in 0..cases(100) {
                    let (Some(ga), Some(gb)) = (random_geo(&mut rng, 0), random_geo(&mut rng, 0)) else { continue };
                    let (Some(a), Some(b)) = (build(&ga), build(&gb)) else { continue };
                    let (S::Small(sa), S::Small(sb)) = (&a, &b) else { continue };
                    let pose_a = [0.0, 0.0, rng.range(0.0, TAU)];
                    let far = [rng.range(-3.0, 3.0), rng.range(-3.0, 3.0), rng.range(0.0, TAU)];
                    let Some(s) = gjk.distance(sa, &transform(&pose_a), sb, &transform(&far)) else { continue };
                    let (size, n) = (ga.extent().max(gb.extent()), pt(s.normal));
                    // B moved along the normal by the distance less `gap`.
                    let at = |gap: f64| {
                        let shift = s.distance as f64 - gap;
                        [far[0] - shift * n[0], far[1] - shift * n[1], far[2]]
                    };
                    // Across the rounding of the cold test and the cached
                    // axis's margin.
                    let gaps = (0..13).flat_map(|j| [1.0, -1.0].map(|side| side * (1u32 << j) as f64 * EPS * size));
                    for gap in gaps.chain([0.0]) {
                        let mut caches = Caches::default();
                        let mut filling = Tally::default();
                        let before = [pose_a, at(0.01 * size)];
                        check_step(&ga, &gb, &a, &b, &before, &mut caches, &mut filling, "before");
                        check_step(&ga, &gb, &a, &b, &[pose_a, at(gap)], &mut caches, &mut tally, "near touching");
                    }
                }
                println!("{}: {tally:?}", stringify!($modname));
                assert!(tally.steps > 1000 && tally.decided > 0, "{tally:?}");
            }

            /// Every kind of shape against every other: polygons of up to 32
            /// vertices, circles, capsules, rounded polygons.
            #[test]
            fn every_kind() {
                let tally = sequences(2, cases(80), 30, &[0, 3, 4, 5, 6]);
                println!("{}: {tally:?}", stringify!($modname));
                assert!(tally.warm_iterations <= tally.cold_iterations, "{tally:?}");
            }

            /// A cache filled by one pair and handed to a pair of other
            /// shapes, or of the same shapes swapped, answers as a cold one.
            #[test]
            fn foreign_and_swapped() {
                let mut rng = Rng(3);
                let gjk = Gjk::<R>::new();
                for _ in 0..cases(200) {
                    let geos: Vec<Geo> = (0..3)
                        .filter_map(|_| {
                            let kind = rng.next() % 7;
                            random_geo(&mut rng, kind)
                        })
                        .collect();
                    let shapes: Vec<S> = geos.iter().filter_map(build).collect();
                    if shapes.len() < 3 || geos.len() < 3 {
                        continue;
                    }
                    let poses = [
                        [0.0, 0.0, rng.range(0.0, TAU)],
                        [rng.range(-1.0, 1.0), rng.range(-1.0, 1.0), rng.range(0.0, TAU)],
                    ];
                    let (ta, tb) = (transform(&poses[0]), transform(&poses[1]));
                    let mut cache = PairCache::default();
                    // Filled by A and B, used for B and A, then for A and C.
                    with!(&shapes[0], |a| with!(&shapes[1], |b| {
                        gjk.penetration_cached(a, &ta, b, &tb, &mut cache);
                        gjk.distance_cached(a, &ta, b, &tb, &mut cache);
                    }));
                    let mut tally = Tally::default();
                    let mut caches = Caches { each: [cache; 4], shared: cache };
                    check_step(&geos[1], &geos[0], &shapes[1], &shapes[0], &poses, &mut caches, &mut tally, "swapped");
                    let mut caches = Caches { each: [cache; 4], shared: cache };
                    check_step(&geos[0], &geos[2], &shapes[0], &shapes[2], &poses, &mut caches, &mut tally, "foreign");
                }
            }
        }
    };
}

warm_suite!(f32_suite, f32, Vec2);
warm_suite!(f64_suite, f64, DVec2);
