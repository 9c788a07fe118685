use super::polygon_frame::{Frame, Framing};
use super::SupportMap;
use crate::error::Error;
#[cfg(not(any(target_os = "none", target_family = "wasm")))]
use crate::polytope::{
    at, searched_here, searched_support, searched_support_near, write_compass, Compass, COMPASS_SLOTS,
};
use crate::polytope::{
    cast_ray_many_sided, cast_ray_polygon, polytope_support, polytope_support_near, searched, FaceRounding,
    SCAN_ONLY_MAX,
};
use crate::real::{Real, V2};
use crate::result::LocalRayCast;
use glam::{DVec2, Vec2};

/// A convex polygon of at most `N` vertices, stored inline (no allocator).
///
/// The vertices are a plain array and a length, not a `heapless::Vec`: a
/// type without a destructor is what lets a `const` declare one
/// ([`from_array`](Polygon::from_array)). Unused slots stay zero, or hold
/// copies of the first vertex where a support scan reads them all (small
/// polygons on hosts); on hosts, a large polygon with room for eight more
/// vertices keeps its compass in the last eight (its supports along
/// sixteen directions, which shorten every search for a support). So the
/// derived comparison compares the polygons.
///
/// Vertices are kept counter-clockwise and relative to the first one (the
/// reference point), so a polygon given in world coordinates far from the
/// origin loses no precision.
#[derive(Clone, Debug, PartialEq)]
pub struct Polygon<R: Real, const N: usize> {
    reference: V2<R>,
    vertices: [V2<R>; N],
    len: usize,
    center: V2<R>,
    /// Squared: `from_array` computes it at compile time, where no square
    /// root is available. Only queries that need the pair's size take the
    /// root (the intersection test with the default zero margin does not).
    bounding_radius_squared: R,
    #[cfg(not(any(target_os = "none", target_family = "wasm")))]
    inner_radius_squared: R,
}

impl<R: Real, const N: usize> Polygon<R, N> {
    /// A convex polygon from its vertices in either winding. Rejects fewer
    /// than 3 or more than `N` vertices, non-finite or out-of-range
    /// coordinates, repeated consecutive vertices, zero area, and any reflex
    /// turn or second winding. Collinear vertices on an edge are accepted.
    pub fn new(points: &[R::Vector]) -> Result<Self, Error> {
        // Fewer than 3 is the framing's verdict, shared with `from_array`.
        if points.len() > N {
            return Err(Error::OverCapacity);
        }
        // Each slot written once, not zeroed first: zeroing is a call to
        // `memclr`, in a firmware that needs none.
        let mut vertices: [V2<R>; N] =
            core::array::from_fn(|i| points.get(i).map_or(V2::zero(), |&p| V2::from_glam(p)));
        let frame = R::per_type::<Framing>(vertices.get_mut(..points.len()).unwrap_or(&mut []))?;
        if Self::SCANS_EVERY_SLOT {
            let first = vertices.first().copied().unwrap_or_default();
            for slot in vertices.iter_mut().skip(points.len()) {
                *slot = first;
            }
        }
        #[allow(unused_mut)]
        let mut polygon = Self::framed(vertices, points.len(), frame);
        #[cfg(not(any(target_os = "none", target_family = "wasm")))]
        if Self::has_compass(polygon.len) {
            let (vertices, slots) = polygon.vertices.split_at_mut(N - COMPASS_SLOTS);
            write_compass(vertices.get(..polygon.len).unwrap_or_default(), slots);
        }
        Ok(polygon)
    }

    /// Whether a polygon of `len` vertices keeps a compass in its last
    /// slots: where its supports are searched, it has room for one, and
    /// its indices fit the compass's 16 bits.
    #[cfg(not(any(target_os = "none", target_family = "wasm")))]
    #[inline(always)]
    fn has_compass(len: usize) -> bool {
        searched_here::<R, N>(len) && len + COMPASS_SLOTS <= N && len < usize::from(u16::MAX)
    }

