//! EPA as a user calls it (`PenetrationSolver::solve`), on a Minkowski
//! difference that is a convex polygon with integer vertices, so the exact
//! depth is a ratio of integers: the smallest (cross(p, q))^2 / |q - p|^2
//! over the edges, computed in i128 and divided once.
//!
//! The seeds are the ones GJK can hand over (a point, an edge or a triangle
//! around the origin, in either winding), plus what only a hand call can
//! give (repeated points, no points), and a polytope too small for the
//! polygon (`Epa<_, 3>`), where EPA must prune and still answer soundly.

use gjk2d::glam::DVec2;
use gjk2d::{Epa, EpaConfig, MinkowskiDifference, PenetrationEstimate, PenetrationSolver, Status, SupportPoint};
use proptest::prelude::*;

#[path = "common/geo.rs"]
mod geo;
use geo::integer_hull;

/// A convex polygon (counter-clockwise, integer vertices) posing as B - A.
struct Difference {
    vertices: Vec<(i64, i64)>,
    /// What it says of its vertex count (`MinkowskiDifference::vertex_bound`).
    vertex_bound: usize,
}

impl Difference {
    fn new(vertices: &[(i64, i64)]) -> Self {
        let n = vertices.len();
        for i in 0..n {
            let (a, b, c) = (vertices[i], vertices[(i + 1) % n], vertices[(i + 2) % n]);
            let turn = (b.0 - a.0) * (c.1 - b.1) - (b.1 - a.1) * (c.0 - b.0);
            assert!(turn > 0, "test polygon must be strictly convex and counter-clockwise");
        }
        Self { vertices: vertices.to_vec(), vertex_bound: usize::MAX }
    }

    fn point(&self, i: usize) -> SupportPoint<f64> {
        let (x, y) = self.vertices[i];
        SupportPoint { point: DVec2::new(x as f64, y as f64), id: i as u32 }
    }

    /// The exact depth, squared: the smallest squared distance from the
    /// origin to an edge's line (the origin is inside or on the boundary).
    fn exact_depth_squared(&self) -> f64 {
        let n = self.vertices.len();
        let mut best: Option<(i128, i128)> = None;
        for i in 0..n {
            let (p, q) = (self.vertices[i], self.vertices[(i + 1) % n]);
            let cross = p.0 as i128 * q.1 as i128 - p.1 as i128 * q.0 as i128;
            assert!(cross >= 0, "the origin must be inside the test polygon");
            let (dx, dy) = ((q.0 - p.0) as i128, (q.1 - p.1) as i128);
            let (num, den) = (cross * cross, dx * dx + dy * dy);
            // num / den < best.0 / best.1, compared exactly.
            if best.is_none_or(|(bn, bd)| num * bd < bn * den) {
                best = Some((num, den));
            }
        }
        let (num, den) = best.unwrap();
        num as f64 / den as f64
    }
}

impl MinkowskiDifference<f64> for Difference {
    fn support(&self, direction: DVec2) -> SupportPoint<f64> {
        let mut best = 0;
        for i in 1..self.vertices.len() {
            if self.point(i).point.dot(direction) > self.point(best).point.dot(direction) {
                best = i;
            }
        }
        self.point(best)
    }
    fn scale(&self) -> f64 {
        self.vertices.iter().map(|&(x, y)| ((x * x + y * y) as f64).sqrt()).fold(0.0, f64::max)
    }
    fn is_polytope(&self) -> bool {
        true
    }
    fn vertex_bound(&self) -> usize {
        self.vertex_bound
    }
}

fn check_depth(name: &str, difference: &Difference, simplex: &[SupportPoint<f64>]) {
    let estimate = Epa::<f64>::default().solve(difference, simplex);
    assert_eq!(estimate.status, Status::Converged, "{name}: {estimate:?}");
    assert!((estimate.normal.length() - 1.0).abs() <= 1e-15, "{name}: normal {:?}", estimate.normal);
    // Converged: the exact depth, and B moved by it along `normal` separates.
    check_sound(name, difference, &estimate).unwrap();
}

