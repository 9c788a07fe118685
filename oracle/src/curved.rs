//! Signed distance of two convex shapes, curved ones included, from their
//! support functions alone: independent of GJK and EPA, and certified by
//! branch and bound instead of trusted.
//!
//! Ellipses, half-ellipses and circular sectors have irrational answers, so
//! the rational oracle of this crate cannot give them. Here they come from the
//! Minkowski difference `K = A - B` in `f64`: with `h_K(n) = h_A(n) + h_B(-n)`
//! its support function, the minimum `m` of `h_K` over unit `n` is the depth
//! of the origin inside `K` when positive and minus its distance from `K`
//! when negative, so the signed distance of the pair is `-m` and its
//! minimiser is the normal from A towards B in both cases.
//!
//! # The bound
//!
//! On an arc of directions between `n0` and `n1` (less than a half turn),
//! each shape contributes a lower bound of its support function: on a smooth
//! run of directions (all of them for a circle, capsule or ellipse; a half
//! ellipse's dome; a slice's arc) the disk inside it that touches it at both
//! ends' support points (a circle's or capsule's radius, `b^2 / a` for an
//! ellipse of semi-axes `a >= b`, the slice's own circle about its apex),
//! `h(n) >= max(c0 . n, c1 . n) + r`; elsewhere the support points alone
//! (`r = 0`). The sum for `K` is the radii plus the largest of four linear
//! parts, minimised over the arc in closed form (at an end, where two parts
//! cross, or opposite one). The bound is exact on disks, on flat runs and
//! where both ends share a vertex, and off by a chord's sagitta `rho w^2 / 8`
//! (`rho` the excess radius of curvature, `w` the arc) elsewhere, so
//! concentric round shapes, whose `h_K` is flat, are bounded exactly instead
//! of never.
//!
//! Branch and bound splits the arc of least lower bound until the best value
//! seen (an upper bound: it is `h_K` at a direction) is within `tol` of it:
//! near a minimum that is about 25 halvings from 64 starting arcs, so a few
//! hundred support evaluations.
//!
//! # Error
//!
//! `h_K` and the chord bound are evaluated in `f64`: a support point, a dot
//! product and a transform each round a few ulps of the coordinates' size, so
//! with `S` the larger of the shapes' farthest points from the world origin,
//! each value is within about `8 eps S` (`eps = 2^-52`), taken as
//! `error = (upper - lower) + 16 eps S`. At sizes near 1 this is about 1e-14,
//! a hundredth of the 1e-12 `L` that gjk2d guarantees for curved shapes in f64
//! and far below the 1e-6 `L` of f32. The shapes are the ones gjk2d stores:
//! lengths as given (exact floats) and a transform's rounded cosine and sine,
//! so `M = [[c, -s], [s, c]]` is a rotation scaled by `sqrt(c^2 + s^2)`, which
//! the support functions below honour exactly (`h(n) = h_local(M^T n) + t . n`).

use std::cmp::Ordering;
use std::collections::BinaryHeap;

pub type Pt = [f64; 2];

/// A shape in its local frame, as gjk2d defines it.
#[derive(Clone, Debug, PartialEq)]
pub enum Local {
    /// Counter-clockwise convex polygon (a segment is two vertices, a point one).
    Polygon(Vec<Pt>),
    Circle {
        center: Pt,
        radius: f64,
    },
    Capsule {
        a: Pt,
        b: Pt,
        radius: f64,
    },
    /// Axis-aligned ellipse centred on the origin, semi-axes `a` (x) and `b` (y).
    Ellipse {
        a: f64,
        b: f64,
    },
    /// The upper half (`y >= 0`) of the ellipse of semi-axes `a` and `h`.
    HalfEllipse {
        a: f64,
        h: f64,
    },
    /// The circular sector of `radius` with its apex on the origin, symmetric
    /// about +x, whose arc ends at `end = (x, y)` and `(x, -y)` (`y >= 0`):
    /// the hull of the apex, both ends and the arc of angles within
    /// `atan2(y, x)` of +x. gjk2d computes the ends from the angle with its
    /// own sine and cosine; given its stored ends, the oracle answers for the
    /// shape gjk2d holds.
    Slice {
        radius: f64,
        end: Pt,
    },
}

/// A shape placed by `x -> M x + t`, `M = [[cos, -sin], [sin, cos]]`.
#[derive(Clone, Debug, PartialEq)]
pub struct Placed {
    pub shape: Local,
    pub cos: f64,
    pub sin: f64,
    pub t: Pt,
}

