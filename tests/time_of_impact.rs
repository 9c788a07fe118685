//! Time of impact with rotation ([`Gjk::time_of_impact`]) against the exact
//! rational oracle, in f32 and f64 (one macro, one suite per precision).
//!
//! The shapes are placed at a time by the sweeps' own placements
//! ([`Sweep::transform_at`]), and the oracle measures the exact distance of
//! those placed shapes. The key property: the reported time is never after
//! the first contact with the target, and the shapes there are within the
//! tolerance above it. Checked by the exact distance at the reported time
//! (at least the target, at most target plus tolerance when converged) and
//! at many times before it (never below the target), and for misses over
//! the whole step. "Below" allows rounding: `16 eps` times the pair's
//! size and placement.
//!
//! `cargo test --features std --test time_of_impact -- --nocapture` prints
//! each family's worst margins and iterations.

use gjk2d::glam::{DVec2, Vec2};
use gjk2d::*;
use gjk2d_oracle::curved::{curved_pair, Local, Placed};
use gjk2d_oracle::{pair, transform_shape};

#[path = "common/geo.rs"]
mod geo;
#[path = "common/rng.rs"]
mod rng;
use geo::{norm, Geo, Pt};
use rng::{cases, Rng};

/// A random convex shape of about size `s` around the origin, its numbers
/// rounded by `round` (to the suite's precision).
fn random_shape(rng: &mut Rng, s: f64, round: fn(f64) -> f64) -> Geo {
    let (a, b) = (s * rng.range(0.3, 1.0), s * rng.range(0.05, 1.0));
    match rng.next() % 4 {
        0 | 1 => {
            let n = 3 + (rng.next() % 6) as usize;
            let phase = rng.range(0.0, std::f64::consts::TAU);
            let mut angles: Vec<f64> =
                (0..n).map(|i| phase + std::f64::consts::TAU * (i as f64 + rng.range(0.0, 0.6)) / n as f64).collect();
            angles.sort_by(f64::total_cmp);
            Geo::Poly(angles.iter().map(|t| [round(a * t.cos()), round(b * t.sin())]).collect())
        }
        2 => Geo::Circle([0.0, 0.0], round(a)),
        _ => Geo::Capsule([round(-a), 0.0], [round(a), 0.0], round(0.5 * b)),
    }
}

/// The worst margins of a family.
#[derive(Debug, Default)]
struct Worst {
    /// Least exact distance at or before a reported time (or over a miss's
    /// step), minus the target, in units of the allowed rounding.
    below_target: f64,
    /// Largest exact distance at a converged hit above target plus
    /// tolerance, in units of the allowed rounding.
    above_band: f64,
    hits: usize,
    misses: usize,
    starts: usize,
    limits: usize,
    iterations: u32,
}

