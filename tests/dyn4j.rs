//! dyn4j's own narrow-phase test checks, run against gjk2d.
//!
//! `tests/data/dyn4j_cases.txt` holds the 3141 checks of dyn4j's unit tests
//! (45 shape-pair tests, the Gjk ray casts, the support functions, the
//! Gjk/Epa defaults and setter ranges), converted by
//! `tests/data/convert_dyn4j.py`; its header documents the format. Each
//! query kind has one test per precision that runs every check, collects the
//! failures (case id, query, field, expected and actual) and prints a
//! summary: `cargo test --test dyn4j -- --nocapture`.
//!
//! How dyn4j's conventions map onto gjk2d's:
//! - Normals point from A to B in both. Separation points: point1 is on A,
//!   point2 on B.
//! - Touching: dyn4j's `detect` calls touching shapes not colliding, gjk2d's
//!   `intersects` and `penetration` call them intersecting, and gjk2d's
//!   `distance` returns `None`. A boolean check gjk2d answers differently is
//!   counted under "touching: semantics differ" when the pair is touching:
//!   its gap (gjk2d's f64 distance, or minus its depth) is within
//!   [`TOUCH`] times the pair's scale of zero. Any other disagreement fails.
//! - dyn4j's `distance` also says "separated, distance 0" for a circle that
//!   overlaps a rectangle by half its radius (CircleRectangleTest, its own
//!   detect test finds depth 0.5 there). gjk2d reports the overlap; such
//!   checks are counted under their own reason, after checking that gjk2d's
//!   penetration depth is indeed positive.
//! - Penetration normals other than dyn4j's, and dyn4j's equal-depth cases
//!   (`initial_direction_sensitive`, and the zero normal dyn4j returns for
//!   concentric circles): the depth is checked as usual; gjk2d's normal must
//!   be a unit vector along which moving B by the reported depth leaves the
//!   pair touching (|gap| within `resolve_limit`), and the reported depth
//!   must be the minimum over all directions, found by brute force on the
//!   f64 support functions (`min_depth`). A normal other than dyn4j's is
//!   noted as a tie when dyn4j's is a minimum-depth direction too (to the
//!   precision it was written with), else as dyn4j's not being one.
//! - Rays: dyn4j's direction may be non-unit; its distance and maximum
//!   length are then in units of |d|, converted here. A ray starting inside
//!   a shape returns false in dyn4j and `RayOutcome::Inside` in gjk2d.
//! - getFarthestPoint: the world point is `transform(reference_point +
//!   support(local direction)) + radius * unit(direction)`.
//! - `exact` checks compare with `==`, so `-0.0` equals `0.0` (dyn4j's
//!   `Double.equals` would tell them apart; the sign of a zero normal
//!   component is not geometry).
//!
//! - dyn4j's expectation off the exact answer: several expectations (curved
//!   shapes: distance normals and points, ray normals) were written from
//!   dyn4j's own approximate answer and exclude the exact one by more than
//!   their tolerance (checked by brute force for calls 4143, 2061, 2846, and
//!   by hand for the capsule and ellipse ray normals). When gjk2d's value
//!   misses such an expectation, its f64 answer is certified with the
//!   support functions (separations: the points lie in the shapes and the
//!   supporting lines along the normal are as far apart as the points, to a
//!   bound; ray normals: the hit point lies on the supporting line along the
//!   normal). If the certified f64 answer, minus its error bound, still
//!   misses dyn4j's expectation, the check compares the answer under test
//!   with the certified f64 one under dyn4j's tolerance instead (noted, ids
//!   listed). Otherwise it fails as usual.
//!
//! Tolerances: an `approx` check passes when |actual - expected| <= tol *
//! (1 + 1e-6) + 64 * EPSILON * scale (EPSILON of the precision under test,
//! scale = max(1, the farthest extent of the shapes or ray origin from the
//! world origin)). Many expectations were written truncated (1.599 for 1.6,
//! tolerance 1e-3), so the exact answer sits on the boundary: the relative
//! 1e-6 and the 64 ulps of the scale are that slack.
//!
//! f32: an `approx` check runs in f32 when its tolerance is at least
//! [`F32_FACTOR`] * f32::EPSILON * scale (about 1.2e-4 at scale 1); a boolean
//! or predicate check on a shape pair runs when the pair's f64 gap is
//! farther than that from zero (otherwise f32 cannot tell the answer);
//! `exact` checks run in f32 too (their expected values are small dyadic
//! numbers). Normals and points of pairs with a curved shape (ellipse, half
//! ellipse, slice) do not run in f32: those queries iterate to a relative
//! 1e-6 in the distance or depth, which leaves directions good to about
//! sqrt(1e-6 * size / distance), coarser than dyn4j's 1e-3 for close pairs.
//! Everything that does not run is counted as skipped with its reason.

use gjk2d::*;
use std::collections::BTreeMap;
use std::fmt::Write as _;

const DATA: &str = include_str!("data/dyn4j_cases.txt");

/// A pair is touching when |gap| <= TOUCH * scale (f64).
const TOUCH: f64 = 1e-12;
/// f32 runs a check whose tolerance (or margin) is >= F32_FACTOR * f32::EPSILON * scale.
const F32_FACTOR: f64 = 1000.0;
/// Truncated expectations: relative slack on the tolerance.
const TRUNCATION_SLACK: f64 = 1e-6;
/// Rounding slack: this many EPSILONs of the scale, in the precision under test.
const ROUNDING_ULPS: f64 = 64.0;

// ---------------------------------------------------------------- data model

#[derive(Clone, Copy, Debug)]
struct Place {
    p: [f64; 2],
    c: f64,
    s: f64,
}

#[derive(Clone, Debug)]
enum Kind {
    Circle([f64; 2], f64),
    Rect(f64, f64),
    Poly(Vec<[f64; 2]>),
    Tri([[f64; 2]; 3]),
    Seg([f64; 2], [f64; 2]),
    Capsule(f64, f64),
    Capsule2([f64; 2], [f64; 2], f64),
    Ellipse(f64, f64),
    HalfEllipse(f64, f64),
    Slice(f64, f64),
}

#[derive(Clone, Debug)]
struct ShapeDef {
    /// dyn4j's recorded center, local frame.
    center: [f64; 2],
    kind: Kind,
    place: Option<Place>,
}

#[derive(Clone, Copy, Debug)]
struct TDef {
    x: f64,
    y: f64,
    c: f64,
    s: f64,
}

#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord)]
enum QKind {
    Detect,
    Pen,
    Dist,
    Ray,
    Far,
}

