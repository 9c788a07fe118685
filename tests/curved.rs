//! Curved shapes (ellipses, half-ellipses, slices) against every shape,
//! judged by an oracle independent of GJK and EPA: the signed distance of the
//! Minkowski difference from its support function, certified by branch and
//! bound (`gjk2d_oracle::curved`, whose error analysis is in its module
//! documentation: within about 1e-14 of the pair's size, a hundredth of the
//! f64 guarantee).
//!
//! - `oracle_*`: the oracle itself against exact answers: the rational
//!   oracle on polygons, circles, capsules and segments, placed by rotations
//!   and on ellipses of equal axes (disks); Eberly's point-to-ellipse distance,
//!   the half disk's and the sector's closed forms against a circle.
//! - `single::*`, `double::*`: each curved shape against each shape kind
//!   (circle, polygon of 3 to 16 vertices, rectangle, triangle, segment,
//!   capsule, ellipse, half-ellipse, slice), in f32 and f64, at random sizes
//!   (1e-2 to 1e2), aspect ratios (1, 0.999, 0.9, 0.5, 0.1, 0.01 and between)
//!   and rigid placements: apart, overlapping, touching to within a few
//!   rounding errors, concentric (local origins or centres on each other);
//!   and a point or small circle core deep inside each curved shape.
//!   Slices span 1e-6 rad to pi. Every `Converged` distance and depth must be
//!   within README's curved guarantee (`1e-6 L` in f32, `1e-12 L` in f64, plus
//!   `8 eps L` of rounding and the oracle's own error) of the oracle, an
//!   answer at its iteration limit within that plus its `error_bound`; its
//!   normal must achieve it (the difference's support along the reported
//!   normal agrees with the reported value), its closest points lie on their
//!   shapes along it, nothing is NaN, and verdicts agree wherever the exact
//!   margin exceeds the tolerance. L is the larger bounding radius, or the
//!   centres' distance when larger (as `tests/certified.rs`).
//!
//! 1200 pairs per shape kind, curved kind and precision (a failure of one
//! pair in 400 is found with probability 0.95); `GJK2D_LONG=N` multiplies
//! the counts. `cargo test --test curved -- --nocapture` prints each
//! family's mean and largest iteration counts, iteration limits and worst
//! errors.

// `!(err <= allowed)`: a NaN error must fail the check.
#![allow(clippy::neg_cmp_op_on_partial_ord)]

use gjk2d::glam::{DVec2, Vec2};
use gjk2d::*;
use gjk2d_oracle::curved::{curved_pair, difference_support, CurvedAnswer, Local, Placed};
use gjk2d_oracle::{pair, transform_shape, Shape};
use std::f64::consts::PI;

#[path = "common/geo.rs"]
mod geo;
#[path = "common/point_distance.rs"]
mod point_distance;
#[path = "common/rng.rs"]
mod rng;
use geo::{norm, sub, Pt};
use rng::{cases, Rng};

/// The gap the oracle's branch and bound reaches, relative to the shapes'
/// reach from the world origin.
const ORACLE_TOL: f64 = 1e-15;

/// A shape as its constructor's arguments (values of the precision under
/// test, held in f64), placed by a rotation angle and a translation.
#[derive(Clone, Debug, PartialEq)]
enum Kind {
    Circle(f64),
    Polygon(Vec<Pt>),
    /// Width, height.
    Rectangle(f64, f64),
    Triangle([Pt; 3]),
    Segment(Pt, Pt),
    Capsule(Pt, Pt, f64),
    /// Width, height (full extents).
    Ellipse(f64, f64),
    /// Width of the flat side, height of the dome.
    HalfEllipse(f64, f64),
    /// Radius, angle spanned.
    Slice(f64, f64),
}

#[derive(Clone, Debug, PartialEq)]
struct Spec {
    kind: Kind,
    angle: f64,
    t: Pt,
}

/// The shape kinds a curved shape is paired with, by name.
const PARTNERS: [&str; 9] =
    ["circle", "polygon", "rectangle", "triangle", "segment", "capsule", "ellipse", "half_ellipse", "slice"];

/// Aspect ratios: round (equal axes) twice as often, nearly round, flat.
fn aspect(rng: &mut Rng) -> f64 {
    match rng.next() % 8 {
        0 | 1 => 1.0,
        2 => 0.999,
        3 => 0.9,
        4 => 0.5,
        5 => 0.1,
        6 => 0.01,
        _ => 0.01f64.powf(rng.unit()),
    }
}

/// A curved shape of size about `s`, in values rounded by `q`.
fn curved_kind(rng: &mut Rng, which: &str, s: f64, q: fn(f64) -> f64) -> Kind {
    let (major, k) = (s * rng.range(0.3, 1.0), aspect(rng));
    let (x, y) = if rng.unit() < 0.5 { (major, major * k) } else { (major * k, major) };
    match which {
        "ellipse" => Kind::Ellipse(q(2.0 * x), q(2.0 * y)),
        "half_ellipse" => Kind::HalfEllipse(q(2.0 * x), q(y)),
        _ => {
            let theta = match rng.next() % 8 {
                0 => 1e-6,
                1 => 1e-3,
                2 => PI - 1e-4,
                3 => PI,
                4 => PI / 2.0,
                _ => rng.range(0.0, PI),
            };
            // The largest value of the precision not above pi (f32's pi rounds up).
            let theta = if q(theta) > PI { f32::from_bits((PI as f32).to_bits() - 1) as f64 } else { q(theta) };
            Kind::Slice(q(major), theta.max(q(1e-6)))
        }
    }
}

