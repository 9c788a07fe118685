//! Ray casts: closed forms for polygons, circles, capsules and segments
//! (exact face normals, no iteration), and GJK ray casting (conservative
//! advancement, van den Bergen 2004) for every other support map.

use crate::minkowski::NO_ID;
use crate::real::{Real, V2};
use crate::result::{RayCast, RayHit, RayOutcome, Status};
use crate::shape::{at, first_reached, polytope_support, SupportMap};
use crate::simplex::{Closest, Simplex, Vertex, Witness};
use crate::transform::check_point;
use crate::Error;

/// A ray cast in a shape's local frame: what [`SupportMap::cast_local_ray`]
/// returns (point and normal local, relative to the reference point).
pub type LocalRayCast<R> = RayCast<R>;

/// A half-line: an origin and a unit direction.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Ray<R: Real> {
    pub(crate) origin: V2<R>,
    pub(crate) direction: V2<R>,
}

impl<R: Real> Ray<R> {
    /// A ray from `origin` along `direction`, which is normalised and must
    /// be finite and non-zero.
    pub fn new(origin: R::Vector, direction: R::Vector) -> Result<Self, Error> {
        let origin = check_point(V2::from_glam(origin))?;
        let d = V2::from_glam(direction);
        if !d.is_finite() {
            return Err(Error::NonFinite);
        }
        // Scale first so tiny and huge directions normalise without
        // under- or overflow.
        let m = d.max_abs();
        if m == R::ZERO {
            return Err(Error::ZeroLength);
        }
        let direction = (d * (R::ONE / m)).try_normalize().ok_or(Error::ZeroLength)?;
        Ok(Self { origin, direction })
    }
    pub fn origin(&self) -> R::Vector {
        self.origin.to_glam()
    }
    /// The unit direction.
    pub fn direction(&self) -> R::Vector {
        self.direction.to_glam()
    }
}

fn hit<R: Real>(o: V2<R>, d: V2<R>, t: R, normal: V2<R>, error_bound: R) -> RayOutcome<R> {
    RayOutcome::Hit(RayHit { distance: t, point: (o + d * t).to_glam(), normal: normal.to_glam(), error_bound })
}

/// `bound`, at most `cap` (a NaN or infinite bound gives `cap`): the hit
/// distance's error cannot exceed the distance plus the shape's diameter.
#[inline(always)]
fn capped<R: Real>(bound: R, cap: R) -> R {
    if bound < cap {
        bound
    } else {
        cap
    }
}

/// How far the hit moves when the boundary's line moves by `across`, met at
/// incidence `cos` (`|n . d|` of the computed unit normal `n`), at most `cap`.
/// The computed `cos` is within `2 eps` of the exact one, so that much is
/// taken off: a ray within rounding of the tangent gets the cap.
#[inline(always)]
fn incidence_bound<R: Real>(across: R, cos: R, cap: R) -> R {
    let cos = cos - R::TWO * R::EPSILON;
    if cos * cap > across {
        across / cos
    } else {
        cap
    }
}

/// How far rounding may have moved the local ray: its origin `o` (which
/// came through a subtraction and a rotation, within `1.5 eps |o|`) and, at
/// distance `t`, its direction (a rotation and a normalisation: within
/// `eps` of its angle and `3 eps` of unit length). Across the ray, then
/// along it.
#[inline(always)]
fn ray_rounding<R: Real>(o: V2<R>, t: R) -> (R, R) {
    let eps = R::EPSILON;
    // |x| + |y| for |o|: no square root, at most 1.42 times as large.
    (eps * (R::from_f64(1.5) * (o.x.abs() + o.y.abs()) + t), R::from_u32(3) * eps * t)
}

/// Clips the ray against each edge's half-plane (counter-clockwise vertices):
/// the hit is the last entry, its normal the entered face's.
///
/// `size` bounds the vertices' distance from their centre: it caps the hit's
/// `error_bound`.
pub(crate) fn cast_ray_polygon<R: Real>(vertices: &[V2<R>], o: V2<R>, d: V2<R>, max: R, size: R) -> RayCast<R> {
    let mut clip = Clip::new(o, d, max);
    for (&a, &b) in vertices.iter().zip(vertices.iter().skip(1).chain(vertices.first())) {
        if clip.misses(a, b) {
            return RayCast::closed_form(RayOutcome::Miss);
        }
    }
    clip.outcome(size)
}

