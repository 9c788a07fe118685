use super::{polytope_support, polytope_support_near, SupportMap};
use crate::ray::{cast_ray_polygon, LocalRayCast};
use crate::real::{cyclic, orientation, Real, V2};
use crate::transform::check_point;
use crate::Error;
use heapless::Vec;

/// A convex polygon of at most `N` vertices, stored inline (no allocator).
///
/// Vertices are kept counter-clockwise and relative to the first one (the
/// reference point), so a polygon given in world coordinates far from the
/// origin loses no precision.
#[derive(Clone, Debug, PartialEq)]
pub struct Polygon<R: Real, const N: usize> {
    reference: V2<R>,
    vertices: Vec<V2<R>, N>,
    center: V2<R>,
    /// Squared, so a firmware that only tests polygons for overlap links no
    /// square root.
    bounding_radius_squared: R,
}

impl<R: Real, const N: usize> Polygon<R, N> {
    /// A convex polygon from its vertices in either winding. Rejects fewer
    /// than 3 or more than `N` vertices, non-finite or out-of-range
    /// coordinates, repeated consecutive vertices, zero area, and any reflex
    /// turn or second winding. Collinear vertices on an edge are accepted.
    pub fn new(points: &[R::Vector]) -> Result<Self, Error> {
        if points.len() < 3 {
            return Err(Error::TooFewVertices);
        }
        if points.len() > N {
            return Err(Error::OverCapacity);
        }
        // Built complete at the end, not zeroed first: zeroing it is a call
        // to `memclr` (0.2 KB of flash) in a firmware that needs none.
        let mut vertices: Vec<V2<R>, N> = Vec::new();
        for &p in points {
            // Capacity was checked above.
            let _ = vertices.push(check_point(V2::from_glam(p))?);
        }
        if convex_winding(&vertices)? < 0 {
            vertices.reverse();
        }
        let reference = choose_reference(&vertices);
        for p in vertices.iter_mut() {
            *p = *p - reference;
        }
        let center = area_centroid(&vertices);
        let mut r2 = R::ZERO;
        for &v in vertices.iter() {
            r2 = r2.max((v - center).length_squared());
        }
        Ok(Self { reference, vertices, center, bounding_radius_squared: r2 })
    }

    /// A regular polygon of `count` vertices on a circle of `radius` about the
    /// origin, the first vertex on the +x axis.
    pub fn regular(count: usize, radius: R) -> Result<Self, Error> {
        crate::transform::check_length(radius)?;
        if count < 3 {
            return Err(Error::TooFewVertices);
        }
        if count > N {
            return Err(Error::OverCapacity);
        }
        let mut points: Vec<R::Vector, N> = Vec::new();
        for i in 0..count {
            let angle = R::from_f64(core::f64::consts::TAU * i as f64 / count as f64);
            let (sin, cos) = angle.sin_cos();
            let _ = points.push(R::vector(radius * cos, radius * sin));
        }
        Self::new(&points)
    }

    pub fn len(&self) -> usize {
        self.vertices.len()
    }
    /// Always false: a polygon has at least 3 vertices.
    pub fn is_empty(&self) -> bool {
        false
    }
    /// Vertex `i` (counter-clockwise order) in local coordinates.
    pub fn vertex(&self, i: usize) -> Option<R::Vector> {
        self.vertices.get(i).map(|&v| (v + self.reference).to_glam())
    }
    /// The area centroid in local coordinates.
    pub fn centroid(&self) -> R::Vector {
        (self.center + self.reference).to_glam()
    }
}

/// The point vertices are stored relative to. Far from the origin (or
/// wherever the shift is exact), the first vertex: differences of nearby
/// floats are exact, and the shape keeps its own precision, not its
/// position's. Near the origin, the origin itself: the coordinates as given
/// are exact already, and a shift would round them.
pub(crate) fn choose_reference<R: Real>(points: &[V2<R>]) -> V2<R> {
    let first = cyclic(points, 0);
    let exact = points
        .iter()
        .all(|&p| crate::real::is_exact_difference(p.x, first.x) && crate::real::is_exact_difference(p.y, first.y));
    let mut extent = R::ZERO;
    for &p in points {
        extent = extent.max((p - first).max_abs());
    }
    if exact || first.max_abs() > extent * R::from_u32(4) {
        first
    } else {
        V2::zero()
    }
}

