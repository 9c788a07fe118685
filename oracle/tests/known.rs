//! Hand-computed answers. Every expected value is derived by hand (or from IEEE-correct
//! float operations such as `/` and `sqrt`), never from the oracle itself.

use gjk2d_oracle::exact::{q_to_f64, sqrt_to_f64, Q};
use gjk2d_oracle::{pair, ray, transform_shape, ExactShape, RayStatus, Shape};
use num_bigint::BigInt;
use num_traits::One;
use std::f64::consts::{FRAC_1_SQRT_2, SQRT_2};

fn rect(x0: f64, y0: f64, x1: f64, y1: f64) -> ExactShape {
    ExactShape::from(&Shape::Polygon(vec![[x0, y0], [x1, y0], [x1, y1], [x0, y1]]))
}

fn unit() -> ExactShape {
    rect(0.0, 0.0, 1.0, 1.0)
}

fn circle(x: f64, y: f64, r: f64) -> ExactShape {
    ExactShape::from(&Shape::Circle { center: [x, y], radius: r })
}

fn dec(s: &str) -> f64 {
    s.parse().unwrap() // Rust's parser is correctly rounded.
}

#[test]
fn squares_apart_axis() {
    let p = pair(&unit(), &rect(3.0, 0.0, 4.0, 1.0));
    assert!(!p.touching_or_overlapping);
    assert_eq!(p.distance, 2.0);
    assert_eq!(p.signed_distance, 2.0);
    assert_eq!(p.depth, 0.0);
    assert_eq!(p.normal, [1.0, 0.0]);
    assert!(p.normal_unique);
    assert_eq!(p.point_a[0], 1.0);
    assert_eq!(p.point_b[0], 3.0);
    assert_eq!(p.point_a[1], p.point_b[1]);
    assert!((0.0..=1.0).contains(&p.point_a[1]));
}

#[test]
fn squares_apart_diagonal() {
    let p = pair(&unit(), &rect(2.0, 2.0, 3.0, 3.0));
    assert_eq!(p.distance, SQRT_2);
    assert_eq!(p.normal, [FRAC_1_SQRT_2, FRAC_1_SQRT_2]);
    assert_eq!(p.point_a, [1.0, 1.0]);
    assert_eq!(p.point_b, [2.0, 2.0]);
    // Swapped order flips the normal and the points.
    let q = pair(&rect(2.0, 2.0, 3.0, 3.0), &unit());
    assert_eq!(q.normal, [-FRAC_1_SQRT_2, -FRAC_1_SQRT_2]);
    assert_eq!(q.point_a, [2.0, 2.0]);
}

#[test]
fn collinear_input_vertices_are_fine() {
    // Unit square given with extra collinear and duplicate vertices, clockwise order.
    let a = ExactShape::from(&Shape::Polygon(vec![
        [0.0, 0.0],
        [0.0, 0.5],
        [0.0, 1.0],
        [1.0, 1.0],
        [1.0, 0.0],
        [0.5, 0.0],
        [0.5, 0.0],
    ]));
    assert_eq!(a.core_vertices().len(), 4);
    let p = pair(&a, &rect(3.0, 0.0, 4.0, 1.0));
    assert_eq!(p.distance, 2.0);
}

