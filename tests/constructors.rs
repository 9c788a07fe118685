//! Constructors against exact oracles: the polygon checks (every error and
//! every accepted polygon), the `const` polygon constructor against the run
//! time one, and rotations given by cosine and sine.
//!
//! Polygon coordinates are small integers, scaled by a power of two and
//! shifted by an exactly representable offset, so every coordinate is exact
//! in both precisions and the oracle decides convexity in integer arithmetic
//! with no rounding at all. Small integers are what makes the hard cases
//! common: repeated vertices, collinear runs, flat polygons, reflex turns and
//! pentagrams.

use gjk2d::glam::{DVec2, Vec2};
use gjk2d::{Error, Polygon, Real, SupportMap, Transform};
use proptest::prelude::*;

#[path = "common/geo.rs"]
mod geo;
use geo::integer_hull as hull;

/// What `Polygon::new` must answer for `p` (integer coordinates), decided
/// without floats: a polygon is convex when every vertex lies on one side
/// (the same for every edge, boundary included) of every edge.
fn oracle(p: &[(i64, i64)], capacity: usize) -> Result<i32, Error> {
    let n = p.len();
    if n < 3 {
        return Err(Error::TooFewVertices);
    }
    if n > capacity {
        return Err(Error::OverCapacity);
    }
    let at = |i: usize| p[i % n];
    if (0..n).any(|i| at(i) == at(i + 1)) {
        return Err(Error::DuplicateVertex);
    }
    let cross = |o: (i64, i64), a: (i64, i64), b: (i64, i64)| (a.0 - o.0) * (b.1 - o.1) - (a.1 - o.1) * (b.0 - o.0);
    let (mut left, mut right) = (false, false);
    for i in 0..n {
        for &q in p {
            let side = cross(at(i), at(i + 1), q);
            left |= side > 0;
            right |= side < 0;
        }
    }
    let winding = match (left, right) {
        (false, false) => return Err(Error::Degenerate),
        (true, true) => return Err(Error::NotConvex),
        (true, false) => 1,
        (false, true) => -1,
    };
    // Turning one way everywhere, a polygon can still go round more than
    // once (a triangle listed twice): count the times its edge direction
    // passes angle zero, comparing angles exactly (half-plane, then cross).
    let direction = |i: usize| (at(i + 1).0 - at(i).0, at(i + 1).1 - at(i).1);
    let lower_half = |d: (i64, i64)| d.1 < 0 || (d.1 == 0 && d.0 < 0);
    // Whether a's angle in [0, 2 pi) is below b's.
    let before = |a: (i64, i64), b: (i64, i64)| {
        let (ha, hb) = (lower_half(a), lower_half(b));
        (!ha && hb) || (ha == hb && a.0 * b.1 - a.1 * b.0 > 0)
    };
    let turns = (0..n)
        .filter(|&i| {
            if winding > 0 {
                before(direction(i + 1), direction(i))
            } else {
                before(direction(i), direction(i + 1))
            }
        })
        .count();
    if turns > 1 {
        return Err(Error::NotConvex);
    }
    Ok(winding)
}

/// Exact area centroid of a convex polygon with integer vertices, as
/// (numerator x, numerator y, denominator) of the fan formula.
fn exact_centroid(p: &[(i64, i64)]) -> (i128, i128, i128) {
    let (mut cx, mut cy, mut a6) = (0i128, 0i128, 0i128);
    for i in 0..p.len() {
        let (x0, y0) = (p[i].0 as i128, p[i].1 as i128);
        let (x1, y1) = (p[(i + 1) % p.len()].0 as i128, p[(i + 1) % p.len()].1 as i128);
        let c = x0 * y1 - x1 * y0;
        cx += (x0 + x1) * c;
        cy += (y0 + y1) * c;
        a6 += 3 * c;
    }
    (cx, cy, a6)
}

