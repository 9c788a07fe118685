//! The hot queries, gjk2d and parry2d side by side on the same pairs:
//! `cargo bench --bench queries` (filter with e.g. `-- poly8/intersect`).
//!
//! Each benchmark runs one query over a batch of 64 pairs (about half overlapping)
//! from a fixed seed; criterion reports the time per query (throughput: elements).
//! Shapes are f32 values, so f32 and f64 see the same geometry.

use criterion::{criterion_group, criterion_main, BenchmarkId, Criterion, Throughput};
use gjk2d::{Capsule, Circle, Gjk, Polygon, Ray, Real, SupportMap, Transform};
use std::hint::black_box;
use std::time::Duration;

const BATCH: usize = 64;

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

/// A batch of pairs: A around the origin, B's center at 0.4..1.6 of their size away.
fn pairs(seed: u64, mk_a: &dyn Fn(&mut Rng, [f64; 2]) -> Sh, mk_b: &dyn Fn(&mut Rng, [f64; 2]) -> Sh) -> Vec<(Sh, Sh)> {
    let mut rng = Rng(seed);
    (0..BATCH)
        .map(|_| {
            let a = mk_a(&mut rng, [0.0, 0.0]);
            let (d, t) = (rng.range(0.4, 1.6), rng.range(0.0, 6.3));
            (a, mk_b(&mut rng, [d * t.cos(), d * t.sin()]))
        })
        .collect()
}

/// Rays from about 2.5 away aimed within 1 of the center; half unbounded.
fn rays(seed: u64, mk: &dyn Fn(&mut Rng, [f64; 2]) -> Sh) -> Vec<([f64; 2], [f64; 2], f64, Sh)> {
    let mut rng = Rng(seed);
    (0..BATCH)
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
            G::P($x) => {
                let $x: &Polygon<R, N> = $x;
                $body
            }
            G::C($x) => $body,
            G::K($x) => $body,
        }
    };
}

/// Calls `f` on every pair of the batch with both shapes' concrete types.
fn g_pair_bench<R: Real, const N: usize>(batch: &[(G<R, N>, G<R, N>)], query: &str) {
    let gjk = Gjk::<R>::new();
    let id = Transform::<R>::IDENTITY;
    fn run<R: Real, A: SupportMap<R>, B: SupportMap<R>>(gjk: &Gjk<R>, q: &str, a: &A, b: &B, id: &Transform<R>) {
        match q {
            "intersect" => {
                black_box(gjk.intersects(a, id, b, id));
            }
            "distance" => {
                black_box(gjk.distance(a, id, b, id));
            }
            _ => {
                black_box(gjk.penetration(a, id, b, id));
            }
        }
    }
    for (a, b) in batch {
        let (a, b) = (black_box(a), black_box(b));
        with_g!(a, |x| with_g!(b, |y| run(&gjk, query, x, y, &id)));
    }
}

