//! Known-answer tests of every query on every shape kind, generic over the
//! precision. Every expected value is derived by hand (comments give the
//! geometry); tolerances are stated in [`Tol`].

use crate::harness::Tally;
use gjk2d::{
    Capsule, Circle, Ellipse, Epa, Gjk, GjkConfig, HalfEllipse, Polygon, Ray, RayOutcome, Real, Rectangle, Rounded,
    Segment, Slice, Status, SupportMap, Transform, Triangle,
};

fn r<R: Real>(x: f64) -> R {
    R::from_f64(x)
}

fn is_f32<R: Real>() -> bool {
    R::EPSILON > R::from_f64(1e-10)
}

/// The tolerances of the checks (absolute; every answer is of size 0.1 to 5).
///
/// - `exact`: closed-form answers (polygons, rectangles, triangles, segments,
///   circles, capsules, and the distance and depth of rounded shapes): a few
///   dozen ulps. f32 1e-5, f64 1e-13.
/// - `curved`: distances, depths and ray distances on curved boundaries
///   (ellipse, half ellipse, slice arc, ray casts on rounded shapes), which
///   iterate to the default relative epsilon (1e-6 in f32, 1e-12 in f64)
///   times the pair's size. f32 5e-5, f64 5e-11.
/// - `curved_dir`: normals and closest points on curved boundaries: their
///   error is about the square root of the distance's (the support direction
///   converges linearly). f32 5e-3, f64 5e-6.
#[derive(Clone, Copy)]
pub struct Tol<R> {
    pub exact: R,
    pub curved: R,
    pub curved_dir: R,
}

impl<R: Real> Tol<R> {
    pub fn new() -> Self {
        if is_f32::<R>() {
            Tol { exact: r(1e-5), curved: r(5e-5), curved_dir: r(5e-3) }
        } else {
            Tol { exact: r(1e-13), curved: r(5e-11), curved_dir: r(5e-6) }
        }
    }
}

impl<R: Real> Default for Tol<R> {
    fn default() -> Self {
        Self::new()
    }
}

/// A shape placed right of the "wall" (the polygon x in [-1, 1], y in
/// [-10, 10] at the identity), rotated by (cos, sin).
struct WallCase<'a, R: Real> {
    name: &'static str,
    shape: &'a dyn SupportMap<R>,
    cos: f64,
    sin: f64,
    /// Extent of the rotated shape to the left of its placement point.
    left: f64,
    /// The y range of its leftmost points (a single y for a unique point).
    ylo: f64,
    yhi: f64,
    /// Distance and penetration meet a curved boundary: iterative tolerances.
    curved: bool,
    /// The ray cast iterates (no closed form for this shape).
    ray_iterates: bool,
    /// The leftmost point is a vertex: the ray's normal there is ambiguous.
    vertex: bool,
    /// A point strictly inside the shape (local coordinates).
    inside: (f64, f64),
}

const GAP: f64 = 0.5;
const DEPTH: f64 = 0.25;

