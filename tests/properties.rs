//! Property tests of every query against the exact rational oracle
//! (`gjk2d_oracle`), in f32 and f64 (one macro, one suite per precision).
//!
//! Shapes: random convex polygons (points on a random ellipse at sorted random
//! angles), circles and capsules, every coordinate rounded to f32 so the oracle
//! sees exactly what gjk2d sees (the f64 suite widens the same f32 values).
//!
//! Error model. With `eps` the precision's machine epsilon:
//! - `L` is the pair's size: the larger bounding radius
//!   ([`SupportMap::bounding_radius`]), or the distance between the two shapes'
//!   centers if that is larger (rounding of the Minkowski difference scales with
//!   its coordinates, which reach that far). For rays, `L = max(bounding radius,
//!   |origin - center|)`.
//! - Shapes given in world coordinates with identity transforms are the fair
//!   frame: the oracle sees exactly gjk2d's input, and every answer must be
//!   within `8 eps L` of the exact one.
//! - With rotated and translated shapes the oracle places them exactly (with
//!   the transform's own cos/sin, read back from [`Transform::cos`] and
//!   [`Transform::sin`]) while gjk2d rounds the relative placement. The bound
//!   then gets the placement's rounding on top: `4 eps (|t_B - t_A| + e_A +
//!   e_B)`, `e` the largest local coordinate of a shape (radius included), which
//!   also covers `|(cos, sin)| = 1 +- eps` scaling the oracle's shapes.
//! - Points are world coordinates and round by `4 eps |p|` more.
//! - A verdict (overlap or apart; hit, miss or inside) is only checked when the
//!   exact margin exceeds the bound. For rays, "exceeds" means that the exact
//!   verdict also holds for the ray shifted by the bound across and along
//!   itself (a grazing hit has an infinite oracle margin, yet flips under a
//!   rounding-sized shift of the shape).
//!
//! Invariants: swapping A and B, translating both by one vector, agreement of
//! `intersects`, `distance` and `penetration`, unit normals, closest points on
//! the boundaries and `distance` apart, normals that separate (distance) or
//! resolve (depth) the pair, finite outputs, `Status::Converged` and small
//! error bounds.

use gjk2d::glam::{DVec2, Vec2};
use gjk2d::*;
use gjk2d_oracle::{pair, ray as oracle_ray, transform_shape, ExactShape, PairAnswer, RayStatus};
use proptest::prelude::*;
use std::f64::consts::TAU;

#[path = "common/geo.rs"]
mod geo;
#[macro_use]
#[path = "common/placed.rs"]
mod placed;
use geo::{integer_hull, norm, sub, Geo, Pt};

fn r32(x: f64) -> f64 {
    x as f32 as f64
}
fn rp(p: Pt) -> Pt {
    [r32(p[0]), r32(p[1])]
}

/// Parameters of one random shape.
#[derive(Clone, Debug)]
struct Spec {
    kind: u8,
    a: f64,
    b: f64,
    phi: f64,
    angles: Vec<f64>,
    scale: f64,
}

fn spec() -> impl Strategy<Value = Spec> {
    (0u8..4, 0.2f64..1.0, 0.05f64..1.0, 0.0..TAU, prop::collection::vec(0.0..TAU, 3..13), -3.0f64..3.0)
        .prop_map(|(kind, a, b, phi, angles, e)| Spec { kind, a, b, phi, angles, scale: 2f64.powf(e) })
}

impl Spec {
    /// The shape centered near `c`, rounded to f32; `None` when too few
    /// distinct angles are left.
    fn geo(&self, c: Pt) -> Option<Geo> {
        let s = self.scale;
        let (cp, sp) = (self.phi.cos(), self.phi.sin());
        let place = |x: f64, y: f64| rp([c[0] + cp * x - sp * y, c[1] + sp * x + cp * y]);
        match self.kind {
            0 | 1 => {
                let mut t = self.angles.clone();
                t.sort_by(|x, y| x.partial_cmp(y).unwrap());
                let mut kept: Vec<f64> = Vec::new();
                for th in t {
                    if kept.last().is_none_or(|&l| th - l >= 0.05) {
                        kept.push(th);
                    }
                }
                if kept.len() >= 2 && kept[0] + TAU - kept[kept.len() - 1] < 0.05 {
                    kept.pop();
                }
                if kept.len() < 3 {
                    return None;
                }
                Some(Geo::Poly(kept.iter().map(|&th| place(self.a * s * th.cos(), self.b * s * th.sin())).collect()))
            }
            2 => Some(Geo::Circle(rp(c), r32(self.a * s))),
            _ => {
                let (p, q) = (place(-self.a * s, 0.0), place(self.a * s, 0.0));
                (p != q).then(|| Geo::Capsule(p, q, r32(0.5 * self.b * s)))
            }
        }
    }
    /// About the bounding radius of the shape.
    fn nominal(&self) -> f64 {
        match self.kind {
            0 | 1 => self.a.max(self.b) * self.scale,
            2 => self.a * self.scale,
            _ => (self.a + 0.5 * self.b) * self.scale,
        }
    }
}

