//! gjk2d's error against its run time, side by side with parry2d.
//!
//! ```text
//! cargo run --release --example report              # the default run
//! cargo run --release --example report -- --quick   # CI's smoke run: fewer cases and repeats
//! cargo run --release --example report -- --long    # 4x the cases, more repeats
//! cargo run --release --example report -- --cases my-cases.txt --out report
//! ```
//!
//! Every scene family is generated from a fixed seed. All inputs are f32 values, so the
//! f32 and f64 runs (and parry2d / parry2d-f64) read identical shapes, and one exact
//! answer serves them all. Exact answers come from `gjk2d-oracle` (rational arithmetic,
//! correctly rounded to f64). Ellipses are beyond the oracle: the ellipse-vs-circle
//! family is answered by Eberly's robust point-to-ellipse distance (bisection to the
//! last bit in f64), an independent method accurate to a few f64 ulps of the size.
//!
//! Errors are relative to the pair's size L (the larger bounding radius about the
//! vertex mean); for rays L = max(bounding radius, distance from the ray origin to the
//! shape's center). A verdict counts as wrong only when the exact margin exceeds
//! 8 eps L (eps of the precision under test): closer cases are too close to call.
//!
//! Writes `report.md` (the table, date, machine), `sweep.csv` and `sweep.svg`
//! (error against time per query as settings vary) to `--out` (default
//! `target/report/`, so a run leaves the checkout clean; `--out report` refreshes
//! the committed copy).

use gjk2d::{Capsule, Circle, Ellipse, EpaConfig, Gjk, GjkConfig, Polygon, Ray, RayOutcome, Real, Status, Transform};
use gjk2d_oracle as oracle;
use std::fmt::Write as _;
use std::hint::black_box;
use std::time::Instant;

// ---------------------------------------------------------------------------------
// Deterministic random numbers (SplitMix64: small, seedable, good enough here).

struct Rng(u64);