impl QKind {
    fn name(self) -> &'static str {
        match self {
            QKind::Detect => "detect",
            QKind::Pen => "detect_penetration",
            QKind::Dist => "distance",
            QKind::Ray => "raycast",
            QKind::Far => "getFarthestPoint",
        }
    }
}

#[derive(Clone, Copy, Debug)]
enum Op {
    Ret(bool),
    Approx(f64, f64),
    Exact(f64),
    Ge(f64),
    NotNan,
}

#[derive(Clone, Debug)]
struct Check {
    id: u32,
    field: String,
    op: Op,
    ids: bool,
}

#[derive(Clone, Debug)]
struct Call {
    kind: QKind,
    call: u32,
    a: usize,
    ta: usize,
    b: usize,
    tb: usize,
    /// Ray origin, direction, maximum length (dyn4j's units).
    origin: [f64; 2],
    dir: [f64; 2],
    max: f64,
    checks: Vec<Check>,
}

#[derive(Clone, Debug)]
enum ConfigCheck {
    Default { id: u32, setting: String, value: String },
    Set { id: u32, setting: String, value: String, how: String },
}

struct Data {
    shapes: Vec<ShapeDef>,
    transforms: Vec<TDef>,
    calls: Vec<Call>,
    config: Vec<ConfigCheck>,
    skipped: Vec<(u32, String)>,
}

fn parse() -> Data {
    let mut d =
        Data { shapes: Vec::new(), transforms: Vec::new(), calls: Vec::new(), config: Vec::new(), skipped: Vec::new() };
    let mut in_config = false;
    for (n, line) in DATA.lines().enumerate() {
        let line = line.trim();
        if line.is_empty() || line.starts_with('#') {
            continue;
        }
        let t: Vec<&str> = line.split_whitespace().collect();
        let f = |i: usize| -> f64 { t[i].parse().unwrap_or_else(|_| panic!("line {}: bad number {:?}", n + 1, t[i])) };
        let u = |i: usize| -> usize { t[i].parse().unwrap_or_else(|_| panic!("line {}: bad index {:?}", n + 1, t[i])) };
        match t[0] {
            "S" => {
                assert_eq!(u(1), d.shapes.len(), "line {}", n + 1);
                let center = [f(2), f(3)];
                let place = |i: usize| Place { p: [f(i), f(i + 1)], c: f(i + 2), s: f(i + 3) };
                let (kind, place) = match t[4] {
                    "circle" => (Kind::Circle([f(5), f(6)], f(7)), None),
                    "rect" => (Kind::Rect(f(5), f(6)), None),
                    "poly" => {
                        let count = u(5);
                        (Kind::Poly((0..count).map(|k| [f(6 + 2 * k), f(7 + 2 * k)]).collect()), None)
                    }
                    "tri" => (Kind::Tri([[f(5), f(6)], [f(7), f(8)], [f(9), f(10)]]), None),
                    "seg" => (Kind::Seg([f(5), f(6)], [f(7), f(8)]), None),
                    "capsule" => (Kind::Capsule(f(5), f(6)), None),
                    "capsule2" => (Kind::Capsule2([f(5), f(6)], [f(7), f(8)], f(9)), None),
                    "ellipse" => (Kind::Ellipse(f(5), f(6)), Some(place(7))),
                    "halfellipse" => (Kind::HalfEllipse(f(5), f(6)), Some(place(7))),
                    "slice" => (Kind::Slice(f(5), f(6)), Some(place(7))),
                    other => panic!("line {}: unknown shape {other}", n + 1),
                };
                d.shapes.push(ShapeDef { center, kind, place });
            }
            "T" => {
                assert_eq!(u(1), d.transforms.len(), "line {}", n + 1);
                d.transforms.push(TDef { x: f(2), y: f(3), c: f(4), s: f(5) });
            }
            "Q" => {
                let kind = match t[1] {
                    "detect" => QKind::Detect,
                    "pen" => QKind::Pen,
                    "dist" => QKind::Dist,
                    "ray" => QKind::Ray,
                    "far" => QKind::Far,
                    "config" => {
                        in_config = true;
                        continue;
                    }
                    other => panic!("line {}: unknown query {other}", n + 1),
                };
                in_config = false;
                let mut c = Call {
                    kind,
                    call: u(2) as u32,
                    a: u(3),
                    ta: u(4),
                    b: 0,
                    tb: 0,
                    origin: [0.0; 2],
                    dir: [0.0; 2],
                    max: 0.0,
                    checks: Vec::new(),
                };
                match kind {
                    QKind::Ray => {
                        c.origin = [f(5), f(6)];
                        c.dir = [f(7), f(8)];
                        c.max = f(10);
                    }
                    QKind::Far => c.dir = [f(5), f(6)],
                    _ => {
                        c.b = u(5);
                        c.tb = u(6);
                    }
                }
                d.calls.push(c);
            }
            _ => {
                let id: u32 = t[0].parse().unwrap_or_else(|_| panic!("line {}: bad id", n + 1));
                if t[1] == "skip" {
                    d.skipped.push((id, t[2].to_string()));
                    continue;
                }
                if in_config {
                    d.config.push(match t[1] {
                        "default" => ConfigCheck::Default { id, setting: t[2].into(), value: t[3].into() },
                        "set" => ConfigCheck::Set { id, setting: t[2].into(), value: t[3].into(), how: t[4].into() },
                        other => panic!("line {}: unknown config check {other}", n + 1),
                    });
                    continue;
                }
                let call = d.calls.last_mut().expect("check before any call");
                let (field, op, ids) = if t[1] == "ret" {
                    ("ret".to_string(), Op::Ret(t[2] == "1"), false)
                } else {
                    let op = match t[2] {
                        "approx" => Op::Approx(f(3), f(4)),
                        "exact" => Op::Exact(f(3)),
                        "ge" => Op::Ge(f(3)),
                        "notnan" => Op::NotNan,
                        other => panic!("line {}: unknown op {other}", n + 1),
                    };
                    (t[1].to_string(), op, t.last() == Some(&"ids"))
                };
                call.checks.push(Check { id, field, op, ids });
            }
        }
    }
    d
}

// ------------------------------------------------------------ building shapes

fn v<R: Real>(x: f64, y: f64) -> R::Vector {
    R::vector(R::from_f64(x), R::from_f64(y))
}

fn xy<R: Real>(p: R::Vector) -> [f64; 2] {
    let (x, y) = R::components(p);
    [x.to_f64(), y.to_f64()]
}