/// `n` points on an ellipse of semi-axes `a`, `b` at jittered sorted angles.
fn ellipse_points(rng: &mut Rng, n: usize, a: f64, b: f64, q: fn(f64) -> f64) -> Vec<Pt> {
    let phase = rng.range(0.0, 2.0 * PI);
    (0..n)
        .map(|i| {
            let t = phase + 2.0 * PI * (i as f64 + rng.range(0.0, 0.7)) / n as f64;
            [q(a * t.cos()), q(b * t.sin())]
        })
        .collect()
}

/// Any shape kind of size about `s`.
fn partner_kind(rng: &mut Rng, which: &str, s: f64, q: fn(f64) -> f64) -> Kind {
    let (a, k) = (s * rng.range(0.3, 1.0), aspect(rng));
    match which {
        "circle" => Kind::Circle(q(s * rng.range(0.05, 1.0))),
        "polygon" => {
            let n = 3 + (rng.next() % 14) as usize;
            Kind::Polygon(ellipse_points(rng, n, a, a * k.max(0.05), q))
        }
        "rectangle" => Kind::Rectangle(q(2.0 * a), q(2.0 * a * k)),
        "triangle" => {
            let p = ellipse_points(rng, 3, a, a * k.max(0.05), q);
            Kind::Triangle([p[0], p[1], p[2]])
        }
        "segment" | "capsule" => {
            let u = rng.range(0.0, 2.0 * PI);
            let (e0, e1) = ([q(a * u.cos()), q(a * u.sin())], [q(-a * u.cos() * k), q(-a * u.sin() * k)]);
            if which == "segment" {
                Kind::Segment(e0, e1)
            } else {
                Kind::Capsule(e0, e1, q(s * rng.range(0.02, 0.6)))
            }
        }
        curved => curved_kind(rng, curved, s, q),
    }
}

/// A point inside the curved shape `kind`, in its local frame, `depth`
/// (0 to 1) of the way from the boundary towards its middle.
fn inside_point(rng: &mut Rng, kind: &Kind, depth: f64) -> Pt {
    let rho = 1.0 - depth;
    match *kind {
        Kind::Ellipse(w, h) => {
            let u = rng.range(0.0, 2.0 * PI);
            [0.5 * w * rho * u.cos(), 0.5 * h * rho * u.sin()]
        }
        Kind::HalfEllipse(w, h) => {
            let u = rng.range(0.0, PI);
            [0.5 * w * rho * u.cos(), h * (0.5 + 0.5 * rho * u.sin()) * (1.0 - 0.5 * depth)]
        }
        Kind::Slice(r, theta) => {
            let u = 0.5 * theta * rng.range(-1.0, 1.0);
            let along = r * (0.5 + 0.5 * rho * rng.range(-1.0, 1.0));
            [along * u.cos(), along * u.sin() * (1.0 - 0.5 * depth)]
        }
        _ => [0.0, 0.0],
    }
}

fn extent(kind: &Kind) -> f64 {
    match kind {
        Kind::Circle(r) => *r,
        Kind::Polygon(v) => v.iter().map(|&p| norm(p)).fold(0.0, f64::max),
        Kind::Rectangle(w, h) => 0.5 * w.hypot(*h),
        Kind::Triangle(v) => v.iter().map(|&p| norm(p)).fold(0.0, f64::max),
        Kind::Segment(a, b) => norm(*a).max(norm(*b)),
        Kind::Capsule(a, b, r) => norm(*a).max(norm(*b)) + r,
        Kind::Ellipse(w, h) => 0.5 * w.max(*h),
        Kind::HalfEllipse(w, h) => (0.5 * w).max(*h),
        Kind::Slice(r, _) => *r,
    }
}

/// How B is placed against A.
#[derive(Clone, Copy, Debug, PartialEq)]
enum Placement {
    /// Centres a random fraction (0 to 1.3) of the summed extents apart.
    Random,
    /// Moved along the oracle's normal to touch, then off by 0 to 1e-4 L.
    Touching,
    /// B's local origin on A's local origin.
    Concentric,
    /// B's local origin on a point inside A.
    Inside,
}