#[test]
fn circle_vs_square() {
    let p = pair(&unit(), &circle(3.0, 0.5, 0.5));
    assert_eq!(p.distance, 1.5);
    assert_eq!(p.normal, [1.0, 0.0]);
    assert_eq!(p.point_a, [1.0, 0.5]);
    assert_eq!(p.point_b, [2.5, 0.5]);

    // Corner region: sqrt(2) - 1/2, correctly rounded.
    let p = pair(&unit(), &circle(2.0, 2.0, 0.5));
    assert_eq!(p.distance, dec("0.91421356237309504880168872420969807856967187537694"));
    assert_eq!(p.normal, [FRAC_1_SQRT_2, FRAC_1_SQRT_2]);
    // Closest point on the circle: (2 - 0.5/sqrt2, 2 - 0.5/sqrt2).
    let c = dec("1.6464466094067262377995473150181");
    assert_eq!(p.point_b, [c, c]);

    // Core outside, disk overlapping: depth 0.25.
    let p = pair(&unit(), &circle(1.25, 0.5, 0.5));
    assert!(p.touching_or_overlapping);
    assert_eq!(p.depth, 0.25);
    assert_eq!(p.signed_distance, -0.25);
    assert_eq!(p.normal, [1.0, 0.0]);
    assert!(p.normal_unique);

    // Center inside the square, nearest face is the bottom one.
    let p = pair(&unit(), &circle(0.5, 0.25, 0.5));
    assert_eq!(p.depth, 0.75);
    assert_eq!(p.normal, [0.0, -1.0]);
    assert!(p.normal_unique);

    // Exactly touching circle.
    let p = pair(&unit(), &circle(1.5, 0.5, 0.5));
    assert!(p.touching_or_overlapping);
    assert_eq!(p.distance, 0.0);
    assert_eq!(p.depth, 0.0);
    assert!(!p.normal_unique);
}

#[test]
fn circles() {
    let p = pair(&circle(0.0, 0.0, 1.0), &circle(3.0, 4.0, 1.5));
    assert_eq!(p.distance, 2.5);
    assert_eq!(p.normal, [0.6, 0.8]);
    assert_eq!(p.point_a, [0.6, 0.8]);
    assert_eq!(p.point_b, [dec("2.1"), dec("2.8")]);
    let p = pair(&circle(0.0, 0.0, 3.0), &circle(3.0, 4.0, 3.0));
    assert_eq!(p.depth, 1.0);
    assert_eq!(p.normal, [0.6, 0.8]);
    // Concentric: depth = r1 + r2, no preferred direction.
    let p = pair(&circle(1.0, 1.0, 1.0), &circle(1.0, 1.0, 2.0));
    assert_eq!(p.depth, 3.0);
    assert!(!p.normal_unique);
}

#[test]
fn capsule_vs_square() {
    let cap = ExactShape::from(&Shape::Capsule { a: [2.0, 0.0], b: [2.0, 3.0], radius: 0.5 });
    let p = pair(&unit(), &cap);
    assert_eq!(p.distance, 0.5);
    assert_eq!(p.normal, [1.0, 0.0]);
    assert_eq!(p.point_a[0], 1.0);
    assert_eq!(p.point_b[0], 1.5);

    let cap = ExactShape::from(&Shape::Capsule { a: [-1.0, 1.5], b: [3.0, 1.5], radius: 0.25 });
    let p = pair(&unit(), &cap);
    assert_eq!(p.distance, 0.25);
    assert_eq!(p.normal, [0.0, 1.0]);

    // Capsule core crossing the square horizontally through its middle: the core
    // segment is inside; cheapest exit is up or down by 0.5 (+ radius 0.25), a tie.
    let cap = ExactShape::from(&Shape::Capsule { a: [-1.0, 0.5], b: [3.0, 0.5], radius: 0.25 });
    let p = pair(&unit(), &cap);
    assert_eq!(p.depth, 0.75);
    assert!(!p.normal_unique);
    // Slightly above the middle: unique, upwards, depth 0.375 + 0.25.
    let cap = ExactShape::from(&Shape::Capsule { a: [-1.0, 0.625], b: [3.0, 0.625], radius: 0.25 });
    let p = pair(&unit(), &cap);
    assert_eq!(p.depth, 0.625);
    assert_eq!(p.normal, [0.0, 1.0]);
    assert!(p.normal_unique);
}

