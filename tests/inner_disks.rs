//! On hosts, the intersection test and the distance query call two shapes
//! overlapping, before asking any support, where the disks each contains
//! about its center overlap (`SupportMap::inner_radius_squared`); and the
//! intersection test calls them apart where the disks about their centers
//! that contain them (`SupportMap::bounding_radius`) are apart. Checked
//! here against exact arithmetic:
//!
//! - a polygon's inner disk is never larger than the exact distance from
//!   its center to its nearest edge line, and for all but slivers it is
//!   that distance to within 0.1% (else the test would never be taken);
//!   its bounding radius falls short of the exact one by no more than the
//!   margin the test allows for it;
//! - the inner disks decide a pair (no iteration) only where the exact
//!   shapes overlap or touch: squares face to face and circles against a
//!   polygon's nearest edge, with gaps of a few eps either way, rotated and
//!   far from the origin, where the disks touch where the shapes do;
//! - the bounding disks decide a pair only where the exact shapes are
//!   apart: squares and boxes corner to corner along their diagonal,
//!   circles against a polygon's farthest vertex, capsules end to corner,
//!   where the disks touch where the shapes do;
//! - a capsule's disks are about its segment: its side against a polygon's
//!   nearest edge (inner) or farthest vertex (bounding), and against a
//!   circle, decide only pairs that overlap, or are apart, exactly.

#[path = "common/rng.rs"]
mod rng;

use gjk2d::{Capsule, Circle, Gjk, Polygon, Real, Rectangle, SupportMap, Transform};
use gjk2d_oracle::exact::{q_from_f64, Q};
use gjk2d_oracle::{pair, transform_shape, Shape};
use rng::Rng;

fn pt<R: Real>(v: R::Vector) -> [f64; 2] {
    let (x, y) = R::components(v);
    [x.to_f64(), y.to_f64()]
}

fn round<R: Real>(x: f64) -> f64 {
    R::from_f64(x).to_f64()
}

/// A convex polygon near an ellipse of semi-axes `size` and `size * aspect`,
/// counter-clockwise, turned by `turn` and centered on `origin`, rounded to `R`.
fn ellipse_polygon<R: Real>(rng: &mut Rng, n: usize, size: f64, aspect: f64, origin: [f64; 2]) -> Vec<[f64; 2]> {
    let (phase, turn) = (rng.unit(), rng.range(0.0, std::f64::consts::TAU));
    (0..n)
        .map(|k| {
            let t = (k as f64 + phase + 0.3 * rng.unit()) / n as f64 * std::f64::consts::TAU;
            let (x, y) = (size * t.cos(), size * aspect * t.sin());
            let (c, s) = (turn.cos(), turn.sin());
            [round::<R>(origin[0] + c * x - s * y), round::<R>(origin[1] + s * x + c * y)]
        })
        .collect()
}

fn polygon<R: Real>(points: &[[f64; 2]]) -> Option<Polygon<R, 64>> {
    let v: Vec<R::Vector> = points.iter().map(|p| R::vector(R::from_f64(p[0]), R::from_f64(p[1]))).collect();
    Polygon::new(&v).ok()
}

fn q(x: f64) -> Q {
    q_from_f64(x)
}

/// The exact square of the least distance from the polygon's center to an
/// edge line, over the vertices as the polygon stores them (each given
/// point less the reference point, rounded as the constructor rounds it),
/// and the unit normal of that edge (rounded); zero where the center is not
/// strictly inside every edge.
fn exact_inner<R: Real>(p: &Polygon<R, 64>, points: &[[f64; 2]]) -> (Q, [f64; 2]) {
    let reference = pt::<R>(p.reference_point());
    let stored: Vec<[Q; 2]> =
        points.iter().map(|v| [q(round::<R>(v[0] - reference[0])), q(round::<R>(v[1] - reference[1]))]).collect();
    let c = pt::<R>(p.center());
    let c = [q(c[0]), q(c[1])];
    let mut least: Option<(Q, [f64; 2])> = None;
    for i in 0..stored.len() {
        let (v, w) = (&stored[i], &stored[(i + 1) % stored.len()]);
        let e = [&w[0] - &v[0], &w[1] - &v[1]];
        let to_c = [&c[0] - &v[0], &c[1] - &v[1]];
        let cross = &e[0] * &to_c[1] - &e[1] * &to_c[0];
        if cross <= q(0.0) {
            return (q(0.0), [0.0, 0.0]);
        }
        let length2 = &e[0] * &e[0] + &e[1] * &e[1];
        let h2 = &cross * &cross / length2;
        if least.as_ref().is_none_or(|(l, _)| &h2 < l) {
            let (ex, ey) = (gjk2d_oracle::exact::q_to_f64(&e[0]), gjk2d_oracle::exact::q_to_f64(&e[1]));
            let len = ex.hypot(ey);
            least = Some((h2, [ey / len, -ex / len]));
        }
    }
    least.unwrap_or((q(0.0), [0.0, 0.0]))
}

