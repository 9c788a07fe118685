//! The linear shape cast ([`Gjk::cast`]) against the exact rational oracle,
//! in f32 and f64 (one macro, one suite per precision).
//!
//! Exact answer: B moving by `m` first touches A where the ray from the
//! origin along `m` enters the Minkowski difference `A - B` (B at its
//! start). The difference of two cores is the convex hull of their vertices'
//! differences, computed here in rationals, swept by the sum of the radii;
//! the oracle's exact ray cast does the rest.
//!
//! Error model (as `tests/properties.rs`): `L` the larger bounding radius,
//! `t` the exact travelled distance, `eps` the precision's epsilon. Every
//! distance must be within `8 eps (L + t)` of the exact one, plus the
//! placement's rounding of transformed shapes (`4 eps (|t_B - t_A| + e_A +
//! e_B)`) and, where the ray grazes, the exact answer's own spread under a
//! shift of that size. A verdict (hit, miss, overlapping at the start) is
//! checked where it survives such a shift. Touching points must lie on both
//! boundaries (B's moved back by the distance travelled), the normal must
//! separate the shapes at the contact, and equal the exact unit normal where
//! that is unique.
//!
//! `cargo test --features std --test shape_cast -- --nocapture` prints each
//! family's worst distance error in units of `eps (L + t)`.

use gjk2d::glam::{DVec2, Vec2};
use gjk2d::*;
use gjk2d_oracle::exact::{q_to_f64, Q};
use gjk2d_oracle::{pair, ray as oracle_ray, transform_shape, ExactShape, RayAnswer, RayStatus};
use proptest::prelude::*;
use std::f64::consts::TAU;

#[path = "common/geo.rs"]
mod geo;
#[macro_use]
#[path = "common/placed.rs"]
mod placed;
#[path = "common/rng.rs"]
mod rng;
use geo::{norm, sub, Geo, Pt};
use rng::{cases, Rng};

/// Exact convex hull (monotone chain) of rational points: strictly convex,
/// counter-clockwise; one or two points where it degenerates.
fn rational_hull(mut p: Vec<[Q; 2]>) -> Vec<[Q; 2]> {
    p.sort();
    p.dedup();
    if p.len() < 3 {
        return p;
    }
    let zero = Q::from_integer(0.into());
    let cross =
        |o: &[Q; 2], a: &[Q; 2], b: &[Q; 2]| (&a[0] - &o[0]) * (&b[1] - &o[1]) - (&a[1] - &o[1]) * (&b[0] - &o[0]);
    let mut h: Vec<[Q; 2]> = Vec::new();
    for pass in 0..2 {
        let start = h.len();
        let order: Vec<&[Q; 2]> = if pass == 0 { p.iter().collect() } else { p.iter().rev().collect() };
        for q in order {
            while h.len() >= start + 2 && cross(&h[h.len() - 2], &h[h.len() - 1], q) <= zero {
                h.pop();
            }
            h.push(q.clone());
        }
        h.pop();
    }
    h
}

/// The exact Minkowski difference `A - B` of two exact shapes. Of large
/// polygons, only the vertex pairs next to a support pair along an edge's
/// normal (found in floats, one neighbour either side for their rounding):
/// every vertex of the difference is the support pair along a direction
/// bounded by such normals.
fn difference(a: &ExactShape, b: &ExactShape) -> ExactShape {
    let (va, vb) = (a.core_vertices(), b.core_vertices());
    let mut pairs: Vec<(usize, usize)> = Vec::new();
    if va.len() * vb.len() <= 256 {
        pairs = (0..va.len()).flat_map(|i| (0..vb.len()).map(move |j| (i, j))).collect();
    } else {
        let f = |v: &[[Q; 2]]| v.iter().map(|p| [q_to_f64(&p[0]), q_to_f64(&p[1])]).collect::<Vec<Pt>>();
        let (fa, fb) = (f(va), f(vb));
        let best = |v: &[Pt], d: Pt| {
            (0..v.len())
                .max_by(|&i, &j| (v[i][0] * d[0] + v[i][1] * d[1]).total_cmp(&(v[j][0] * d[0] + v[j][1] * d[1])))
                .unwrap()
        };
        let edge_normals = |v: &[Pt]| {
            (0..v.len()).map(|i| sub(v[(i + 1) % v.len()], v[i])).map(|e| [e[1], -e[0]]).collect::<Vec<Pt>>()
        };
        for d in edge_normals(&fa).into_iter().chain(edge_normals(&fb)) {
            let (i, j) = (best(&fa, d), best(&fb, [-d[0], -d[1]]));
            for di in [va.len() - 1, 0, 1] {
                for dj in [vb.len() - 1, 0, 1] {
                    pairs.push(((i + di) % va.len(), (j + dj) % vb.len()));
                }
            }
        }
    }
    let pts = pairs.iter().map(|&(i, j)| [&va[i][0] - &vb[j][0], &va[i][1] - &vb[j][1]]).collect();
    ExactShape::from_core(rational_hull(pts), a.radius() + b.radius())
}

/// The exact cast of B (at its placement shifted by `shift`) moving by `m`
/// (not zero) against A, given their difference `A - B`: distances along
/// `m`, in length units.
fn exact_cast(difference: &ExactShape, m: Pt, shift: Pt) -> RayAnswer {
    oracle_ray(shift, m, norm(m), difference)
}

/// The worst error of a family, in units of `eps (L + t)`.
#[derive(Default)]
struct Worst {
    distance: f64,
    normal: f64,
    hits: usize,
    misses: usize,
    starts: usize,
    /// The most support evaluations a hit or miss took.
    iterations: u32,
}

fn r32(x: f64) -> f64 {
    x as f32 as f64
}

/// `n` points on a rotated ellipse at sorted angles at least 0.05 apart,
/// around the origin, rounded to f32.
fn ellipse_polygon(rng: &mut Rng, n: usize, a: f64, b: f64) -> Vec<Pt> {
    let phase = rng.range(0.0, TAU);
    let mut angles: Vec<f64> = (0..n).map(|i| phase + TAU * (i as f64 + rng.range(0.0, 0.6)) / n as f64).collect();
    angles.sort_by(|x, y| x.partial_cmp(y).unwrap());
    angles.iter().map(|t| [r32(a * t.cos()), r32(b * t.sin())]).collect()
}