/// Whatever the status, an answer must be achievable (moving B by `depth`
/// along `normal` separates: an upper bound of the depth) with its error
/// bound reaching down to the exact depth; a converged one must be exact.
fn check_sound(name: &str, d: &Difference, estimate: &PenetrationEstimate<f64>) -> Result<(), String> {
    let exact = d.exact_depth_squared().sqrt();
    let tolerance = 1e-12 * d.scale();
    let reach = d.support(-estimate.normal).point.dot(-estimate.normal);
    let wrong = if estimate.depth + tolerance < exact {
        "depth below the exact one"
    } else if estimate.depth - estimate.error_bound > exact + tolerance {
        "error bound short of the exact depth"
    } else if reach > estimate.depth + tolerance {
        "the shapes still overlap when moved by the depth"
    } else if estimate.status == Status::Converged && (estimate.depth - exact).abs() > tolerance {
        "converged to a depth that is not exact"
    } else {
        return Ok(());
    };
    Err(format!("{name}: {wrong}: {estimate:?}, exact {exact}, reach {reach}"))
}

/// A hexagon around the origin, no edge through it.
fn hexagon() -> Difference {
    Difference::new(&[(-5, -3), (4, -4), (7, 1), (3, 6), (-2, 5), (-6, 1)])
}

#[test]
fn triangle_seeds_in_either_winding() {
    let d = hexagon();
    // Vertices 0, 2 and 4 enclose the origin.
    let (a, b, c) = (d.point(0), d.point(2), d.point(4));
    check_depth("counter-clockwise triangle", &d, &[a, b, c]);
    check_depth("clockwise triangle", &d, &[a, c, b]);
}

#[test]
fn an_edge_through_the_origin_is_widened_by_the_loop() {
    // Vertices 0 and 3 of this quadrilateral are opposite, on a line
    // through the origin: GJK's touching exit with two points.
    let d = Difference::new(&[(-4, -4), (3, -5), (6, 6), (-5, 2)]);
    check_depth("edge seed", &d, &[d.point(0), d.point(2)]);
    check_depth("edge seed, reversed", &d, &[d.point(2), d.point(0)]);
    // A repeated point is left out: the same edge.
    check_depth("edge seed with a repeat", &d, &[d.point(0), d.point(0), d.point(2)]);
}

#[test]
fn a_point_at_the_origin_on_the_boundary_gives_zero_depth() {
    // The origin is a vertex of the difference: touching.
    let d = Difference::new(&[(0, 0), (5, 1), (4, 6), (-1, 4)]);
    check_depth("point seed at a vertex", &d, &[d.point(0)]);
}

#[test]
fn an_edge_on_the_boundary_gives_zero_depth() {
    // The origin is inside the bottom edge: touching along it.
    let d = Difference::new(&[(-3, 0), (4, 0), (2, 5), (-2, 4)]);
    check_depth("edge seed on the boundary", &d, &[d.point(0), d.point(1)]);
}

#[test]
fn no_seed_at_all_is_an_answer_not_a_panic() {
    let d = hexagon();
    let estimate = Epa::<f64>::default().solve(&d, &[]);
    assert!(estimate.depth.is_finite() && estimate.error_bound.is_finite(), "{estimate:?}");
    assert!((estimate.normal.length() - 1.0).abs() <= 1e-15, "{estimate:?}");
}

/// A 64-gon of radius 1000 with integer vertices (rounded from a regular
/// one, still strictly convex), around the origin but not centred on it.
fn many_sided() -> Difference {
    let vertices: Vec<(i64, i64)> = (0..64)
        .map(|k| {
            let angle = k as f64 * core::f64::consts::TAU / 64.0;
            ((1000.0 * angle.cos()).round() as i64 + 137, (1000.0 * angle.sin()).round() as i64 - 71)
        })
        .collect();
    Difference::new(&vertices)
}

#[test]
fn roomy_polytope_converges_exactly() {
    let d = many_sided();
    check_depth("64-gon", &d, &[d.point(0), d.point(21), d.point(42)]);
}

#[test]
fn a_full_polytope_stays_sound() {
    let d = many_sided();
    let mut limited = 0;
    for n in [3usize, 4, 8] {
        let config = EpaConfig::default();
        let simplex = [d.point(0), d.point(21), d.point(42)];
        let estimate = match n {
            3 => Epa::<f64, 3>::new(config).solve(&d, &simplex),
            4 => Epa::<f64, 4>::new(config).solve(&d, &simplex),
            _ => Epa::<f64, 8>::new(config).solve(&d, &simplex),
        };
        check_sound(&format!("N = {n}"), &d, &estimate).unwrap();
        if estimate.status != Status::Converged {
            // Full with nothing to merge, or merging and going round.
            assert!(matches!(estimate.status, Status::CapacityLimit | Status::IterationLimit), "N = {n}: {estimate:?}");
            limited += 1;
        }
    }
    assert!(limited > 0, "no capacity was too small: the test checks nothing");
}