fn build<R: Real>(s: &ShapeDef) -> Box<dyn SupportMap<R>> {
    let r = R::from_f64;
    match &s.kind {
        Kind::Circle(c, rad) => Box::new(Circle::at(v::<R>(c[0], c[1]), r(*rad)).unwrap()),
        Kind::Rect(w, h) => Box::new(Rectangle::new(r(*w), r(*h)).unwrap()),
        Kind::Poly(p) => {
            let pts: Vec<R::Vector> = p.iter().map(|q| v::<R>(q[0], q[1])).collect();
            Box::new(Polygon::<R, 8>::new(&pts).unwrap())
        }
        Kind::Tri(p) => Box::new(
            Triangle::new(v::<R>(p[0][0], p[0][1]), v::<R>(p[1][0], p[1][1]), v::<R>(p[2][0], p[2][1])).unwrap(),
        ),
        Kind::Seg(a, b) => Box::new(Segment::new(v::<R>(a[0], a[1]), v::<R>(b[0], b[1])).unwrap()),
        Kind::Capsule(w, h) => Box::new(Capsule::from_size(r(*w), r(*h)).unwrap()),
        Kind::Capsule2(a, b, rad) => Box::new(Capsule::new(v::<R>(a[0], a[1]), v::<R>(b[0], b[1]), r(*rad)).unwrap()),
        Kind::Ellipse(w, h) => Box::new(Ellipse::new(r(*w), r(*h)).unwrap()),
        Kind::HalfEllipse(w, h) => Box::new(HalfEllipse::new(r(*w), r(*h)).unwrap()),
        Kind::Slice(rad, theta) => Box::new(Slice::new(r(*rad), r(*theta)).unwrap()),
    }
}

/// The body transform composed with the shape's placement in its own frame
/// (dyn4j's shape.rotate/translate), computed in f64.
fn world_f64(t: &TDef, place: Option<Place>) -> TDef {
    match place {
        None => *t,
        Some(pl) => TDef {
            x: t.c * pl.p[0] - t.s * pl.p[1] + t.x,
            y: t.s * pl.p[0] + t.c * pl.p[1] + t.y,
            c: t.c * pl.c - t.s * pl.s,
            s: t.s * pl.c + t.c * pl.s,
        },
    }
}

fn transform<R: Real>(t: &TDef) -> Transform<R> {
    Transform::from_cos_sin(v::<R>(t.x, t.y), R::from_f64(t.c), R::from_f64(t.s)).unwrap()
}

/// A shape ready for queries in precision R.
struct Placed<R: Real> {
    shape: Box<dyn SupportMap<R>>,
    t: Transform<R>,
    /// Farthest extent from the world origin (f64).
    extent: f64,
}

fn placed<R: Real>(d: &Data, shape: usize, t: usize) -> Placed<R> {
    let def = &d.shapes[shape];
    let w = world_f64(&d.transforms[t], def.place);
    let s64 = build::<f64>(def);
    let local = {
        let c = s64.center() + s64.reference_point();
        c.length() + s64.bounding_radius()
    };
    Placed { shape: build::<R>(def), t: transform::<R>(&w), extent: w.x.hypot(w.y) + local }
}

// --------------------------------------------------------------- bookkeeping

#[derive(Default)]
struct Report {
    total: usize,
    run: usize,
    passed: usize,
    failures: Vec<String>,
    /// Not run or not comparable, by reason: the case ids.
    skipped: BTreeMap<String, Vec<u32>>,
    /// Passed under a convention mapping, by mapping: the case ids.
    notes: BTreeMap<String, Vec<u32>>,
}

impl Report {
    fn pass(&mut self) {
        self.run += 1;
        self.passed += 1;
    }
    fn fail(&mut self, msg: String) {
        self.run += 1;
        self.failures.push(msg);
    }
    fn skip(&mut self, reason: &str, id: u32) {
        self.skipped.entry(reason.to_string()).or_default().push(id);
    }
    fn note(&mut self, note: &str, id: u32) {
        self.notes.entry(note.to_string()).or_default().push(id);
    }
    fn outcome(&mut self, ok: bool, msg: impl FnOnce() -> String) {
        if ok {
            self.pass()
        } else {
            self.fail(msg())
        }
    }

    fn finish(self, title: &str) {
        let skipped: usize = self.skipped.values().map(Vec::len).sum();
        assert_eq!(self.run + skipped, self.total, "{title}: every check is run or skipped");
        let mut s = String::new();
        let _ = writeln!(
            s,
            "dyn4j {title}: {} checks, run {}, passed {}, failed {}, skipped {}",
            self.total,
            self.run,
            self.passed,
            self.failures.len(),
            skipped
        );
        for (reason, ids) in &self.skipped {
            let _ = writeln!(s, "  skipped {:>4}  {reason}  (ids {})", ids.len(), id_list(ids));
        }
        for (note, ids) in &self.notes {
            let _ = writeln!(s, "  note    {:>4}  {note}  (ids {})", ids.len(), id_list(ids));
        }
        for f in &self.failures {
            let _ = writeln!(s, "  FAIL {f}");
        }
        println!("{s}");
        assert!(self.failures.is_empty(), "{title}: {} of {} checks failed", self.failures.len(), self.run);
    }
}

fn id_list(ids: &[u32]) -> String {
    const SHOW: usize = 12;
    let mut s: Vec<String> = ids.iter().take(SHOW).map(u32::to_string).collect();
    if ids.len() > SHOW {
        s.push(format!("... +{}", ids.len() - SHOW));
    }
    s.join(" ")
}

struct Prec {
    name: &'static str,
    eps: f64,
    is_f32: bool,
}

fn prec<R: Real>() -> Prec {
    let eps = R::EPSILON.to_f64();
    Prec { name: if eps > 1e-10 { "f32" } else { "f64" }, eps, is_f32: eps > 1e-10 }
}

fn slack(tol: f64, p: &Prec, scale: f64) -> f64 {
    tol * (1.0 + TRUNCATION_SLACK) + ROUNDING_ULPS * p.eps * scale
}

/// How close to touching a pair moved by its depth along a normal must end
/// up for that normal to count as a minimum-depth direction: rounding (64
/// EPSILONs of the scale) plus ten times gjk2d's default relative epsilon
/// (1e-6 in f32, 1e-12 in f64), the accuracy the iterative queries promise.
/// The depth is flat around its minimum direction, so a normal off by an
/// angle a resolves to about depth * a^2: this limit admits angles of about
/// 3e-6 (f64) or 3e-3 (f32) at unit size, not dyn4j's 1e-3 in f64.
fn resolve_limit(p: &Prec, scale: f64) -> f64 {
    let rel = if p.is_f32 { 1e-6 } else { 1e-12 };
    ROUNDING_ULPS * p.eps * scale + 10.0 * rel * scale
}

fn f32_resolution(scale: f64) -> f64 {
    F32_FACTOR * f32::EPSILON as f64 * scale
}