/// The ray's line meets a convex polygon's boundary on two edges: one on
/// the chain that faces the ray (counter-clockwise from the vertex farthest
/// to the ray's left to the one farthest to its right), one on the chain
/// that faces away. Along each chain the vertices' side of the line changes
/// monotonically, so a binary search finds where it changes, in O(log n).
/// Only the edges there are clipped against (the far crossing only when the
/// origin is past the near one): the scan's clip, with the scan's result
/// wherever the decisive edges are among them.
///
/// Rounding can misplace the change among vertices within rounding of the
/// line (`slack`, from `reach`, a bound on the vertices' distance from the
/// ray's origin): every edge that touches them is clipped. A line within
/// rounding of a tangent has no reliable crossing (edges along it give
/// none); `None` then leaves the ray to the scan.
pub(crate) fn cast_ray_many_sided<R: Real, const N: usize>(
    v: &[V2<R>],
    o: V2<R>,
    d: V2<R>,
    max: R,
    reach: R,
    size: R,
) -> Option<RayCast<R>> {
    let n = v.len();
    let left = d.perp();
    let side = |i: usize| left.dot(at(v, i) - o);
    // `side` rounds by at most 3 eps |v - o|_1 <= 3 sqrt(2) eps reach.
    let slack = R::from_u32(8) * R::EPSILON * reach;
    let leftmost = polytope_support::<R, N>(v, left).0;
    let rightmost = polytope_support::<R, N>(v, -left).0;
    let (farthest_left, farthest_right) = (side(leftmost), side(rightmost));
    // The line passes the polygon by.
    if farthest_left < -slack || farthest_right > slack {
        return Some(RayCast::closed_form(RayOutcome::Miss));
    }
    // Within rounding of a tangent: the scan decides.
    if farthest_left <= slack || farthest_right >= -slack {
        return None;
    }
    let is_left = |i: usize| side(i) > slack;
    let is_right = |i: usize| side(i) < -slack;
    let entry = first_vertex_reaching(n, leftmost, rightmost, |i| side(i) <= R::ZERO)?;
    let mut clip = Clip::new(o, d, max);
    if clip.misses_around(v, entry, is_left, is_right) {
        return Some(RayCast::closed_form(RayOutcome::Miss));
    }
    // Entered ahead of the origin: the line leaves the polygon farther on,
    // so the hit stands without the search for where.
    if clip.entered.is_none() {
        let exit = first_vertex_reaching(n, rightmost, leftmost, |i| side(i) >= R::ZERO)?;
        if clip.misses_around(v, exit, is_right, is_left) {
            return Some(RayCast::closed_form(RayOutcome::Miss));
        }
    }
    Some(clip.outcome(size))
}

/// On the chain counter-clockwise from vertex `from` to vertex `to` (where
/// `reached` holds), the first vertex where it holds, if the chain is not
/// empty.
fn first_vertex_reaching(n: usize, from: usize, to: usize, reached: impl Fn(usize) -> bool) -> Option<usize> {
    let length = wrap(to + n - from, n);
    if length == 0 {
        return None;
    }
    // The first step in 1..=length with `reached`, which holds at `length`.
    let step = first_reached(1, length, |step| reached(wrap(from + step, n)));
    Some(wrap(from + step, n))
}

/// `i mod n` for `i < 2 n`, without a division.
#[inline(always)]
fn wrap(i: usize, n: usize) -> usize {
    if i >= n {
        i - n
    } else {
        i
    }
}

/// The ray clipped by edge half-planes, one at a time (Cyrus-Beck): where
/// it enters and leaves the intersection of those seen so far.
struct Clip<R: Real> {
    o: V2<R>,
    d: V2<R>,
    lower: R,
    upper: R,
    /// The normal of the edge the ray last entered through, and the edge's
    /// first vertex.
    entered: Option<(V2<R>, V2<R>)>,
}