#[test]
fn a_polytope_with_room_for_every_vertex_answers_as_before() {
    // Told that the difference has at most its 64 vertices, a polytope of
    // 80 corners knows it cannot fill: the same answer, to the bit.
    let (unbounded, mut bounded) = (many_sided(), many_sided());
    bounded.vertex_bound = 64;
    let simplex = [unbounded.point(0), unbounded.point(21), unbounded.point(42)];
    let solver = Epa::<f64, 80>::new(EpaConfig::default());
    let (before, after) = (solver.solve(&unbounded, &simplex), solver.solve(&bounded, &simplex));
    assert_eq!(after.status, Status::Converged, "{after:?}");
    assert_eq!(before, after);
    check_depth("64-gon, bounded", &bounded, &simplex);
}

#[test]
fn a_vertex_bound_that_lies_still_stops_soundly() {
    // A difference that says it has 3 vertices, and has 64: the polytope
    // of 8 corners fills all the same, and the solver stops there, its
    // bounds sound, where with no bound it would merge corners and go on.
    let mut d = many_sided();
    d.vertex_bound = 3;
    let simplex = [d.point(0), d.point(21), d.point(42)];
    let estimate = Epa::<f64, 8>::new(EpaConfig::default()).solve(&d, &simplex);
    assert_eq!(estimate.status, Status::CapacityLimit, "{estimate:?}");
    assert!(estimate.iterations as usize <= 8 - 3 + 1, "{estimate:?}");
    check_sound("a bound that lies", &d, &estimate).unwrap();
}

/// A `k`-gon of radius 10^6 with integer vertices, its center 1.3% of its
/// radius from the origin: many faces are nearly as deep as the deepest.
fn round_off_centre(k: usize) -> Difference {
    let vertices: Vec<(i64, i64)> = (0..k)
        .map(|j| {
            let angle = 0.1 + j as f64 * core::f64::consts::TAU / k as f64;
            ((1e6 * angle.cos()).round() as i64 + 13_000, (1e6 * angle.sin()).round() as i64 - 7_000)
        })
        .collect();
    Difference::new(&vertices)
}

#[test]
fn a_full_polytope_merges_certified_faces_and_converges_exactly() {
    for k in [100, 1000] {
        let d = round_off_centre(k);
        let exact = d.exact_depth_squared().sqrt();
        let simplex = [d.point(0), d.point(k / 3), d.point(2 * k / 3)];
        let config = EpaConfig::default();
        for (n, estimate) in [
            (20, Epa::<f64, 20>::new(config).solve(&d, &simplex)),
            (32, Epa::<f64, 32>::new(config).solve(&d, &simplex)),
        ] {
            let name = format!("{k}-gon, N = {n}");
            assert_eq!(estimate.status, Status::Converged, "{name}: {estimate:?}");
            assert!(
                (estimate.depth - exact).abs() <= 1e-12 * d.scale(),
                "{name}: depth {} against {exact}",
                estimate.depth
            );
            // Every support but the last was inserted: more than the free
            // slots, so corners were merged.
            assert!(estimate.iterations as usize - 1 > n - 3, "{name}: nothing merged: {estimate:?}");
        }
    }
}

#[test]
fn a_full_polytope_prunes_and_still_converges_exactly() {
    // A thin 25-gon (an ellipse 77197 by 1041, turned), the origin near its
    // long side, found by a search for a case where room for 6 corners is
    // not enough: EPA must drop one to go on (the iteration count below
    // shows that it did).
    let d = Difference::new(&[
        (16127, 76027),
        (15366, 73710),
        (13638, 66795),
        (11052, 55717),
        (7770, 41172),
        (3997, 24073),
        (-28, 5496),
        (-4053, -13392),
        (-7825, -31405),
        (-11106, -47411),
        (-13692, -60404),
        (-15419, -69568),
        (-16179, -74327),
        (-15924, -74381),
        (-14670, -69728),
        (-12495, -60660),
        (-9538, -47747),
        (-5982, -31799),
        (-2053, -13820),
        (2004, 5062),
        (5934, 23659),
        (9488, 40804),
        (12446, 55418),
        (14619, 66585),
        (15872, 73601),
    ]);
    let simplex = [d.point(0), d.point(8), d.point(16)];
    let estimate = Epa::<f64, 6>::new(EpaConfig::default()).solve(&d, &simplex);
    let exact = d.exact_depth_squared().sqrt();
    assert_eq!(estimate.status, Status::Converged, "{estimate:?}");
    assert!((estimate.depth - exact).abs() <= 1e-12 * d.scale(), "depth {} against exact {exact}", estimate.depth);
    // Every support but the last was inserted: more than the 3 free slots,
    // so at least one corner was pruned (polytopes have no polish).
    assert!(estimate.iterations - 1 > 6 - 3, "no pruning happened: {estimate:?}");
    // The same answer as with room to spare.
    let roomy = Epa::<f64>::default().solve(&d, &simplex);
    assert!((roomy.depth - estimate.depth).abs() <= 1e-12 * d.scale(), "{roomy:?} against {estimate:?}");
}

