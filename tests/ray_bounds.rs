//! Every ray hit's `error_bound` holds: `|distance - exact| <= error_bound`
//! for hits that say `Status::Converged`, against exact answers: the oracle
//! (`gjk2d_oracle::ray`) for circles, 8-gons, 64-gons and capsules, the root
//! of the quadratic in rational arithmetic for ellipses (aspect 1 to 0.01).
//! In f32 and f64, at sizes 1e-3 to 1e4, placed near the origin or 1e4 away
//! (and with the geometry itself off its local origin), two families each:
//! random rays aimed into the shape, and grazing rays that pass within 1e-1
//! to 1e-7 of the size inside or outside a tangent. A miss or `Inside`
//! where the exact line runs deeper into the shape than rounding reaches is
//! a failure too; a NaN bound fails (`!(err <= bound)`).
//!
//! Head-on hits (`cos >= 0.5` at the exact hit, for every face of a polygon
//! within rounding of it) on geometry around its
//! local origin must carry a bound within README's figure. (Geometry far
//! from its local origin and rotated rounds the ray at that distance's
//! scale, and its bounds grow with it.) `cargo test --test ray_bounds -- --nocapture` prints the
//! measured figures; `GJK2D_LONG=N` multiplies every count by N.

// `!(err <= bound)`: a NaN must fail the check.
#![allow(clippy::neg_cmp_op_on_partial_ord)]

use gjk2d::glam::{DVec2, Vec2};
use gjk2d::*;
use gjk2d_oracle::exact::{q_from_f64, Q};
use gjk2d_oracle::{ray as oracle_ray, transform_shape, ExactShape, RayStatus, Shape};
use std::f64::consts::TAU;

#[path = "common/rng.rs"]
mod rng;
use rng::{cases, Rng};
#[path = "common/exact_ray.rs"]
mod exact_ray;
use exact_ray::ellipse_ray;

type Pt = [f64; 2];

fn dot(p: Pt, q: Pt) -> f64 {
    p[0] * q[0] + p[1] * q[1]
}
fn norm(p: Pt) -> f64 {
    p[0].hypot(p[1])
}
fn unit(angle: f64) -> Pt {
    [angle.cos(), angle.sin()]
}

/// Cases per family and precision: enough to see a failure of one ray in
/// 400 with probability above 0.95.
const CASES: u32 = 1200;

/// Rays per shape: the exact shape is built once for them.
const RAYS_PER_SHAPE: u32 = 3;

/// The shapes of the families.
#[derive(Clone, Copy, Debug, PartialEq)]
enum Kind {
    Ellipse,
    Circle,
    Gon8,
    Gon64,
    Capsule,
}

/// How a hit compares with the exact one, over a family.
#[derive(Default, Debug)]
struct Stats {
    hits: u32,
    grazing_hits: u32,
    iteration_limits: u32,
    /// Largest `error / error_bound`.
    ratio: f64,
    /// Largest error and bound over L, at `cos >= 0.5`.
    head_on_error: f64,
    head_on_bound: f64,
    /// Largest error over L, at any incidence.
    error: f64,
    failures: Vec<String>,
}