/// Where a shape goes in the transformed runs.
#[derive(Clone, Debug)]
struct Pose {
    /// Translation, in units of the pair's nominal size.
    t: Pt,
    angle: f64,
    /// Build with `from_cos_sin` from `(k cos, k sin)`, `k` this (0: `Transform::new`).
    cos_sin_scale: f64,
}

fn pose() -> impl Strategy<Value = Pose> {
    (-8.0f64..8.0, -8.0f64..8.0, -4.0f64..4.0, prop_oneof![Just(0.0), 0.5f64..2.0, Just(1.0)])
        .prop_map(|(x, y, angle, k)| Pose { t: [x, y], angle, cos_sin_scale: k })
}

/// Polygons of more vertices than the closed-form ray cast scans (it then
/// searches): the hull of integer points scattered in a thin ring inside a
/// rotated ellipse of radius 2^20 lattice steps, scaled by a power of two, so
/// every coordinate is exact in f32. Every few vertices, edges are split at
/// their midpoints (collinear vertices), or corners cut off between the
/// nearest lattice points on their edges: edges a few steps long, shorter
/// than f32 rounds the side of a vertex to. The points come from a seeded
/// generator, not from proptest's vectors: shrinking a thousand points is
/// slow and tells nothing a seed does not.
fn many_sided() -> impl Strategy<Value = Geo> {
    let shape = (any::<u64>(), 40usize..1500, 0.01f64..1.0, 0.0..TAU, prop_oneof![Just(0.0), 0.0f64..0.05]);
    (shape, 1usize..4, any::<bool>(), any::<bool>(), -3i32..4).prop_filter_map(
        "24 hull vertices or fewer",
        |((seed, count, aspect, phi, ring), every, split, cut, e)| {
            let mut state = seed | 1;
            let mut uniform = move || {
                state ^= state << 13;
                state ^= state >> 7;
                state ^= state << 17;
                (state >> 11) as f64 / (1u64 << 53) as f64
            };
            let radius = (1u64 << 20) as f64;
            let (c, s) = (phi.cos(), phi.sin());
            let cloud: Vec<(i64, i64)> = (0..count)
                .map(|_| {
                    let (theta, r) = (uniform() * TAU, radius * (1.0 - ring * uniform()));
                    let (x, y) = (r * theta.cos(), r * aspect * theta.sin());
                    ((c * x - s * y).round() as i64, (s * x + c * y).round() as i64)
                })
                .collect();
            let hull = integer_hull(cloud);
            if hull.len() <= 24 {
                return None;
            }
            // The lattice point nearest `p` on the edge towards `q`, if not `q`.
            let step = |p: (i64, i64), q: (i64, i64)| {
                let g = gcd((q.0 - p.0).abs(), (q.1 - p.1).abs());
                (g > 1).then(|| (p.0 + (q.0 - p.0) / g, p.1 + (q.1 - p.1) / g))
            };
            let n = hull.len();
            let mut points = Vec::new();
            for (k, &p) in hull.iter().enumerate() {
                let (prev, next) = (hull[(k + n - 1) % n], hull[(k + 1) % n]);
                match (cut && k % every == 0, step(p, prev), step(p, next)) {
                    (true, Some(a), Some(b)) => points.extend([a, b]),
                    _ => points.push(p),
                }
                let even = (next.0 - p.0) % 2 == 0 && (next.1 - p.1) % 2 == 0;
                if split && k % every == 1 % every && even {
                    points.push(((p.0 + next.0) / 2, (p.1 + next.1) / 2));
                }
            }
            let unit = 2f64.powi(e - 20);
            Some(Geo::Poly(points.iter().map(|&(x, y)| [x as f64 * unit, y as f64 * unit]).collect()))
        },
    )
}

