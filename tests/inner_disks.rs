//! On hosts, the intersection test and the distance query call two shapes
//! overlapping, before asking any support, where the disks each contains
//! about its center overlap (`SupportMap::inner_radius_squared`). Checked
//! here against exact arithmetic:
//!
//! - a polygon's disk is never larger than the exact distance from its
//!   center to its nearest edge line, and for all but slivers it is that
//!   distance to within 0.1% (else the test would never be taken);
//! - the disks decide a pair (no iteration) only where the exact shapes
//!   overlap or touch: squares face to face and circles against a
//!   polygon's nearest edge, with gaps of a few eps either way, rotated and
//!   far from the origin, where the disks touch where the shapes do.

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

/// Places B's center at `gap` (a fraction) beyond the sum of the two disks'
/// exact radii from A's, along `along` (a unit vector of A's frame), both
/// turned by `turn` and A at `origin`; where the intersection test took no
/// iteration (the disks decided), the distance query must call the pair
/// overlapping too, and the exact shapes must overlap or touch. Returns
/// whether the disks decided.
#[allow(clippy::too_many_arguments)]
fn placed_pair<R: Real, A: SupportMap<R>, B: SupportMap<R>>(
    (a, exact_a): (&A, &Shape),
    (b, exact_b): (&B, &Shape),
    reach: f64,
    along: [f64; 2],
    gap: f64,
    turn: f64,
    origin: [f64; 2],
) -> bool {
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
        return false;
    }
    let placed = |shape: &Shape, t: &Transform<R>| {
        let o = pt::<R>(t.translation());
        transform_shape(shape, t.cos().to_f64(), t.sin().to_f64(), o[0], o[1])
    };
    let exact = pair(&placed(exact_a, &ta), &placed(exact_b, &tb));
    let ctx = format!("reach {reach:e} gap {gap:e} turn {turn} origin {origin:?}");
    assert!(detection.intersecting, "{ctx}: decided with no iteration, yet apart");
    assert!(apart.is_none(), "{ctx}: the disks overlap, yet the distance query found the shapes apart");
    assert!(
        exact.touching_or_overlapping,
        "{ctx}: the disks called it, the exact shapes are {:e} apart",
        exact.distance
    );
    true
}

/// The polygon as the oracle takes it, in local coordinates (exact here:
/// these polygons are about the origin).
fn exact_polygon<R: Real>(p: &Polygon<R, 64>) -> Shape {
    Shape::Polygon((0..p.len()).map(|i| pt::<R>(p.vertex(i).expect("in range"))).collect())
}

fn disks_decide_only_overlapping_pairs<R: Real>() {
    let mut rng = Rng(0xd15c + R::EPSILON.to_f64().to_bits());
    let eps = R::EPSILON.to_f64();
    let gaps = [-1e-3, -16.0 * eps, -4.0 * eps, -eps, 0.0, eps, 2.0 * eps, 4.0 * eps, 16.0 * eps, 64.0 * eps, 1e-3];
    let mut decided = 0;
    for case in 0..600 {
        let scale = 2f64.powi(rng.range(-20.0, 20.0) as i32);
        let origin = if case % 2 == 0 { [3e4 * scale, -2e4 * scale] } else { [0.0, 0.0] };
        let turn = if case % 3 == 0 { 0.0 } else { rng.range(0.0, std::f64::consts::TAU) };
        let gap = gaps[case % gaps.len()];
        // Two squares face to face: their disks touch where their faces do.
        let (ha, hb) = (round::<R>(scale * rng.range(0.5, 1.0)), round::<R>(scale * rng.range(0.5, 1.0)));
        let square = |h: f64| polygon::<R>(&[[-h, -h], [h, -h], [h, h], [-h, h]]).expect("a square");
        let (sa, sb) = (square(ha), square(hb));
        decided += placed_pair::<R, _, _>(
            (&sa, &exact_polygon(&sa)),
            (&sb, &exact_polygon(&sb)),
            ha + hb,
            [1.0, 0.0],
            gap,
            turn,
            origin,
        ) as u32;
        let (ra, rb) = (
            Rectangle::new(R::from_f64(2.0 * ha), R::from_f64(3.0 * ha)).expect("a box"),
            Rectangle::new(R::from_f64(2.0 * hb), R::from_f64(2.0 * hb)).expect("a box"),
        );
        let boxed = |h: [f64; 2]| Shape::Polygon(vec![[-h[0], -h[1]], [h[0], -h[1]], [h[0], h[1]], [-h[0], h[1]]]);
        decided += placed_pair::<R, _, _>(
            (&ra, &boxed([ha, 1.5 * ha])),
            (&rb, &boxed([hb, hb])),
            ha + hb,
            [1.0, 0.0],
            gap,
            turn,
            origin,
        ) as u32;
        // A circle against a polygon's nearest edge.
        let aspect = rng.range(0.3, 1.0);
        let points = ellipse_polygon::<R>(&mut rng, 3 + case % 30, scale, aspect, [0.0, 0.0]);
        let Some(p) = polygon::<R>(&points) else { continue };
        let (inner, normal) = exact_inner(&p, &points);
        let r = round::<R>(scale * rng.range(0.2, 1.0));
        let circle = Circle::new(R::from_f64(r)).expect("a circle");
        let exact_circle = Shape::Circle { center: [0.0, 0.0], radius: r };
        let reach = exact_f64(&inner).sqrt() + r;
        decided += placed_pair::<R, _, _>(
            (&p, &exact_polygon(&p)),
            (&circle, &exact_circle),
            reach,
            normal,
            gap,
            turn,
            origin,
        ) as u32;
        let facing = [-normal[0], -normal[1]];
        decided += placed_pair::<R, _, _>(
            (&circle, &exact_circle),
            (&p, &exact_polygon(&p)),
            reach,
            facing,
            gap,
            turn,
            origin,
        ) as u32;
    }
    assert!(decided > 300, "only {decided} pairs decided by their disks");
}

#[test]
fn disks_decide_only_overlapping_pairs_f32() {
    disks_decide_only_overlapping_pairs::<f32>();
}

#[test]
fn disks_decide_only_overlapping_pairs_f64() {
    disks_decide_only_overlapping_pairs::<f64>();
}