/// +1 for a counter-clockwise convex polygon, -1 for a clockwise one, in
/// one pass over the edges. No edge may be empty, every turn must go the same
/// way (collinear turns allowed) and the edge directions must wind once: a
/// convex polygon's edge x- and y-components change sign at most twice
/// around the loop, a pentagram's more often.
fn convex_winding<R: Real>(p: &[V2<R>]) -> Result<i32, Error> {
    let n = p.len();
    let (mut left, mut right) = (false, false);
    let mut changes = 0u32;
    let mut last = [R::ZERO; 2];
    // Edge n is edge 0 again: the sign changes close the loop.
    for i in 0..=n {
        let e = cyclic(p, i + 1) - cyclic(p, i);
        if e.x == R::ZERO && e.y == R::ZERO {
            return Err(Error::DuplicateVertex);
        }
        for (component, last) in [e.x, e.y].into_iter().zip(last.iter_mut()) {
            if component != R::ZERO {
                if *last != R::ZERO && (component > R::ZERO) != (*last > R::ZERO) {
                    changes += 1;
                }
                *last = component;
            }
        }
        if i < n {
            let turn = orientation(cyclic(p, i), cyclic(p, i + 1), cyclic(p, i + 2));
            left |= turn > R::ZERO;
            right |= turn < R::ZERO;
        }
    }
    if left && right {
        return Err(Error::NotConvex);
    }
    if !left && !right {
        return Err(Error::Degenerate);
    }
    // Each component of a closed loop's edges changes sign at least twice,
    // and every one of them 2k times when the edges wind k times: more than
    // four changes in all is a second winding.
    if changes > 4 {
        return Err(Error::NotConvex);
    }
    Ok(if left { 1 } else { -1 })
}

/// Area centroid of a counter-clockwise polygon: a fan from vertex 0, on
/// coordinates relative to it, so the triangles' areas and centers lose
/// nothing to a far-away origin. Two passes (total area, then each triangle's
/// share of it) so no intermediate grows like size cubed: at f32's coordinate
/// limit that would overflow.
pub(crate) fn area_centroid<R: Real>(v: &[V2<R>]) -> V2<R> {
    let origin = cyclic(v, 0);
    let fan = || v.iter().zip(v.iter().skip(1)).skip(1).map(move |(&p, &q)| (p - origin, q - origin));
    let area2 = fan().fold(R::ZERO, |sum, (p, q)| sum + p.cross(q));
    if area2 > R::ZERO && area2.is_finite() {
        let third = R::ONE / R::from_u32(3);
        let acc = fan().fold(V2::zero(), |acc, (p, q)| acc + (p + q) * (p.cross(q) / area2));
        origin + acc * third
    } else {
        // Unreachable for validated polygons; the vertex mean is a safe center.
        let mut m = V2::zero();
        for &p in v {
            m = m + (p - origin) * (R::ONE / R::from_u32(v.len() as u32));
        }
        origin + m
    }
}

/// A support index as a feature id, clamped below the capacity (where it is
/// already): the clamp tells the compiler that ids of a polygon of fewer than
/// 65535 vertices are never `NO_FEATURE`, so the paths for curved shapes (and
/// their square roots) drop out of polygon-only code.
#[inline(always)]
fn vertex_id<const N: usize>(i: usize) -> u32 {
    i.min(N.saturating_sub(1)) as u32
}

impl<R: Real, const N: usize> SupportMap<R> for Polygon<R, N> {
    #[inline]
    fn support(&self, direction: R::Vector) -> R::Vector {
        self.support_feature(direction).0
    }
    #[inline]
    fn support_feature(&self, direction: R::Vector) -> (R::Vector, u32) {
        let (i, v) = polytope_support::<R, N>(&self.vertices, V2::from_glam(direction));
        (v.to_glam(), vertex_id::<N>(i))
    }
    #[inline]
    fn support_feature_near(&self, direction: R::Vector, previous: u32) -> (R::Vector, u32) {
        let (i, v) = polytope_support_near::<R, N>(&self.vertices, V2::from_glam(direction), previous);
        (v.to_glam(), vertex_id::<N>(i))
    }
    fn center(&self) -> R::Vector {
        self.center.to_glam()
    }
    fn bounding_radius(&self) -> R {
        self.bounding_radius_squared.sqrt()
    }
    fn bounding_radius_squared(&self) -> R {
        self.bounding_radius_squared
    }
    fn reference_point(&self) -> R::Vector {
        self.reference.to_glam()
    }
    /// Vertex indices below 65535 fit the pair's 16 bits each (65535 there
    /// marks a curve point).
    fn is_polytope(&self) -> bool {
        N <= 0xFFFF
    }
    fn cast_local_ray(&self, o: R::Vector, d: R::Vector, max: R) -> Option<LocalRayCast<R>> {
        Some(cast_ray_polygon(&self.vertices, V2::from_glam(o), V2::from_glam(d), max))
    }
}