// -------------------------------------------------------------- pair queries

/// Signed gap of a pair: distance when apart, minus the depth when overlapping.
fn gap<R: Real>(gjk: &Gjk<R>, a: &Placed<R>, b: &Placed<R>, tb: &Transform<R>) -> f64 {
    if let Some(s) = gjk.distance(&*a.shape, &a.t, &*b.shape, tb) {
        s.distance.to_f64()
    } else if let Some(p) = gjk.penetration(&*a.shape, &a.t, &*b.shape, tb) {
        -p.depth.to_f64()
    } else {
        f64::NAN
    }
}

/// The world farthest point of a placed shape along a world direction:
/// `transform(reference_point + support(local direction)) + radius * unit(direction)`.
fn farthest<R: Real>(s: &Placed<R>, dx: R, dy: R) -> [f64; 2] {
    let (cs, sn) = (s.t.cos(), s.t.sin());
    let local = R::vector(cs * dx + sn * dy, -sn * dx + cs * dy);
    let (rx, ry) = R::components(s.shape.reference_point());
    let (sx, sy) = R::components(s.shape.support(local));
    let (cx, cy) = R::components(s.t.transform_point(R::vector(rx + sx, ry + sy)));
    let len = (dx * dx + dy * dy).sqrt();
    let radius = s.shape.radius();
    [(cx + radius * dx / len).to_f64(), (cy + radius * dy / len).to_f64()]
}

/// The penetration depth of the pair along the unit direction n (f64): how
/// far B must move along n to stop overlapping A.
fn depth_along(a: &Placed<f64>, b: &Placed<f64>, n: glam::DVec2) -> f64 {
    let fa = glam::DVec2::from(farthest(a, n.x, n.y));
    let fb = glam::DVec2::from(farthest(b, -n.x, -n.y));
    n.dot(fa) - n.dot(fb)
}

/// The penetration depth, by brute force: the minimum of `depth_along` over
/// 8192 directions, each of the 8 best refined by a ternary search.
fn min_depth(a: &Placed<f64>, b: &Placed<f64>) -> f64 {
    const N: usize = 8192;
    let h = core::f64::consts::TAU / N as f64;
    let at = |t: f64| depth_along(a, b, glam::DVec2::new(t.cos(), t.sin()));
    let mut samples: Vec<(f64, f64)> = (0..N).map(|i| (at(i as f64 * h), i as f64 * h)).collect();
    samples.sort_by(|x, y| x.0.total_cmp(&y.0));
    let mut best = samples[0].0;
    for &(_, t0) in samples.iter().take(8) {
        let (mut lo, mut hi) = (t0 - h, t0 + h);
        for _ in 0..100 {
            let (m1, m2) = (lo + (hi - lo) / 3.0, hi - (hi - lo) / 3.0);
            if at(m1) <= at(m2) {
                hi = m2;
            } else {
                lo = m1;
            }
        }
        best = best.min(at(0.5 * (lo + hi)));
    }
    best
}

/// The gap left after moving B by `depth` along (nx, ny).
fn resolved_gap<R: Real>(gjk: &Gjk<R>, a: &Placed<R>, b: &Placed<R>, nx: R, ny: R, depth: R) -> f64 {
    let (bx, by) = R::components(b.t.translation());
    let moved = Transform::from_cos_sin(R::vector(bx + nx * depth, by + ny * depth), b.t.cos(), b.t.sin()).unwrap();
    gap(gjk, a, b, &moved)
}

/// Whether `p` lies in the placed shape, to `slack`: no sampled direction m
/// (2048 of them) has m . p beyond the shape's support value along m.
fn contains(s: &Placed<f64>, p: glam::DVec2, slack: f64) -> bool {
    (0..2048).all(|k| {
        let (sn, cs) = (k as f64 * core::f64::consts::TAU / 2048.0).sin_cos();
        let f = glam::DVec2::from(farthest(s, cs, sn));
        let m = glam::DVec2::new(cs, sn);
        m.dot(p) <= m.dot(f) + slack
    })
}

/// Certifies an f64 separation with the support functions: its points lie
/// in the shapes, so U = |p2 - p1| bounds the distance from above; along its
/// normal n the supporting lines of A and B are L apart, a lower bound. As
/// L(n) falls at least like D cos(angle to the optimal normal), the normal is
/// within sqrt(2 (U - L) / L) of the optimal one. Returns a bound on the
/// error of `field`, or None when the certificate does not hold.
fn certify_separation(a: &Placed<f64>, b: &Placed<f64>, sep: &Separation<f64>, field: &str, scale: f64) -> Option<f64> {
    let n = sep.normal;
    let sa = glam::DVec2::from(farthest(a, n.x, n.y));
    let sb = glam::DVec2::from(farthest(b, -n.x, -n.y));
    let (p1, p2) = (sep.point_a, sep.point_b);
    // The points may lie outside their shapes by `tiny`: the distance is then
    // at most |p2 - p1| + 2 tiny.
    let tiny = 1e-14 * scale;
    if !contains(a, p1, tiny) || !contains(b, p2, tiny) {
        return None;
    }
    let lower = n.dot(sb - sa);
    let upper = (p2 - p1).length() + 2.0 * tiny;
    if lower <= 0.0 || upper < lower {
        return None;
    }
    let gap = upper - lower;
    let angle = (2.0 * gap / lower).sqrt();
    match field {
        "dist" => Some(gap + (sep.distance - upper).abs()),
        "nx" | "ny" => Some(angle + (n.length() - 1.0).abs()),
        // A closest point moves by at most (radius of curvature) * angle.
        "p1x" | "p1y" | "p2x" | "p2y" => Some(4.0 * scale * angle + gap),
        _ => None,
    }
}

fn call_name(c: &Call, d: &Data) -> String {
    let ty = |s: usize| match d.shapes[s].kind {
        Kind::Circle(..) => "Circle",
        Kind::Rect(..) => "Rectangle",
        Kind::Poly(..) => "Polygon",
        Kind::Tri(..) => "Triangle",
        Kind::Seg(..) => "Segment",
        Kind::Capsule(..) | Kind::Capsule2(..) => "Capsule",
        Kind::Ellipse(..) => "Ellipse",
        Kind::HalfEllipse(..) => "HalfEllipse",
        Kind::Slice(..) => "Slice",
    };
    match c.kind {
        QKind::Ray | QKind::Far => format!("{} call {} ({})", c.kind.name(), c.call, ty(c.a)),
        _ => format!("{} call {} ({} vs {})", c.kind.name(), c.call, ty(c.a), ty(c.b)),
    }
}

