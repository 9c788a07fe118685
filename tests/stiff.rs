//! Stiff and extreme configurations, in f32 and f64 (one macro, one suite per
//! precision), every answer checked against the exact oracle (`gjk2d_oracle`).
//!
//! Families: shapes 1e5 from the origin (world coordinates, and transforms
//! with a large translation); sizes 1e-4 to 1e4; slivers (aspect 1e-3, 1e-5);
//! exact contact (vertex-vertex, vertex-edge, edge-edge, round shapes) and a
//! few ulps either side; parallel faces with gaps of 1 ulp to 1e-6 of the
//! size; polygons of 1000+ vertices; one shape inside the other; identical
//! shapes at the same place; near-degenerate simplices; rays at far, tiny and
//! huge shapes and grazing a face.
//!
//! Every case states:
//! - the verdict: asserted whenever the exact margin exceeds the bound, and
//!   always for `strict` cases (exact inputs whose contact or gap gjk2d can
//!   resolve exactly: axis-aligned faces, shared coordinates, identical
//!   rotations);
//! - an error bound `tol * eps * L`, `L` the pair's size (larger bounding
//!   radius, or the centers' distance if larger; for rays the bounding radius
//!   or the origin's distance from the center), never the distance from the
//!   origin: shapes far away must keep the precision of their size. Rotated
//!   placements add their rounding, `4 eps (|t_B - t_A| + local extents)`;
//!   world points round by `4 eps |p|` more;
//! - finite outputs, unit normals, closest points on the boundaries;
//! - `Status::Converged`, or else a status that says so with an `error_bound`
//!   that covers the actual error.
//!
//! Failures of a family are collected and reported together, each with its
//! inputs, the expected (exact) and the actual answer.

use gjk2d::glam::{DVec2, Vec2};
use gjk2d::*;
use gjk2d_oracle::{pair, ray as oracle_ray, transform_shape, ExactShape, RayStatus};

#[path = "common/geo.rs"]
mod geo;
#[macro_use]
#[path = "common/placed.rs"]
mod placed;
use geo::{norm, sub, Geo, Pt};