/// Small integer coordinates, with repeats of the previous point and runs
/// along one line made likely.
fn points(max_len: usize) -> impl Strategy<Value = Vec<(i64, i64)>> {
    prop::collection::vec((-4i64..=4, -4i64..=4, 0u8..8), 0..=max_len).prop_map(|raw| {
        let mut out: Vec<(i64, i64)> = Vec::new();
        for (x, y, kind) in raw {
            let point = match (kind, out.last()) {
                (0, Some(&last)) => last,
                (1, Some(&last)) => (last.0 + 1, last.1),
                _ => (x, y),
            };
            out.push(point);
        }
        out
    })
}

/// Convex polygons: the integer points of a circle's neighbourhood that are
/// hull vertices, in either winding.
fn convex(max_len: usize) -> impl Strategy<Value = Vec<(i64, i64)>> {
    (prop::collection::vec((-40i64..=40, -40i64..=40), 3..max_len + 3), any::<bool>()).prop_filter_map(
        "fewer than 3 hull vertices, or too many",
        move |(cloud, clockwise)| {
            let mut hull = hull(cloud);
            if hull.len() < 3 || hull.len() > max_len {
                return None;
            }
            if clockwise {
                hull.reverse();
            }
            Some(hull)
        },
    )
}

macro_rules! suite {
    ($name:ident, $R:ty, $V:ty) => {
        mod $name {
            use super::*;

            type R = $R;
            const CAPACITY: usize = 8;
            const MAX: R = <R as Real>::MAX_COORDINATE;

            /// Integer points scaled by `2^scale` and shifted by `offset`: exact.
            fn place(p: &[(i64, i64)], scale: i32, offset: (R, R)) -> Vec<$V> {
                let s = (2.0 as R).powi(scale);
                p.iter().map(|&(x, y)| <$V>::new(x as R * s + offset.0, y as R * s + offset.1)).collect()
            }

            /// A scale `2^scale` and an offset of up to `2^18` times it, so
            /// every placed coordinate stays exact (within 24 bits of it).
            fn offsets() -> impl Strategy<Value = (i32, (R, R))> {
                (-30i32..30, -16i32..=16, -16i32..=16, 0i32..=14).prop_map(|(scale, mx, my, k)| {
                    let unit = (2.0 as R).powi(scale + k);
                    (scale, (mx as R * unit, my as R * unit))
                })
            }

            /// The polygon answers what the oracle answers, for every kind of
            /// input, and as a constant (`from_array`) exactly what it answers
            /// at run time.
            fn check(p: &[(i64, i64)], scale: i32, offset: (R, R)) -> Result<(), TestCaseError> {
                let world = place(p, scale, offset);
                let s = (2.0 as R).powi(scale);
                // Exact, or the integer oracle would not describe the input.
                for (w, &(x, y)) in world.iter().zip(p) {
                    prop_assert!((w.x - offset.0) / s == x as R && (w.y - offset.1) / s == y as R);
                }
                let built = Polygon::<R, CAPACITY>::new(&world);
                let expected = oracle(p, CAPACITY);
                match (&built, expected) {
                    (Err(e), Err(want)) => prop_assert_eq!(*e, want, "{:?}", p),
                    (Ok(_), Err(want)) => prop_assert!(false, "accepted {:?}, oracle says {:?}", p, want),
                    (Err(e), Ok(_)) => prop_assert!(false, "rejected {:?} with {:?}, oracle accepts", p, e),
                    (Ok(polygon), Ok(winding)) => {
                        // Kept counter-clockwise, each vertex exactly as given.
                        let n = p.len();
                        for i in 0..n {
                            let given = if winding > 0 { world[i] } else { world[n - 1 - i] };
                            prop_assert_eq!(polygon.vertex(i), Some(given), "vertex {} of {:?}", i, p);
                        }
                        // The centroid within a few roundings of the size.
                        let (cx, cy, d) = exact_centroid(p);
                        let (cx, cy) = (cx as f64 / d as f64 * s as f64, cy as f64 / d as f64 * s as f64);
                        let size = p.iter().map(|&(x, y)| x.abs().max(y.abs())).max().unwrap_or(0) as f64 * s as f64;
                        let c = polygon.centroid();
                        let tolerance = 16.0 * R::EPSILON as f64 * (size + offset.0.abs().max(offset.1.abs()) as f64);
                        prop_assert!((c.x as f64 - offset.0 as f64 - cx).abs() <= tolerance, "{:?}: {} vs {}", p, c.x, cx);
                        prop_assert!((c.y as f64 - offset.1 as f64 - cy).abs() <= tolerance, "{:?}: {} vs {}", p, c.y, cy);
                        // The bounding radius holds every vertex.
                        let r = polygon.bounding_radius();
                        for w in &world {
                            let d = ((w.x - c.x) as f64).hypot((w.y - c.y) as f64);
                            prop_assert!(d <= r as f64 * (1.0 + 8.0 * R::EPSILON as f64) + tolerance);
                        }
                    }
                }
                if p.len() == CAPACITY {
                    let array: [$V; CAPACITY] = world.clone().try_into().unwrap();
                    same(&built, &Polygon::<R, CAPACITY>::from_array(array))?;
                }
                if p.len() == 4 {
                    let array: [$V; 4] = world.clone().try_into().unwrap();
                    same(&Polygon::<R, 4>::new(&world), &Polygon::<R, 4>::from_array(array))?;
                }
                Ok(())
            }

            /// Bit for bit the same polygon, or the same error.
            fn same<const N: usize>(
                a: &Result<Polygon<R, N>, Error>,
                b: &Result<Polygon<R, N>, Error>,
            ) -> Result<(), TestCaseError> {
                match (a, b) {
                    (Ok(a), Ok(b)) => {
                        let bits = |p: &Polygon<R, N>| {
                            let mut v: Vec<u64> = (0..p.len())
                                .flat_map(|i| {
                                    let q = p.vertex(i).unwrap();
                                    [q.x.to_bits() as u64, q.y.to_bits() as u64]
                                })
                                .collect();
                            let c = p.centroid();
                            let r = p.reference_point();
                            v.extend([c.x, c.y, r.x, r.y, p.bounding_radius()].map(|x| x.to_bits() as u64));
                            v
                        };
                        prop_assert_eq!(bits(a), bits(b));
                        prop_assert_eq!(a, b);
                    }
                    (Err(a), Err(b)) => prop_assert_eq!(a, b),
                    _ => prop_assert!(false, "{:?} vs {:?}", a, b),
                }
                Ok(())
            }

            proptest! {
                #![proptest_config(ProptestConfig::with_cases(3000))]

                #[test]
                fn any_points_get_the_oracles_verdict(p in points(CAPACITY + 2), (scale, offset) in offsets()) {
                    check(&p, scale, offset)?;
                }

                #[test]
                fn convex_polygons_are_kept_exactly(p in convex(CAPACITY), (scale, offset) in offsets()) {
                    check(&p, scale, offset)?;
                }

                #[test]
                fn collinear_points_on_edges_are_accepted(p in convex(CAPACITY / 2), (scale, offset) in offsets()) {
                    // Each edge's midpoint (made exact by doubling) inserted.
                    let doubled: Vec<(i64, i64)> = p.iter().map(|&(x, y)| (2 * x, 2 * y)).collect();
                    let mut with_midpoints = Vec::new();
                    for i in 0..doubled.len() {
                        let (a, b) = (doubled[i], doubled[(i + 1) % doubled.len()]);
                        with_midpoints.push(a);
                        with_midpoints.push(((a.0 + b.0) / 2, (a.1 + b.1) / 2));
                    }
                    prop_assert!(oracle(&with_midpoints, CAPACITY).is_ok());
                    check(&with_midpoints, scale, offset)?;
                }

                #[test]
                fn non_finite_and_huge_coordinates_are_refused(
                    p in convex(CAPACITY),
                    which in 0usize..CAPACITY,
                    bad in prop_oneof![Just(R::NAN), Just(R::INFINITY), Just(-R::INFINITY), Just(2.0 * MAX), Just(-R::MAX)],
                ) {
                    let mut world = place(&p, 0, (0.0, 0.0));
                    let k = which % world.len();
                    world[k].y = bad;
                    let want = if bad.is_finite() { Error::OutOfRange } else { Error::NonFinite };
                    prop_assert_eq!(Polygon::<R, CAPACITY>::new(&world), Err(want));
                }
            }

            /// A pentagram turns the same way at every vertex but winds
            /// twice: refused, by both constructors.
            #[test]
            fn a_pentagram_is_not_convex() {
                let star = [(0, 10), (6, -8), (-9, 3), (9, 3), (-6, -8)];
                assert_eq!(oracle(&star, 5), Err(Error::NotConvex));
                let world = place(&star, 0, (0.0, 0.0));
                assert_eq!(Polygon::<R, 5>::new(&world), Err(Error::NotConvex));
                let array: [$V; 5] = world.try_into().unwrap();
                assert_eq!(Polygon::<R, 5>::from_array(array), Err(Error::NotConvex));
            }

            /// A triangle listed twice turns the same way at every vertex,
            /// with every vertex on one side of every edge, but goes round
            /// twice (found by the proptest above): refused, either way round.
            #[test]
            fn a_triangle_listed_twice_is_not_convex() {
                let twice = [(-4, -3), (0, 3), (0, -1), (-4, -3), (0, 3), (0, -1)];
                let reversed: Vec<(i64, i64)> = twice.iter().rev().copied().collect();
                for p in [&twice[..], &reversed[..]] {
                    assert_eq!(oracle(p, 6), Err(Error::NotConvex));
                    assert_eq!(Polygon::<R, 6>::new(&place(p, 0, (0.0, 0.0))), Err(Error::NotConvex));
                }
            }

            /// Evaluated by the compiler: the constant is the run-time
            /// polygon, bit for bit.
            #[test]
            fn a_constant_polygon_is_the_run_time_one() {
                const SQUARE: [$V; 4] =
                    [<$V>::new(1.0e6, 3.0), <$V>::new(1.0e6 + 2.0, 3.0), <$V>::new(1.0e6 + 2.0, 5.0), <$V>::new(1.0e6, 5.0)];
                const BUILT: Polygon<R, 4> = match Polygon::<R, 4>::from_array(SQUARE) {
                    Ok(p) => p,
                    Err(e) => panic!("{}", e.as_str()),
                };
                same(&Ok(BUILT), &Polygon::<R, 4>::new(&SQUARE)).unwrap();
                assert_eq!(BUILT.centroid(), <$V>::new(1.0e6 + 1.0, 4.0));
            }

            /// (cos, sin) of any length within the coordinate range is a unit
            /// rotation; beyond it, or zero, it is refused.
            #[test]
            fn rotations_from_cos_and_sin() {
                let at = |c: R, s: R| Transform::<R>::from_cos_sin(<$V>::ZERO, c, s);
                let unit = |t: Transform<R>| (t.cos() as f64).hypot(t.sin() as f64);
                // Exactly unit stays exactly as given; axis-aligned is exact.
                assert_eq!(at(0.6, 0.8).map(|t| (t.cos(), t.sin())), Ok((0.6, 0.8)));
                assert_eq!(at(2.0, 0.0).map(|t| (t.cos(), t.sin())), Ok((1.0, 0.0)));
                assert_eq!(at(0.0, -1.0e-3).map(|t| (t.cos(), t.sin())), Ok((0.0, -1.0)));
                // Large: the squared length would overflow without the range.
                let big = at(MAX, MAX).unwrap();
                assert!((unit(big) - 1.0).abs() <= 4.0 * R::EPSILON as f64);
                assert!((big.cos() - big.sin()).abs() <= R::EPSILON);
                assert_eq!(at(2.0 * MAX, 2.0 * MAX), Err(Error::OutOfRange));
                assert_eq!(at(R::NAN, 1.0), Err(Error::NonFinite));
                assert_eq!(at(R::INFINITY, 1.0), Err(Error::NonFinite));
                // Small, down to where the square underflows to zero.
                let small = at(1.0e-15, -1.0e-15).unwrap();
                assert!((unit(small) - 1.0).abs() <= 4.0 * R::EPSILON as f64);
                assert_eq!(at(0.0, 0.0), Err(Error::ZeroLength));
                let tiny = (R::MIN_POSITIVE * R::EPSILON).sqrt() / 2.0;
                assert_eq!(at(tiny, 0.0), Err(Error::ZeroLength));
            }
        }
    };
}

suite!(single, f32, Vec2);
suite!(double, f64, DVec2);