impl<R: Real> Clip<R> {
    #[inline(always)]
    fn new(o: V2<R>, d: V2<R>, max: R) -> Self {
        Self { o, d, lower: R::ZERO, upper: max, entered: None }
    }

    /// Clips by the inner side of edge `a`-`b`; true when the ray
    /// certainly misses.
    #[inline(always)]
    fn misses(&mut self, a: V2<R>, b: V2<R>) -> bool {
        let normal = (b - a).perp_cw();
        // Positive when the origin is on the inner side of this edge.
        let numerator = normal.dot(a - self.o);
        let denominator = normal.dot(self.d);
        if denominator == R::ZERO {
            if numerator < R::ZERO {
                return true;
            }
        } else if denominator < R::ZERO {
            // Entering. t = numerator / denominator > lower, multiplied out
            // (denominator < 0 flips it): one division per update, not per edge.
            if numerator < self.lower * denominator {
                self.lower = numerator / denominator;
                self.entered = Some((normal, a));
                // A subnormal denominator (a ray parallel to the face to
                // rounding) sends t to infinity: no entry, a miss.
                if self.upper < self.lower || !self.lower.is_finite() {
                    return true;
                }
            }
        } else if numerator < self.upper * denominator {
            // Leaving: t < upper.
            self.upper = numerator / denominator;
            if self.upper < self.lower {
                return true;
            }
        }
        false
    }

    /// Clips by the edges around `vertex`, where a chain crosses the ray's
    /// line: from the last vertex before it clearly on the side the chain
    /// comes from to the first clearly on the side it goes to. True when the
    /// ray certainly misses. Each walk is bounded by the vertex count.
    fn misses_around(
        &mut self,
        v: &[V2<R>],
        vertex: usize,
        came_from: impl Fn(usize) -> bool,
        goes_to: impl Fn(usize) -> bool,
    ) -> bool {
        let n = v.len();
        let mut first = wrap(vertex + n - 1, n);
        let mut steps = 0;
        while !came_from(first) && steps < n {
            first = wrap(first + n - 1, n);
            steps += 1;
        }
        let mut last = vertex;
        while !goes_to(last) && steps < n {
            last = wrap(last + 1, n);
            steps += 1;
        }
        let mut k = first;
        while k != last && steps < 2 * n {
            let next = wrap(k + 1, n);
            if self.misses(at(v, k), at(v, next)) {
                return true;
            }
            k = next;
            steps += 1;
        }
        false
    }

    /// The hit's `error_bound`: `t = n.(a - o) / n.d` with the edge normal
    /// `n` and vertex `a` as computed (a normal turned by rounding turns the
    /// face about `a`, within `eps/2` of the distance to the hit) is within
    /// `eps (2 |a - o| + 3 t)` of the face's crossing across the face, which
    /// the incidence divides. `size` bounds the vertices' distance from
    /// their centre.
    fn outcome(self, size: R) -> RayCast<R> {
        RayCast::closed_form(match self.entered {
            None => RayOutcome::Inside,
            Some((normal, a)) => {
                let (o, d, t) = (self.o, self.d, self.lower);
                let normal = normal.try_normalize().unwrap_or(-d);
                let (across, along) = ray_rounding(o, t);
                let across = across + R::EPSILON * (R::TWO * (a - o).length() + R::from_u32(3) * t);
                let cap = t + R::TWO * size;
                hit(o, d, t, normal, capped(incidence_bound(across, normal.dot(d).abs(), cap) + along, cap))
            }
        })
    }
}