/// A pair of one curved kind and one partner kind from a seed; `touch`
/// moves B along a normal by a signed distance (the oracle's, given A and B).
fn generate(
    seed: u64,
    curved: &str,
    partner: &str,
    q: fn(f64) -> f64,
    touch: &dyn Fn(&Spec, &Spec) -> Option<CurvedAnswer>,
) -> (Spec, Spec, Placement) {
    let mut rng = Rng(seed);
    let s = 10f64.powf(rng.range(-2.0, 2.0));
    let a_kind = curved_kind(&mut rng, curved, s, q);
    let b_kind = partner_kind(&mut rng, partner, s, q);
    let angle = |rng: &mut Rng| if rng.next().is_multiple_of(4) { 0.0 } else { q(rng.range(-PI, PI)) };
    let ta = [q(s * rng.range(-2.0, 2.0)), q(s * rng.range(-2.0, 2.0))];
    let a = Spec { kind: a_kind, angle: angle(&mut rng), t: ta };
    let (ca, sa) = (a.angle.cos(), a.angle.sin());
    let world = |p: Pt| [ta[0] + ca * p[0] - sa * p[1], ta[1] + sa * p[0] + ca * p[1]];
    let placement = match rng.next() % 20 {
        0..=8 => Placement::Random,
        9..=14 => Placement::Touching,
        15..=16 => Placement::Concentric,
        _ => Placement::Inside,
    };
    let tb = match placement {
        Placement::Random | Placement::Touching => {
            let u = rng.range(0.0, 2.0 * PI);
            let reach = (extent(&a.kind) + extent(&b_kind)) * rng.range(0.0, 1.3);
            [q(ta[0] + reach * u.cos()), q(ta[1] + reach * u.sin())]
        }
        Placement::Concentric => ta,
        Placement::Inside => {
            let depth = rng.range(0.05, 1.0);
            let p = world(inside_point(&mut rng, &a.kind, depth));
            [q(p[0]), q(p[1])]
        }
    };
    let mut b = Spec { kind: b_kind, angle: angle(&mut rng), t: tb };
    if placement == Placement::Touching {
        if let Some(ans) = touch(&a, &b) {
            let l = extent(&a.kind).max(extent(&b.kind));
            let off = [0.0, 0.0, 1e-7, -1e-7, 1e-5, -1e-5, 1e-4, -1e-4][(rng.next() % 8) as usize] * l;
            let shift = off - ans.signed;
            b.t = [q(b.t[0] + shift * ans.normal[0]), q(b.t[1] + shift * ans.normal[1])];
        }
    }
    if rng.next().is_multiple_of(2) {
        (b, a, placement)
    } else {
        (a, b, placement)
    }
}

/// The core-inside family: a point core (a circle of radius 1e-6 of the
/// curved shape's size), a small circle or a small triangle deep inside.
fn generate_inside(seed: u64, curved: &str, q: fn(f64) -> f64) -> (Spec, Spec, Placement) {
    let mut rng = Rng(seed);
    let s = 10f64.powf(rng.range(-2.0, 2.0));
    let kind = curved_kind(&mut rng, curved, s, q);
    let angle = q(rng.range(-PI, PI));
    let ta = [q(s * rng.range(-2.0, 2.0)), q(s * rng.range(-2.0, 2.0))];
    let depth = rng.range(0.3, 1.0);
    let p = inside_point(&mut rng, &kind, depth);
    let (c, si) = (angle.cos(), angle.sin());
    let tb = [q(ta[0] + c * p[0] - si * p[1]), q(ta[1] + si * p[0] + c * p[1])];
    let size = extent(&kind);
    let b_kind = match rng.next() % 4 {
        0 => Kind::Circle(q(size * 1e-6)),
        1 => Kind::Circle(q(size * 10f64.powf(rng.range(-4.0, -1.0)))),
        2 => {
            let p = ellipse_points(&mut rng, 3, size * 1e-3, size * 1e-3, q);
            Kind::Triangle([p[0], p[1], p[2]])
        }
        _ => Kind::Segment([q(size * 1e-3), 0.0], [q(-size * 1e-3), q(size * 1e-4)]),
    };
    let a = Spec { kind, angle, t: ta };
    let b = Spec { kind: b_kind, angle: q(rng.range(-PI, PI)), t: tb };
    (a, b, Placement::Inside)
}

/// What a family of checks saw: per query (intersects, distance,
/// penetration) the answers, iterations, limits and worst error over L.
#[derive(Default, Clone)]
struct Tally {
    pairs: u32,
    answers: [u32; 3],
    iterations: [u64; 3],
    most: [u32; 3],
    limits: [u32; 3],
    worst: [f64; 3],
    oracle_evaluations: u64,
}

impl Tally {
    fn add(&mut self, q: usize, iterations: u32, limited: bool, err_over_l: f64) {
        self.answers[q] += 1;
        self.iterations[q] += iterations as u64;
        self.most[q] = self.most[q].max(iterations);
        self.limits[q] += limited as u32;
        self.worst[q] = self.worst[q].max(err_over_l);
    }
    fn row(&self, name: &str) -> String {
        let mut s = format!("{name:<28} {:>6}", self.pairs);
        for q in 0..3 {
            let mean = self.iterations[q] as f64 / self.answers[q].max(1) as f64;
            s += &format!(" | {:>5.1} {:>4} {:>4} {:>8.1e}", mean, self.most[q], self.limits[q], self.worst[q]);
        }
        s + &format!(" | {:>5.0}", self.oracle_evaluations as f64 / self.pairs.max(1) as f64)
    }
}

const HEADER: &str = "family                        pairs | intersects: mean max limits worst/L | distance: same | penetration: same | oracle evaluations";