#[test]
fn segments_crossing_and_collinear() {
    let seg = |a: [f64; 2], b: [f64; 2]| ExactShape::from(&Shape::Capsule { a, b, radius: 0.0 });
    // Cross: depth of an X of two segments is 0 (D has empty interior? no: it is a
    // parallelogram); here the min translation is 1 (move B's horizontal segment up or
    // down by 1 to clear the vertical one of length 2 centred at its crossing... ).
    let p = pair(&seg([0.0, -1.0], [0.0, 1.0]), &seg([-3.0, 0.0], [3.0, 0.0]));
    assert!(p.touching_or_overlapping);
    assert_eq!(p.depth, 1.0);
    assert!(!p.normal_unique); // up or down
                               // Collinear, not overlapping: apart by 1.
    let p = pair(&seg([0.0, 0.0], [1.0, 0.0]), &seg([2.0, 0.0], [3.0, 0.0]));
    assert!(!p.touching_or_overlapping);
    assert_eq!(p.distance, 1.0);
    // Collinear overlapping: touching (no interior), no unique normal.
    let p = pair(&seg([0.0, 0.0], [2.0, 0.0]), &seg([1.0, 0.0], [3.0, 0.0]));
    assert!(p.touching_or_overlapping);
    assert_eq!(p.depth, 0.0);
    assert!(!p.normal_unique);
    // Point on the segment's line beyond its end: apart.
    let p = pair(&seg([0.0, 0.0], [2.0, 0.0]), &ExactShape::point([3.0, 0.0]));
    assert_eq!(p.distance, 1.0);
}

#[test]
fn touching_at_vertex_and_edge() {
    let p = pair(&unit(), &rect(1.0, 1.0, 2.0, 2.0));
    assert!(p.touching_or_overlapping);
    assert_eq!(p.distance, 0.0);
    assert_eq!(p.depth, 0.0);
    assert_eq!(p.signed_distance, 0.0);
    assert_eq!(p.normal, [0.0, 0.0]);
    assert!(!p.normal_unique);

    let p = pair(&unit(), &rect(1.0, 0.25, 2.0, 0.75));
    assert!(p.touching_or_overlapping);
    assert_eq!(p.distance, 0.0);
    assert_eq!(p.normal, [1.0, 0.0]);
    assert!(!p.normal_unique);

    // One ulp apart is apart.
    let x = f64::from_bits(1.0f64.to_bits() + 1);
    let p = pair(&unit(), &rect(x, x, 2.0, 2.0));
    assert!(!p.touching_or_overlapping);
    assert_eq!(p.distance, (x - 1.0) * SQRT_2);
}

#[test]
fn square_inside_square() {
    let big = rect(0.0, 0.0, 10.0, 10.0);
    let p = pair(&big, &rect(2.0, 4.0, 3.0, 5.0));
    assert_eq!(p.depth, 3.0);
    assert_eq!(p.signed_distance, -3.0);
    assert_eq!(p.normal, [-1.0, 0.0]);
    assert!(p.normal_unique);
    assert_eq!(p.point_a, [0.0, 0.0]);

    let p = pair(&unit(), &rect(0.5, 0.25, 1.5, 1.25));
    assert_eq!(p.depth, 0.5);
    assert_eq!(p.normal, [1.0, 0.0]);
    assert!(p.normal_unique);

    let p = pair(&unit(), &rect(0.5, 0.5, 1.5, 1.5));
    assert_eq!(p.depth, 0.5);
    assert!(!p.normal_unique);
}

#[test]
fn triangle_depth_along_slanted_edge() {
    // Triangle (0,0),(4,0),(0,4); small square [2.5,2.75]x[0.5,0.75]. To clear the
    // hypotenuse x+y=4 its lowest corner (x+y = 3) must move 1/sqrt2 = 0.7071 along the
    // normal; moving down needs 0.75, left 2.75.
    let tri = ExactShape::from(&Shape::Polygon(vec![[0.0, 0.0], [4.0, 0.0], [0.0, 4.0]]));
    let p = pair(&tri, &rect(2.5, 0.5, 2.75, 0.75));
    assert_eq!(p.depth, FRAC_1_SQRT_2);
    assert!(p.normal_unique);
    assert_eq!(p.normal, [FRAC_1_SQRT_2, FRAC_1_SQRT_2]);
}