impl Rng {
    fn next_u64(&mut self) -> u64 {
        self.0 = self.0.wrapping_add(0x9E37_79B9_7F4A_7C15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        z ^ (z >> 31)
    }
    /// Uniform in [0, 1).
    fn f(&mut self) -> f64 {
        (self.next_u64() >> 11) as f64 / (1u64 << 53) as f64
    }
    fn range(&mut self, lo: f64, hi: f64) -> f64 {
        lo + (hi - lo) * self.f()
    }
    fn below(&mut self, n: usize) -> usize {
        (self.f() * n as f64) as usize % n
    }
    fn unit(&mut self) -> [f64; 2] {
        let t = self.range(0.0, std::f64::consts::TAU);
        [t.cos(), t.sin()]
    }
}

/// Rounds to the nearest f32 (every input coordinate is an f32 value).
fn r32(x: f64) -> f64 {
    x as f32 as f64
}

/// `x` moved by `k` f32 ulps (k may be negative).
fn ulp_step(x: f64, k: i32) -> f64 {
    let mut v = x as f32;
    for _ in 0..k.unsigned_abs() {
        v = if k > 0 { v.next_up() } else { v.next_down() };
    }
    v as f64
}

// ---------------------------------------------------------------------------------
// Input shapes (f32 values held in f64) and their exact answers.

#[derive(Clone, Debug)]
enum Sh {
    /// Strictly convex, counter-clockwise.
    Poly(Vec<[f64; 2]>),
    Circle([f64; 2], f64),
    Capsule([f64; 2], [f64; 2], f64),
    /// Axis-aligned ellipse: center, half-width, half-height.
    Ellipse([f64; 2], f64, f64),
}

impl Sh {
    /// Center (vertex mean for polygons) and bounding radius about it, in f64.
    fn bounds(&self) -> ([f64; 2], f64) {
        let dist = |p: [f64; 2], q: [f64; 2]| (p[0] - q[0]).hypot(p[1] - q[1]);
        match self {
            Sh::Poly(v) => {
                let n = v.len() as f64;
                let c = [v.iter().map(|p| p[0]).sum::<f64>() / n, v.iter().map(|p| p[1]).sum::<f64>() / n];
                (c, v.iter().map(|&p| dist(p, c)).fold(0.0, f64::max))
            }
            Sh::Circle(c, r) => (*c, *r),
            Sh::Capsule(a, b, r) => {
                let c = [(a[0] + b[0]) / 2.0, (a[1] + b[1]) / 2.0];
                (c, dist(*a, c) + r)
            }
            Sh::Ellipse(c, a, b) => (*c, a.max(*b)),
        }
    }
    fn vertex_count(&self) -> usize {
        match self {
            Sh::Poly(v) => v.len(),
            _ => 1,
        }
    }
    fn oracle(&self) -> oracle::Shape {
        match self {
            Sh::Poly(v) => oracle::Shape::Polygon(v.clone()),
            Sh::Circle(c, r) => oracle::Shape::Circle { center: *c, radius: *r },
            Sh::Capsule(a, b, r) => oracle::Shape::Capsule { a: *a, b: *b, radius: *r },
            Sh::Ellipse(..) => unreachable!("the oracle has no ellipses"),
        }
    }
    fn tokens(&self, t: &mut Vec<String>) {
        match self {
            Sh::Poly(v) => {
                t.push(format!("poly {}", v.len()));
                for p in v {
                    t.push(format!("{} {}", p[0], p[1]));
                }
            }
            Sh::Circle(c, r) => t.push(format!("circle {} {} {}", c[0], c[1], r)),
            Sh::Capsule(a, b, r) => t.push(format!("capsule {} {} {} {} {}", a[0], a[1], b[0], b[1], r)),
            Sh::Ellipse(c, a, b) => t.push(format!("ellipse {} {} {} {}", c[0], c[1], a, b)),
        }
    }
}

#[derive(Clone, Debug)]
struct PairTruth {
    /// Distance if apart, -depth if overlapping, 0 if touching.
    signed: f64,
    distance: f64,
    depth: f64,
    normal: [f64; 2],
    normal_unique: bool,
}

#[derive(Clone, Copy, Debug, PartialEq)]
enum RayVerdict {
    Hit,
    Miss,
    Inside,
}

#[derive(Clone, Debug)]
struct RayTruth {
    verdict: RayVerdict,
    t: f64,
    normal: [f64; 2],
    normal_unique: bool,
    margin: f64,
}

struct PairCase {
    a: Sh,
    b: Sh,
    l: f64,
    truth: PairTruth,
}

struct RayCase {
    o: [f64; 2],
    d: [f64; 2],
    max_len: f64,
    s: Sh,
    l: f64,
    truth: RayTruth,
}

enum Cases {
    Pairs(Vec<PairCase>),
    Rays(Vec<RayCase>),
}

struct Family {
    name: String,
    stiff: bool,
    cases: Cases,
    /// More inputs of the same kind, timed but not judged, so that every timed
    /// pass asks [`TIMED_CASES`] distinct questions.
    extra: Extra,
}

enum Extra {
    Pairs(Vec<(Sh, Sh)>),
    Rays(Vec<([f64; 2], [f64; 2], f64, Sh)>),
}

impl Family {
    fn extra_pairs(&self) -> &[(Sh, Sh)] {
        match &self.extra {
            Extra::Pairs(v) => v,
            Extra::Rays(_) => &[],
        }
    }
    fn extra_rays(&self) -> &[([f64; 2], [f64; 2], f64, Sh)] {
        match &self.extra {
            Extra::Rays(v) => v,
            Extra::Pairs(_) => &[],
        }
    }
}

fn oracle_pair(a: &Sh, b: &Sh) -> PairTruth {
    if let (Sh::Ellipse(c, ea, eb), Sh::Circle(cc, r)) = (a, b) {
        return ellipse_circle_truth(*c, *ea, *eb, *cc, *r);
    }
    let p = oracle::pair(&oracle::ExactShape::from(&a.oracle()), &oracle::ExactShape::from(&b.oracle()));
    PairTruth {
        signed: p.signed_distance,
        distance: p.distance,
        depth: p.depth,
        normal: p.normal,
        normal_unique: p.normal_unique,
    }
}

fn oracle_ray(o: [f64; 2], d: [f64; 2], max_len: f64, s: &Sh) -> RayTruth {
    let r = oracle::ray(o, d, max_len, &oracle::ExactShape::from(&s.oracle()));
    RayTruth {
        verdict: match r.status {
            oracle::RayStatus::Hit => RayVerdict::Hit,
            oracle::RayStatus::Miss => RayVerdict::Miss,
            oracle::RayStatus::Inside => RayVerdict::Inside,
        },
        t: r.t,
        normal: r.normal,
        normal_unique: r.normal_unique,
        margin: r.margin,
    }
}

/// Distance from `y` (first quadrant, relative to the center) to the ellipse with
/// semi-axes e0 >= e1, and the closest point: Eberly, "Distance from a point to an
/// ellipse, an ellipsoid, or a hyperellipsoid", with the root bracketed by bisection
/// until the midpoint no longer moves (the last bit of f64).
fn point_ellipse(e0: f64, e1: f64, y0: f64, y1: f64) -> (f64, [f64; 2]) {
    if y1 > 0.0 {
        if y0 > 0.0 {
            let (z0, z1) = (y0 / e0, y1 / e1);
            let g = z0 * z0 + z1 * z1 - 1.0;
            if g != 0.0 {
                let r0 = (e0 / e1) * (e0 / e1);
                let n0 = r0 * z0;
                let mut s0 = z1 - 1.0;
                let mut s1 = if g < 0.0 { 0.0 } else { n0.hypot(z1) - 1.0 };
                let mut s = 0.0;
                for _ in 0..2200 {
                    s = 0.5 * (s0 + s1);
                    if s == s0 || s == s1 {
                        break;
                    }
                    let (q0, q1) = (n0 / (s + r0), z1 / (s + 1.0));
                    let gs = q0 * q0 + q1 * q1 - 1.0;
                    if gs > 0.0 {
                        s0 = s;
                    } else if gs < 0.0 {
                        s1 = s;
                    } else {
                        break;
                    }
                }
                let x = [r0 * y0 / (s + r0), y1 / (s + 1.0)];
                ((x[0] - y0).hypot(x[1] - y1), x)
            } else {
                (0.0, [y0, y1])
            }
        } else {
            ((y1 - e1).abs(), [0.0, e1])
        }
    } else {
        let (numer0, denom0) = (e0 * y0, e0 * e0 - e1 * e1);
        if numer0 < denom0 {
            let xde0 = numer0 / denom0;
            let x = [e0 * xde0, e1 * (1.0 - xde0 * xde0).sqrt()];
            ((x[0] - y0).hypot(x[1]), x)
        } else {
            ((y0 - e0).abs(), [e0, 0.0])
        }
    }
}

/// Ellipse (A) against a disk (B) from the point-to-ellipse distance of the disk's
/// center: apart by `d - r`, or overlapping by `r - d` (center outside) or `r + d`
/// (center inside: B must first leave the ellipse).
fn ellipse_circle_truth(c: [f64; 2], ha: f64, hb: f64, cc: [f64; 2], r: f64) -> PairTruth {
    let (px, py) = (cc[0] - c[0], cc[1] - c[1]); // exact: nearby f32 values
    let swap = hb > ha;
    let (e0, e1, y0, y1) = if swap { (hb, ha, py.abs(), px.abs()) } else { (ha, hb, px.abs(), py.abs()) };
    let inside = (y0 / e0).powi(2) + (y1 / e1).powi(2) < 1.0;
    let (d, x) = point_ellipse(e0, e1, y0, y1);
    // Outward direction at the closest point, back in the ellipse's frame.
    let mut n = if d > 0.0 {
        if inside {
            [x[0] - y0, x[1] - y1]
        } else {
            [y0 - x[0], y1 - x[1]]
        }
    } else {
        [x[0] / (e0 * e0), x[1] / (e1 * e1)]
    };
    let len = n[0].hypot(n[1]);
    n = [n[0] / len, n[1] / len];
    if swap {
        n = [n[1], n[0]];
    }
    n = [n[0] * px.signum(), n[1] * py.signum()];
    let signed = if inside { -(d + r) } else { d - r };
    PairTruth { signed, distance: signed.max(0.0), depth: (-signed).max(0.0), normal: n, normal_unique: true }
}

// ---------------------------------------------------------------------------------
// Scene generation.

/// Exact convex hull (monotone chain) of f32 points, counter-clockwise, strictly
/// convex. Differences of f32 values and their products are exact in f64, so the
/// orientation signs are exact.
fn hull(mut p: Vec<[f64; 2]>) -> Vec<[f64; 2]> {
    p.sort_by(|a, b| a.partial_cmp(b).unwrap());
    p.dedup();
    let cross = |o: [f64; 2], a: [f64; 2], b: [f64; 2]| {
        let l = (a[0] - o[0]) * (b[1] - o[1]);
        let r = (a[1] - o[1]) * (b[0] - o[0]);
        l > r
    };
    let mut h: Vec<[f64; 2]> = Vec::new();
    for pass in 0..2 {
        let start = h.len();
        let iter: Box<dyn Iterator<Item = &[f64; 2]>> =
            if pass == 0 { Box::new(p.iter()) } else { Box::new(p.iter().rev()) };
        for &v in iter {
            while h.len() >= start + 2 && !cross(h[h.len() - 2], h[h.len() - 1], v) {
                h.pop();
            }
            h.push(v);
        }
        h.pop();
    }
    h
}

/// `n` points on an ellipse of semi-axes (a, b), rotated, centered at `c`, at jittered
/// stratified angles, rounded to f32, made strictly convex.
fn ellipse_poly(rng: &mut Rng, n: usize, a: f64, b: f64, rot: f64, c: [f64; 2]) -> Vec<[f64; 2]> {
    let (cs, sn) = (rot.cos(), rot.sin());
    let phase = rng.f();
    let pts = (0..n)
        .map(|i| {
            let t = (i as f64 + phase + 0.6 * rng.f()) / n as f64 * std::f64::consts::TAU;
            let (x, y) = (a * t.cos(), b * t.sin());
            [r32(c[0] + cs * x - sn * y), r32(c[1] + sn * x + cs * y)]
        })
        .collect();
    hull(pts)
}

fn random_poly(rng: &mut Rng, n: usize, size: f64, aspect: f64, c: [f64; 2]) -> Sh {
    let a = size * rng.range(0.4, 1.0);
    let b = if aspect < 1.0 { a * aspect } else { size * rng.range(0.4, 1.0) };
    let rot = rng.range(0.0, std::f64::consts::TAU);
    Sh::Poly(ellipse_poly(rng, n, a, b, rot, c))
}

fn offset(c: [f64; 2], dir: [f64; 2], d: f64) -> [f64; 2] {
    [c[0] + dir[0] * d, c[1] + dir[1] * d]
}

fn translate(s: &Sh, t: [f64; 2]) -> Sh {
    let m = |p: &[f64; 2]| [r32(p[0] + t[0]), r32(p[1] + t[1])];
    match s {
        Sh::Poly(v) => Sh::Poly(hull(v.iter().map(m).collect())),
        Sh::Circle(c, r) => Sh::Circle(m(c), *r),
        Sh::Capsule(a, b, r) => Sh::Capsule(m(a), m(b), *r),
        Sh::Ellipse(c, a, b) => Sh::Ellipse(m(c), *a, *b),
    }
}

/// A pair whose centers are a random fraction of their summed radii apart: about
/// half of them overlap.
fn place_pair(
    rng: &mut Rng,
    make_a: &mut dyn FnMut(&mut Rng, [f64; 2]) -> Sh,
    make_b: &mut dyn FnMut(&mut Rng, [f64; 2]) -> Sh,
    origin: [f64; 2],
    size: f64,
) -> (Sh, Sh) {
    let ca = [r32(origin[0] + size * rng.range(-1.0, 1.0)), r32(origin[1] + size * rng.range(-1.0, 1.0))];
    let a = make_a(rng, ca);
    let b0 = make_b(rng, [0.0, 0.0]);
    let (_, ra) = a.bounds();
    let (cb, rb) = b0.bounds();
    let dir = rng.unit();
    let target = offset(ca, dir, (ra + rb) * rng.range(0.25, 1.3));
    (a, translate(&b0, [target[0] - cb[0], target[1] - cb[1]]))
}

fn pair_family(
    name: &str,
    stiff: bool,
    n: usize,
    rng: &mut Rng,
    mut gen: impl FnMut(&mut Rng) -> Option<(Sh, Sh)>,
) -> PairSpec {
    let total = n.max(TIMED_CASES);
    let mut v = Vec::with_capacity(total);
    while v.len() < total {
        if let Some(p) = gen(rng) {
            if valid(&p.0) && valid(&p.1) {
                v.push(p);
            }
        }
    }
    (name.to_string(), stiff, v, n)
}

fn valid(s: &Sh) -> bool {
    match s {
        Sh::Poly(v) => v.len() >= 3 && build_g::<f32, 1100>(s).is_some() && build_g::<f64, 1100>(s).is_some(),
        _ => true,
    }
}

/// A pair of polygons touching at a vertex (B's support point along -u placed on A's
/// along u), then for most cases moved a few f32 ulps apart or together.
fn touching_pair(rng: &mut Rng) -> Option<(Sh, Sh)> {
    let a = random_poly(rng, 8, 1.0, 1.0, [0.0, 0.0]);
    let b0 = random_poly(rng, 8, 1.0, 1.0, [0.0, 0.0]);
    let (Sh::Poly(va), Sh::Poly(vb)) = (&a, &b0) else { unreachable!() };
    let u = rng.unit();
    let dot = |p: &[f64; 2]| p[0] * u[0] + p[1] * u[1];
    let pa = *va.iter().max_by(|p, q| dot(p).partial_cmp(&dot(q)).unwrap())?;
    let pb = *vb.iter().min_by(|p, q| dot(p).partial_cmp(&dot(q)).unwrap())?;
    let k = [0, 0, 1, 2, 4, 16, -1, -4][rng.below(8)];
    let moved: Vec<[f64; 2]> = vb
        .iter()
        .map(|p| {
            let q = if *p == pb { pa } else { [r32(p[0] - pb[0] + pa[0]), r32(p[1] - pb[1] + pa[1])] };
            [ulp_step(q[0], k * u[0].signum() as i32), ulp_step(q[1], k * u[1].signum() as i32)]
        })
        .collect();
    Some((a, Sh::Poly(hull(moved))))
}

/// Two half-ellipses whose flat faces are parallel (exactly: both on lines y = const,
/// or x = const), `gap` apart: 0, a few f32 ulps, 1e-5 or 1e-3, either sign.
fn parallel_pair(rng: &mut Rng) -> Option<(Sh, Sh)> {
    let half = |rng: &mut Rng, cx: f64, y: f64, up: bool| {
        let (a, b) = (rng.range(0.4, 1.0), rng.range(0.2, 1.0));
        let n = 8;
        let mut pts = vec![[r32(cx - a), y], [r32(cx + a), y]];
        for i in 1..n - 1 {
            let t = (i as f64 + 0.8 * rng.f() - 0.4) / (n - 1) as f64 * std::f64::consts::PI;
            let dy = b * t.sin();
            pts.push([r32(cx + a * t.cos()), r32(if up { y + dy } else { y - dy })]);
        }
        hull(pts)
    };
    let gaps_ulps = [0, 0, 1, 2, 8, 64, -1, -8];
    let y = 1.0;
    let yb = match rng.below(4) {
        0 => r32(y + if rng.f() < 0.5 { 1e-5 } else { -1e-5 }),
        1 => r32(y + if rng.f() < 0.5 { 1e-3 } else { -1e-3 }),
        _ => ulp_step(y, gaps_ulps[rng.below(gaps_ulps.len())]),
    };
    let a = half(rng, 0.0, y, false);
    let cx = rng.range(-0.8, 0.8);
    let b = half(rng, cx, yb, true);
    let swap = rng.f() < 0.5;
    let rot = |v: Vec<[f64; 2]>| {
        if swap {
            hull(v.into_iter().map(|p| [-p[1], p[0]]).collect())
        } else {
            v
        }
    };
    Some((Sh::Poly(rot(a)), Sh::Poly(rot(b))))
}

fn capsule(rng: &mut Rng, size: f64, c: [f64; 2]) -> Sh {
    let half = size * rng.range(0.2, 0.8);
    let r = r32(size * rng.range(0.1, 0.4));
    let u = rng.unit();
    Sh::Capsule(
        [r32(c[0] - u[0] * half), r32(c[1] - u[1] * half)],
        [r32(c[0] + u[0] * half), r32(c[1] + u[1] * half)],
        r,
    )
}

fn circle(rng: &mut Rng, size: f64, c: [f64; 2]) -> Sh {
    Sh::Circle([r32(c[0]), r32(c[1])], r32(size * rng.range(0.2, 1.0)))
}

/// Rays from outside (and 10% from inside) aimed near the shape, half unbounded.
fn make_ray(rng: &mut Rng, s: &Sh) -> ([f64; 2], [f64; 2], f64) {
    let (c, br) = s.bounds();
    let o = if rng.f() < 0.1 {
        offset(c, rng.unit(), br * rng.range(0.0, 0.5))
    } else {
        offset(c, rng.unit(), br * rng.range(1.1, 3.0))
    };
    let o = [r32(o[0]), r32(o[1])];
    let aim = offset(c, rng.unit(), br * rng.range(0.0, 1.2));
    let d = [r32(aim[0] - o[0]), r32(aim[1] - o[1])];
    let len = d[0].hypot(d[1]);
    let max_len = if rng.f() < 0.5 { 0.0 } else { r32(len * rng.range(0.5, 1.5)) };
    if d == [0.0, 0.0] {
        return ([r32(o[0] + br * 2.0), o[1]], [-1.0, 0.0], 0.0);
    }
    (o, d, max_len)
}

fn pair_l(a: &Sh, b: &Sh) -> f64 {
    a.bounds().1.max(b.bounds().1)
}

fn ray_l(o: [f64; 2], s: &Sh) -> f64 {
    let (c, br) = s.bounds();
    br.max((o[0] - c[0]).hypot(o[1] - c[1]))
}

/// Oracle answers on both cores, once for f32 and f64 alike.
fn solve_pairs(raw: Vec<(Sh, Sh)>) -> Vec<PairCase> {
    parallel_map(raw, |(a, b)| {
        let truth = oracle_pair(&a, &b);
        PairCase { l: pair_l(&a, &b), a, b, truth }
    })
}

fn solve_rays(raw: Vec<([f64; 2], [f64; 2], f64, Sh)>) -> Vec<RayCase> {
    parallel_map(raw, |(o, d, max_len, s)| RayCase {
        truth: oracle_ray(o, d, max_len, &s),
        l: ray_l(o, &s),
        o,
        d,
        max_len,
        s,
    })
}

fn parallel_map<T: Send, U: Send>(v: Vec<T>, f: impl Fn(T) -> U + Sync) -> Vec<U> {
    let threads = std::thread::available_parallelism().map_or(1, |n| n.get()).clamp(1, 8);
    let chunk = v.len().div_ceil(threads).max(1);
    let mut parts: Vec<Vec<T>> = Vec::new();
    let mut it = v.into_iter().peekable();
    while it.peek().is_some() {
        parts.push(it.by_ref().take(chunk).collect());
    }
    let f = &f;
    std::thread::scope(|s| {
        let handles: Vec<_> =
            parts.into_iter().map(|p| s.spawn(move || p.into_iter().map(f).collect::<Vec<U>>())).collect();
        handles.into_iter().flat_map(|h| h.join().unwrap()).collect()
    })
}

/// A family's name, whether it is stiff, its inputs, and how many of them are
/// judged by the oracle (the rest are only timed).
type PairSpec = (String, bool, Vec<(Sh, Sh)>, usize);
type RaySpec = (String, bool, Vec<([f64; 2], [f64; 2], f64, Sh)>, usize);

fn generate(scale: f64) -> Vec<Family> {
    let mut rng = Rng(0x6A6B_3264_2024);
    let n = |k: usize| ((k as f64 * scale).round() as usize).max(4);
    let mut pair_specs: Vec<PairSpec> = Vec::new();
    let poly = |nv: usize, size: f64, aspect: f64| move |r: &mut Rng, c: [f64; 2]| random_poly(r, nv, size, aspect, c);
    let std_pair = |nv: usize, size: f64, aspect: f64, origin: [f64; 2]| {
        move |r: &mut Rng| Some(place_pair(r, &mut poly(nv, size, aspect), &mut poly(nv, size, aspect), origin, size))
    };
    pair_specs.push(pair_family("poly8", false, n(2000), &mut rng, std_pair(8, 1.0, 1.0, [0.0, 0.0])));
    pair_specs.push(pair_family("poly64", false, n(1000), &mut rng, std_pair(64, 1.0, 1.0, [0.0, 0.0])));
    pair_specs.push(pair_family("circle_poly", false, n(2000), &mut rng, |r| {
        Some(place_pair(r, &mut |r, c| circle(r, 1.0, c), &mut poly(8, 1.0, 1.0), [0.0, 0.0], 1.0))
    }));
    pair_specs.push(pair_family("capsule_poly", false, n(2000), &mut rng, |r| {
        Some(place_pair(r, &mut |r, c| capsule(r, 1.0, c), &mut poly(8, 1.0, 1.0), [0.0, 0.0], 1.0))
    }));
    pair_specs.push(pair_family("circle_circle", false, n(2000), &mut rng, |r| {
        Some(place_pair(r, &mut |r, c| circle(r, 1.0, c), &mut |r, c| circle(r, 1.0, c), [0.0, 0.0], 1.0))
    }));
    pair_specs.push(pair_family("ellipse_circle", false, n(2000), &mut rng, |r| {
        let ellipse = |r: &mut Rng, c: [f64; 2]| {
            Sh::Ellipse([r32(c[0]), r32(c[1])], r32(r.range(0.2, 1.0)), r32(r.range(0.2, 1.0)))
        };
        Some(place_pair(r, &mut |r, c| ellipse(r, c), &mut |r, c| circle(r, 0.5, c), [0.0, 0.0], 1.0))
    }));
    pair_specs.push(pair_family("far_1e5", true, n(1000), &mut rng, std_pair(8, 1.0, 1.0, [1e5, -7e4])));
    pair_specs.push(pair_family("tiny_1e-4", true, n(1000), &mut rng, std_pair(8, 1e-4, 1.0, [0.0, 0.0])));
    pair_specs.push(pair_family("huge_1e4", true, n(1000), &mut rng, std_pair(8, 1e4, 1.0, [0.0, 0.0])));
    pair_specs.push(pair_family("sliver_1e-3", true, n(1000), &mut rng, std_pair(8, 1.0, 1e-3, [0.0, 0.0])));
    pair_specs.push(pair_family("touching", true, n(1000), &mut rng, touching_pair));
    pair_specs.push(pair_family("parallel_gap", true, n(1000), &mut rng, parallel_pair));
    pair_specs.push(pair_family("poly1024", true, n(60), &mut rng, std_pair(1024, 1.0, 1.0, [0.0, 0.0])));

    let mut ray_specs: Vec<RaySpec> = Vec::new();
    let mut ray_family = |name: &str, stiff: bool, k: usize, rng: &mut Rng, mk: &dyn Fn(&mut Rng) -> Sh| {
        let mut v = Vec::new();
        while v.len() < k.max(TIMED_CASES) {
            let s = mk(rng);
            if valid(&s) {
                let (o, d, m) = make_ray(rng, &s);
                v.push((o, d, m, s));
            }
        }
        ray_specs.push((name.to_string(), stiff, v, k));
    };
    ray_family("ray_poly8", false, n(1000), &mut rng, &|r| random_poly(r, 8, 1.0, 1.0, [0.0, 0.0]));
    ray_family("ray_poly64", false, n(300), &mut rng, &|r| random_poly(r, 64, 1.0, 1.0, [0.0, 0.0]));
    ray_family("ray_circle", false, n(1000), &mut rng, &|r| circle(r, 1.0, [0.0, 0.0]));
    ray_family("ray_capsule", false, n(600), &mut rng, &|r| capsule(r, 1.0, [0.0, 0.0]));
    ray_family("ray_far_1e5", true, n(500), &mut rng, &|r| random_poly(r, 8, 1.0, 1.0, [1e5, -7e4]));
    ray_family("ray_poly1024", true, n(25), &mut rng, &|r| random_poly(r, 1024, 1.0, 1.0, [0.0, 0.0]));

    let mut out = Vec::new();
    for (name, stiff, mut raw, judged) in pair_specs {
        let t = Instant::now();
        let extra = raw.split_off(judged);
        let cases = solve_pairs(raw);
        eprintln!("[report] oracle: {name:<16} {:5} pairs in {:6.2} s", cases.len(), t.elapsed().as_secs_f64());
        out.push(Family { name, stiff, cases: Cases::Pairs(cases), extra: Extra::Pairs(extra) });
    }
    for (name, stiff, mut raw, judged) in ray_specs {
        let t = Instant::now();
        let extra = raw.split_off(judged);
        let cases = solve_rays(raw);
        eprintln!("[report] oracle: {name:<16} {:5} rays  in {:6.2} s", cases.len(), t.elapsed().as_secs_f64());
        out.push(Family { name, stiff, cases: Cases::Rays(cases), extra: Extra::Rays(extra) });
    }
    out
}

// ---------------------------------------------------------------------------------
// Case files (the format is in docs/speed.md): shapes parsed, answers recomputed by the
// oracle (which also gives margins and normals) and checked against the file's.

fn parse_shape(t: &[&str], i: &mut usize) -> Result<Sh, String> {
    let f = |s: &str| s.parse::<f64>().map_err(|e| format!("{s}: {e}"));
    let kind = t.get(*i).ok_or("missing shape")?;
    *i += 1;
    let take = |i: &mut usize, k: usize| -> Result<Vec<f64>, String> {
        let v =
            t.get(*i..*i + k).ok_or("truncated shape")?.iter().map(|s| f(s)).collect::<Result<Vec<f64>, String>>()?;
        *i += k;
        Ok(v)
    };
    match *kind {
        "poly" => {
            let n: usize = t.get(*i).ok_or("missing count")?.parse().map_err(|e| format!("{e}"))?;
            *i += 1;
            let v = take(i, 2 * n)?;
            Ok(Sh::Poly(v.chunks(2).map(|c| [c[0], c[1]]).collect()))
        }
        "circle" => {
            let v = take(i, 3)?;
            Ok(Sh::Circle([v[0], v[1]], v[2]))
        }
        "capsule" => {
            let v = take(i, 5)?;
            Ok(Sh::Capsule([v[0], v[1]], [v[2], v[3]], v[4]))
        }
        k => Err(format!("unknown shape {k}")),
    }
}

fn load_cases(path: &str) -> Result<Family, String> {
    let text = std::fs::read_to_string(path).map_err(|e| format!("{path}: {e}"))?;
    let mut pairs = Vec::new();
    let mut rays = Vec::new();
    let mut mismatches = 0;
    for (ln, line) in text.lines().enumerate() {
        let t: Vec<&str> = line.split_whitespace().collect();
        if t.is_empty() || t[0].starts_with('#') {
            continue;
        }
        let err = |e: String| format!("{path}:{}: {e}", ln + 1);
        let f = |s: &str| s.parse::<f64>().map_err(|e| err(format!("{s}: {e}")));
        if t[0] == "ray" {
            let mut i = 6;
            let s = parse_shape(&t, &mut i).map_err(err)?;
            let (o, d, m) = ([f(t[1])?, f(t[2])?], [f(t[3])?, f(t[4])?], f(t[5])?);
            if let (Some(st), Some(tt)) = (t.get(i), t.get(i + 1)) {
                rays.push((o, d, m, s, st.to_string(), f(tt)?));
            }
        } else {
            let mut i = 0;
            let a = parse_shape(&t, &mut i).map_err(err)?;
            let b = parse_shape(&t, &mut i).map_err(err)?;
            let (d, p) = (
                f(t.get(i).ok_or_else(|| err("no distance".into()))?)?,
                f(t.get(i + 1).ok_or_else(|| err("no depth".into()))?)?,
            );
            pairs.push((a, b, d, p));
        }
    }
    let name = std::path::Path::new(path).file_stem().map_or("cases".into(), |s| s.to_string_lossy().into_owned());
    let cases = if !rays.is_empty() {
        let given: Vec<(String, f64)> = rays.iter().map(|r| (r.4.clone(), r.5)).collect();
        let cases = solve_rays(rays.into_iter().map(|r| (r.0, r.1, r.2, r.3)).collect());
        for (c, (st, t)) in cases.iter().zip(&given) {
            let v = format!("{:?}", c.truth.verdict).to_lowercase();
            if &v != st || (c.truth.verdict == RayVerdict::Hit && (c.truth.t - t).abs() > 1e-12 * c.l) {
                mismatches += 1;
            }
        }
        Cases::Rays(cases)
    } else {
        let given: Vec<(f64, f64)> = pairs.iter().map(|p| (p.2, p.3)).collect();
        let cases = solve_pairs(pairs.into_iter().map(|p| (p.0, p.1)).collect());
        for (c, (d, p)) in cases.iter().zip(&given) {
            if (c.truth.distance - d).abs() > 1e-12 * c.l || (c.truth.depth - p).abs() > 1e-12 * c.l {
                mismatches += 1;
            }
        }
        Cases::Pairs(cases)
    };
    eprintln!(
        "[report] {path}: answers recomputed by the oracle; {mismatches} differ from the file's by more than 1e-12 L"
    );
    // A file's cases are timed as they are: no more of them to add.
    let extra = match cases {
        Cases::Pairs(_) => Extra::Pairs(Vec::new()),
        Cases::Rays(_) => Extra::Rays(Vec::new()),
    };
    Ok(Family { name: format!("file:{name}"), stiff: false, cases, extra })
}

// ---------------------------------------------------------------------------------
// Accuracy bookkeeping, shared by gjk2d and parry.

#[derive(Clone, Copy, Debug, PartialEq)]
enum Query {
    Intersect,
    Distance,
    Penetration,
    Ray,
}

impl Query {
    fn name(self) -> &'static str {
        match self {
            Query::Intersect => "intersect",
            Query::Distance => "distance",
            Query::Penetration => "penetration",
            Query::Ray => "ray",
        }
    }
}