/// A random shape of a family, of size about `s`, around the origin.
fn family_shape(rng: &mut Rng, family: &str, s: f64) -> Geo {
    let (a, b) = (s * rng.range(0.3, 1.0), s * rng.range(0.05, 1.0));
    match family {
        "polygon" => {
            let n = 3 + (rng.next() % 6) as usize;
            Geo::Poly(ellipse_polygon(rng, n, a, b))
        }
        "rectangle" => {
            let (w, h) = (r32(2.0 * a), r32(2.0 * b));
            Geo::Poly(vec![[-w / 2.0, -h / 2.0], [w / 2.0, -h / 2.0], [w / 2.0, h / 2.0], [-w / 2.0, h / 2.0]])
        }
        "triangle" => Geo::Poly(ellipse_polygon(rng, 3, a, b)),
        "circle" => Geo::Circle([0.0, 0.0], r32(a)),
        "capsule" => Geo::Capsule([r32(-a), 0.0], [r32(a), 0.0], r32(0.5 * b)),
        "rounded" => {
            let n = 3 + (rng.next() % 6) as usize;
            Geo::Rounded(ellipse_polygon(rng, n, 0.7 * a, 0.7 * b), r32(0.3 * b))
        }
        _ => Geo::Segment([r32(-a), r32(-0.1 * b)], [r32(a), r32(0.1 * b)]),
    }
}

const FAMILIES: [&str; 7] = ["polygon", "rectangle", "triangle", "circle", "capsule", "segment", "rounded"];

fn config() -> ProptestConfig {
    let seed = std::env::var("PROPTEST_RNG_SEED").ok().and_then(|s| s.parse().ok()).unwrap_or(0x6361_7374);
    ProptestConfig {
        cases: cases(256),
        rng_seed: proptest::test_runner::RngSeed::Fixed(seed),
        ..ProptestConfig::default()
    }
}