/// Ray against a disk. The root is taken in the form without cancellation,
/// `t = c / (-b + sqrt(disc))`, and the discriminant from the perpendicular
/// offset `r^2 - p^2 = (r - p)(r + p)`, so grazing rays keep their precision.
///
/// The hit's `error_bound` follows each rounded input of the root: the
/// offset `p` (within `dp`) moves `sqrt(disc)` by at most
/// `min(E / sqrt(disc), sqrt(E))`, `E = dp (2 p + dp)` (the second is the
/// `sqrt(2 r dp)` of a tangent ray); `c` moves `t` by its error over the far
/// root `-b + sqrt(disc)`, `b` moves it by its own.
pub(crate) fn cast_ray_disk<R: Real>(center: V2<R>, r: R, o: V2<R>, d: V2<R>, max: R) -> RayCast<R> {
    let m = o - center;
    // |m|^2 - r^2: rounds like (|m| - r)(|m| + r) would (|m| is rounded
    // too), without a square root.
    let c = m.length_squared() - r * r;
    if c <= R::ZERO {
        return RayCast::closed_form(RayOutcome::Inside);
    }
    let b = m.dot(d);
    // The offset's component across the ray: m = b d + across d⊥.
    let across = d.cross(m);
    let p = across.abs();
    // One branch, not two: which test a miss fails is not predictable.
    if (b >= R::ZERO) | (p > r) {
        return RayCast::closed_form(RayOutcome::Miss);
    }
    let half_chord = ((r - p) * (r + p)).sqrt();
    let far = -b + half_chord;
    let t = c / far;
    if t > max {
        return RayCast::closed_form(RayOutcome::Miss);
    }
    // The hit point from the center is m + t d = -half_chord d + across d⊥
    // (b + t = -half_chord): of length r to rounding, with no cancellation
    // however far the origin, and no second square root on the way.
    let normal = (d * -half_chord + d.perp() * across) * (R::ONE / r);
    RayCast::closed_form(hit(o, d, t, normal, disk_error_bound(center, r, m, p, half_chord, far, o, t)))
}

/// The error bound of [`cast_ray_disk`]'s hit at `t`, from the rounding of
/// each input of its root. Lengths are taken as `|x| + |y|` (no square
/// root; at most 1.42 times the length), and the tangent case's `sqrt(E)`
/// only where it is the smaller term.
#[allow(clippy::too_many_arguments)]
#[inline(always)]
fn disk_error_bound<R: Real>(center: V2<R>, r: R, m: V2<R>, p: R, half_chord: R, far: R, o: V2<R>, t: R) -> R {
    let eps = R::EPSILON;
    let (across_ray, along_ray) = ray_rounding(o, t);
    let mm = m.x.abs() + m.y.abs();
    // `m` rounds within eps/2 |m| (and `center` within eps/2 |center|); `p`
    // and `b` within 2.5 eps |m| more, with the direction's length.
    let dm = eps * (R::HALF * mm + center.x.abs() + center.y.abs());
    let dp = across_ray + dm + R::from_u32(3) * eps * mm;
    let e = dp * (R::TWO * p + dp);
    let d_root = if half_chord * half_chord >= e { e / half_chord } else { e.sqrt() };
    // |m|^2 - r^2 within 2 eps |m|^2 of rounding, and 2 |m| dm from m's.
    let d_c = R::TWO * (dm * (mm + dm) + eps * mm * mm);
    let bound = d_c / far + dp + d_root + R::from_f64(1.5) * eps * half_chord + along_ray + eps * t;
    capped(bound, t + R::TWO * r)
}