/// `from.1` sizes away from `center`, in direction `from.0`, rounded to f32:
/// where the ray tests start.
fn around(center: Pt, size: f64, from: (f64, f64)) -> Pt {
    rp([center[0] + from.1 * size * from.0.cos(), center[1] + from.1 * size * from.0.sin()])
}

/// The direction from `o` towards `p` as an angle.
fn bearing(o: Pt, p: Pt) -> f64 {
    (p[1] - o[1]).atan2(p[0] - o[0])
}

/// The direction at `angle`, rounded to f32.
fn heading(angle: f64) -> Pt {
    rp([angle.cos(), angle.sin()])
}

fn gcd(a: i64, b: i64) -> i64 {
    if b == 0 {
        a
    } else {
        gcd(b, a % b)
    }
}

/// A fixed seed so CI is reproducible; `PROPTEST_RNG_SEED=<u64>` explores
/// other cases (failures are saved to the regressions file and replayed),
/// `PROPTEST_CASES=<n>` runs n of each.
fn config() -> ProptestConfig {
    let seed = std::env::var("PROPTEST_RNG_SEED").ok().and_then(|s| s.parse().ok()).unwrap_or(0x6a6b_3264);
    // A long run (`PROPTEST_CASES=<n>`) gets a reject cap to match: about
    // one many-sided polygon in four is rejected.
    let cases = std::env::var("PROPTEST_CASES").ok().and_then(|s| s.parse().ok()).unwrap_or(256);
    ProptestConfig {
        cases,
        max_global_rejects: cases.max(4096),
        rng_seed: proptest::test_runner::RngSeed::Fixed(seed),
        ..ProptestConfig::default()
    }
}