#[test]
fn rotated_transform() {
    // 90 degrees: (x, y) -> (-y, x) then + (5, 0): unit square -> [4,5] x [0,1].
    let b = transform_shape(&Shape::Polygon(vec![[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0]]), 0.0, 1.0, 5.0, 0.0);
    let p = pair(&unit(), &b);
    assert_eq!(p.distance, 3.0);
    assert_eq!(p.normal, [1.0, 0.0]);
    // Not normalising cos/sin: scale by 2 (cos = 2, sin = 0).
    let b = transform_shape(&Shape::Polygon(vec![[1.0, 0.0], [2.0, 0.0], [2.0, 1.0], [1.0, 1.0]]), 2.0, 0.0, 0.0, 0.0);
    assert_eq!(pair(&unit(), &b).distance, 1.0);
}

#[test]
fn rounded_polygon() {
    let rp = ExactShape::from(&Shape::RoundedPolygon {
        vertices: vec![[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0]],
        radius: 0.5,
    });
    let p = pair(&rp, &circle(4.0, 5.0, 0.5));
    // Core corner (1,1) to (4,5): 5; minus 1.
    assert_eq!(p.distance, 4.0);
    assert_eq!(p.normal, [0.6, 0.8]);
    assert_eq!(p.point_a, [1.3, 1.4]);
    // Cores touching at an edge, radii overlap: depth = R, normal the edge's.
    let p = pair(
        &rp,
        &ExactShape::from(&Shape::RoundedPolygon {
            vertices: vec![[1.0, 0.25], [2.0, 0.25], [2.0, 0.75], [1.0, 0.75]],
            radius: 0.25,
        }),
    );
    assert_eq!(p.depth, 0.75);
    assert_eq!(p.normal, [1.0, 0.0]);
    assert!(p.normal_unique);
}

#[test]
fn rays_on_square() {
    let s = unit();
    let r = ray([-1.0, 0.5], [1.0, 0.0], 0.0, &s);
    assert_eq!(r.status, RayStatus::Hit);
    assert_eq!(r.t, 1.0);
    assert_eq!(r.normal, [-1.0, 0.0]);
    assert!(r.normal_unique);
    assert_eq!(r.margin, f64::INFINITY);
    // Non-unit direction: t still in length units.
    let r = ray([-1.0, 0.5], [2.0, 0.0], f64::INFINITY, &s);
    assert_eq!(r.t, 1.0);
    // Vertex hit at (0, 0) from (-1, -1): t = sqrt 2, tie between bottom and left faces
    // (equally head-on) -> the lower index, the bottom face (hull starts at (0,0)).
    let r = ray([-1.0, -1.0], [1.0, 1.0], 0.0, &s);
    assert_eq!(r.status, RayStatus::Hit);
    assert_eq!(r.t, SQRT_2);
    assert_eq!(r.normal, [0.0, -1.0]);
    assert!(!r.normal_unique);
    // Vertex hit not head-on: from (-1, -0.5) towards (0,0): left face (-1,0) is more
    // head-on for d = (2, 1).
    let r = ray([-2.0, -1.0], [2.0, 1.0], 0.0, &s);
    assert_eq!(r.normal, [-1.0, 0.0]);
    // Miss above: margin is the distance to the square.
    let r = ray([-1.0, 2.0], [1.0, 0.0], 0.0, &s);
    assert_eq!(r.status, RayStatus::Miss);
    assert_eq!(r.margin, 1.0);
    // Miss pointing away: distance from origin (-1,0.5) to square is 1.
    let r = ray([-1.0, 0.5], [-1.0, 0.0], 0.0, &s);
    assert_eq!(r.status, RayStatus::Miss);
    assert_eq!(r.margin, 1.0);
    // Inside.
    let r = ray([0.5, 0.25], [1.0, 0.0], 0.0, &s);
    assert_eq!(r.status, RayStatus::Inside);
    assert_eq!(r.margin, 0.25);
    assert_eq!(r.t, 0.0);
    // On the boundary counts as inside.
    let r = ray([0.0, 0.5], [-1.0, 0.0], 0.0, &s);
    assert_eq!(r.status, RayStatus::Inside);
    assert_eq!(r.margin, 0.0);
    // Too short: stops at (-0.5, 0.5), 0.5 away.
    let r = ray([-1.0, 0.5], [1.0, 0.0], 0.5, &s);
    assert_eq!(r.status, RayStatus::Miss);
    assert_eq!(r.margin, 0.5);
    // Just long enough, and longer.
    let r = ray([-1.0, 0.5], [1.0, 0.0], 1.0, &s);
    assert_eq!(r.status, RayStatus::Hit);
    assert_eq!(r.margin, 0.0);
    let r = ray([-1.0, 0.5], [1.0, 0.0], 3.0, &s);
    assert_eq!(r.margin, 2.0);
    // Too short along a diagonal with non-unit d: stops at distance 1 along (3,4)/5.
    let r = ray([-3.0, -4.0], [3.0, 4.0], 1.0, &rect(0.0, 0.0, 1.0, 1.0));
    assert_eq!(r.status, RayStatus::Miss);
    // End point (-2.4, -3.2): nearest square point (0,0): distance 4.
    assert_eq!(r.margin, 4.0);
    // Grazing along the top edge is a hit.
    let r = ray([-1.0, 1.0], [1.0, 0.0], 0.0, &s);
    assert_eq!(r.status, RayStatus::Hit);
    assert_eq!(r.t, 1.0);
}

