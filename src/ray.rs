//! Ray casts: closed forms for polygons, circles, capsules and segments
//! (exact face normals, no iteration), and GJK ray casting (conservative
//! advancement, van den Bergen 2004) for every other support map.

use crate::minkowski::NO_ID;
use crate::real::{Real, V2};
use crate::result::{RayCast, RayHit, RayOutcome, Status};
use crate::shape::SupportMap;
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

fn hit<R: Real>(o: V2<R>, d: V2<R>, t: R, normal: V2<R>) -> RayOutcome<R> {
    RayOutcome::Hit(RayHit { distance: t, point: (o + d * t).to_glam(), normal: normal.to_glam() })
}

/// Clips the ray against each edge's half-plane (counter-clockwise vertices):
/// the hit is the last entry, its normal the entered face's.
pub(crate) fn cast_ray_polygon<R: Real>(vertices: &[V2<R>], o: V2<R>, d: V2<R>, max: R) -> RayCast<R> {
    let (mut lower, mut upper) = (R::ZERO, max);
    let mut entered: Option<V2<R>> = None;
    for (&a, &b) in vertices.iter().zip(vertices.iter().skip(1).chain(vertices.first())) {
        let normal = (b - a).perp_cw();
        // Positive when the origin is on the inner side of this edge.
        let numerator = normal.dot(a - o);
        let denominator = normal.dot(d);
        if denominator == R::ZERO {
            if numerator < R::ZERO {
                return RayCast::closed_form(RayOutcome::Miss);
            }
        } else if denominator < R::ZERO {
            // Entering. t = numerator / denominator > lower, multiplied out
            // (denominator < 0 flips it): one division per update, not per edge.
            if numerator < lower * denominator {
                lower = numerator / denominator;
                entered = Some(normal);
                // A subnormal denominator (a ray parallel to the face to
                // rounding) sends t to infinity: no entry, a miss.
                if upper < lower || !lower.is_finite() {
                    return RayCast::closed_form(RayOutcome::Miss);
                }
            }
        } else if numerator < upper * denominator {
            // Leaving: t < upper.
            upper = numerator / denominator;
            if upper < lower {
                return RayCast::closed_form(RayOutcome::Miss);
            }
        }
    }
    RayCast::closed_form(match entered {
        None => RayOutcome::Inside,
        Some(normal) => hit(o, d, lower, normal.try_normalize().unwrap_or(-d)),
    })
}

/// Ray against a disk. The root is taken in the form without cancellation,
/// `t = c / (-b + sqrt(disc))`, and the discriminant from the perpendicular
/// offset `r^2 - p^2 = (r - p)(r + p)`, so grazing rays keep their precision.
pub(crate) fn cast_ray_disk<R: Real>(center: V2<R>, r: R, o: V2<R>, d: V2<R>, max: R) -> RayCast<R> {
    let m = o - center;
    let mm = m.length();
    if mm <= r {
        return RayCast::closed_form(RayOutcome::Inside);
    }
    let b = m.dot(d);
    let p = d.cross(m).abs();
    if b >= R::ZERO || p > r {
        return RayCast::closed_form(RayOutcome::Miss);
    }
    let disc = (r - p) * (r + p);
    let c = (mm - r) * (mm + r);
    let t = c / (-b + disc.sqrt());
    if t > max {
        return RayCast::closed_form(RayOutcome::Miss);
    }
    let normal = (m + d * t).try_normalize().unwrap_or(-d);
    RayCast::closed_form(hit(o, d, t, normal))
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
            let outcome = if t <= max { hit(o, d, t, side * toward) } else { RayOutcome::Miss };
            return RayCast::closed_form(outcome);
        }
    }
    cast_ray_disk(if along < R::ZERO { a } else { a + delta }, r, o, d, max)
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
    let mut best: Option<(R, V2<R>)> = None;
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
            best = Some((t, n.try_normalize().unwrap_or(-d)));
        }
    }
    for end in [rel, rel + delta] {
        let t = end.dot(d);
        let off = d.cross(end).abs();
        if t >= R::ZERO
            && t <= max
            && off <= slack * (end.length() + delta.length())
            && best.is_none_or(|(bt, _)| t < bt)
        {
            if t == R::ZERO {
                return RayCast::closed_form(RayOutcome::Inside);
            }
            best = Some((t, -d));
        }
    }
    RayCast::closed_form(match best {
        Some((t, normal)) => hit(o, d, t, normal),
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
    let outcome =
        if lambda == R::ZERO { RayOutcome::Inside } else { hit(o, d, lambda, normal.try_normalize().unwrap_or(-d)) };
    RayCast { outcome, iterations, status }
}

/// A simplex vertex for the ray cast: the ray point minus a shape point,
/// which it keeps (as `b`) because the ray point moves.
fn vertex<R: Real>(x: V2<R>, p: V2<R>) -> Vertex<R, Witness<R>> {
    Vertex { w: x - p, id: NO_ID, payload: Witness { a: V2::zero(), b: p, weight: R::ONE } }
}