fn dot(p: Pt, q: Pt) -> f64 {
    p[0] * q[0] + p[1] * q[1]
}
fn cross(p: Pt, q: Pt) -> f64 {
    p[0] * q[1] - p[1] * q[0]
}
fn norm(p: Pt) -> f64 {
    p[0].hypot(p[1])
}
fn scale(p: Pt, k: f64) -> Pt {
    [p[0] * k, p[1] * k]
}

/// Support point of the ellipse of semi-axes `(a, b)` along `m`.
fn ellipse_point(a: f64, b: f64, m: Pt) -> Pt {
    let s = m[0].abs().max(m[1].abs());
    let u = [m[0] / s, m[1] / s];
    let len = (a * u[0]).hypot(b * u[1]);
    [a * a * u[0] / len, b * b * u[1] / len]
}

impl Local {
    /// Support point of the shape along `m` (non-zero, any length).
    pub fn support(&self, m: Pt) -> Pt {
        self.support_disk(m).0
    }

    /// Support point along `m`, and the radius of a disk inside the shape
    /// that touches it there, valid along the whole smooth run of directions
    /// `m` lies in: for every direction `n` of that run, `h(n) >= c . n + r`
    /// with `c` the disk's centre. `None` off any smooth run (at a corner,
    /// along a flat side), where the chord bound uses the point alone. The
    /// runs are one arc of directions per shape (all of them for a circle,
    /// capsule or ellipse, whose radius of curvature is at least the radius;
    /// the dome of a half-ellipse, which is the full ellipse's there; the arc
    /// of a slice, a disk about its apex there).
    pub fn support_disk(&self, m: Pt) -> (Pt, Option<f64>) {
        let unit = scale(m, 1.0 / norm(m));
        let best = |pts: &mut dyn Iterator<Item = Pt>| {
            pts.fold((f64::NEG_INFINITY, [0.0, 0.0]), |(v, p), q| if dot(q, m) > v { (dot(q, m), q) } else { (v, p) }).1
        };
        match self {
            Local::Polygon(v) => (best(&mut v.iter().copied()), None),
            Local::Circle { center, radius } => {
                ([center[0] + radius * unit[0], center[1] + radius * unit[1]], Some(*radius))
            }
            Local::Capsule { a, b, radius } => {
                let p = if dot(*b, m) > dot(*a, m) { *b } else { *a };
                ([p[0] + radius * unit[0], p[1] + radius * unit[1]], Some(*radius))
            }
            Local::Ellipse { a, b } => (ellipse_point(*a, *b, m), Some(a.min(*b) * (a.min(*b) / a.max(*b)))),
            Local::HalfEllipse { a, h } => {
                if m[1] > 0.0 {
                    (ellipse_point(*a, *h, m), Some(a.min(*h) * (a.min(*h) / a.max(*h))))
                } else if m[0] >= 0.0 {
                    ([*a, 0.0], None)
                } else {
                    ([-*a, 0.0], None)
                }
            }
            Local::Slice { radius, end } => {
                let alpha = end[1].atan2(end[0]);
                let angle = unit[1].atan2(unit[0]);
                let ends = [[0.0, 0.0], *end, [end[0], -end[1]]];
                if angle.abs() <= alpha {
                    let arc = scale(unit, *radius);
                    let p = best(&mut [arc].into_iter().chain(ends));
                    (p, if p == arc { Some(*radius) } else { None })
                } else {
                    let side = if angle > 0.0 { 1.0 } else { -1.0 };
                    let arc_end = [radius * alpha.cos(), side * radius * alpha.sin()];
                    (best(&mut [arc_end].into_iter().chain(ends)), None)
                }
            }
        }
    }

    /// The largest distance of a point of the shape from its local origin.
    pub fn extent(&self) -> f64 {
        match self {
            Local::Polygon(v) => v.iter().map(|&p| norm(p)).fold(0.0, f64::max),
            Local::Circle { center, radius } => norm(*center) + radius,
            Local::Capsule { a, b, radius } => norm(*a).max(norm(*b)) + radius,
            Local::Ellipse { a, b } => a.max(*b),
            Local::HalfEllipse { a, h } => a.max(*h),
            Local::Slice { radius, end } => radius.max(norm(*end)),
        }
    }
}