/// A `k`-gon of radius 10^6 with integer vertices around the origin, its
/// center `(cx, cy)` away: with the center at the origin every face is
/// within rounding of the deepest, the hardest case for a small polytope.
fn round_around(k: usize, (cx, cy): (i64, i64)) -> Difference {
    let vertices: Vec<(i64, i64)> = (0..k)
        .map(|j| {
            let angle = 0.1 + j as f64 * core::f64::consts::TAU / k as f64;
            ((1e6 * angle.cos()).round() as i64 + cx, (1e6 * angle.sin()).round() as i64 + cy)
        })
        .collect();
    Difference::new(&vertices)
}

/// The convex hull of `points`, counter-clockwise, no collinear vertices
/// (exact in integers); `None` when it is flat or does not hold the origin.
fn convex_hull(points: &[(i64, i64)]) -> Option<Difference> {
    let hull = integer_hull(points.to_vec());
    let n = hull.len();
    let cross = |p: (i64, i64), q: (i64, i64)| p.0 * q.1 - p.1 * q.0;
    let holds_origin = (0..n).all(|i| cross(hull[i], hull[(i + 1) % n]) >= 0);
    (n >= 3 && holds_origin).then(|| Difference::new(&hull))
}

/// The Minkowski sum of `a` and `b`: the hull of their vertices' sums.
fn minkowski_sum(a: &Difference, b: &[(i64, i64)]) -> Difference {
    let sums: Vec<(i64, i64)> = a.vertices.iter().flat_map(|p| b.iter().map(move |q| (p.0 + q.0, p.1 + q.1))).collect();
    convex_hull(&sums).expect("a round polygon around the origin plus a square around it")
}

#[test]
fn a_full_polytope_converges_with_faces_tied_in_four_directions() {
    // A round polygon around a small square at its center, as B - A: the
    // difference has four flat sides, tied for the deepest. The polytope
    // fills before any face is certified; merging the corner whose merged
    // edge keeps the largest bound (not yet certified) makes room, and the
    // default 32 corners converge exactly.
    let square = [(-10_000, -10_000), (10_000, -10_000), (10_000, 10_000), (-10_000, 10_000)];
    for k in [40, 100, 333, 1000] {
        for centre in [(0, 0), (1, 0)] {
            let d = minkowski_sum(&round_around(k, centre), &square);
            let n = d.vertices.len();
            check_depth(
                &format!("{k}-gon around a square, centred at {centre:?}"),
                &d,
                &[d.point(0), d.point(n / 3), d.point(2 * n / 3)],
            );
        }
    }
}

/// EPA from `simplex` with room for 4, 5, 8, 12, 16 and 32 corners (the
/// default): each capacity and its answer.
fn at_small_capacities(d: &Difference, simplex: &[SupportPoint<f64>]) -> [(usize, PenetrationEstimate<f64>); 6] {
    let config = EpaConfig::default();
    [
        (4, Epa::<f64, 4>::new(config).solve(d, simplex)),
        (5, Epa::<f64, 5>::new(config).solve(d, simplex)),
        (8, Epa::<f64, 8>::new(config).solve(d, simplex)),
        (12, Epa::<f64, 12>::new(config).solve(d, simplex)),
        (16, Epa::<f64, 16>::new(config).solve(d, simplex)),
        (32, Epa::<f64, 32>::new(config).solve(d, simplex)),
    ]
}