macro_rules! property_suite {
    ($modname:ident, $r:ty, $vec:ident) => {
        mod $modname {
            use super::*;
            type R = $r;
            const EPS: f64 = <$r>::EPSILON as f64;
            /// Rounding of the f64 evaluation of support values in the checks.
            const EPS64: f64 = f64::EPSILON;

            fn v(p: Pt) -> $vec {
                $vec::new(p[0] as R, p[1] as R)
            }
            fn pt(p: $vec) -> Pt {
                [p.x as f64, p.y as f64]
            }
            fn finite(p: $vec) -> bool {
                p.x.is_finite() && p.y.is_finite()
            }

            fn build(g: &Geo) -> Option<Box<dyn SupportMap<R>>> {
                Some(match g {
                    Geo::Poly(pts) => {
                        let pts: Vec<$vec> = pts.iter().map(|&p| v(p)).collect();
                        if pts.len() <= 16 {
                            Box::new(Polygon::<R, 16>::new(&pts).ok()?)
                        } else {
                            Box::new(Polygon::<R, 2048>::new(&pts).ok()?)
                        }
                    }
                    Geo::Circle(c, r) => Box::new(Circle::at(v(*c), *r as R).ok()?),
                    Geo::Capsule(a, b, r) => Box::new(Capsule::new(v(*a), v(*b), *r as R).ok()?),
                    Geo::Segment(a, b) => Box::new(Segment::new(v(*a), v(*b)).ok()?),
                    Geo::Rounded(p, r) => Box::new(Rounded::new(Polygon::<R, 16>::new(&p.iter().map(|&q| v(q)).collect::<Vec<_>>()).ok()?, *r as R).ok()?),
                })
            }

            placed_shape!();

            impl Placed {
                fn new(geo: Geo, tf: Transform<R>) -> Option<Self> {
                    let shape = build(&geo)?;
                    Some(Self::from_parts(geo, shape, tf))
                }
                fn world(geo: Geo) -> Option<Self> {
                    Self::new(geo, Transform::IDENTITY)
                }
            }

            fn transform(p: &Pose, t: Pt) -> Transform<R> {
                if p.cos_sin_scale == 0.0 {
                    Transform::new(v(t), p.angle as R).unwrap()
                } else {
                    let k = p.cos_sin_scale;
                    Transform::from_cos_sin(v(t), (k * p.angle.cos()) as R, (k * p.angle.sin()) as R).unwrap()
                }
            }

            /// The pair's size `L` and the bound `8 eps L` plus the placement's rounding.
            fn pair_bound(a: &Placed, b: &Placed) -> (f64, f64) {
                let l = a.radius().max(b.radius()).max(norm(sub(a.center(), b.center())));
                let placement = if a.identity() && b.identity() {
                    0.0
                } else {
                    4.0 * EPS * (norm(sub(b.t, a.t)) + a.geo.extent() + b.geo.extent())
                };
                (l, 8.0 * EPS * l + placement)
            }

            struct Outcome {
                oracle: PairAnswer,
                bound: f64,
                det: Detection,
                dist: Option<Separation<R>>,
                pen: Option<Penetration<R>>,
            }

            /// Every pair query on (a, b), checked against the oracle and the invariants.
            fn check_pair(a: &Placed, b: &Placed, what: &str) -> Result<Outcome, TestCaseError> {
                let gjk = Gjk::<R>::new();
                let o = pair(&a.exact, &b.exact);
                let (_, bound) = pair_bound(a, b);
                // f64 evaluation of support values in the checks below.
                let slack = 8.0 * EPS64 * (a.reach() + b.reach());
                let det = gjk.intersects(&*a.shape, &a.tf, &*b.shape, &b.tf);
                let dist = gjk.distance(&*a.shape, &a.tf, &*b.shape, &b.tf);
                let pen = gjk.penetration(&*a.shape, &a.tf, &*b.shape, &b.tf);
                let ctx = || format!("{what}: A {:?} at {:?}, B {:?} at {:?}; oracle {:?}; bound {bound:e}", a.geo, a.tf, b.geo, b.tf, o);
                prop_assert!(det.status.is_converged(), "{}: intersects {:?}", ctx(), det);
                if o.signed_distance.abs() > bound {
                    let overlap = o.touching_or_overlapping;
                    prop_assert_eq!(det.intersecting, overlap, "{}: intersects {:?}", ctx(), det);
                    prop_assert_eq!(dist.is_none(), overlap, "{}: distance {:?}", ctx(), dist);
                    prop_assert_eq!(pen.is_some(), overlap, "{}: penetration {:?}", ctx(), pen);
                }
                if let Some(s) = &dist {
                    let (pa, pb, n) = (pt(s.point_a), pt(s.point_b), pt(s.normal));
                    let d = s.distance as f64;
                    prop_assert!(d.is_finite() && finite(s.normal) && finite(s.point_a) && finite(s.point_b) && (s.error_bound as f64).is_finite(), "{}: {:?}", ctx(), s);
                    prop_assert!(s.status.is_converged(), "{}: {:?}", ctx(), s);
                    prop_assert!(d >= 0.0 && (s.error_bound as f64) <= bound, "{}: {:?}", ctx(), s);
                    prop_assert!((d - o.distance).abs() <= bound, "{}: distance {d:e} vs exact {:e} (error {:e})", ctx(), o.distance, (d - o.distance).abs());
                    prop_assert!((norm(n) - 1.0).abs() <= 4.0 * EPS, "{}: normal {:?} not unit", ctx(), n);
                    let pr = bound + 4.0 * EPS * norm(pa).max(norm(pb));
                    let gap = sub(pb, pa);
                    prop_assert!((norm(gap) - d).abs() <= 2.0 * pr, "{}: points {pa:?} {pb:?} are {:e} apart, distance {d:e}", ctx(), norm(gap));
                    prop_assert!((n[0] * gap[1] - n[1] * gap[0]).abs() <= 2.0 * pr, "{}: normal {n:?} not along {gap:?}", ctx());
                    let on_a = pair(&ExactShape::point(pa), &a.exact).signed_distance;
                    let on_b = pair(&ExactShape::point(pb), &b.exact).signed_distance;
                    prop_assert!(on_a.abs() <= pr && on_b.abs() <= pr, "{}: points off the boundaries by {on_a:e} (A) and {on_b:e} (B); {:?}", ctx(), s);
                    // The normal separates the shapes by the distance.
                    let along = -(a.support(n) + b.support([-n[0], -n[1]]));
                    prop_assert!(along >= d - bound - slack, "{}: the shapes are only {along:e} apart along the normal {n:?}, distance {d:e}", ctx());
                }
                if let Some(p) = &pen {
                    let n = pt(p.normal);
                    let depth = p.depth as f64;
                    prop_assert!(depth.is_finite() && finite(p.normal) && (p.error_bound as f64).is_finite(), "{}: {:?}", ctx(), p);
                    prop_assert!(p.status.is_converged(), "{}: {:?}", ctx(), p);
                    prop_assert!(depth >= 0.0 && (p.error_bound as f64) <= bound, "{}: {:?}", ctx(), p);
                    prop_assert!((depth - o.depth).abs() <= bound, "{}: depth {depth:e} vs exact {:e} (error {:e})", ctx(), o.depth, (depth - o.depth).abs());
                    prop_assert!((norm(n) - 1.0).abs() <= 4.0 * EPS, "{}: normal {:?} not unit", ctx(), n);
                    // Moving B by the depth along the normal resolves the overlap.
                    let needed = a.support(n) + b.support([-n[0], -n[1]]);
                    prop_assert!(needed <= depth + bound + slack, "{}: along the normal {n:?} B must move {needed:e}, depth {depth:e}", ctx());
                }
                Ok(Outcome { oracle: o, bound, det, dist, pen })
            }

            /// Two shapes in world coordinates: A near the origin, B at `k` times
            /// the sum of their sizes from it (overlapping to well apart).
            fn world_pair(sa: &Spec, sb: &Spec, ca: Pt, dir: f64, k: f64) -> Option<(Placed, Placed)> {
                let size = sa.nominal().max(sb.nominal());
                let ca = [ca[0] * size, ca[1] * size];
                let reach = k * (sa.nominal() + sb.nominal());
                let cb = [ca[0] + reach * dir.cos(), ca[1] + reach * dir.sin()];
                Some((Placed::world(sa.geo(ca)?)?, Placed::world(sb.geo(cb)?)?))
            }

            /// Two shapes placed by transforms: local geometry near the local
            /// origin, world centers as in `world_pair`.
            fn posed_pair(sa: &Spec, pa: &Pose, sb: &Spec, pb: &Pose, dir: f64, k: f64, shift: Pt) -> Option<(Placed, Placed)> {
                let size = sa.nominal().max(sb.nominal());
                let ga = sa.geo([0.25 * sa.nominal(), -0.125 * sa.nominal()])?;
                let gb = sb.geo([-0.125 * sb.nominal(), 0.25 * sb.nominal()])?;
                let ta = rp([pa.t[0] * size + shift[0], pa.t[1] * size + shift[1]]);
                let ta = transform(pa, ta);
                let a = Placed::new(ga, ta)?;
                let reach = k * (sa.nominal() + sb.nominal());
                let ca = a.center();
                let want = [ca[0] + reach * dir.cos(), ca[1] + reach * dir.sin()];
                // B's translation so its center lands there (to rounding).
                let probe = Placed::new(gb.clone(), transform(pb, [0.0, 0.0]))?;
                let off = probe.center();
                let tb = transform(pb, rp(sub(want, off)));
                Some((a, Placed::new(gb, tb)?))
            }

            fn ray_check(shape: &Placed, origin: Pt, dir: Pt, max_len: f64, closed_form: bool, what: &str) -> Result<(), TestCaseError> {
                let mut gjk = Gjk::<R>::new();
                gjk.closed_form_rays = closed_form;
                let ray = Ray::new(v(origin), v(dir)).unwrap();
                let (o, d) = (pt(ray.origin()), pt(ray.direction()));
                let max = max_len as R;
                let cast = gjk.raycast(&ray, max, &*shape.shape, &shape.tf);
                let exact = oracle_ray(o, d, max as f64, &shape.exact);
                let l = shape.radius().max(norm(sub(o, shape.center())));
                let t_far = if exact.t.is_finite() { exact.t } else { 0.0 };
                let placement = if shape.identity() { 0.0 } else { 4.0 * EPS * (norm(sub(o, shape.t)) + shape.geo.extent() + t_far) };
                let mut bound = 8.0 * EPS * l + placement;
                if !closed_form {
                    // The iterative cast stops within its epsilon of the surface.
                    let cfg = GjkConfig::<R>::default().raycast_epsilon() as f64;
                    bound += 2.0 * cfg * shape.radius();
                }
                let ctx = || format!("{what}: ray {o:?} -> {d:?} max {max_len:e} at {:?} placed {:?}; oracle {:?}; bound {bound:e}", shape.geo, shape.tf, exact);
                prop_assert!(cast.status.is_converged(), "{}: {:?}", ctx(), cast);
                if closed_form {
                    prop_assert_eq!(cast.iterations, 0, "{}: {:?}", ctx(), cast);
                }
                // The verdict must survive shifting the ray by the bound.
                let shifted = |s: Pt| oracle_ray([o[0] + s[0], o[1] + s[1]], d, max as f64, &shape.exact);
                let shifts = [[-d[1] * bound, d[0] * bound], [d[1] * bound, -d[0] * bound], [d[0] * bound, d[1] * bound], [-d[0] * bound, -d[1] * bound]];
                let perturbed: Vec<_> = shifts.iter().map(|&s| shifted(s)).collect();
                let robust = exact.margin > bound && perturbed.iter().all(|p| p.status == exact.status);
                let got = match cast.outcome {
                    RayOutcome::Hit(_) => RayStatus::Hit,
                    RayOutcome::Miss => RayStatus::Miss,
                    RayOutcome::Inside => RayStatus::Inside,
                };
                if robust {
                    prop_assert_eq!(got, exact.status, "{}: {:?}", ctx(), cast);
                }
                // Inside only for an origin within rounding of the shape, grazing or not.
                if got == RayStatus::Inside {
                    let outside = pair(&ExactShape::point(o), &shape.exact).signed_distance;
                    prop_assert!(outside <= bound, "{}: inside, but the origin is {outside:e} outside", ctx());
                }
                if let RayOutcome::Hit(h) = cast.outcome {
                    let (t, n, p) = (h.distance as f64, pt(h.normal), pt(h.point));
                    prop_assert!(t.is_finite() && finite(h.normal) && finite(h.point), "{}: {:?}", ctx(), h);
                    prop_assert!(t >= 0.0 && (max_len <= 0.0 || t <= max as f64), "{}: {:?}", ctx(), h);
                    prop_assert!((norm(n) - 1.0).abs() <= 4.0 * EPS, "{}: normal not unit {:?}", ctx(), h);
                    let pr = bound + 4.0 * EPS * norm(p);
                    // The hit point is on the boundary.
                    let on = pair(&ExactShape::point(p), &shape.exact).signed_distance;
                    prop_assert!(on.abs() <= pr + 4.0 * EPS * t, "{}: hit point {:e} off the boundary; {:?}", ctx(), on, h);
                    if exact.status == RayStatus::Hit {
                        // Conditioning: how far the exact hit moves when the ray shifts by the bound.
                        let spread = perturbed.iter().filter(|q| q.status == RayStatus::Hit).map(|q| (q.t - exact.t).abs()).fold(0.0, f64::max);
                        prop_assert!((t - exact.t).abs() <= bound + 1.5 * spread, "{}: t {t:e} vs exact {:e} (error {:e}, spread {spread:e})", ctx(), exact.t, (t - exact.t).abs());
                    }
                    // The normal is outward at the hit point: the shape lies behind it.
                    let slack = 8.0 * EPS64 * (shape.reach() + norm(p));
                    let behind = shape.support(n) - (n[0] * p[0] + n[1] * p[1]);
                    let tol = if closed_form { pr } else { pr + 64.0 * (GjkConfig::<R>::default().raycast_epsilon() as f64).sqrt() * shape.radius() };
                    prop_assert!(behind.abs() <= tol + slack, "{}: shape reaches {behind:e} beyond the normal {n:?} plane", ctx());
                    // Round shapes have one normal everywhere: compare.
                    if closed_form && !matches!(shape.geo, Geo::Poly(_)) && exact.status == RayStatus::Hit && robust {
                        let e = norm(sub(n, exact.normal));
                        prop_assert!(e <= 64.0 * bound / shape.geo.radius() + 1e3 * EPS, "{}: normal {n:?} vs exact {:?}", ctx(), exact.normal);
                    }
                }
                Ok(())
            }

            proptest! {
                #![proptest_config(config())]

                #[test]
                fn pair_queries_in_world_coordinates(sa in spec(), sb in spec(), ca in (-2.0f64..2.0, -2.0f64..2.0), dir in 0.0..TAU, k in 0.0f64..1.4) {
                    let Some((a, b)) = world_pair(&sa, &sb, [ca.0, ca.1], dir, k) else { return Err(TestCaseError::reject("degenerate")) };
                    check_pair(&a, &b, "world")?;
                }

                #[test]
                fn pair_queries_with_transforms(sa in spec(), sb in spec(), pa in pose(), pb in pose(), dir in 0.0..TAU, k in 0.0f64..1.4) {
                    let Some((a, b)) = posed_pair(&sa, &pa, &sb, &pb, dir, k, [0.0, 0.0]) else { return Err(TestCaseError::reject("degenerate")) };
                    check_pair(&a, &b, "posed")?;
                }

                #[test]
                fn swapping_a_and_b(sa in spec(), sb in spec(), pa in pose(), pb in pose(), dir in 0.0..TAU, k in 0.0f64..1.4) {
                    let Some((a, b)) = posed_pair(&sa, &pa, &sb, &pb, dir, k, [0.0, 0.0]) else { return Err(TestCaseError::reject("degenerate")) };
                    let ab = check_pair(&a, &b, "A-B")?;
                    let ba = check_pair(&b, &a, "B-A")?;
                    let bound = ab.bound.max(ba.bound);
                    let what = format!("A {:?} at {:?}, B {:?} at {:?}", a.geo, a.tf, b.geo, b.tf);
                    if ab.oracle.signed_distance.abs() > bound {
                        prop_assert_eq!(ab.det.intersecting, ba.det.intersecting, "{}", what);
                    }
                    if let (Some(x), Some(y)) = (&ab.dist, &ba.dist) {
                        let d = x.distance as f64;
                        prop_assert!((d - y.distance as f64).abs() <= bound, "{}: {:?} vs {:?}", what, x, y);
                        let pr = bound + 4.0 * EPS * (norm(pt(x.point_a)).max(norm(pt(x.point_b))));
                        if d > 16.0 * pr {
                            let e = norm([x.normal.x as f64 + y.normal.x as f64, x.normal.y as f64 + y.normal.y as f64]);
                            prop_assert!(e <= 8.0 * pr / d + 16.0 * EPS, "{}: normals {:?} vs {:?}", what, x.normal, y.normal);
                        }
                        // With a circle the closest points are unique: they swap.
                        if a.geo.is_circle() || b.geo.is_circle() {
                            let e = norm(sub(pt(x.point_a), pt(y.point_b))).max(norm(sub(pt(x.point_b), pt(y.point_a))));
                            prop_assert!(e <= 16.0 * pr, "{}: points {:?} vs {:?}", what, x, y);
                        }
                    }
                    if let (Some(x), Some(y)) = (&ab.pen, &ba.pen) {
                        prop_assert!((x.depth as f64 - y.depth as f64).abs() <= bound, "{}: {:?} vs {:?}", what, x, y);
                    }
                }

                #[test]
                fn translating_both(sa in spec(), sb in spec(), pa in pose(), pb in pose(), dir in 0.0..TAU, k in 0.0f64..1.4, shift in (-1e3f64..1e3, -1e3f64..1e3)) {
                    let Some((a, b)) = posed_pair(&sa, &pa, &sb, &pb, dir, k, [0.0, 0.0]) else { return Err(TestCaseError::reject("degenerate")) };
                    let size = sa.nominal().max(sb.nominal());
                    let s = [shift.0 * size, shift.1 * size];
                    let Some((a2, b2)) = posed_pair(&sa, &pa, &sb, &pb, dir, k, s) else { return Err(TestCaseError::reject("degenerate")) };
                    let one = check_pair(&a, &b, "here")?;
                    let two = check_pair(&a2, &b2, "shifted")?;
                    // The shifted translations round: the pairs differ by that much.
                    let moved = norm(sub(sub(b2.t, a2.t), sub(b.t, a.t)));
                    let bound = one.bound + two.bound + moved;
                    let what = format!("A {:?} at {:?} / {:?}, B {:?} at {:?} / {:?}", a.geo, a.tf, a2.tf, b.geo, b.tf, b2.tf);
                    if one.oracle.signed_distance.abs() > bound {
                        prop_assert_eq!(one.det.intersecting, two.det.intersecting, "{}", what);
                        prop_assert_eq!(one.dist.is_some(), two.dist.is_some(), "{}", what);
                        prop_assert_eq!(one.pen.is_some(), two.pen.is_some(), "{}", what);
                    }
                    if let (Some(x), Some(y)) = (&one.dist, &two.dist) {
                        prop_assert!((x.distance as f64 - y.distance as f64).abs() <= bound, "{}: {:?} vs {:?}", what, x, y);
                        let d = x.distance as f64;
                        if d > 16.0 * bound {
                            let e = norm(sub(pt(x.normal), pt(y.normal)));
                            prop_assert!(e <= 8.0 * bound / d + 16.0 * EPS, "{}: normals {:?} vs {:?}", what, x.normal, y.normal);
                        }
                    }
                    if let (Some(x), Some(y)) = (&one.pen, &two.pen) {
                        prop_assert!((x.depth as f64 - y.depth as f64).abs() <= bound, "{}: {:?} vs {:?}", what, x, y);
                    }
                }

                #[test]
                fn rays_in_world_coordinates(s in spec(), c in (-2.0f64..2.0, -2.0f64..2.0), from in (0.0..TAU, 0.0f64..3.0), aim in prop_oneof![Just(None), (0.0..TAU).prop_map(Some)], jitter in -0.6f64..0.6, max in prop_oneof![Just(0.0), 0.0f64..4.0]) {
                    let size = s.nominal();
                    let Some(shape) = s.geo([c.0 * size, c.1 * size]).and_then(Placed::world) else { return Err(TestCaseError::reject("degenerate")) };
                    let center = shape.center();
                    let o = around(center, size, from);
                    // Aimed near the center (mostly hits) or anywhere.
                    let d = heading(aim.unwrap_or_else(|| bearing(o, center) + jitter));
                    prop_assume!(d != [0.0, 0.0]);
                    ray_check(&shape, o, d, max * size, true, "closed form")?;
                    ray_check(&shape, o, d, max * size, false, "iterative")?;
                }

                /// Rays at many-sided polygons, which the closed form casts by
                /// a binary search rather than a scan: aimed near the center,
                /// at a vertex, along an edge's line (through the vertices on
                /// it), nearly along it, or anywhere.
                #[test]
                fn rays_at_many_sided_polygons(g in many_sided(), p in pose(), from in (0.0..TAU, 0.0f64..3.0), aim in 0u8..5, pick in any::<prop::sample::Index>(), jitter in -0.6f64..0.6, max in prop_oneof![Just(0.0), 0.0f64..4.0]) {
                    let Geo::Poly(vertices) = &g else { unreachable!() };
                    let k = pick.index(vertices.len());
                    let (vertex, next) = (vertices[k], vertices[(k + 1) % vertices.len()]);
                    let Some(shape) = Placed::world(g.clone()) else { return Err(TestCaseError::reject("rejected")) };
                    let (center, size) = (shape.center(), shape.radius());
                    let o = around(center, size, from);
                    let (o, d) = match aim {
                        0 => (o, heading(bearing(o, center) + jitter)),
                        1 => (o, rp(sub(vertex, o))),
                        2 | 3 => {
                            let along = sub(next, vertex);
                            let back = from.1 * size / norm(along);
                            let o = rp([vertex[0] - back * along[0], vertex[1] - back * along[1]]);
                            // Aim 3 turns the ray off the edge's line by up to 6e-6 rad: it crosses
                            // the boundary at a shallow angle, a few rounding units from the line.
                            (o, if aim == 2 { rp(along) } else { heading(bearing(vertex, next) + jitter * 1e-5) })
                        }
                        _ => (o, heading(from.0)),
                    };
                    prop_assume!(d != [0.0, 0.0]);
                    ray_check(&shape, o, d, max * size, true, "closed form")?;
                    // Along an edge the iterative cast may stop anywhere within its
                    // epsilon of the vertex, and the ray is nearly parallel to the
                    // faces there: its error along the ray has no useful bound.
                    if aim != 2 && aim != 3 {
                        ray_check(&shape, o, d, max * size, false, "iterative")?;
                    }
                    // Placed by a transform: the ray reaches the polygon in its own frame.
                    let Some(posed) = Placed::new(g, transform(&p, rp([p.t[0] * size, p.t[1] * size]))) else { return Err(TestCaseError::reject("rejected")) };
                    let c = posed.center();
                    let o = around(c, size, from);
                    let d = heading(bearing(o, c) + jitter);
                    prop_assume!(d != [0.0, 0.0]);
                    ray_check(&posed, o, d, max * size, true, "closed form, posed")?;
                }

                #[test]
                fn rays_with_transforms(s in spec(), p in pose(), from in (0.0..TAU, 0.0f64..3.0), jitter in -0.6f64..0.6, max in prop_oneof![Just(0.0), 0.0f64..4.0]) {
                    let size = s.nominal();
                    let Some(g) = s.geo([0.3 * size, 0.2 * size]) else { return Err(TestCaseError::reject("degenerate")) };
                    let Some(shape) = Placed::new(g, transform(&p, rp([p.t[0] * size, p.t[1] * size]))) else { return Err(TestCaseError::reject("degenerate")) };
                    let center = shape.center();
                    let o = around(center, size, from);
                    let d = heading(bearing(o, center) + jitter);
                    ray_check(&shape, o, d, max * size, true, "closed form")?;
                    ray_check(&shape, o, d, max * size, false, "iterative")?;
                }
            }
        }
    };
}

property_suite!(f32_suite, f32, Vec2);
property_suite!(f64_suite, f64, DVec2);
