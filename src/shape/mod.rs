//! Shapes as support maps: the trait GJK, EPA and the GJK ray cast query, and
//! one module per shape.
//!
//! Every shape is a *core* (a point, a segment, a polygon or a curved convex
//! set) swept by a *radius*. Circles and capsules are a point and a segment
//! with a radius, so the queries handle their curvature in closed form and
//! spend no iterations on it: they come out as exact as polygons.
//!
//! On bare-metal targets a shape's support code, where it is more than a
//! few instructions, is one function out of line, which the trait's two
//! support methods (`support`, `support_feature`) call. Inlined, each
//! method held its own copy, and a firmware that reaches shapes through
//! `dyn SupportMap` links every method of every shape: 1.0 KB of flash
//! with every shape and query on the M4F (when there were three support
//! methods). The call costs an ellipse's GJK ray cast 2% more instructions
//! there (its distance query measured 5% fewer). Hosts inline it for speed.
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

pub use capsule::Capsule;
pub use circle::Circle;
pub use ellipse::Ellipse;
pub use half_ellipse::HalfEllipse;
pub use polygon::Polygon;
pub(crate) use polygon_frame::ConstChecks;
pub use rectangle::Rectangle;
pub use rounded::Rounded;
pub use segment::Segment;
pub use slice::Slice;
pub(crate) use slice::SliceConst;
pub use triangle::Triangle;

use crate::real::{Real, V2};
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
    /// shape, radius included. Relative tolerances are measured against it.
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
    /// linked, and the second was dead weight in every vtable.
    fn support_feature(&self, direction: R::Vector, near: u32) -> (R::Vector, u32) {
        let _ = near;
        (self.support(direction), NO_FEATURE)
    }

    /// Whether the core is a polytope: every [`support_feature`](Self::support_feature)
    /// is a vertex with an id, never [`NO_FEATURE`]. A penetration solver then
    /// leaves out its work for curved boundaries, and a firmware whose shapes
    /// are all polytopes links none of it (1.1 KB of flash with EPA on the
    /// M4F). The default, false, is always safe: it only keeps that work.
    fn is_polytope(&self) -> bool {
        false
    }

    /// An exact ray cast, for shapes that have a closed form: a ray in the
    /// local frame (origin relative to the reference point, unit direction),
    /// `max_length` infinite when unbounded. `None` (the default) makes the ray
    /// cast iterate on the support function.
    fn cast_local_ray(&self, origin: R::Vector, direction: R::Vector, max_length: R) -> Option<LocalRayCast<R>> {
        let _ = (origin, direction, max_length);
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
}

/// The most vertices a polygon may have for the separating-axis test.
#[cfg(not(any(target_os = "none", target_family = "wasm")))]
pub const SMALL_POLYGON_MAX: usize = 8;

/// A polygon core of at most [`SMALL_POLYGON_MAX`] vertices, as
/// [`SupportMap::small_polygon`] lends it: counter-clockwise, relative to
/// the reference point.
#[doc(hidden)]
#[cfg(not(any(target_os = "none", target_family = "wasm")))]
#[derive(Clone, Copy, Debug)]
pub struct SmallPolygon<'s, R: Real> {
    pub(crate) vertices: &'s [V2<R>],
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
    fn support_feature(&self, direction: R::Vector, near: u32) -> (R::Vector, u32) {
        (**self).support_feature(direction, near)
    }
    fn is_polytope(&self) -> bool {
        (**self).is_polytope()
    }
    fn cast_local_ray(&self, o: R::Vector, d: R::Vector, max: R) -> Option<LocalRayCast<R>> {
        (**self).cast_local_ray(o, d, max)
    }
    #[cfg(not(any(target_os = "none", target_family = "wasm")))]
    fn small_polygon(&self) -> Option<SmallPolygon<'_, R>> {
        (**self).small_polygon()
    }
}

/// Up to this many vertices a polytope is scanned, beyond it searched in
/// O(log n): for its support here, and for a ray cast
/// ([`cast_ray_many_sided`](crate::ray::cast_ray_many_sided)).
const LINEAR_SCAN_MAX: usize = 24;

/// Whether a polytope of capacity `N` and `len` vertices is searched rather
/// than scanned: for small capacities no search is even compiled in.
#[inline(always)]
pub(crate) const fn searched<const N: usize>(len: usize) -> bool {
    N > LINEAR_SCAN_MAX && len > LINEAR_SCAN_MAX
}