/// What a query returned, in f64.
enum Out {
    Verdict(bool),
    /// Distance (apart) or depth (overlapping) with its normal; None: the other verdict.
    Value(Option<(f64, [f64; 2])>),
    Ray(RayVerdict, f64, [f64; 2]),
}

#[derive(Clone, Default, Debug)]
struct Acc {
    cases: usize,
    judged: usize,
    wrong: usize,
    errs: Vec<f64>,
    nerrs: Vec<f64>,
    limit: usize,
    capacity: usize,
    nonfinite: usize,
    iters: u64,
    answered: usize,
}

impl Acc {
    fn count_status(&mut self, (s, it): (Status, Option<u32>)) {
        if let Some(it) = it {
            self.iters += it as u64;
            self.answered += 1;
        }
        self.limit += (s == Status::IterationLimit) as usize;
        self.capacity += (s == Status::CapacityLimit) as usize;
    }
    fn max_err(&self) -> f64 {
        self.errs.iter().copied().fold(0.0, f64::max)
    }
    fn med_err(&self) -> f64 {
        median(self.errs.clone())
    }
    fn max_nerr(&self) -> f64 {
        self.nerrs.iter().copied().fold(0.0, f64::max)
    }
}

fn median(mut v: Vec<f64>) -> f64 {
    if v.is_empty() {
        return 0.0;
    }
    v.sort_by(|a, b| a.partial_cmp(b).unwrap());
    v[v.len() / 2]
}

