//! Shapes as support maps: the trait GJK, EPA and the GJK ray cast query, and
//! one module per shape.
//!
//! Every shape is a *core* (a point, a segment, a polygon or a curved convex
//! set) swept by a *radius*. Circles and capsules are a point and a segment
//! with a radius, so the queries handle their curvature in closed form and
//! spend no iterations on it: they come out as exact as polygons.
//!
//! On bare metal a shape's support code (beyond a few instructions) is one
//! function out of line that both support methods call, so a firmware that
//! reaches shapes through `dyn SupportMap` links one copy, not two; hosts
//! inline it for speed.
//!
//! The trait has no method that no query calls through `dyn`: each one is
//! a function per shape in every firmware that uses trait objects.

/// `?` for `const fn`s, where the operator is not available.
macro_rules! const_try {
    ($result:expr) => {
        match $result {
            Ok(value) => value,
            Err(e) => return Err(e),
        }
    };
}

mod capsule;
mod circle;
mod ellipse;
mod half_ellipse;
mod polygon;
mod polygon_frame;
mod rectangle;
mod rounded;
mod segment;
mod slice;
mod triangle;

pub(crate) use capsule::cast_ray_capsule;
pub use capsule::Capsule;
pub use circle::Circle;
pub(crate) use circle::{cast_ray_disk, DiskRay};
pub use ellipse::Ellipse;
pub use half_ellipse::HalfEllipse;
pub use polygon::Polygon;
pub use rectangle::Rectangle;
pub use rounded::Rounded;
pub use segment::Segment;
pub use slice::Slice;
pub use triangle::Triangle;

#[cfg(not(any(target_os = "none", target_family = "wasm")))]
pub use crate::polytope::SMALL_POLYGON_MAX;
use crate::real::Real;
#[cfg(any(feature = "far-geometry", not(any(target_os = "none", target_family = "wasm"))))]
use crate::real::V2;
use crate::result::LocalRayCast;

/// The feature id of a support point that is not one of finitely many
/// vertices (a point on a curve).
pub const NO_FEATURE: u32 = u32::MAX;

/// A convex shape, given by its support function.
///
/// Coordinates are in the shape's local frame, measured from
/// [`reference_point`](Self::reference_point) (the origin unless the shape
/// says otherwise). Storing geometry relative to a point on the shape is what
/// keeps full precision for shapes given in world coordinates far from the
/// origin: differences of nearby floats are exact.
///
/// Only [`support`](Self::support), [`center`](Self::center) and
/// [`bounding_radius`](Self::bounding_radius) are required.
///
/// ```
/// use gjk2d::{Circle, Gjk, SupportMap, Transform};
/// use glam::Vec2;
///
/// /// A square turned 45 degrees, by its half-diagonal.
/// struct Diamond(f32);
///
/// impl SupportMap<f32> for Diamond {
///     fn support(&self, d: Vec2) -> Vec2 {
///         if d.x.abs() >= d.y.abs() {
///             Vec2::new(self.0.copysign(d.x), 0.0)
///         } else {
///             Vec2::new(0.0, self.0.copysign(d.y))
///         }
///     }
///     fn center(&self) -> Vec2 {
///         Vec2::ZERO
///     }
///     fn bounding_radius(&self) -> f32 {
///         self.0
///     }
/// }
///
/// let gjk = Gjk::<f32>::new();
/// let ball = Circle::new(0.5)?;
/// let right = Transform::from_translation(Vec2::new(3.0, 0.0))?;
/// let sep = gjk.distance(&Diamond(1.0), &Transform::IDENTITY, &ball, &right).expect("apart");
/// assert!((sep.distance - 1.5).abs() < 1e-6);
/// # Ok::<(), gjk2d::Error>(())
/// ```
pub trait SupportMap<R: Real> {
    /// The farthest point of the core along `direction` (never zero, not
    /// necessarily unit), relative to the reference point.
    fn support(&self, direction: R::Vector) -> R::Vector;

    /// A point inside the core, relative to the reference point. GJK's first
    /// search direction runs from A's center to B's.
    fn center(&self) -> R::Vector;

    /// An upper bound of the distance from `center` to any point of the
    /// shape, radius included. Relative tolerances are measured against it,
    /// and on hosts the intersection test calls two shapes apart, with no
    /// support, where these disks are: it must not fall short of the true
    /// bound by more than rounding (an eps or two).
    fn bounding_radius(&self) -> R;

    /// The radius the core is swept by. Zero for sharp shapes.
    fn radius(&self) -> R {
        R::ZERO
    }

    /// Where, in local coordinates, the coordinates of `support` and
    /// `center` are measured from.
    fn reference_point(&self) -> R::Vector {
        R::vector(R::ZERO, R::ZERO)
    }