/// Per shape: intersection apart and overlapping, distance with closest
/// points (gap 0.5), penetration (depth 0.25: the wall is tall, so pushing
/// the shape right along +x is the shortest way out), and ray casts along +x
/// (hit at distance 2, miss above, start inside, stop short).
fn wall_case<R: Real>(t: &mut Tally, gjk: &Gjk<R>, wall: &Polygon<R, 4>, c: &WallCase<R>) {
    let tol = Tol::<R>::new();
    let (pt, dt) = if c.curved { (tol.curved_dir, tol.curved) } else { (tol.exact, tol.exact) };
    let id = Transform::<R>::IDENTITY;
    let place = |x: f64| Transform::<R>::from_cos_sin(R::vector(r(x), R::ZERO), r(c.cos), r(c.sin));
    let (apart, over) = match (place(1.0 + GAP + c.left), place(1.0 - DEPTH + c.left)) {
        (Ok(a), Ok(o)) => (a, o),
        _ => {
            t.ok(c.name, false);
            return;
        }
    };
    let mut name = Name::new(c.name);

    // Intersection.
    t.ok(name.with(" intersects apart = false"), !gjk.intersects(wall, &id, c.shape, &apart).intersecting);
    t.ok(name.with(" intersects overlapping = true"), gjk.intersects(wall, &id, c.shape, &over).intersecting);

    // Distance and closest points.
    match gjk.distance(wall, &id, c.shape, &apart) {
        None => {
            t.ok(name.with(" distance apart is Some"), false);
        }
        Some(s) => {
            t.near(name.with(" distance"), s.distance, r(GAP), dt);
            t.near_v(name.with(" distance normal"), s.normal, (R::ONE, R::ZERO), pt);
            let (ax, ay) = R::components(s.point_a);
            let (bx, by) = R::components(s.point_b);
            t.near(name.with(" point_a.x"), ax, R::ONE, pt);
            t.within(name.with(" point_a.y"), ay, r(c.ylo), r(c.yhi), pt);
            t.near(name.with(" point_b.x"), bx, r(1.0 + GAP), pt);
            t.near(name.with(" point_b.y = point_a.y"), by, ay, pt);
            t.ok(name.with(" distance converged"), s.status == Status::Converged);
            t.ok(name.with(" distance error bound"), s.error_bound <= dt);
        }
    }
    t.ok(name.with(" distance overlapping = None"), gjk.distance(wall, &id, c.shape, &over).is_none());

    // Penetration.
    match gjk.penetration(wall, &id, c.shape, &over) {
        None => {
            t.ok(name.with(" penetration overlapping is Some"), false);
        }
        Some(p) => {
            t.near(name.with(" depth"), p.depth, r(DEPTH), dt);
            t.near_v(name.with(" penetration normal"), p.normal, (R::ONE, R::ZERO), pt);
            t.ok(name.with(" penetration converged"), p.status == Status::Converged);
            t.ok(name.with(" penetration error bound"), p.error_bound <= dt);
        }
    }
    t.ok(name.with(" penetration apart = None"), gjk.penetration(wall, &id, c.shape, &apart).is_none());

    // Ray casts against the shape alone, placed apart.
    let face = 1.0 + GAP; // x of the leftmost point
    let ymid = 0.5 * (c.ylo + c.yhi);
    let rt = if c.ray_iterates { tol.curved } else { tol.exact };
    let rn = if c.ray_iterates || c.curved { tol.curved_dir } else { tol.exact };
    if let Ok(ray) = Ray::new(R::vector(r(face - 2.0), r(ymid)), R::vector(R::ONE, R::ZERO)) {
        let cast = gjk.raycast(&ray, R::ZERO, c.shape, &apart);
        match cast.outcome {
            RayOutcome::Hit(h) => {
                t.near(name.with(" ray distance"), h.distance, r(2.0), rt);
                t.near_v(name.with(" ray point"), h.point, (r(face), r(ymid)), rt);
                if !c.vertex {
                    t.near_v(name.with(" ray normal"), h.normal, (-R::ONE, R::ZERO), rn);
                }
                t.ok(name.with(" ray converged"), cast.status == Status::Converged);
                t.ok(name.with(" ray iterations"), (cast.iterations > 0) == c.ray_iterates);
            }
            _ => {
                t.ok(name.with(" ray hits"), false);
            }
        }
        // Bounded: a maximum length short of the hit misses, a longer one hits.
        t.ok(name.with(" ray max 1.5 misses"), gjk.raycast(&ray, r(1.5), c.shape, &apart).outcome == RayOutcome::Miss);
        t.ok(name.with(" ray max 2.5 hits"), gjk.raycast(&ray, r(2.5), c.shape, &apart).hit().is_some());
    }
    if let Ok(ray) = Ray::new(R::vector(r(face - 2.0), r(30.0)), R::vector(R::ONE, R::ZERO)) {
        t.ok(name.with(" ray above misses"), gjk.raycast(&ray, R::ZERO, c.shape, &apart).outcome == RayOutcome::Miss);
    }
    let inside = apart.transform_point(R::vector(r(c.inside.0), r(c.inside.1)));
    if let Ok(ray) = Ray::new(inside, R::vector(R::ZERO, R::ONE)) {
        t.ok(name.with(" ray from inside"), gjk.raycast(&ray, R::ZERO, c.shape, &apart).outcome == RayOutcome::Inside);
    }
}

/// A check's name: the case name plus a suffix, in a fixed buffer.
struct Name {
    buf: [u8; 96],
    base: usize,
}