/// Ray against the segment `a`-`a + delta` swept by `r` (> 0, as a
/// [`Capsule`](crate::Capsule) has). Within the band of the two side lines,
/// the capsule beyond an end of the core is that end's disk, and the other
/// disk lies behind it; so the first hit is on the side the ray comes in
/// through or, where it comes in beyond an end (or starts in the band), on
/// that end's disk: one disk cast, not a comparison of three hits. A bare
/// segment has its own cast ([`cast_ray_segment`]), so a firmware with
/// capsules links no segment cast.
pub(crate) fn cast_ray_capsule<R: Real>(a: V2<R>, delta: V2<R>, r: R, o: V2<R>, d: V2<R>, max: R) -> RayCast<R> {
    let len2 = delta.length_squared();
    let rel = o - a;
    // Closest point of the core to the ray origin decides "inside".
    let t_axis = (rel.dot(delta) / len2).max(R::ZERO).min(R::ONE);
    if (rel - delta * t_axis).length() <= r {
        return RayCast::closed_form(RayOutcome::Inside);
    }
    let length = len2.sqrt();
    let axis = delta * (R::ONE / length);
    let side = axis.perp();
    // Height over the core's line, and where along the axis the ray is when
    // it is in the band (its origin, if it starts there).
    let h = side.dot(rel);
    let mut along = axis.dot(rel);
    if h.abs() > r {
        // Outside the band: it comes in through the nearer side line or not
        // at all.
        let toward = if h >= R::ZERO { R::ONE } else { -R::ONE };
        let dn = side.dot(d);
        if toward * dn >= R::ZERO {
            return RayCast::closed_form(RayOutcome::Miss);
        }
        let t = (h.abs() - r) / dn.abs();
        along = axis.dot(rel + d * t);
        if along >= R::ZERO && along <= length {
            let outcome = if t <= max {
                hit(o, d, t, side * toward, side_bound(rel, r, length, t, dn))
            } else {
                RayOutcome::Miss
            };
            return RayCast::closed_form(outcome);
        }
    }
    cast_ray_disk(if along < R::ZERO { a } else { a + delta }, r, o, d, max)
}

/// The `error_bound` of a hit on a capsule's side `t = (|h| - r) / |dn|`:
/// the side line is within `eps (|rel| + r + length / 2)` of where it is
/// (the axis rounded in length and angle, the height `h` in its dot
/// product), and `dn` within `2.5 eps`, which moves `t` by `2.5 eps t`
/// across the side; the incidence `|dn|` divides both.
fn side_bound<R: Real>(rel: V2<R>, r: R, length: R, t: R, dn: R) -> R {
    let eps = R::EPSILON;
    let (across, along) = ray_rounding(rel, t);
    let across = across + eps * (R::from_u32(2) * (rel.length() + r) + length + R::from_u32(3) * t);
    let cap = t + length + R::TWO * r;
    capped(incidence_bound(across, dn.abs(), cap) + along + eps * t, cap)
}

/// Ray against the bare segment `a`-`a + delta`. A segment has no inside, so
/// a ray nearly along its line is ill-conditioned: an end point the ray
/// passes within rounding distance of counts as hit, as a user expects of a
/// ray aimed along a wall.
pub(crate) fn cast_ray_segment<R: Real>(a: V2<R>, delta: V2<R>, o: V2<R>, d: V2<R>, max: R) -> RayCast<R> {
    let rel = a - o;
    let slack = R::from_u32(4) * R::EPSILON;
    // An origin on the segment (to rounding) is on the shape.
    let along = -rel.dot(delta);
    let scale = rel.length() + delta.length();
    if along >= R::ZERO && along <= delta.length_squared() && delta.cross(rel).abs() <= slack * scale * delta.length() {
        return RayCast::closed_form(RayOutcome::Inside);
    }
    let denominator = d.cross(delta);
    let mut best: Option<(R, V2<R>, R)> = None;
    if denominator != R::ZERO {
        let t = rel.cross(delta) / denominator;
        let s = rel.cross(d) / denominator;
        if s >= R::ZERO && s <= R::ONE && t >= R::ZERO && t <= max {
            if t == R::ZERO {
                return RayCast::closed_form(RayOutcome::Inside);
            }
            // The face normal on the side the ray comes from.
            let n = delta.perp();
            let n = if n.dot(d) > R::ZERO { -n } else { n };
            // As a polygon's face: `t = (a - o) x delta / d x delta`.
            let across = R::EPSILON * (R::TWO * rel.length() + R::from_u32(3) * t);
            best = Some((t, n.try_normalize().unwrap_or(-d), across));
        }
    }
    // The incidence, |d x delta| / |delta|, for the bound.
    let cos = denominator.abs() / delta.length();
    for end in [rel, rel + delta] {
        let t = end.dot(d);
        let off = d.cross(end).abs();
        if t >= R::ZERO
            && t <= max
            && off <= slack * (end.length() + delta.length())
            && best.is_none_or(|(bt, _, _)| t < bt)
        {
            if t == R::ZERO {
                return RayCast::closed_form(RayOutcome::Inside);
            }
            // The ray may pass the end by the slack: across the segment's
            // line, as far as a crossing that near would be.
            best = Some((t, -d, off + slack * (end.length() + delta.length()) + R::EPSILON * t));
        }
    }
    RayCast::closed_form(match best {
        Some((t, normal, across)) => {
            let (ray_across, along) = ray_rounding(o, t);
            let cap = t + delta.length();
            hit(o, d, t, normal, capped(incidence_bound(across + ray_across, cos, cap) + along, cap))
        }
        None => RayOutcome::Miss,
    })
}