fn angle(a: [f64; 2], b: [f64; 2]) -> f64 {
    let cross = a[0] * b[1] - a[1] * b[0];
    let dot = a[0] * b[0] + a[1] * b[1];
    cross.abs().atan2(dot)
}

fn finite2(v: [f64; 2]) -> bool {
    v[0].is_finite() && v[1].is_finite()
}

fn judge_pair(acc: &mut Acc, q: Query, c: &PairCase, eps: f64, out: Out, status: (Status, Option<u32>)) {
    acc.cases += 1;
    acc.count_status(status);
    let tol = 8.0 * eps * c.l;
    let judged = c.truth.signed.abs() > tol;
    acc.judged += judged as usize;
    let overlap = c.truth.signed <= 0.0;
    match out {
        Out::Verdict(v) => acc.wrong += (judged && v != overlap) as usize,
        Out::Value(v) => {
            let says = v.is_some();
            let want = if q == Query::Distance { !overlap } else { overlap };
            acc.wrong += (judged && says != want) as usize;
            if let Some((x, n)) = v {
                if !x.is_finite() || !finite2(n) {
                    acc.nonfinite += 1;
                    return;
                }
                let truth = if q == Query::Distance { c.truth.distance } else { c.truth.depth };
                if says == want {
                    acc.errs.push((x - truth).abs() / c.l);
                    if judged && c.truth.normal_unique {
                        acc.nerrs.push(angle(n, c.truth.normal));
                    }
                }
            }
        }
        Out::Ray(..) => unreachable!(),
    }
}

fn judge_ray(acc: &mut Acc, c: &RayCase, eps: f64, out: Out, status: (Status, Option<u32>)) {
    let Out::Ray(v, t, n) = out else { unreachable!() };
    acc.cases += 1;
    acc.count_status(status);
    let judged = c.truth.margin > 8.0 * eps * c.l;
    acc.judged += judged as usize;
    acc.wrong += (judged && v != c.truth.verdict) as usize;
    if v == RayVerdict::Hit {
        if !t.is_finite() || !finite2(n) {
            acc.nonfinite += 1;
            return;
        }
        if c.truth.verdict == RayVerdict::Hit {
            acc.errs.push((t - c.truth.t).abs() / c.l);
            if judged && c.truth.normal_unique {
                acc.nerrs.push(angle(n, c.truth.normal));
            }
        }
    }
}

/// Distinct cases per timed pass: a family's judged cases and as many more of the
/// same kind, each asked once per pass. Repeating a small batch would let the
/// branch predictor learn the answers, which flatters branchy code by 2x or more;
/// a physics step or a game frame asks each pair once.
const TIMED_CASES: usize = 16_384;

/// Median over `reps` passes of the time per query; each pass asks every timed
/// case (`n` queries) once.
fn time_batches(n: usize, reps: usize, mut batch: impl FnMut()) -> f64 {
    if n == 0 {
        return f64::NAN;
    }
    batch();
    let v = (0..reps)
        .map(|_| {
            let t = Instant::now();
            batch();
            t.elapsed().as_nanos() as f64 / n as f64
        })
        .collect();
    median(v)
}