macro_rules! curved_suite {
    ($modname:ident, $r:ty, $vec:ident) => {
        mod $modname {
            use super::*;
            type R = $r;
            const EPS: f64 = <$r>::EPSILON as f64;
            /// README's guarantee for curved shapes at the default epsilons.
            const CURVED: f64 = if EPS > 1e-10 { 1e-6 } else { 1e-12 };

            fn q(x: f64) -> f64 {
                x as R as f64
            }
            fn v(p: Pt) -> $vec {
                $vec::new(p[0] as R, p[1] as R)
            }
            fn pt(p: $vec) -> Pt {
                [p.x as f64, p.y as f64]
            }

            /// The shape gjk2d builds, its transform, and the oracle's copy
            /// of what gjk2d stores. `None` where the constructor refuses
            /// (a polygon that rounding made non-convex).
            fn build(spec: &Spec) -> Option<(Box<dyn SupportMap<R>>, Transform<R>, Placed)> {
                let (shape, local): (Box<dyn SupportMap<R>>, Local) = match &spec.kind {
                    Kind::Circle(r) => (Box::new(Circle::new(*r as R).ok()?), Local::Circle { center: [0.0, 0.0], radius: *r }),
                    Kind::Polygon(p) => {
                        let vs: Vec<$vec> = p.iter().map(|&p| v(p)).collect();
                        (Box::new(Polygon::<R, 16>::new(&vs).ok()?), Local::Polygon(p.clone()))
                    }
                    Kind::Rectangle(w, h) => {
                        let (x, y) = (0.5 * w, 0.5 * h);
                        let corners = vec![[-x, -y], [x, -y], [x, y], [-x, y]];
                        (Box::new(Rectangle::new(*w as R, *h as R).ok()?), Local::Polygon(corners))
                    }
                    Kind::Triangle(p) => (Box::new(Triangle::new(v(p[0]), v(p[1]), v(p[2])).ok()?), Local::Polygon(p.to_vec())),
                    Kind::Segment(a, b) => (Box::new(Segment::new(v(*a), v(*b)).ok()?), Local::Polygon(vec![*a, *b])),
                    Kind::Capsule(a, b, r) => {
                        (Box::new(Capsule::new(v(*a), v(*b), *r as R).ok()?), Local::Capsule { a: *a, b: *b, radius: *r })
                    }
                    Kind::Ellipse(w, h) => (Box::new(Ellipse::new(*w as R, *h as R).ok()?), Local::Ellipse { a: 0.5 * w, b: 0.5 * h }),
                    Kind::HalfEllipse(w, h) => {
                        (Box::new(HalfEllipse::new(*w as R, *h as R).ok()?), Local::HalfEllipse { a: 0.5 * w, h: *h })
                    }
                    Kind::Slice(r, theta) => {
                        let slice = Slice::new(*r as R, *theta as R).ok()?;
                        // The end gjk2d computed: its support straight up
                        // (the slice spans at most pi, so that is an end).
                        let end = pt(slice.support($vec::Y));
                        (Box::new(slice), Local::Slice { radius: *r, end })
                    }
                };
                let tf = Transform::new(v(spec.t), spec.angle as R).ok()?;
                let placed = Placed::new(local, tf.cos() as f64, tf.sin() as f64, pt(tf.translation()));
                Some((shape, tf, placed))
            }

            fn oracle(a: &Spec, b: &Spec) -> Option<CurvedAnswer> {
                let (_, _, pa) = build(a)?;
                let (_, _, pb) = build(b)?;
                Some(curved_pair(&pa, &pb, ORACLE_TOL))
            }

            /// Checks every query on one pair against the oracle.
            pub(super) fn check(a: &Spec, b: &Spec, tally: &mut Tally) -> Result<(), String> {
                let (Some((sa, ta, pa)), Some((sb, tb, pb))) = (build(a), build(b)) else { return Ok(()) };
                let truth = curved_pair(&pa, &pb, ORACLE_TOL);
                let centres = norm(sub(pt(ta.transform_point(sa.reference_point() + sa.center())), pt(tb.transform_point(sb.reference_point() + sb.center()))));
                let l = (sa.bounding_radius() as f64).max(sb.bounding_radius() as f64).max(centres);
                tally.pairs += 1;
                tally.oracle_evaluations += truth.evaluations as u64;
                let signed = truth.signed;
                let tol = CURVED * l + 8.0 * EPS * l + truth.error;
                let fail = |m: String| {
                    Err(format!("{m}\n  A = {a:?}\n  B = {b:?}\n  exact signed distance {signed:e} (oracle error {:e}), L {l:e}, tolerance {tol:e}", truth.error))
                };
                if !(truth.error <= 2.5e-13 * l) {
                    return fail(format!("oracle gap {:e} L", truth.error / l));
                }
                let gjk = Gjk::<R>::new();
                let (sa, sb) = (&*sa, &*sb);
                let h = |n: $vec| {
                    let n = pt(n);
                    let len = norm(n);
                    difference_support(&pa, &pb, [n[0] / len, n[1] / len])
                };
                let detection = gjk.intersects(sa, &ta, sb, &tb);
                tally.add(0, detection.iterations, !detection.status.is_converged(), 0.0);
                if detection.status.is_converged() && signed.abs() > tol && detection.intersecting != (signed < 0.0) {
                    return fail(format!("wrong verdict {detection:?}"));
                }
                match gjk.distance(sa, &ta, sb, &tb) {
                    Some(s) => {
                        let err = (s.distance as f64 - signed.max(0.0)).abs();
                        let converged = s.status.is_converged();
                        tally.add(1, s.iterations, !converged, err / l);
                        let allowed = if converged { tol } else { tol + s.error_bound as f64 };
                        let nan = [s.distance, s.normal.x, s.normal.y, s.point_a.x, s.point_a.y, s.point_b.x, s.point_b.y, s.error_bound].iter().any(|x| x.is_nan());
                        if nan || !(err <= allowed) || (converged && signed < -tol) {
                            return fail(format!("distance {s:?}: error {err:e}"));
                        }
                        // The normal separates by the distance; the points lie
                        // on their shapes' support lines along it, that far apart.
                        let n = pt(s.normal);
                        let (ha, hb) = (pa.h(n), pb.h([-n[0], -n[1]]));
                        let (da, db) = (pt(s.point_a), pt(s.point_b));
                        let gaps = [
                            s.distance as f64 + h(s.normal),
                            (ha - (da[0] * n[0] + da[1] * n[1])).abs(),
                            (hb + (db[0] * n[0] + db[1] * n[1])).abs(),
                            ((db[0] - da[0]) * n[0] + (db[1] - da[1]) * n[1] - s.distance as f64).abs(),
                        ];
                        if let Some(k) = (0..4).find(|&k| !(gaps[k] <= allowed)) {
                            return fail(format!("distance {s:?}: check {k} (normal, point A, point B, points' gap) off by {:e}", gaps[k]));
                        }
                    }
                    None if signed > tol => return fail("distance None".into()),
                    None => {}
                }
                match gjk.penetration(sa, &ta, sb, &tb) {
                    Some(p) => {
                        let err = (p.depth as f64 - (-signed).max(0.0)).abs();
                        let converged = p.status.is_converged();
                        tally.add(2, p.iterations, !converged, err / l);
                        let allowed = if converged { tol } else { tol + p.error_bound as f64 };
                        let nan = [p.depth, p.normal.x, p.normal.y, p.error_bound].iter().any(|x| x.is_nan());
                        if nan || !(err <= allowed) || (converged && signed > tol) {
                            return fail(format!("penetration {p:?}: error {err:e}"));
                        }
                        // Moving B by the depth along the normal separates.
                        let achieved = h(p.normal) - p.depth as f64;
                        if !(achieved <= allowed) {
                            return fail(format!("penetration {p:?}: its normal needs {achieved:e} more than its depth"));
                        }
                    }
                    None if signed < -tol => return fail("penetration None".into()),
                    None => {}
                }
                Ok(())
            }

            /// One curved kind against every partner kind and the
            /// core-inside family: 1200 pairs each (times `GJK2D_LONG`).
            fn family(curved: &str) {
                let n = cases(1200) as u64;
                let mut failures = Vec::new();
                let mut rows = Vec::new();
                let touch = |a: &Spec, b: &Spec| oracle(a, b);
                let salt = curved.bytes().fold(0u64, |h, c| h.wrapping_mul(131).wrapping_add(c as u64));
                for (k, partner) in PARTNERS.iter().chain(["core_inside"].iter()).enumerate() {
                    let mut tally = Tally::default();
                    for i in 0..n {
                        let seed = (salt << 32) ^ ((k as u64) << 24) ^ i ^ (EPS.to_bits() << 7);
                        let (a, b, _) = if *partner == "core_inside" {
                            generate_inside(seed, curved, q)
                        } else {
                            generate(seed, curved, partner, q, &touch)
                        };
                        if let Err(e) = check(&a, &b, &mut tally) {
                            failures.push(format!("{curved} against {partner}, seed {seed:#x}: {e}"));
                        }
                    }
                    rows.push(tally.row(&format!("{curved}_{partner}")));
                }
                println!("{} ({})\n{HEADER}\n{}", stringify!($modname), stringify!($r), rows.join("\n"));
                if std::env::var("CURVED_ALL").is_ok() {
                    for f in &failures {
                        eprintln!("FAIL {}", f.replace('\n', " ##"));
                    }
                }
                let shown: Vec<&String> = failures.iter().take(8).collect();
                assert!(failures.is_empty(), "{} failures, the first:\n{}", failures.len(), shown.iter().map(|s| s.as_str()).collect::<Vec<_>>().join("\n"));
            }

            #[test]
            fn ellipse_against_every_shape() {
                family("ellipse");
            }

            #[test]
            fn half_ellipse_against_every_shape() {
                family("half_ellipse");
            }

            #[test]
            fn slice_against_every_shape() {
                family("slice");
            }
        }
    };
}