fn disks_are_below_the_exact_ones<R: Real>() {
    let mut rng = Rng(0x1ee7 + R::EPSILON.to_f64().to_bits());
    let (mut checked, mut useful, mut well_shaped) = (0, 0, 0);
    for case in 0..3000 {
        let n = 3 + case % 62;
        let aspect = [1.0, 0.7, 0.3, 1e-2, 1e-3][case % 5];
        let scale = 2f64.powi(rng.range(-30.0, 30.0) as i32);
        let origin = if case % 3 == 0 { [1e5 * scale, -7e4 * scale] } else { [0.0, 0.0] };
        let points = ellipse_polygon::<R>(&mut rng, n, scale, aspect, origin);
        let Some(p) = polygon::<R>(&points) else { continue };
        let disk = p.inner_radius_squared().to_f64();
        let (exact, _) = exact_inner(&p, &points);
        assert!(q(disk) <= exact, "case {case}: disk^2 {disk:e} above the exact {:e}", exact_f64(&exact));
        checked += 1;
        if aspect >= 0.3 {
            well_shaped += 1;
            useful += (q(disk) >= exact * q(0.999)) as u32;
        }
    }
    assert!(checked > 2000, "only {checked} polygons built");
    assert!(useful * 100 >= well_shaped * 99, "{useful} of {well_shaped} disks within 0.1% of the exact");
    for r in [1e-20, 1e-3, 1.0, 1e6] {
        let r_real = R::from_f64(r);
        let exact = q(round::<R>(r)) * q(round::<R>(r));
        for disk in [
            Circle::new(r_real).map(|c| c.inner_radius_squared()),
            Capsule::new(R::vector(R::ZERO, R::ZERO), R::vector(r_real, r_real), r_real)
                .map(|c| c.inner_radius_squared()),
            Rectangle::new(r_real + r_real, R::from_f64(3.0 * r)).map(|c| c.inner_radius_squared()),
        ]
        .into_iter()
        .flatten()
        {
            assert!(q(disk.to_f64()) <= exact, "r {r:e}: disk^2 {:e}", disk.to_f64());
        }
    }
}

fn exact_f64(x: &Q) -> f64 {
    gjk2d_oracle::exact::q_to_f64(x)
}

#[test]
fn disks_are_below_the_exact_ones_f32() {
    disks_are_below_the_exact_ones::<f32>();
}

#[test]
fn disks_are_below_the_exact_ones_f64() {
    disks_are_below_the_exact_ones::<f64>();
}