#[test]
fn merging_uncertified_corners_keeps_every_answer_sound() {
    // Too small a polytope for the faces nearly as deep as the deepest: a
    // full one merges the corner whose merged edge keeps the largest bound,
    // even where that bound is not certified yet. That loses information,
    // never soundness: whatever the status, the depth is achievable and
    // its error bound reaches down to the exact depth.
    let mut stopped_short = 0;
    for k in [12, 40, 100, 333] {
        for centre in [(0, 0), (1, 0), (13_000, -7_000), (-250_000, 400_000)] {
            let d = round_around(k, centre);
            let simplex = [d.point(0), d.point(k / 3), d.point(2 * k / 3)];
            for (n, estimate) in at_small_capacities(&d, &simplex) {
                let name = format!("{k}-gon centred at {centre:?}, N = {n}");
                check_sound(&name, &d, &estimate).unwrap();
                if estimate.status != Status::Converged {
                    stopped_short += 1;
                }
                // Centred (to within 1 in 10^6), a 100-gon's faces are all
                // within 10^-6 of the deepest: certifying it takes a
                // support on nearly every face, more than the default 100
                // iterations. Every other case converges in the default
                // 32 corners.
                let all_tied = k >= 100 && centre.0.abs() <= 1 && centre.1 == 0;
                if n == 32 && !all_tied {
                    assert_eq!(estimate.status, Status::Converged, "{name}: {estimate:?}");
                }
            }
        }
    }
    assert!(stopped_short > 0, "every capacity sufficed: the lossy merge went untested");
}

/// Points scattered over a square around the origin.
fn scattered() -> impl Strategy<Value = Vec<(i64, i64)>> {
    prop::collection::vec((-1000i64..=1000, -1000i64..=1000), 3..80)
}

/// Points within 100 of a circle of radius 10^6, its center up to 0.3
/// radii from the origin (or on it).
fn nearly_round() -> impl Strategy<Value = Vec<(i64, i64)>> {
    let centre = prop_oneof![Just((0i64, 0i64)), (-300_000i64..=300_000, -300_000i64..=300_000)];
    (prop::collection::vec((0u32..1_000_000, -100i64..=100), 3..300), centre).prop_map(|(raw, (cx, cy))| {
        raw.into_iter()
            .map(|(turn, jitter)| {
                let angle = turn as f64 * core::f64::consts::TAU / 1e6;
                let r = 1e6 + jitter as f64;
                ((r * angle.cos()).round() as i64 + cx, (r * angle.sin()).round() as i64 + cy)
            })
            .collect()
    })
}

/// A triangle of `d`'s vertices that holds the origin (inside or on its
/// boundary), as GJK would hand over: the first found.
fn enclosing_triangle(d: &Difference) -> Option<[SupportPoint<f64>; 3]> {
    let v = &d.vertices;
    let n = v.len();
    let cross = |p: (i64, i64), q: (i64, i64)| p.0 * q.1 - p.1 * q.0;
    for i in 0..n {
        for j in i + 1..n {
            for k in j + 1..n {
                // Counter-clockwise (vertex order): the origin is inside when
                // it is on no edge's outer side.
                if cross(v[i], v[j]) >= 0 && cross(v[j], v[k]) >= 0 && cross(v[k], v[i]) >= 0 {
                    return Some([d.point(i), d.point(j), d.point(k)]);
                }
            }
        }
    }
    None
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(400))]

    /// Random convex polygons around the origin (the hulls of scattered
    /// points: a few vertices; of points near a circle: up to hundreds, many
    /// faces nearly as deep as the deepest), and polytopes from 4 corners
    /// up: every answer sound, every converged one exact.
    #[test]
    fn small_polytopes_stay_sound_on_random_polygons(raw in prop_oneof![scattered(), nearly_round()]) {
        let Some(d) = convex_hull(&raw) else { return Ok(()) };
        let Some(simplex) = enclosing_triangle(&d) else { return Ok(()) };
        for (n, estimate) in at_small_capacities(&d, &simplex) {
            check_sound(&format!("N = {n}"), &d, &estimate).map_err(TestCaseError::fail)?;
        }
    }

    /// The reasoning that lets EPA drop its code for a full polytope: every
    /// corner is a vertex of the difference, none twice, so a polytope
    /// with room for all of them never fills. Told the true vertex count,
    /// a polytope of 64 corners converges on every polygon of fewer
    /// vertices, with the answer it gives knowing nothing of the count.
    #[test]
    fn room_for_every_vertex_never_fills(raw in prop_oneof![scattered(), nearly_round()]) {
        let Some(mut d) = convex_hull(&raw) else { return Ok(()) };
        let Some(simplex) = enclosing_triangle(&d) else { return Ok(()) };
        if d.vertices.len() >= 64 {
            return Ok(());
        }
        let solver = Epa::<f64, 64>::new(EpaConfig::default());
        let unbounded = solver.solve(&d, &simplex);
        d.vertex_bound = d.vertices.len();
        let bounded = solver.solve(&d, &simplex);
        prop_assert_eq!(bounded.status, Status::Converged, "{:?}", bounded);
        prop_assert_eq!(bounded, unbounded);
    }
}