curved_suite!(single, f32, Vec2);
curved_suite!(double, f64, DVec2);

// ---------------------------------------------------------------------------------
// The oracle against exact answers.

fn polygon_on_ellipse(rng: &mut Rng, n: usize, a: f64, b: f64) -> Vec<Pt> {
    let pts: Vec<(i64, i64)> = ellipse_points(rng, n, a, b, |x| x)
        .into_iter()
        .map(|p| ((p[0] * 1048576.0).round() as i64, (p[1] * 1048576.0).round() as i64))
        .collect();
    geo::integer_hull(pts).into_iter().map(|(x, y)| [x as f64 / 1048576.0, y as f64 / 1048576.0]).collect()
}

/// Polygons, circles, capsules and segments, rotated and translated, and
/// ellipses of equal axes (disks): the curved oracle against the rational one.
#[test]
fn oracle_against_exact_pairs() {
    let mut rng = Rng(0x5eed_0c0e);
    let mut worst: f64 = 0.0;
    for i in 0..cases(1500) {
        let s = 10f64.powf(rng.range(-2.0, 2.0));
        let make = |rng: &mut Rng, k: u64| -> (Shape, Local) {
            let r = s * rng.range(0.05, 1.0);
            let p = [s * rng.range(-0.3, 0.3), s * rng.range(-0.3, 0.3)];
            let e = [p[0] + s * rng.range(-1.0, 1.0), p[1] + s * rng.range(-1.0, 1.0)];
            match k {
                0 => {
                    let n = 3 + (rng.next() % 14) as usize;
                    let b = s * rng.range(0.01, 1.0);
                    let v = polygon_on_ellipse(rng, n, s, b);
                    (Shape::Polygon(v.clone()), Local::Polygon(v))
                }
                1 => (Shape::Circle { center: p, radius: r }, Local::Circle { center: p, radius: r }),
                2 => (Shape::Capsule { a: p, b: e, radius: r }, Local::Capsule { a: p, b: e, radius: r }),
                3 => (Shape::Capsule { a: p, b: e, radius: 0.0 }, Local::Polygon(vec![p, e])),
                _ => (Shape::Circle { center: [0.0, 0.0], radius: r }, Local::Ellipse { a: r, b: r }),
            }
        };
        let (ka, kb) = (rng.next() % 5, rng.next() % 5);
        let ((ea, la), (eb, lb)) = (make(&mut rng, ka), make(&mut rng, kb));
        // Disks are placed unrotated: a rounded rotation scales by sqrt(c^2 + s^2).
        let place = |rng: &mut Rng, disk: bool| {
            let t = [s * rng.range(-1.5, 1.5), s * rng.range(-1.5, 1.5)];
            let u = if disk { 0.0 } else { rng.range(-PI, PI) };
            (u.cos(), u.sin(), t)
        };
        let ((ca, sa, tta), (cb, sb, ttb)) = (place(&mut rng, ka == 4), place(&mut rng, kb == 4));
        let exact = pair(&transform_shape(&ea, ca, sa, tta[0], tta[1]), &transform_shape(&eb, cb, sb, ttb[0], ttb[1]));
        let (pa, pb) = (Placed::new(la, ca, sa, tta), Placed::new(lb, cb, sb, ttb));
        let got = curved_pair(&pa, &pb, ORACLE_TOL);
        let err = (got.signed - exact.signed_distance).abs();
        assert!(err <= got.error, "pair {i}: {pa:?} {pb:?}: {got:?}, exact {}", exact.signed_distance);
        assert!(got.error <= 1e-13 * s, "pair {i}: gap {:e} at size {s:e}", got.error);
        worst = worst.max(err / s);
    }
    println!("curved oracle against the rational oracle: worst error {worst:e} of the size");
}