macro_rules! stiff_suite {
    ($modname:ident, $r:ty, $vec:ident) => {
        mod $modname {
            use super::*;
            type R = $r;
            const EPS: f64 = <$r>::EPSILON as f64;
            const EPS64: f64 = f64::EPSILON;
            const F32: bool = <$r>::EPSILON as f64 > 1e-10;

            fn v(p: Pt) -> $vec {
                $vec::new(p[0] as R, p[1] as R)
            }
            fn pt(p: $vec) -> Pt {
                [p.x as f64, p.y as f64]
            }
            fn finite(p: $vec) -> bool {
                p.x.is_finite() && p.y.is_finite()
            }
            /// `x` rounded to the suite's precision.
            fn q(x: f64) -> f64 {
                x as R as f64
            }
            fn qp(x: f64, y: f64) -> Pt {
                [q(x), q(y)]
            }
            /// `x` moved by `k` ulps of the suite's precision (up for k > 0).
            fn ulps(x: f64, k: i32) -> f64 {
                let mut y = x as R;
                for _ in 0..k.abs() {
                    y = if k > 0 { y.next_up() } else { y.next_down() };
                }
                y as f64
            }
            fn ulp(x: f64) -> f64 {
                ulps(x, 1) - q(x)
            }

            fn rect(x0: f64, y0: f64, x1: f64, y1: f64) -> Geo {
                Geo::Poly(vec![qp(x0, y0), qp(x1, y0), qp(x1, y1), qp(x0, y1)])
            }
            fn poly(points: &[(f64, f64)]) -> Geo {
                Geo::Poly(points.iter().map(|&(x, y)| qp(x, y)).collect())
            }
            /// `n` points on a circle of radius `r` about `c`, computed in the
            /// suite's precision.
            fn regular(n: usize, r: f64, c: Pt, phase: f64) -> Geo {
                Geo::Poly(
                    (0..n)
                        .map(|i| {
                            let a = (phase + std::f64::consts::TAU * i as f64 / n as f64) as R;
                            [(c[0] as R + r as R * a.cos()) as f64, (c[1] as R + r as R * a.sin()) as f64]
                        })
                        .collect(),
                )
            }
            fn circle(c: Pt, r: f64) -> Geo {
                Geo::Circle([q(c[0]), q(c[1])], q(r))
            }
            fn capsule(a: Pt, b: Pt, r: f64) -> Geo {
                Geo::Capsule([q(a[0]), q(a[1])], [q(b[0]), q(b[1])], q(r))
            }
            fn segment(a: Pt, b: Pt) -> Geo {
                Geo::Segment([q(a[0]), q(a[1])], [q(b[0]), q(b[1])])
            }
            fn shifted(g: &Geo, d: Pt) -> Geo {
                let m = |p: &Pt| [q(p[0] + d[0]), q(p[1] + d[1])];
                match g {
                    Geo::Poly(vs) => Geo::Poly(vs.iter().map(m).collect()),
                    Geo::Circle(c, r) => Geo::Circle(m(c), *r),
                    Geo::Capsule(a, b, r) => Geo::Capsule(m(a), m(b), *r),
                    Geo::Segment(a, b) => Geo::Segment(m(a), m(b)),
                    Geo::Rounded(vs, r) => Geo::Rounded(vs.iter().map(m).collect(), *r),
                }
            }

            fn build(g: &Geo) -> Result<Box<dyn SupportMap<R>>, Error> {
                Ok(match g {
                    Geo::Poly(pts) => {
                        let pts: Vec<$vec> = pts.iter().map(|&p| v(p)).collect();
                        if pts.len() <= 16 {
                            Box::new(Polygon::<R, 16>::new(&pts)?)
                        } else {
                            Box::new(Polygon::<R, 1100>::new(&pts)?)
                        }
                    }
                    Geo::Circle(c, r) => Box::new(Circle::at(v(*c), *r as R)?),
                    Geo::Capsule(a, b, r) => Box::new(Capsule::new(v(*a), v(*b), *r as R)?),
                    Geo::Segment(a, b) => Box::new(Segment::new(v(*a), v(*b))?),
                    Geo::Rounded(pts, r) => {
                        let pts: Vec<$vec> = pts.iter().map(|&p| v(p)).collect();
                        Box::new(Rounded::new(Polygon::<R, 16>::new(&pts)?, *r as R)?)
                    }
                })
            }

            fn tf(t: Pt, angle: f64) -> Transform<R> {
                Transform::new(v(t), angle as R).unwrap()
            }

            placed_shape!();

            impl Placed {
                fn new(geo: &Geo, tf: Transform<R>) -> Self {
                    let shape = build(geo).unwrap_or_else(|e| panic!("test shape rejected ({e}): {}", geo.describe()));
                    Self::from_parts(geo.clone(), shape, tf)
                }
            }

            /// One pair configuration.
            struct PairCase {
                name: String,
                a: Geo,
                ta: Transform<R>,
                b: Geo,
                tb: Transform<R>,
                /// The verdict is asserted even within the bound.
                strict: bool,
                /// Error bound in units of `eps * L`.
                tol: f64,
            }

            fn case(name: impl Into<String>, a: Geo, b: Geo, strict: bool) -> PairCase {
                PairCase { name: name.into(), a, ta: Transform::IDENTITY, b, tb: Transform::IDENTITY, strict, tol: 8.0 }
            }
            fn posed(name: impl Into<String>, a: Geo, ta: Transform<R>, b: Geo, tb: Transform<R>, strict: bool) -> PairCase {
                PairCase { name: name.into(), a, ta, b, tb, strict, tol: 8.0 }
            }

            fn check_pair(c: &PairCase) -> Result<(), String> {
                let a = Placed::new(&c.a, c.ta);
                let b = Placed::new(&c.b, c.tb);
                let gjk = Gjk::<R>::new();
                let o = pair(&a.exact, &b.exact);
                let l = a.radius().max(b.radius()).max(norm(sub(a.center(), b.center())));
                let identity = c.ta == Transform::IDENTITY && c.tb == Transform::IDENTITY;
                let placement = if identity { 0.0 } else { 4.0 * EPS * (norm(sub(b.t, a.t)) + c.a.extent() + c.b.extent()) };
                let bound = c.tol * EPS * l + placement;
                let slack = 8.0 * EPS64 * (a.reach() + b.reach());
                // A converged answer may stop on the configured relative epsilon
                // (GJK's distance epsilon, EPA's epsilon) before a vertex repeats:
                // its error_bound then certifies the rest.
                let cfg_bound = 2.0 * (GjkConfig::<R>::default().distance_epsilon() as f64).max(EpaConfig::<R>::default().epsilon() as f64) * l;
                let det = gjk.intersects(&*a.shape, &a.tf, &*b.shape, &b.tf);
                let dist = gjk.distance(&*a.shape, &a.tf, &*b.shape, &b.tf);
                let pen = gjk.penetration(&*a.shape, &a.tf, &*b.shape, &b.tf);
                let ctx = || {
                    format!(
                        "[{}] A {} {:?}, B {} {:?}\n    exact: signed distance {:e}, depth {:e}, normal {:?}; bound {:e} (L {:e})\n    gjk2d: {:?}\n           {:?}\n           {:?}",
                        c.name,
                        c.a.describe(),
                        c.ta,
                        c.b.describe(),
                        c.tb,
                        o.signed_distance,
                        o.depth,
                        o.normal,
                        bound,
                        l,
                        det,
                        dist,
                        pen
                    )
                };
                let fail = |why: String| Err(format!("{}\n    -> {why}", ctx()));
                if !det.status.is_converged() {
                    return fail("intersects hit its iteration limit".into());
                }
                let overlap = o.touching_or_overlapping;
                if c.strict || o.signed_distance.abs() > bound {
                    if det.intersecting != overlap || dist.is_none() != overlap || pen.is_some() != overlap {
                        return fail(format!("wrong verdict: exact {}", if overlap { "touching/overlapping" } else { "apart" }));
                    }
                }
                if let Some(s) = &dist {
                    let (pa, pb, n) = (pt(s.point_a), pt(s.point_b), pt(s.normal));
                    let d = s.distance as f64;
                    if !(d.is_finite() && finite(s.normal) && finite(s.point_a) && finite(s.point_b) && (s.error_bound as f64).is_finite()) {
                        return fail("non-finite distance output".into());
                    }
                    let err = (d - o.distance).abs();
                    let certified = s.error_bound as f64 + bound;
                    if err > certified {
                        return fail(format!("distance error {err:e} exceeds the bound {bound:e} plus error_bound (status {:?}, error_bound {:e})", s.status, s.error_bound));
                    }
                    if s.status.is_converged() && s.error_bound as f64 > bound.max(cfg_bound) {
                        return fail("converged with a large error_bound".into());
                    }
                    if (norm(n) - 1.0).abs() > 4.0 * EPS {
                        return fail("distance normal not unit".into());
                    }
                    let pr = certified + 4.0 * EPS * norm(pa).max(norm(pb));
                    let gap = sub(pb, pa);
                    if (norm(gap) - d).abs() > 2.0 * pr {
                        return fail(format!("closest points {:e} apart", norm(gap)));
                    }
                    let on_a = pair(&ExactShape::point(pa), &a.exact).signed_distance;
                    let on_b = pair(&ExactShape::point(pb), &b.exact).signed_distance;
                    if on_a.abs() > pr || on_b.abs() > pr {
                        return fail(format!("closest points off the boundaries by {on_a:e} (A), {on_b:e} (B)"));
                    }
                    let along = -(a.support(n) + b.support([-n[0], -n[1]]));
                    if along < d - certified - slack {
                        return fail(format!("the shapes are only {along:e} apart along the normal"));
                    }
                }
                if let Some(p) = &pen {
                    let n = pt(p.normal);
                    let depth = p.depth as f64;
                    if !(depth.is_finite() && finite(p.normal) && (p.error_bound as f64).is_finite()) {
                        return fail("non-finite penetration output".into());
                    }
                    let err = (depth - o.depth).abs();
                    let certified = p.error_bound as f64 + bound;
                    if err > certified {
                        return fail(format!("depth error {err:e} exceeds the bound {bound:e} plus error_bound (status {:?}, error_bound {:e})", p.status, p.error_bound));
                    }
                    if p.status.is_converged() && p.error_bound as f64 > bound.max(cfg_bound) {
                        return fail("converged with a large error_bound".into());
                    }
                    if (norm(n) - 1.0).abs() > 4.0 * EPS {
                        return fail("penetration normal not unit".into());
                    }
                    let needed = a.support(n) + b.support([-n[0], -n[1]]);
                    if needed > depth + certified + slack {
                        return fail(format!("along the normal B must move {needed:e}, more than the depth"));
                    }
                }
                Ok(())
            }

            fn run_pairs(family: &str, cases: Vec<PairCase>) {
                let total = cases.len();
                let failures: Vec<String> = cases.iter().filter_map(|c| check_pair(c).err()).collect();
                assert!(failures.is_empty(), "{family}: {} of {total} cases failed:\n{}", failures.len(), failures.join("\n"));
            }

            /// One ray configuration.
            struct RayCase {
                name: String,
                shape: Geo,
                tf: Transform<R>,
                origin: Pt,
                dir: Pt,
                max: f64,
                strict: bool,
                /// Also cast by iteration (not for grazing rays: ill-conditioned).
                iterative: bool,
            }

            fn ray_case(name: impl Into<String>, shape: Geo, origin: Pt, dir: Pt, strict: bool) -> RayCase {
                RayCase { name: name.into(), shape, tf: Transform::IDENTITY, origin: [q(origin[0]), q(origin[1])], dir: [q(dir[0]), q(dir[1])], max: 0.0, strict, iterative: !strict }
            }

            fn check_ray(c: &RayCase, closed_form: bool) -> Result<(), String> {
                let shape = Placed::new(&c.shape, c.tf);
                let mut gjk = Gjk::<R>::new();
                gjk.closed_form_rays = closed_form;
                let ray = Ray::new(v(c.origin), v(c.dir)).unwrap();
                let (o, d) = (pt(ray.origin()), pt(ray.direction()));
                let cast = gjk.raycast(&ray, c.max as R, &*shape.shape, &shape.tf);
                let exact = oracle_ray(o, d, c.max, &shape.exact);
                let l = shape.radius().max(norm(sub(o, shape.center())));
                let t_far = if exact.t.is_finite() { exact.t } else { 0.0 };
                let placement = if c.tf == Transform::IDENTITY { 0.0 } else { 4.0 * EPS * (norm(sub(o, shape.t)) + c.shape.extent() + t_far) };
                let mut bound = 8.0 * EPS * l + placement;
                if !closed_form {
                    bound += 2.0 * GjkConfig::<R>::default().raycast_epsilon() as f64 * shape.radius();
                }
                let ctx = || format!("[{} {}] ray {o:?} -> {d:?} max {:e} at {} {:?}\n    exact: {:?}; bound {bound:e}\n    gjk2d: {:?}", c.name, if closed_form { "closed form" } else { "iterative" }, c.max, c.shape.describe(), c.tf, exact, cast);
                let fail = |why: String| Err(format!("{}\n    -> {why}", ctx()));
                if !cast.status.is_converged() {
                    // Not silent: the status says so (rays carry no error bound).
                    if closed_form || cast.status != Status::IterationLimit {
                        return fail("closed form cast not converged".into());
                    }
                    return Ok(());
                }
                let shifted = |s: Pt| oracle_ray([o[0] + s[0], o[1] + s[1]], d, c.max, &shape.exact);
                let shifts = [[-d[1] * bound, d[0] * bound], [d[1] * bound, -d[0] * bound], [d[0] * bound, d[1] * bound], [-d[0] * bound, -d[1] * bound]];
                let perturbed: Vec<_> = shifts.iter().map(|&s| shifted(s)).collect();
                let robust = exact.margin > bound && perturbed.iter().all(|p| p.status == exact.status);
                let got = match cast.outcome {
                    RayOutcome::Hit(_) => RayStatus::Hit,
                    RayOutcome::Miss => RayStatus::Miss,
                    RayOutcome::Inside => RayStatus::Inside,
                };
                if (c.strict || robust) && got != exact.status {
                    return fail(format!("wrong verdict: exact {:?}", exact.status));
                }
                if let RayOutcome::Hit(h) = cast.outcome {
                    let (t, n, p) = (h.distance as f64, pt(h.normal), pt(h.point));
                    if !(t.is_finite() && finite(h.normal) && finite(h.point)) {
                        return fail("non-finite hit".into());
                    }
                    if (norm(n) - 1.0).abs() > 4.0 * EPS {
                        return fail("normal not unit".into());
                    }
                    let pr = bound + 4.0 * EPS * (norm(p) + t);
                    let on = pair(&ExactShape::point(p), &shape.exact).signed_distance;
                    if on.abs() > pr {
                        return fail(format!("hit point {on:e} off the boundary"));
                    }
                    if exact.status == RayStatus::Hit {
                        let spread = perturbed.iter().filter(|q| q.status == RayStatus::Hit).map(|q| (q.t - exact.t).abs()).fold(0.0, f64::max);
                        let err = (t - exact.t).abs();
                        if err > bound + 1.5 * spread {
                            return fail(format!("hit distance error {err:e} (spread under shifts {spread:e})"));
                        }
                    }
                    let slack = 8.0 * EPS64 * (shape.reach() + norm(p));
                    let behind = shape.support(n) - (n[0] * p[0] + n[1] * p[1]);
                    let tol = if closed_form { pr } else { pr + 64.0 * (GjkConfig::<R>::default().raycast_epsilon() as f64).sqrt() * shape.radius() };
                    if behind.abs() > tol + slack {
                        return fail(format!("the shape reaches {behind:e} beyond the plane of the normal"));
                    }
                }
                Ok(())
            }

            fn run_rays(family: &str, cases: Vec<RayCase>) {
                let total = cases.len();
                let mut failures = Vec::new();
                for c in &cases {
                    failures.extend(check_ray(c, true).err());
                    if c.iterative {
                        failures.extend(check_ray(c, false).err());
                    }
                }
                assert!(failures.is_empty(), "{family}: {} failures in {total} cases:\n{}", failures.len(), failures.join("\n"));
            }

            /// Local test shapes of size about `s` centered near the origin.
            fn menagerie(s: f64) -> Vec<(&'static str, Geo)> {
                vec![
                    ("square", rect(-0.5 * s, -0.5 * s, 0.5 * s, 0.5 * s)),
                    ("pentagon", poly(&[(0.5 * s, 0.0), (0.15 * s, 0.48 * s), (-0.4 * s, 0.29 * s), (-0.4 * s, -0.29 * s), (0.15 * s, -0.48 * s)])),
                    ("circle", circle([0.0, 0.0], 0.5 * s)),
                    ("capsule", capsule([-0.3 * s, 0.0], [0.3 * s, 0.0], 0.2 * s)),
                    ("segment", segment([-0.5 * s, 0.1 * s], [0.5 * s, -0.1 * s])),
                ]
            }

            /// Pairs of every menagerie shape, B's center at `gaps` (multiples of
            /// the size) along a few directions from A's, in world coordinates
            /// about `base` and by transforms to `base`.
            fn pair_grid(label: &str, s: f64, base: Pt, reaches: &[f64]) -> Vec<PairCase> {
                let mut out = Vec::new();
                let shapes = menagerie(s);
                for (na, a) in &shapes {
                    for (nb, b) in &shapes {
                        for &k in reaches {
                            for &dir in &[0.0f64, 0.9, 2.3, -1.6] {
                                let off = [k * s * dir.cos(), k * s * dir.sin()];
                                let wa = shifted(a, base);
                                let wb = shifted(b, [base[0] + off[0], base[1] + off[1]]);
                                out.push(case(format!("{label} world {na}-{nb} reach {k} dir {dir}"), wa, wb, false));
                                let ta = tf(base, 0.4);
                                let tb = tf([q(base[0] + off[0]), q(base[1] + off[1])], -1.1 + dir);
                                out.push(posed(format!("{label} posed {na}-{nb} reach {k} dir {dir}"), a.clone(), ta, b.clone(), tb, false));
                            }
                        }
                    }
                }
                out
            }

            #[test]
            fn far_from_origin() {
                let mut cases = Vec::new();
                for base in [[1e5, 1e5], [-1e5, 3e4], [1e5, -1e5]] {
                    cases.extend(pair_grid(&format!("at {base:?}"), 1.0, base, &[0.3, 0.9, 1.6]));
                    if !F32 {
                        cases.extend(pair_grid(&format!("at {base:?} small"), 1e-3, base, &[0.3, 1.6]));
                    }
                }
                // Exact contact far away: shared coordinates, in world coordinates.
                let b = 1e5;
                cases.push(case("far edge-edge touching", rect(b, b, b + 1.0, b + 1.0), rect(b + 1.0, b + 0.25, b + 2.0, b + 0.75), true));
                cases.push(case("far vertex-vertex touching", rect(b, b, b + 1.0, b + 1.0), rect(b + 1.0, b + 1.0, b + 2.0, b + 2.0), true));
                cases.push(case("far edge-edge 1 ulp apart", rect(b, b, b + 1.0, b + 1.0), rect(ulps(b + 1.0, 1), b + 0.25, b + 2.0, b + 0.75), true));
                cases.push(case("far edge-edge 1 ulp overlap", rect(b, b, b + 1.0, b + 1.0), rect(ulps(b + 1.0, -1), b + 0.25, b + 2.0, b + 0.75), true));
                cases.push(case("far circle on edge", rect(b, b, b + 1.0, b + 1.0), circle([b + 1.5, b + 0.5], 0.5), true));
                // The same by transforms with one shared rotation: relative placement exact.
                for angle in [0.0, 0.7, 2.9] {
                    let t = tf([1e5, -1e5], angle);
                    cases.push(posed(format!("far posed edge-edge touching angle {angle}"), rect(0.0, 0.0, 1.0, 1.0), t, rect(1.0, 0.25, 2.0, 0.75), t, true));
                    cases.push(posed(format!("far posed edge-edge 1 ulp apart angle {angle}"), rect(0.0, 0.0, 1.0, 1.0), t, rect(ulps(1.0, 1), 0.25, 2.0, 0.75), t, true));
                    cases.push(posed(format!("far posed capsules touching angle {angle}"), capsule([0.0, 0.0], [2.0, 0.0], 0.5), t, capsule([0.5, 1.0], [3.0, 1.0], 0.5), t, angle == 0.0));
                }
                run_pairs("far from origin", cases);
            }

            #[test]
            fn sizes_from_1e_4_to_1e4() {
                let mut cases = Vec::new();
                for s in [1e-4, 1e-2, 1.0, 1e2, 1e4] {
                    cases.extend(pair_grid(&format!("size {s:e}"), s, [0.0, 0.0], &[0.2, 0.95, 1.3]));
                    cases.extend(pair_grid(&format!("size {s:e} offset"), s, [3.0 * s, -2.0 * s], &[0.6]));
                }
                // Mixed sizes: tiny against huge.
                for (small, big) in [(1e-4, 1.0), (1e-2, 1e4), (1.0, 1e4)] {
                    let face = rect(-big, -big, 0.0, big);
                    for (name, g) in menagerie(small) {
                        cases.push(case(format!("{name} {small:e} apart from face {big:e}"), face.clone(), shifted(&g, [small, 0.0]), false));
                        cases.push(case(format!("{name} {small:e} into face {big:e}"), face.clone(), shifted(&g, [0.25 * small, 0.0]), false));
                        cases.push(case(format!("{name} {small:e} deep in {big:e}"), face.clone(), shifted(&g, [-0.5 * big, 0.0]), false));
                    }
                }
                run_pairs("sizes", cases);
            }

            #[test]
            fn slivers() {
                let mut cases = Vec::new();
                for aspect in [1e-3, 1e-5] {
                    for s in [1e-2, 1.0, 1e3] {
                        let w = aspect * s;
                        let sliver = rect(-s, -0.5 * w, s, 0.5 * w);
                        let spike = poly(&[(s, 0.0), (-s, 0.5 * w), (-s, -0.5 * w)]);
                        let cross = rect(-0.5 * w, -s, 0.5 * w, s);
                        let label = format!("aspect {aspect:e} size {s:e}");
                        cases.push(case(format!("{label} crossing slivers"), sliver.clone(), cross.clone(), false));
                        cases.push(case(format!("{label} crossing slivers shifted"), sliver.clone(), shifted(&cross, [0.7 * s, 0.0]), false));
                        cases.push(case(format!("{label} parallel slivers apart by width"), sliver.clone(), shifted(&sliver, [0.3 * s, 2.0 * w]), false));
                        cases.push(case(format!("{label} parallel slivers overlapping by half width"), sliver.clone(), shifted(&sliver, [0.3 * s, 0.5 * w]), false));
                        cases.push(case(format!("{label} end to end gap"), sliver.clone(), shifted(&sliver, [2.0 * s + w, 0.0]), false));
                        cases.push(case(format!("{label} end to end overlap"), sliver.clone(), shifted(&sliver, [2.0 * s - w, 0.0]), false));
                        cases.push(case(format!("{label} spike tip at circle"), spike.clone(), circle([1.5 * s, 0.1 * s], 0.5 * s), false));
                        cases.push(case(format!("{label} spike tip into circle"), spike.clone(), circle([1.4 * s, 0.0], 0.5 * s), false));
                        cases.push(case(format!("{label} spike vs spike side by side"), spike.clone(), shifted(&spike, [0.0, 2.0 * w]), false));
                        cases.push(case(format!("{label} spike vs spike overlapping"), spike.clone(), shifted(&spike, [0.1 * s, 0.25 * w]), false));
                        cases.push(case(format!("{label} sliver capsule vs square"), capsule([-s, 0.0], [s, 0.0], w), rect(-0.5 * s, 2.0 * w, 0.5 * s, s), false));
                        cases.push(case(format!("{label} sliver capsule into square"), capsule([-s, 0.0], [s, 0.0], w), rect(-0.5 * s, 0.5 * w, 0.5 * s, s), false));
                        for angle in [0.3, 1.2] {
                            cases.push(posed(format!("{label} rotated sliver near square angle {angle}"), sliver.clone(), tf([0.0, 0.0], angle), rect(-0.5 * s, -0.5 * s, 0.5 * s, 0.5 * s), tf([0.0, 1.2 * s], 0.0), false));
                            cases.push(posed(format!("{label} rotated sliver through square angle {angle}"), sliver.clone(), tf([0.0, 0.0], angle), rect(-0.5 * s, -0.5 * s, 0.5 * s, 0.5 * s), tf([0.2 * s, 0.0], 0.0), false));
                        }
                    }
                }
                run_pairs("slivers", cases);
            }

            /// A's square `[0, s]^2` against B's contact shapes, B moved by `dx` in x.
            fn contact_cases(s: f64, label: &str, step: i32) -> Vec<PairCase> {
                let a = rect(0.0, 0.0, s, s);
                let x = |k: f64| ulps(k * s, step);
                let tri = Geo::Poly(vec![qp(0.0, 0.0), qp(s, 0.0), qp(0.0, s)]);
                let strict = true;
                vec![
                    case(format!("{label} edge-edge"), a.clone(), Geo::Poly(vec![[x(1.0), q(0.25 * s)], [q(2.0 * s), q(0.25 * s)], [q(2.0 * s), q(0.75 * s)], [x(1.0), q(0.75 * s)]]), strict),
                    case(format!("{label} edge-edge full"), a.clone(), Geo::Poly(vec![[x(1.0), 0.0], [q(2.0 * s), 0.0], [q(2.0 * s), q(s)], [x(1.0), q(s)]]), strict),
                    case(format!("{label} vertex-edge"), a.clone(), Geo::Poly(vec![[x(1.0), q(0.5 * s)], [q(2.0 * s), 0.0], [q(2.0 * s), q(s)]]), strict),
                    case(format!("{label} vertex-vertex"), a.clone(), Geo::Poly(vec![[x(1.0), q(s)], [q(2.0 * s), q(s)], [q(2.0 * s), q(2.0 * s)], [x(1.0), q(2.0 * s)]]), strict),
                    case(format!("{label} vertex-vertex diagonal"), a.clone(), Geo::Poly(vec![[x(1.0), q(s)], [q(2.0 * s), q(1.5 * s)], [q(1.5 * s), q(2.0 * s)]]), strict),
                    case(format!("{label} circle on edge"), a.clone(), Geo::Circle([ulps(q(s) + q(0.5 * s), step), q(0.5 * s)], q(0.5 * s)), strict),
                    case(format!("{label} capsule side on edge"), a.clone(), Geo::Capsule([ulps(q(s) + q(0.25 * s), step), q(0.1 * s)], [ulps(q(s) + q(0.25 * s), step), q(0.9 * s)], q(0.25 * s)), strict),
                    case(format!("{label} capsule end on edge"), a.clone(), Geo::Capsule([ulps(q(s) + q(0.25 * s), step), q(0.5 * s)], [q(3.0 * s), q(0.5 * s)], q(0.25 * s)), strict),
                    case(format!("{label} circles"), Geo::Circle([0.0, 0.0], q(s)), Geo::Circle([ulps(q(2.0 * s), step), 0.0], q(s)), strict),
                    case(format!("{label} segments end to end"), Geo::Segment([0.0, 0.0], [q(s), 0.0]), Geo::Segment([x(1.0), 0.0], [q(2.0 * s), 0.0]), strict),
                    case(format!("{label} segment on edge"), a.clone(), Geo::Segment([x(1.0), q(0.25 * s)], [x(1.0), q(0.75 * s)]), strict),
                    // The slanted hypotenuse x + y = s: exact contact, rounding on the slant.
                    case(format!("{label} slanted edge-edge"), tri.clone(), Geo::Poly(vec![[x(1.0), 0.0], [x(1.0), q(s)], [ulps(0.0, step), q(s)]]), step == 0),
                    case(format!("{label} vertex on slanted edge"), tri.clone(), Geo::Poly(vec![[x(0.5), q(0.5 * s)], [q(1.5 * s), q(0.5 * s)], [q(s), q(1.5 * s)]]), false),
                ]
            }

            #[test]
            fn exact_contact_and_ulps_apart() {
                let mut cases = Vec::new();
                for s in [1e-4, 0.75, 1.0, 3.0, 1e4] {
                    for step in [0, 1, 2, 4, -1, -4] {
                        cases.extend(contact_cases(s, &format!("size {s:e} step {step} ulps"), step));
                    }
                }
                // One shared rotation and translation: the relative placement is exact.
                for angle in [0.5, 2.0] {
                    let t = tf([10.0, -3.0], angle);
                    for c in contact_cases(1.0, &format!("posed angle {angle}"), 0).into_iter().chain(contact_cases(1.0, &format!("posed angle {angle} 1 ulp apart"), 1)) {
                        // The oracle rotates cores with |(cos, sin)| = 1 +- eps but keeps
                        // radii: exact contact of round shapes is not preserved.
                        let strict = c.strict && c.a.radius() == 0.0 && c.b.radius() == 0.0;
                        cases.push(PairCase { ta: t, tb: t, strict, ..c });
                    }
                }
                run_pairs("exact contact", cases);
            }

            #[test]
            fn parallel_faces_with_tiny_gaps() {
                let mut cases = Vec::new();
                for s in [1e-4, 1.0, 1e4] {
                    let a = rect(0.0, 0.0, s, s);
                    let mut gaps = vec![ulp(s), 4.0 * ulp(s), 1e-6 * s];
                    if !F32 {
                        gaps.push(1e-9 * s);
                        gaps.push(1e-12 * s);
                    }
                    for g in gaps {
                        for sign in [1.0, -1.0] {
                            let x0 = q(s + sign * g);
                            let label = format!("size {s:e} gap {:e}", sign * g);
                            cases.push(case(format!("{label} axis faces"), a.clone(), rect(x0, 0.1 * s, x0 + s, 0.9 * s), true));
                            cases.push(case(format!("{label} axis faces offset"), a.clone(), rect(x0, 0.5 * s, x0 + s, 1.5 * s), true));
                            // Slanted faces along x + y = s (world coordinates, rounded).
                            let d = sign * g / std::f64::consts::SQRT_2;
                            let tri = poly(&[(0.0, 0.0), (s, 0.0), (0.0, s)]);
                            let far = poly(&[(s + d, d), (s + d, s + d), (d, s + d)]);
                            cases.push(case(format!("{label} slanted faces"), tri.clone(), far, false));
                            // Rotated by transforms: the same shapes, one shared rotation.
                            let t = tf([5.0 * s, 2.0 * s], 0.3);
                            cases.push(posed(format!("{label} posed axis faces"), a.clone(), t, rect(x0, 0.1 * s, x0 + s, 0.9 * s), t, true));
                            // Different rotations: B's face rotated into A's frame; B's
                            // reference point joins the offset, which rounds (not strict).
                            let tb = Transform::from_cos_sin(v([s + sign * g, 0.0]), 0.0, 1.0).unwrap();
                            cases.push(posed(format!("{label} quarter-turned B"), a.clone(), Transform::IDENTITY, rect(0.1 * s, -s, 0.9 * s, 0.0), tb, false));
                        }
                    }
                    // Capsule sides parallel to a face.
                    for g in [ulp(s), 1e-6 * s] {
                        cases.push(case(format!("size {s:e} capsule side gap {g:e}"), a.clone(), capsule([0.2 * s, q(q(1.5 * s) + g)], [0.8 * s, q(q(1.5 * s) + g)], q(0.5 * s)), false));
                        cases.push(case(format!("size {s:e} capsules parallel gap {g:e}"), capsule([0.0, 0.0], [s, 0.0], 0.25 * s), capsule([0.5 * s, q(q(0.5 * s) + g)], [1.5 * s, q(q(0.5 * s) + g)], 0.25 * s), false));
                    }
                }
                run_pairs("parallel faces", cases);
            }

            #[test]
            fn polygons_with_1000_plus_vertices() {
                let mut cases = Vec::new();
                for (n, r) in [(1024usize, 1.0), (1100, 100.0)] {
                    let big = regular(n, r, [0.0, 0.0], 0.001);
                    let label = format!("{n}-gon radius {r}");
                    cases.push(case(format!("{label} vs itself apart"), big.clone(), shifted(&big, [2.0 * r + 0.01 * r, 0.3 * r]), false));
                    cases.push(case(format!("{label} vs itself overlapping"), big.clone(), shifted(&big, [1.9 * r, 0.2 * r]), false));
                    cases.push(case(format!("{label} vs itself same place"), big.clone(), big.clone(), false));
                    cases.push(case(format!("{label} vs triangle outside"), big.clone(), poly(&[(1.01 * r, 0.1 * r), (1.2 * r, 0.0), (1.2 * r, 0.3 * r)]), false));
                    cases.push(case(format!("{label} vs triangle poking in"), big.clone(), poly(&[(0.99 * r, 0.1 * r), (1.2 * r, 0.0), (1.2 * r, 0.3 * r)]), false));
                    cases.push(case(format!("{label} vs circle inside"), big.clone(), circle([0.3 * r, -0.2 * r], 0.1 * r), false));
                    cases.push(case(format!("{label} vs capsule outside"), big.clone(), capsule([-1.2 * r, 0.5 * r], [-0.9 * r, 1.0 * r], 0.05 * r), false));
                    cases.push(posed(format!("{label} vs square, rotated"), big.clone(), tf([0.0, 0.0], 0.37), rect(-0.1 * r, -0.1 * r, 0.1 * r, 0.1 * r), tf([0.0, 1.05 * r], 1.0), false));
                    cases.push(posed(format!("{label} far by transform"), big.clone(), tf([1e5, 1e5], 0.37), big.clone(), tf([1e5 + 2.05 * r, 1e5], -0.2), false));
                }
                // A 1000-gon with a long, nearly straight side (many almost collinear vertices).
                let mut pts: Vec<(f64, f64)> = (0..1000).map(|i| (i as f64 / 999.0, 1e-4 * ((i as f64 / 999.0) * (1.0 - i as f64 / 999.0)))).collect();
                pts.reverse();
                pts.push((0.0, -0.5));
                pts.push((1.0, -0.5));
                pts.rotate_right(2);
                let flat = Geo::Poly(pts.iter().map(|&(x, y)| qp(x, y)).collect());
                if build(&flat).is_ok() {
                    cases.push(case("nearly flat 1002-gon vs square above", flat.clone(), rect(0.4, 0.01, 0.6, 0.2), false));
                    cases.push(case("nearly flat 1002-gon vs square just above", flat.clone(), rect(0.4, 2.6e-5, 0.6, 0.2), false));
                }
                // Big polygons: their stack-stored vertices are run on a roomy thread.
                std::thread::Builder::new().stack_size(64 << 20).spawn(move || run_pairs("big polygons", cases)).unwrap().join().unwrap();
            }

            /// Nearly round polygons with many more sides than EPA's polytope
            /// has room for (32 corners), around a small shape at or near
            /// their center: every face of the difference is nearly as deep
            /// as the deepest, so certifying the depth takes most of them.
            /// Merging the faces EPA has certified keeps the polytope small:
            /// each must converge, not stop with a full polytope.
            ///
            /// A square at the center ties the depth in four directions: the
            /// polytope fills before the upper bound comes down to the depth,
            /// nothing is certified yet, and EPA stops at its capacity. Those
            /// answers are checked for soundness only.
            #[test]
            fn round_many_sided_polygons_around_a_small_shape() {
                // Around a centred square the depth ties in four directions;
                // a full polytope then merges uncertified corners, and every
                // case still converges in the default 32 corners.
                let mut cases = Vec::new();
                for n in [40usize, 100, 333, 1024] {
                    let round = regular(n, 1.0, [0.0, 0.0], 0.1);
                    let small = [
                        ("triangle", poly(&[(-0.01, -0.01), (0.01, -0.01), (0.0, 0.01)])),
                        ("segment", segment([-0.01, 0.0], [0.01, 0.003])),
                        ("square", rect(-0.01, -0.01, 0.01, 0.01)),
                    ];
                    for (name, g) in small {
                        for c in [[0.0, 0.0], [0.013, -0.007], [1e-6, 0.0]] {
                            cases.push(case(format!("{n}-gon around a {name} at {c:?}"), round.clone(), shifted(&g, c), true));
                        }
                    }
                }
                let unconverged: Vec<String> = cases
                    .iter()
                    .filter_map(|c| {
                        let (a, b) = (Placed::new(&c.a, c.ta), Placed::new(&c.b, c.tb));
                        let pen = Gjk::<R>::new().penetration(&*a.shape, &a.tf, &*b.shape, &b.tf)?;
                        (pen.status != Status::Converged).then(|| format!("{}: {pen:?}", c.name))
                    })
                    .collect();
                assert!(unconverged.is_empty(), "{} of {} did not converge:\n{}", unconverged.len(), cases.len(), unconverged.join("\n"));
                run_pairs("round many-sided", cases);
            }

            #[test]
            fn one_shape_inside_the_other() {
                let mut cases = Vec::new();
                for s in [1e-3, 1.0, 1e3] {
                    let outer = [
                        ("big square", rect(-s, -s, s, s)),
                        ("big circle", circle([0.0, 0.0], s)),
                        ("big capsule", capsule([-s, 0.0], [s, 0.0], 0.8 * s)),
                        ("big hexagon", regular(6, s, [0.0, 0.0], 0.2)),
                    ];
                    for (no, o) in &outer {
                        for (ni, i) in menagerie(0.2 * s) {
                            for c in [[0.0, 0.0], [0.3 * s, 0.1 * s], [-0.5 * s, -0.2 * s]] {
                                cases.push(case(format!("size {s:e} {ni} inside {no} at {c:?}"), o.clone(), shifted(&i, c), false));
                                cases.push(case(format!("size {s:e} {no} around {ni} at {c:?}"), shifted(&i, c), o.clone(), false));
                            }
                        }
                    }
                }
                // Tiny inside huge.
                cases.push(case("1e-4 square inside 1e4 square", rect(-1e4, -1e4, 1e4, 1e4), rect(1.0, 1.0, 1.0001, 1.0001), false));
                cases.push(case("1e-4 circle inside 1e4 circle", circle([0.0, 0.0], 1e4), circle([3.0, -2.0], 1e-4), false));
                run_pairs("inside", cases);
            }

            #[test]
            fn identical_shapes_at_the_same_place() {
                let mut cases = Vec::new();
                for s in [1e-4, 1.0, 1e4] {
                    let mut shapes = menagerie(s);
                    shapes.push(("rectangle 3x1", rect(-1.5 * s, -0.5 * s, 1.5 * s, 0.5 * s)));
                    shapes.push(("sliver", rect(-s, -1e-3 * s, s, 1e-3 * s)));
                    shapes.push(("triangle", poly(&[(0.0, 0.0), (s, 0.1 * s), (0.3 * s, 0.8 * s)])));
                    for (name, g) in shapes {
                        cases.push(case(format!("size {s:e} {name} on itself"), g.clone(), g.clone(), false));
                        cases.push(posed(format!("size {s:e} {name} on itself, same transform"), g.clone(), tf([2.0 * s, s], 1.3), g.clone(), tf([2.0 * s, s], 1.3), false));
                        if s > 1e3 * ulp(1e5) {
                            cases.push(case(format!("size {s:e} {name} on itself far away"), shifted(&g, [1e5, 1e5]), shifted(&g, [1e5, 1e5]), false));
                        }
                    }
                }
                run_pairs("identical", cases);
            }

            #[test]
            fn near_degenerate_simplices() {
                let mut cases = Vec::new();
                for s in [1e-3, 1.0, 1e3] {
                    for tilt in [1e-3, 1e-5, 1e-7] {
                        let label = format!("size {s:e} tilt {tilt:e}");
                        let a = segment([0.0, 0.0], [s, 0.0]);
                        cases.push(case(format!("{label} almost parallel segments apart"), a.clone(), segment([0.1 * s, 1e-3 * s], [1.1 * s, 1e-3 * s + tilt * s]), false));
                        cases.push(case(format!("{label} almost parallel segments near"), a.clone(), segment([0.1 * s, tilt * s], [1.1 * s, 2.0 * tilt * s]), false));
                        cases.push(case(format!("{label} segments crossing at a tiny angle"), segment([0.0, -tilt * s], [s, tilt * s]), segment([0.0, tilt * s], [s, -tilt * s]), false));
                        cases.push(case(format!("{label} collinear segments gap"), a.clone(), segment([1.001 * s, tilt * s], [2.0 * s, 0.0]), false));
                        cases.push(case(format!("{label} almost parallel capsules"), capsule([0.0, 0.0], [s, 0.0], 0.1 * s), capsule([0.2 * s, 0.25 * s], [1.2 * s, 0.25 * s + tilt * s], 0.1 * s), false));
                        let sliver = poly(&[(0.0, 0.0), (s, 0.0), (0.5 * s, tilt * s)]);
                        let dot = 1e-4 * tilt * s;
                        for (where_, y) in [("above", 2.0 * tilt * s), ("just above", 1.5 * tilt * s), ("inside", 0.25 * tilt * s), ("below", -tilt * s)] {
                            let p = rect(0.3 * s, y, 0.3 * s + dot.max(ulp(s) * 4.0), y + dot.max(ulp(s) * 4.0));
                            if build(&p).is_ok() {
                                cases.push(case(format!("{label} sliver triangle vs point-like square {where_}"), sliver.clone(), p, false));
                            }
                        }
                        cases.push(case(format!("{label} sliver triangle vs tiny circle near apex"), sliver.clone(), circle([0.5 * s, 2.0 * tilt * s], tilt * s * 0.5), false));
                        cases.push(case(format!("{label} sliver triangle vs segment along base"), sliver.clone(), segment([-0.5 * s, -tilt * s], [1.5 * s, -tilt * s]), false));
                    }
                }
                run_pairs("near-degenerate simplices", cases);
            }

            #[test]
            fn rays_at_far_tiny_huge_and_grazing() {
                let mut cases = Vec::new();
                for (label, s, base) in [("far", 1.0, [1e5, -1e5]), ("tiny", 1e-4, [0.0, 0.0]), ("huge", 1e4, [0.0, 0.0]), ("tiny offset", 1e-4, [0.3, 0.1]), ("huge far", 1e4, [1e6, 0.0])] {
                    for (name, g) in menagerie(s) {
                        let g = shifted(&g, base);
                        for (from, dir) in [([-3.0, 0.1], [1.0, 0.0]), ([2.0, 2.0], [-1.0, -0.9]), ([0.1, -4.0], [0.05, 1.0]), ([3.0, 3.0], [1.0, 0.0]), ([0.1, 0.05], [0.3, 1.0])] {
                            let origin = [base[0] + from[0] * s, base[1] + from[1] * s];
                            cases.push(RayCase { strict: false, iterative: true, ..ray_case(format!("{label} {name} from {from:?}"), g.clone(), origin, dir, false) });
                        }
                    }
                    // The same shapes by a transform.
                    for (name, g) in menagerie(s) {
                        let origin = [q(base[0] - 3.0 * s), q(base[1] + 0.2 * s)];
                        cases.push(RayCase { tf: tf(base, 0.8), iterative: true, ..ray_case(format!("{label} posed {name}"), g, origin, [1.0, 0.0], false) });
                    }
                    // Grazing along the top face of a square [0, s]^2 (shifted by base).
                    let sq = shifted(&rect(0.0, 0.0, s, s), base);
                    let top = q(q(s) + base[1]);
                    let left = q(base[0] - 2.0 * s);
                    // Exact sums (no rounding of base + s): contact is exact.
                    let exact = label != "tiny offset";
                    cases.push(ray_case(format!("{label} along the top face"), sq.clone(), [left, top], [1.0, 0.0], true));
                    cases.push(ray_case(format!("{label} 1 ulp above the top face"), sq.clone(), [left, ulps(top, 1)], [1.0, 0.0], true));
                    cases.push(ray_case(format!("{label} 1 ulp below the top face"), sq.clone(), [left, ulps(top, -1)], [1.0, 0.0], true));
                    cases.push(ray_case(format!("{label} from the top face outward"), sq.clone(), [q(base[0] + 0.5 * s), top], [0.0, 1.0], true));
                    cases.push(ray_case(format!("{label} from the top face along it"), sq.clone(), [q(base[0] + 0.5 * s), top], [1.0, 0.0], true));
                    cases.push(ray_case(format!("{label} at a vertex diagonally"), sq.clone(), [q(base[0] - s), q(base[1] - s)], [1.0, 1.0], false));
                    // Tangent to a circle and along a capsule side.
                    let c = circle(base, s);
                    cases.push(ray_case(format!("{label} tangent to a circle"), c.clone(), [left, q(base[1] + s)], [1.0, 0.0], exact));
                    cases.push(ray_case(format!("{label} 1 ulp outside the tangent"), c.clone(), [left, ulps(q(base[1] + s), 1)], [1.0, 0.0], false));
                    let k = capsule([base[0], base[1]], [base[0] + s, base[1]], 0.5 * s);
                    // Along a flat side the iterative cast may stop anywhere on it: closed form only.
                    cases.push(RayCase { iterative: false, ..ray_case(format!("{label} along a capsule side"), k.clone(), [left, q(base[1] + q(0.5 * s))], [1.0, 0.0], false) });
                    cases.push(ray_case(format!("{label} slanted grazing a triangle face"), poly(&[(base[0], base[1]), (base[0] + s, base[1]), (base[0], base[1] + s)]), [q(base[0] - s), q(base[1] + 2.0 * s)], [1.0, -1.0], false));
                    // Bounded: ends short of, exactly at and past the hit.
                    for (what, max) in [("short", 1.9 * s), ("exact", 2.0 * s), ("past", 2.1 * s)] {
                        cases.push(RayCase { max: q(max), ..ray_case(format!("{label} bounded {what}"), sq.clone(), [left, q(base[1] + 0.5 * s)], [1.0, 0.0], what != "exact") });
                    }
                }
                // A 1000-gon.
                let big = regular(1024, 1.0, [0.0, 0.0], 0.001);
                cases.push(ray_case("1024-gon head on", big.clone(), [-3.0, 0.1], [1.0, 0.0], false));
                cases.push(ray_case("1024-gon grazing", big.clone(), [-3.0, 0.9999], [1.0, 0.0], false));
                std::thread::Builder::new().stack_size(64 << 20).spawn(move || run_rays("rays", cases)).unwrap().join().unwrap();
            }
        }
    };
}

stiff_suite!(f32_suite, f32, Vec2);
stiff_suite!(f64_suite, f64, DVec2);