    /// The polygon's compass, or none.
    #[cfg(not(any(target_os = "none", target_family = "wasm")))]
    #[inline(always)]
    fn compass(&self) -> Compass<'_, R> {
        // Slots at a fixed place, next to the fields a query reads first:
        // their line is asked for with those, not after the length is known.
        let slots = self.vertices.get(N.saturating_sub(COMPASS_SLOTS)..).unwrap_or_default();
        if Self::has_compass(self.len) {
            Compass::in_slots(slots)
        } else {
            Compass::ABSENT
        }
    }

    #[inline(always)]
    const fn framed(vertices: [V2<R>; N], len: usize, frame: Frame<R>) -> Self {
        Self {
            reference: frame.reference,
            vertices,
            len,
            center: frame.center,
            bounding_radius_squared: frame.bounding_radius_squared,
            #[cfg(not(any(target_os = "none", target_family = "wasm")))]
            inner_radius_squared: frame.inner_radius_squared,
        }
    }

    /// The vertices, counter-clockwise, relative to the reference point.
    #[inline(always)]
    fn vertices(&self) -> &[V2<R>] {
        // Clamped rather than checked: `len <= N` always holds, and the
        // compiler sees from the clamp that the slice cannot panic.
        &self.vertices[..self.len.min(N)]
    }

    /// Whether a support scan reads every slot: on hosts, for small
    /// capacities, where a scan of fixed length has no branch on the vertex
    /// count to mispredict. The unused slots then copy vertex 0, which a
    /// strict comparison never prefers. Bare-metal targets scan the vertices
    /// alone: fewer products are fewer cycles there.
    const SCANS_EVERY_SLOT: bool = cfg!(not(target_os = "none")) && N <= SCAN_ONLY_MAX;

    /// What a support scan reads ([`SCANS_EVERY_SLOT`](Self::SCANS_EVERY_SLOT)).
    #[inline(always)]
    fn scanned(&self) -> &[V2<R>] {
        if Self::SCANS_EVERY_SLOT {
            &self.vertices
        } else {
            self.vertices()
        }
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
        let points: [R::Vector; N] = core::array::from_fn(|i| {
            if i >= count {
                return R::Vector::default();
            }
            let angle = R::from_f64(core::f64::consts::TAU * i as f64 / count as f64);
            let (sin, cos) = angle.sin_cos();
            R::vector(radius * cos, radius * sin)
        });
        Self::new(points.get(..count).unwrap_or(&[]))
    }

    pub fn len(&self) -> usize {
        self.len
    }
    /// Always false: a polygon has at least 3 vertices.
    pub fn is_empty(&self) -> bool {
        false
    }
    /// Vertex `i` (counter-clockwise order) in local coordinates.
    pub fn vertex(&self, i: usize) -> Option<R::Vector> {
        self.vertices().get(i).map(|&v| (v + self.reference).to_glam())
    }
    /// The area centroid in local coordinates.
    pub fn centroid(&self) -> R::Vector {
        (self.center + self.reference).to_glam()
    }
}