#[test]
fn rays_on_round_shapes() {
    let c = circle(0.0, 0.0, 1.0);
    let r = ray([-3.0, 0.0], [1.0, 0.0], 0.0, &c);
    assert_eq!(r.status, RayStatus::Hit);
    assert_eq!(r.t, 2.0);
    assert_eq!(r.normal, [-1.0, 0.0]);
    let r = ray([-3.0, 0.6], [1.0, 0.0], 0.0, &c);
    assert_eq!(r.t, dec("2.2"));
    assert_eq!(r.normal, [dec("-0.8"), dec("0.6")]);
    let r = ray([-3.0, 1.5], [1.0, 0.0], 0.0, &c);
    assert_eq!(r.status, RayStatus::Miss);
    assert_eq!(r.margin, 0.5);
    // Irrational hit: x^2 + 0.5^2 = 1 -> x = -sqrt(3)/2, t = 3 - sqrt(3)/2.
    let r = ray([-3.0, 0.5], [1.0, 0.0], 0.0, &c);
    assert_eq!(r.t, dec("2.1339745962155613532208842153982"));

    let cap = ExactShape::from(&Shape::Capsule { a: [0.0, 0.0], b: [2.0, 0.0], radius: 1.0 });
    let r = ray([1.0, 5.0], [0.0, -3.0], 0.0, &cap);
    assert_eq!(r.t, 4.0);
    assert_eq!(r.normal, [0.0, 1.0]);
    assert!(r.normal_unique);
    // Along the axis into the end cap.
    let r = ray([5.0, 0.0], [-1.0, 0.0], 0.0, &cap);
    assert_eq!(r.t, 2.0);
    assert_eq!(r.normal, [1.0, 0.0]);
    // Rounded square, hit the rounded corner on the diagonal.
    let rp = ExactShape::from(&Shape::RoundedPolygon {
        vertices: vec![[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0]],
        radius: 0.5,
    });
    let r = ray([4.0, 5.0], [-3.0, -4.0], 0.0, &rp);
    assert_eq!(r.t, 4.5);
    assert_eq!(r.normal, [0.6, 0.8]);
    let r = ray([0.5, 3.0], [0.0, -1.0], 0.0, &rp);
    assert_eq!(r.t, 1.5);
    assert_eq!(r.normal, [0.0, 1.0]);
    let r = ray([0.5, 1.25], [0.0, -1.0], 0.0, &rp);
    assert_eq!(r.status, RayStatus::Inside);
    assert_eq!(r.margin, 0.25);
}

