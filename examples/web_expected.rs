//! The browser demo's queries, run natively: what `web/test/browser-test.mjs`
//! compares the numbers the page shows against.
//!
//! Reads a scene on stdin, one item a line, in the web crate's record format
//! (`web/src/lib.rs`: `kind x y angle p0 .. p19`, 24 numbers):
//!
//! ```text
//! prec f32            # or f64
//! shape 1 0 0 0 0.9 0 0 ...
//! shape 3 2 1 0.5 2 1.2 0 ...
//! pair 0 1            # A and B, indices into the shapes
//! ray -7 -4 0.8 0.6   # origin and direction, cast unbounded at every shape
//! motion 2.2 -1       # A's motion, cast against every other shape
//! end                 # answers the scene so far; more scenes may follow
//! ```
//!
//! and prints one JSON object per `end`, every number as Rust's shortest
//! round-trip decimal of the `f64` (an `f32` result widened exactly):
//! `{"intersects":[hit,iterations,status],"penetration":[nx,ny,depth,error_bound,iterations,status]|null,
//! "distance":[d,nx,ny,ax,ay,bx,by,error_bound,iterations,status]|null,"ray":[shape,code,distance,px,py,nx,ny,iterations,status]}`.
//! The ray answer is the first shape (lowest index) the ray starts inside
//! (code 2), else the nearest hit (code 1, ties to the lower index), else
//! `[-1,0]` for a miss. The cast answer, `"cast":[shape,code,...]`, is A moving by the
//! motion against every other shape as the page picks it: the first shape (lowest
//! index) A touches or overlaps at the start (code 2: `nx,ny,depth,separating,iterations,status`),
//! else the earliest hit (code 1, ties to the lower index:
//! `fraction,distance,nx,ny,ax,ay,bx,by,error_bound,iterations,status`), else `[-1,0]`.
//! `"manifold":[count,nx,ny,iterations,status,(px,py,separation,id_a,id_b) per point]` is
//! A and B's contact manifold within the page's margin (0.25), a feature id as a number:
//! vertex k -> k, edge k -> 65536 + k, a curve -> -1.
//! Status: 0 converged, 1 iteration limit, 2 capacity limit.
//!
//! `cargo run --release --example web_expected < scene.txt`

use gjk2d::{
    Capsule, CastOutcome, Circle, Ellipse, Feature, Gjk, HalfEllipse, Motion, Polygon, Ray, RayOutcome, Real,
    Rectangle, Rounded, Segment, Slice, Status, SupportMap, Transform, Triangle,
};
use std::fmt::Write as _;
use std::io::Read;

enum Shape<R: Real> {
    Circle(Circle<R>),
    Polygon(Polygon<R, 8>),
    Rectangle(Rectangle<R>),
    Triangle(Triangle<R>),
    Segment(Segment<R>),
    Capsule(Capsule<R>),
    Ellipse(Ellipse<R>),
    HalfEllipse(HalfEllipse<R>),
    Slice(Slice<R>),
    Rounded(Rounded<R, Polygon<R, 8>>),
}

impl<R: Real> Shape<R> {
    fn as_dyn(&self) -> &dyn SupportMap<R> {
        match self {
            Shape::Circle(s) => s,
            Shape::Polygon(s) => s,
            Shape::Rectangle(s) => s,
            Shape::Triangle(s) => s,
            Shape::Segment(s) => s,
            Shape::Capsule(s) => s,
            Shape::Ellipse(s) => s,
            Shape::HalfEllipse(s) => s,
            Shape::Slice(s) => s,
            Shape::Rounded(s) => s,
        }
    }
}

fn v<R: Real>(x: f64, y: f64) -> R::Vector {
    R::vector(R::from_f64(x), R::from_f64(y))
}

fn polygon<R: Real>(p: &[f64]) -> Polygon<R, 8> {
    let n = p[0] as usize;
    let pts: Vec<R::Vector> = (0..n).map(|k| v::<R>(p[1 + 2 * k], p[2 + 2 * k])).collect();
    Polygon::new(&pts).expect("polygon")
}