macro_rules! cast_suite {
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

            /// The gjk2d shape of a description: rectangles and triangles
            /// through their own types, so their code paths are cast too.
            fn shape_of(g: &Geo) -> Option<Box<dyn SupportMap<R>>> {
                Some(match g {
                    Geo::Poly(p) if p.len() == 4 && p[0][0] == -p[2][0] && p[0][1] == p[1][1] && p[1][0] == p[2][0] => {
                        Box::new(Rectangle::new((p[1][0] - p[0][0]) as R, (p[2][1] - p[1][1]) as R).ok()?)
                    }
                    Geo::Poly(p) if p.len() == 3 => Box::new(Triangle::new(v(p[0]), v(p[1]), v(p[2])).ok()?),
                    Geo::Poly(p) => Box::new(Polygon::<R, 16>::new(&p.iter().map(|&q| v(q)).collect::<Vec<_>>()).ok()?),
                    Geo::Circle(c, r) => Box::new(Circle::at(v(*c), *r as R).ok()?),
                    Geo::Capsule(a, b, r) => Box::new(Capsule::new(v(*a), v(*b), *r as R).ok()?),
                    Geo::Segment(a, b) => Box::new(Segment::new(v(*a), v(*b)).ok()?),
                    Geo::Rounded(p, r) => Box::new(Rounded::new(Polygon::<R, 16>::new(&p.iter().map(|&q| v(q)).collect::<Vec<_>>()).ok()?, *r as R).ok()?),
                })
            }

            placed_shape!();

            fn placed(geo: Geo, t: Pt, angle: f64) -> Option<Placed> {
                let shape = shape_of(&geo)?;
                let tf = Transform::new(v(t), angle as R).ok()?;
                Some(Placed::from_parts(geo, shape, tf))
            }

            /// Every check of one cast of B moving by `m` against A; the
            /// distance error in units of `eps (L + t)` and the normal's
            /// error where checked.
            fn check(a: &Placed, b: &Placed, m: Pt, worst: &mut Worst) -> Result<(), String> {
                let m = pt(v(m));
                let gjk = Gjk::<R>::new();
                let motion = Motion::new(v(m)).map_err(|e| format!("motion {m:?}: {e}"))?;
                let cast = gjk.cast(&*a.shape, &a.tf, &*b.shape, &b.tf, &motion);
                if norm(m) == 0.0 {
                    // No motion: overlapping at the start, or a miss.
                    let apart = pair(&a.exact, &b.exact).signed_distance;
                    let bound = 8.0 * EPS * a.radius().max(b.radius()) + 4.0 * EPS * (norm(sub(b.t, a.t)) + a.geo.extent() + b.geo.extent());
                    let ok = match cast.outcome {
                        CastOutcome::Hit(_) => false,
                        CastOutcome::Miss => apart >= -bound,
                        CastOutcome::Start(start) => apart <= bound && !start.separating,
                    };
                    return if ok { Ok(()) } else { Err(format!("zero motion, {apart:e} apart: {cast:?}")) };
                }
                let diff = difference(&a.exact, &b.exact);
                let exact = exact_cast(&diff, m, [0.0, 0.0]);
                let l = a.radius().max(b.radius());
                let t_far = if exact.t.is_finite() { exact.t } else { norm(m) };
                let placement = 4.0 * EPS * (norm(sub(b.t, a.t)) + a.geo.extent() + b.geo.extent());
                let unit = EPS * (l + t_far);
                let bound = 8.0 * unit + placement;
                let ctx = || {
                    format!(
                        "A {} at {:?}, B {} at {:?}, motion {m:?}: {cast:?}; exact {exact:?}; bound {bound:e}",
                        a.geo.describe(),
                        a.tf,
                        b.geo.describe(),
                        b.tf
                    )
                };
                if !matches!(cast.outcome, CastOutcome::Start(_)) {
                    worst.iterations = worst.iterations.max(cast.iterations);
                }
                if !cast.status.is_converged() {
                    return Err(format!("not converged: {}", ctx()));
                }
                // The verdict counts where it survives moving B by the bound.
                let d = m.iter().map(|x| x / norm(m).max(f64::MIN_POSITIVE)).collect::<Vec<_>>();
                let shifts = [[-d[1] * bound, d[0] * bound], [d[1] * bound, -d[0] * bound], [d[0] * bound, d[1] * bound], [-d[0] * bound, -d[1] * bound]];
                let perturbed: Vec<RayAnswer> = if norm(m) > 0.0 { shifts.iter().map(|&s| exact_cast(&diff, m, s)).collect() } else { vec![] };
                let robust = exact.margin > bound && perturbed.iter().all(|p| p.status == exact.status);
                let got = match cast.outcome {
                    CastOutcome::Hit(_) => RayStatus::Hit,
                    CastOutcome::Miss => RayStatus::Miss,
                    CastOutcome::Start(_) => RayStatus::Inside,
                };
                if robust && got != exact.status {
                    return Err(format!("verdict {got:?}: {}", ctx()));
                }
                match cast.outcome {
                    CastOutcome::Miss => worst.misses += 1,
                    CastOutcome::Start(start) => {
                        worst.starts += 1;
                        let apart = pair(&a.exact, &b.exact).signed_distance;
                        if apart > bound {
                            return Err(format!("start, but {apart:e} apart: {}", ctx()));
                        }
                        let n = pt(start.penetration.normal);
                        if (norm(n) - 1.0).abs() > 4.0 * EPS || start.separating != (n[0] * m[0] + n[1] * m[1] > 0.0) {
                            return Err(format!("start's normal or separating: {}", ctx()));
                        }
                    }
                    CastOutcome::Hit(h) => {
                        worst.hits += 1;
                        let (s, n, pa, pb) = (h.distance as f64, pt(h.normal), pt(h.point_a), pt(h.point_b));
                        let fraction = h.fraction as f64;
                        if !(s.is_finite() && s >= 0.0 && (0.0..=1.0).contains(&fraction)) {
                            return Err(format!("distance or fraction: {}", ctx()));
                        }
                        if (fraction * norm(m) - s).abs() > 4.0 * EPS * s {
                            return Err(format!("fraction {fraction:e} against distance {s:e}: {}", ctx()));
                        }
                        if (norm(n) - 1.0).abs() > 4.0 * EPS {
                            return Err(format!("normal not unit: {}", ctx()));
                        }
                        if exact.status == RayStatus::Hit {
                            let spread = perturbed.iter().filter(|q| q.status == RayStatus::Hit).map(|q| (q.t - exact.t).abs()).fold(0.0, f64::max);
                            let err = (s - exact.t).abs();
                            if err > bound + 1.5 * spread {
                                return Err(format!("distance {s:e} vs exact {:e} (error {err:e}, spread {spread:e}): {}", exact.t, ctx()));
                            }
                            if spread <= bound {
                                worst.distance = worst.distance.max(err / unit);
                            }
                            if h.error_bound as f64 + 1.5 * spread < err - 4.0 * unit {
                                return Err(format!("error bound {:e} below the error {err:e}: {}", h.error_bound, ctx()));
                            }
                        }
                        // Both points on their boundaries, B's moved back to its start.
                        let slack = bound + 4.0 * EPS * (norm(pa) + norm(pb) + s);
                        let on_a = pair(&ExactShape::point(pa), &a.exact).signed_distance;
                        let back = [pb[0] - m[0] * fraction, pb[1] - m[1] * fraction];
                        let on_b = pair(&ExactShape::point(back), &b.exact).signed_distance;
                        if on_a.abs() > slack || on_b.abs() > slack + 4.0 * EPS * s {
                            return Err(format!("points off the boundaries ({on_a:e}, {on_b:e}): {}", ctx()));
                        }
                        if norm(sub(pa, pb)) > 2.0 * slack {
                            return Err(format!("points apart: {}", ctx()));
                        }
                        // The normal separates A from B moved to the contact.
                        let moved = [m[0] * fraction, m[1] * fraction];
                        let plane = n[0] * pa[0] + n[1] * pa[1];
                        let beyond_a = a.support(n) - plane;
                        let beyond_b = b.support([-n[0], -n[1]]) - (n[0] * moved[0] + n[1] * moved[1]) + plane;
                        let tol = slack + 8.0 * EPS64 * (a.reach() + b.reach() + s);
                        if beyond_a > tol || beyond_b > tol {
                            return Err(format!("normal does not separate ({beyond_a:e}, {beyond_b:e}): {}", ctx()));
                        }
                        // The features the hit names hold its touching
                        // points: a vertex is the point less the radius
                        // along the normal, an edge (out by the radius)
                        // passes through it; B's at its start.
                        let features = gjk.cast_features(&*a.shape, &a.tf, &*b.shape, &b.tf, &h);
                        for (side, point, sign, feature) in [(a, pa, 1.0, features.a), (b, back, -1.0, features.b)] {
                            let core = side.geo.core();
                            let c = [point[0] - sign * side.geo.radius() * n[0], point[1] - sign * side.geo.radius() * n[1]];
                            let at = |i: usize| side.map(core[i % core.len()]);
                            let off = match feature {
                                Feature::Vertex(i) => norm(sub(c, at(i as usize))),
                                Feature::Edge(i) => {
                                    let (p, q) = (at(i as usize), at(i as usize + 1));
                                    let (e, w) = (sub(q, p), sub(c, p));
                                    let u = ((w[0] * e[0] + w[1] * e[1]) / (e[0] * e[0] + e[1] * e[1])).clamp(0.0, 1.0);
                                    norm([w[0] - u * e[0], w[1] - u * e[1]])
                                }
                                Feature::Curve => 0.0,
                            };
                            if off > 2.0 * slack + 1e-6 * side.geo.extent() {
                                return Err(format!("feature {feature:?} {off:e} from its touching point: {}", ctx()));
                            }
                        }
                        if exact.status == RayStatus::Hit && exact.normal_unique && robust {
                            let e = norm(sub(n, exact.normal));
                            worst.normal = worst.normal.max(e);
                            if e > 1e3 * bound / l + 1e3 * EPS {
                                return Err(format!("normal {n:?} vs exact {:?}: {}", exact.normal, ctx()));
                            }
                        }
                    }
                }
                Ok(())
            }

            /// A pair of a family's shapes of size about `s` at `at`, B
            /// heading for A (aimed within `aim` of its centre) by a motion
            /// reaching `reach` times the way there.
            fn random_case(rng: &mut Rng, fa: &str, fb: &str, s: f64, at: Pt, aim: f64, reach: f64) -> Option<(Placed, Placed, Pt)> {
                let ga = family_shape(rng, fa, s);
                let sb = s * rng.range(0.2, 2.0);
                let gb = family_shape(rng, fb, sb);
                let ta = [r32(at[0] + rng.range(-s, s)), r32(at[1] + rng.range(-s, s))];
                let heading = rng.range(0.0, TAU);
                // A quarter of the pairs start close enough to overlap.
                let far = s * if rng.unit() < 0.25 { rng.range(0.2, 1.5) } else { rng.range(2.0, 6.0) };
                let tb = [r32(ta[0] + far * heading.cos()), r32(ta[1] + far * heading.sin())];
                let a = placed(ga, ta, rng.range(-4.0, 4.0))?;
                let b = placed(gb, tb, rng.range(-4.0, 4.0))?;
                let side = rng.range(-aim, aim) * s;
                let target = [ta[0] - heading.sin() * side, ta[1] + heading.cos() * side];
                let m = [(target[0] - tb[0]) * reach, (target[1] - tb[1]) * reach];
                Some((a, b, m))
            }

            fn run_family(fa: &str, fb: &str, s: f64, at: Pt, n: u32, seed: u64) -> Worst {
                let mut rng = Rng(seed);
                let mut worst = Worst::default();
                let mut done = 0;
                while done < n {
                    let aim = if rng.unit() < 0.5 { 1.5 } else { 3.0 };
                    let reach = rng.range(0.3, 1.6);
                    let Some((a, b, m)) = random_case(&mut rng, fa, fb, s, at, aim, reach) else { continue };
                    done += 1;
                    if let Err(e) = check(&a, &b, m, &mut worst) {
                        panic!("{fa} vs {fb}, size {s:e} at {at:?}: {e}");
                    }
                }
                worst
            }

            /// Every family against every family, at unit size near the
            /// origin, far from it, and tiny and huge: the worst errors.
            #[test]
            fn families_against_the_oracle() {
                let placements: [(f64, Pt); 4] = [(1.0, [0.0, 0.0]), (1.0, [1e4, -1e4]), (1e-3, [0.0, 0.0]), (1e3, [3e3, 1e3])];
                let mut seed = 1u64;
                for fa in FAMILIES {
                    let mut line = format!("{:>6} {fa:>9}:", stringify!($modname));
                    let mut report = Worst::default();
                    for fb in FAMILIES {
                        for &(s, at) in &placements {
                            seed += 1;
                            let w = run_family(fa, fb, s, at, cases(10), seed);
                            report.distance = report.distance.max(w.distance);
                            report.normal = report.normal.max(w.normal);
                            report.hits += w.hits;
                            report.misses += w.misses;
                            report.starts += w.starts;
                            report.iterations = report.iterations.max(w.iterations);
                        }
                    }
                    line += &format!(
                        " worst distance error {:.2} eps (L + t), normal {:.1e}; {} hits, {} misses, {} starts; at most {} support evaluations",
                        report.distance, report.normal, report.hits, report.misses, report.starts, report.iterations
                    );
                    println!("{line}");
                }
            }

            fn world(geo: Geo) -> Placed {
                placed(geo, [0.0, 0.0], 0.0).expect("a valid shape")
            }
            fn at(geo: Geo, t: Pt, angle: f64) -> Placed {
                placed(geo, t, angle).expect("a valid shape")
            }
            fn cast(a: &Placed, b: &Placed, m: Pt) -> ShapeCast<R> {
                Gjk::<R>::new().cast(&*a.shape, &a.tf, &*b.shape, &b.tf, &Motion::new(v(m)).unwrap())
            }
            fn oracle_checked(a: &Placed, b: &Placed, m: Pt) {
                if let Err(e) = check(a, b, m, &mut Worst::default()) {
                    panic!("{e}");
                }
            }
            fn square(h: f64) -> Geo {
                Geo::Poly(vec![[-h, -h], [h, -h], [h, h], [-h, h]])
            }

            /// B resting on A's top face, its bottom face on it: sliding
            /// along is not separating, lifting off is, pushing in is not;
            /// one ulp above it, sliding along misses.
            #[test]
            fn parallel_faces_sliding_past_each_other() {
                let a = world(square(1.0));
                for (x, sideways) in [(0.0, 3.0), (1.5, -3.0), (-1.25, 0.5)] {
                    let b = at(square(0.5), [x, 1.5], 0.0);
                    for (m, separating) in [([sideways, 0.0], false), ([sideways, 1.0], true), ([sideways, -0.25], false)] {
                        match cast(&a, &b, m).outcome {
                            CastOutcome::Start(start) => {
                                assert_eq!(start.separating, separating, "{m:?}: {start:?}");
                                assert!(start.penetration.depth.abs() <= 4.0 * <R>::EPSILON, "{start:?}");
                                assert_eq!(pt(start.penetration.normal), [0.0, 1.0]);
                            }
                            other => panic!("touching at the start, got {other:?}"),
                        }
                        oracle_checked(&a, &b, m);
                    }
                    let above = (1.5 as R).next_up() as f64;
                    let b = at(square(0.5), [x, above], 0.0);
                    assert_eq!(cast(&a, &b, [sideways, 0.0]).outcome, CastOutcome::Miss);
                    // Coming down from just above: a contact at once, on the face.
                    let hit = *cast(&a, &b, [sideways, -1.0]).hit().expect("a hit");
                    assert!(hit.fraction as f64 <= 2.0 * (above - 1.5), "{hit:?}");
                    assert_eq!(pt(hit.normal), [0.0, 1.0]);
                    oracle_checked(&a, &b, [sideways, -1.0]);
                }
            }

            /// B's faces grazing A's vertices and faces along the motion,
            /// exactly and a rounding error inside or outside.
            #[test]
            fn grazing_motion() {
                let a = world(square(1.0));
                for dy in [0.0, 1e-7, -1e-7, 1e-3, -1e-3] {
                    for (geo, y) in [(square(0.5), 1.5), (Geo::Circle([0.0, 0.0], 0.5), 1.5), (Geo::Segment([-0.5, 0.0], [0.5, 0.0]), 1.0)] {
                        for angle in [0.0, 0.3] {
                            let b = at(geo.clone(), [-5.0, y + dy], angle);
                            oracle_checked(&a, &b, [10.0, 0.0]);
                            oracle_checked(&a, &b, [10.0, -1e-6]);
                            oracle_checked(&a, &b, [10.0, 1e-6]);
                        }
                    }
                }
                // Exactly along A's top face: the first contact is at B's corner.
                let b = at(square(0.5), [-5.0, 1.5], 0.0);
                let hit = *cast(&a, &b, [10.0, 0.0]).hit().expect("a grazing hit");
                assert!((hit.distance as f64 - 3.5).abs() <= 8.0 * EPS * 5.0, "{hit:?}");
            }

            /// A small circle and a thin segment or rectangle crossing a
            /// thin wall in one step, a thousand times their size.
            #[test]
            fn thin_shapes_at_high_speed() {
                let wall = world(Geo::Poly(vec![[-1e-3, -10.0], [1e-3, -10.0], [1e-3, 10.0], [-1e-3, 10.0]]));
                let mut rng = Rng(7);
                for _ in 0..200 {
                    let geo = match rng.next() % 3 {
                        0 => Geo::Circle([0.0, 0.0], r32(rng.range(1e-3, 1e-2))),
                        1 => Geo::Segment([0.0, r32(-rng.range(1e-3, 1.0))], [r32(rng.range(1e-4, 1e-3)), r32(rng.range(1e-3, 1.0))]),
                        _ => Geo::Poly(vec![[-1e-3, -1e-4], [1e-3, -1e-4], [1e-3, 1e-4], [-1e-3, 1e-4]]),
                    };
                    let b = at(geo, [r32(-rng.range(1.0, 500.0)), r32(rng.range(-5.0, 5.0))], rng.range(-4.0, 4.0));
                    let m = [r32(rng.range(1e3, 2e3)), r32(rng.range(-5.0, 5.0))];
                    let c = cast(&wall, &b, m);
                    assert!(c.hit().is_some(), "tunnelled: {c:?}");
                    oracle_checked(&wall, &b, m);
                }
            }

            /// Every family far from the origin and at tiny and huge scales.
            #[test]
            fn far_tiny_and_huge() {
                let far = if EPS > 1e-10 { 1e4 } else { 1e8 };
                for (s, at) in [(1.0, [far, far]), (1.0, [-far, 0.5 * far]), (1e-6, [0.0, 0.0]), (1e-6, [1e-3, 0.0]), (1e6, [0.0, 0.0]), (1e6, [1e7, -1e7])] {
                    for fa in FAMILIES {
                        for fb in FAMILIES {
                            let w = run_family(fa, fb, s, at, cases(4), (s.to_bits() ^ at[0].to_bits()) as u64);
                            assert!(w.distance <= 8.0, "{fa} {fb} {s} {at:?}: {}", w.distance);
                        }
                    }
                }
            }

            /// Overlapping at the start: the penetration, and whether the
            /// motion separates; no motion answers the same, or a miss.
            #[test]
            fn overlapping_at_the_start_and_zero_motion() {
                let a = world(square(1.0));
                let b = at(square(0.5), [1.25, 0.25], 0.0);
                for (m, separating) in [([1.0, 0.0], true), ([-1.0, 0.0], false), ([0.0, 1.0], false), ([0.0, 0.0], false), ([0.1, 5.0], true)] {
                    match cast(&a, &b, m).outcome {
                        CastOutcome::Start(start) => {
                            assert_eq!(start.separating, separating, "{m:?}");
                            assert!((start.penetration.depth as f64 - 0.25).abs() <= 8.0 * EPS);
                            assert_eq!(pt(start.penetration.normal), [1.0, 0.0]);
                        }
                        other => panic!("overlapping at the start, got {other:?}"),
                    }
                }
                let apart = at(square(0.5), [3.0, 0.0], 0.0);
                assert_eq!(cast(&a, &apart, [0.0, 0.0]).outcome, CastOutcome::Miss);
                assert_eq!(cast(&a, &apart, [1e-30, 0.0]).outcome, CastOutcome::Miss);
                let hit = *cast(&a, &apart, [-1.5, 0.0]).hit().expect("a hit");
                assert_eq!((hit.fraction, hit.distance, pt(hit.normal)), (1.0, 1.5, [1.0, 0.0]));
                assert_eq!(cast(&a, &apart, [-1.5, 0.0].map(|x: f64| (x as R).next_up() as f64)).outcome, CastOutcome::Miss);
            }

            /// Bad motions are typed errors, never a NaN in a cast.
            #[test]
            fn invalid_motions() {
                assert_eq!(Motion::<R>::new($vec::new(R::NAN, 0.0)), Err(Error::NonFinite));
                assert_eq!(Motion::<R>::new($vec::new(0.0, R::INFINITY)), Err(Error::NonFinite));
                assert_eq!(Motion::<R>::new($vec::new(R::MAX, 0.0)), Err(Error::OutOfRange));
                assert_eq!(Motion::<R>::relative($vec::new(R::NAN, 0.0), $vec::ZERO), Err(Error::NonFinite));
                let both = Motion::<R>::relative($vec::new(1.0, 2.0), $vec::new(-1.0, 2.5)).unwrap();
                assert_eq!(both.translation(), $vec::new(-2.0, 0.5));
                // The largest motion allowed, across a small pair: finite answers.
                let big = R::MAX_COORDINATE as f64;
                let a = world(square(1.0));
                let b = at(Geo::Circle([0.0, 0.0], 0.5), [-3.0, 0.25], 0.0);
                for m in [[big, 0.0], [big, big], [-big, big], [big, -1e-3]] {
                    let c = cast(&a, &b, m);
                    if let Some(h) = c.hit() {
                        assert!(h.distance.is_finite() && h.fraction.is_finite() && h.error_bound.is_finite(), "{c:?}");
                        assert!(pt(h.point_a)[0].is_finite() && pt(h.normal)[1].is_finite(), "{c:?}");
                    }
                }
            }

            /// Curved shapes (an ellipse, a half-ellipse or a slice against
            /// every kind): within the configured epsilon, as `tests/curved.rs`
            /// judges them, by the certified branch-and-bound oracle: at the
            /// reported contact the shapes touch, and no contact is missed at
            /// 64 fractions of the motion.
            #[test]
            fn curved_shapes_within_the_epsilon() {
                use gjk2d_oracle::curved::{curved_pair, Local, Placed as Curved};
                let mut rng = Rng(11);
                let eps_cfg = GjkConfig::<R>::default().raycast_epsilon() as f64;
                let (mut worst, mut most) = (0.0f64, 0);
                for i in 0..cases(900) {
                    let (w, h) = (r32(rng.range(0.2, 2.0)), r32(rng.range(0.02, 2.0)));
                    // A: an ellipse, a half-ellipse or a slice (of 1e-3 rad to pi).
                    let (curved, local_a, reach_a): (Box<dyn SupportMap<R>>, Local, f64) = match (i / 6) % 3 {
                        0 => (Box::new(Ellipse::<R>::new(w as R, h as R).unwrap()), Local::Ellipse { a: w / 2.0, b: h / 2.0 }, w.max(h) / 2.0),
                        1 => (Box::new(HalfEllipse::<R>::new(w as R, h as R).unwrap()), Local::HalfEllipse { a: w / 2.0, h }, (w / 2.0).max(h)),
                        _ => {
                            let theta = r32(rng.range(-3.0, 0.0).exp().min(1.0) * std::f64::consts::PI);
                            let slice = Slice::<R>::new(w as R, theta as R).unwrap();
                            // The end gjk2d computed: its support straight up
                            // (the slice spans at most pi, so that is an end).
                            let end = pt(slice.support(v([0.0, 1.0])));
                            (Box::new(slice), Local::Slice { radius: w, end }, w)
                        }
                    };
                    let ta = Transform::new(v([r32(rng.range(-2.0, 2.0)), r32(rng.range(-2.0, 2.0))]), rng.range(-4.0, 4.0) as R).unwrap();
                    let (geo, local): (Box<dyn SupportMap<R>>, Local) = match i % 6 {
                        0 => {
                            let r = r32(rng.range(0.05, 1.0));
                            (Box::new(Circle::new(r as R).unwrap()), Local::Circle { center: [0.0, 0.0], radius: r })
                        }
                        1 => {
                            let a = rng.range(0.2, 1.0);
                            let p = ellipse_polygon(&mut rng, 5, a, 0.5);
                            let Ok(poly) = Polygon::<R, 16>::new(&p.iter().map(|&q| v(q)).collect::<Vec<_>>()) else { continue };
                            (Box::new(poly), Local::Polygon(p))
                        }
                        2 => {
                            let (x, r) = (r32(rng.range(0.1, 1.0)), r32(rng.range(0.01, 0.5)));
                            (Box::new(Capsule::new(v([-x, 0.0]), v([x, 0.0]), r as R).unwrap()), Local::Capsule { a: [-x, 0.0], b: [x, 0.0], radius: r })
                        }
                        3 => {
                            let (w2, h2) = (r32(rng.range(0.1, 2.0)), r32(rng.range(0.05, 2.0)));
                            (Box::new(Ellipse::<R>::new(w2 as R, h2 as R).unwrap()), Local::Ellipse { a: w2 / 2.0, b: h2 / 2.0 })
                        }
                        4 => {
                            let (w2, h2) = (r32(rng.range(0.1, 2.0)), r32(rng.range(0.05, 2.0)));
                            (Box::new(HalfEllipse::<R>::new(w2 as R, h2 as R).unwrap()), Local::HalfEllipse { a: w2 / 2.0, h: h2 })
                        }
                        _ => {
                            let (r2, theta) = (r32(rng.range(0.1, 2.0)), r32(rng.range(-3.0, 0.0).exp() * std::f64::consts::PI));
                            let slice = Slice::<R>::new(r2 as R, theta as R).unwrap();
                            let end = pt(slice.support(v([0.0, 1.0])));
                            (Box::new(slice), Local::Slice { radius: r2, end })
                        }
                    };
                    let heading = rng.range(0.0, TAU);
                    let from = pt(ta.translation());
                    let tb = Transform::new(v([r32(from[0] + 6.0 * heading.cos()), r32(from[1] + 6.0 * heading.sin())]), rng.range(-4.0, 4.0) as R).unwrap();
                    let side = rng.range(-2.5, 2.5);
                    let start = pt(tb.translation());
                    let m = pt(v([(from[0] - heading.sin() * side - start[0]) * 1.2, (from[1] + heading.cos() * side - start[1]) * 1.2]));
                    let c = Gjk::<R>::new().cast(&*curved, &ta, &*geo, &tb, &Motion::new(v(m)).unwrap());
                    let pa = Curved::new(local_a.clone(), ta.cos() as f64, ta.sin() as f64, from);
                    let at_fraction = |f: f64| Curved::new(local.clone(), tb.cos() as f64, tb.sin() as f64, [start[0] + m[0] * f, start[1] + m[1] * f]);
                    let reach = pa.reach() + at_fraction(1.0).reach();
                    let l = reach_a.max(geo.bounding_radius() as f64);
                    let tol = 2.0 * eps_cfg * l + 8.0 * EPS * (l + norm(m) + reach);
                    let signed = |f: f64| curved_pair(&pa, &at_fraction(f), 1e-15 * reach);
                    let ctx = || format!("{local_a:?} at {ta:?}, B {local:?} at {tb:?} moving {m:?}: {c:?}");
                    assert!(c.status.is_converged(), "{}", ctx());
                    if !matches!(c.outcome, CastOutcome::Start(_)) {
                        most = most.max(c.iterations);
                    }
                    match c.outcome {
                        CastOutcome::Start(_) => assert!(signed(0.0).signed <= tol, "{}", ctx()),
                        CastOutcome::Miss => {
                            for k in 0..=64 {
                                let s = signed(k as f64 / 64.0);
                                assert!(s.signed > -tol, "missed a contact at {k}/64 ({:e}): {}", s.signed, ctx());
                            }
                        }
                        CastOutcome::Hit(hit) => {
                            let s = signed(hit.fraction as f64);
                            worst = worst.max(s.signed.abs() / l);
                            assert!(s.signed.abs() <= tol + s.error, "contact {:e} apart: {}", s.signed, ctx());
                            assert!(signed(0.0).signed > -tol, "{}", ctx());
                        }
                    }
                }
                println!("{:>6} curved: worst separation at the contact {worst:.1e} L; at most {most} support evaluations", stringify!($modname));
            }

            /// Shapes of types known when the program is compiled (where the
            /// overlap test at the start takes its shortcuts) cast as the
            /// same shapes through `dyn SupportMap` do.
            #[test]
            fn typed_and_dyn_shapes_agree() {
                let mut rng = Rng(5);
                let gjk = Gjk::<R>::new();
                for _ in 0..cases(400) {
                    let (pa, pb) = (ellipse_polygon(&mut rng, 6, 1.0, 0.6), ellipse_polygon(&mut rng, 5, 0.7, 0.4));
                    let poly = |p: &[Pt]| Polygon::<R, 8>::new(&p.iter().map(|&q| v(q)).collect::<Vec<_>>());
                    let (Ok(a), Ok(b)) = (poly(&pa), poly(&pb)) else { continue };
                    let ta = Transform::new(v([r32(rng.range(-1.0, 1.0)), 0.0]), rng.range(-3.0, 3.0) as R).unwrap();
                    let tb = Transform::new(v([r32(rng.range(2.0, 3.0)), r32(rng.range(-1.5, 1.5))]), rng.range(-3.0, 3.0) as R).unwrap();
                    let motion = Motion::new(v([r32(rng.range(-4.0, -1.0)), r32(rng.range(-1.0, 1.0))])).unwrap();
                    let typed = gjk.cast(&a, &ta, &b, &tb, &motion);
                    let dynamic = gjk.cast(&a as &dyn SupportMap<R>, &ta, &b as &dyn SupportMap<R>, &tb, &motion);
                    match (typed.outcome, dynamic.outcome) {
                        (CastOutcome::Hit(x), CastOutcome::Hit(y)) => assert_eq!(x, y),
                        (CastOutcome::Start(x), CastOutcome::Start(y)) => assert_eq!(x.separating, y.separating),
                        (x, y) => assert_eq!(x, y),
                    }
                }
            }

            /// Polygons of up to 160 vertices, against each other and against
            /// circles and capsules: the refinement ends within the iteration
            /// limit, as exact as for small ones.
            #[test]
            fn many_sided_polygons() {
                let mut rng = Rng(9);
                let mut worst = Worst::default();
                for i in 0..cases(16) {
                    let n = 40 + (rng.next() % 120) as usize;
                    let (flat, k) = (rng.range(0.3, 1.0), 20 + (rng.next() % 40) as usize);
                    let geo = Geo::Poly(ellipse_polygon(&mut rng, n, 1.0, flat));
                    let partner = match i % 3 {
                        0 => Geo::Poly(ellipse_polygon(&mut rng, k, 0.5, 0.4)),
                        1 => Geo::Circle([0.0, 0.0], 0.3),
                        _ => Geo::Capsule([-0.4, 0.0], [0.4, 0.0], 0.1),
                    };
                    let big = |g: &Geo| -> Option<Box<dyn SupportMap<R>>> {
                        match g {
                            Geo::Poly(p) => Some(Box::new(Polygon::<R, 1024>::new(&p.iter().map(|&q| v(q)).collect::<Vec<_>>()).ok()?)),
                            other => shape_of(other),
                        }
                    };
                    let (Some(sa), Some(sb)) = (big(&geo), big(&partner)) else { continue };
                    let heading = rng.range(0.0, TAU);
                    let tb = [r32(3.0 * heading.cos()), r32(3.0 * heading.sin())];
                    let a = Placed::from_parts(geo, sa, Transform::new(v([0.0, 0.0]), rng.range(-3.0, 3.0) as R).unwrap());
                    let b = Placed::from_parts(partner, sb, Transform::new(v(tb), rng.range(-3.0, 3.0) as R).unwrap());
                    let side = rng.range(-1.5, 1.5);
                    let m = [(-heading.sin() * side - tb[0]) * 1.3, (heading.cos() * side - tb[1]) * 1.3];
                    if let Err(e) = check(&a, &b, m, &mut worst) {
                        panic!("{e}");
                    }
                }
                assert!(worst.distance <= 8.0 && worst.hits > 0, "{} over {} hits", worst.distance, worst.hits);
            }

            /// A shape of any kind (curved and rounded too) of size `s`.
            fn any_shape(kind: usize, s: f64, rng: &mut Rng) -> Option<Box<dyn SupportMap<R>>> {
                let (a, b) = ((s * rng.range(0.2, 1.0)) as R, (s * rng.range(0.01, 1.0)) as R);
                Some(match kind {
                    0 => Box::new(Ellipse::new(a, b).ok()?),
                    1 => Box::new(HalfEllipse::new(a, b).ok()?),
                    2 => Box::new(Slice::new(a, rng.range(1e-6, 3.1) as R).ok()?),
                    3 => Box::new(Rounded::new(Rectangle::new(a, b).ok()?, (s * 0.1) as R).ok()?),
                    4 => Box::new(Circle::new(a).ok()?),
                    5 => Box::new(Capsule::new(v([0.0, 0.0]), v([a as f64, b as f64]), b).ok()?),
                    6 => Box::new(Segment::new(v([0.0, 0.0]), v([a as f64, b as f64])).ok()?),
                    _ => Box::new(Polygon::<R, 16>::new(&ellipse_polygon(rng, 7, a as f64, b as f64).iter().map(|&q| v(q)).collect::<Vec<_>>()).ok()?),
                })
            }

            proptest! {
                #![proptest_config(config())]
                /// Wild inputs (every kind of shape, sizes from 1e-6 to 1e6,
                /// far placements, motions from 1e-30 to 1e12 long, along the
                /// axes or not): the cast ends within its iteration limit with
                /// finite answers in range, never a panic or NaN.
                #[test]
                fn wild_inputs_give_finite_answers(ka in 0usize..8, kb in 0usize..8, seed in any::<u64>(), scale in -6.0f64..6.0, place in -6.0f64..6.0, length in -30.0f64..12.0, axis in any::<bool>()) {
                    let mut rng = Rng(seed);
                    let s = 10f64.powf(scale);
                    let (Some(a), Some(b)) = (any_shape(ka, s, &mut rng), any_shape(kb, s * rng.range(0.1, 10.0), &mut rng)) else { return Ok(()) };
                    let far = 10f64.powf(place);
                    let ta = Transform::new(v([far, -far]), rng.range(-4.0, 4.0) as R).unwrap();
                    let tb = Transform::new(v([far + rng.range(-3.0, 3.0) * s, -far + rng.range(-3.0, 3.0) * s]), rng.range(-4.0, 4.0) as R).unwrap();
                    let heading = if axis { (rng.next() % 4) as f64 * TAU / 4.0 } else { rng.range(0.0, TAU) };
                    let len = 10f64.powf(length);
                    let Ok(motion) = Motion::new(v([len * heading.cos(), len * heading.sin()])) else { return Ok(()) };
                    let gjk = Gjk::<R>::new();
                    let c = gjk.cast(&*a, &ta, &*b, &tb, &motion);
                    prop_assert!(c.iterations <= gjk.config.max_raycast_iterations() + 1 || matches!(c.outcome, CastOutcome::Start(_)), "{c:?}");
                    match c.outcome {
                        CastOutcome::Hit(h) => {
                            let finite = [h.distance, h.fraction, h.error_bound, h.normal.x, h.normal.y, h.point_a.x, h.point_a.y, h.point_b.x, h.point_b.y].iter().all(|x| x.is_finite());
                            prop_assert!(finite && (0.0..=1.0).contains(&h.fraction) && h.distance >= 0.0 && h.error_bound >= 0.0, "{c:?}");
                            prop_assert!((h.normal.length() - 1.0).abs() < 1e-3, "{c:?}");
                        }
                        CastOutcome::Start(start) => prop_assert!(start.penetration.depth.is_finite() && start.penetration.normal.is_finite(), "{c:?}"),
                        CastOutcome::Miss => {}
                    }
                }
            }

            proptest! {
                #![proptest_config(config())]
                #[test]
                fn random_casts(fa in 0usize..FAMILIES.len(), fb in 0usize..FAMILIES.len(), seed in any::<u64>(), scale in -3.0f64..3.0, far in prop_oneof![Just(0.0), 1.0f64..1e4], aim in 0.0f64..3.0, reach in 0.0f64..2.0) {
                    let mut rng = Rng(seed);
                    let s = 2f64.powf(scale);
                    let at = [far, -0.5 * far];
                    if let Some((a, b, m)) = random_case(&mut rng, FAMILIES[fa], FAMILIES[fb], s, at, aim, reach) {
                        let mut worst = Worst::default();
                        let result = check(&a, &b, m, &mut worst);
                        prop_assert!(result.is_ok(), "{}", result.unwrap_err());
                    }
                }
            }
        }
    };
}