/// The `const` constructor, for each scalar type (a `const fn` cannot be
/// generic over [`Real`]'s arithmetic).
macro_rules! from_array {
    ($R:ty, $vector:ty, $frame:path) => {
        impl<const N: usize> Polygon<$R, N> {
            /// A convex polygon of exactly `N` vertices, in either winding,
            /// checked as [`Polygon::new`] checks them and stored bit for bit
            /// as it stores them; but `const`, so a polygon declared as a
            /// constant is checked when the program is compiled. An invalid
            /// one fails the build, and the program carries neither the
            /// checks nor a copy of the vertices in RAM:
            ///
            /// ```
            /// # use gjk2d::Polygon;
            #[doc = concat!("# use glam::", stringify!($vector), ";")]
            #[doc = concat!("const WEDGE: Polygon<", stringify!($R), ", 3> = match Polygon::<", stringify!($R), ", 3>::from_array([")]
            #[doc = concat!("    ", stringify!($vector), "::new(0.0, 0.0),")]
            #[doc = concat!("    ", stringify!($vector), "::new(2.0, 0.0),")]
            #[doc = concat!("    ", stringify!($vector), "::new(0.0, 1.0),")]
            /// ]) {
            ///     Ok(wedge) => wedge,
            ///     Err(e) => panic!("{}", e.as_str()), // a compile error, never a run-time panic
            /// };
            /// assert_eq!(WEDGE.len(), 3);
            /// ```
            ///
            /// Three points on a line are no polygon, and the build says so
            /// ("the polygon has no area"):
            ///
            /// ```compile_fail
            /// # use gjk2d::Polygon;
            #[doc = concat!("# use glam::", stringify!($vector), ";")]
            #[doc = concat!("const FLAT: Polygon<", stringify!($R), ", 3> = match Polygon::<", stringify!($R), ", 3>::from_array([")]
            #[doc = concat!("    ", stringify!($vector), "::new(0.0, 0.0),")]
            #[doc = concat!("    ", stringify!($vector), "::new(1.0, 0.0),")]
            #[doc = concat!("    ", stringify!($vector), "::new(2.0, 0.0),")]
            /// ]) {
            ///     Ok(flat) => flat,
            ///     Err(e) => panic!("{}", e.as_str()),
            /// };
            /// ```
            pub const fn from_array(points: [$vector; N]) -> Result<Self, Error> {
                let mut vertices = [V2 { x: 0.0, y: 0.0 }; N];
                let mut i = 0;
                while i < N {
                    vertices[i] = V2 { x: points[i].x, y: points[i].y };
                    i += 1;
                }
                match $frame(&mut vertices) {
                    Ok(frame) => Ok(Self::framed(vertices, N, frame)),
                    Err(e) => Err(e),
                }
            }
        }
    };
}

