//! What the queries return. Every result carries how it ended and how many
//! iterations it took, so a caller can tell an answer from a best guess.

use crate::real::{Real, V2};

/// How a query ended.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub enum Status {
    /// Converged: exactly (a support vertex repeated) or within the epsilon.
    Converged,
    /// Stopped at the configured iteration limit; the answer is the best
    /// the query had, and its `error_bound` says how far it may be off. A
    /// full EPA polytope that keeps merging corners can end this way too
    /// (raise the limit or the capacity).
    IterationLimit,
    /// EPA's polytope filled up with no corner it could merge away before
    /// it converged (raise its capacity); the answer is sound, as above.
    CapacityLimit,
}

impl Status {
    pub fn is_converged(self) -> bool {
        self == Status::Converged
    }
}

/// The answer of the intersection test.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Detection {
    /// Whether the shapes overlap (touching counts as overlapping).
    pub intersecting: bool,
    /// GJK iterations (1 for two small polygons answered by their
    /// separating axes, in one pass).
    pub iterations: u32,
    /// `IterationLimit` means the verdict is a best guess.
    pub status: Status,
}

/// Two shapes apart: the distance, the unit normal from A towards B, and the
/// closest point on each shape, in world coordinates.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Separation<R: Real> {
    pub distance: R,
    pub normal: R::Vector,
    pub point_a: R::Vector,
    pub point_b: R::Vector,
    /// Certified bound on the error of `distance` from the iteration: the
    /// gap between GJK's upper and lower bounds (rounding comes on top, a few
    /// ulps of the pair's size). Usually zero for polytopes that converged;
    /// nearly parallel faces can leave it wider than the actual error.
    pub error_bound: R,
    pub iterations: u32,
    pub status: Status,
}

/// Two shapes overlapping: moving B by `depth` along `normal` (a unit vector
/// pointing from A towards B) separates them. The depth is always achievable
/// in that sense (to rounding); the true minimum depth lies between
/// `depth - error_bound` and `depth`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Penetration<R: Real> {
    pub normal: R::Vector,
    pub depth: R,
    /// Certified bound on the error of `depth` from the iteration: the gap
    /// between EPA's lower bound (its closest polytope edge) and the depth.
    /// Zero-width for polytopes that converged; on curved shapes whose
    /// polytope filled up it can be far wider than the actual error (the depth
    /// is then polished to the configured epsilon, the bound is not).
    pub error_bound: R,
    /// GJK and EPA iterations together (1 for two small polygons answered by
    /// their separating axes, in one pass).
    pub iterations: u32,
    pub status: Status,
}

/// Where a ray ended up.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum RayOutcome<R: Real> {
    Hit(RayHit<R>),
    /// No hit within the maximum length.
    Miss,
    /// The ray starts inside the shape or on its boundary. Not a hit: there
    /// is no entry point and no meaningful normal, as in dyn4j.
    Inside,
}

/// The first point where a ray enters a shape.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct RayHit<R: Real> {
    /// Distance along the (unit) ray direction.
    pub distance: R,
    pub point: R::Vector,
    /// Unit outward normal of the surface at the hit point.
    pub normal: R::Vector,
    /// Bound on `|distance - exact distance|` (the world ray against the
    /// world shape), rounding and the GJK cast's tolerance included. It grows
    /// as the ray turns towards the surface's tangent, as the hit itself does:
    /// what moves the boundary by `e` moves the hit by `e / cos` (cos =
    /// `|normal . direction|`, at most `sqrt(2 r e)` at the tangent of a curve
    /// of radius `r`, which the computed `cos` covers). At most the distance
    /// plus the shape's diameter, never inf or NaN. In a local cast
    /// ([`SupportMap::cast_local_ray`](crate::SupportMap::cast_local_ray)) it
    /// is the cast's own gap across the surface: zero for an exact closed
    /// form.
    pub error_bound: R,
}

/// The answer of a ray cast.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct RayCast<R: Real> {
    pub outcome: RayOutcome<R>,
    /// Zero for closed-form casts (polygons, circles, capsules, segments).
    pub iterations: u32,
    pub status: Status,
}