/// Places B's center at `gap` (a fraction) beyond `reach` (the sum of the
/// two disks' exact radii) from A's, along `along` (a unit vector of A's
/// frame), both turned by `turn` and A at `origin`. Where the intersection
/// test took no iteration (the disks decided), the exact shapes must agree
/// with its verdict, and where it found them overlapping the distance
/// query must too. Returns the verdict where the disks decided.
#[allow(clippy::too_many_arguments)]
fn placed_pair<R: Real, A: SupportMap<R>, B: SupportMap<R>>(
    (a, exact_a): (&A, &Shape),
    (b, exact_b): (&B, &Shape),
    reach: f64,
    along: [f64; 2],
    gap: f64,
    turn: f64,
    origin: [f64; 2],
) -> Option<bool> {
    let gjk = Gjk::<R>::new();
    let (c, s) = (turn.cos(), turn.sin());
    let d = reach * (1.0 + gap);
    // B's center in A's frame, then both placed; a shape's center is
    // measured from its reference point, and B's translation takes it off.
    let center = |shape: &dyn SupportMap<R>| {
        let (reference, center) = (pt::<R>(shape.reference_point()), pt::<R>(shape.center()));
        [reference[0] + center[0], reference[1] + center[1]]
    };
    let (ca, cb) = (center(a), center(b));
    let turned = |p: [f64; 2]| [c * p[0] - s * p[1], s * p[0] + c * p[1]];
    let world_b = turned([ca[0] + along[0] * d, ca[1] + along[1] * d]);
    let turned_cb = turned(cb);
    let tb_at = [origin[0] + world_b[0] - turned_cb[0], origin[1] + world_b[1] - turned_cb[1]];
    let angle = R::from_f64(turn);
    let ta = Transform::new(R::vector(R::from_f64(origin[0]), R::from_f64(origin[1])), angle).expect("placement");
    let tb = Transform::new(R::vector(R::from_f64(tb_at[0]), R::from_f64(tb_at[1])), angle).expect("placement");
    let detection = gjk.intersects(a, &ta, b, &tb);
    let apart = gjk.distance(a, &ta, b, &tb);
    if detection.iterations != 0 {
        return None;
    }
    let placed = |shape: &Shape, t: &Transform<R>| {
        let o = pt::<R>(t.translation());
        transform_shape(shape, t.cos().to_f64(), t.sin().to_f64(), o[0], o[1])
    };
    let exact = pair(&placed(exact_a, &ta), &placed(exact_b, &tb));
    let ctx = format!("reach {reach:e} gap {gap:e} turn {turn} origin {origin:?}");
    assert_eq!(
        detection.intersecting, exact.touching_or_overlapping,
        "{ctx}: decided with no iteration; the exact shapes are {:e} apart",
        exact.distance
    );
    if detection.intersecting {
        assert!(apart.is_none(), "{ctx}: the disks overlap, yet the distance query found the shapes apart");
    }
    Some(detection.intersecting)
}

/// [`placed_pair`] both ways round: B placed along `along` from A, and A
/// along its opposite from B; `at` is the gap, the turn and the origin.
fn both_ways<R: Real, A: SupportMap<R>, B: SupportMap<R>>(
    a: (&A, &Shape),
    b: (&B, &Shape),
    reach: f64,
    along: [f64; 2],
    (gap, turn, origin): (f64, f64, [f64; 2]),
) -> [Option<bool>; 2] {
    let away = [-along[0], -along[1]];
    [
        placed_pair::<R, _, _>(a, b, reach, along, gap, turn, origin),
        placed_pair::<R, _, _>(b, a, reach, away, gap, turn, origin),
    ]
}

/// The polygon as the oracle takes it, in local coordinates (exact here:
/// these polygons are about the origin).
fn exact_polygon<R: Real>(p: &Polygon<R, 64>) -> Shape {
    Shape::Polygon((0..p.len()).map(|i| pt::<R>(p.vertex(i).expect("in range"))).collect())
}

/// A case's placement: its scale, A's origin (near or far), the turn of
/// both shapes, and the gap (a fraction of the disks' reach): a few eps
/// either way, none, and 1e-3.
fn placement<R: Real>(rng: &mut Rng, case: usize) -> (f64, [f64; 2], f64, f64) {
    let eps = R::EPSILON.to_f64();
    let gaps = [-1e-3, -16.0 * eps, -4.0 * eps, -eps, 0.0, eps, 2.0 * eps, 4.0 * eps, 16.0 * eps, 64.0 * eps, 1e-3];
    let scale = 2f64.powi(rng.range(-20.0, 20.0) as i32);
    let origin = if case.is_multiple_of(2) { [3e4 * scale, -2e4 * scale] } else { [0.0, 0.0] };
    let turn = if case.is_multiple_of(3) { 0.0 } else { rng.range(0.0, std::f64::consts::TAU) };
    (scale, origin, turn, gaps[case % gaps.len()])
}

/// A capsule whose segment, of half length `half`, lies across `along` (a
/// unit vector) through its center: placed along `along`, its side faces
/// the other shape. Its ends are each other's negatives, so its center is
/// the origin exactly.
fn capsule_across<R: Real>(along: [f64; 2], half: f64, radius: f64) -> (Capsule<R>, Shape) {
    let end = [round::<R>(-half * along[1]), round::<R>(half * along[0])];
    let v = |p: [f64; 2]| R::vector(R::from_f64(p[0]), R::from_f64(p[1]));
    let capsule = Capsule::new(v([-end[0], -end[1]]), v(end), R::from_f64(radius)).expect("a capsule");
    (capsule, Shape::Capsule { a: [-end[0], -end[1]], b: end, radius })
}