const TOUCHING: &str = "touching: semantics differ (gjk2d: touching intersects, dyn4j: it does not)";
const DYN4J_ZERO: &str = "dyn4j distance says separated at distance 0 for an overlap gjk2d measures (depth > 0)";
const F32_TOL: &str = "f32: tolerance below F32_FACTOR * f32::EPSILON * scale";
const F32_EDGE: &str = "f32: pair within F32_FACTOR * f32::EPSILON * scale of touching";
const F32_CURVED: &str = "f32: normal/point of a pair with a curved shape (iterative: directions good to ~sqrt(1e-6))";
const DYN4J_OFF: &str =
    "dyn4j's expectation excludes the exact answer: checked against gjk2d's f64 answer, certified by support functions";
const TIE: &str = "unflagged tie: dyn4j's and gjk2d's normals are both minimum-depth directions";
const DYN4J_NOT_MIN: &str =
    "dyn4j's normal is not a minimum-depth direction (depth above the brute-force minimum); gjk2d's is";

fn run_pairs<R: Real>(kind: QKind) {
    let d = parse();
    let p = prec::<R>();
    let gjk = Gjk::<R>::new();
    let gjk64 = Gjk::<f64>::new();
    let mut rep = Report::default();
    for c in d.calls.iter().filter(|c| c.kind == kind) {
        let (a, b) = (placed::<R>(&d, c.a, c.ta), placed::<R>(&d, c.b, c.tb));
        let (a64, b64) = (placed::<f64>(&d, c.a, c.ta), placed::<f64>(&d, c.b, c.tb));
        let scale = 1f64.max(a64.extent).max(b64.extent);
        let gap64 = gap(&gjk64, &a64, &b64, &b64.t);
        let touching = gap64.abs() <= TOUCH * scale;
        let name = call_name(c, &d);
        let is_curved =
            |k: usize| matches!(d.shapes[k].kind, Kind::Ellipse(..) | Kind::HalfEllipse(..) | Kind::Slice(..));
        let curved = is_curved(c.a) || is_curved(c.b);
        // dyn4j's "separated, distance 0" on an overlap (see the module docs).
        let dyn4j_zero = kind == QKind::Dist
            && gap64 < -TOUCH * scale
            && c.checks.iter().any(|k| matches!(k.op, Op::Ret(true)))
            && c.checks.iter().any(|k| k.field == "dist" && matches!(k.op, Op::Approx(e, t) if e.abs() <= t));

        let detect = gjk.intersects(&*a.shape, &a.t, &*b.shape, &b.t);
        let pen = gjk.penetration(&*a.shape, &a.t, &*b.shape, &b.t);
        let sep = gjk.distance(&*a.shape, &a.t, &*b.shape, &b.t);
        let got_bool = match kind {
            QKind::Detect => detect.intersecting,
            QKind::Pen => pen.is_some(),
            _ => sep.is_some(),
        };
        // A zero normal expected (concentric circles): every direction has the depth.
        let zero_normal = kind == QKind::Pen
            && ["nx", "ny"].iter().all(|f| {
                c.checks.iter().any(|k| k.field == *f && matches!(k.op, Op::Exact(e) | Op::Approx(e, _) if e == 0.0))
            });

        for k in &c.checks {
            rep.total += 1;
            let id = k.id;
            let is_bool = matches!(k.op, Op::Ret(_) | Op::Ge(_) | Op::NotNan);
            if p.is_f32 {
                if let Op::Approx(_, tol) = k.op {
                    if tol < f32_resolution(scale) {
                        rep.skip(F32_TOL, id);
                        continue;
                    }
                }
                if is_bool && gap64.abs() <= f32_resolution(scale) {
                    rep.skip(F32_EDGE, id);
                    continue;
                }
                if curved && k.field != "depth" && k.field != "dist" && !is_bool {
                    rep.skip(F32_CURVED, id);
                    continue;
                }
            }
            if dyn4j_zero {
                // gjk2d must see the overlap dyn4j's own detect test sees.
                match pen {
                    Some(pp) if pp.depth.to_f64() > 0.0 => rep.skip(DYN4J_ZERO, id),
                    _ => rep.fail(format!(
                        "id {id} [{}] {name} {}: dyn4j-zero case but gjk2d finds no overlap",
                        p.name, k.field
                    )),
                }
                continue;
            }
            if let Op::Ret(expected) = k.op {
                if expected != got_bool && touching {
                    rep.skip(TOUCHING, id);
                } else {
                    rep.outcome(expected == got_bool, || {
                        format!(
                            "id {id} [{}] {name} ret: expected {expected}, got {got_bool} (f64 gap {gap64:e})",
                            p.name
                        )
                    });
                }
                continue;
            }
            // Value checks: the result must exist.
            let value: Option<f64> = match kind {
                QKind::Pen => pen.map(|r| {
                    let n = xy::<R>(r.normal);
                    match k.field.as_str() {
                        "depth" => r.depth.to_f64(),
                        "nx" => n[0],
                        "ny" => n[1],
                        f => panic!("id {id}: unknown field {f}"),
                    }
                }),
                QKind::Dist => sep.map(|r| separation_field(&r, &k.field)),
                _ => unreachable!(),
            };
            let Some(actual) = value else {
                if touching {
                    rep.skip(TOUCHING, id);
                } else {
                    rep.fail(format!(
                        "id {id} [{}] {name} {}: gjk2d returned no result (f64 gap {gap64:e})",
                        p.name, k.field
                    ));
                }
                continue;
            };
            // Penetration normals that need more than a comparison: dyn4j's
            // equal-depth cases, and any normal other than dyn4j's. gjk2d's
            // normal is valid when moving B by the reported depth along it
            // leaves the pair touching and that depth is the minimum over all
            // directions (brute force on the f64 support functions).
            let normal_field = kind == QKind::Pen && (k.field == "nx" || k.field == "ny");
            if normal_field && (k.ids || zero_normal || !passes(&p, scale, k, actual)) {
                let r = pen.expect("value implies a result");
                let (nx, ny) = R::components(r.normal);
                let len = nx.to_f64().hypot(ny.to_f64());
                let after = resolved_gap(&gjk, &a, &b, nx, ny, r.depth);
                let lim = resolve_limit(&p, scale);
                let min = min_depth(&a64, &b64);
                let depth = r.depth.to_f64();
                let ours_ok = (len - 1.0).abs() <= lim && after.abs() <= lim && depth <= min + lim;
                let expected = |f: &str| {
                    c.checks.iter().find_map(|k| match k.op {
                        Op::Approx(e, _) | Op::Exact(e) if k.field == f => Some(e),
                        _ => None,
                    })
                };
                let fail = |why: String| {
                    format!(
                        "id {id} [{}] {name} {}: normal ({nx:?}, {ny:?}), depth {depth} ({:?}, error bound {:?}): {why}; dyn4j expected {:?}",
                        p.name, k.field, r.status, r.error_bound, k.op
                    )
                };
                let why = format!("moving B by the depth along it leaves gap {after:e}, minimum depth over all directions {min} (limit {lim:e})");
                if k.ids || zero_normal {
                    rep.note(
                        if k.ids {
                            "initial_direction_sensitive normal: checked as a minimum-depth direction"
                        } else {
                            "zero normal expected (concentric): checked as a minimum-depth direction"
                        },
                        id,
                    );
                    rep.outcome(ours_ok, || fail(why));
                    continue;
                }
                let tol = match k.op {
                    Op::Approx(_, t) => t,
                    _ => 0.0,
                };
                if let (true, Some(ex), Some(ey)) = (ours_ok, expected("nx"), expected("ny")) {
                    // dyn4j's normal, written to `tol` per component (an angle
                    // of up to 2 tol), is a minimum-depth direction when its
                    // depth is within what such an angle can add: the depth
                    // changes by at most (extent of A + extent of B) per radian.
                    let theirs = depth_along(&a64, &b64, glam::DVec2::new(ex, ey).normalize());
                    let trunc = 2.0 * tol * (a64.extent + b64.extent) + resolve_limit(&prec::<f64>(), scale);
                    if theirs <= min + trunc {
                        rep.note(TIE, id);
                    } else {
                        rep.note(DYN4J_NOT_MIN, id);
                    }
                    rep.pass();
                    continue;
                }
                rep.fail(fail(why));
                continue;
            }
            if !passes(&p, scale, k, actual) {
                // Separation value: is dyn4j's expectation off the exact answer?
                if let (QKind::Dist, Op::Approx(expected, tol)) = (kind, k.op) {
                    if let Some(s64) = gjk64.distance(&*a64.shape, &a64.t, &*b64.shape, &b64.t) {
                        let v64 = separation_field(&s64, &k.field);
                        if let Some(err) = certify_separation(&a64, &b64, &s64, &k.field, scale) {
                            let p64 = prec::<f64>();
                            if (v64 - expected).abs() - err > slack(tol, &p64, scale) {
                                rep.note(DYN4J_OFF, id);
                                rep.outcome((actual - v64).abs() <= slack(tol, &p, scale), || {
                                    format!("id {id} [{}] {name} {}: dyn4j's {expected} ± {tol} excludes the certified f64 answer {v64} (± {err:e}); got {actual}", p.name, k.field)
                                });
                                continue;
                            }
                        }
                    }
                }
            }
            check_value(&mut rep, &p, scale, k, actual, &name);
        }
    }
    rep.finish(&format!("{} {}", kind.name(), p.name));
}