/// An ellipse, a half disk and a sector against a circle: the curved oracle
/// against Eberly's point-to-ellipse distance and the closed forms.
#[test]
fn oracle_against_point_distances() {
    let mut rng = Rng(0x0e11_1b5e);
    let mut worst: f64 = 0.0;
    for i in 0..cases(1500) {
        let s = 10f64.powf(rng.range(-2.0, 2.0));
        let (a, k) = (s * rng.range(0.3, 1.0), aspect(&mut rng));
        let c = [s * rng.range(-1.5, 1.5), s * rng.range(-1.5, 1.5)];
        let r = s * rng.range(0.0, 0.8);
        let (shape, truth) = match i % 3 {
            0 => (Local::Ellipse { a, b: a * k }, point_distance::signed_ellipse(a, a * k, c)),
            1 => (Local::HalfEllipse { a, h: a }, point_distance::signed_half_disk(a, c)),
            _ => {
                let half = rng.range(1e-3, 0.5 * PI);
                let end = [a * half.cos(), a * half.sin()];
                let (u0, u1) = ([half.cos(), -half.sin()], [half.cos(), half.sin()]);
                (Local::Slice { radius: a, end }, point_distance::signed_sector(a, u0, u1, c))
            }
        };
        let circle = Local::Circle { center: [0.0, 0.0], radius: r };
        let got = curved_pair(&Placed::at_origin(shape.clone()), &Placed::new(circle, 1.0, 0.0, c), ORACLE_TOL);
        let exact = truth - r;
        let err = (got.signed - exact).abs();
        assert!(
            err <= got.error + 1e-14 * s,
            "case {i}: {shape:?} against a circle of radius {r} at {c:?}: {got:?}, exact {exact}"
        );
        worst = worst.max(err / s);
    }
    println!("curved oracle against point distances: worst error {worst:e} of the size");
}

// ---------------------------------------------------------------------------------
// Regressions: failures the families found, with their exact inputs.

fn regression(
    check: fn(&Spec, &Spec, &mut Tally) -> Result<(), String>,
    a: Kind,
    ta: (f64, Pt),
    b: Kind,
    tb: (f64, Pt),
) {
    let (a, b) = (Spec { kind: a, angle: ta.0, t: ta.1 }, Spec { kind: b, angle: tb.0, t: tb.1 });
    let mut tally = Tally::default();
    if let Err(e) = check(&a, &b, &mut tally) {
        panic!("{e}");
    }
    assert_eq!(tally.pairs, 1, "the shapes build");
}