/// Like [`time_batches`] for several contenders over the same `n` cases, one pass
/// each in turn within every repeat, in an order that rotates from repeat to
/// repeat: the median time per query of each.
fn time_interleaved(n: usize, reps: usize, batches: &mut [Batch<'_>]) -> Vec<f64> {
    if n == 0 {
        return vec![f64::NAN; batches.len()];
    }
    for b in batches.iter_mut() {
        b();
    }
    let k = batches.len();
    let mut times = vec![Vec::new(); k];
    for rep in 0..reps {
        for j in 0..k {
            let i = (rep + j) % k;
            let t = Instant::now();
            (batches[i])();
            times[i].push(t.elapsed().as_nanos() as f64 / n as f64);
        }
    }
    times.into_iter().map(median).collect()
}

#[derive(Clone, Debug)]
struct Meas {
    acc: Acc,
    ns: f64,
}

// ---------------------------------------------------------------------------------
// gjk2d side.

/// The polygon boxed, as parry's shapes are (`Box<dyn Shape>`): a scene's
/// enum of shapes then costs a circle its own size, not a polygon's.
enum G<R: Real, const N: usize> {
    P(Box<Polygon<R, N>>),
    C(Circle<R>),
    K(Capsule<R>),
    E(Ellipse<R>),
}

struct GS<R: Real, const N: usize> {
    s: G<R, N>,
    t: Transform<R>,
}

fn build_g<R: Real, const N: usize>(sh: &Sh) -> Option<GS<R, N>> {
    let v = |p: &[f64; 2]| R::vector(R::from_f64(p[0]), R::from_f64(p[1]));
    let id = Transform::IDENTITY;
    Some(match sh {
        Sh::Poly(p) => GS { s: G::P(Box::new(Polygon::new(&p.iter().map(v).collect::<Vec<_>>()).ok()?)), t: id },
        Sh::Circle(c, r) => GS { s: G::C(Circle::at(v(c), R::from_f64(*r)).ok()?), t: id },
        Sh::Capsule(a, b, r) => GS { s: G::K(Capsule::new(v(a), v(b), R::from_f64(*r)).ok()?), t: id },
        Sh::Ellipse(c, a, b) => GS {
            s: G::E(Ellipse::new(R::from_f64(2.0 * a), R::from_f64(2.0 * b)).ok()?),
            t: Transform::from_translation(v(c)).ok()?,
        },
    })
}

/// Calls `$body` with `$x`, `$y` bound to the concrete shapes of a pair (static
/// dispatch: every combination the families use is its own monomorphised call).
macro_rules! with_pair {
    ($a:expr, $b:expr, |$x:ident, $y:ident| $body:expr) => {
        match (&$a.s, &$b.s) {
            (G::P(p), G::P(q)) => {
                let ($x, $y) = (&**p, &**q);
                $body
            }
            (G::C($x), G::P(q)) => {
                let $y = &**q;
                $body
            }
            (G::K($x), G::P(q)) => {
                let $y = &**q;
                $body
            }
            (G::C($x), G::C($y)) => $body,
            (G::E($x), G::C($y)) => $body,
            _ => unreachable!("pair kind not used by the report"),
        }
    };
}

macro_rules! with_shape {
    ($a:expr, |$x:ident| $body:expr) => {
        match &$a.s {
            G::P(p) => {
                let $x = &**p;
                $body
            }
            G::C($x) => $body,
            G::K($x) => $body,
            G::E($x) => $body,
        }
    };
}

fn v2<R: Real>(v: R::Vector) -> [f64; 2] {
    let (x, y) = R::components(v);
    [x.to_f64(), y.to_f64()]
}

fn g_pair_query<R: Real, const N: usize>(
    gjk: &Gjk<R>,
    q: Query,
    a: &GS<R, N>,
    b: &GS<R, N>,
) -> (Out, (Status, Option<u32>)) {
    match q {
        Query::Intersect => {
            let d = with_pair!(a, b, |x, y| gjk.intersects(x, &a.t, y, &b.t));
            (Out::Verdict(d.intersecting), (d.status, Some(d.iterations)))
        }
        Query::Distance => {
            let d = with_pair!(a, b, |x, y| gjk.distance(x, &a.t, y, &b.t));
            (
                Out::Value(d.map(|s| (s.distance.to_f64(), v2::<R>(s.normal)))),
                d.map_or((Status::Converged, None), |s| (s.status, Some(s.iterations))),
            )
        }
        Query::Penetration => {
            let p = with_pair!(a, b, |x, y| gjk.penetration(x, &a.t, y, &b.t));
            (
                Out::Value(p.map(|s| (s.depth.to_f64(), v2::<R>(s.normal)))),
                p.map_or((Status::Converged, None), |s| (s.status, Some(s.iterations))),
            )
        }
        Query::Ray => unreachable!(),
    }
}

fn g_ray<R: Real, const N: usize>(gjk: &Gjk<R>, ray: &Ray<R>, max: R, s: &GS<R, N>) -> (Out, (Status, Option<u32>)) {
    let r = with_shape!(s, |x| gjk.raycast(ray, max, x, &s.t));
    let out = match r.outcome {
        RayOutcome::Hit(h) => Out::Ray(RayVerdict::Hit, h.distance.to_f64(), v2::<R>(h.normal)),
        RayOutcome::Miss => Out::Ray(RayVerdict::Miss, 0.0, [0.0; 2]),
        RayOutcome::Inside => Out::Ray(RayVerdict::Inside, 0.0, [0.0; 2]),
    };
    (out, (r.status, Some(r.iterations)))
}

struct GFamily<R: Real, const N: usize> {
    pairs: Vec<(GS<R, N>, GS<R, N>)>,
    rays: Vec<(Ray<R>, R, GS<R, N>)>,
}

fn build_family<R: Real, const N: usize>(f: &Family) -> GFamily<R, N> {
    let v = |p: &[f64; 2]| R::vector(R::from_f64(p[0]), R::from_f64(p[1]));
    match &f.cases {
        Cases::Pairs(c) => GFamily {
            pairs: c
                .iter()
                .map(|c| (&c.a, &c.b))
                .chain(f.extra_pairs().iter().map(|(a, b)| (a, b)))
                .map(|(a, b)| (build_g(a).expect("valid shape"), build_g(b).expect("valid shape")))
                .collect(),
            rays: Vec::new(),
        },
        Cases::Rays(c) => GFamily {
            pairs: Vec::new(),
            rays: c
                .iter()
                .map(|c| (&c.o, &c.d, c.max_len, &c.s))
                .chain(f.extra_rays().iter().map(|(o, d, m, s)| (o, d, *m, s)))
                .map(|(o, d, max_len, s)| {
                    (Ray::new(v(o), v(d)).expect("valid ray"), R::from_f64(max_len), build_g(s).expect("valid shape"))
                })
                .collect(),
        },
    }
}

fn measure_g<R: Real, const N: usize>(f: &Family, gf: &GFamily<R, N>, gjk: &Gjk<R>, q: Query, reps: usize) -> Meas {
    let (acc, n, batch) = accuracy_and_batch_g(f, gf, gjk, q);
    Meas { acc, ns: time_batches(n, reps, batch) }
}

/// A batch: every case of a family once, results black-boxed.
type Batch<'a> = Box<dyn FnMut() + 'a>;

/// The accuracy of every case, and the batch that times them.
fn accuracy_and_batch_g<'a, R: Real, const N: usize>(
    f: &'a Family,
    gf: &'a GFamily<R, N>,
    gjk: &'a Gjk<R>,
    q: Query,
) -> (Acc, usize, Batch<'a>) {
    let eps = R::EPSILON.to_f64();
    let mut acc = Acc::default();
    match &f.cases {
        Cases::Pairs(cases) => {
            for (c, (a, b)) in cases.iter().zip(&gf.pairs) {
                let (out, lim) = g_pair_query(gjk, q, a, b);
                judge_pair(&mut acc, q, c, eps, out, lim);
            }
            let batch: Batch<'a> = Box::new(move || {
                for (a, b) in gf.pairs.iter().take(TIMED_CASES) {
                    let (a, b) = (black_box(a), black_box(b));
                    match q {
                        Query::Intersect => {
                            black_box(with_pair!(a, b, |x, y| gjk.intersects(x, &a.t, y, &b.t)));
                        }
                        Query::Distance => {
                            black_box(with_pair!(a, b, |x, y| gjk.distance(x, &a.t, y, &b.t)));
                        }
                        Query::Penetration => {
                            black_box(with_pair!(a, b, |x, y| gjk.penetration(x, &a.t, y, &b.t)));
                        }
                        Query::Ray => unreachable!(),
                    }
                }
            });
            (acc, gf.pairs.len().min(TIMED_CASES), batch)
        }
        Cases::Rays(cases) => {
            for (c, (ray, max, s)) in cases.iter().zip(&gf.rays) {
                let (out, lim) = g_ray(gjk, ray, *max, s);
                judge_ray(&mut acc, c, eps, out, lim);
            }
            let batch: Batch<'a> = Box::new(move || {
                for (ray, max, s) in gf.rays.iter().take(TIMED_CASES) {
                    let s = black_box(s);
                    black_box(with_shape!(s, |x| gjk.raycast(black_box(ray), *max, x, &s.t)));
                }
            });
            (acc, gf.rays.len().min(TIMED_CASES), batch)
        }
    }
}

// ---------------------------------------------------------------------------------
// parry side: the same measurement for parry2d (f32) and parry2d-f64, through its
// public dyn-Shape API (identity poses, shapes given in world coordinates).