fn separation_field<R: Real>(r: &Separation<R>, field: &str) -> f64 {
    let (n, p1, p2) = (xy::<R>(r.normal), xy::<R>(r.point_a), xy::<R>(r.point_b));
    match field {
        "dist" => r.distance.to_f64(),
        "nx" => n[0],
        "ny" => n[1],
        "p1x" => p1[0],
        "p1y" => p1[1],
        "p2x" => p2[0],
        "p2y" => p2[1],
        f => panic!("unknown separation field {f}"),
    }
}

fn passes(p: &Prec, scale: f64, k: &Check, actual: f64) -> bool {
    match k.op {
        Op::Approx(expected, tol) => (actual - expected).abs() <= slack(tol, p, scale),
        Op::Exact(expected) => actual == expected,
        Op::Ge(value) => actual >= value,
        Op::NotNan => !actual.is_nan(),
        Op::Ret(_) => unreachable!(),
    }
}

fn check_value(rep: &mut Report, p: &Prec, scale: f64, k: &Check, actual: f64, name: &str) {
    let id = k.id;
    match k.op {
        Op::Approx(expected, tol) => {
            let lim = slack(tol, p, scale);
            rep.outcome((actual - expected).abs() <= lim, || {
                format!(
                    "id {id} [{}] {name} {}: expected {expected} ± {tol}, got {actual} (off by {:e}, limit {lim:e})",
                    p.name,
                    k.field,
                    (actual - expected).abs()
                )
            });
        }
        Op::Exact(expected) => {
            rep.outcome(actual == expected, || {
                format!("id {id} [{}] {name} {}: expected exactly {expected}, got {actual}", p.name, k.field)
            });
        }
        Op::Ge(value) => {
            rep.outcome(actual >= value, || {
                format!("id {id} [{}] {name} {}: expected >= {value}, got {actual}", p.name, k.field)
            });
        }
        Op::NotNan => {
            rep.outcome(!actual.is_nan(), || {
                format!("id {id} [{}] {name} {}: expected a number, got NaN", p.name, k.field)
            });
        }
        Op::Ret(_) => unreachable!(),
    }
}

// ------------------------------------------------------------------- raycast