cast_suite!(single, f32, Vec2);
cast_suite!(double, f64, DVec2);

/// A chord from a curve point to a vertex is no face of the cores'
/// difference, though the support along its normal is that vertex: a circle
/// cast at a half-ellipse's dome beside its corner (the cast stopped 0.036
/// past the first contact), and at a slice's arc beside its end (it ran to
/// its iteration limit). Judged by the certified curved oracle: at the
/// reported fraction the shapes touch.
#[test]
fn curve_point_beside_a_vertex_is_no_face() {
    use gjk2d_oracle::curved::{curved_pair, Local, Placed as Curved};
    let half = HalfEllipse::<f64>::new(2.0 * 0.5622016191482544, 1.4074671268463135).unwrap();
    let slice = Slice::<f64>::new(0.9364948868751526, 2.0 * 0.15194948764435703f64.atan2(0.9240855081365157)).unwrap();
    let end = slice.support(DVec2::Y);
    let slice_end = [end.x, end.y];
    // A, its oracle, A's and B's placements (x, y, cos, sin), B's motion
    // and B's radius.
    type Case<'s> = (&'s dyn SupportMap<f64>, Local, [f64; 4], [f64; 4], [f64; 2], f64);
    let cases: [Case; 2] = [
        (
            &half,
            Local::HalfEllipse { a: 0.5622016191482544, h: 1.4074671268463135 },
            [-0.05714494362473488, -0.18534518778324127, 0.3994933357188446, 0.9167360987308346],
            [-3.907733201980591, -4.786754608154297, 0.3023763650018677, 0.9531886140152206],
            [4.546893192433294, 5.583459848797024],
            0.8042811155319214,
        ),
        (
            &slice,
            Local::Slice { radius: 0.9364948868751526, end: slice_end },
            [-0.8660104274749756, -1.7392363548278809, -0.9632151728121908, -0.26873133584377806],
            [-4.853647232055664, -6.222399711608887, 0.9289209810729546, 0.370278018416513],
            [3.233527798374004, 6.759929277517651],
            0.9551822543144226,
        ),
    ];
    for (shape, local, pa, pb, m, radius) in cases {
        let circle = Circle::<f64>::new(radius).unwrap();
        let ta = Transform::from_cos_sin(DVec2::new(pa[0], pa[1]), pa[2], pa[3]).unwrap();
        let tb = Transform::from_cos_sin(DVec2::new(pb[0], pb[1]), pb[2], pb[3]).unwrap();
        let c = Gjk::<f64>::new().cast(shape, &ta, &circle, &tb, &Motion::new(DVec2::new(m[0], m[1])).unwrap());
        assert!(c.status.is_converged(), "{c:?}");
        let CastOutcome::Hit(hit) = c.outcome else { panic!("expected a hit: {local:?} {c:?}") };
        let a = Curved::new(local, ta.cos(), ta.sin(), [pa[0], pa[1]]);
        let f = hit.fraction;
        let b = Curved::new(
            Local::Circle { center: [0.0, 0.0], radius },
            tb.cos(),
            tb.sin(),
            [pb[0] + m[0] * f, pb[1] + m[1] * f],
        );
        let s = curved_pair(&a, &b, 1e-15);
        let tol = 1e-10 * (a.reach() + b.reach());
        assert!(s.signed.abs() <= tol + s.error, "{:e} apart at the reported contact: {c:?}", s.signed);
        assert!(hit.error_bound < 1e-10, "{c:?}");
    }
}
