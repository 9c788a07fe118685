//! The hot queries, gjk2d and parry2d side by side, timed as a physics step or a
//! game frame meets them: every pass asks each of 16,384 distinct pairs once, so
//! the branch predictor cannot learn the answers (a small batch repeated lets it,
//! and flatters branchy code by 2x or more).
//!
//! ```text
//! cargo bench --bench queries                 # every family, f32 and f64
//! cargo bench --bench queries -- poly8 ray    # families whose name contains a word
//! cargo bench --bench queries -- cast         # the linear casts against parry's cast_shapes
//! cargo bench --bench queries -- toi          # time of impact with rotation against cast_shapes_nonlinear
//! GJK2D_BENCH_PASSES=31 cargo bench --bench queries
//! cargo bench --bench queries -- warm        # warm-started queries against cold, step by step
//! cargo bench --bench queries -- warm penetration   # one warm-started query only
//! cargo bench --bench queries -- warm_poly64  # the same of 64-gons, whose cold queries iterate
//! ```
//!
//! The four contenders (gjk2d and parry2d, f32 and f64) take turns within every
//! pass, in a rotating order, so a change of machine load falls on all alike. The
//! table gives each one's median time per query over the passes and the median of
//! the per-pass ratios gjk2d / parry2d. Shapes are held in an enum and passed to
//! the generic queries (gjk2d) or as `dyn Shape` (parry), with identity
//! transforms held as data (as a scene's are, not constants to fold); inputs
//! are f32 values, so both precisions see the same geometry.

use gjk2d::{Capsule, Circle, Gjk, ImpactConfig, Motion, PairCache, Polygon, Ray, Real, Sweep, Transform};
use std::hint::black_box;
use std::time::Instant;

/// Distinct cases per family and pass.
const CASES: usize = 16_384;

struct Rng(u64);

