//! The hot queries, gjk2d and parry2d side by side, timed as a physics step or a
//! game frame meets them: every pass asks each of 16,384 distinct pairs once, so
//! the branch predictor cannot learn the answers (a small batch repeated lets it,
//! and flatters branchy code by 2x or more).
//!
//! ```text
//! cargo bench --bench queries                 # every family, f32 and f64
//! cargo bench --bench queries -- poly8 ray    # families whose name contains a word
//! GJK2D_BENCH_PASSES=31 cargo bench --bench queries
//! ```
//!
//! The four contenders (gjk2d and parry2d, f32 and f64) take turns within every
//! pass, in a rotating order, so a change of machine load falls on all alike. The
//! table gives each one's median time per query over the passes and the median of
//! the per-pass ratios gjk2d / parry2d. Shapes are held in an enum and passed to
//! the generic queries (gjk2d) or as `dyn Shape` (parry), with identity
//! transforms; inputs are f32 values, so both precisions see the same geometry.

use gjk2d::{Capsule, Circle, Gjk, Polygon, Ray, Real, SupportMap, Transform};
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

/// Rays from about 2.5 away aimed within 1 of the center; half unbounded.
type RayCase = ([f64; 2], [f64; 2], f64, Sh);

fn rays(seed: u64, count: usize, mk: &Maker) -> Vec<RayCase> {
    let mut rng = Rng(seed);
    (0..count)
        .map(|_| {
            let s = mk(&mut rng, [0.0, 0.0]);
            let t = rng.range(0.0, 6.3);
            let o = [r32(2.5 * t.cos()), r32(2.5 * t.sin())];
            let aim = [rng.range(-1.0, 1.0), rng.range(-1.0, 1.0)];
            let d = [r32(aim[0] - o[0]), r32(aim[1] - o[1])];
            let max = if rng.f() < 0.5 { 0.0 } else { 3.0 };
            (o, d, max, s)
        })
        .collect()
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

fn g_pairs<R: Real, const N: usize>(batch: &[(G<R, N>, G<R, N>)], q: Query) {
    let gjk = Gjk::<R>::new();
    let id = Transform::<R>::IDENTITY;
    #[inline(always)]
    fn run<R: Real, A: SupportMap<R>, B: SupportMap<R>>(gjk: &Gjk<R>, q: Query, a: &A, b: &B, id: &Transform<R>) {
        match q {
            Query::Intersect => {
                black_box(gjk.intersects(a, id, b, id));
            }
            Query::Distance => {
                black_box(gjk.distance(a, id, b, id));
            }
            Query::Penetration => {
                black_box(gjk.penetration(a, id, b, id));
            }
            Query::Manifold => {
                let _ = black_box(gjk.manifold(a, id, b, id, R::ZERO));
            }
        }
    }
    for (a, b) in batch {
        let (a, b) = (black_box(a), black_box(b));
        with_g!(a, |x| with_g!(b, |y| run(&gjk, q, x, y, &id)));
    }
}

fn g_rays<R: Real, const N: usize>(batch: &[(Ray<R>, R, G<R, N>)]) {
    let gjk = Gjk::<R>::new();
    let id = Transform::<R>::IDENTITY;
    for (ray, max, s) in batch {
        black_box(with_g!(black_box(s), |x| gjk.raycast(ray, *max, x, &id)));
    }
}

// --- parry -----------------------------------------------------------------------

macro_rules! parry_side {
    ($m:ident, $p:ident, $R:ty) => {
        mod $m {
            use super::{Query, Sh};
            use std::hint::black_box;
            use $p::math::{Pose, Vector};
            use $p::query::{self, ContactManifold, DefaultQueryDispatcher, PersistentQueryDispatcher, Ray};
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

            pub fn pairs(batch: &[(PS, PS)], q: Query) {
                // Cleared before each pair: every manifold is computed cold.
                let mut manifolds: Vec<ContactManifold<(), ()>> = Vec::with_capacity(1);
                for (a, b) in batch {
                    let (a, b) = (black_box(a), black_box(b));
                    match q {
                        Query::Intersect => {
                            let _ = black_box(query::intersection_test(&a.1, &*a.0, &b.1, &*b.0));
                        }
                        Query::Distance => {
                            let _ = black_box(query::distance(&a.1, &*a.0, &b.1, &*b.0));
                        }
                        Query::Penetration => {
                            let _ = black_box(query::contact(&a.1, &*a.0, &b.1, &*b.0, 0.0));
                        }
                        Query::Manifold => {
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
        let row = Row {
            family: name.to_string(),
            query: qn,
            cells: [
                (median(t[0].clone()), median(t[1].clone()), ratio(&t[0], &t[1])),
                (median(t[2].clone()), median(t[3].clone()), ratio(&t[2], &t[3])),
            ],
        };
        print_row(&row);
        rows.push(row);
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
    let row = Row {
        family: name.to_string(),
        query: "raycast",
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
    // Manifolds of 8-gons, and of a circle or a capsule on an 8-gon.
    let manifold = [(Query::Manifold, "manifold")];
    let on_p8: [(&str, u64, &Maker); 3] =
        [("manifold_poly8", 12, &p8), ("manifold_circle_poly8", 13, &circle), ("manifold_capsule_poly8", 14, &capsule)];
    for (name, seed, a) in on_p8 {
        if wanted(name) {
            pair_family::<8>(name, &pairs(seed, CASES, a, &p8), &manifold, passes, &mut rows);
        }
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