impl Name {
    fn new(base: &str) -> Self {
        let mut buf = [0u8; 96];
        let n = base.len().min(48);
        buf[..n].copy_from_slice(&base.as_bytes()[..n]);
        Name { buf, base: n }
    }
    fn with(&mut self, suffix: &str) -> &str {
        let n = suffix.len().min(self.buf.len() - self.base);
        self.buf[self.base..self.base + n].copy_from_slice(&suffix.as_bytes()[..n]);
        core::str::from_utf8(&self.buf[..self.base + n]).unwrap_or("?")
    }
}

fn v<R: Real>(x: f64, y: f64) -> R::Vector {
    R::vector(r(x), r(y))
}

/// Runs every known-answer test in precision R.
pub fn run<R: Real>(t: &mut Tally) {
    let tol = Tol::<R>::new();
    let gjk = Gjk::<R>::new();
    let id = Transform::<R>::IDENTITY;
    let Ok(wall) =
        Polygon::<R, 4>::new(&[v::<R>(-1.0, -10.0), v::<R>(1.0, -10.0), v::<R>(1.0, 10.0), v::<R>(-1.0, 10.0)])
    else {
        t.ok("wall polygon", false);
        return;
    };

    macro_rules! case {
        ($shape:expr, $name:expr, cos = $c:expr, sin = $s:expr, left = $left:expr, y = $ylo:expr, $yhi:expr,
         curved = $curved:expr, ray_iterates = $ri:expr, vertex = $vx:expr, inside = $inside:expr) => {
            match $shape {
                Ok(shape) => wall_case(
                    t,
                    &gjk,
                    &wall,
                    &WallCase {
                        name: $name,
                        shape: &shape,
                        cos: $c,
                        sin: $s,
                        left: $left,
                        ylo: $ylo,
                        yhi: $yhi,
                        curved: $curved,
                        ray_iterates: $ri,
                        vertex: $vx,
                        inside: $inside,
                    },
                ),
                Err(_) => {
                    t.ok(concat!($name, " constructs"), false);
                }
            }
        };
    }

    // Circle r = 0.5 about its origin: leftmost (-0.5, 0).
    case!(
        Circle::<R>::new(r(0.5)),
        "circle",
        cos = 1.0,
        sin = 0.0,
        left = 0.5,
        y = 0.0,
        0.0,
        curved = false,
        ray_iterates = false,
        vertex = false,
        inside = (0.1, 0.0)
    );
    // Circle r = 0.5 centred at (0.25, 0.1): leftmost (-0.25, 0.1).
    case!(
        Circle::<R>::at(v::<R>(0.25, 0.1), r(0.5)),
        "offset circle",
        cos = 1.0,
        sin = 0.0,
        left = 0.25,
        y = 0.1,
        0.1,
        curved = false,
        ray_iterates = false,
        vertex = false,
        inside = (0.25, 0.1)
    );
    // Unit square [0,1]^2: flat left face x = 0, y in [0, 1].
    case!(
        Polygon::<R, 4>::new(&[v::<R>(0.0, 0.0), v::<R>(1.0, 0.0), v::<R>(1.0, 1.0), v::<R>(0.0, 1.0)]),
        "square",
        cos = 1.0,
        sin = 0.0,
        left = 0.0,
        y = 0.0,
        1.0,
        curved = false,
        ray_iterates = false,
        vertex = false,
        inside = (0.5, 0.5)
    );
    // Diamond (given clockwise, which the constructor reverses): vertex (0, 0) leftmost.
    case!(
        Polygon::<R, 6>::new(&[v::<R>(0.0, 0.0), v::<R>(1.0, 1.0), v::<R>(2.0, 0.0), v::<R>(1.0, -1.0)]),
        "diamond",
        cos = 1.0,
        sin = 0.0,
        left = 0.0,
        y = 0.0,
        0.0,
        curved = false,
        ray_iterates = false,
        vertex = true,
        inside = (1.0, 0.0)
    );
    // Regular octagon of circumradius 1 rotated by pi/8: a face at distance
    // cos(pi/8) faces -x, spanning y in [-sin(pi/8), sin(pi/8)].
    let (c8, s8) = (0.923_879_532_511_286_7, 0.382_683_432_365_089_8);
    case!(
        Polygon::<R, 8>::regular(8, R::ONE),
        "rotated octagon",
        cos = c8,
        sin = s8,
        left = c8,
        y = -s8,
        s8,
        curved = false,
        ray_iterates = false,
        vertex = false,
        inside = (0.0, 0.0)
    );
    // Rectangle 2 x 1 about its origin: flat left face x = -1, y in [-0.5, 0.5].
    case!(
        Rectangle::<R>::new(r(2.0), r(1.0)),
        "rectangle",
        cos = 1.0,
        sin = 0.0,
        left = 1.0,
        y = -0.5,
        0.5,
        curved = false,
        ray_iterates = false,
        vertex = false,
        inside = (0.0, 0.0)
    );
    // Triangle (0,0), (2,-1), (2,1): apex (0, 0) leftmost.
    case!(
        Triangle::<R>::new(v::<R>(0.0, 0.0), v::<R>(2.0, -1.0), v::<R>(2.0, 1.0)),
        "triangle",
        cos = 1.0,
        sin = 0.0,
        left = 0.0,
        y = 0.0,
        0.0,
        curved = false,
        ray_iterates = false,
        vertex = true,
        inside = (1.0, 0.0)
    );
    // Vertical segment x = 0, y in [-1, 1]. A ray starting on it is "inside".
    case!(
        Segment::<R>::new(v::<R>(0.0, -1.0), v::<R>(0.0, 1.0)),
        "segment",
        cos = 1.0,
        sin = 0.0,
        left = 0.0,
        y = -1.0,
        1.0,
        curved = false,
        ray_iterates = false,
        vertex = false,
        inside = (0.0, 0.5)
    );
    // Horizontal capsule (-0.5,0)-(0.5,0), r 0.25: leftmost (-0.75, 0), on the end cap.
    case!(
        Capsule::<R>::new(v::<R>(-0.5, 0.0), v::<R>(0.5, 0.0), r(0.25)),
        "capsule (cap)",
        cos = 1.0,
        sin = 0.0,
        left = 0.75,
        y = 0.0,
        0.0,
        curved = false,
        ray_iterates = false,
        vertex = false,
        inside = (0.0, 0.0)
    );
    // Vertical capsule (0,-0.5)-(0,0.5), r 0.25: flat side x = -0.25, y in [-0.5, 0.5].
    case!(
        Capsule::<R>::new(v::<R>(0.0, -0.5), v::<R>(0.0, 0.5), r(0.25)),
        "capsule (side)",
        cos = 1.0,
        sin = 0.0,
        left = 0.25,
        y = -0.5,
        0.5,
        curved = false,
        ray_iterates = false,
        vertex = false,
        inside = (0.0, 0.0)
    );
    // Ellipse 4 x 2 (semi-axes 2, 1): leftmost (-2, 0).
    case!(
        Ellipse::<R>::new(r(4.0), r(2.0)),
        "ellipse",
        cos = 1.0,
        sin = 0.0,
        left = 2.0,
        y = 0.0,
        0.0,
        curved = true,
        ray_iterates = true,
        vertex = false,
        inside = (1.0, 0.3)
    );
    // Half ellipse 4 wide, 2 high, rotated +90 degrees: its dome top (0, 2)
    // becomes the leftmost point (-2, 0).
    case!(
        HalfEllipse::<R>::new(r(4.0), r(2.0)),
        "half ellipse (dome)",
        cos = 0.0,
        sin = 1.0,
        left = 2.0,
        y = 0.0,
        0.0,
        curved = true,
        ray_iterates = true,
        vertex = false,
        inside = (0.5, 0.5)
    );
    // The same unrotated: its flat side's corner (-2, 0) is leftmost; the
    // dome (a half circle here) meets it with a vertical tangent, so GJK
    // converges to it along a curve.
    case!(
        HalfEllipse::<R>::new(r(4.0), r(2.0)),
        "half ellipse (corner)",
        cos = 1.0,
        sin = 0.0,
        left = 2.0,
        y = 0.0,
        0.0,
        curved = true,
        ray_iterates = true,
        vertex = true,
        inside = (0.5, 0.5)
    );
    // Slice r 1, 90 degrees, rotated by 180: its arc's middle (-1, 0) is leftmost.
    case!(
        Slice::<R>::new(R::ONE, r(core::f64::consts::FRAC_PI_2)),
        "slice (arc)",
        cos = -1.0,
        sin = 0.0,
        left = 1.0,
        y = 0.0,
        0.0,
        curved = true,
        ray_iterates = true,
        vertex = false,
        inside = (0.5, 0.0)
    );
    // The same unrotated: its apex (0, 0) is leftmost.
    case!(
        Slice::<R>::new(R::ONE, r(core::f64::consts::FRAC_PI_2)),
        "slice (apex)",
        cos = 1.0,
        sin = 0.0,
        left = 0.0,
        y = 0.0,
        0.0,
        curved = false,
        ray_iterates = true,
        vertex = true,
        inside = (0.5, 0.0)
    );
    // Unit square rounded by 0.25: flat left face x = -0.75, y in [-0.5, 0.5].
    case!(
        Rectangle::<R>::new(R::ONE, R::ONE).and_then(|s| Rounded::new(s, r(0.25))),
        "rounded rectangle",
        cos = 1.0,
        sin = 0.0,
        left = 0.75,
        y = -0.5,
        0.5,
        curved = false,
        ray_iterates = true,
        vertex = false,
        inside = (0.0, 0.0)
    );
    // Triangle (0,0), (2,-1), (2,1) rounded by 0.5: the apex's disk gives the
    // leftmost point (-0.5, 0) (the apex's normal cone contains -x).
    case!(
        Triangle::<R>::new(v::<R>(0.0, 0.0), v::<R>(2.0, -1.0), v::<R>(2.0, 1.0)).and_then(|s| Rounded::new(s, r(0.5))),
        "rounded triangle",
        cos = 1.0,
        sin = 0.0,
        left = 0.5,
        y = 0.0,
        0.0,
        curved = false,
        ray_iterates = true,
        vertex = false,
        inside = (1.0, 0.0)
    );

    pairs::<R>(t, &gjk, &id, &tol);
}