/// Support of a polytope core given as a vertex slice, as (index, vertex):
/// a linear scan, or an O(log n) search over edge directions where
/// [`searched`]. No indexing can panic: an empty slice gives vertex 0 at
/// the origin.
///
/// Out of line on bare-metal targets, like [`polytope_support_near`]: one
/// copy then serves both shapes of a pair and every call site: 0.32 KB less
/// flash with every shape and query on the M4F, for 12 B more in a firmware
/// with polygons alone. Hosts inline it for speed.
#[cfg_attr(target_os = "none", inline(never))]
#[cfg_attr(not(target_os = "none"), inline)]
pub(crate) fn polytope_support<R: Real, const N: usize>(vertices: &[V2<R>], d: V2<R>) -> (usize, V2<R>) {
    if searched::<N>(vertices.len()) && !simd_scanned::<R>(vertices.len()) {
        let (k, _) = hill_climb(vertices, d, angular_search(vertices, d), vertices.len());
        return (k, at(vertices, k));
    }
    scan_support(vertices, d)
}

/// The first vertex of largest dot product with `d`. On hosts its index is
/// kept by a select, not a branch: which vertex leads changes from query to
/// query, and a branch on it is mispredicted about twice in an 8-gon's scan.
/// Microcontrollers have no predictor to miss, and there the branch is the
/// fewer instructions. Both give the same vertex, to the bit. An empty slice
/// gives vertex 0 at the origin.
#[inline(always)]
fn scan_support<R: Real>(vertices: &[V2<R>], d: V2<R>) -> (usize, V2<R>) {
    let mut best_dot = -R::INFINITY;
    if cfg!(target_os = "none") {
        let mut best = (0, V2::zero());
        for (i, &v) in vertices.iter().enumerate() {
            let dot = v.dot(d);
            if dot > best_dot {
                best = (i, v);
                best_dot = dot;
            }
        }
        return best;
    }
    if let Some(i) = R::first_max_dot(vertices, d) {
        return (i, at(vertices, i));
    }
    let mut best_i = 0;
    for (i, &v) in vertices.iter().enumerate() {
        let dot = v.dot(d);
        let better = dot > best_dot;
        best_i = core::hint::select_unpredictable(better, i, best_i);
        best_dot = core::hint::select_unpredictable(better, dot, best_dot);
    }
    (best_i, at(vertices, best_i))
}

/// Vertex `i`, or the origin out of range (never the case for the callers,
/// whose indices stay below the length; this keeps panics out of the code).
#[inline(always)]
pub(crate) fn at<R: Real>(vertices: &[V2<R>], i: usize) -> V2<R> {
    vertices.get(i).copied().unwrap_or_default()
}

/// The support vertex is the start of the first edge whose direction, going
/// counter-clockwise, reaches the tangent `perp(d)`. Edge directions of a
/// convex polygon turn monotonically through one full turn, so angles measured
/// from edge 0 are sorted and a binary search finds that edge. Rounding can make
/// the comparison wrong for nearly parallel edges; the hill climb mends that.
fn angular_search<R: Real>(vertices: &[V2<R>], d: V2<R>) -> usize {
    let n = vertices.len();
    let edge = |i: usize| at(vertices, if i + 1 >= n { 0 } else { i + 1 }) - at(vertices, i);
    let e0 = edge(0);
    let tangent = d.perp();
    // Half-turn index of u relative to e0: 0 for [0, pi), 1 for [pi, 2 pi).
    let half = |u: V2<R>| {
        let c = e0.cross(u);
        !(c > R::ZERO || (c == R::ZERO && e0.dot(u) > R::ZERO))
    };
    let angle_less = |u: V2<R>, hu: bool, w: V2<R>, hw: bool| if hu != hw { !hu } else { u.cross(w) > R::ZERO };
    let ht = half(tangent);
    // The first edge k with angle(e_k) >= angle(tangent); edges 1..n.
    let k = first_reached(1, n, |k| {
        let e = edge(k);
        !angle_less(e, half(e), tangent, ht)
    });
    if k >= n {
        0
    } else {
        k
    }
}