macro_rules! parry_side {
    ($m:ident, $p:ident, $R:ty) => {
        mod $m {
            use super::{
                judge_pair, judge_ray, Acc, Batch, Cases, Family, Out, Query, RayVerdict, Sh, Status, TIMED_CASES,
            };
            use std::hint::black_box;
            use $p::math::{Pose, Vector};
            use $p::query::{self, Ray};
            use $p::shape::{Ball, Capsule, ConvexPolygon, Shape};

            pub struct PS {
                s: Box<dyn Shape>,
                pos: Pose,
            }

            fn v(p: &[f64; 2]) -> Vector {
                Vector::new(p[0] as $R, p[1] as $R)
            }

            /// `None` for ellipses (parry has none). Polygons keep every vertex
            /// (`from_convex_polyline_unmodified`; `from_convex_polyline` would drop
            /// vertices whose edges turn by less than sqrt(eps), changing the shape).
            pub fn build(sh: &Sh) -> Option<PS> {
                Some(match sh {
                    Sh::Poly(p) => PS {
                        s: Box::new(ConvexPolygon::from_convex_polyline_unmodified(p.iter().map(v).collect())?),
                        pos: Pose::identity(),
                    },
                    Sh::Circle(c, r) => PS { s: Box::new(Ball::new(*r as $R)), pos: Pose::from_translation(v(c)) },
                    Sh::Capsule(a, b, r) => {
                        PS { s: Box::new(Capsule::new(v(a), v(b), *r as $R)), pos: Pose::identity() }
                    }
                    Sh::Ellipse(..) => return None,
                })
            }

            fn w(x: Vector) -> [f64; 2] {
                [x.x as f64, x.y as f64]
            }

            fn pair_query(q: Query, a: &PS, b: &PS) -> Out {
                match q {
                    Query::Intersect => Out::Verdict(
                        query::intersection_test(&a.pos, &*a.s, &b.pos, &*b.s).map_or(false, |i| i.intersecting),
                    ),
                    Query::Distance => {
                        // parry reports 0 for overlap; its normal comes from closest points.
                        match query::distance(&a.pos, &*a.s, &b.pos, &*b.s) {
                            Ok(d) if d.distance > 0.0 => {
                                let n = match query::closest_points(&a.pos, &*a.s, &b.pos, &*b.s, <$R>::MAX) {
                                    Ok(query::ClosestPoints::WithinMargin(p1, p2)) => {
                                        let d = p2 - p1;
                                        w(d / d.length())
                                    }
                                    _ => [f64::NAN; 2],
                                };
                                Out::Value(Some((d.distance as f64, n)))
                            }
                            _ => Out::Value(None),
                        }
                    }
                    Query::Penetration => match query::contact(&a.pos, &*a.s, &b.pos, &*b.s, 0.0) {
                        Ok(Some(c)) if c.dist <= 0.0 => Out::Value(Some((-(c.dist as f64), w(c.normal1)))),
                        _ => Out::Value(None),
                    },
                    Query::Ray => unreachable!(),
                }
            }

            fn ray_query(ray: &Ray, max: $R, s: &PS) -> Out {
                match s.s.cast_ray_and_get_normal(&s.pos, ray, max, true) {
                    Some(h) if h.time_of_impact == 0.0 => Out::Ray(RayVerdict::Inside, 0.0, [0.0; 2]),
                    Some(h) => Out::Ray(RayVerdict::Hit, h.time_of_impact as f64, w(h.normal)),
                    None => Out::Ray(RayVerdict::Miss, 0.0, [0.0; 2]),
                }
            }

            pub enum PFamily {
                Pairs(Vec<(PS, PS)>),
                Rays(Vec<(Ray, $R, PS)>),
                Unsupported,
            }

            pub fn build_family(f: &Family) -> PFamily {
                match &f.cases {
                    Cases::Pairs(c) => {
                        let v: Option<Vec<(PS, PS)>> = c
                            .iter()
                            .map(|c| (&c.a, &c.b))
                            .chain(f.extra_pairs().iter().map(|(a, b)| (a, b)))
                            .map(|(a, b)| Some((build(a)?, build(b)?)))
                            .collect();
                        v.map_or(PFamily::Unsupported, PFamily::Pairs)
                    }
                    Cases::Rays(c) => {
                        let v: Option<Vec<(Ray, $R, PS)>> = c
                            .iter()
                            .map(|c| (&c.o, &c.d, c.max_len, &c.s))
                            .chain(f.extra_rays().iter().map(|(o, d, m, s)| (o, d, *m, s)))
                            .map(|(o, d, max_len, s)| {
                                let d = v(d);
                                let max = if max_len > 0.0 { max_len as $R } else { <$R>::MAX };
                                Some((Ray::new(v(o), d / d.length()), max, build(s)?))
                            })
                            .collect();
                        v.map_or(PFamily::Unsupported, PFamily::Rays)
                    }
                }
            }

            pub fn accuracy_and_batch<'a>(f: &'a Family, pf: &'a PFamily, q: Query) -> Option<(Acc, usize, Batch<'a>)> {
                let eps = <$R>::EPSILON as f64;
                let mut acc = Acc::default();
                match (&f.cases, pf) {
                    (Cases::Pairs(cases), PFamily::Pairs(shapes)) => {
                        for (c, (a, b)) in cases.iter().zip(shapes) {
                            judge_pair(&mut acc, q, c, eps, pair_query(q, a, b), (Status::Converged, None));
                        }
                        let batch: Batch<'a> = Box::new(move || {
                            for (a, b) in shapes.iter().take(TIMED_CASES) {
                                let (a, b) = (black_box(a), black_box(b));
                                match q {
                                    Query::Intersect => {
                                        let _ = black_box(query::intersection_test(&a.pos, &*a.s, &b.pos, &*b.s));
                                    }
                                    Query::Distance => {
                                        let _ = black_box(query::distance(&a.pos, &*a.s, &b.pos, &*b.s));
                                    }
                                    Query::Penetration => {
                                        let _ = black_box(query::contact(&a.pos, &*a.s, &b.pos, &*b.s, 0.0));
                                    }
                                    Query::Ray => unreachable!(),
                                }
                            }
                        });
                        Some((acc, shapes.len().min(TIMED_CASES), batch))
                    }
                    (Cases::Rays(cases), PFamily::Rays(rays)) => {
                        for (c, (ray, max, s)) in cases.iter().zip(rays) {
                            judge_ray(&mut acc, c, eps, ray_query(ray, *max, s), (Status::Converged, None));
                        }
                        let batch: Batch<'a> = Box::new(move || {
                            for (ray, max, s) in rays.iter().take(TIMED_CASES) {
                                let s = black_box(s);
                                black_box(s.s.cast_ray_and_get_normal(&s.pos, black_box(ray), *max, true));
                            }
                        });
                        Some((acc, rays.len().min(TIMED_CASES), batch))
                    }
                    _ => None,
                }
            }
        }
    };
}

parry_side!(parry32, parry2d, f32);
parry_side!(parry64, parry2d_f64, f64);

// ---------------------------------------------------------------------------------
// One family: every query, both precisions, both libraries.

struct Row {
    family: String,
    stiff: bool,
    query: Query,
    prec: &'static str,
    ours: Meas,
    parry: Option<Meas>,
    eps: f64,
}

fn queries_of(f: &Family) -> &'static [Query] {
    match f.cases {
        Cases::Pairs(_) => &[Query::Intersect, Query::Penetration, Query::Distance],
        Cases::Rays(_) => &[Query::Ray],
    }
}

fn max_vertices(f: &Family) -> usize {
    match &f.cases {
        Cases::Pairs(c) => c.iter().map(|c| c.a.vertex_count().max(c.b.vertex_count())).max().unwrap_or(0),
        Cases::Rays(c) => c.iter().map(|c| c.s.vertex_count()).max().unwrap_or(0),
    }
}

fn run_family<const N: usize>(f: &Family, reps: usize, rows: &mut Vec<Row>) {
    let g32 = build_family::<f32, N>(f);
    let g64 = build_family::<f64, N>(f);
    let p32 = parry32::build_family(f);
    let p64 = parry64::build_family(f);
    let (gjk32, gjk64) = (Gjk::<f32>::new(), Gjk::<f64>::new());
    for &q in queries_of(f) {
        // The four contenders' batches run in turn within every repeat, so a change
        // in machine load falls on all of them alike.
        let (a32, n, b32) = accuracy_and_batch_g(f, &g32, &gjk32, q);
        let (a64, _, b64) = accuracy_and_batch_g(f, &g64, &gjk64, q);
        let mut batches = vec![b32, b64];
        let mut parry_acc = Vec::new();
        for pr in [parry32::accuracy_and_batch(f, &p32, q), parry64::accuracy_and_batch(f, &p64, q)] {
            match pr {
                Some((acc, _, b)) => {
                    parry_acc.push(Some(acc));
                    batches.push(b);
                }
                None => parry_acc.push(None),
            }
        }
        let ns = time_interleaved(n, reps, &mut batches);
        let mut k = 2;
        let mut parry = |acc: Option<Acc>| {
            acc.map(|acc| {
                k += 1;
                Meas { acc, ns: ns[k - 1] }
            })
        };
        let (p32m, p64m) = (parry(parry_acc[0].take()), parry(parry_acc[1].take()));
        for (prec, acc, ns, parry, eps) in
            [("f32", a32, ns[0], p32m, f32::EPSILON as f64), ("f64", a64, ns[1], p64m, f64::EPSILON)]
        {
            rows.push(Row {
                family: f.name.clone(),
                stiff: f.stiff,
                query: q,
                prec,
                ours: Meas { acc, ns },
                parry,
                eps,
            });
        }
    }
}

// ---------------------------------------------------------------------------------
// Error against run time.

struct SweepPoint {
    line: String,
    family: String,
    query: Query,
    prec: &'static str,
    imp: &'static str,
    setting: String,
    ns: f64,
    max_err: f64,
    med_err: f64,
    wrong: usize,
    limit: usize,
}

fn sweep_family<R: Real, const N: usize>(f: &Family, prec: &'static str, reps: usize, out: &mut Vec<SweepPoint>) {
    let gf = build_family::<R, N>(f);
    let mut point = |line: String, q: Query, setting: String, gjk: &Gjk<R>| {
        let m = measure_g(f, &gf, gjk, q, reps);
        out.push(SweepPoint {
            line,
            family: f.name.clone(),
            query: q,
            prec,
            imp: "gjk2d",
            setting,
            ns: m.ns,
            max_err: m.acc.max_err(),
            med_err: m.acc.med_err(),
            wrong: m.acc.wrong,
            limit: m.acc.limit + m.acc.capacity,
        });
    };
    let epsilons = [1e-2, 1e-4, 1e-6, 1e-8, 1e-10, 1e-12];
    let limits = [5u32, 8, 12, 16, 24, 32, 64];
    let name = &f.name;
    match (name.as_str(), &f.cases) {
        (_, Cases::Pairs(_)) => {
            for q in [Query::Distance, Query::Penetration] {
                for e in epsilons {
                    let mut gjk = Gjk::<R>::new();
                    if q == Query::Distance {
                        gjk.config.set_distance_epsilon(R::from_f64(e)).unwrap();
                    } else {
                        let mut epa = EpaConfig::default();
                        epa.set_epsilon(R::from_f64(e)).unwrap();
                        gjk.solver = gjk2d::Epa::new(epa);
                    }
                    let what = if q == Query::Distance { "distance eps" } else { "EPA eps" };
                    point(format!("{prec} {name} {} ({what} 1e-2..1e-12)", q.name()), q, format!("{what} {e:e}"), &gjk);
                }
                for n in limits {
                    let mut gjk = Gjk::<R>::new();
                    if q == Query::Distance {
                        gjk.config.set_max_distance_iterations(n).unwrap();
                    } else {
                        let mut epa = EpaConfig::default();
                        epa.set_max_iterations(n).unwrap();
                        gjk.solver = gjk2d::Epa::new(epa);
                    }
                    let what = if q == Query::Distance { "GJK iterations" } else { "EPA iterations" };
                    point(format!("{prec} {name} {} ({what} 5..64)", q.name()), q, format!("{what} {n}"), &gjk);
                }
            }
        }
        (_, Cases::Rays(_)) => {
            let mut closed = Gjk::<R>::new();
            closed.closed_form_rays = true;
            point(format!("{prec} {name} ray (closed form vs iterative)"), Query::Ray, "closed form".into(), &closed);
            for e in epsilons {
                let mut gjk = Gjk::<R>::new();
                gjk.closed_form_rays = false;
                gjk.config.set_raycast_epsilon(R::from_f64(e)).unwrap();
                point(
                    format!("{prec} {name} ray (iterative, raycast eps 1e-2..1e-12)"),
                    Query::Ray,
                    format!("raycast eps {e:e}"),
                    &gjk,
                );
            }
            let mut iter = Gjk::<R>::new();
            iter.closed_form_rays = false;
            point(
                format!("{prec} {name} ray (closed form vs iterative)"),
                Query::Ray,
                "iterative (default eps)".into(),
                &iter,
            );
        }
    }
    let _ = GjkConfig::<R>::default();
}