impl Placed {
    pub fn new(shape: Local, cos: f64, sin: f64, t: Pt) -> Self {
        Self { shape, cos, sin, t }
    }
    /// Unrotated, untranslated.
    pub fn at_origin(shape: Local) -> Self {
        Self::new(shape, 1.0, 0.0, [0.0, 0.0])
    }
    fn to_local(&self, n: Pt) -> Pt {
        [self.cos * n[0] + self.sin * n[1], -self.sin * n[0] + self.cos * n[1]]
    }
    fn to_world(&self, p: Pt) -> Pt {
        [self.cos * p[0] - self.sin * p[1] + self.t[0], self.sin * p[0] + self.cos * p[1] + self.t[1]]
    }
    /// World support point along `n`.
    pub fn support(&self, n: Pt) -> Pt {
        self.to_world(self.shape.support(self.to_local(n)))
    }
    /// The support function `h(n) = max over the shape of x . n`, world frame.
    pub fn h(&self, n: Pt) -> f64 {
        dot(self.support(n), n)
    }
    /// World support point along `n`, and the centre and radius of the
    /// disk of [`Local::support_disk`] in the world (`M` scales by
    /// `sqrt(c^2 + s^2)`).
    fn support_disk(&self, n: Pt) -> End {
        let m = self.to_local(n);
        let (p, r) = self.shape.support_disk(m);
        let disk = r.map(|r| {
            let u = scale(m, 1.0 / norm(m));
            (self.to_world([p[0] - r * u[0], p[1] - r * u[1]]), r * self.cos.hypot(self.sin))
        });
        End { point: self.to_world(p), disk }
    }
    /// The farthest point's distance from the world origin (an upper bound).
    pub fn reach(&self) -> f64 {
        norm(self.t) + self.shape.extent() * self.cos.hypot(self.sin)
    }
}

/// The oracle's answer for a pair.
#[derive(Clone, Copy, Debug)]
pub struct CurvedAnswer {
    /// Distance apart, or minus the depth (the exact value within `error`).
    pub signed: f64,
    /// Bound on `|signed - exact|`: the branch and bound's gap plus rounding.
    pub error: f64,
    /// A unit normal from A towards B achieving `signed` within `error`.
    pub normal: Pt,
    /// Support evaluations spent.
    pub evaluations: u32,
}

/// A shape's support along an end direction of an arc.
#[derive(Clone, Copy, Debug)]
struct End {
    point: Pt,
    /// The inner disk's centre and radius on a smooth run (see
    /// [`Local::support_disk`]).
    disk: Option<(Pt, f64)>,
}

impl End {
    /// The point the chord bound uses when `radius` is taken out: the disk's
    /// centre on a smooth run, the support point where the radius is zero.
    fn inner(&self, radius: f64) -> Pt {
        match self.disk {
            Some((c, _)) if radius > 0.0 => c,
            _ => self.point,
        }
    }
}

/// An arc of directions `t0..t1` with both shapes' supports at its ends
/// (B's along the opposite directions) and its lower bound.
#[derive(Clone, Copy, Debug)]
struct Arc {
    lower: f64,
    t0: f64,
    t1: f64,
    e0: [End; 2],
    e1: [End; 2],
}

impl PartialEq for Arc {
    fn eq(&self, o: &Self) -> bool {
        self.lower == o.lower
    }
}
impl Eq for Arc {}
impl PartialOrd for Arc {
    fn partial_cmp(&self, o: &Self) -> Option<Ordering> {
        Some(self.cmp(o))
    }
}
impl Ord for Arc {
    /// Reversed, so the heap pops the least lower bound.
    fn cmp(&self, o: &Self) -> Ordering {
        o.lower.total_cmp(&self.lower)
    }
}

fn dir(t: f64) -> Pt {
    [t.cos(), t.sin()]
}