/// The intersection test called a slice apart from a rectangle around its
/// apex: GJK's second support was opposite the first, the triangle solve
/// put the origin a rounding error outside, the third support repeated, and
/// a repeat counted as apart with no support plane separating the origin.
#[test]
fn slice_apex_inside_rectangle_f32() {
    regression(
        single::check,
        Kind::Slice(13.971187591552734, 3.141592502593994),
        (0.0, [13.270705223083496, -35.01667022705078]),
        Kind::Rectangle(20.618791580200195, 10.309395790100098),
        (-0.18388767540454865, [13.270705223083496, -35.01667022705078]),
    );
}

/// The same in f64, a slice of nearly pi around a segment through its apex.
#[test]
fn slice_apex_on_segment_f64() {
    regression(
        double::check,
        Kind::Slice(11.361697315109708, 3.141492653589793),
        (0.0, [32.34353226437585, -5.970963310645936]),
        Kind::Segment([-3.550413848428247, -9.185248562056], [3.550413848428247, 9.185248562056]),
        (0.05246353622303346, [32.34353226437585, -5.970963310645936]),
    );
}

/// The intersection test's other exit without progress: |v| grew (rounding
/// in the triangle solve, |v| about 1e-5 L) with every support plane behind
/// the origin, and a half ellipse overlapping a slice by 7e-6 L was called
/// apart.
#[test]
fn half_ellipse_slice_stall_f32() {
    regression(
        single::check,
        Kind::HalfEllipse(0.8895944356918335, 44.47972106933594),
        (2.2773196697235107, [-55.643157958984375, 49.96820068359375]),
        Kind::Slice(45.94130325317383, 1.5707963705062866),
        (-1.2187237739562988, [-131.1692657470703, 40.38206481933594]),
    );
}

/// GJK stopped on a lower bound measured along an earlier direction (the
/// gap was 2e-14), but reported `v`'s direction, whose own support plane
/// separated the shapes by 4.6e-12 less than the distance: 24 times the
/// f64 guarantee. The normal is now the certified direction.
#[test]
fn distance_normal_certified_f64() {
    regression(
        double::check,
        Kind::Ellipse(0.21550091678526528, 0.21571663341868397),
        (-1.900119858743243, [0.014965849057927215, -0.06985527799728365]),
        Kind::Slice(0.12500555033898783, 2.954053272805981),
        (-0.7151458741855534, [-0.2118203310875402, -0.01695037481218893]),
    );
}

/// The same mechanism through the penetration of a circle and an ellipse
/// whose cores are apart (depth from the core distance): the normal needed
/// 3.2e-11 more than the depth, twice the f64 guarantee.
#[test]
fn rounded_penetration_normal_certified_f64() {
    regression(
        double::check,
        Kind::Circle(15.969450172360158),
        (0.0, [10.57043593142659, -11.772718484546907]),
        Kind::Ellipse(25.733484933098392, 1.47035797981146),
        (-0.8667759683365608, [2.2916734821888936, -19.970033197980186]),
    );
}

/// A needle slice (1e-3 rad) 6e-9 from a rectangle in f32: the normal of
/// the last direction missed the separation by 0.8 L (no certified plane
/// along it); the certified direction separates.
#[test]
fn needle_slice_touching_rectangle_f32() {
    regression(
        single::check,
        Kind::Slice(0.025234436616301537, 0.0010000000474974513),
        (0.3916860520839691, [0.0719246193766594, -0.058191727846860886]),
        Kind::Rectangle(0.06756099313497543, 0.020583847537636757),
        (-1.9824167490005493, [0.09116966277360916, -0.08364689350128174]),
    );
}

/// An ellipse and a 12-gon 2e-7 apart (3.7e-8 L) in f32: distance 1.5e-8,
/// converged with error_bound 0, but its normal was 1.16 L short of
/// separating them. GJK ended on an edge of two curve points, 1.07 long,
/// passing 2.8e-8 from the origin, below the rounding of those points
/// (1e-6 at the ellipse's 9.5): the sign of the edge's distance, which
/// chose the normal's way, was rounding, and the normal pointed from B
/// towards A. Now the centers' offset orients it there (touching: no
/// distance, which the exact 2e-7 allows).
#[test]
fn touching_ellipse_polygon_normal_f32() {
    regression(
        single::check,
        Kind::Ellipse(0.635755181312561, 9.488019943237305),
        (-1.9555832147598267, [-0.7571213841438293, -7.171781539916992]),
        Kind::Polygon(vec![
            [0.1323264241218567, 0.7736392021179199],
            [-0.9287988543510437, 0.6222767233848572],
            [-1.273573398590088, 0.444294810295105],
            [-1.5118659734725952, -0.17737115919589996],
            [-1.1251341104507446, -0.5351760983467102],
            [-0.6340129971504211, -0.7088032364845276],
            [0.26215359568595886, -0.7653195858001709],
            [0.9890796542167664, -0.5986029505729675],
            [1.4718043804168701, -0.24767553806304932],
            [1.5518159866333008, -0.029359549283981323],
            [1.2863214015960693, 0.4350166618824005],
            [0.6979597210884094, 0.6936196684837341],
        ]),
        (0.0, [4.0976972579956055, -9.657927513122559]),
    );
}

