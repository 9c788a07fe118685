//! The seeded scene families: random numbers, shapes, and how each family places
//! its pairs and rays.

use crate::cases::{solve_casts, solve_pairs, solve_rays, Cases, Extra, Family, Sh};
use crate::ours::build_g;
use crate::timing::TIMED_CASES;
use std::time::Instant;

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

/// B (made around its centre) placed beside A (made at the origin), one
/// time in ten already within reach, and moved towards a point near A by
/// half to one and a half times the way there: hits, misses by a little,
/// and starts in contact, none of them predictable.
fn make_cast(
    rng: &mut Rng,
    mk_a: &dyn Fn(&mut Rng, [f64; 2]) -> Sh,
    mk_b: &dyn Fn(&mut Rng, [f64; 2]) -> Sh,
) -> (Sh, Sh, [f64; 2]) {
    let a = mk_a(rng, [0.0, 0.0]);
    let near = rng.f() < 0.1;
    let (u, k) = (rng.unit(), if near { rng.range(0.0, 1.0) } else { rng.range(1.5, 4.0) });
    let b = mk_b(rng, offset([0.0, 0.0], u, k));
    let (ca, _) = a.bounds();
    let (cb, _) = b.bounds();
    let aim = offset(ca, rng.unit(), rng.range(0.0, 1.2));
    let f = rng.range(0.5, 1.5);
    (a, b, [r32((aim[0] - cb[0]) * f), r32((aim[1] - cb[1]) * f)])
}

/// judged by the oracle (the rest are only timed).
type PairSpec = (String, bool, Vec<(Sh, Sh)>, usize);
type RaySpec = (String, bool, Vec<([f64; 2], [f64; 2], f64, Sh)>, usize);
type CastSpec = (String, Vec<(Sh, Sh, [f64; 2])>, usize);

/// Every family drawn from the fixed seed; only those `keep` names are
/// solved by the oracle and returned (the others' draws still happen, so a
/// family's cases are the same in a partial run).
pub(crate) fn generate(scale: f64, keep: &mut dyn FnMut(&str) -> bool) -> Vec<Family> {
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

    let mut cast_specs: Vec<CastSpec> = Vec::new();
    let mut cast_family = |name: &str, k: usize, rng: &mut Rng, mk_a: &dyn Fn(&mut Rng, [f64; 2]) -> Sh| {
        let mut v = Vec::new();
        while v.len() < k.max(TIMED_CASES) {
            let (a, b, m) = make_cast(rng, mk_a, &|r, c| random_poly(r, 8, 1.0, 1.0, c));
            if valid(&a) && valid(&b) && m != [0.0, 0.0] {
                v.push((a, b, m));
            }
        }
        cast_specs.push((name.to_string(), v, k));
    };
    cast_family("cast_poly8", n(1000), &mut rng, &|r, c| random_poly(r, 8, 1.0, 1.0, c));
    cast_family("cast_rounded_poly", n(1000), &mut rng, &|r, c| {
        if r.f() < 0.5 {
            circle(r, 1.0, c)
        } else {
            capsule(r, 1.0, c)
        }
    });

    let mut out = Vec::new();
    for (name, stiff, mut raw, judged) in pair_specs.into_iter().filter(|spec| keep(&spec.0)) {
        let t = Instant::now();
        let extra = raw.split_off(judged);
        let cases = solve_pairs(raw);
        eprintln!("[report] oracle: {name:<16} {:5} pairs in {:6.2} s", cases.len(), t.elapsed().as_secs_f64());
        out.push(Family { name, stiff, cases: Cases::Pairs(cases), extra: Extra::Pairs(extra) });
    }
    for (name, stiff, mut raw, judged) in ray_specs.into_iter().filter(|spec| keep(&spec.0)) {
        let t = Instant::now();
        let extra = raw.split_off(judged);
        let cases = solve_rays(raw);
        eprintln!("[report] oracle: {name:<16} {:5} rays  in {:6.2} s", cases.len(), t.elapsed().as_secs_f64());
        out.push(Family { name, stiff, cases: Cases::Rays(cases), extra: Extra::Rays(extra) });
    }
    for (name, mut raw, judged) in cast_specs.into_iter().filter(|spec| keep(&spec.0)) {
        let t = Instant::now();
        let extra = raw.split_off(judged);
        let cases = solve_casts(raw);
        eprintln!("[report] oracle: {name:<16} {:5} casts in {:6.2} s", cases.len(), t.elapsed().as_secs_f64());
        out.push(Family { name, stiff: false, cases: Cases::Casts(cases), extra: Extra::Casts(extra) });
    }
    out
}

/// `count` pairs of 8-gons for the frame-to-frame family, placed as poly8's
/// (about half overlapping), each with B's motion a step: a velocity of at
/// most 1% of B's size and a spin of at most 1 degree.
pub(crate) fn frame_pairs(count: usize) -> Vec<(Sh, Sh, [f64; 2], f64)> {
    let mut rng = Rng(0x7761_726d);
    let mut poly = |r: &mut Rng, c: [f64; 2]| random_poly(r, 8, 1.0, 1.0, c);
    let mut out = Vec::with_capacity(count);
    while out.len() < count {
        let (a, b) = place_pair(&mut rng, &mut poly.clone(), &mut poly, [0.0, 0.0], 1.0);
        let (_, size) = b.bounds();
        let dir = rng.unit();
        let speed = 0.01 * size * rng.f();
        let spin = rng.range(-1.0, 1.0).to_radians();
        out.push((a, b, [dir[0] * speed, dir[1] * speed], spin));
    }
    out
}