from_array!(f32, Vec2, super::polygon_frame::single::frame);
from_array!(f64, DVec2, super::polygon_frame::double::frame);

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
        #[cfg(not(any(target_os = "none", target_family = "wasm")))]
        if searched_here::<R, N>(self.len) {
            let i = searched_support(self.vertices(), self.compass(), V2::from_glam(direction));
            return at(self.vertices(), i).to_glam();
        }
        polytope_support::<R, N>(self.scanned(), V2::from_glam(direction)).1.to_glam()
    }
    #[inline]
    fn support_feature(&self, direction: R::Vector, near: u32) -> (R::Vector, u32) {
        #[cfg(not(any(target_os = "none", target_family = "wasm")))]
        if searched_here::<R, N>(self.len) {
            let i = searched_support_near(self.vertices(), self.compass(), V2::from_glam(direction), near);
            return (at(self.vertices(), i).to_glam(), vertex_id::<N>(i));
        }
        let (i, v) = polytope_support_near::<R, N>(self.scanned(), V2::from_glam(direction), near);
        (v.to_glam(), vertex_id::<N>(i))
    }
    fn center(&self) -> R::Vector {
        self.center.to_glam()
    }
    fn bounding_radius(&self) -> R {
        self.bounding_radius_squared.sqrt()
    }
    fn reference_point(&self) -> R::Vector {
        self.reference.to_glam()
    }
    #[cfg(feature = "far-geometry")]
    fn far_from_origin(&self) -> bool {
        self.reference.length_squared() > R::from_u32(4) * self.bounding_radius_squared
    }
    /// Vertex indices below 65535 fit the pair's 16 bits each (65535 there
    /// marks a curve point).
    fn is_polytope(&self) -> bool {
        N <= 0xFFFF
    }
    fn core_vertex_bound(&self) -> usize {
        N
    }
    #[cfg(not(any(target_os = "none", target_family = "wasm")))]
    fn small_polygon(&self) -> Option<super::SmallPolygon<'_, R>> {
        (self.len <= super::SMALL_POLYGON_MAX)
            .then(|| super::SmallPolygon { vertices: self.vertices(), compass: self.compass() })
    }
    #[cfg(not(any(target_os = "none", target_family = "wasm")))]
    fn polygon_core(&self) -> Option<super::SmallPolygon<'_, R>> {
        Some(super::SmallPolygon { vertices: self.vertices(), compass: self.compass() })
    }
    #[cfg(not(any(target_os = "none", target_family = "wasm")))]
    fn inner_radius_squared(&self) -> R {
        self.inner_radius_squared
    }
    #[cfg(not(any(target_os = "none", target_family = "wasm")))]
    fn searched_polygon_core(&self) -> Option<super::SmallPolygon<'_, R>> {
        searched_here::<R, N>(self.len)
            .then(|| super::SmallPolygon { vertices: self.vertices(), compass: self.compass() })
    }
    fn cast_local_ray(&self, o: R::Vector, d: R::Vector, max: R) -> Option<LocalRayCast<R>> {
        crate::polytope::face_cast_to_local(self.cast_local_face_ray(o, d, max), d)
    }
    fn casts_face_rays(&self) -> bool {
        true
    }
    fn cast_local_face_ray(&self, o: R::Vector, d: R::Vector, max: R) -> Option<LocalRayCast<R>> {
        let (o, d) = (V2::from_glam(o), V2::from_glam(d));
        let size = self.bounding_radius_squared.sqrt();
        // Far from the origin, the ray was placed error-free (see
        // `Gjk::raycast`): its origin rounds at its own scale only.
        #[cfg(feature = "far-geometry")]
        let reference = if self.far_from_origin() { V2::zero() } else { self.reference };
        #[cfg(not(feature = "far-geometry"))]
        let reference = self.reference;
        let rounding = FaceRounding::new(o, reference, size);
        if searched::<N>(self.len) {
            // How far the vertices are from the ray's origin, at most.
            let reach = (self.center - o).length() + size;
            if let Some(cast) = cast_ray_many_sided::<R, N>(self.vertices(), o, d, max, reach, rounding) {
                return Some(cast);
            }
        }
        Some(cast_ray_polygon(self.vertices(), o, d, max, rounding))
    }
}

#[cfg(all(test, not(any(target_os = "none", target_family = "wasm"))))]
mod tests {
    extern crate std;

    use super::Polygon;
    use crate::shape::SupportMap;
    use glam::DVec2;

    /// A polygon with room for its compass finds every support where one
    /// without room finds it, from no hint and from a far one; and keeps
    /// its compass in its slots, not in its vertices.
    #[test]
    fn a_compass_finds_the_supports_a_search_finds() {
        let points: std::vec::Vec<DVec2> = (0..1000)
            .map(|i| {
                let t = f64::from(i) / 1000.0 * core::f64::consts::TAU;
                DVec2::new(2.0 * t.cos(), 0.7 * t.sin())
            })
            .collect();
        let roomy = Polygon::<f64, 1024>::new(&points).unwrap();
        let tight = Polygon::<f64, 1000>::new(&points).unwrap();
        assert!(roomy.compass().arc(1000, crate::real::V2::new(1.0, 0.3)).is_some());
        assert!(tight.compass().arc(1000, crate::real::V2::new(1.0, 0.3)).is_none());
        assert_eq!(roomy.len(), 1000);
        for k in 0..4000 {
            let t = f64::from(k) * 0.001_573;
            let d = DVec2::new(t.cos(), t.sin());
            for hint in [u32::MAX, 500] {
                assert_eq!(roomy.support_feature(d, hint), tight.support_feature(d, hint), "direction {k}");
            }
            assert_eq!(roomy.support(d), tight.support(d), "direction {k}");
        }
    }
}