/// A segment of length 1e-3 inside a needle slice (1e-3 rad) in f32:
/// penetration said Converged, error_bound 0, depth 2.14e-4 where the exact
/// depth is 1.89e-4 (7e-5 L, 38 times the guarantee). The slice's support
/// told the arc from its ends by cos(angle) >= cos(theta / 2), which f32
/// cannot resolve near 1: directions 1e-4 rad past the ends got arc points
/// outside the slice, and EPA's polytope, no longer inside the Minkowski
/// difference, certified a lower bound above the depth. Two more needles
/// (1e-6 rad) around small triangles failed the same way in the core-inside
/// family (their seeds run there again).
#[test]
fn segment_inside_needle_slice_f32() {
    regression(
        single::check,
        Kind::Slice(0.5175861120223999, 0.0010000000474974513),
        (0.6980543732643127, [-0.4694567918777466, 0.5218161344528198]),
        Kind::Segment([0.0005175861297175288, 0.0], [-0.0005175861297175288, 5.175861224415712e-5]),
        (-2.60260009765625, [-0.2672390937805176, 0.691437840461731]),
    );
}

/// A triangle 1.8e-7 (5.6e-6 L) from an ellipse of aspect 1:90 in f32,
/// called overlapping. The edge between GJK's first support, 6e-7 from the
/// origin, and a far one, 0.035 away, put its closest point as
/// `n (n . far) / (n . n)`: rounded at the far end's magnitude, 1e-2 of
/// `v` itself, so `-v` picked the far end again, `|v|` grew, and with no
/// plane yet separating the origin the test said touching. The foot is now
/// taken from the nearer end.
#[test]
fn sliver_ellipse_near_triangle_verdict_f32() {
    regression(
        single::check,
        Kind::Triangle([
            [0.013424628414213657, 0.01119184959679842],
            [-0.018289048224687576, 0.0005476198857650161],
            [0.01604045368731022, -0.007926306687295437],
        ]),
        (0.0, [-0.010986234061419964, -0.012498260475695133]),
        Kind::Ellipse(0.00040215725312009454, 0.0358913317322731),
        (-2.6182844638824463, [0.014022509567439556, -0.03596879914402962]),
    );
}

/// The same in f64: a segment 1e-9 from a half ellipse, called
/// overlapping.
#[test]
fn half_ellipse_near_segment_verdict_f64() {
    regression(
        double::check,
        Kind::Segment([0.8566446827739428, 2.925895499633267], [-0.08566446827739428, -0.2925895499633267]),
        (-3.0577682623656868, [2.0969895533208254, -3.229125657257552]),
        Kind::HalfEllipse(2.5182950919818747, 3.179365961537089),
        (-1.1205624011147903, [2.7058068010506773, -4.06405869944395]),
    );
}

/// A thin half ellipse against a capsule in f32: the difference has a flat
/// edge (the capsule's segment) ending in the dome's tight tip, and GJK's
/// supports alternated between the edge's far end and the tip, each step
/// gaining less than rounding. `|v|` grew by an ulp, and the distance
/// stopped there as converged with its bounds 2.2e-5 apart (the tolerance
/// is 2e-6). A stall with the bounds apart now takes the new support, as
/// exact arithmetic would.
#[test]
fn thin_half_ellipse_capsule_stall_f32() {
    regression(
        single::check,
        Kind::HalfEllipse(0.11965974420309067, 0.5982987284660339),
        (0.8014267683029175, [-1.6193724870681763, -1.1513267755508423]),
        Kind::Capsule(
            [0.20282569527626038, -1.0558140277862549],
            [-0.20282569527626038, 1.0558140277862549],
            0.4627188742160797,
        ),
        (0.7054097652435303, [0.08885528147220612, -0.0921773836016655]),
    );
}

/// A circle against an ellipse of aspect 1:100 in f32: GJK stalled with
/// its bounds met but `v`'s own plane 2.7e-6 short of them, and the stall
/// ended the loop, so the penetration's normal needed 2.8e-6 more than its
/// depth (the tolerance is 1.4e-6). A stall with `v`'s plane short goes on
/// too.
#[test]
fn sliver_ellipse_circle_normal_after_stall_f32() {
    regression(
        single::check,
        Kind::Circle(0.738764762878418),
        (0.0, [-0.9650048613548279, 0.012695771642029285]),
        Kind::Ellipse(0.012209111824631691, 1.2209111452102661),
        (-2.7727606296539307, [-1.2244101762771606, -0.04399112984538078]),
    );
}

/// A slice centred on a nearly round ellipse in f64: EPA stopped at its
/// limit, and the polish found a local minimum of the support function
/// 3.2e-7 above the depth, reported as converged. The polished answer now
/// keeps EPA's status, its error bound (5.2e-6) covering the error.
#[test]
fn slice_in_round_ellipse_polish_f64() {
    regression(
        double::check,
        Kind::Slice(12.559733323217374, 0.282133170380125),
        (3.072973565133452, [30.56451695115341, 11.88043764865815]),
        Kind::Ellipse(24.506256594935365, 24.530787382317683),
        (-1.5820475521795077, [30.56451695115341, 11.88043764865815]),
    );
}