/// Pairs other than against the wall: squares, circles, capsules, ellipses,
/// rotated rays, and EPA at a small capacity.
fn pairs<R: Real>(t: &mut Tally, gjk: &Gjk<R>, id: &Transform<R>, tol: &Tol<R>) {
    let e = tol.exact;
    let at = |x: f64, y: f64| Transform::<R>::from_translation(v::<R>(x, y)).unwrap_or(Transform::IDENTITY);
    let Ok(square) = Polygon::<R, 4>::new(&[v::<R>(0.0, 0.0), v::<R>(1.0, 0.0), v::<R>(1.0, 1.0), v::<R>(0.0, 1.0)])
    else {
        t.ok("square", false);
        return;
    };

    // Unit squares [0,1]^2: B at (2, 0) is 1 apart along +x.
    t.ok("squares (2,0) apart", !gjk.intersects(&square, id, &square, &at(2.0, 0.0)).intersecting);
    match gjk.distance(&square, id, &square, &at(2.0, 0.0)) {
        Some(s) => {
            t.near("squares (2,0) distance", s.distance, R::ONE, e);
            t.near_v("squares (2,0) normal", s.normal, (R::ONE, R::ZERO), e);
        }
        None => {
            t.ok("squares (2,0) distance", false);
        }
    }
    // B at (2, 2): corner to corner, sqrt 2 along the diagonal, closest
    // points (1, 1) and (2, 2).
    match gjk.distance(&square, id, &square, &at(2.0, 2.0)) {
        Some(s) => {
            let h = r::<R>(core::f64::consts::FRAC_1_SQRT_2);
            t.near("squares (2,2) distance", s.distance, r(core::f64::consts::SQRT_2), e);
            t.near_v("squares (2,2) normal", s.normal, (h, h), e);
            t.near_v("squares (2,2) point_a", s.point_a, (R::ONE, R::ONE), e);
            t.near_v("squares (2,2) point_b", s.point_b, (r(2.0), r(2.0)), e);
        }
        None => {
            t.ok("squares (2,2) distance", false);
        }
    }
    // B at (0.75, 0.5): overlap 0.25 in x, 0.5 in y: depth 0.25 along +x.
    t.ok("squares (0.75,0.5) intersect", gjk.intersects(&square, id, &square, &at(0.75, 0.5)).intersecting);
    match gjk.penetration(&square, id, &square, &at(0.75, 0.5)) {
        Some(p) => {
            t.near("squares (0.75,0.5) depth", p.depth, r(0.25), e);
            t.near_v("squares (0.75,0.5) normal", p.normal, (R::ONE, R::ZERO), e);
        }
        None => {
            t.ok("squares (0.75,0.5) penetration", false);
        }
    }
    // B at (0.5, 0.9): overlap 0.5 in x, 0.1 in y: depth 0.1 along +y.
    match gjk.penetration(&square, id, &square, &at(0.5, 0.9)) {
        Some(p) => {
            t.near("squares (0.5,0.9) depth", p.depth, r(0.1), e);
            t.near_v("squares (0.5,0.9) normal", p.normal, (R::ZERO, R::ONE), e);
        }
        None => {
            t.ok("squares (0.5,0.9) penetration", false);
        }
    }
    // Same squares, B at (0.5, -0.9): depth 0.1 along -y.
    match gjk.penetration(&square, id, &square, &at(0.5, -0.9)) {
        Some(p) => {
            t.near("squares (0.5,-0.9) depth", p.depth, r(0.1), e);
            t.near_v("squares (0.5,-0.9) normal", p.normal, (R::ZERO, -R::ONE), e);
        }
        None => {
            t.ok("squares (0.5,-0.9) penetration", false);
        }
    }

    // Circles r 1 at the origin and r 0.5 at (3, 4): 5 - 1.5 = 3.5 apart
    // along (0.6, 0.8); closest points (0.6, 0.8) and (2.7, 3.6).
    if let (Ok(a), Ok(b)) = (Circle::<R>::new(R::ONE), Circle::<R>::new(r(0.5))) {
        match gjk.distance(&a, id, &b, &at(3.0, 4.0)) {
            Some(s) => {
                t.near("circles distance", s.distance, r(3.5), e);
                t.near_v("circles normal", s.normal, (r(0.6), r(0.8)), e);
                t.near_v("circles point_a", s.point_a, (r(0.6), r(0.8)), e);
                t.near_v("circles point_b", s.point_b, (r(2.7), r(3.6)), e);
                t.ok("circles no iteration error", s.error_bound == R::ZERO);
            }
            None => {
                t.ok("circles distance", false);
            }
        }
        // B at (1.2, 0): depth 1 + 0.5 - 1.2 = 0.3 along +x.
        t.ok("circles (1.2,0) intersect", gjk.intersects(&a, id, &b, &at(1.2, 0.0)).intersecting);
        match gjk.penetration(&a, id, &b, &at(1.2, 0.0)) {
            Some(p) => {
                t.near("circles depth", p.depth, r(0.3), e);
                t.near_v("circles penetration normal", p.normal, (R::ONE, R::ZERO), e);
            }
            None => {
                t.ok("circles penetration", false);
            }
        }
        // Ray from the origin along (0.6, 0.8) to a circle r 5 at (6, 8):
        // enters at distance 10 - 5 = 5, point (3, 4), normal (-0.6, -0.8).
        if let (Ok(big), Ok(ray)) = (Circle::<R>::new(r(5.0)), Ray::new(v::<R>(0.0, 0.0), v::<R>(3.0, 4.0))) {
            match gjk.raycast(&ray, R::ZERO, &big, &at(6.0, 8.0)).outcome {
                RayOutcome::Hit(h) => {
                    t.near("circle ray distance", h.distance, r(5.0), e);
                    t.near_v("circle ray point", h.point, (r(3.0), r(4.0)), e);
                    t.near_v("circle ray normal", h.normal, (r(-0.6), r(-0.8)), e);
                }
                _ => {
                    t.ok("circle ray hits", false);
                }
            }
        }
    }

    // Parallel capsules (-1,0)-(1,0), r 0.5, B 1.5 above: 0.5 apart along +y.
    if let Ok(c) = Capsule::<R>::new(v::<R>(-1.0, 0.0), v::<R>(1.0, 0.0), r(0.5)) {
        match gjk.distance(&c, id, &c, &at(0.0, 1.5)) {
            Some(s) => {
                t.near("capsules distance", s.distance, r(0.5), e);
                t.near_v("capsules normal", s.normal, (R::ZERO, R::ONE), e);
                let (ax, ay) = R::components(s.point_a);
                let (bx, by) = R::components(s.point_b);
                t.near("capsules point_a.y", ay, r(0.5), e);
                t.near("capsules point_b.y", by, R::ONE, e);
                t.within("capsules point_a.x", ax, -R::ONE, R::ONE, e);
                t.near("capsules point_b.x", bx, ax, e);
            }
            None => {
                t.ok("capsules distance", false);
            }
        }
        // B 0.8 above: cores 0.8 apart, depth 1 - 0.8 = 0.2 along +y (closed form, no EPA).
        match gjk.penetration(&c, id, &c, &at(0.0, 0.8)) {
            Some(p) => {
                t.near("capsules depth", p.depth, r(0.2), e);
                t.near_v("capsules penetration normal", p.normal, (R::ZERO, R::ONE), e);
            }
            None => {
                t.ok("capsules penetration", false);
            }
        }
    }

    // Ellipses 4 x 2 at the origin and 2 x 4 at (4, 0): tips (2, 0) and
    // (3, 0), 1 apart along +x. At (2.75, 0) they overlap by 0.25 along +x
    // (the depth along angle a from +x grows as 0.25 + 2.125 a^2).
    if let (Ok(a), Ok(b)) = (Ellipse::<R>::new(r(4.0), r(2.0)), Ellipse::<R>::new(r(2.0), r(4.0))) {
        match gjk.distance(&a, id, &b, &at(4.0, 0.0)) {
            Some(s) => {
                t.near("ellipses distance", s.distance, R::ONE, tol.curved);
                t.near_v("ellipses normal", s.normal, (R::ONE, R::ZERO), tol.curved_dir);
                t.near_v("ellipses point_a", s.point_a, (r(2.0), R::ZERO), tol.curved_dir);
                t.near_v("ellipses point_b", s.point_b, (r(3.0), R::ZERO), tol.curved_dir);
            }
            None => {
                t.ok("ellipses distance", false);
            }
        }
        // Default EPA (N = 32): converges in both precisions. In f64
        // (epsilon 1e-12) it takes about 45 supports, more than the polytope
        // holds: the corners whose edges are certified merge away. The
        // bounds hold: depth <= 0.25 <= depth + bound.
        match gjk.penetration(&a, id, &b, &at(2.75, 0.0)) {
            Some(p) => {
                t.ok("ellipses penetration (N = 32) status", p.status == Status::Converged);
                t.ok("ellipses penetration (N = 32) lower bound", p.depth <= r::<R>(0.25) + tol.curved);
                t.ok("ellipses penetration (N = 32) upper bound", p.depth + p.error_bound >= r::<R>(0.25) - tol.curved);
                t.near_v("ellipses penetration (N = 32) normal", p.normal, (R::ONE, R::ZERO), tol.curved_dir * r(10.0));
            }
            None => {
                t.ok("ellipses penetration (N = 32)", false);
            }
        }
        // With room for 64 vertices EPA converges in both precisions.
        let roomy = Gjk::with_solver(GjkConfig::default(), Epa::<R, 64>::default());
        match roomy.penetration(&a, id, &b, &at(2.75, 0.0)) {
            Some(p) => {
                t.near("ellipses depth (N = 64)", p.depth, r(0.25), tol.curved);
                t.near_v("ellipses penetration normal (N = 64)", p.normal, (R::ONE, R::ZERO), tol.curved_dir);
                t.ok("ellipses penetration converged (N = 64)", p.status == Status::Converged);
            }
            None => {
                t.ok("ellipses penetration (N = 64)", false);
            }
        }
        // EPA with room for 4 polytope vertices cannot certify curved cores:
        // its polytope fills up and the support-function polish finds the
        // depth. Whatever the status, the depth is achievable (an upper
        // bound) within its certified gap, |depth - 0.25| <= error_bound,
        // and a converged answer is accurate.
        let small = Gjk::with_solver(GjkConfig::default(), Epa::<R, 4>::default());
        match small.penetration(&a, id, &b, &at(2.75, 0.0)) {
            Some(p) => {
                let accurate = (p.depth - r::<R>(0.25)).abs() <= tol.curved;
                t.ok("EPA<4> converged answers are accurate", p.status != Status::Converged || accurate);
                t.ok("EPA<4> depth is achievable", p.depth >= r::<R>(0.25) - tol.curved);
                t.ok("EPA<4> within its error bound", (p.depth - r::<R>(0.25)).abs() <= p.error_bound + tol.curved);
            }
            None => {
                t.ok("EPA<4> penetration", false);
            }
        }
    }

    // Unit square rotated by pi/4 with Transform::new (sin, cos): the face
    // that was x = 1 has outward normal (s, s), s = sqrt(1/2), and midpoint
    // (s/2, 3s/2). A ray from 3 units out along the normal, pointing back,
    // enters at distance 3.
    let s = core::f64::consts::FRAC_1_SQRT_2;
    if let (Ok(tf), Ok(ray)) = (
        Transform::<R>::new(v::<R>(0.0, 0.0), r(core::f64::consts::FRAC_PI_4)),
        Ray::new(v::<R>(0.5 * s + 3.0 * s, 1.5 * s + 3.0 * s), v::<R>(-1.0, -1.0)),
    ) {
        match gjk.raycast(&ray, R::ZERO, &square, &tf).outcome {
            RayOutcome::Hit(h) => {
                // The rotation comes from sin and cos: a few ulps more.
                let e4 = e * r(4.0);
                t.near("rotated square ray distance", h.distance, r(3.0), e4);
                t.near_v("rotated square ray point", h.point, (r(0.5 * s), r(1.5 * s)), e4);
                t.near_v("rotated square ray normal", h.normal, (r(s), r(s)), e4);
            }
            _ => {
                t.ok("rotated square ray hits", false);
            }
        }
    }
}