fn disks_decide_only_overlapping_pairs<R: Real>() {
    let mut rng = Rng(0xd15c + R::EPSILON.to_f64().to_bits());
    let mut decided = 0;
    for case in 0..600 {
        let (scale, origin, turn, gap) = placement::<R>(&mut rng, case);
        // Two squares face to face: their disks touch where their faces do.
        let (ha, hb) = (round::<R>(scale * rng.range(0.5, 1.0)), round::<R>(scale * rng.range(0.5, 1.0)));
        let square = |h: f64| polygon::<R>(&[[-h, -h], [h, -h], [h, h], [-h, h]]).expect("a square");
        let (sa, sb) = (square(ha), square(hb));
        decided += (placed_pair::<R, _, _>(
            (&sa, &exact_polygon(&sa)),
            (&sb, &exact_polygon(&sb)),
            ha + hb,
            [1.0, 0.0],
            gap,
            turn,
            origin,
        ) == Some(true)) as u32;
        let (ra, rb) = (
            Rectangle::new(R::from_f64(2.0 * ha), R::from_f64(3.0 * ha)).expect("a box"),
            Rectangle::new(R::from_f64(2.0 * hb), R::from_f64(2.0 * hb)).expect("a box"),
        );
        let boxed = |h: [f64; 2]| Shape::Polygon(vec![[-h[0], -h[1]], [h[0], -h[1]], [h[0], h[1]], [-h[0], h[1]]]);
        decided += (placed_pair::<R, _, _>(
            (&ra, &boxed([ha, 1.5 * ha])),
            (&rb, &boxed([hb, hb])),
            ha + hb,
            [1.0, 0.0],
            gap,
            turn,
            origin,
        ) == Some(true)) as u32;
        // A circle against a polygon's nearest edge.
        let aspect = rng.range(0.3, 1.0);
        let points = ellipse_polygon::<R>(&mut rng, 3 + case % 30, scale, aspect, [0.0, 0.0]);
        let Some(p) = polygon::<R>(&points) else { continue };
        let (inner, normal) = exact_inner(&p, &points);
        let r = round::<R>(scale * rng.range(0.2, 1.0));
        let circle = Circle::new(R::from_f64(r)).expect("a circle");
        let exact_circle = Shape::Circle { center: [0.0, 0.0], radius: r };
        let reach = exact_f64(&inner).sqrt() + r;
        decided += (placed_pair::<R, _, _>(
            (&p, &exact_polygon(&p)),
            (&circle, &exact_circle),
            reach,
            normal,
            gap,
            turn,
            origin,
        ) == Some(true)) as u32;
        let facing = [-normal[0], -normal[1]];
        decided += (placed_pair::<R, _, _>(
            (&circle, &exact_circle),
            (&p, &exact_polygon(&p)),
            reach,
            facing,
            gap,
            turn,
            origin,
        ) == Some(true)) as u32;
        // A capsule's side against the polygon's nearest edge, and against
        // a circle: its disk reaches along its whole segment.
        let (capsule, exact_capsule) = capsule_across::<R>(normal, round::<R>(scale * rng.range(0.1, 2.0)), r);
        let exact_p = exact_polygon(&p);
        let at = (gap, turn, origin);
        let verdicts = both_ways::<R, _, _>((&p, &exact_p), (&capsule, &exact_capsule), reach, normal, at)
            .into_iter()
            .chain(both_ways::<R, _, _>((&circle, &exact_circle), (&capsule, &exact_capsule), 2.0 * r, normal, at));
        decided += verdicts.filter(|v| *v == Some(true)).count() as u32;
    }
    assert!(decided > 600, "only {decided} pairs decided by their disks");
}

#[test]
fn disks_decide_only_overlapping_pairs_f32() {
    disks_decide_only_overlapping_pairs::<f32>();
}

#[test]
fn disks_decide_only_overlapping_pairs_f64() {
    disks_decide_only_overlapping_pairs::<f64>();
}

/// Whether `bound` (a bounding radius), with the 4 eps the pair's test
/// allows each radius, covers `exact_square` (the exact square of the
/// farthest distance from the center) plus `radius` beyond it.
fn covers<R: Real>(bound: f64, exact_square: &Q, radius: f64) -> bool {
    let reach = q(bound) * q(1.0 + 4.0 * R::EPSILON.to_f64()) - q(radius);
    reach >= q(0.0) && exact_square <= &(&reach * &reach)
}