fn g_ray_bench<R: Real, const N: usize>(batch: &[(Ray<R>, R, G<R, N>)]) {
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
            use super::Sh;
            use std::hint::black_box;
            use $p::math::{Pose, Vector};
            use $p::query::{self, Ray};
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

            pub fn pair_bench(batch: &[(PS, PS)], q: &str) {
                for (a, b) in batch {
                    let (a, b) = (black_box(a), black_box(b));
                    match q {
                        "intersect" => {
                            let _ = black_box(query::intersection_test(&a.1, &*a.0, &b.1, &*b.0));
                        }
                        "distance" => {
                            let _ = black_box(query::distance(&a.1, &*a.0, &b.1, &*b.0));
                        }
                        _ => {
                            let _ = black_box(query::contact(&a.1, &*a.0, &b.1, &*b.0, 0.0));
                        }
                    }
                }
            }

            pub fn ray_bench(batch: &[((Ray, $R), PS)]) {
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

// --- the benchmarks --------------------------------------------------------------

fn scene<const N: usize>(c: &mut Criterion, name: &str, batch: &[(Sh, Sh)]) {
    let mut group = c.benchmark_group(name);
    group.throughput(Throughput::Elements(BATCH as u64));
    let g32: Vec<(G<f32, N>, G<f32, N>)> = batch.iter().map(|(a, b)| (g(a), g(b))).collect();
    let g64: Vec<(G<f64, N>, G<f64, N>)> = batch.iter().map(|(a, b)| (g(a), g(b))).collect();
    let p32: Vec<_> = batch.iter().map(|(a, b)| (parry32::build(a), parry32::build(b))).collect();
    let p64: Vec<_> = batch.iter().map(|(a, b)| (parry64::build(a), parry64::build(b))).collect();
    for q in ["intersect", "distance", "penetration"] {
        group.bench_function(BenchmarkId::new(format!("{q}/gjk2d"), "f32"), |bn| bn.iter(|| g_pair_bench(&g32, q)));
        group.bench_function(BenchmarkId::new(format!("{q}/parry2d"), "f32"), |bn| {
            bn.iter(|| parry32::pair_bench(&p32, q))
        });
        group.bench_function(BenchmarkId::new(format!("{q}/gjk2d"), "f64"), |bn| bn.iter(|| g_pair_bench(&g64, q)));
        group.bench_function(BenchmarkId::new(format!("{q}/parry2d"), "f64"), |bn| {
            bn.iter(|| parry64::pair_bench(&p64, q))
        });
    }
    group.finish();
}

fn ray_scene<const N: usize>(c: &mut Criterion, name: &str, batch: &[([f64; 2], [f64; 2], f64, Sh)]) {
    let mut group = c.benchmark_group(name);
    group.throughput(Throughput::Elements(BATCH as u64));
    fn gr<R: Real, const N: usize>(b: &[([f64; 2], [f64; 2], f64, Sh)]) -> Vec<(Ray<R>, R, G<R, N>)> {
        let v = |p: &[f64; 2]| R::vector(R::from_f64(p[0]), R::from_f64(p[1]));
        b.iter().map(|(o, d, m, s)| (Ray::new(v(o), v(d)).unwrap(), R::from_f64(*m), g(s))).collect()
    }
    let g32 = gr::<f32, N>(batch);
    let g64 = gr::<f64, N>(batch);
    let p32: Vec<_> = batch.iter().map(|(o, d, m, s)| (parry32::ray(o, d, *m), parry32::build(s))).collect();
    let p64: Vec<_> = batch.iter().map(|(o, d, m, s)| (parry64::ray(o, d, *m), parry64::build(s))).collect();
    group.bench_function(BenchmarkId::new("ray/gjk2d", "f32"), |bn| bn.iter(|| g_ray_bench(&g32)));
    group.bench_function(BenchmarkId::new("ray/parry2d", "f32"), |bn| bn.iter(|| parry32::ray_bench(&p32)));
    group.bench_function(BenchmarkId::new("ray/gjk2d", "f64"), |bn| bn.iter(|| g_ray_bench(&g64)));
    group.bench_function(BenchmarkId::new("ray/parry2d", "f64"), |bn| bn.iter(|| parry64::ray_bench(&p64)));
    group.finish();
}

fn benches(c: &mut Criterion) {
    let p8 = |r: &mut Rng, c: [f64; 2]| poly(r, 8, c);
    let p64 = |r: &mut Rng, c: [f64; 2]| poly(r, 64, c);
    let p1024 = |r: &mut Rng, c: [f64; 2]| poly(r, 1024, c);
    scene::<8>(c, "poly8", &pairs(1, &p8, &p8));
    scene::<64>(c, "poly64", &pairs(2, &p64, &p64));
    scene::<8>(c, "circle_poly8", &pairs(3, &circle, &p8));
    scene::<8>(c, "capsule_poly8", &pairs(4, &capsule, &p8));
    scene::<1024>(c, "poly1024", &pairs(5, &p1024, &p1024));
    ray_scene::<8>(c, "ray_poly8", &rays(6, &p8));
    ray_scene::<64>(c, "ray_poly64", &rays(7, &p64));
    ray_scene::<8>(c, "ray_circle", &rays(8, &circle));
    ray_scene::<1024>(c, "ray_poly1024", &rays(9, &p1024));
}

criterion_group! {
    name = queries;
    config = Criterion::default().sample_size(20).warm_up_time(Duration::from_millis(300)).measurement_time(Duration::from_millis(800));
    targets = benches
}
criterion_main!(queries);