/// A lower bound of `h_K = h_A + h_B(-.)` on the arc `t0..t1` (shorter than
/// a half turn). Each shape whose both ends lie on its smooth run contributes
/// its disk radius and the disks' centres, any other its support points: then
/// `h_K(n) >= r + max over the points p of p . n`, the points being the
/// differences of A's and B's, and that is minimised in closed form over the
/// arc (at an end, where two of the linear parts cross, or opposite a point).
fn arc_bound(t0: f64, t1: f64, e0: &[End; 2], e1: &[End; 2]) -> f64 {
    let radius_of = |k: usize| match (e0[k].disk, e1[k].disk) {
        (Some((_, r0)), Some((_, r1))) => r0.min(r1),
        _ => 0.0,
    };
    let (ra, rb) = (radius_of(0), radius_of(1));
    let a = [e0[0].inner(ra), e1[0].inner(ra)];
    let b = [e0[1].inner(rb), e1[1].inner(rb)];
    let points = [
        [a[0][0] - b[0][0], a[0][1] - b[0][1]],
        [a[0][0] - b[1][0], a[0][1] - b[1][1]],
        [a[1][0] - b[0][0], a[1][1] - b[0][1]],
        [a[1][0] - b[1][0], a[1][1] - b[1][1]],
    ];
    let (n0, n1) = (dir(t0), dir(t1));
    let f = |n: Pt| points.iter().map(|&p| dot(p, n)).fold(f64::NEG_INFINITY, f64::max);
    let within = |u: Pt| cross(n0, u) >= 0.0 && cross(u, n1) >= 0.0;
    let mut low = f(n0).min(f(n1));
    let mut consider = |u: Pt| {
        if within(u) {
            low = low.min(f(u));
        }
    };
    for (i, p) in points.iter().enumerate() {
        let lp = norm(*p);
        if lp > 0.0 {
            consider([-p[0] / lp, -p[1] / lp]);
        }
        for q in &points[i + 1..] {
            let e = [p[0] - q[0], p[1] - q[1]];
            let le = norm(e);
            if le > 0.0 {
                consider([-e[1] / le, e[0] / le]);
                consider([e[1] / le, -e[0] / le]);
            }
        }
    }
    low + ra + rb
}

/// How many arcs the branch and bound may split before it answers with the
/// gap it has (counted in `error`).
const MAX_SPLITS: u32 = 200_000;

/// Signed distance of A and B (see the module documentation), with `tol`
/// the gap to reach relative to the shapes' reach (1e-15 is a good value).
pub fn curved_pair(a: &Placed, b: &Placed, tol: f64) -> CurvedAnswer {
    let size = a.reach() + b.reach();
    let goal = tol * size;
    let mut evaluations = 0u32;
    let mut best = (f64::INFINITY, 0.0);
    let mut eval = |t: f64, best: &mut (f64, f64)| {
        evaluations += 1;
        let n = dir(t);
        let ends = [a.support_disk(n), b.support_disk([-n[0], -n[1]])];
        let v = dot(ends[0].point, n) - dot(ends[1].point, n);
        if v < best.0 {
            *best = (v, t);
        }
        ends
    };
    const START: usize = 64;
    let step = std::f64::consts::TAU / START as f64;
    let ends: Vec<[End; 2]> = (0..START).map(|i| eval(i as f64 * step, &mut best)).collect();
    let mut heap = BinaryHeap::new();
    for i in 0..START {
        let (t0, t1) = (i as f64 * step, (i + 1) as f64 * step);
        let (e0, e1) = (ends[i], ends[(i + 1) % START]);
        heap.push(Arc { lower: arc_bound(t0, t1, &e0, &e1), t0, t1, e0, e1 });
    }
    let mut lower = f64::NEG_INFINITY;
    let mut splits = 0;
    while let Some(arc) = heap.pop() {
        lower = arc.lower;
        if best.0 - arc.lower <= goal || splits >= MAX_SPLITS {
            break;
        }
        splits += 1;
        let tm = 0.5 * (arc.t0 + arc.t1);
        let em = eval(tm, &mut best);
        for (t0, t1, e0, e1) in [(arc.t0, tm, arc.e0, em), (tm, arc.t1, em, arc.e1)] {
            let low = arc_bound(t0, t1, &e0, &e1);
            if low <= best.0 {
                heap.push(Arc { lower: low, t0, t1, e0, e1 });
            }
        }
    }
    let lower = lower.min(best.0);
    CurvedAnswer {
        signed: -best.0,
        error: (best.0 - lower) + 16.0 * f64::EPSILON * size,
        normal: dir(best.1),
        evaluations,
    }
}

/// `h_A(n) + h_B(-n)`: the support function of `K = A - B` at `n`, so that
/// a reported normal can be checked to achieve a reported value.
pub fn difference_support(a: &Placed, b: &Placed, n: Pt) -> f64 {
    a.h(n) + b.h([-n[0], -n[1]])
}