/// The exact square of the farthest distance from the polygon's center to
/// a vertex as the polygon stores it (as `exact_inner`), and the unit
/// direction to that vertex (rounded).
fn exact_outer<R: Real>(p: &Polygon<R, 64>, points: &[[f64; 2]]) -> (Q, [f64; 2]) {
    let reference = pt::<R>(p.reference_point());
    let c = pt::<R>(p.center());
    let mut farthest = (q(0.0), [0.0, 0.0]);
    for v in points {
        let d = [q(round::<R>(v[0] - reference[0])) - q(c[0]), q(round::<R>(v[1] - reference[1])) - q(c[1])];
        let d2 = &d[0] * &d[0] + &d[1] * &d[1];
        if d2 > farthest.0 {
            let (x, y) = (exact_f64(&d[0]), exact_f64(&d[1]));
            let len = x.hypot(y);
            farthest = (d2, [x / len, y / len]);
        }
    }
    farthest
}

fn bounding_radii_cover_the_exact_ones<R: Real>() {
    let mut rng = Rng(0xb0d5 + R::EPSILON.to_f64().to_bits());
    let (mut checked, mut tight) = (0, 0);
    for case in 0..3000 {
        let n = 3 + case % 62;
        let aspect = [1.0, 0.7, 0.3, 1e-2, 1e-3][case % 5];
        let scale = 2f64.powi(rng.range(-30.0, 30.0) as i32);
        let origin = if case % 3 == 0 { [1e5 * scale, -7e4 * scale] } else { [0.0, 0.0] };
        let points = ellipse_polygon::<R>(&mut rng, n, scale, aspect, origin);
        let Some(p) = polygon::<R>(&points) else { continue };
        let bound = p.bounding_radius().to_f64();
        let (exact, _) = exact_outer(&p, &points);
        assert!(
            covers::<R>(bound, &exact, 0.0),
            "case {case}: radius {bound:e} short of {:e}",
            exact_f64(&exact).sqrt()
        );
        checked += 1;
        tight += (q(bound) * q(bound) <= exact * q(1.001)) as u32;
    }
    assert!(checked > 2000, "only {checked} polygons built");
    assert_eq!(tight, checked, "a bounding radius more than 0.1% loose");
    for case in 0..400 {
        let scale = 2f64.powi(rng.range(-30.0, 30.0) as i32);
        let (w, h) = (round::<R>(scale * rng.range(0.1, 2.0)), round::<R>(scale * rng.range(0.1, 2.0)));
        let (hw, hh) = (q(w) * q(0.5), q(h) * q(0.5));
        let exact = &hw * &hw + &hh * &hh;
        let rectangle = Rectangle::new(R::from_f64(w), R::from_f64(h)).expect("a box");
        assert!(covers::<R>(rectangle.bounding_radius().to_f64(), &exact, 0.0), "case {case}: box {w:e} x {h:e}");
        // A capsule from the origin: its core is exact, its center half
        // of it.
        let end = [round::<R>(scale * rng.range(-2.0, 2.0)), round::<R>(scale * rng.range(-2.0, 2.0))];
        let r = round::<R>(scale * rng.range(0.0, 1.0));
        let Ok(capsule) = Capsule::new(
            R::vector(R::ZERO, R::ZERO),
            R::vector(R::from_f64(end[0]), R::from_f64(end[1])),
            R::from_f64(r),
        ) else {
            continue;
        };
        let half = [q(end[0]) * q(0.5), q(end[1]) * q(0.5)];
        let exact = &half[0] * &half[0] + &half[1] * &half[1];
        assert!(
            covers::<R>(capsule.bounding_radius().to_f64(), &exact, r),
            "case {case}: capsule to {end:?}, radius {r:e}"
        );
    }
}

#[test]
fn bounding_radii_cover_the_exact_ones_f32() {
    bounding_radii_cover_the_exact_ones::<f32>();
}

#[test]
fn bounding_radii_cover_the_exact_ones_f64() {
    bounding_radii_cover_the_exact_ones::<f64>();
}