impl Rng {
    fn f(&mut self) -> f64 {
        self.0 = self.0.wrapping_add(0x9E37_79B9_7F4A_7C15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        ((z ^ (z >> 31)) >> 11) as f64 / (1u64 << 53) as f64
    }
    fn range(&mut self, lo: f64, hi: f64) -> f64 {
        lo + (hi - lo) * self.f()
    }
}

/// Input shapes: f32 values held in f64.
#[derive(Clone)]
enum Sh {
    Poly(Vec<[f64; 2]>),
    Circle([f64; 2], f64),
    Capsule([f64; 2], [f64; 2], f64),
}

fn r32(x: f64) -> f64 {
    x as f32 as f64
}

/// `n` vertices on a random ellipse around `c` at evenly spread angles (so every
/// vertex is a corner in f32 too).
fn poly(rng: &mut Rng, n: usize, c: [f64; 2]) -> Sh {
    let (a, b, rot) = (rng.range(0.5, 1.0), rng.range(0.5, 1.0), rng.range(0.0, 6.3));
    let phase = rng.f();
    Sh::Poly(
        (0..n)
            .map(|i| {
                let t = (i as f64 + phase) / n as f64 * std::f64::consts::TAU;
                let (x, y) = (a * t.cos(), b * t.sin());
                [r32(c[0] + rot.cos() * x - rot.sin() * y), r32(c[1] + rot.sin() * x + rot.cos() * y)]
            })
            .collect(),
    )
}

fn circle(rng: &mut Rng, c: [f64; 2]) -> Sh {
    Sh::Circle([r32(c[0]), r32(c[1])], r32(rng.range(0.3, 1.0)))
}

fn capsule(rng: &mut Rng, c: [f64; 2]) -> Sh {
    let (h, t) = (rng.range(0.2, 0.8), rng.range(0.0, 6.3));
    let u = [h * t.cos(), h * t.sin()];
    Sh::Capsule([r32(c[0] - u[0]), r32(c[1] - u[1])], [r32(c[0] + u[0]), r32(c[1] + u[1])], r32(rng.range(0.1, 0.4)))
}

type Maker = dyn Fn(&mut Rng, [f64; 2]) -> Sh;

/// Pairs: A around the origin, B's center 0.4 to 1.6 of their size away (about
/// half of them overlap).
fn pairs(seed: u64, count: usize, mk_a: &Maker, mk_b: &Maker) -> Vec<(Sh, Sh)> {
    let mut rng = Rng(seed);
    (0..count)
        .map(|_| {
            let a = mk_a(&mut rng, [0.0, 0.0]);
            let (d, t) = (rng.range(0.4, 1.6), rng.range(0.0, 6.3));
            (a, mk_b(&mut rng, [d * t.cos(), d * t.sin()]))
        })
        .collect()
}

/// A ray's origin, direction and maximum length (0: unbounded), and its shape.
type RayCase = ([f64; 2], [f64; 2], f64, Sh);

/// The shape's centre and bounding radius.
fn bounds(s: &Sh) -> ([f64; 2], f64) {
    let dist = |p: [f64; 2], q: [f64; 2]| (p[0] - q[0]).hypot(p[1] - q[1]);
    match s {
        Sh::Poly(v) => {
            let n = v.len() as f64;
            let c = [v.iter().map(|p| p[0]).sum::<f64>() / n, v.iter().map(|p| p[1]).sum::<f64>() / n];
            (c, v.iter().map(|&p| dist(p, c)).fold(0.0, f64::max))
        }
        Sh::Circle(c, r) => (*c, *r),
        Sh::Capsule(a, b, r) => ([(a[0] + b[0]) / 2.0, (a[1] + b[1]) / 2.0], dist(*a, *b) / 2.0 + r),
    }
}

/// Rays as the report draws them: from outside (one in ten from inside),
/// aimed near the shape, half unbounded and half of a length around the
/// distance to the aim (so whether the hit lies within it is not
/// predictable either).
fn rays(seed: u64, count: usize, mk: &Maker) -> Vec<RayCase> {
    let mut rng = Rng(seed);
    let unit = |rng: &mut Rng| {
        let t = rng.range(0.0, std::f64::consts::TAU);
        [t.cos(), t.sin()]
    };
    (0..count)
        .map(|_| {
            let s = mk(&mut rng, [0.0, 0.0]);
            let (c, br) = bounds(&s);
            let inside = rng.f() < 0.1;
            let u = unit(&mut rng);
            let k = if inside { rng.range(0.0, 0.5) } else { rng.range(1.1, 3.0) };
            let o = [r32(c[0] + u[0] * br * k), r32(c[1] + u[1] * br * k)];
            let (u, k) = (unit(&mut rng), rng.range(0.0, 1.2));
            let aim = [c[0] + u[0] * br * k, c[1] + u[1] * br * k];
            let d = [r32(aim[0] - o[0]), r32(aim[1] - o[1])];
            let max = if rng.f() < 0.5 { 0.0 } else { r32(d[0].hypot(d[1]) * rng.range(0.5, 1.5)) };
            if d == [0.0, 0.0] {
                return ([r32(o[0] + 2.0 * br), o[1]], [-1.0, 0.0], 0.0, s);
            }
            (o, d, max, s)
        })
        .collect()
}

/// Linear casts: B's center 1 to 3 of their size from A's, moving by a
/// motion aimed within 1 of A's center that reaches 0.5 to 1.5 of the way
/// there (hits, misses, and a few pairs overlapping at the start).
type CastCase = (Sh, Sh, [f64; 2]);

fn casts(seed: u64, count: usize, mk_a: &Maker, mk_b: &Maker) -> Vec<CastCase> {
    let mut rng = Rng(seed);
    (0..count)
        .map(|_| {
            let a = mk_a(&mut rng, [0.0, 0.0]);
            let (d, t) = (rng.range(1.0, 3.0), rng.range(0.0, 6.3));
            let c = [d * t.cos(), d * t.sin()];
            let b = mk_b(&mut rng, c);
            let (aim, k) = ([rng.range(-1.0, 1.0), rng.range(-1.0, 1.0)], rng.range(0.5, 1.5));
            (a, b, [r32((aim[0] - c[0]) * k), r32((aim[1] - c[1]) * k)])
        })
        .collect()
}

/// Times of impact: a cast's pair and motion, B turning by up to half a
/// turn either way about its centre over the step (A stays).
type ToiCase = (Sh, Sh, [f64; 2], f64);

fn tois(seed: u64, count: usize, mk_a: &Maker, mk_b: &Maker) -> Vec<ToiCase> {
    let mut rng = Rng(seed ^ 0x746f69);
    casts(seed, count, mk_a, mk_b).into_iter().map(|(a, b, m)| (a, b, m, r32(rng.range(-3.1, 3.1)))).collect()
}

// --- gjk2d -----------------------------------------------------------------------

/// The polygon boxed, as parry's shapes are (`Box<dyn Shape>`): a scene's
/// enum of shapes then costs a circle its own size, not a polygon's.
enum G<R: Real, const N: usize> {
    P(Box<Polygon<R, N>>),
    C(Circle<R>),
    K(Capsule<R>),
}

fn g<R: Real, const N: usize>(s: &Sh) -> G<R, N> {
    let v = |p: &[f64; 2]| R::vector(R::from_f64(p[0]), R::from_f64(p[1]));
    match s {
        Sh::Poly(p) => G::P(Box::new(Polygon::new(&p.iter().map(v).collect::<Vec<_>>()).unwrap())),
        Sh::Circle(c, r) => G::C(Circle::at(v(c), R::from_f64(*r)).unwrap()),
        Sh::Capsule(a, b, r) => G::K(Capsule::new(v(a), v(b), R::from_f64(*r)).unwrap()),
    }
}

macro_rules! with_g {
    ($s:expr, |$x:ident| $body:expr) => {
        match $s {
            G::P(p) => {
                let $x = &**p;
                $body
            }
            G::C($x) => $body,
            G::K($x) => $body,
        }
    };
}

#[derive(Clone, Copy)]
enum Query {
    Intersect,
    Distance,
    Penetration,
    /// Contact points of touching and overlapping pairs (margin and
    /// parry's prediction 0), cold: no manifold of an earlier pass is kept.
    Manifold,
}

/// The three queries of every pair family.
const PAIR_QUERIES: [(Query, &str); 3] =
    [(Query::Intersect, "intersects"), (Query::Distance, "distance"), (Query::Penetration, "penetration")];

/// Every pair of `batch` asked `$body`, with `$x`, `$y` its two shapes (each
/// enum matched, as a scene's shapes are) and `$id` the transform as data (a
/// scene's are), not a constant the compiler folds.
macro_rules! g_each_pair {
    ($R:ty, $batch:expr, |$gjk:ident, $x:ident, $y:ident, $id:ident| $body:expr) => {{
        let $gjk = Gjk::<$R>::new();
        let identity = Transform::<$R>::IDENTITY;
        for (a, b) in $batch {
            let (a, b) = (black_box(a), black_box(b));
            let $id = black_box(&identity);
            with_g!(a, |$x| with_g!(b, |$y| $body));
        }
    }};
}

/// One loop a query kind, as a scene asks one kind of many pairs in turn:
/// the kind is not chosen again for every pair.
fn g_pairs<R: Real, const N: usize>(batch: &[(G<R, N>, G<R, N>)], q: Query) {
    match q {
        Query::Intersect => g_each_pair!(R, batch, |gjk, a, b, id| {
            black_box(gjk.intersects(a, id, b, id));
        }),
        Query::Distance => g_each_pair!(R, batch, |gjk, a, b, id| {
            black_box(gjk.distance(a, id, b, id));
        }),
        Query::Penetration => g_each_pair!(R, batch, |gjk, a, b, id| {
            black_box(gjk.penetration(a, id, b, id));
        }),
        Query::Manifold => g_each_pair!(R, batch, |gjk, a, b, id| {
            let _ = black_box(gjk.manifold(a, id, b, id, R::ZERO));
        }),
    }
}

fn g_rays<R: Real, const N: usize>(batch: &[(Ray<R>, R, G<R, N>)]) {
    let gjk = Gjk::<R>::new();
    let id = Transform::<R>::IDENTITY;
    for (ray, max, s) in batch {
        black_box(with_g!(black_box(s), |x| gjk.raycast(ray, *max, x, black_box(&id))));
    }
}

fn g_casts<R: Real, const N: usize>(batch: &[(G<R, N>, G<R, N>, Motion<R>)]) {
    let gjk = Gjk::<R>::new();
    let id = Transform::<R>::IDENTITY;
    for (a, b, m) in batch {
        let (a, b) = (black_box(a), black_box(b));
        black_box(with_g!(a, |x| with_g!(b, |y| gjk.cast(x, &id, y, &id, m))));
    }
}

/// B's sweep: its centre moving by the motion while it turns. A Box2D-like
/// target (a linear slop of 0.005 for shapes of size 1) and tolerance.
fn g_tois<R: Real, const N: usize>(batch: &[(G<R, N>, G<R, N>, Sweep<R>)]) {
    let gjk = Gjk::<R>::new();
    let still = Sweep::still(&Transform::<R>::IDENTITY);
    let config = ImpactConfig::new(R::from_f64(0.005), R::from_f64(0.00125)).unwrap();
    for (a, b, sweep) in batch {
        let (a, b) = (black_box(a), black_box(b));
        black_box(with_g!(a, |x| with_g!(b, |y| gjk.time_of_impact(x, black_box(&still), y, sweep, &config))));
    }
}

// --- parry -----------------------------------------------------------------------

macro_rules! parry_side {
    ($m:ident, $p:ident, $R:ty) => {
        mod $m {
            use super::{Query, Sh};
            use std::hint::black_box;
            use $p::math::{Pose, Vector};
            use $p::query::{
                self, ContactManifold, DefaultQueryDispatcher, NonlinearRigidMotion, PersistentQueryDispatcher, Ray,
                ShapeCastOptions,
            };
            use $p::shape::{Ball, Capsule, ConvexPolygon, Shape};

            pub struct PS(Box<dyn Shape>, Pose);

            fn v(p: &[f64; 2]) -> Vector {
                Vector::new(p[0] as $R, p[1] as $R)
            }

            pub fn build(s: &Sh) -> PS {
                match s {
                    Sh::Poly(p) => PS(
                        Box::new(ConvexPolygon::from_convex_polyline_unmodified(p.iter().map(v).collect()).unwrap()),
                        Pose::identity(),
                    ),
                    Sh::Circle(c, r) => PS(Box::new(Ball::new(*r as $R)), Pose::from_translation(v(c))),
                    Sh::Capsule(a, b, r) => PS(Box::new(Capsule::new(v(a), v(b), *r as $R)), Pose::identity()),
                }
            }

            pub fn ray(o: &[f64; 2], d: &[f64; 2], max: f64) -> (Ray, $R) {
                let d = v(d);
                (Ray::new(v(o), d / d.length()), if max > 0.0 { max as $R } else { <$R>::MAX })
            }

            /// One loop a query kind, as for gjk2d.
            pub fn pairs(batch: &[(PS, PS)], q: Query) {
                let each = || batch.iter().map(|(a, b)| (black_box(a), black_box(b)));
                match q {
                    Query::Intersect => {
                        for (a, b) in each() {
                            let _ = black_box(query::intersection_test(&a.1, &*a.0, &b.1, &*b.0));
                        }
                    }
                    Query::Distance => {
                        for (a, b) in each() {
                            let _ = black_box(query::distance(&a.1, &*a.0, &b.1, &*b.0));
                        }
                    }
                    Query::Penetration => {
                        for (a, b) in each() {
                            let _ = black_box(query::contact(&a.1, &*a.0, &b.1, &*b.0, 0.0));
                        }
                    }
                    Query::Manifold => {
                        // Cleared before each pair: every manifold is computed cold.
                        let mut manifolds: Vec<ContactManifold<(), ()>> = Vec::with_capacity(1);
                        for (a, b) in each() {
                            manifolds.clear();
                            let pos12 = a.1.inv_mul(&b.1);
                            let mut workspace = None;
                            let _ = black_box(DefaultQueryDispatcher.contact_manifolds(
                                &pos12,
                                &*a.0,
                                &*b.0,
                                0.0,
                                &mut manifolds,
                                &mut workspace,
                            ));
                            black_box(&manifolds);
                        }
                    }
                }
            }

            pub fn motion(m: &[f64; 2]) -> Vector {
                v(m)
            }

            /// B moving by its motion against A, fixed, up to the whole motion.
            pub fn casts(batch: &[(PS, PS, Vector)]) {
                for (a, b, m) in batch {
                    let (a, b) = (black_box(a), black_box(b));
                    let options = ShapeCastOptions::with_max_time_of_impact(1.0);
                    let _ = black_box(query::cast_shapes(&a.1, Vector::ZERO, &*a.0, &b.1, *m, &*b.0, options));
                }
            }

            /// The shape moving its world point `center` by `m` while turning
            /// by `angle` over the unit time; A stays.
            pub fn nonlinear(s: &PS, center: &[f64; 2], m: &[f64; 2], angle: f64) -> NonlinearRigidMotion {
                NonlinearRigidMotion::new(s.1, v(center) - s.1.translation, v(m), angle as $R)
            }

            pub fn still(s: &PS) -> NonlinearRigidMotion {
                NonlinearRigidMotion::constant_position(s.1)
            }

            /// B turning and moving against A over the whole step, stopping at
            /// a penetration at the start.
            pub fn tois(batch: &[(PS, PS, NonlinearRigidMotion, NonlinearRigidMotion)]) {
                for (a, b, ma, mb) in batch {
                    let (a, b) = (black_box(a), black_box(b));
                    let _ = black_box(query::cast_shapes_nonlinear(ma, &*a.0, mb, &*b.0, 0.0, 1.0, true));
                }
            }

            pub fn rays(batch: &[((Ray, $R), PS)]) {
                for ((ray, max), s) in batch {
                    let s = black_box(s);
                    black_box(s.0.cast_ray_and_get_normal(&s.1, ray, *max, true));
                }
            }
        }
    };
}

parry_side!(parry32, parry2d, f32);
parry_side!(parry64, parry2d_f64, f64);

// --- warm starting ---------------------------------------------------------------

/// A pair of polygons in motion, step by step: each shape (about 1 across,
/// its semi-axes 0.5 to 1) moves by at most 1% of that and turns by at most
/// 1 degree a step. Poses as (x, y, angle), in f64.
struct Moving {
    shapes: (Sh, Sh),
    poses: [[f64; 3]; 2],
}

fn moving_pairs(seed: u64, count: usize, vertices: usize) -> (Vec<Moving>, Rng) {
    let mut rng = Rng(seed);
    let pairs = (0..count)
        .map(|_| {
            let (a, b) = (poly(&mut rng, vertices, [0.0, 0.0]), poly(&mut rng, vertices, [0.0, 0.0]));
            let (d, t) = (rng.range(0.4, 1.6), rng.range(0.0, 6.3));
            let poses = [[0.0, 0.0, rng.range(0.0, 6.3)], [d * t.cos(), d * t.sin(), rng.range(0.0, 6.3)]];
            Moving { shapes: (a, b), poses }
        })
        .collect();
    (pairs, rng)
}

/// One step of every pair: a random move of at most 0.01 and turn of at
/// most 1 degree, each shape.
fn step(pairs: &mut [Moving], rng: &mut Rng) {
    for m in pairs {
        for p in &mut m.poses {
            let (r, t) = (0.01 * rng.f().sqrt(), rng.range(0.0, std::f64::consts::TAU));
            p[0] = r32(p[0] + r * t.cos());
            p[1] = r32(p[1] + r * t.sin());
            p[2] = r32(p[2] + rng.range(-1.0, 1.0).to_radians());
        }
    }
}

/// The shapes, their transforms this step, and the pair's cache.
struct Warm<R: Real, const N: usize> {
    a: Box<Polygon<R, N>>,
    b: Box<Polygon<R, N>>,
    ta: Transform<R>,
    tb: Transform<R>,
    cache: PairCache<R>,
}

fn warm_pairs<R: Real, const N: usize>(pairs: &[Moving]) -> Vec<Warm<R, N>> {
    let poly = |s: &Sh| match g::<R, N>(s) {
        G::P(p) => p,
        _ => unreachable!("polygons only"),
    };
    pairs
        .iter()
        .map(|m| Warm {
            a: poly(&m.shapes.0),
            b: poly(&m.shapes.1),
            ta: Transform::IDENTITY,
            tb: Transform::IDENTITY,
            cache: PairCache::default(),
        })
        .collect()
}

fn place<R: Real, const N: usize>(warm: &mut [Warm<R, N>], pairs: &[Moving]) {
    let t = |p: &[f64; 3]| Transform::new(R::vector(R::from_f64(p[0]), R::from_f64(p[1])), R::from_f64(p[2])).unwrap();
    for (w, m) in warm.iter_mut().zip(pairs) {
        (w.ta, w.tb) = (t(&m.poses[0]), t(&m.poses[1]));
    }
}

/// One query of every pair, cold or warm started from (and updating) its
/// cache: the sum of the iterations and the number of answers (an answer of
/// `None` has no iterations to count).
fn warm_pass<R: Real, const N: usize>(warm: &mut [Warm<R, N>], q: Query, cached: bool) -> (u64, u64) {
    let gjk = Gjk::<R>::new();
    let (mut iterations, mut answers) = (0u64, 0u64);
    for w in warm.iter_mut() {
        let w = black_box(w);
        let (a, b, ta, tb) = (&*w.a, &*w.b, &w.ta, &w.tb);
        let cache = &mut w.cache;
        let n = match (q, cached) {
            (Query::Intersect, false) => Some(black_box(gjk.intersects(a, ta, b, tb)).iterations),
            (Query::Intersect, true) => Some(black_box(gjk.intersects_cached(a, ta, b, tb, cache)).iterations),
            (Query::Distance, false) => black_box(gjk.distance(a, ta, b, tb)).map(|s| s.iterations),
            (Query::Distance, true) => black_box(gjk.distance_cached(a, ta, b, tb, cache)).map(|s| s.iterations),
            (Query::Penetration, false) => black_box(gjk.penetration(a, ta, b, tb)).map(|p| p.iterations),
            (Query::Penetration, true) => black_box(gjk.penetration_cached(a, ta, b, tb, cache)).map(|p| p.iterations),
            (Query::Manifold, false) => black_box(gjk.manifold(a, ta, b, tb, R::ZERO)).ok().map(|m| m.iterations),
            (Query::Manifold, true) => {
                black_box(gjk.manifold_cached(a, ta, b, tb, R::ZERO, cache)).ok().map(|m| m.iterations)
            }
        };
        if let Some(n) = n {
            iterations += u64::from(n);
            answers += 1;
        }
    }
    (iterations, answers)
}

/// The frame-to-frame family: every pass is one step of every pair (moved
/// untimed), each query timed cold and warm started, f32 and f64, every
/// pair once (as every family: too many for the branch predictor to learn). Rows: ns per query (median over
/// steps), cached / cold (median of per-step ratios), and the mean
/// iterations of each (an answer of `None` counts none).
fn warm_family<const N: usize>(name: &str, passes: usize, words: &[String]) {
    println!("\n{name}: {CASES} pairs of {N}-gons, each shape moved by at most 1% of its size and turned by at most 1 degree a step, {passes} steps after one untimed");
    println!("| query | cold f32 ns | cached f32 ns | cached/cold f32 | iterations cold/cached f32 | cold f64 ns | cached f64 ns | cached/cold f64 | iterations cold/cached f64 |");
    println!("|---|---:|---:|---:|---:|---:|---:|---:|---:|");
    let queries = [
        (Query::Intersect, "intersects"),
        (Query::Distance, "distance"),
        (Query::Penetration, "penetration"),
        (Query::Manifold, "manifold"),
    ];
    // A word that names a query keeps the rows to the queries named.
    let named = |qn: &str| words.iter().any(|w| w == qn);
    let some_named = queries.iter().any(|&(_, qn)| named(qn));
    for (q, qn) in queries {
        if some_named && !named(qn) {
            continue;
        }
        let (mut pairs, mut rng) = moving_pairs(21, CASES, N);
        let (mut w32, mut w64) = (warm_pairs::<f32, N>(&pairs), warm_pairs::<f64, N>(&pairs));
        // Per contender (cold f32, cached f32, cold f64, cached f64): times and iterations.
        let mut times = vec![Vec::new(); 4];
        let mut iterations = [(0u64, 0u64); 4];
        for pass in 0..=passes {
            step(&mut pairs, &mut rng);
            place(&mut w32, &pairs);
            place(&mut w64, &pairs);
            for j in 0..4 {
                let k = (pass + j) % 4;
                let t = Instant::now();
                let (n, answers) = match k {
                    0 => warm_pass(&mut w32, q, false),
                    1 => warm_pass(&mut w32, q, true),
                    2 => warm_pass(&mut w64, q, false),
                    _ => warm_pass(&mut w64, q, true),
                };
                let ns = t.elapsed().as_nanos() as f64 / CASES as f64;
                // The first step fills the caches: untimed.
                if pass > 0 {
                    times[k].push(ns);
                    iterations[k].0 += n;
                    iterations[k].1 += answers;
                }
            }
        }
        let mean = |k: usize| iterations[k].0 as f64 / iterations[k].1.max(1) as f64;
        println!(
            "| {qn} | {:.1} | {:.1} | {:.2} | {:.2} / {:.2} | {:.1} | {:.1} | {:.2} | {:.2} / {:.2} |",
            median(times[0].clone()),
            median(times[1].clone()),
            ratio(&times[1], &times[0]),
            mean(0),
            mean(1),
            median(times[2].clone()),
            median(times[3].clone()),
            ratio(&times[3], &times[2]),
            mean(2),
            mean(3),
        );
    }
}

// --- timing ----------------------------------------------------------------------

fn median(mut v: Vec<f64>) -> f64 {
    v.sort_by(f64::total_cmp);
    let n = v.len();
    if n == 0 {
        f64::NAN
    } else if n % 2 == 1 {
        v[n / 2]
    } else {
        (v[n / 2 - 1] + v[n / 2]) / 2.0
    }
}

/// One pass of each contender over its cases, `passes` times, in an order that
/// rotates from pass to pass: per contender, the time per query of every pass.
fn time_passes(passes: usize, cases: usize, contenders: &mut [&mut dyn FnMut()]) -> Vec<Vec<f64>> {
    let k = contenders.len();
    // One untimed pass each: page faults and lazy initialisation.
    for c in contenders.iter_mut() {
        c();
    }
    let mut times = vec![Vec::with_capacity(passes); k];
    for pass in 0..passes {
        for j in 0..k {
            let i = (pass + j) % k;
            let t = Instant::now();
            (contenders[i])();
            times[i].push(t.elapsed().as_nanos() as f64 / cases as f64);
        }
    }
    times
}

/// `gjk / parry` per pass, then the median: the ratio of two runs taken side by
/// side, which machine load moves less than either time.
fn ratio(ours: &[f64], theirs: &[f64]) -> f64 {
    median(ours.iter().zip(theirs).map(|(a, b)| a / b).collect())
}

struct Row {
    family: String,
    query: &'static str,
    /// Median ns per query and ratio to parry, f32 then f64.
    cells: [(f64, f64, f64); 2],
}

fn print_row(r: &Row) {
    let [a, b] = r.cells;
    println!(
        "| {} | {} | {:.1} | {:.1} | {:.2} | {:.1} | {:.1} | {:.2} |",
        r.family, r.query, a.0, a.1, a.2, b.0, b.1, b.2
    );
}

fn pair_family<const N: usize>(
    name: &str,
    cases: &[(Sh, Sh)],
    queries: &[(Query, &'static str)],
    passes: usize,
    rows: &mut Vec<Row>,
) {
    let g32: Vec<(G<f32, N>, G<f32, N>)> = cases.iter().map(|(a, b)| (g(a), g(b))).collect();
    let g64: Vec<(G<f64, N>, G<f64, N>)> = cases.iter().map(|(a, b)| (g(a), g(b))).collect();
    let p32: Vec<_> = cases.iter().map(|(a, b)| (parry32::build(a), parry32::build(b))).collect();
    let p64: Vec<_> = cases.iter().map(|(a, b)| (parry64::build(a), parry64::build(b))).collect();
    for &(q, qn) in queries {
        let t = time_passes(
            passes,
            cases.len(),
            &mut [&mut || g_pairs(&g32, q), &mut || parry32::pairs(&p32, q), &mut || g_pairs(&g64, q), &mut || {
                parry64::pairs(&p64, q)
            }],
        );
        push_row(rows, name, qn, &t);
    }
}

fn ray_family<const N: usize>(name: &str, cases: &[RayCase], passes: usize, rows: &mut Vec<Row>) {
    fn gr<R: Real, const N: usize>(b: &[RayCase]) -> Vec<(Ray<R>, R, G<R, N>)> {
        let v = |p: &[f64; 2]| R::vector(R::from_f64(p[0]), R::from_f64(p[1]));
        b.iter().map(|(o, d, m, s)| (Ray::new(v(o), v(d)).unwrap(), R::from_f64(*m), g(s))).collect()
    }
    let g32 = gr::<f32, N>(cases);
    let g64 = gr::<f64, N>(cases);
    let p32: Vec<_> = cases.iter().map(|(o, d, m, s)| (parry32::ray(o, d, *m), parry32::build(s))).collect();
    let p64: Vec<_> = cases.iter().map(|(o, d, m, s)| (parry64::ray(o, d, *m), parry64::build(s))).collect();
    let t = time_passes(
        passes,
        cases.len(),
        &mut [&mut || g_rays(&g32), &mut || parry32::rays(&p32), &mut || g_rays(&g64), &mut || parry64::rays(&p64)],
    );
    push_row(rows, name, "raycast", &t);
}

fn cast_family<const N: usize>(name: &str, cases: &[CastCase], passes: usize, rows: &mut Vec<Row>) {
    fn gc<R: Real, const N: usize>(b: &[CastCase]) -> Vec<(G<R, N>, G<R, N>, Motion<R>)> {
        let v = |p: &[f64; 2]| R::vector(R::from_f64(p[0]), R::from_f64(p[1]));
        b.iter().map(|(a, b, m)| (g(a), g(b), Motion::new(v(m)).unwrap())).collect()
    }
    let g32 = gc::<f32, N>(cases);
    let g64 = gc::<f64, N>(cases);
    let p32: Vec<_> =
        cases.iter().map(|(a, b, m)| (parry32::build(a), parry32::build(b), parry32::motion(m))).collect();
    let p64: Vec<_> =
        cases.iter().map(|(a, b, m)| (parry64::build(a), parry64::build(b), parry64::motion(m))).collect();
    let t = time_passes(
        passes,
        cases.len(),
        &mut [&mut || g_casts(&g32), &mut || parry32::casts(&p32), &mut || g_casts(&g64), &mut || parry64::casts(&p64)],
    );
    push_row(rows, name, "cast", &t);
}

fn toi_family<const N: usize>(name: &str, cases: &[ToiCase], passes: usize, rows: &mut Vec<Row>) {
    fn gt<R: Real, const N: usize>(b: &[ToiCase]) -> Vec<(G<R, N>, G<R, N>, Sweep<R>)> {
        let v = |p: &[f64; 2]| R::vector(R::from_f64(p[0]), R::from_f64(p[1]));
        let id = Transform::<R>::IDENTITY;
        b.iter()
            .map(|(a, b, m, angle)| {
                let sweep = Sweep::new(&id, v(&bounds(b).0), v(m), R::from_f64(*angle)).unwrap();
                (g(a), g(b), sweep)
            })
            .collect()
    }
    let g32 = gt::<f32, N>(cases);
    let g64 = gt::<f64, N>(cases);
    macro_rules! parry_cases {
        ($m:ident) => {
            cases
                .iter()
                .map(|(a, b, m, angle)| {
                    let (a, b, c) = ($m::build(a), $m::build(b), bounds(b).0);
                    let (ma, mb) = ($m::still(&a), $m::nonlinear(&b, &c, m, *angle));
                    (a, b, ma, mb)
                })
                .collect::<Vec<_>>()
        };
    }
    let p32 = parry_cases!(parry32);
    let p64 = parry_cases!(parry64);
    let t = time_passes(
        passes,
        cases.len(),
        &mut [&mut || g_tois(&g32), &mut || parry32::tois(&p32), &mut || g_tois(&g64), &mut || parry64::tois(&p64)],
    );
    push_row(rows, name, "time_of_impact", &t);
}

/// A family's row from its contenders' times (gjk2d f32, parry f32, gjk2d
/// f64, parry f64), printed and kept for the summary.
fn push_row(rows: &mut Vec<Row>, name: &str, query: &'static str, t: &[Vec<f64>]) {
    let row = Row {
        family: name.to_string(),
        query,
        cells: [
            (median(t[0].clone()), median(t[1].clone()), ratio(&t[0], &t[1])),
            (median(t[2].clone()), median(t[3].clone()), ratio(&t[2], &t[3])),
        ],
    };
    print_row(&row);
    rows.push(row);
}

fn main() {
    // `cargo bench` passes `--bench`; every other argument selects families.
    let words: Vec<String> = std::env::args().skip(1).filter(|a| !a.starts_with("--")).collect();
    let wanted = |name: &str| words.is_empty() || words.iter().any(|w| name.contains(w.as_str()));
    let passes = std::env::var("GJK2D_BENCH_PASSES").ok().and_then(|s| s.parse().ok()).unwrap_or(15);
    println!("{CASES} distinct cases per family and pass, {passes} passes; ns per query (median over passes) and gjk2d / parry2d (median of per-pass ratios)\n");
    println!("| family | query | gjk2d f32 ns | parry f32 ns | ratio f32 | gjk2d f64 ns | parry f64 ns | ratio f64 |");
    println!("|---|---|---:|---:|---:|---:|---:|---:|");
    let mut rows = Vec::new();
    let p8 = |r: &mut Rng, c: [f64; 2]| poly(r, 8, c);
    let p64 = |r: &mut Rng, c: [f64; 2]| poly(r, 64, c);
    let p1024 = |r: &mut Rng, c: [f64; 2]| poly(r, 1024, c);
    if wanted("poly8") {
        pair_family::<8>("poly8", &pairs(1, CASES, &p8, &p8), &PAIR_QUERIES, passes, &mut rows);
    }
    if wanted("poly64") {
        pair_family::<64>("poly64", &pairs(2, CASES, &p64, &p64), &PAIR_QUERIES, passes, &mut rows);
    }
    if wanted("poly1024") {
        pair_family::<1024>("poly1024", &pairs(5, CASES, &p1024, &p1024), &PAIR_QUERIES, passes, &mut rows);
    }
    if wanted("circle_poly8") {
        pair_family::<8>("circle_poly8", &pairs(3, CASES, &circle, &p8), &PAIR_QUERIES, passes, &mut rows);
    }
    if wanted("capsule_poly8") {
        pair_family::<8>("capsule_poly8", &pairs(4, CASES, &capsule, &p8), &PAIR_QUERIES, passes, &mut rows);
    }
    if wanted("circle_circle") {
        pair_family::<8>("circle_circle", &pairs(10, CASES, &circle, &circle), &PAIR_QUERIES, passes, &mut rows);
    }
    // Manifolds of 8-gons, of a circle or a capsule on an 8-gon, and of 64-gons.
    let manifold = [(Query::Manifold, "manifold")];
    let on_p8: [(&str, u64, &Maker); 3] =
        [("manifold_poly8", 12, &p8), ("manifold_circle_poly8", 13, &circle), ("manifold_capsule_poly8", 14, &capsule)];
    for (name, seed, a) in on_p8 {
        if wanted(name) {
            pair_family::<8>(name, &pairs(seed, CASES, a, &p8), &manifold, passes, &mut rows);
        }
    }
    if wanted("manifold_poly64") {
        pair_family::<64>("manifold_poly64", &pairs(15, CASES, &p64, &p64), &manifold, passes, &mut rows);
    }
    if wanted("ray_poly8") {
        ray_family::<8>("ray_poly8", &rays(6, CASES, &p8), passes, &mut rows);
    }
    if wanted("ray_poly64") {
        ray_family::<64>("ray_poly64", &rays(7, CASES, &p64), passes, &mut rows);
    }
    if wanted("ray_circle") {
        ray_family::<8>("ray_circle", &rays(8, CASES, &circle), passes, &mut rows);
    }
    if wanted("ray_capsule") {
        ray_family::<8>("ray_capsule", &rays(11, CASES, &capsule), passes, &mut rows);
    }
    if wanted("ray_poly1024") {
        ray_family::<1024>("ray_poly1024", &rays(9, CASES, &p1024), passes, &mut rows);
    }
    if wanted("cast_poly8") {
        cast_family::<8>("cast_poly8", &casts(12, CASES, &p8, &p8), passes, &mut rows);
    }
    if wanted("cast_circle_poly8") {
        cast_family::<8>("cast_circle_poly8", &casts(13, CASES, &circle, &p8), passes, &mut rows);
    }
    if wanted("cast_capsule_poly8") {
        cast_family::<8>("cast_capsule_poly8", &casts(14, CASES, &capsule, &p8), passes, &mut rows);
    }
    if wanted("toi_poly8") {
        toi_family::<8>("toi_poly8", &tois(15, CASES, &p8, &p8), passes, &mut rows);
    }
    if wanted("toi_poly8_capsule") {
        toi_family::<8>("toi_poly8_capsule", &tois(16, CASES, &p8, &capsule), passes, &mut rows);
    }
    if wanted("warm_poly8") {
        warm_family::<8>("warm_poly8", passes, &words);
    }
    // Where the cold queries iterate (GJK, EPA), not closed forms as for 8-gons.
    if wanted("warm_poly64") {
        warm_family::<64>("warm_poly64", passes, &words);
    }
    let slower: Vec<String> = rows
        .iter()
        .flat_map(|r| {
            [("f32", r.cells[0].2), ("f64", r.cells[1].2)]
                .into_iter()
                .filter(|(_, x)| *x > 1.0)
                .map(move |(p, x)| format!("{} {} {p} ({x:.2})", r.family, r.query))
        })
        .collect();
    println!("\nslower than parry2d: {}", if slower.is_empty() { "none".to_string() } else { slower.join(", ") });
}