/// The first index in `lo..hi` where `reached` holds, given that it holds
/// from there on; `hi` where it holds nowhere. A binary search over indices
/// rather than a slice (the searches here go round a polygon).
pub(crate) fn first_reached(mut lo: usize, mut hi: usize, reached: impl Fn(usize) -> bool) -> usize {
    while lo < hi {
        let mid = lo + (hi - lo) / 2;
        if reached(mid) {
            hi = mid;
        } else {
            lo = mid + 1;
        }
    }
    lo
}

/// Up to this many vertices a polytope is scanned, not walked or searched,
/// where the scan is SIMD: a branch-free pass over a few dozen vertices
/// beats a walk or a binary search whose branches the predictor misses.
const SIMD_SCAN_MAX: usize = 64;

/// Whether `len` vertices are scanned in SIMD rather than walked or searched.
#[inline(always)]
fn simd_scanned<R: Real>(len: usize) -> bool {
    R::SIMD_SCAN && len <= SIMD_SCAN_MAX
}

/// Up to this capacity a polytope is always scanned: firmware with small
/// polygons then links no walk, and on hosts a branch-free scan of a few
/// vertices beats a walk whose steps the branch predictor cannot guess.
pub(crate) const SCAN_ONLY_MAX: usize = 8;

/// Support from the previous support vertex `start`, by walking at most 3
/// steps; a direction that turned farther than that (or an out-of-range
/// hint) falls back to the full search, so a jump never costs O(n).
#[inline(always)]
pub(crate) fn polytope_support_near<R: Real, const N: usize>(
    vertices: &[V2<R>],
    d: V2<R>,
    start: u32,
) -> (usize, V2<R>) {
    if N > SCAN_ONLY_MAX && !simd_scanned::<R>(vertices.len()) {
        walk_from::<R, N>(vertices, d, start)
    } else {
        polytope_support::<R, N>(vertices, d)
    }
}

/// The walk of [`polytope_support_near`], out of line on bare-metal targets
/// like [`polytope_support`].
#[cfg_attr(target_os = "none", inline(never))]
#[cfg_attr(not(target_os = "none"), inline)]
fn walk_from<R: Real, const N: usize>(vertices: &[V2<R>], d: V2<R>, start: u32) -> (usize, V2<R>) {
    const MAX_WALK: usize = 3;
    if (start as usize) < vertices.len() {
        if let (k, true) = hill_climb(vertices, d, start as usize, MAX_WALK) {
            return (k, at(vertices, k));
        }
    }
    polytope_support::<R, N>(vertices, d)
}

/// Walk from `start` towards the top along `d`, at most `max_steps` steps:
/// returns the vertex and whether it is the top. Each step is decided by the
/// sign of an edge's rise `(v[k+1] - v[k]) . d`, not by comparing two rounded
/// vertex dot products: the rise rounds with the edge's length, not with the
/// vertices' distance from the origin, so a long run of vertices whose dot
/// products tie to rounding is climbed to its true top. The walk keeps one
/// way and stops where the next edge does not rise: on a convex polygon,
/// the top (the first end of an edge perpendicular to `d`, as the scan picks
/// the first of tied vertices). `max_steps = n` always gets there; a wrong
/// sign can only come from an edge perpendicular to `d` within rounding,
/// which moves the dot product by as little.
fn hill_climb<R: Real>(vertices: &[V2<R>], d: V2<R>, start: usize, max_steps: usize) -> (usize, bool) {
    let n = vertices.len();
    if n == 0 {
        return (0, true);
    }
    let next = |k: usize| if k + 1 >= n { 0 } else { k + 1 };
    let prev = |k: usize| if k == 0 { n - 1 } else { k - 1 };
    let mut k = start.min(n - 1);
    let rise = |from: usize, to: usize| (at(vertices, to) - at(vertices, from)).dot(d);
    let (ahead, behind) = (rise(k, next(k)), rise(prev(k), k));
    // Forward up a rising edge (the steeper way at a bottom), back where the
    // edge behind falls; then on that way while the next edge rises (not
    // rising, NaN too: the top).
    let forward = ahead > R::ZERO && ahead >= -behind;
    let backward = behind < R::ZERO;
    if !forward && !backward {
        return (k, true);
    }
    let step = |k: usize| if forward { next(k) } else { prev(k) };
    for _ in 0..max_steps {
        let j = step(k);
        let up = rise(k, j) > R::ZERO;
        if !up {
            return (k, true);
        }
        k = j;
    }
    (k, false)
}