impl<R: Real> RayCast<R> {
    pub fn hit(&self) -> Option<&RayHit<R>> {
        match &self.outcome {
            RayOutcome::Hit(h) => Some(h),
            _ => None,
        }
    }
    pub(crate) fn closed_form(outcome: RayOutcome<R>) -> Self {
        Self { outcome, iterations: 0, status: Status::Converged }
    }
}

/// A ray cast in a shape's local frame: what
/// [`SupportMap::cast_local_ray`](crate::SupportMap::cast_local_ray) returns
/// (point and normal local, relative to the reference point).
pub type LocalRayCast<R> = RayCast<R>;

/// A hit of an exact closed form: no gap across the surface
/// ([`RayHit::error_bound`] of a local cast); rounding is added in the world.
pub(crate) fn hit<R: Real>(o: V2<R>, d: V2<R>, t: R, normal: V2<R>) -> RayOutcome<R> {
    gap_hit(o, d, t, normal, R::ZERO)
}

pub(crate) fn gap_hit<R: Real>(o: V2<R>, d: V2<R>, t: R, normal: V2<R>, gap: R) -> RayOutcome<R> {
    RayOutcome::Hit(RayHit { distance: t, point: (o + d * t).to_glam(), normal: normal.to_glam(), error_bound: gap })
}

/// Which part of a shape's boundary made a contact point. A solver matches
/// the points of two steps by it, so it names the feature, not the point:
/// it stays the same while the shapes move a little.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub enum Feature {
    /// A vertex of the core, by the id [`SupportMap::support_feature`](crate::SupportMap::support_feature)
    /// gives it (on a rounded shape, the arc around it).
    Vertex(u16),
    /// The edge of the core that starts at this vertex id and runs
    /// counter-clockwise (on a rounded shape, the flat side along it).
    Edge(u16),
    /// A point of a curved boundary (a circle, an ellipse), which no vertex
    /// or edge names: such a shape has one face.
    Curve,
}

/// The features of A and of B that made a contact point.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub struct FeatureId {
    pub a: Feature,
    pub b: Feature,
}

/// One point of a [`Manifold`]: `point` lies on A's boundary and
/// `point + separation * normal` on B's, in world coordinates.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ContactPoint<R: Real> {
    pub point: R::Vector,
    /// The gap from A's boundary to B's along the manifold's normal:
    /// negative where they overlap.
    pub separation: R,
    pub id: FeatureId,
}

/// Up to two contact points of a pair within a speculative margin, with the
/// one normal they share, as a physics step's contact solver wants them. A
/// fixed array, no allocation: in 2D two points span any contact region of
/// convex shapes.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Manifold<R: Real> {
    /// Unit normal from A towards B: the distance query's normal when the
    /// shapes are apart, the penetration query's when they overlap.
    pub normal: R::Vector,
    /// The first [`len`](Self::len) are the points; the rest are unused.
    pub points: [ContactPoint<R>; 2],
    pub len: usize,
    /// Iterations of the query that gave the normal.
    pub iterations: u32,
    /// How the query that gave the normal ended.
    pub status: Status,
}

impl<R: Real> Manifold<R> {
    /// The contact points (none when the pair is farther apart than the
    /// margin).
    pub fn points(&self) -> &[ContactPoint<R>] {
        &self.points[..self.len.min(2)]
    }

    pub fn is_empty(&self) -> bool {
        self.len == 0
    }

    /// No points yet, with the normal and the query's iterations and status.
    pub(crate) fn empty(normal: R::Vector, iterations: u32, status: Status) -> Self {
        let none = ContactPoint {
            point: V2::<R>::zero().to_glam(),
            separation: R::ZERO,
            id: FeatureId { a: Feature::Curve, b: Feature::Curve },
        };
        Self { normal, points: [none; 2], len: 0, iterations, status }
    }

    /// Adds a point if there is room: a third would be a bug, never a panic.
    pub(crate) fn push(&mut self, point: ContactPoint<R>) {
        if let Some(slot) = self.points.get_mut(self.len) {
            *slot = point;
            self.len += 1;
        }
    }
}