fn body<R: Real>(r: &[f64]) -> (Shape<R>, Transform<R>) {
    let p = &r[4..];
    let f = |k: usize| R::from_f64(p[k]);
    let shape = match r[0] as u32 {
        1 => Shape::Circle(Circle::new(f(0)).unwrap()),
        2 => Shape::Polygon(polygon(p)),
        3 => Shape::Rectangle(Rectangle::new(f(0), f(1)).unwrap()),
        4 => Shape::Triangle(Triangle::new(v::<R>(p[0], p[1]), v::<R>(p[2], p[3]), v::<R>(p[4], p[5])).unwrap()),
        5 => Shape::Segment(Segment::new(v::<R>(p[0], p[1]), v::<R>(p[2], p[3])).unwrap()),
        6 => Shape::Capsule(Capsule::from_size(f(0), f(1)).unwrap()),
        7 => Shape::Ellipse(Ellipse::new(f(0), f(1)).unwrap()),
        8 => Shape::HalfEllipse(HalfEllipse::new(f(0), f(1)).unwrap()),
        9 => Shape::Slice(Slice::new(f(0), f(1)).unwrap()),
        10 => Shape::Rounded(Rounded::new(polygon(p), f(17)).unwrap()),
        k => panic!("unknown shape kind {k}"),
    };
    (shape, Transform::new(v::<R>(r[1], r[2]), R::from_f64(r[3])).unwrap())
}

fn status(s: Status) -> u32 {
    match s {
        Status::Converged => 0,
        Status::IterationLimit => 1,
        Status::CapacityLimit => 2,
    }
}

fn list(values: &[f64]) -> String {
    let mut s = String::from("[");
    for (i, x) in values.iter().enumerate() {
        if i > 0 {
            s.push(',');
        }
        write!(s, "{x:?}").unwrap();
    }
    s.push(']');
    s
}

/// The page's speculative margin for the manifold (web/www/app.js).
const MANIFOLD_MARGIN: f64 = 0.25;

struct Scene {
    records: Vec<Vec<f64>>,
    pair: (usize, usize),
    ray: [f64; 4],
    motion: [f64; 2],
}