#[test]
fn correct_rounding_of_rationals() {
    let q = |a: i64, b: i64| Q::new(BigInt::from(a), BigInt::from(b));
    assert_eq!(q_to_f64(&q(1, 3)), 1.0 / 3.0);
    assert_eq!(q_to_f64(&q(2, 3)), 2.0 / 3.0);
    assert_eq!(q_to_f64(&q(-2, 3)), -2.0 / 3.0);
    assert_eq!(q_to_f64(&q(1, 10)), 0.1);
    // IEEE division of exact integers is correctly rounded: compare many.
    let mut x: u64 = 0x9E37_79B9_7F4A_7C15;
    for _ in 0..20000 {
        x ^= x << 13;
        x ^= x >> 7;
        x ^= x << 17;
        let a = (x >> 11) as i64;
        let b = ((x.rotate_left(29) >> 11) | 1) as i64;
        assert_eq!(q_to_f64(&q(a, b)), a as f64 / b as f64, "{a}/{b}");
        let n = x >> 11;
        assert_eq!(sqrt_to_f64(&q(n as i64, 1)), (n as f64).sqrt(), "sqrt {n}");
    }
    let two = |e: i64| -> Q {
        if e >= 0 {
            Q::from_integer(BigInt::one() << e as usize)
        } else {
            Q::new(BigInt::one(), BigInt::one() << (-e) as usize)
        }
    };
    let one = Q::one();
    // Exactly halfway between 1 and 1 + 2^-52: ties to even -> 1.
    assert_eq!(q_to_f64(&(&one + two(-53))), 1.0);
    // A hair above halfway -> up.
    assert_eq!(q_to_f64(&(&one + two(-53) + two(-300))), 1.0 + f64::EPSILON);
    // A hair below halfway -> down.
    assert_eq!(q_to_f64(&(&one + two(-53) - two(-300))), 1.0);
    // Halfway between 1 + 2^-52 and 1 + 2^-51: even is 1 + 2^-51.
    assert_eq!(q_to_f64(&(&one + two(-53) * Q::from_integer(3.into()))), 1.0 + 2.0 * f64::EPSILON);
    // Halfway to 1/3 neighbours: (fl(1/3) + next)/2 rounds to even.
    let t = 1.0f64 / 3.0;
    let t2 = f64::from_bits(t.to_bits() + 1);
    let mid = (gjk2d_oracle_exact(t) + gjk2d_oracle_exact(t2)) / Q::from_integer(2.into());
    let even = if t.to_bits() & 1 == 0 { t } else { t2 };
    assert_eq!(q_to_f64(&mid), even);
    // Subnormals and overflow.
    assert_eq!(q_to_f64(&two(-1075)), 0.0);
    assert_eq!(q_to_f64(&(two(-1075) + two(-1200))), f64::from_bits(1));
    assert_eq!(q_to_f64(&(two(-1076) * Q::from_integer(3.into()))), f64::from_bits(1));
    assert_eq!(q_to_f64(&two(-1074)), f64::from_bits(1));
    assert_eq!(q_to_f64(&two(-1022)), f64::MIN_POSITIVE);
    assert_eq!(q_to_f64(&two(1024)), f64::INFINITY);
    assert_eq!(q_to_f64(&two(1023)), 2f64.powi(1023));
    // Square roots.
    assert_eq!(sqrt_to_f64(&q(2, 1)), SQRT_2);
    assert_eq!(sqrt_to_f64(&q(1, 2)), FRAC_1_SQRT_2);
    assert_eq!(sqrt_to_f64(&q(9, 4)), 1.5);
}

fn gjk2d_oracle_exact(x: f64) -> Q {
    gjk2d_oracle::exact::q_from_f64(x)
}
