//! The ray, and GJK ray casting (conservative advancement, van den Bergen
//! 2004) for every support map without a closed form. Shapes with one cast
//! their own: capsules and segments beside their support (`shape/`),
//! polygons and rectangles through the clip in `polytope/`, circles in the
//! detector, placed, so one arithmetic serves every target.

use crate::error::Error;
use crate::minkowski::NO_ID;
use crate::real::{Real, V2};
use crate::result::{gap_hit, RayCast, RayOutcome, Status};
use crate::shape::SupportMap;
use crate::simplex::{Closest, Simplex, Vertex, Witness};
use crate::transform::check_point;

/// A half-line: an origin and a unit direction.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Ray<R: Real> {
    pub(crate) origin: V2<R>,
    pub(crate) direction: V2<R>,
}

impl<R: Real> Ray<R> {
    /// Both vectors through [`Real`]'s scalar barrier.
    #[cfg(not(any(target_os = "none", target_family = "wasm")))]
    #[inline(always)]
    pub(crate) fn scalar_barrier(&self) -> Self {
        Self { origin: self.origin.scalar_barrier(), direction: self.direction.scalar_barrier() }
    }
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

/// GJK ray cast on any support map (radius included): advance the ray point
/// towards the shape by the support plane's distance until it reaches the
/// surface within `epsilon * size` (plus the ray point's own rounding). The normal is the last advancing direction,
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
        // Or within the rounding of the ray point itself (`o + d lambda`,
        // which rounds with its own size and the step's): a ray from far
        // away cannot place it closer, and would spin to its limit.
        // The tolerance is the hit's, along the ray: across the surface, it
        // shrinks with the incidence cos = |v.d| / |v| (down to a half, as
        // the guarantee holds head-on; towards the tangent the hit is
        // ill-conditioned anyway). Squared, with no root.
        let rounding = R::from_u32(2) * R::EPSILON * (x.l1() + lambda);
        let vv = v.length_squared();
        let vd = v.dot(d);
        let incident = (vd * vd).max(vv * R::HALF * R::HALF);
        let reached = tolerance + rounding;
        if vv <= rounding * rounding || vv * vv <= reached * reached * incident {
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
    // The ray point is outside the shape (to rounding) and within |v| of it:
    // to first order, |v| across the surface from the hit.
    let outcome = if lambda == R::ZERO {
        RayOutcome::Inside
    } else {
        gap_hit(o, d, lambda, normal.try_normalize().unwrap_or(-d), v.length())
    };
    RayCast { outcome, iterations, status }
}

/// A simplex vertex for the ray cast: the ray point minus a shape point,
/// which it keeps (as `b`) because the ray point moves.
fn vertex<R: Real>(x: V2<R>, p: V2<R>) -> Vertex<R, Witness<R>> {
    Vertex { w: x - p, id: NO_ID, payload: Witness { a: V2::zero(), b: p, weight: R::ONE } }
}