macro_rules! ray_bounds_suite {
    ($modname:ident, $r:ty, $vec:ident) => {
        mod $modname {
            use super::*;
            type R = $r;
            const EPS: f64 = <$r>::EPSILON as f64;
            /// README's curved-shape figure at the default epsilon.
            const CURVED: f64 = if EPS > 1e-10 { 1e-6 } else { 1e-12 };

            fn v(p: Pt) -> $vec {
                $vec::new(p[0] as R, p[1] as R)
            }
            fn pt(p: $vec) -> Pt {
                [p.x as f64, p.y as f64]
            }
            fn q(x: f64) -> f64 {
                x as R as f64
            }

            /// A shape placed by a transform, as gjk2d and the exact side see it.
            struct Case {
                kind: Kind,
                shape: Box<dyn SupportMap<R>>,
                tf: Transform<R>,
                /// Local core points and radius (ellipse: its semi-axes in `axes`).
                core: Vec<Pt>,
                radius: f64,
                axes: Pt,
                cs: (f64, f64),
                t: Pt,
                /// How far the geometry lies from its local origin.
                offset: f64,
                /// The oracle's world shape (not for ellipses).
                exact: Option<ExactShape>,
            }

            impl Case {
                fn new(kind: Kind, rng: &mut Rng) -> Option<Self> {
                    let s = q(10f64.powf(rng.range(-3.0, 4.0)));
                    // The geometry off its local origin (a polygon's reference
                    // point is then a far vertex) or around it.
                    let offset = if rng.unit() < 0.25 { unit(rng.range(0.0, TAU)).map(|x| x * s * 100.0) } else { [0.0; 2] };
                    let mut core = Vec::new();
                    let (mut radius, mut axes) = (0.0, [0.0; 2]);
                    let shape: Box<dyn SupportMap<R>> = match kind {
                        Kind::Ellipse => {
                            let aspect = [1.0, 1.0, 0.7, 0.5, 0.1, 0.03, 0.01][(rng.next() % 7) as usize];
                            axes = [q(s), q(s * aspect)];
                            Box::new(Ellipse::<R>::new((2.0 * axes[0]) as R, (2.0 * axes[1]) as R).ok()?)
                        }
                        Kind::Circle => {
                            radius = s;
                            core.push([q(offset[0]), q(offset[1])]);
                            Box::new(Circle::<R>::at(v(core[0]), s as R).ok()?)
                        }
                        Kind::Gon8 | Kind::Gon64 => {
                            let n = if kind == Kind::Gon8 { 8 } else { 64 };
                            let aspect = rng.range(0.2, 1.0);
                            let start = rng.range(0.0, TAU);
                            for i in 0..n {
                                let a = start + TAU * (i as f64 + rng.range(-0.3, 0.3)) / n as f64;
                                core.push([q(offset[0] + s * a.cos()), q(offset[1] + s * aspect * a.sin())]);
                            }
                            let vs: Vec<$vec> = core.iter().map(|&p| v(p)).collect();
                            let p = Polygon::<R, 64>::new(&vs).ok()?;
                            core = (0..p.len()).map(|i| pt(p.vertex(i).unwrap())).collect();
                            Box::new(p)
                        }
                        Kind::Capsule => {
                            let u = unit(rng.range(0.0, TAU));
                            let h = s * rng.range(0.05, 1.0);
                            core.push([q(offset[0] + u[0] * h), q(offset[1] + u[1] * h)]);
                            core.push([q(offset[0] - u[0] * h), q(offset[1] - u[1] * h)]);
                            radius = q(s * rng.range(0.1, 1.0));
                            Box::new(Capsule::<R>::new(v(core[0]), v(core[1]), radius as R).ok()?)
                        }
                    };
                    let place = match rng.next() % 3 {
                        0 => [0.0; 2],
                        1 => [rng.range(-3.0, 3.0) * s, rng.range(-3.0, 3.0) * s],
                        _ => [1e4 * rng.range(-1.0, 1.0), 1e4 * rng.range(-1.0, 1.0)],
                    };
                    let tf = Transform::new(v(place), rng.range(0.0, TAU) as R).ok()?;
                    let cs = (tf.cos() as f64, tf.sin() as f64);
                    let t = pt(tf.translation());
                    let exact = match kind {
                        Kind::Ellipse => None,
                        Kind::Circle => Some(Shape::Circle { center: core[0], radius }),
                        Kind::Capsule => Some(Shape::Capsule { a: core[0], b: core[1], radius }),
                        _ => Some(Shape::Polygon(core.clone())),
                    }
                    .map(|shape| transform_shape(&shape, cs.0, cs.1, t[0], t[1]));
                    Some(Self { kind, shape, tf, core, radius, axes, cs, t, offset: norm(offset), exact })
                }
                /// `x -> M x + t`, `M = [[c, -s], [s, c]]`, in f64.
                fn map(&self, p: Pt) -> Pt {
                    let (c, s) = self.cs;
                    [c * p[0] - s * p[1] + self.t[0], s * p[0] + c * p[1] + self.t[1]]
                }
                /// `M^T n`.
                fn pull(&self, n: Pt) -> Pt {
                    let (c, s) = self.cs;
                    [c * n[0] + s * n[1], -s * n[0] + c * n[1]]
                }
                fn center(&self) -> Pt {
                    self.map(pt(self.shape.reference_point() + self.shape.center()))
                }
                /// The world shape's support value and point in direction `n`.
                fn support(&self, n: Pt) -> (f64, Pt) {
                    let m = self.pull(n);
                    let local = if self.kind == Kind::Ellipse {
                        let [a, b] = self.axes;
                        let h = (a * m[0]).hypot(b * m[1]);
                        [a * a * m[0] / h, b * b * m[1] / h]
                    } else {
                        let best = self.core.iter().copied().fold([f64::NAN; 2], |best, p| {
                            if best[0].is_nan() || dot(p, m) > dot(best, m) {
                                p
                            } else {
                                best
                            }
                        });
                        let k = self.radius / norm(m);
                        [best[0] + m[0] * k, best[1] + m[1] * k]
                    };
                    let p = self.map(local);
                    (dot(n, p), p)
                }
                /// How deep the ray's line runs into the shape: the smaller of
                /// the shape's reach beyond it on either side (negative: apart).
                fn depth(&self, o: Pt, d: Pt) -> f64 {
                    let n = [-d[1] / norm(d), d[0] / norm(d)];
                    let (hi, _) = self.support(n);
                    let (lo, _) = self.support([-n[0], -n[1]]);
                    (hi - dot(n, o)).min(lo + dot(n, o))
                }
                /// The incidence of a polygon hit at `t`: the least `|n . d|`
                /// over the faces within rounding of the hit point (both at a
                /// vertex: the ray may enter through either), else `cos`.
                fn incidence(&self, o: Pt, d: Pt, t: f64, cos: f64) -> f64 {
                    if !matches!(self.kind, Kind::Gon8 | Kind::Gon64) {
                        return cos;
                    }
                    let dn = norm(d);
                    let hit = [o[0] + d[0] * t / dn, o[1] + d[1] * t / dn];
                    let world: Vec<Pt> = self.core.iter().map(|&p| self.map(p)).collect();
                    let extent = self.core.iter().map(|&p| norm(p)).fold(0.0, f64::max);
                    let near = 1024.0 * EPS * (norm(o) + norm(self.t) + extent + t);
                    let n = world.len();
                    (0..n).fold(cos, |least, i| {
                        let (a, b) = (world[i], world[(i + 1) % n]);
                        let e = [b[0] - a[0], b[1] - a[1]];
                        let along = (dot([hit[0] - a[0], hit[1] - a[1]], e) / dot(e, e)).clamp(0.0, 1.0);
                        let foot = [a[0] + e[0] * along, a[1] + e[1] * along];
                        if norm([hit[0] - foot[0], hit[1] - foot[1]]) <= near {
                            least.min((e[1] * d[0] - e[0] * d[1]).abs() / (norm(e) * dn))
                        } else {
                            least
                        }
                    })
                }
                /// The exact hit: distance and incidence `|n . d|`, or why not.
                fn exact(&self, o: Pt, d: Pt) -> Result<(f64, f64), RayStatus> {
                    let dn = norm(d);
                    if let Some(exact) = &self.exact {
                        let answer = oracle_ray(o, d, 0.0, exact);
                        return match answer.status {
                            RayStatus::Hit => Ok((answer.t, self.incidence(o, d, answer.t, dot(answer.normal, d).abs() / dn))),
                            other => Err(other),
                        };
                    }
                    // The ellipse mapped by M, t: its points M y + T with y on
                    // the local ellipse, so M^T (x - T) / k is on it (k = c^2 + s^2):
                    // the ellipse of semi-axes k a, k b met by M^T (o - T) + t M^T d.
                    let qv = |x: f64| q_from_f64(x);
                    let (c, s) = (qv(self.cs.0), qv(self.cs.1));
                    let k = &c * &c + &s * &s;
                    let pull = |p: [Q; 2]| [&c * &p[0] + &s * &p[1], &c * &p[1] - &s * &p[0]];
                    let rel = pull([qv(o[0]) - qv(self.t[0]), qv(o[1]) - qv(self.t[1])]);
                    let dir = pull([qv(d[0]), qv(d[1])]);
                    let (a, b) = (&k * qv(self.axes[0]), &k * qv(self.axes[1]));
                    let inside = {
                        let (x, y) = (&rel[0] / &a, &rel[1] / &b);
                        &x * &x + &y * &y <= Q::from_integer(1.into())
                    };
                    if inside {
                        return Err(RayStatus::Inside);
                    }
                    let t = ellipse_ray(&a, &b, &rel, &dir).ok_or(RayStatus::Miss)?;
                    // The normal at the hit, from the local gradient.
                    let hit = [o[0] + d[0] * t, o[1] + d[1] * t];
                    let y = self.pull([hit[0] - self.t[0], hit[1] - self.t[1]]);
                    let [ea, eb] = self.axes;
                    let (c, s) = self.cs;
                    let g = [y[0] / (ea * ea), y[1] / (eb * eb)];
                    let n = [c * g[0] - s * g[1], s * g[0] + c * g[1]];
                    Ok((t * dn, dot(n, d).abs() / (norm(n) * dn)))
                }
            }

            /// One ray at one case: checks it and adds it to the figures.
            fn check(case: &Case, o: Pt, target: Pt, grazing: bool, stats: &mut Stats) {
                let Ok(ray) = Ray::new(v(o), v(target) - v(o)) else { return };
                let (o, d) = (pt(ray.origin()), pt(ray.direction()));
                let cast = Gjk::<R>::new().raycast(&ray, 0.0, &*case.shape, &case.tf);
                let l = (case.shape.bounding_radius() as f64).max(norm([o[0] - case.center()[0], o[1] - case.center()[1]]));
                let what = || {
                    format!(
                        "{:?} (axes {:?}, core {:?}, radius {}) at {:?} cos/sin {:?}, ray {o:?} -> {d:?}",
                        case.kind,
                        case.axes,
                        &case.core[..case.core.len().min(3)],
                        case.radius,
                        case.t,
                        case.cs
                    )
                };
                if cast.status != Status::Converged {
                    stats.iteration_limits += 1;
                }
                match (case.exact(o, d), cast.outcome) {
                    (Ok((t, cos)), RayOutcome::Hit(h)) => {
                        stats.hits += 1;
                        stats.grazing_hits += grazing as u32;
                        let err = (h.distance as f64 - t).abs();
                        let bound = h.error_bound as f64;
                        if cast.status.is_converged() && !(err <= bound && bound.is_finite()) {
                            stats.failures.push(format!("{}: {h:?}, exact {t} (cos {cos:e}): error {err:e} > bound", what()));
                        }
                        stats.ratio = stats.ratio.max(err / bound);
                        stats.error = stats.error.max(err / l);
                        // Geometry far from its local origin keeps the
                        // figures where it is placed error-free.
                        if cos >= 0.5 && (case.offset == 0.0 || cfg!(feature = "far-geometry")) {
                            stats.head_on_error = stats.head_on_error.max(err / l);
                            stats.head_on_bound = stats.head_on_bound.max(bound / l);
                        }
                    }
                    (Ok((t, _)), other) if cast.status.is_converged() => {
                        // Only a line within rounding of the tangent may miss.
                        let depth = case.depth(o, d);
                        let rounded = if cfg!(feature = "far-geometry") { 0.0 } else { case.offset };
                        if depth > 32.0 * EPS * (l + rounded) {
                            stats.failures.push(format!("{}: {other:?}, exact hit at {t} (line {:e} L deep)", what(), depth / l));
                        }
                    }
                    _ => {}
                }
            }

            /// Random rays from 1.5 to 4 sizes away, aimed at a point inside.
            fn random_rays(kind: Kind, seed: u64) -> Stats {
                let mut rng = Rng(seed);
                let mut stats = Stats::default();
                let mut shape = None;
                for k in 0..cases(CASES) {
                    if k % RAYS_PER_SHAPE == 0 {
                        shape = Case::new(kind, &mut rng);
                    }
                    let Some(case) = &shape else { continue };
                    let size = case.shape.bounding_radius() as f64;
                    let c = case.center();
                    let far = size * rng.range(1.5, 4.0);
                    let u = unit(rng.range(0.0, TAU));
                    let o = [c[0] + u[0] * far, c[1] + u[1] * far];
                    // A point between the centre and the boundary, in a random direction.
                    let n = unit(rng.range(0.0, TAU));
                    let (_, p) = case.support(n);
                    let w = rng.range(0.0, 0.99);
                    let target = [c[0] + (p[0] - c[0]) * w, c[1] + (p[1] - c[1]) * w];
                    check(case, o, target, false, &mut stats);
                }
                stats
            }

            /// Rays parallel to a tangent, 1e-1 to 1e-7 of the size inside it
            /// (hits) or outside (misses).
            fn grazing_rays(kind: Kind, seed: u64) -> Stats {
                let mut rng = Rng(seed);
                let mut stats = Stats::default();
                let mut shape = None;
                for k in 0..cases(CASES) {
                    if k % RAYS_PER_SHAPE == 0 {
                        shape = Case::new(kind, &mut rng);
                    }
                    let Some(case) = &shape else { continue };
                    let size = case.shape.bounding_radius() as f64;
                    let angle = rng.range(0.0, TAU);
                    let (u, n) = (unit(angle), unit(angle + TAU / 4.0));
                    let (_, p) = case.support(n);
                    let sign = if rng.unit() < 0.75 { 1.0 } else { -1.0 };
                    let off = sign * size * 10f64.powf(-rng.range(1.0, 7.0));
                    let back = size * rng.range(1.5, 4.0);
                    let o = [p[0] - n[0] * off - u[0] * back, p[1] - n[1] * off - u[1] * back];
                    let target = [o[0] + u[0] * back, o[1] + u[1] * back];
                    check(case, o, target, true, &mut stats);
                }
                stats
            }

            fn run(kind: Kind, seed: u64) {
                let mut report = Vec::new();
                let mut failures = Vec::new();
                for (family, stats) in [("random", random_rays(kind, seed)), ("grazing", grazing_rays(kind, seed ^ 0x5eed))] {
                    report.push(format!(
                        "{} {kind:?} {family}: {} hits ({} grazing), {} at the limit; error/bound <= {:.3}; error <= {:.2e} L \
                         ({:.2} eps L); head-on (cos >= 0.5) error <= {:.2} eps L, bound <= {:.2} eps L",
                        stringify!($r),
                        stats.hits,
                        stats.grazing_hits,
                        stats.iteration_limits,
                        stats.ratio,
                        stats.error,
                        stats.error / EPS,
                        stats.head_on_error / EPS,
                        stats.head_on_bound / EPS,
                    ));
                    // docs/accuracy.md's figures for head-on hits: the error
                    // within the guarantee, the bound within 128 eps L more
                    // than it allows for the iteration (its rounding terms,
                    // each at most 2 L, over cos >= 0.5); 256 on polygons,
                    // whose hits near a vertex also bound an entry through
                    // the face beyond it.
                    let (curved, error_allowed) = if kind == Kind::Ellipse { (CURVED, CURVED) } else { (0.0, 8.0 * EPS) };
                    let polygon = matches!(kind, Kind::Gon8 | Kind::Gon64);
                    let bound_allowed = curved + if polygon { 256.0 } else { 128.0 } * EPS;
                    if !(stats.head_on_bound <= bound_allowed && stats.head_on_error <= error_allowed) {
                        failures.push(format!(
                            "{kind:?} {family}: head-on error {:e} L (allowed {error_allowed:e} L), bound {:e} L (allowed {bound_allowed:e} L)",
                            stats.head_on_error, stats.head_on_bound
                        ));
                    }
                    failures.extend(stats.failures.into_iter().take(5));
                }
                for line in &report {
                    eprintln!("{line}");
                }
                assert!(failures.is_empty(), "{} failures:\n{}", failures.len(), failures.join("\n"));
            }

            #[test]
            fn ellipses() {
                run(Kind::Ellipse, 0xe11);
            }
            #[test]
            fn circles() {
                run(Kind::Circle, 0xc1c);
            }
            #[test]
            fn octagons() {
                run(Kind::Gon8, 0x8);
            }
            #[test]
            fn polygons_of_64() {
                run(Kind::Gon64, 0x64);
            }
            #[test]
            fn capsules() {
                run(Kind::Capsule, 0xca5);
            }
        }
    };
}

ray_bounds_suite!(f32_suite, f32, Vec2);
ray_bounds_suite!(f64_suite, f64, DVec2);