/// GJK ray cast on any support map (radius included): advance the ray point
/// towards the shape by the support plane's distance until it reaches the
/// surface within `epsilon * size`. The normal is the last advancing direction,
/// which converges to the surface normal.
pub(crate) fn cast_ray_gjk<R: Real, S: SupportMap<R> + ?Sized>(
    shape: &S,
    o: V2<R>,
    d: V2<R>,
    max: R,
    max_iterations: u32,
    epsilon: R,
) -> RayCast<R> {
    let radius = shape.radius();
    let tolerance = epsilon * shape.bounding_radius();
    let support = |dir: V2<R>| {
        let p = V2::from_glam(shape.support(dir.to_glam()));
        // Only a rounded shape needs the unit direction.
        match (radius > R::ZERO).then(|| dir.try_normalize()).flatten() {
            Some(u) => p + u * radius,
            None => p,
        }
    };
    let mut lambda = R::ZERO;
    let mut x = o;
    let mut normal = V2::zero();
    let mut v = x - V2::from_glam(shape.center());
    // Vertices x - p that keep their shape points p, measured again from
    // each new x as the ray advances.
    let mut simplex = Simplex::empty_like(vertex(o, o));
    let mut iterations = 0;
    let status = loop {
        if v.length_squared() <= tolerance * tolerance {
            break Status::Converged;
        }
        if iterations >= max_iterations {
            break Status::IterationLimit;
        }
        iterations += 1;
        let p = support(v);
        let w = x - p;
        let vw = v.dot(w);
        if vw > R::ZERO {
            let vd = v.dot(d);
            if vd >= R::ZERO {
                return RayCast { outcome: RayOutcome::Miss, iterations, status: Status::Converged };
            }
            lambda -= vw / vd;
            // A near-parallel support plane (vd tiny, even subnormal) sends
            // lambda to infinity: no finite hit, so a miss (never inf or NaN).
            if !lambda.is_finite() || lambda > max {
                return RayCast { outcome: RayOutcome::Miss, iterations, status: Status::Converged };
            }
            x = o + d * lambda;
            normal = v;
        }
        // The reduced simplex (at most two points) and p, from x.
        simplex.measure_from(x);
        simplex.push(vertex(x, p));
        v = match simplex.solve() {
            Closest::Enclosed => V2::zero(),
            Closest::Point(closest) => closest,
        };
    };
    let outcome = if lambda == R::ZERO {
        RayOutcome::Inside
    } else {
        let normal = normal.try_normalize().unwrap_or(-d);
        // The ray point is outside the shape (to rounding) and within |v| of
        // it: to first order, |v| across the surface from the hit. Rounding:
        // the ray point's and the support points' (within eps of the shape's
        // size), and the ray's own.
        let (across, along) = ray_rounding(o, lambda);
        let size = shape.bounding_radius();
        let across = v.length() + across + R::EPSILON * (lambda + R::TWO * size);
        let cap = lambda + R::TWO * size + tolerance;
        hit(o, d, lambda, normal, capped(incidence_bound(across, normal.dot(d).abs(), cap) + along, cap))
    };
    RayCast { outcome, iterations, status }
}

/// A simplex vertex for the ray cast: the ray point minus a shape point,
/// which it keeps (as `b`) because the ray point moves.
fn vertex<R: Real>(x: V2<R>, p: V2<R>) -> Vertex<R, Witness<R>> {
    Vertex { w: x - p, id: NO_ID, payload: Witness { a: V2::zero(), b: p, weight: R::ONE } }
}