fn run_rays<R: Real>() {
    let d = parse();
    let p = prec::<R>();
    let gjk = Gjk::<R>::new();
    let mut rep = Report::default();
    for c in d.calls.iter().filter(|c| c.kind == QKind::Ray) {
        let s = placed::<R>(&d, c.a, c.ta);
        let scale = 1f64.max(s.extent).max(c.origin[0].hypot(c.origin[1]));
        let name = call_name(c, &d);
        // dyn4j's distance and maximum are in units of |d|.
        let dlen = c.dir[0].hypot(c.dir[1]);
        let ray = Ray::new(v::<R>(c.origin[0], c.origin[1]), v::<R>(c.dir[0], c.dir[1])).unwrap();
        let max = if c.max > 0.0 { c.max * dlen } else { 0.0 };
        let cast = gjk.raycast(&ray, R::from_f64(max), &*s.shape, &s.t);
        let hit = cast.hit().copied();
        for k in &c.checks {
            rep.total += 1;
            let id = k.id;
            if (dlen - 1.0).abs() > 1e-12 {
                rep.note("non-unit dyn4j direction: distances converted by |d|", id);
            }
            if let Op::Ret(expected) = k.op {
                let got = hit.is_some();
                if !expected && cast.outcome == RayOutcome::Inside {
                    rep.note("ray starts inside: dyn4j false, gjk2d Inside", id);
                }
                rep.outcome(expected == got, || {
                    format!("id {id} [{}] {name} ret: expected {expected}, got {:?}", p.name, cast.outcome)
                });
                continue;
            }
            if let (true, Op::Approx(_, tol)) = (p.is_f32, k.op) {
                if tol < f32_resolution(scale) {
                    rep.skip(F32_TOL, id);
                    continue;
                }
            }
            let Some(h) = hit else {
                rep.fail(format!("id {id} [{}] {name} {}: gjk2d missed: {:?}", p.name, k.field, cast.outcome));
                continue;
            };
            let (pt, n) = (xy::<R>(h.point), xy::<R>(h.normal));
            let actual = match k.field.as_str() {
                "px" => pt[0],
                "py" => pt[1],
                "nx" => n[0],
                "ny" => n[1],
                "dist" => h.distance.to_f64() / dlen,
                f => panic!("id {id}: unknown field {f}"),
            };
            if let (false, "nx" | "ny", Op::Approx(expected, tol)) =
                (passes(&p, scale, k, actual), k.field.as_str(), k.op)
            {
                // The f64 normal at the f64 hit point is exact when the hit
                // point lies on the shape's supporting line along it. A normal
                // tilted by angle a from the true one leaves the hit point about
                // rho a^2 / 2 inside that line (rho: radius of curvature there,
                // taken >= 1e-3 of the bounding radius, true of every shape here).
                let s64 = placed::<f64>(&d, c.a, c.ta);
                let ray64 = Ray::new(glam::DVec2::from(c.origin), glam::DVec2::from(c.dir)).unwrap();
                let cast64 = Gjk::<f64>::new().raycast(&ray64, max, &*s64.shape, &s64.t);
                if let Some(h64) = cast64.hit() {
                    let f = glam::DVec2::from(farthest(&s64, h64.normal.x, h64.normal.y));
                    let off = (h64.normal.dot(f) - h64.normal.dot(h64.point)).abs() + (h64.normal.length() - 1.0).abs();
                    let err = (2.0 * off.max(1e-15) / (s64.shape.bounding_radius() * 1e-3)).sqrt();
                    let v64 = if k.field == "nx" { h64.normal.x } else { h64.normal.y };
                    let p64 = prec::<f64>();
                    if off <= 1e-9 * scale && (v64 - expected).abs() - err > slack(tol, &p64, scale) {
                        rep.note(DYN4J_OFF, id);
                        rep.outcome((actual - v64).abs() <= slack(tol, &p, scale), || {
                            format!("id {id} [{}] {name} {}: dyn4j's {expected} ± {tol} excludes the certified f64 answer {v64} (± {err:e}); got {actual}", p.name, k.field)
                        });
                        continue;
                    }
                }
            }
            check_value(&mut rep, &p, scale, k, actual, &name);
        }
    }
    rep.finish(&format!("raycast {}", p.name));
}

// ---------------------------------------------------------- getFarthestPoint

fn run_farthest<R: Real>() {
    let d = parse();
    let p = prec::<R>();
    let mut rep = Report::default();
    for c in d.calls.iter().filter(|c| c.kind == QKind::Far) {
        let s = placed::<R>(&d, c.a, c.ta);
        let scale = 1f64.max(s.extent);
        let name = call_name(c, &d);
        let (cs, sn) = (s.t.cos(), s.t.sin());
        let (dx, dy) = (R::from_f64(c.dir[0]), R::from_f64(c.dir[1]));
        let local = R::vector(cs * dx + sn * dy, -sn * dx + cs * dy);
        let (rx, ry) = R::components(s.shape.reference_point());
        let (sx, sy) = R::components(s.shape.support(local));
        let core = s.t.transform_point(R::vector(rx + sx, ry + sy));
        let (cx, cy) = R::components(core);
        let len = (dx * dx + dy * dy).sqrt();
        let radius = s.shape.radius();
        let far = [(cx + radius * dx / len).to_f64(), (cy + radius * dy / len).to_f64()];
        for k in &c.checks {
            rep.total += 1;
            if let (true, Op::Approx(_, tol)) = (p.is_f32, k.op) {
                if tol < f32_resolution(scale) {
                    rep.skip(F32_TOL, k.id);
                    continue;
                }
            }
            let actual = match k.field.as_str() {
                "x" => far[0],
                "y" => far[1],
                f => panic!("id {}: unknown field {f}", k.id),
            };
            check_value(&mut rep, &p, scale, k, actual, &name);
        }
    }
    rep.finish(&format!("getFarthestPoint {}", p.name));
}

// -------------------------------------------------------------------- config