    #[cfg(feature = "far-geometry")]
    /// Whether the reference point lies more than about twice the bounding
    /// radius from the local origin (feature `far-geometry` only). A
    /// rotation about that origin rounds at the reference's distance, not
    /// at the shape's size, so the queries then place such a shape with
    /// error-free sums and products. The default asks `reference_point` and
    /// `bounding_radius`.
    fn far_from_origin(&self) -> bool {
        let r = self.bounding_radius();
        V2::<R>::from_glam(self.reference_point()).length_squared() > R::from_u32(4) * r * r
    }

    /// The support point and an id of the vertex it is, for cores that are
    /// polytopes; [`NO_FEATURE`] for a point on a curve. With ids, GJK and EPA
    /// stop exactly when a vertex repeats instead of on a tolerance.
    ///
    /// `near` is the id this shape returned for the previous, nearby
    /// direction ([`NO_FEATURE`] when there is none). GJK and EPA turn their
    /// search direction a little at a time, so a polygon can walk from that
    /// vertex to the new one (convexity makes the walk exact) instead of
    /// scanning or searching all of them. Shapes without such a walk ignore
    /// it, as the default does. One method, not one with the hint and one
    /// without: through `dyn SupportMap` every method of every shape is
    /// linked, and a second would be dead weight in every vtable.
    fn support_feature(&self, direction: R::Vector, near: u32) -> (R::Vector, u32) {
        let _ = near;
        (self.support(direction), NO_FEATURE)
    }

    /// Whether the core is a polytope: every [`support_feature`](Self::support_feature)
    /// is a vertex with an id, never [`NO_FEATURE`]. A penetration solver then
    /// leaves out its work for curved boundaries, and a firmware whose shapes
    /// are all polytopes links none of it. The default, false, is always
    /// safe: it only keeps that work.
    fn is_polytope(&self) -> bool {
        false
    }

    /// At most how many vertices the core has, where it is a polytope
    /// ([`is_polytope`](Self::is_polytope)). A penetration solver whose
    /// polytope has room for more than two such cores' vertices can never
    /// fill it, and leaves out its work for a full one: a firmware of small
    /// polygons links none of it. The default, unbounded, is always safe.
    fn core_vertex_bound(&self) -> usize {
        usize::MAX
    }

    /// An exact ray cast, for shapes that have a closed form: a ray in the
    /// local frame (origin relative to the reference point, unit direction),
    /// `max_length` infinite when unbounded. `None` (the default) makes the ray
    /// cast iterate on the support function.
    fn cast_local_ray(&self, origin: R::Vector, direction: R::Vector, max_length: R) -> Option<LocalRayCast<R>> {
        let _ = (origin, direction, max_length);
        None
    }

    /// Whether [`cast_local_face_ray`](Self::cast_local_face_ray) answers:
    /// a method apart, so that a ray cast at a shape whose type is known
    /// when the program is compiled links only the one cast it uses.
    #[doc(hidden)]
    fn casts_face_rays(&self) -> bool {
        false
    }

    /// A polygon core's [`cast_local_ray`](Self::cast_local_ray) in the
    /// form its faces give it: the hit's normal is the entered face's
    /// outward normal at the length its edge gives it, and its error bound
    /// is how much later along the ray an exact ray may enter. The world
    /// hit's unit normal and error bound then both wait for one square
    /// root, not for each other. `None` (the default) for every other shape.
    #[doc(hidden)]
    fn cast_local_face_ray(&self, origin: R::Vector, direction: R::Vector, max_length: R) -> Option<LocalRayCast<R>> {
        let _ = (origin, direction, max_length);
        None
    }

    /// The radius of a disk centered on [`center`](Self::center), whose
    /// rays are cast in closed form straight into the world frame, with the
    /// same arithmetic on every target and through `dyn SupportMap` alike.
    /// `None` (the default) for every other shape. A shape that answers
    /// `Some` must have [`center`](Self::center) for its whole core and that
    /// radius for [`radius`](Self::radius): pair queries take it for a point
    /// core without asking the radii.
    #[doc(hidden)]
    fn disk_radius(&self) -> Option<R> {
        None
    }