fn answer<R: Real>(scene: &Scene) -> String {
    let bodies: Vec<(Shape<R>, Transform<R>)> = scene.records.iter().map(|r| body::<R>(r)).collect();
    let c = |v: R::Vector| {
        let (x, y) = R::components(v);
        [x.to_f64(), y.to_f64()]
    };
    let gjk = Gjk::<R>::new();
    let (a, ta) = (bodies[scene.pair.0].0.as_dyn(), &bodies[scene.pair.0].1);
    let (b, tb) = (bodies[scene.pair.1].0.as_dyn(), &bodies[scene.pair.1].1);

    let d = gjk.intersects(a, ta, b, tb);
    let intersects = list(&[d.intersecting as u32 as f64, d.iterations as f64, status(d.status) as f64]);
    let penetration = match gjk.penetration(a, ta, b, tb) {
        Some(p) => {
            let n = c(p.normal);
            list(&[n[0], n[1], p.depth.to_f64(), p.error_bound.to_f64(), p.iterations as f64, status(p.status) as f64])
        }
        None => "null".into(),
    };
    let distance = match gjk.distance(a, ta, b, tb) {
        Some(s) => {
            let (n, pa, pb) = (c(s.normal), c(s.point_a), c(s.point_b));
            list(&[
                s.distance.to_f64(),
                n[0],
                n[1],
                pa[0],
                pa[1],
                pb[0],
                pb[1],
                s.error_bound.to_f64(),
                s.iterations as f64,
                status(s.status) as f64,
            ])
        }
        None => "null".into(),
    };

    let [ox, oy, dx, dy] = scene.ray;
    let ray = Ray::new(v::<R>(ox, oy), v::<R>(dx, dy)).expect("ray");
    let mut best: Option<(usize, u32, Vec<f64>)> = None;
    for (k, (s, t)) in bodies.iter().enumerate() {
        let cast = gjk.raycast(&ray, R::ZERO, s.as_dyn(), t);
        let tail = [cast.iterations as f64, status(cast.status) as f64];
        match cast.outcome {
            RayOutcome::Inside => {
                best = Some((k, 2, vec![0.0, 0.0, 0.0, 0.0, 0.0, tail[0], tail[1]]));
                break;
            }
            RayOutcome::Hit(h) => {
                let closer = match &best {
                    Some((_, _, v)) => h.distance.to_f64() < v[0],
                    None => true,
                };
                if closer {
                    let (p, n) = (c(h.point), c(h.normal));
                    best = Some((k, 1, vec![h.distance.to_f64(), p[0], p[1], n[0], n[1], tail[0], tail[1]]));
                }
            }
            RayOutcome::Miss => {}
        }
    }
    let ray = match best {
        Some((k, code, values)) => {
            let mut all = vec![k as f64, code as f64];
            all.extend(values);
            list(&all)
        }
        None => "[-1,0]".into(),
    };
    let code = |f: Feature| match f {
        Feature::Vertex(k) => k as f64,
        Feature::Edge(k) => 65536.0 + k as f64,
        Feature::Curve => -1.0,
    };
    let m = gjk.manifold(a, ta, b, tb, R::from_f64(MANIFOLD_MARGIN)).expect("margin");
    let n = c(m.normal);
    let mut values = vec![m.points().len() as f64, n[0], n[1], m.iterations as f64, status(m.status) as f64];
    for p in m.points() {
        let q = c(p.point);
        values.extend([q[0], q[1], p.separation.to_f64(), code(p.id.a), code(p.id.b)]);
    }
    let manifold = list(&values);

    let motion = Motion::new(v::<R>(scene.motion[0], scene.motion[1])).expect("motion");
    let (moving, tm) = (bodies[scene.pair.0].0.as_dyn(), &bodies[scene.pair.0].1);
    let mut first: Option<(usize, u32, Vec<f64>)> = None;
    for (k, (s, t)) in bodies.iter().enumerate() {
        if k == scene.pair.0 {
            continue;
        }
        let cast = gjk.cast(s.as_dyn(), t, moving, tm, &motion);
        let tail = [cast.iterations as f64, status(cast.status) as f64];
        match cast.outcome {
            CastOutcome::Start(start) => {
                let (p, n) = (start.penetration, c(start.penetration.normal));
                let separating = start.separating as u32 as f64;
                first = Some((k, 2, vec![n[0], n[1], p.depth.to_f64(), separating, tail[0], tail[1]]));
                break;
            }
            CastOutcome::Hit(h) => {
                if first.as_ref().is_none_or(|(_, _, v)| h.fraction.to_f64() < v[0]) {
                    let (n, pa, pb) = (c(h.normal), c(h.point_a), c(h.point_b));
                    let at = [h.fraction.to_f64(), h.distance.to_f64(), n[0], n[1], pa[0], pa[1], pb[0], pb[1]];
                    first = Some((k, 1, [&at[..], &[h.error_bound.to_f64()], &tail[..]].concat()));
                }
            }
            CastOutcome::Miss => {}
        }
    }
    let cast = match first {
        Some((k, code, values)) => list(&[&[k as f64, code as f64][..], &values].concat()),
        None => "[-1,0]".into(),
    };
    format!(
        "{{\"intersects\":{intersects},\"penetration\":{penetration},\"distance\":{distance},\"ray\":{ray},\"cast\":{cast},\"manifold\":{manifold}}}"
    )
}

fn main() {
    let mut input = String::new();
    std::io::stdin().read_to_string(&mut input).expect("stdin");
    let mut scene = Scene { records: Vec::new(), pair: (0, 1), ray: [0.0, 0.0, 1.0, 0.0], motion: [1.0, 0.0] };
    let mut f64_precision = false;
    for line in input.lines() {
        let mut words = line.split_whitespace();
        let Some(head) = words.next() else { continue };
        let nums: Vec<f64> = words.clone().filter_map(|w| w.parse().ok()).collect();
        match head {
            "prec" => f64_precision = words.next() == Some("f64"),
            "shape" => {
                let mut r = nums;
                r.resize(24, 0.0);
                scene.records.push(r);
            }
            "pair" => scene.pair = (nums[0] as usize, nums[1] as usize),
            "ray" => scene.ray = [nums[0], nums[1], nums[2], nums[3]],
            "motion" => scene.motion = [nums[0], nums[1]],
            "end" => {
                let out = if f64_precision { answer::<f64>(&scene) } else { answer::<f32>(&scene) };
                println!("{out}");
                scene.records.clear();
            }
            _ => panic!("unknown line: {line}"),
        }
    }
}