fn run_config<R: Real>() {
    let d = parse();
    let p = prec::<R>();
    let mut rep = Report::default();
    let gjk = Gjk::<R>::new();
    // gjk2d's epsilons are relative (times the pair's size) and documented as
    // 5e-7 in f32 and 5e-13 in f64 (half the 1e-6 / 1e-12 they give, rounding
    // comes on top); dyn4j's are absolute, 1.0536712127723509e-8
    // (sqrt of f64 epsilon, roughly). Those checks assert gjk2d's documented value.
    let rel_eps = if p.is_f32 { 5e-7 } else { 5e-13 };
    for c in &d.config {
        rep.total += 1;
        match c {
            ConfigCheck::Default { id, setting, value } => {
                let id = *id;
                let cfg = &gjk.config;
                let epa = &gjk.solver.config;
                let want = |x: f64| value.parse::<f64>().map(|v| v == x).unwrap_or(false);
                let (ok, got): (bool, String) = match setting.as_str() {
                    "Gjk.maxDetectIterations" => {
                        (want(cfg.max_detect_iterations() as f64), cfg.max_detect_iterations().to_string())
                    }
                    "Gjk.maxDistanceIterations" => {
                        (want(cfg.max_distance_iterations() as f64), cfg.max_distance_iterations().to_string())
                    }
                    "Gjk.maxRaycastIterations" => {
                        (want(cfg.max_raycast_iterations() as f64), cfg.max_raycast_iterations().to_string())
                    }
                    "Epa.maxIterations" => (want(epa.max_iterations() as f64), epa.max_iterations().to_string()),
                    "Gjk.detectEpsilon" => (want(cfg.detect_epsilon().to_f64()), format!("{:?}", cfg.detect_epsilon())),
                    "Gjk.distanceEpsilon" | "Gjk.raycastEpsilon" | "Epa.distanceEpsilon" => {
                        let e = match setting.as_str() {
                            "Gjk.distanceEpsilon" => cfg.distance_epsilon(),
                            "Gjk.raycastEpsilon" => cfg.raycast_epsilon(),
                            _ => epa.epsilon(),
                        };
                        rep.note(
                            "epsilon default: gjk2d's documented relative value, not dyn4j's absolute 1.05e-8",
                            id,
                        );
                        (e == R::from_f64(rel_eps), format!("{e:?} (gjk2d documents {rel_eps:e}; dyn4j {value})"))
                    }
                    "Gjk.minkowskiPenetrationSolver" => {
                        // The default detector's solver is EPA, by type and by value.
                        let solver: &Epa<R> = &gjk.solver;
                        (value == "Epa" && *solver == Epa::default(), "Epa".into())
                    }
                    other => panic!("id {id}: unknown setting {other}"),
                };
                rep.outcome(ok, || {
                    format!("id {id} [{}] config_default {setting}: expected {value}, got {got}", p.name)
                });
            }
            ConfigCheck::Set { id, setting, value, how } => {
                let id = *id;
                if value == "null" {
                    // A null solver cannot be written in Rust: `Gjk::solver` is a value.
                    rep.note("null solver: unrepresentable in Rust (rejected by the type system)", id);
                    rep.pass();
                    continue;
                }
                let x: f64 = value.parse().unwrap();
                let mut cfg = GjkConfig::<R>::default();
                let mut epa = EpaConfig::<R>::default();
                let result: Result<(), Error> = if setting.ends_with("Iterations") {
                    if x < 0.0 {
                        // The setters take u32: a negative count does not compile.
                        rep.note("negative iteration count: unrepresentable (u32), rejected by the type system", id);
                        rep.outcome(how == "rejected", || {
                            format!("id {id} [{}] config_set {setting} {value}: expected {how}", p.name)
                        });
                        continue;
                    }
                    let n = x as u32;
                    match setting.as_str() {
                        "Gjk.maxDetectIterations" => cfg.set_max_detect_iterations(n),
                        "Gjk.maxDistanceIterations" => cfg.set_max_distance_iterations(n),
                        "Gjk.maxRaycastIterations" => cfg.set_max_raycast_iterations(n),
                        "Epa.maxIterations" => epa.set_max_iterations(n),
                        other => panic!("id {id}: unknown setting {other}"),
                    }
                } else {
                    let e = R::from_f64(x);
                    match setting.as_str() {
                        "Gjk.detectEpsilon" => cfg.set_detect_epsilon(e),
                        "Gjk.distanceEpsilon" => cfg.set_distance_epsilon(e),
                        "Gjk.raycastEpsilon" => cfg.set_raycast_epsilon(e),
                        "Epa.distanceEpsilon" => epa.set_epsilon(e),
                        other => panic!("id {id}: unknown setting {other}"),
                    }
                };
                let read_back = match setting.as_str() {
                    "Gjk.maxDetectIterations" => cfg.max_detect_iterations() as f64,
                    "Gjk.maxDistanceIterations" => cfg.max_distance_iterations() as f64,
                    "Gjk.maxRaycastIterations" => cfg.max_raycast_iterations() as f64,
                    "Epa.maxIterations" => epa.max_iterations() as f64,
                    "Gjk.detectEpsilon" => cfg.detect_epsilon().to_f64(),
                    "Gjk.distanceEpsilon" => cfg.distance_epsilon().to_f64(),
                    "Gjk.raycastEpsilon" => cfg.raycast_epsilon().to_f64(),
                    _ => epa.epsilon().to_f64(),
                };
                let ok = match how.as_str() {
                    "rejected" => result.is_err(),
                    "accepted" => result.is_ok(),
                    "readback" => result.is_ok() && read_back == R::from_f64(x).to_f64(),
                    other => panic!("id {id}: unknown expectation {other}"),
                };
                rep.outcome(ok, || format!("id {id} [{}] config_set {setting} = {value}: expected {how}, got {result:?} (reads back {read_back})", p.name));
            }
        }
    }
    rep.finish(&format!("config {}", p.name));
}

// --------------------------------------------------------------------- tests

/// Every check of cases.json is in the data file exactly once.
#[test]
fn data_file_is_complete() {
    let d = parse();
    let mut ids: Vec<u32> = d.calls.iter().flat_map(|c| c.checks.iter().map(|k| k.id)).collect();
    ids.extend(d.config.iter().map(|c| match c {
        ConfigCheck::Default { id, .. } | ConfigCheck::Set { id, .. } => *id,
    }));
    ids.extend(d.skipped.iter().map(|s| s.0));
    ids.sort_unstable();
    assert_eq!(ids, (1..=3141).collect::<Vec<u32>>());
    let mut by: BTreeMap<&str, usize> = BTreeMap::new();
    for s in &d.skipped {
        *by.entry(s.1.as_str()).or_default() += 1;
    }
    println!(
        "dyn4j data: 3141 checks; {} skipped as dyn4j internals (Minkowski support points, EPA simplex: not gjk2d API): {by:?}",
        d.skipped.len()
    );
}

/// The shapes built from the data have dyn4j's recorded centers (the area
/// centroid dyn4j starts GJK from): `center() + reference_point()`, placed.
#[test]
fn shape_centers_match_dyn4j() {
    let d = parse();
    let mut bad = Vec::new();
    for (k, s) in d.shapes.iter().enumerate() {
        let shape = build::<f64>(s);
        let local = shape.center() + shape.reference_point();
        let c = match s.place {
            None => local,
            Some(pl) => {
                let w = world_f64(&TDef { x: 0.0, y: 0.0, c: 1.0, s: 0.0 }, Some(pl));
                transform::<f64>(&w).transform_point(local)
            }
        };
        if (c - glam::DVec2::from(s.center)).length() > 1e-12 {
            bad.push(format!("shape {k} ({:?}): gjk2d center {c} vs dyn4j {:?}", s.kind, s.center));
        }
    }
    for b in &bad {
        println!("  FAIL {b}");
    }
    assert!(bad.is_empty(), "{} of {} shapes have a center other than dyn4j's", bad.len(), d.shapes.len());
}

#[test]
fn detect_f64() {
    run_pairs::<f64>(QKind::Detect);
}
#[test]
fn detect_f32() {
    run_pairs::<f32>(QKind::Detect);
}
#[test]
fn penetration_f64() {
    run_pairs::<f64>(QKind::Pen);
}
#[test]
fn penetration_f32() {
    run_pairs::<f32>(QKind::Pen);
}
#[test]
fn distance_f64() {
    run_pairs::<f64>(QKind::Dist);
}
#[test]
fn distance_f32() {
    run_pairs::<f32>(QKind::Dist);
}
#[test]
fn raycast_f64() {
    run_rays::<f64>();
}
#[test]
fn raycast_f32() {
    run_rays::<f32>();
}
#[test]
fn farthest_point_f64() {
    run_farthest::<f64>();
}
#[test]
fn farthest_point_f32() {
    run_farthest::<f32>();
}
#[test]
fn config_f64() {
    run_config::<f64>();
}
#[test]
fn config_f32() {
    run_config::<f32>();
}
