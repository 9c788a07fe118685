//! The inputs and their exact answers: shapes (f32 values held in f64), what the
//! oracle says about a pair or a ray, and a family's cases.

use gjk2d_oracle as oracle;
use oracle::exact::Q;

#[derive(Clone, Debug)]
pub(crate) enum Sh {
    /// Strictly convex, counter-clockwise.
    Poly(Vec<[f64; 2]>),
    Circle([f64; 2], f64),
    Capsule([f64; 2], [f64; 2], f64),
    /// Axis-aligned ellipse: center, half-width, half-height.
    Ellipse([f64; 2], f64, f64),
}

impl Sh {
    /// Center (vertex mean for polygons) and bounding radius about it, in f64.
    pub(crate) fn bounds(&self) -> ([f64; 2], f64) {
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
    pub(crate) fn vertex_count(&self) -> usize {
        match self {
            Sh::Poly(v) => v.len(),
            _ => 1,
        }
    }
    pub(crate) fn oracle(&self) -> oracle::Shape {
        match self {
            Sh::Poly(v) => oracle::Shape::Polygon(v.clone()),
            Sh::Circle(c, r) => oracle::Shape::Circle { center: *c, radius: *r },
            Sh::Capsule(a, b, r) => oracle::Shape::Capsule { a: *a, b: *b, radius: *r },
            Sh::Ellipse(..) => unreachable!("the oracle has no ellipses"),
        }
    }
    pub(crate) fn tokens(&self, t: &mut Vec<String>) {
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
pub(crate) struct PairTruth {
    /// Distance if apart, -depth if overlapping, 0 if touching.
    pub(crate) signed: f64,
    pub(crate) distance: f64,
    pub(crate) depth: f64,
    pub(crate) normal: [f64; 2],
    pub(crate) normal_unique: bool,
}

#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) enum RayVerdict {
    Hit,
    Miss,
    Inside,
}

#[derive(Clone, Debug)]
pub(crate) struct RayTruth {
    pub(crate) verdict: RayVerdict,
    pub(crate) t: f64,
    pub(crate) normal: [f64; 2],
    pub(crate) normal_unique: bool,
    pub(crate) margin: f64,
}

pub(crate) struct PairCase {
    pub(crate) a: Sh,
    pub(crate) b: Sh,
    pub(crate) l: f64,
    pub(crate) truth: PairTruth,
}

pub(crate) struct RayCase {
    pub(crate) o: [f64; 2],
    pub(crate) d: [f64; 2],
    pub(crate) max_len: f64,
    pub(crate) s: Sh,
    pub(crate) l: f64,
    pub(crate) truth: RayTruth,
}

/// B moving by `m` against A: the first contact is a ray from the origin
/// along `m` against their exact Minkowski difference `A - B`.
pub(crate) struct CastCase {
    pub(crate) a: Sh,
    pub(crate) b: Sh,
    pub(crate) m: [f64; 2],
    /// The pair's size plus the motion's length: errors are over `L + t`.
    pub(crate) l: f64,
    pub(crate) truth: RayTruth,
}

pub(crate) enum Cases {
    Pairs(Vec<PairCase>),
    Rays(Vec<RayCase>),
    Casts(Vec<CastCase>),
}

pub(crate) struct Family {
    pub(crate) name: String,
    pub(crate) stiff: bool,
    pub(crate) cases: Cases,
    /// More inputs of the same kind, timed but not judged, so that every timed
    /// pass asks [`TIMED_CASES`](crate::timing::TIMED_CASES) distinct questions.
    pub(crate) extra: Extra,
}

pub(crate) enum Extra {
    Pairs(Vec<(Sh, Sh)>),
    Rays(Vec<([f64; 2], [f64; 2], f64, Sh)>),
    Casts(Vec<(Sh, Sh, [f64; 2])>),
}

impl Family {
    pub(crate) fn extra_pairs(&self) -> &[(Sh, Sh)] {
        match &self.extra {
            Extra::Pairs(v) => v,
            _ => &[],
        }
    }
    pub(crate) fn extra_rays(&self) -> &[([f64; 2], [f64; 2], f64, Sh)] {
        match &self.extra {
            Extra::Rays(v) => v,
            _ => &[],
        }
    }
    pub(crate) fn extra_casts(&self) -> &[(Sh, Sh, [f64; 2])] {
        match &self.extra {
            Extra::Casts(v) => v,
            _ => &[],
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
    ray_truth(oracle::ray(o, d, max_len, &oracle::ExactShape::from(&s.oracle())))
}

fn ray_truth(r: oracle::RayAnswer) -> RayTruth {
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

fn pair_l(a: &Sh, b: &Sh) -> f64 {
    a.bounds().1.max(b.bounds().1)
}

fn ray_l(o: [f64; 2], s: &Sh) -> f64 {
    let (c, br) = s.bounds();
    br.max((o[0] - c[0]).hypot(o[1] - c[1]))
}

/// Oracle answers on both cores, once for f32 and f64 alike.
pub(crate) fn solve_pairs(raw: Vec<(Sh, Sh)>) -> Vec<PairCase> {
    parallel_map(raw, |(a, b)| {
        let truth = oracle_pair(&a, &b);
        PairCase { l: pair_l(&a, &b), a, b, truth }
    })
}

/// The exact Minkowski difference `A - B`: the hull of the cores' vertex
/// differences (rational, strictly convex, counter-clockwise; a point or a
/// segment where it degenerates), swept by both radii.
fn exact_difference(a: &Sh, b: &Sh) -> oracle::ExactShape {
    let (ea, eb) = (oracle::ExactShape::from(&a.oracle()), oracle::ExactShape::from(&b.oracle()));
    let mut pts: Vec<[Q; 2]> = Vec::new();
    for p in ea.core_vertices() {
        for q in eb.core_vertices() {
            pts.push([&p[0] - &q[0], &p[1] - &q[1]]);
        }
    }
    pts.sort();
    pts.dedup();
    let cross =
        |o: &[Q; 2], p: &[Q; 2], q: &[Q; 2]| (&p[0] - &o[0]) * (&q[1] - &o[1]) - (&p[1] - &o[1]) * (&q[0] - &o[0]);
    // Andrew's monotone chain, dropping collinear points.
    let mut hull: Vec<[Q; 2]> = Vec::new();
    for pass in 0..2 {
        let start = hull.len();
        let ordered: Box<dyn Iterator<Item = &[Q; 2]>> =
            if pass == 0 { Box::new(pts.iter()) } else { Box::new(pts.iter().rev()) };
        for p in ordered {
            while hull.len() >= start + 2
                && cross(&hull[hull.len() - 2], &hull[hull.len() - 1], p) <= Q::from_integer(0.into())
            {
                hull.pop();
            }
            hull.push(p.clone());
        }
        hull.pop();
    }
    if hull.is_empty() {
        hull = pts[..1].to_vec();
    }
    oracle::ExactShape::from_core(hull, ea.radius() + eb.radius())
}

pub(crate) fn solve_casts(raw: Vec<(Sh, Sh, [f64; 2])>) -> Vec<CastCase> {
    parallel_map(raw, |(a, b, m)| {
        let length = m[0].hypot(m[1]);
        let truth = ray_truth(oracle::ray([0.0, 0.0], m, length, &exact_difference(&a, &b)));
        CastCase { l: pair_l(&a, &b) + length, a, b, m, truth }
    })
}

pub(crate) fn solve_rays(raw: Vec<([f64; 2], [f64; 2], f64, Sh)>) -> Vec<RayCase> {
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