fn sweep(families: &[Family], rows: &[Row], reps: usize) -> Vec<SweepPoint> {
    let mut pts = Vec::new();
    for f in
        families.iter().filter(|f| ["ellipse_circle", "poly64", "ray_circle", "ray_poly8"].contains(&f.name.as_str()))
    {
        eprintln!("[report] sweep: {}", f.name);
        sweep_family::<f32, 64>(f, "f32", reps, &mut pts);
        sweep_family::<f64, 64>(f, "f64", reps, &mut pts);
        for r in rows.iter().filter(|r| r.family == f.name) {
            if let Some(p) = &r.parry {
                if r.query == Query::Intersect {
                    continue;
                }
                pts.push(SweepPoint {
                    line: format!("parry {} {} {}", r.prec, r.family, r.query.name()),
                    family: r.family.clone(),
                    query: r.query,
                    prec: r.prec,
                    imp: "parry2d",
                    setting: "default".into(),
                    ns: p.ns,
                    max_err: p.acc.max_err(),
                    med_err: p.acc.med_err(),
                    wrong: p.acc.wrong,
                    limit: p.acc.limit + p.acc.capacity,
                });
            }
        }
    }
    pts
}

fn write_sweep(dir: &std::path::Path, pts: &[SweepPoint]) -> Result<(), Box<dyn std::error::Error>> {
    let mut csv = String::from("line,family,query,precision,impl,setting,ns_per_query,max_err_rel_L,median_err_rel_L,wrong_verdicts,limit_hits_iteration_or_capacity\n");
    for p in pts {
        writeln!(
            csv,
            "\"{}\",{},{},{},{},{},{:.2},{:e},{:e},{},{}",
            p.line,
            p.family,
            p.query.name(),
            p.prec,
            p.imp,
            p.setting,
            p.ns,
            p.max_err,
            p.med_err,
            p.wrong,
            p.limit
        )?;
    }
    std::fs::write(dir.join("sweep.csv"), csv)?;

    use plotters::prelude::*;
    // One panel per (family, query): a line per setting family and precision, a
    // triangle per peer (parry2d, parry2d-f64) at its defaults.
    let floor = 1e-17;
    let y = |e: f64| e.max(floor);
    let mut panels: Vec<(String, Query)> = Vec::new();
    for p in pts {
        if !panels.contains(&(p.family.clone(), p.query)) {
            panels.push((p.family.clone(), p.query));
        }
    }
    let path = dir.join("sweep.svg");
    let cols = 2usize;
    let rows_n = panels.len().div_ceil(cols).max(1);
    let root = SVGBackend::new(&path, (1400, 520 * rows_n as u32)).into_drawing_area();
    root.fill(&WHITE)?;
    let root = root.titled(
        "gjk2d: max error / L against ns per query, log-log (an error of 0 is drawn at 1e-17)",
        ("sans-serif", 22),
    )?;
    let areas = root.split_evenly((rows_n, cols));
    for ((family, query), area) in panels.iter().zip(areas.iter()) {
        let mine: Vec<&SweepPoint> = pts.iter().filter(|p| &p.family == family && p.query == *query).collect();
        let (mut xmin, mut xmax, mut ymin) = (f64::MAX, 0f64, 1f64);
        for p in &mine {
            xmin = xmin.min(p.ns);
            xmax = xmax.max(p.ns);
            ymin = ymin.min(y(p.max_err));
        }
        let mut chart = ChartBuilder::on(area)
            .caption(format!("{family}: {}", query.name()), ("sans-serif", 18))
            .margin(12)
            .x_label_area_size(40)
            .y_label_area_size(65)
            .build_cartesian_2d((xmin * 0.8..xmax * 1.25).log_scale(), (ymin * 0.3..1.0).log_scale())?;
        chart
            .configure_mesh()
            .x_desc("ns per query")
            .y_desc("max error / L")
            .y_label_formatter(&|v| format!("{v:.0e}"))
            .x_label_formatter(&|v| format!("{v:.0}"))
            .draw()?;
        let mut lines: Vec<&str> = Vec::new();
        for p in &mine {
            if !lines.contains(&p.line.as_str()) {
                lines.push(&p.line);
            }
        }
        for (i, line) in lines.iter().enumerate() {
            let color = Palette99::pick(i).to_rgba();
            let ps: Vec<(f64, f64)> = mine.iter().filter(|p| p.line == *line).map(|p| (p.ns, y(p.max_err))).collect();
            let label = line.replacen(&format!(" {family}"), "", 1);
            if line.starts_with("parry") {
                chart
                    .draw_series(PointSeries::of_element(ps, 8, color, &|c, s, st| {
                        TriangleMarker::new(c, s, st.filled())
                    }))?
                    .label(label)
                    .legend(move |(x, y)| TriangleMarker::new((x + 10, y), 5, color.filled()));
            } else {
                chart
                    .draw_series(LineSeries::new(ps.clone(), color.stroke_width(2)))?
                    .label(label)
                    .legend(move |(x, y)| PathElement::new(vec![(x, y), (x + 20, y)], color.stroke_width(2)));
                chart.draw_series(PointSeries::of_element(ps, 3, color, &|c, s, st| Circle::new(c, s, st.filled())))?;
            }
        }
        chart
            .configure_series_labels()
            .position(SeriesLabelPosition::LowerLeft)
            .label_font(("sans-serif", 12))
            .background_style(WHITE.mix(0.8))
            .border_style(BLACK)
            .draw()?;
    }
    root.present()?;
    Ok(())
}

// ---------------------------------------------------------------------------------
// Tables.

fn sci(x: f64) -> String {
    if x == 0.0 {
        "0".into()
    } else if x.is_nan() {
        "-".into()
    } else {
        format!("{x:.1e}")
    }
}

const HEADER: [&str; 18] = [
    "family",
    "query",
    "prec",
    "cases",
    "wrong",
    "max err/L",
    "med err/L",
    "max normal (rad)",
    "ns/query",
    "mean iters",
    "iter-limit",
    "NaN/inf",
    "parry wrong",
    "parry max err/L",
    "parry med err/L",
    "parry normal (rad)",
    "parry ns/query",
    "parry/ours time",
];

fn table_rows(rows: &[Row]) -> Vec<Vec<String>> {
    rows.iter()
        .map(|r| {
            let o = &r.ours;
            let mut v = vec![
                r.family.clone(),
                r.query.name().to_string(),
                r.prec.to_string(),
                o.acc.cases.to_string(),
                o.acc.wrong.to_string(),
                sci(o.acc.max_err()),
                sci(o.acc.med_err()),
                sci(o.acc.max_nerr()),
                format!("{:.0}", o.ns),
                if o.acc.answered > 0 {
                    format!("{:.1}", o.acc.iters as f64 / o.acc.answered as f64)
                } else {
                    "-".into()
                },
                if o.acc.capacity > 0 {
                    format!("{} +{} capacity", o.acc.limit, o.acc.capacity)
                } else {
                    o.acc.limit.to_string()
                },
                o.acc.nonfinite.to_string(),
            ];
            match &r.parry {
                Some(p) => v.extend([
                    format!(
                        "{}{}",
                        p.acc.wrong,
                        if p.acc.nonfinite > 0 { format!(" ({} NaN)", p.acc.nonfinite) } else { String::new() }
                    ),
                    sci(p.acc.max_err()),
                    sci(p.acc.med_err()),
                    sci(p.acc.max_nerr()),
                    format!("{:.0}", p.ns),
                    format!("{:.2}", p.ns / o.ns),
                ]),
                None => v.extend([
                    "n/a (no ellipse in parry)".into(),
                    "-".into(),
                    "-".into(),
                    "-".into(),
                    "-".into(),
                    "-".into(),
                ]),
            }
            v
        })
        .collect()
}

fn plain_table(header: &[&str], rows: &[Vec<String>]) -> String {
    let mut w: Vec<usize> = header.iter().map(|h| h.len()).collect();
    for r in rows {
        for (i, c) in r.iter().enumerate() {
            w[i] = w[i].max(c.len());
        }
    }
    let mut s = String::new();
    let line = |s: &mut String, cells: Vec<&str>| {
        for (i, c) in cells.iter().enumerate() {
            let _ = write!(s, "{:>w$} ", c, w = w[i]);
        }
        s.push('\n');
    };
    line(&mut s, header.to_vec());
    for r in rows {
        line(&mut s, r.iter().map(|c| c.as_str()).collect());
    }
    s
}

fn md_table(header: &[&str], rows: &[Vec<String>]) -> String {
    let mut s = format!("| {} |\n|{}\n", header.join(" | "), "---|".repeat(header.len()));
    for r in rows {
        let _ = writeln!(s, "| {} |", r.join(" | "));
    }
    s
}

/// The stiff families: everything that can go wrong, per family and precision, and the
/// bound on the value error that held (as a multiple of eps L).
fn stability(rows: &[Row]) -> (Vec<&'static str>, Vec<Vec<String>>) {
    let header = vec![
        "family",
        "prec",
        "cases",
        "wrong verdicts",
        "NaN/inf",
        "iter-limit",
        "worst err/L",
        "bound held",
        "parry wrong",
        "parry worst err/L",
        "parry bound",
    ];
    let mut out = Vec::new();
    let mut keys: Vec<(String, &str)> = Vec::new();
    for r in rows.iter().filter(|r| r.stiff) {
        if !keys.contains(&(r.family.clone(), r.prec)) {
            keys.push((r.family.clone(), r.prec));
        }
    }
    let bound = |worst: f64, eps: f64| {
        let m = worst / eps;
        if m <= 8.0 {
            "held: 8 eps L".to_string()
        } else {
            format!("{:.3} eps L", m)
        }
    };
    for (fam, prec) in keys {
        let rs: Vec<&Row> = rows.iter().filter(|r| r.family == fam && r.prec == prec).collect();
        let eps = rs[0].eps;
        let cases = rs[0].ours.acc.cases;
        let sum = |f: &dyn Fn(&Acc) -> usize| rs.iter().map(|r| f(&r.ours.acc)).sum::<usize>();
        let worst = rs.iter().map(|r| r.ours.acc.max_err()).fold(0.0, f64::max);
        let pw: usize = rs.iter().filter_map(|r| r.parry.as_ref()).map(|p| p.acc.wrong + p.acc.nonfinite).sum();
        let pworst = rs.iter().filter_map(|r| r.parry.as_ref()).map(|p| p.acc.max_err()).fold(0.0, f64::max);
        out.push(vec![
            fam,
            prec.to_string(),
            cases.to_string(),
            sum(&|a| a.wrong).to_string(),
            sum(&|a| a.nonfinite).to_string(),
            sum(&|a| a.limit + a.capacity).to_string(),
            sci(worst),
            bound(worst, eps),
            pw.to_string(),
            sci(pworst),
            bound(pworst, eps),
        ]);
    }
    (header, out)
}