    /// The vertices of a polygon core of at most [`SMALL_POLYGON_MAX`],
    /// which the intersection test and the default penetration solver of
    /// two such polygons answer by their separating axes, with no iteration.
    /// Only on hosts, where the few vector instructions of that test beat
    /// GJK's and EPA's branches; firmware keeps its vtables as they are.
    #[doc(hidden)]
    #[cfg(not(any(target_os = "none", target_family = "wasm")))]
    fn small_polygon(&self) -> Option<SmallPolygon<'_, R>> {
        None
    }

    /// The vertices of a polygon core of any size, counter-clockwise,
    /// relative to the reference point and indexed by their support ids: a
    /// contact manifold finds a support vertex's edges by index instead of
    /// asking the support function around it. Hosts only, as
    /// [`small_polygon`](Self::small_polygon).
    #[doc(hidden)]
    #[cfg(not(any(target_os = "none", target_family = "wasm")))]
    fn polygon_core(&self) -> Option<SmallPolygon<'_, R>> {
        None
    }

    /// The vertices of a polygon core whose support is searched, not
    /// scanned (a large one, as [`polygon_core`](Self::polygon_core) lends
    /// them): a pair of them has its two searches wait for memory together.
    /// Hosts only, as [`small_polygon`](Self::small_polygon).
    #[doc(hidden)]
    #[cfg(not(any(target_os = "none", target_family = "wasm")))]
    fn searched_polygon_core(&self) -> Option<SmallPolygon<'_, R>> {
        None
    }

    /// The end points of a segment core (a segment's, a capsule's),
    /// relative to the reference point: against a small polygon, its two
    /// normals and the polygon's are all the separating axes there are, so
    /// the test answers most capsule pairs with no iteration. Hosts only,
    /// as [`small_polygon`](Self::small_polygon).
    #[doc(hidden)]
    #[cfg(not(any(target_os = "none", target_family = "wasm")))]
    fn segment_core(&self) -> Option<[V2<R>; 2]> {
        None
    }

    /// The square of a radius, rounded down, within which every point about
    /// [`center`](Self::center) (or about the whole of a
    /// [`segment_core`](Self::segment_core)) belongs to the shape: where two
    /// such disks overlap, so do the shapes, and the intersection test and the
    /// distance query answer before any support (most deeply overlapping
    /// pairs in a scene). Zero, the default, claims no disk. Hosts only, as
    /// [`small_polygon`](Self::small_polygon).
    #[doc(hidden)]
    #[cfg(not(any(target_os = "none", target_family = "wasm")))]
    fn inner_radius_squared(&self) -> R {
        R::ZERO
    }
}

/// `r^2` rounded down, for [`SupportMap::inner_radius_squared`]: zero
/// below the normal range, where rounding is no longer relative.
#[cfg(not(any(target_os = "none", target_family = "wasm")))]
#[inline(always)]
pub(crate) fn squared_down<R: Real>(r: R) -> R {
    let square = r * r;
    if square >= R::MIN_POSITIVE {
        square * (R::ONE - R::TWO * R::EPSILON)
    } else {
        R::ZERO
    }
}

/// A polygon core's vertices, as [`SupportMap::small_polygon`] (at most
/// [`SMALL_POLYGON_MAX`]) and [`SupportMap::polygon_core`] (any number)
/// lend them: counter-clockwise, relative to the reference point.
#[doc(hidden)]
#[cfg(not(any(target_os = "none", target_family = "wasm")))]
#[derive(Clone, Copy, Debug)]
pub struct SmallPolygon<'s, R: Real> {
    pub(crate) vertices: &'s [V2<R>],
    pub(crate) compass: crate::polytope::Compass<'s, R>,
}

impl<R: Real, S: SupportMap<R> + ?Sized> SupportMap<R> for &S {
    fn support(&self, direction: R::Vector) -> R::Vector {
        (**self).support(direction)
    }
    fn center(&self) -> R::Vector {
        (**self).center()
    }
    fn bounding_radius(&self) -> R {
        (**self).bounding_radius()
    }
    fn radius(&self) -> R {
        (**self).radius()
    }
    fn reference_point(&self) -> R::Vector {
        (**self).reference_point()
    }
    #[cfg(feature = "far-geometry")]
    fn far_from_origin(&self) -> bool {
        (**self).far_from_origin()
    }
    fn support_feature(&self, direction: R::Vector, near: u32) -> (R::Vector, u32) {
        (**self).support_feature(direction, near)
    }
    fn is_polytope(&self) -> bool {
        (**self).is_polytope()
    }
    fn core_vertex_bound(&self) -> usize {
        (**self).core_vertex_bound()
    }
    fn cast_local_ray(&self, o: R::Vector, d: R::Vector, max: R) -> Option<LocalRayCast<R>> {
        (**self).cast_local_ray(o, d, max)
    }
    fn casts_face_rays(&self) -> bool {
        (**self).casts_face_rays()
    }
    fn cast_local_face_ray(&self, o: R::Vector, d: R::Vector, max: R) -> Option<LocalRayCast<R>> {
        (**self).cast_local_face_ray(o, d, max)
    }
    fn disk_radius(&self) -> Option<R> {
        (**self).disk_radius()
    }
    #[cfg(not(any(target_os = "none", target_family = "wasm")))]
    fn small_polygon(&self) -> Option<SmallPolygon<'_, R>> {
        (**self).small_polygon()
    }
    #[cfg(not(any(target_os = "none", target_family = "wasm")))]
    fn polygon_core(&self) -> Option<SmallPolygon<'_, R>> {
        (**self).polygon_core()
    }
    #[cfg(not(any(target_os = "none", target_family = "wasm")))]
    fn searched_polygon_core(&self) -> Option<SmallPolygon<'_, R>> {
        (**self).searched_polygon_core()
    }
    #[cfg(not(any(target_os = "none", target_family = "wasm")))]
    fn segment_core(&self) -> Option<[V2<R>; 2]> {
        (**self).segment_core()
    }
    #[cfg(not(any(target_os = "none", target_family = "wasm")))]
    fn inner_radius_squared(&self) -> R {
        (**self).inner_radius_squared()
    }
}