/// Polygons the compiler checked and framed (`Polygon::from_array`, run by
/// rustc's const evaluator on the build machine) are bit for bit the ones
/// this target builds at run time (`Polygon::new`): one more determinism
/// check, between the build host and the device.
macro_rules! const_polygons {
    ($name:ident, $R:ty, $V:ty) => {
        pub fn $name(t: &mut Tally) {
            const fn frozen<const N: usize>(points: [$V; N]) -> Polygon<$R, N> {
                match Polygon::<$R, N>::from_array(points) {
                    Ok(p) => p,
                    Err(e) => panic!("{}", e.as_str()),
                }
            }
            // Clockwise, with a collinear vertex; far from the origin; tiny.
            const CW: [$V; 5] = [
                <$V>::new(0.0, 0.0),
                <$V>::new(0.25, 3.0),
                <$V>::new(0.5, 6.0),
                <$V>::new(7.0, 0.5),
                <$V>::new(3.0, -1.0),
            ];
            const FAR: [$V; 4] = [
                <$V>::new(1.0e5 + 0.1, -2.0e5),
                <$V>::new(1.0e5 + 3.3, -2.0e5 + 0.7),
                <$V>::new(1.0e5 + 1.9, -2.0e5 + 2.9),
                <$V>::new(1.0e5 - 0.3, -2.0e5 + 1.3),
            ];
            const TINY: [$V; 3] =
                [<$V>::new(1.0e-20, 3.0e-20), <$V>::new(-2.0e-20, 1.0e-20), <$V>::new(0.7e-20, -2.1e-20)];
            const BUILT_CW: Polygon<$R, 5> = frozen(CW);
            const BUILT_FAR: Polygon<$R, 4> = frozen(FAR);
            const BUILT_TINY: Polygon<$R, 3> = frozen(TINY);
            // Through `black_box`: folded by the compiler, the run-time
            // polygon would be computed on the build machine too.
            fn same<const N: usize>(points: &[$V; N], frozen: &Polygon<$R, N>) -> bool {
                let Ok(built) = Polygon::<$R, N>::new(core::hint::black_box(points)) else {
                    return false;
                };
                let bits = |v: $V| (v.x.to_bits(), v.y.to_bits());
                (0..N).all(|i| built.vertex(i).map(bits) == frozen.vertex(i).map(bits))
                    && bits(built.centroid()) == bits(frozen.centroid())
                    && bits(built.reference_point()) == bits(frozen.reference_point())
                    && built.bounding_radius().to_bits() == frozen.bounding_radius().to_bits()
                    && &built == frozen
            }
            t.ok("const polygon = run-time polygon (clockwise, collinear)", same(&CW, &BUILT_CW));
            t.ok("const polygon = run-time polygon (far)", same(&FAR, &BUILT_FAR));
            t.ok("const polygon = run-time polygon (tiny)", same(&TINY, &BUILT_TINY));
        }
    };
}

const_polygons!(const_polygons_f32, f32, gjk2d::glam::Vec2);
const_polygons!(const_polygons_f64, f64, gjk2d::glam::DVec2);