/// Time ratios against the issue's targets, as geometric means over families.
/// Issue 27's targets: our time / parry's, per family, query and precision, each
/// timed predictor-cold in the same run.
fn targets(rows: &[Row]) -> String {
    // (family, intersect, distance, penetration) goals; rays have one.
    const PAIR_GOALS: [(&str, f64, f64, f64); 6] = [
        ("poly8", 0.4, 0.5, 0.35),
        ("poly64", 0.3, 0.3, 0.3),
        ("poly1024", 0.1, 0.1, 0.1),
        ("circle_poly", 0.3, 0.3, 0.3),
        ("capsule_poly", 0.3, 0.3, 0.3),
        ("circle_circle", 1.0, 1.0, 1.0),
    ];
    const RAY_GOALS: [(&str, f64); 2] = [("ray_poly8", 0.25), ("ray_circle", 1.0)];
    let mut s = String::from("| family | query | goal | f32 | f64 | |\n|---|---|---:|---:|---:|---|\n");
    let mut line = |family: &str, q: Query, goal: f64| {
        let ratio = |prec: &str| {
            rows.iter()
                .find(|r| r.family == family && r.query == q && r.prec == prec)
                .and_then(|r| r.parry.as_ref().map(|p| r.ours.ns / p.ns))
                .unwrap_or(f64::NAN)
        };
        let (a, b) = (ratio("f32"), ratio("f64"));
        let met = a <= goal && b <= goal;
        let _ = writeln!(
            s,
            "| {family} | {} | <= {goal} | {a:.2} | {b:.2} | {} |",
            q.name(),
            if met { "met" } else { "MISSED" }
        );
    };
    for (family, i, d, p) in PAIR_GOALS {
        line(family, Query::Intersect, i);
        line(family, Query::Distance, d);
        line(family, Query::Penetration, p);
    }
    for (family, goal) in RAY_GOALS {
        line(family, Query::Ray, goal);
    }
    let slower: Vec<String> = rows
        .iter()
        .filter_map(|r| {
            let x = r.ours.ns / r.parry.as_ref()?.ns;
            (x > 1.0).then(|| format!("{} {} {} ({x:.2})", r.family, r.query.name(), r.prec))
        })
        .collect();
    let _ =
        writeln!(s, "\nSlower than parry: {}.", if slower.is_empty() { "none".to_string() } else { slower.join(", ") });
    s
}

fn today() -> String {
    let secs = std::time::SystemTime::now().duration_since(std::time::UNIX_EPOCH).map_or(0, |d| d.as_secs()) as i64;
    // Howard Hinnant's civil_from_days.
    let z = secs.div_euclid(86_400) + 719_468;
    let era = z.div_euclid(146_097);
    let doe = z - era * 146_097;
    let yoe = (doe - doe / 1460 + doe / 36_524 - doe / 146_096) / 365;
    let doy = doe - (365 * yoe + yoe / 4 - yoe / 100);
    let mp = (5 * doy + 2) / 153;
    let d = doy - (153 * mp + 2) / 5 + 1;
    let m = if mp < 10 { mp + 3 } else { mp - 9 };
    let y = yoe + era * 400 + (m <= 2) as i64;
    format!("{y:04}-{m:02}-{d:02}")
}

fn machine() -> String {
    let model = std::fs::read_to_string("/proc/cpuinfo")
        .ok()
        .and_then(|s| {
            s.lines()
                .find(|l| l.starts_with("model name"))
                .and_then(|l| l.split(':').nth(1))
                .map(|m| m.trim().to_string())
        })
        .unwrap_or_else(|| "unknown CPU".into());
    let n = std::thread::available_parallelism().map_or(1, |n| n.get());
    format!("{model}, {n} cores")
}

// ---------------------------------------------------------------------------------

/// Writes every generated family (ellipses excepted: the format has none) as a case
/// file (docs/speed.md has the format), for tests and for reproducing a row of the table.
fn save_cases(dir: &std::path::Path, families: &[Family]) -> std::io::Result<()> {
    std::fs::create_dir_all(dir)?;
    for f in families.iter().filter(|f| !f.name.starts_with("file:")) {
        let mut s = String::new();
        match &f.cases {
            Cases::Pairs(c) => {
                for c in c {
                    if matches!(c.a, Sh::Ellipse(..)) {
                        continue;
                    }
                    let mut t = Vec::new();
                    c.a.tokens(&mut t);
                    c.b.tokens(&mut t);
                    let _ = writeln!(s, "{} {:?} {:?}", t.join(" "), c.truth.distance, c.truth.depth);
                }
            }
            Cases::Rays(c) => {
                for c in c {
                    let mut t = Vec::new();
                    c.s.tokens(&mut t);
                    let (st, tt, n) = match c.truth.verdict {
                        RayVerdict::Hit => ("hit", c.truth.t, c.truth.normal),
                        RayVerdict::Miss => ("miss", 0.0, [0.0; 2]),
                        RayVerdict::Inside => ("inside", 0.0, [0.0; 2]),
                    };
                    let _ = writeln!(
                        s,
                        "ray {:?} {:?} {:?} {:?} {:?} {} {st} {tt:?} {:?} {:?}",
                        c.o[0],
                        c.o[1],
                        c.d[0],
                        c.d[1],
                        c.max_len,
                        t.join(" "),
                        n[0],
                        n[1]
                    );
                }
            }
        }
        if !s.is_empty() {
            std::fs::write(dir.join(format!("{}.txt", f.name)), s)?;
        }
    }
    Ok(())
}

fn main() {
    let mut scale = 4.0;
    let mut reps = 31;
    let mut mode = "default";
    let mut files: Vec<String> = Vec::new();
    let mut out_dir = "target/report".to_string();
    let mut save_dir: Option<String> = None;
    let mut args = std::env::args().skip(1);
    while let Some(a) = args.next() {
        match a.as_str() {
            "--quick" => {
                scale = 0.15;
                reps = 9;
                mode = "quick";
            }
            "--long" => {
                scale = 4.0;
                reps = 61;
                mode = "long";
            }
            "--cases" => files.push(args.next().expect("--cases FILE")),
            "--out" => out_dir = args.next().expect("--out DIR"),
            "--save-cases" => save_dir = Some(args.next().expect("--save-cases DIR")),
            "-h" | "--help" => {
                println!("usage: report [--quick | --long] [--cases FILE]... [--out DIR] [--save-cases DIR]");
                return;
            }
            other => {
                eprintln!("unknown argument {other}; try --help");
                std::process::exit(2);
            }
        }
    }
    let start = Instant::now();
    let mut families = generate(scale);
    for f in &files {
        match load_cases(f) {
            Ok(fam) => families.push(fam),
            Err(e) => {
                eprintln!("[report] {e}");
                std::process::exit(1);
            }
        }
    }
    let mut rows = Vec::new();
    for f in &families {
        let t = Instant::now();
        match max_vertices(f) {
            0..=16 => run_family::<16>(f, reps, &mut rows),
            17..=64 => run_family::<64>(f, reps, &mut rows),
            _ => run_family::<1100>(f, reps, &mut rows),
        }
        eprintln!("[report] measured {:<16} in {:5.2} s", f.name, t.elapsed().as_secs_f64());
    }
    let sweep_pts = sweep(&families, &rows, reps.min(5));

    let table = table_rows(&rows);
    let (sh, st) = stability(&rows);
    let tg = targets(&rows);
    let notes = "Errors are relative to L, the larger bounding radius of the pair; for rays L = max(bounding radius, distance from the ray origin to the shape's center). \
A verdict is wrong only where the exact margin exceeds 8 eps L (eps of the precision). \
Value errors are taken where the query and the exact answer agree on the verdict; normal errors where the exact normal is unique. \
Exact answers: gjk2d-oracle (rational arithmetic), except ellipse_circle (Eberly's point-to-ellipse distance, bisected to the last f64 bit). \
parry2d 0.31 / parry2d-f64 0.31 through their public dyn-Shape API: intersection_test, distance (normal from closest_points), contact with prediction 0 for penetration, cast_ray_and_get_normal (solid) for rays; polygons built with from_convex_polyline_unmodified. \
parry has no ellipse. mean iters: GJK (+EPA) or ray-cast iterations reported by gjk2d, averaged over the queries that returned a result (0 for closed-form rays). iter-limit: results with Status::IterationLimit (\"+N capacity\": EPA's polytope filled, Status::CapacityLimit). ns/query: median over passes, each pass asking 16,384 distinct cases of the family once (its judged cases and more of the same kind, so the branch predictor cannot learn them; files: their own cases), gjk2d f32/f64 and parry f32/f64 passes interleaved in rotating order, single thread.";
    println!("\ngjk2d error against run time ({mode} run, {}, {})\n", today(), machine());
    println!("{}", plain_table(&HEADER, &table));
    println!("Stiff families (all queries together):\n");
    println!("{}", plain_table(&sh, &st));
    println!("Targets (our time / parry's, predictor-cold, same run; all at the accuracy in the table above):\n");
    println!("{tg}");
    println!("{notes}\n");

    let dir = std::path::Path::new(&out_dir);
    if let Err(e) = std::fs::create_dir_all(dir) {
        eprintln!("[report] cannot create {out_dir}: {e}");
        std::process::exit(1);
    }
    let md = format!(
        "# gjk2d: error against run time\n\n{mode} run of `cargo run --release --example report`, {}, on {}.\n\n{}\n## Stiff families\n\n{}\n## Targets\n\n{}\n{}\n\nThe sweep (error against time as settings vary) is in `sweep.csv` and `sweep.svg`.\n",
        today(),
        machine(),
        md_table(&HEADER, &table),
        md_table(&sh, &st),
        tg,
        notes
    );
    let written = std::fs::write(dir.join("report.md"), md)
        .map_err(|e| e.to_string())
        .and_then(|_| write_sweep(dir, &sweep_pts).map_err(|e| e.to_string()));
    match written {
        Ok(()) => eprintln!(
            "[report] wrote {out_dir}/report.md, sweep.csv, sweep.svg in {:.1} s total",
            start.elapsed().as_secs_f64()
        ),
        Err(e) => {
            eprintln!("[report] writing {out_dir}: {e}");
            std::process::exit(1);
        }
    }
    if let Some(save) = save_dir {
        if let Err(e) = save_cases(std::path::Path::new(&save), &families) {
            eprintln!("[report] saving cases to {save}: {e}");
            std::process::exit(1);
        }
        eprintln!("[report] saved the generated cases to {save}/ (format: docs/speed.md)");
    }
}