fn bounding_disks_decide_only_separated_pairs<R: Real>() {
    let mut rng = Rng(0xa9a7 + R::EPSILON.to_f64().to_bits());
    let mut decided = 0;
    for case in 0..600 {
        let (scale, origin, turn, gap) = placement::<R>(&mut rng, case);
        let mut count = |verdict: Option<bool>| decided += (verdict == Some(false)) as u32;
        // Squares corner to corner along their diagonal: their bounding
        // disks touch where their corners do.
        let (ha, hb) = (round::<R>(scale * rng.range(0.5, 1.0)), round::<R>(scale * rng.range(0.5, 1.0)));
        let square = |h: f64| polygon::<R>(&[[-h, -h], [h, -h], [h, h], [-h, h]]).expect("a square");
        let (sa, sb) = (square(ha), square(hb));
        let diagonal = [std::f64::consts::FRAC_1_SQRT_2; 2];
        let (exact_sa, exact_sb) = (exact_polygon(&sa), exact_polygon(&sb));
        let reach = (ha + hb) * std::f64::consts::SQRT_2;
        count(placed_pair::<R, _, _>((&sa, &exact_sa), (&sb, &exact_sb), reach, diagonal, gap, turn, origin));
        // Boxes of one aspect, corner to corner.
        let k = rng.range(0.3, 1.0);
        let (wa, wb) = (round::<R>(2.0 * ha), round::<R>(2.0 * hb));
        let (ta, tb) = (round::<R>(wa * k), round::<R>(wb * k));
        let boxed = |w: f64, h: f64| {
            let (x, y) = (w * 0.5, h * 0.5);
            (
                Rectangle::new(R::from_f64(w), R::from_f64(h)).expect("a box"),
                Shape::Polygon(vec![[-x, -y], [x, -y], [x, y], [-x, y]]),
            )
        };
        let ((ra, exact_ra), (rb, exact_rb)) = (boxed(wa, ta), boxed(wb, tb));
        let corner = |w: f64, h: f64| 0.5 * w.hypot(h);
        let along = [wa / (2.0 * corner(wa, ta)), ta / (2.0 * corner(wa, ta))];
        let reach = corner(wa, ta) + corner(wb, tb);
        count(placed_pair::<R, _, _>((&ra, &exact_ra), (&rb, &exact_rb), reach, along, gap, turn, origin));
        // A capsule along the diagonal, its end against a square's corner.
        let l = round::<R>(scale * rng.range(0.2, 1.0));
        let rc = round::<R>(scale * rng.range(0.1, 0.5));
        let capsule = Capsule::new(
            R::vector(R::from_f64(-l), R::from_f64(-l)),
            R::vector(R::from_f64(l), R::from_f64(l)),
            R::from_f64(rc),
        )
        .expect("a capsule");
        let exact_capsule = Shape::Capsule { a: [-l, -l], b: [l, l], radius: rc };
        let reach = l * std::f64::consts::SQRT_2 + rc + hb * std::f64::consts::SQRT_2;
        count(placed_pair::<R, _, _>((&capsule, &exact_capsule), (&sb, &exact_sb), reach, diagonal, gap, turn, origin));
        // A circle against a polygon's farthest vertex, as A and as B.
        let aspect = rng.range(0.3, 1.0);
        let points = ellipse_polygon::<R>(&mut rng, 3 + case % 30, scale, aspect, [0.0, 0.0]);
        let Some(p) = polygon::<R>(&points) else { continue };
        let (outer, toward) = exact_outer(&p, &points);
        let r = round::<R>(scale * rng.range(0.2, 1.0));
        let circle = Circle::new(R::from_f64(r)).expect("a circle");
        let exact_circle = Shape::Circle { center: [0.0, 0.0], radius: r };
        let exact_p = exact_polygon(&p);
        let reach = exact_f64(&outer).sqrt() + r;
        count(placed_pair::<R, _, _>((&p, &exact_p), (&circle, &exact_circle), reach, toward, gap, turn, origin));
        let away = [-toward[0], -toward[1]];
        count(placed_pair::<R, _, _>((&circle, &exact_circle), (&p, &exact_p), reach, away, gap, turn, origin));
        // A capsule's side against the polygon's farthest vertex, and
        // against a circle: its bounding disk is about its segment.
        let (capsule, exact_capsule) = capsule_across::<R>(toward, round::<R>(scale * rng.range(0.1, 2.0)), r);
        let at = (gap, turn, origin);
        let verdicts = both_ways::<R, _, _>((&p, &exact_p), (&capsule, &exact_capsule), reach, toward, at)
            .into_iter()
            .chain(both_ways::<R, _, _>((&circle, &exact_circle), (&capsule, &exact_capsule), 2.0 * r, toward, at));
        verdicts.for_each(&mut count);
    }
    assert!(decided > 200, "only {decided} pairs decided apart by their bounding disks");
}

#[test]
fn bounding_disks_decide_only_separated_pairs_f32() {
    bounding_disks_decide_only_separated_pairs::<f32>();
}

#[test]
fn bounding_disks_decide_only_separated_pairs_f64() {
    bounding_disks_decide_only_separated_pairs::<f64>();
}