macro_rules! toi_suite {
    ($modname:ident, $r:ty, $vec:ident) => {
        mod $modname {
            use super::*;
            type R = $r;
            const EPS: f64 = <$r>::EPSILON as f64;

            fn round(x: f64) -> f64 {
                x as R as f64
            }
            fn v(p: Pt) -> $vec {
                $vec::new(p[0] as R, p[1] as R)
            }
            fn pt(p: $vec) -> Pt {
                [p.x as f64, p.y as f64]
            }

            fn shape_of(g: &Geo) -> Box<dyn SupportMap<R>> {
                match g {
                    Geo::Poly(p) => Box::new(Polygon::<R, 16>::new(&p.iter().map(|&q| v(q)).collect::<Vec<_>>()).unwrap()),
                    Geo::Circle(c, r) => Box::new(Circle::at(v(*c), *r as R).unwrap()),
                    Geo::Capsule(a, b, r) => Box::new(Capsule::new(v(*a), v(*b), *r as R).unwrap()),
                    Geo::Segment(a, b) => Box::new(Segment::new(v(*a), v(*b)).unwrap()),
                    Geo::Rounded(p, r) => Box::new(Rounded::new(Polygon::<R, 16>::new(&p.iter().map(|&q| v(q)).collect::<Vec<_>>()).unwrap(), *r as R).unwrap()),
                }
            }

            /// The exact distance (minus the depth when overlapping) of the
            /// shapes placed by the sweeps at `t`.
            fn exact(ga: &Geo, sa: &Sweep<R>, gb: &Geo, sb: &Sweep<R>, t: R) -> f64 {
                let place = |g: &Geo, s: &Sweep<R>| {
                    let tf = s.transform_at(t);
                    let p = pt(tf.translation());
                    transform_shape(&g.oracle(), tf.cos() as f64, tf.sin() as f64, p[0], p[1])
                };
                pair(&place(ga, sa), &place(gb, sb)).signed_distance
            }

            /// The rounding allowed at the checks: the pair's size and the
            /// placements' magnitude over the step.
            fn slack(ga: &Geo, sa: &Sweep<R>, gb: &Geo, sb: &Sweep<R>) -> f64 {
                let size = ga.extent().max(gb.extent());
                let far = |s: &Sweep<R>| {
                    let (p, q) = (pt(s.transform_at(0.0).translation()), pt(s.transform_at(1.0).translation()));
                    norm(p).max(norm(q))
                };
                16.0 * EPS * (size + far(sa) + far(sb) + norm(pt(sa.linear())) + norm(pt(sb.linear())))
            }

            /// The features a hit names hold its closest points: a vertex's
            /// core point is the closest point less the radius along the
            /// normal, and an edge (moved out by the radius) passes through it.
            fn check_features(ga: &Geo, sa: &Sweep<R>, gb: &Geo, sb: &Sweep<R>, hit: &Impact<R>, slack: f64, ctx: &dyn Fn() -> String) {
                let n = pt(hit.normal);
                let sides = [(ga, sa, pt(hit.point_a), 1.0, hit.features.a), (gb, sb, pt(hit.point_b), -1.0, hit.features.b)];
                for (g, s, closest, sign, feature) in sides {
                    let (core, tf) = (g.core(), s.transform_at(hit.time));
                    // The closest point moved back onto the core.
                    let c = [closest[0] - sign * g.radius() * n[0], closest[1] - sign * g.radius() * n[1]];
                    let at = |i: usize| pt(tf.transform_point(v(core[i % core.len()])));
                    let tol = slack + 1e-6 * g.extent();
                    match feature {
                        Feature::Vertex(i) => {
                            let d = norm(geo::sub(c, at(i as usize)));
                            assert!(d <= tol, "vertex {i} {d} from the closest point: {}", ctx());
                        }
                        Feature::Edge(i) => {
                            let (p, q) = (at(i as usize), at(i as usize + 1));
                            let (e, w) = (geo::sub(q, p), geo::sub(c, p));
                            let u = ((w[0] * e[0] + w[1] * e[1]) / (e[0] * e[0] + e[1] * e[1])).clamp(0.0, 1.0);
                            let d = norm([w[0] - u * e[0], w[1] - u * e[1]]);
                            assert!(d <= tol, "edge {i} {d} from the closest point: {}", ctx());
                        }
                        Feature::Curve => {}
                    }
                }
            }

            /// Runs one case and checks it against the oracle; `samples`
            /// times before the reported time (or over a miss's step).
            #[allow(clippy::too_many_arguments)]
            fn check(
                ga: &Geo,
                sa: &Sweep<R>,
                gb: &Geo,
                sb: &Sweep<R>,
                config: &ImpactConfig<R>,
                samples: u32,
                worst: &mut Worst,
                what: &str,
            ) -> TimeOfImpact<R> {
                let gjk = Gjk::<R>::new();
                let (a, b) = (shape_of(ga), shape_of(gb));
                let toi = gjk.time_of_impact(&*a, sa, &*b, sb, config);
                let (target, tol) = (config.target() as f64, config.tolerance() as f64);
                let slack = slack(ga, sa, gb, sb);
                let ctx = || format!("{what}: {ga:?} {sa:?} / {gb:?} {sb:?} target {target} tol {tol}: {toi:?}");
                worst.iterations = worst.iterations.max(toi.iterations);
                let floor = |t: R, worst: &mut Worst| {
                    let d = exact(ga, sa, gb, sb, t);
                    let below = (target - d) / slack;
                    worst.below_target = worst.below_target.max(below);
                    assert!(d >= target - slack, "distance {d} at time {t} before the reported one: {}", ctx());
                };
                let before = |end: R, k: u32| end * (k as R / samples as R);
                match toi.outcome {
                    ImpactOutcome::Hit(hit) => {
                        assert!((0.0..=1.0).contains(&hit.time), "{}", ctx());
                        assert!(hit.separation.is_finite() && hit.normal.is_finite(), "{}", ctx());
                        assert!((hit.normal.length() - 1.0).abs() < 1e-3, "{}", ctx());
                        let d = exact(ga, sa, gb, sb, hit.time);
                        assert!((d - hit.separation as f64).abs() <= slack + 1e-4 * d.abs(), "separation {d}: {}", ctx());
                        floor(hit.time, worst);
                        // Densest just before the time, where a late answer would show.
                        for k in 0..samples {
                            floor(before(hit.time, k), worst);
                            floor(hit.time * (1.0 - (k as R + 1.0) * 1e-3), worst);
                        }
                        check_features(ga, sa, gb, sb, &hit, slack, &ctx);
                        if toi.status.is_converged() {
                            worst.hits += 1;
                            let above = (d - target - tol) / slack;
                            worst.above_band = worst.above_band.max(above);
                            assert!(d <= target + tol + slack, "distance {d} above the band: {}", ctx());
                        } else {
                            worst.limits += 1;
                        }
                    }
                    ImpactOutcome::Miss => {
                        worst.misses += 1;
                        for k in 0..=samples {
                            floor(before(1.0, k), worst);
                        }
                    }
                    ImpactOutcome::Start(start) => {
                        worst.starts += 1;
                        let d = exact(ga, sa, gb, sb, 0.0);
                        assert!(d < target + slack, "start at distance {d}: {}", ctx());
                        assert!((d - start.separation as f64).abs() <= slack + 1e-3 * (1.0 + d.abs()), "{}", ctx());
                    }
                }
                toi
            }

            fn random_sweep(rng: &mut Rng, at: Pt, reach: f64, spin: f64) -> Sweep<R> {
                let start = Transform::new(v(at), rng.range(-3.0, 3.0) as R).unwrap();
                let center = v([rng.range(-0.5, 0.5), rng.range(-0.5, 0.5)]);
                let m = v([rng.range(-reach, reach), rng.range(-reach, reach)]);
                let angle = if rng.next() % 4 == 0 { 0.0 } else { rng.range(-spin, spin) };
                Sweep::new(&start, center, m, angle as R).unwrap()
            }

            /// Random pairs, translating and turning towards and past each
            /// other, at a scale and offset.
            fn family(seed: u64, scale: f64, offset: f64, spin: f64) -> Worst {
                let mut rng = Rng(seed);
                let mut worst = Worst::default();
                for _ in 0..cases(60) {
                    let ga = random_shape(&mut rng, scale, round);
                    let gb = random_shape(&mut rng, scale, round);
                    let o = [offset, -offset];
                    let sa = random_sweep(&mut rng, o, 2.0 * scale, spin);
                    let b_at = [o[0] + scale * rng.range(-5.0, 5.0), o[1] + scale * rng.range(-5.0, 5.0)];
                    // B heading at A's start, give or take.
                    let towards = [o[0] - b_at[0] + scale * rng.range(-2.0, 2.0), o[1] - b_at[1] + scale * rng.range(-2.0, 2.0)];
                    let mut sb = random_sweep(&mut rng, b_at, 0.0, spin);
                    sb = Sweep::new(&sb.start(), v([0.0, 0.0]), v(towards), sb.angle()).unwrap();
                    let target = if rng.next() % 3 == 0 { 0.0 } else { scale * rng.range(0.0, 0.05) };
                    let config = ImpactConfig::new(round(target) as R, (scale * 1e-3) as R).unwrap();
                    check(&ga, &sa, &gb, &sb, &config, 32, &mut worst, "family");
                }
                println!("{} scale {scale} offset {offset} spin {spin}: {worst:?}", stringify!($modname));
                worst
            }

            #[test]
            fn unit_scale() {
                let w = family(1, 1.0, 0.0, 3.0);
                assert!(w.hits > 10 && w.misses > 5, "{w:?}");
            }

            #[test]
            fn fast_spin() {
                let w = family(2, 1.0, 0.0, 40.0);
                assert!(w.hits + w.limits > 10, "{w:?}");
            }

            #[test]
            fn tiny_and_huge() {
                family(3, 1e-4, 0.0, 3.0);
                family(4, 1e4, 0.0, 3.0);
            }

            #[test]
            fn far_from_origin() {
                let offset = if EPS > 1e-10 { 1e4 } else { 1e10 };
                family(5, 1.0, offset, 3.0);
            }

            fn plank() -> Geo {
                Geo::Poly(vec![[-2.0, -0.05], [2.0, -0.05], [2.0, 0.05], [-2.0, 0.05]])
            }
            fn wall() -> Geo {
                Geo::Poly(vec![[-0.005, -5.0], [0.005, -5.0], [0.005, 5.0], [-0.005, 5.0]])
            }
            fn square() -> Geo {
                Geo::Poly(vec![[-1.0, -1.0], [1.0, -1.0], [1.0, 1.0], [-1.0, 1.0]])
            }
            fn fixed(at: Pt) -> Sweep<R> {
                Sweep::still(&Transform::from_translation(v(at)).unwrap())
            }

            /// A thin bullet at high speed through a thin wall: a hit, never
            /// a miss, however far it gets in one step.
            #[test]
            fn no_tunnelling() {
                let mut worst = Worst::default();
                let bullet = Geo::Poly(vec![[-0.01, -0.01], [0.01, -0.01], [0.01, 0.01], [-0.01, 0.01]]);
                for (speed, spin) in [(1e3, 0.0), (1e4, 0.0), (1e3, 50.0), (100.0, 1e3)] {
                    let start = Transform::new(v([-10.0, 0.3]), 0.3).unwrap();
                    let s = Sweep::new(&start, v([0.0, 0.0]), v([speed, 0.0]), spin).unwrap();
                    let config = ImpactConfig::new(0.001, 0.0005).unwrap();
                    let toi = check(&wall(), &fixed([0.0, 0.0]), &bullet, &s, &config, 64, &mut worst, "bullet");
                    assert!(toi.hit().is_some(), "tunnelled at {speed}, spin {spin}: {toi:?}");
                }
                println!("{}: {worst:?}", stringify!($modname));
            }

            /// Pure rotation: a plank turning about its centre next to a
            /// wall hits it with its end; turning the other way from
            /// farther off, it never reaches.
            #[test]
            fn pure_rotation() {
                let mut worst = Worst::default();
                let config = ImpactConfig::new(0.01, 0.001).unwrap();
                let upright = std::f64::consts::FRAC_PI_2 as R;
                let start = Transform::new(v([-1.5, 0.0]), upright).unwrap();
                let turn = Sweep::new(&start, v([0.0, 0.0]), v([0.0, 0.0]), -2.0).unwrap();
                let toi = check(&wall(), &fixed([0.0, 0.0]), &plank(), &turn, &config, 128, &mut worst, "rotation");
                assert!(toi.hit().is_some(), "{toi:?}");
                let away = Transform::new(v([-2.5, 0.0]), upright).unwrap();
                let turn = Sweep::new(&away, v([0.0, 0.0]), v([0.0, 0.0]), 6.0).unwrap();
                let toi = check(&wall(), &fixed([0.0, 0.0]), &plank(), &turn, &config, 128, &mut worst, "rotation");
                assert_eq!(toi.outcome, ImpactOutcome::Miss, "{toi:?}");
                println!("{}: {worst:?}", stringify!($modname));
            }

            /// Passing a corner just above and just below the target.
            #[test]
            fn grazing() {
                let mut worst = Worst::default();
                let square = square();
                let config = ImpactConfig::new(0.01, 0.001).unwrap();
                for (gap, hits) in [(0.0125, false), (0.02, false), (0.0105, true), (0.005, true)] {
                    let start = Transform::from_translation(v([-4.0, 2.0 + gap])).unwrap();
                    let s = Sweep::new(&start, v([0.0, 0.0]), v([8.0, 0.0]), 0.0).unwrap();
                    let toi = check(&square, &fixed([0.0, 0.0]), &square, &s, &config, 128, &mut worst, "grazing");
                    assert_eq!(toi.hit().is_some(), hits, "gap {gap}: {toi:?}");
                }
                println!("{}: {worst:?}", stringify!($modname));
            }

            /// No motion: a miss apart, a start when closer than the target
            /// or overlapping.
            #[test]
            fn zero_motion_and_start() {
                let mut worst = Worst::default();
                let square = square();
                let config = ImpactConfig::new(0.01, 0.001).unwrap();
                let toi = check(&square, &fixed([0.0, 0.0]), &square, &fixed([3.0, 0.0]), &config, 8, &mut worst, "still");
                assert_eq!(toi.outcome, ImpactOutcome::Miss);
                // Moving away without turning: the gap never closes, one look.
                let away = Sweep::translation(&Transform::from_translation(v([3.0, 0.0])).unwrap(), v([5.0, 1.0])).unwrap();
                let toi = check(&square, &fixed([0.0, 0.0]), &square, &away, &config, 8, &mut worst, "away");
                assert_eq!((toi.outcome, toi.iterations), (ImpactOutcome::Miss, 1));
                let toi = check(&square, &fixed([0.0, 0.0]), &square, &fixed([2.005, 0.0]), &config, 8, &mut worst, "near");
                assert!(matches!(toi.outcome, ImpactOutcome::Start(s) if (s.separation - 0.005).abs() < 1e-5), "{toi:?}");
                let moving = Sweep::translation(&Transform::from_translation(v([1.5, 0.0])).unwrap(), v([5.0, 0.0])).unwrap();
                let toi = check(&square, &fixed([0.0, 0.0]), &square, &moving, &config, 8, &mut worst, "overlap");
                match toi.outcome {
                    ImpactOutcome::Start(s) => {
                        assert!((s.separation + 0.5).abs() < 1e-5, "{toi:?}");
                        assert!((pt(s.normal)[0] - 1.0).abs() < 1e-5, "{toi:?}");
                    }
                    other => panic!("{other:?}"),
                }
            }

            /// Pure translation agrees with the linear cast: the time is no
            /// later than the cast's, and short of it by no more than the
            /// tolerance along the normal.
            #[test]
            fn translation_agrees_with_the_linear_cast() {
                let mut rng = Rng(7);
                let gjk = Gjk::<R>::new();
                let (mut compared, mut worst_short) = (0, 0.0f64);
                for _ in 0..cases(200) {
                    let ga = random_shape(&mut rng, 1.0, round);
                    let gb = random_shape(&mut rng, 1.0, round);
                    let ta = Transform::new(v([0.0, 0.0]), rng.range(-3.0, 3.0) as R).unwrap();
                    let tb = Transform::new(v([rng.range(-5.0, 5.0), rng.range(-5.0, 5.0)]), rng.range(-3.0, 3.0) as R).unwrap();
                    let m = [-pt(tb.translation())[0] + rng.range(-2.0, 2.0), -pt(tb.translation())[1] + rng.range(-2.0, 2.0)];
                    let tol = 1e-3;
                    let config = ImpactConfig::new(0.0, tol as R).unwrap();
                    let (a, b) = (shape_of(&ga), shape_of(&gb));
                    let cast = gjk.cast(&*a, &ta, &*b, &tb, &Motion::new(v(m)).unwrap());
                    let sb = Sweep::translation(&tb, v(m)).unwrap();
                    let toi = gjk.time_of_impact(&*a, &Sweep::still(&ta), &*b, &sb, &config);
                    match (cast.outcome, toi.outcome) {
                        (CastOutcome::Hit(c), ImpactOutcome::Hit(h)) => {
                            assert!(toi.status.is_converged(), "{toi:?}");
                            let len = norm(m);
                            let cos = (pt(c.normal)[0] * m[0] + pt(c.normal)[1] * m[1]).abs() / len;
                            let short = (c.fraction - h.time) as f64 * len * cos;
                            let rounding = 64.0 * EPS * (len + 10.0) + c.error_bound as f64;
                            assert!(short >= -rounding, "toi after the cast: {cast:?} {toi:?}");
                            assert!(short <= tol + rounding, "toi short by {short}: {cast:?} {toi:?}");
                            worst_short = worst_short.max(short);
                            compared += 1;
                        }
                        (CastOutcome::Miss, ImpactOutcome::Miss) | (CastOutcome::Start(_), ImpactOutcome::Start(_)) => {}
                        // A cast that grazes within the tolerance.
                        (CastOutcome::Miss, ImpactOutcome::Hit(h)) => assert!(h.separation as f64 <= tol + 1e-4),
                        other => panic!("{other:?}"),
                    }
                }
                println!("{}: {compared} hits compared, shortest {worst_short}", stringify!($modname));
                assert!(compared > 50);
            }

            /// The features that touch at the hit: a corner on a face, two
            /// faces, a circle, a spinning plank's corner on a wall.
            #[test]
            fn features_at_the_hit() {
                let mut worst = Worst::default();
                let config = ImpactConfig::new(0.01, 0.001).unwrap();
                let diamond = Geo::Poly(vec![[0.0, -1.0], [1.0, 0.0], [0.0, 1.0], [-1.0, 0.0]]);
                let falling = |x: f64| {
                    let start = Transform::from_translation(v([x, 5.0])).unwrap();
                    Sweep::translation(&start, v([0.0, -6.0])).unwrap()
                };
                let cases = [
                    (diamond, FeatureId { a: Feature::Edge(2), b: Feature::Vertex(0) }),
                    (square(), FeatureId { a: Feature::Edge(2), b: Feature::Edge(0) }),
                    // A circle's core is one point: its vertex 0, as the manifold names it.
                    (Geo::Circle([0.0, 0.0], 0.5), FeatureId { a: Feature::Edge(2), b: Feature::Vertex(0) }),
                ];
                for (shape, features) in cases {
                    let toi = check(&square(), &fixed([0.0, 0.0]), &shape, &falling(0.25), &config, 16, &mut worst, "features");
                    assert_eq!(toi.hit().map(|h| h.features), Some(features), "{toi:?}");
                }
                let upright = std::f64::consts::FRAC_PI_2 as R;
                let start = Transform::new(v([-1.5, 0.0]), upright).unwrap();
                let turn = Sweep::new(&start, v([0.0, 0.0]), v([0.0, 0.0]), -2.0).unwrap();
                let toi = check(&wall(), &fixed([0.0, 0.0]), &plank(), &turn, &config, 16, &mut worst, "features");
                let hit = toi.hit().expect("a hit");
                // The wall's left face (from its vertex 3 down to 0, counter-clockwise
                // from 3), and one of the plank's corners.
                assert_eq!(hit.features.a, Feature::Edge(3), "{toi:?}");
                assert!(matches!(hit.features.b, Feature::Vertex(_)), "{toi:?}");
            }

            /// Ellipses turning and moving against each other, against the
            /// oracle's branch and bound for curved shapes: the same
            /// property, within its error and the distance query's
            /// relative epsilon on top of rounding.
            #[test]
            fn ellipses() {
                let mut rng = Rng(11);
                let gjk = Gjk::<R>::new();
                let (mut hits, mut misses, mut most) = (0, 0, 0);
                for _ in 0..cases(100) {
                    let (wa, ha, wb, hb) = (round(rng.range(0.5, 3.0)), round(rng.range(0.2, 2.0)), round(rng.range(0.5, 3.0)), round(rng.range(0.2, 2.0)));
                    let (a, b) = (Ellipse::<R>::new(wa as R, ha as R).unwrap(), Ellipse::<R>::new(wb as R, hb as R).unwrap());
                    let sa = random_sweep(&mut rng, [0.0, 0.0], 1.0, 3.0);
                    let at = [rng.range(-5.0, 5.0), rng.range(-5.0, 5.0)];
                    let towards = [-at[0] + rng.range(-2.0, 2.0), -at[1] + rng.range(-2.0, 2.0)];
                    let start = Transform::new(v(at), rng.range(-3.0, 3.0) as R).unwrap();
                    let sb = Sweep::new(&start, v([0.0, 0.0]), v(towards), rng.range(-3.0, 3.0) as R).unwrap();
                    let config = ImpactConfig::new(0.01, 1e-3).unwrap();
                    let toi = gjk.time_of_impact(&a, &sa, &b, &sb, &config);
                    most = most.max(toi.iterations);
                    // The exact distance at `t` lies within [lo, hi].
                    let exact = |t: R| {
                        let place = |w: f64, h: f64, s: &Sweep<R>| {
                            let tf = s.transform_at(t);
                            Placed::new(Local::Ellipse { a: 0.5 * w, b: 0.5 * h }, tf.cos() as f64, tf.sin() as f64, pt(tf.translation()))
                        };
                        let e = curved_pair(&place(wa, ha, &sa), &place(wb, hb, &sb), 1e-15);
                        (e.signed - e.error, e.signed + e.error)
                    };
                    let slack = 16.0 * EPS * 20.0;
                    let floor = |t: R| {
                        let (_, hi) = exact(t);
                        assert!(hi >= 0.01 - slack, "distance {hi} at {t}: {toi:?}");
                    };
                    match toi.outcome {
                        ImpactOutcome::Hit(h) => {
                            for k in 0..=32 {
                                floor(h.time * (k as R / 32.0));
                            }
                            if toi.status.is_converged() {
                                hits += 1;
                                let (lo, _) = exact(h.time);
                                assert!(lo <= 0.011 + slack, "distance {lo} above the band: {toi:?}");
                            }
                        }
                        ImpactOutcome::Miss => {
                            misses += 1;
                            for k in 0..=64 {
                                floor(k as R / 64.0);
                            }
                        }
                        ImpactOutcome::Start(_) => assert!(exact(0.0).0 < 0.01 + slack, "{toi:?}"),
                    }
                }
                println!("{} ellipses: {hits} hits, {misses} misses, at most {most} iterations", stringify!($modname));
                assert!(hits > 20 && misses > 10);
            }

            /// Every bad input is a typed error; a wild time is clamped.
            #[test]
            fn bad_input() {
                let t = Transform::<R>::IDENTITY;
                let z = $vec::ZERO;
                assert_eq!(Sweep::new(&t, z, z, R::NAN), Err(Error::NonFinite));
                assert_eq!(Sweep::new(&t, z, z, 1e6), Err(Error::AngleOutOfRange));
                assert_eq!(Sweep::new(&t, z, $vec::new(R::INFINITY, 0.0), 0.0), Err(Error::NonFinite));
                assert_eq!(Sweep::new(&t, $vec::new(R::NAN, 0.0), z, 0.0), Err(Error::NonFinite));
                assert_eq!(Sweep::new(&t, z, $vec::new(R::MAX_COORDINATE * 4.0, 0.0), 0.0), Err(Error::OutOfRange));
                assert_eq!(Sweep::translation(&t, $vec::new(0.0, R::NAN)), Err(Error::NonFinite));
                let big = Transform::<R>::from_translation($vec::new(R::MAX_COORDINATE, 0.0)).unwrap();
                assert_eq!(Sweep::translation(&big, $vec::new(R::MAX_COORDINATE, 0.0)), Err(Error::OutOfRange));
                assert_eq!(ImpactConfig::<R>::new(-1.0, 0.1), Err(Error::NonPositive));
                assert_eq!(ImpactConfig::<R>::new(R::NAN, 0.1), Err(Error::NonFinite));
                assert_eq!(ImpactConfig::<R>::new(0.0, 0.0), Err(Error::NonPositive));
                assert_eq!(ImpactConfig::<R>::new(0.0, R::INFINITY), Err(Error::NonFinite));
                let mut c = ImpactConfig::<R>::new(0.0, 0.1).unwrap();
                assert_eq!(c.set_max_iterations(2), Err(Error::TooFewIterations));
                assert_eq!(c.max_iterations(), 50);
                let s = Sweep::new(&t, z, $vec::new(1.0, 2.0), 1.0).unwrap();
                assert_eq!(s.transform_at(R::NAN), t);
                assert_eq!(s.transform_at(-5.0), t);
                assert_eq!(s.transform_at(7.0), s.transform_at(1.0));
            }

            /// A limit of 5 iterations on a slow approach stops early, at a
            /// safe time, with the status that says so.
            #[test]
            fn iteration_limit_is_conservative() {
                let mut worst = Worst::default();
                let square = square();
                let mut config = ImpactConfig::new(0.0, 1e-6).unwrap();
                config.set_max_iterations(5).unwrap();
                let start = Transform::from_translation(v([-4.0, 2.5])).unwrap();
                let s = Sweep::new(&start, v([0.0, 0.0]), v([8.0, -2.0]), 20.0).unwrap();
                let toi = check(&square, &fixed([0.0, 0.0]), &square, &s, &config, 64, &mut worst, "limit");
                assert_eq!(toi.status, Status::IterationLimit, "{toi:?}");
                assert_eq!(toi.iterations, 5);
            }
        }
    };
}

toi_suite!(single, f32, Vec2);
toi_suite!(double, f64, DVec2);
