//! The Minkowski difference B - A of two placed shapes, evaluated in A's
//! reference frame: the relative pose is computed once per query, so two
//! shapes far from the origin are handled with the precision of their size,
//! not of their position.

use core::cell::Cell;

#[cfg(not(any(target_os = "none", target_family = "wasm")))]
use crate::polytope::{
    at, pair_support_near, polytope_support_between, squares_in_one_pass, ARC_SEARCH_MIN, SMALL_POLYGON_MAX,
};
use crate::real::{Real, V2};
#[cfg(not(any(target_os = "none", target_family = "wasm")))]
use crate::shape::SmallPolygon;
use crate::shape::SupportMap;
use crate::transform::Transform;

/// Feature id of a Minkowski vertex: both shapes' vertex ids packed in 16
/// bits each, or [`NO_ID`] when either support point lies on a curve (or a
/// polygon has more than 65535 vertices, where exact termination gives way to
/// the tolerance).
pub const NO_ID: u32 = u32::MAX;

/// A point of the Minkowski difference with the shape points it came from.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub(crate) struct MinkowskiVertex<R> {
    /// `b - a`.
    pub w: V2<R>,
    pub a: V2<R>,
    pub b: V2<R>,
    pub id: u32,
}

/// A support point of a Minkowski difference, as pluggable penetration
/// solvers see it.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SupportPoint<R: Real> {
    pub point: R::Vector,
    /// Identifies the pair of shape vertices; [`NO_ID`] on curves. Equal ids
    /// mean the same point, so a solver can stop exactly.
    pub id: u32,
}

/// The Minkowski difference of the cores of two shapes (B - A), in the
/// frame of A's reference point: what a penetration solver works on.
pub trait MinkowskiDifference<R: Real> {
    /// The farthest point of B - A along `direction` (not necessarily unit).
    fn support(&self, direction: R::Vector) -> SupportPoint<R>;
    /// The support along `direction` where it turns between the directions
    /// whose supports were the points of ids `from` and `to`, in that order
    /// counter-clockwise, as the outward normal of a polytope's edge lies
    /// between its ends': a difference of polygons then searches only the
    /// vertices between. The answer is [`support`](Self::support)'s, which
    /// the default gives.
    fn support_between(&self, direction: R::Vector, from: u32, to: u32) -> SupportPoint<R> {
        let _ = (from, to);
        self.support(direction)
    }
    /// Whether the points of ids `from` and `to`, in that order
    /// counter-clockwise, end one edge of the difference: a polytope edge
    /// between them then lies on its boundary, and a solver can stop there
    /// without asking for the support that would only repeat an end. False,
    /// the default, is always safe.
    fn is_face(&self, from: u32, to: u32) -> bool {
        let _ = (from, to);
        false
    }
    /// The faces of the difference's boundary from the point of id `from`
    /// to the point of id `to`, in that order counter-clockwise, written to
    /// `faces` where they fit: each face's far end and its outward unit
    /// normal, the last ending at `to`; their number. A solver that has
    /// found a short stretch of the boundary takes it whole, not a support
    /// at a time. The normals come from the shapes' own edges: taken from
    /// two rounded points of the difference, a short edge's would turn
    /// every way. `None`, the default, is always safe.
    fn faces_between(&self, from: u32, to: u32, faces: &mut [(SupportPoint<R>, R::Vector)]) -> Option<usize> {
        let _ = (from, to, faces);
        None
    }
    /// The closest to the origin of the faces of the difference's boundary
    /// from the point of id `from` to the point of id `to`, in that order
    /// counter-clockwise, where at most `max_faces` lie between: its
    /// distance from the origin (never negative) and its outward unit
    /// normal. No part of the boundary between is closer, so a solver can
    /// settle that whole stretch at once. The normal comes from the shapes'
    /// own edges, as in [`faces_between`](Self::faces_between). `None`, the
    /// default, is always safe.
    fn closest_face_between(&self, from: u32, to: u32, max_faces: usize) -> Option<(R, R::Vector)> {
        let _ = (from, to, max_faces);
        None
    }
    /// The pair's size: the larger bounding radius. Relative tolerances are
    /// multiplied by it.
    fn scale(&self) -> R;
    /// Whether both cores are polytopes ([`SupportMap::is_polytope`]): no
    /// support point is ever on a curve. False, the default, is always safe.
    fn is_polytope(&self) -> bool {
        false
    }
    /// At most how many vertices the difference has, where it is a
    /// polytope ([`SupportMap::core_vertex_bound`]): the sum of the cores'.
    /// The default, unbounded, is always safe.
    fn vertex_bound(&self) -> usize {
        usize::MAX
    }
}

/// A polytope core's vertices, relative to its reference point.
#[cfg(not(any(target_os = "none", target_family = "wasm")))]
pub(crate) type Vertices<'s, R> = &'s [V2<R>];

/// Two shapes placed relative to each other.
pub(crate) struct Pair<'s, R: Real, A: ?Sized, B: ?Sized> {
    a: &'s A,
    b: &'s B,
    /// Rotation of B's frame in A's frame, skipped when it is the identity.
    cos: R,
    sin: R,
    rotated: bool,
    /// B's reference point in A's reference frame.
    offset: V2<R>,
    /// B's center minus A's center: orients a normal the simplex cannot.
    pub centers: V2<R>,
    /// GJK's first search direction, from A's center towards B's, chosen
    /// here once, not in an inlined copy in each GJK loop.
    pub first_direction: V2<R>,
    /// A's placement, for answers in world coordinates.
    frame: &'s Transform<R>,
    reference_a: V2<R>,
    /// Each shape's last support id: where the next support starts looking.
    hint_a: Cell<u32>,
    hint_b: Cell<u32>,
}

impl<'s, R: Real, A: SupportMap<R> + ?Sized, B: SupportMap<R> + ?Sized> Pair<'s, R, A, B> {
    #[cfg_attr(not(target_os = "none"), inline(always))]
    pub fn new(a: &'s A, ta: &'s Transform<R>, b: &'s B, tb: &Transform<R>) -> Self {
        let reference_a = V2::from_glam(a.reference_point());
        let reference_b = V2::from_glam(b.reference_point());
        let (cos, sin, rotated) = if ta.cos == tb.cos && ta.sin == tb.sin {
            (R::ONE, R::ZERO, false)
        } else {
            (ta.cos * tb.cos + ta.sin * tb.sin, ta.cos * tb.sin - ta.sin * tb.cos, true)
        };
        let mut pair = Self {
            a,
            b,
            cos,
            sin,
            rotated,
            offset: V2::zero(),
            centers: V2::zero(),
            first_direction: V2::zero(),
            frame: ta,
            reference_a,
            hint_a: Cell::new(NO_ID),
            hint_b: Cell::new(NO_ID),
        };
        // Differences first: references and translations of nearby shapes
        // nearly cancel, and a difference of nearby floats is exact.
        let references = pair.rotate(reference_b) - reference_a;
        let translations = ta.inverse_rotate(tb.translation - ta.translation);
        pair.offset = translations + references;
        // Geometry far from its local origin and placed: those terms are
        // large, round at their own scale and cancel, so the gap between
        // the placed references is summed error-free instead.
        #[cfg(feature = "far-geometry")]
        if (a.far_from_origin() || b.far_from_origin()) && !(ta.is_identity() && tb.is_identity()) {
            pair.offset = ta.inverse_rotate(crate::compensated::placed_gap(ta, reference_a, tb, reference_b));
        }
        pair.centers = pair.rotate(V2::from_glam(b.center())) + pair.offset - V2::from_glam(a.center());
        // Towards the origin from B's center minus A's: the point of B - A
        // most likely closest to the origin.
        pair.first_direction =
            if pair.centers.length_squared() > R::ZERO { -pair.centers } else { V2::new(R::ONE, R::ZERO) };
        pair
    }

    /// Sum of both radii: the cores are compared, the radii added after.
    /// Asked of the shapes where needed rather than stored: a polygon's
    /// radius is then a constant zero, and the code for rounded shapes
    /// (square roots, closed forms) drops out of a firmware with polygons.
    #[inline(always)]
    pub fn radius(&self) -> R {
        self.a.radius() + self.b.radius()
    }
    /// How far apart the cores may be and still count as intersecting: the
    /// radii, widened by `detect_epsilon` times the pair's size. The size
    /// is asked for only with a margin: with the default (none) two
    /// polygons are tested with no square root, and a firmware that only
    /// tests polygons for overlap links none.
    #[inline(always)]
    pub fn detect_reach(&self, detect_epsilon: R) -> R {
        let margin = if detect_epsilon == R::ZERO { R::ZERO } else { detect_epsilon * self.scale() };
        self.radius() + margin
    }
    #[inline(always)]
    pub fn radius_a(&self) -> R {
        self.a.radius()
    }
    #[inline(always)]
    pub fn radius_b(&self) -> R {
        self.b.radius()
    }
    /// Each shape's center, in its own frame.
    #[cfg(not(any(target_os = "none", target_family = "wasm")))]
    #[inline(always)]
    pub fn a_center(&self) -> R::Vector {
        self.a.center()
    }
    #[cfg(not(any(target_os = "none", target_family = "wasm")))]
    #[inline(always)]
    pub fn b_center(&self) -> R::Vector {
        self.b.center()
    }

    /// The pair's size: the larger bounding radius. Asked for where it is
    /// needed, not up front: the polygon overlap test never needs it, and then
    /// links no square root. One out-of-line copy on bare metal, whose flash
    /// is scarce, where GJK and EPA each ask for it.
    #[cfg_attr(target_os = "none", inline(never))]
    pub fn scale(&self) -> R {
        self.a.bounding_radius().max(self.b.bounding_radius())
    }

    #[inline(always)]
    fn rotate(&self, v: V2<R>) -> V2<R> {
        self.turn(v, self.sin)
    }
    /// The inverse rotation is the rotation by `-sin`, to the bit: negation
    /// is exact, and `a - (-b)` rounds as `a + b`.
    #[inline(always)]
    fn inverse_rotate(&self, v: V2<R>) -> V2<R> {
        self.turn(v, -self.sin)
    }
    /// `v` rotated by (`cos`, `sin`), or left as it is when the shapes are
    /// not rotated relative to each other.
    #[inline(always)]
    fn turn(&self, v: V2<R>, sin: R) -> V2<R> {
        if self.rotated {
            V2::new(self.cos * v.x - sin * v.y, sin * v.x + self.cos * v.y)
        } else {
            v
        }
    }

    /// [`support`](Self::support) for the queries that ask for supports in
    /// several places (distance, EPA): one out-of-line copy on bare-metal
    /// targets, so that each call site does not carry a copy of its own. The intersection test
    /// keeps the inlined one where the shapes' types are known
    /// ([`shapes_known`](Self::shapes_known)): there the compiler sees that a
    /// polygon's ids are never [`NO_ID`] and drops the code for curved
    /// shapes.
    #[cfg_attr(target_os = "none", inline(never))]
    #[cfg_attr(not(target_os = "none"), inline(always))]
    pub fn support_shared(&self, d: V2<R>) -> MinkowskiVertex<R> {
        self.support(d)
    }

    /// Whether both cores are single points (circles), asked only on hosts
    /// (where skipping GJK's loop spares mispredicted branches; a firmware
    /// keeps its code as it is) and only where the shapes' types are known
    /// when the program is compiled: a polygon's constant zero radius then
    /// drops the question, and trait objects never ask it.
    #[inline(always)]
    pub fn point_cores(&self) -> bool {
        cfg!(not(target_os = "none")) && Self::shapes_known() && point_core(self.a) && point_core(self.b)
    }

    /// Whether both shapes' types are known when the program is compiled:
    /// false for trait objects (`&dyn SupportMap`, a wide pointer), where
    /// an inlined support call can drop nothing and one shared copy
    /// ([`support_shared`](Self::support_shared)) is smaller.
    #[inline(always)]
    pub const fn shapes_known() -> bool {
        let thin = core::mem::size_of::<&()>();
        core::mem::size_of::<&A>() == thin && core::mem::size_of::<&B>() == thin
    }

    /// [`MinkowskiDifference::support_between`] for two polygons, one of
    /// more than [`ARC_SEARCH_MIN`] vertices, where both shapes' types are known when the
    /// program is compiled: each polygon's support is searched on its arc
    /// between the two ids' vertices (A's along `-d`, turning the same way).
    #[cfg(not(any(target_os = "none", target_family = "wasm")))]
    #[inline(always)]
    pub fn support_between(&self, d: V2<R>, from: u32, to: u32) -> MinkowskiVertex<R> {
        let Some((a, b)) = self
            .polygons()
            .filter(|(a, b)| (ARC_SEARCH_MIN + 1..0xFFFF).contains(&a.vertices.len().max(b.vertices.len())))
        else {
            return self.support_shared(d);
        };
        if from == NO_ID || to == NO_ID {
            return self.support_shared(d);
        }
        let (ia, a) = polytope_support_between(a.vertices, a.compass, -d, from >> 16, to >> 16);
        let (ib, b) =
            polytope_support_between(b.vertices, b.compass, self.inverse_rotate(d), from & 0xFFFF, to & 0xFFFF);
        self.vertex_of((ia, a), (ib, b))
    }

    /// [`MinkowskiDifference::is_face`] for two polygons whose types are
    /// known when the program is compiled. The ids must step along one
    /// polygon's edge while the other's vertex stays, and that vertex must
    /// be its polygon's support along the edge's normal: the edge of B - A
    /// between the two points is then that polygon's edge moved by the
    /// vertex, on the boundary.
    #[cfg(not(any(target_os = "none", target_family = "wasm")))]
    #[inline(always)]
    pub fn is_face(&self, from: u32, to: u32) -> bool {
        let Some((a, b)) = self.polygon_cores() else { return false };
        let (n, m) = (a.len(), b.len());
        let (Some((ia, ib)), Some((ja, jb))) = (vertex_indices(from, n, m), vertex_indices(to, n, m)) else {
            return false;
        };
        let next = |k: usize, len: usize| if k + 1 >= len { 0 } else { k + 1 };
        let prev = |k: usize, len: usize| if k == 0 { len - 1 } else { k - 1 };
        // `k` is a support of `v` along `d`: neither edge beside it rises.
        let supports = |v: &[V2<R>], k: usize, d: V2<R>| {
            (v[k] - v[prev(k, v.len())]).dot(d) >= R::ZERO && (v[next(k, v.len())] - v[k]).dot(d) <= R::ZERO
        };
        if ib == jb && ja == next(ia, n) {
            // A's edge, whose outward normal points against B - A's.
            let outward = (a[ja] - a[ia]).perp_cw();
            supports(b, ib, -self.inverse_rotate(outward))
        } else if ia == ja && jb == next(ib, m) {
            let outward = self.rotate((b[jb] - b[ib]).perp_cw());
            supports(a, ia, -outward)
        } else {
            false
        }
    }

    /// [`MinkowskiDifference::faces_between`] for two polygons whose types
    /// are known when the program is compiled, where at most `out.len()`
    /// (and [`WALKED_FACES_MAX`]) faces lie between.
    #[cfg(not(any(target_os = "none", target_family = "wasm")))]
    #[inline(always)]
    pub fn faces_between(&self, from: u32, to: u32, out: &mut [(SupportPoint<R>, R::Vector)]) -> Option<usize> {
        let mut slots = out.iter_mut();
        self.walk_faces(from, to, slots.len().min(WALKED_FACES_MAX), |_, end, edge| {
            let normal = edge.perp_cw().try_normalize()?;
            if let Some(slot) = slots.next() {
                *slot = (SupportPoint { point: end.w.to_glam(), id: end.id }, normal.to_glam());
            }
            Some(())
        })
    }

    /// [`MinkowskiDifference::closest_face_between`] for two polygons whose
    /// types are known when the program is compiled.
    #[cfg(not(any(target_os = "none", target_family = "wasm")))]
    #[inline(always)]
    pub fn closest_face_between(&self, from: u32, to: u32, max_faces: usize) -> Option<(R, V2<R>)> {
        // Faces compared by their distances divided by their edges' lengths:
        // a root and a division each, where the unit normal takes a root and
        // two; the closest's normal is then taken with the usual care.
        let mut closest = (R::INFINITY, V2::zero(), V2::zero());
        self.walk_faces(from, to, max_faces, |start, _, edge| {
            let outward = edge.perp_cw();
            let length = outward.length();
            // Too short to divide by safely: the careful unit normal.
            let distance =
                if length > R::EPSILON { start.dot(outward) / length } else { start.dot(outward.try_normalize()?) };
            let closer = distance < closest.0;
            closest = core::hint::select_unpredictable(closer, (distance, outward, start), closest);
            Some(())
        })?;
        let (_, outward, start) = closest;
        let normal = outward.try_normalize()?;
        // Measured from the face's start, as a solver measures its edges.
        Some((start.dot(normal).max(R::ZERO), normal))
    }

    /// The faces of the boundary from the point of id `from` to that of id
    /// `to`, counter-clockwise, where at most `max_faces` lie between: the
    /// merge of the polygons' edges, walked from `from` as
    /// [`neighbours`](Self::neighbours) steps, each polygon's index going
    /// forwards as far as the ids say. Each face goes to `each` as its start,
    /// its end and its edge (turned in the polygon's own frame); the count,
    /// once the walk arrives at `to`.
    #[cfg(not(any(target_os = "none", target_family = "wasm")))]
    #[inline(always)]
    fn walk_faces(
        &self,
        from: u32,
        to: u32,
        max_faces: usize,
        mut each: impl FnMut(V2<R>, MinkowskiVertex<R>, V2<R>) -> Option<()>,
    ) -> Option<usize> {
        let (a, b) = self.polygon_cores()?;
        let (n, m) = (a.len(), b.len());
        let ((mut ia, mut ib), (ja, jb)) = (vertex_indices(from, n, m)?, vertex_indices(to, n, m)?);
        let steps = |from: usize, to: usize, len: usize| if to >= from { to - from } else { to + len - from };
        let (mut left_a, mut left_b) = (steps(ia, ja, n), steps(ib, jb, m));
        // Room for as many faces as the steps (parallel edges, taken
        // together, make fewer).
        if !(1..=max_faces).contains(&(left_a + left_b)) {
            return None;
        }
        let next = |k: usize, len: usize| if k + 1 >= len { 0 } else { k + 1 };
        let mut start = self.rotate(at(b, ib)) + self.offset - at(a, ia);
        for count in 0..max_faces {
            // B's edge first where A's (reversed) turns further; parallel
            // edges together. A polygon with no steps left stays.
            let (edge_a, edge_b) = (at(a, ia) - at(a, next(ia, n)), self.rotate(at(b, next(ib, m)) - at(b, ib)));
            let turn = edge_b.cross(edge_a);
            let (arrived_a, arrived_b) = (left_a == 0, left_b == 0);
            // The ids must agree with the merge: a polygon that has arrived
            // is not the one to step.
            if (arrived_a && turn < R::ZERO) || (arrived_b && turn > R::ZERO) {
                return None;
            }
            // Which polygon steps is as unpredictable as the shapes: chosen
            // by selects, so that each face's normal (a root and a division)
            // is not thrown away by a mispredicted branch after it.
            let step_a = !arrived_a && (arrived_b || turn <= R::ZERO);
            let step_b = !arrived_b && (arrived_a || turn >= R::ZERO);
            ia = core::hint::select_unpredictable(step_a, next(ia, n), ia);
            ib = core::hint::select_unpredictable(step_b, next(ib, m), ib);
            left_a -= usize::from(step_a);
            left_b -= usize::from(step_b);
            // Of parallel edges, the longer's direction.
            let edge =
                core::hint::select_unpredictable(step_b && (!step_a || edge_b.l1() >= edge_a.l1()), edge_b, edge_a);
            let end = self.vertex_of((ia, at(a, ia)), (ib, at(b, ib)));
            each(start, end, edge)?;
            start = end.w;
            if left_a + left_b == 0 {
                return Some(count + 1);
            }
        }
        None
    }

    /// The vertex of B - A from A's vertex `ia` (`a` in its frame) and B's
    /// `ib`, which are the next supports' hints.
    #[cfg(not(any(target_os = "none", target_family = "wasm")))]
    #[inline(always)]
    fn vertex_of(&self, (ia, a): (usize, V2<R>), (ib, b): (usize, V2<R>)) -> MinkowskiVertex<R> {
        let (ia, ib) = (ia as u32, ib as u32);
        self.hint_a.set(ia);
        self.hint_b.set(ib);
        let b = self.rotate(b) + self.offset;
        let id = if ia >= 0xFFFF || ib >= 0xFFFF { NO_ID } else { (ia << 16) | ib };
        MinkowskiVertex { w: b - a, a, b, id }
    }

    /// The support point of B - A along `d`.
    #[inline(always)]
    pub fn support(&self, d: V2<R>) -> MinkowskiVertex<R> {
        #[cfg(not(any(target_os = "none", target_family = "wasm")))]
        if let Some((a, b)) = self.searched_polygon_cores() {
            let (ia, ib) = pair_support_near(
                (a.vertices, a.compass, -d, self.hint_a.get()),
                (b.vertices, b.compass, self.inverse_rotate(d), self.hint_b.get()),
            );
            return self.vertex_of((ia, at(a.vertices, ia)), (ib, at(b.vertices, ib)));
        }
        let (a, ia) = self.a.support_feature((-d).to_glam(), self.hint_a.get());
        let (b, ib) = self.b.support_feature(self.inverse_rotate(d).to_glam(), self.hint_b.get());
        self.hint_a.set(ia);
        self.hint_b.set(ib);
        let a = V2::from_glam(a);
        let b = self.rotate(V2::from_glam(b)) + self.offset;
        // NO_FEATURE (u32::MAX) and vertex indices past 16 bits both land here.
        let id = if ia >= 0xFFFF || ib >= 0xFFFF { NO_ID } else { (ia << 16) | ib };
        MinkowskiVertex { w: b - a, a, b, id }
    }

    /// The supports along `u`, `u.perp()`, `-u` and `-u.perp()`, as
    /// [`support`](Self::support) gives each, in that order (the hints left
    /// where the last leaves them), from one pass over each polygon core,
    /// where both are scanned in SIMD ([`squares_in_one_pass`]).
    #[cfg(not(any(target_os = "none", target_family = "wasm")))]
    #[inline(always)]
    pub fn scanned_square(&self, u: V2<R>) -> Option<[MinkowskiVertex<R>; 4]> {
        let (a, b) = self.prefetch_scanned_cores()?;
        let turned = u.perp();
        // A's supports are along the reverse directions, B's in its frame.
        let ia = R::extreme_dots(a, -u, -turned)?;
        let ib = R::extreme_dots(b, self.inverse_rotate(u), self.inverse_rotate(turned))?;
        Some(core::array::from_fn(|k| self.vertex_of((ia[k], at(a, ia[k])), (ib[k], at(b, ib[k])))))
    }

    /// Asks for the lines the supports along `u`, `u.perp()`, `-u` and
    /// `-u.perp()` will read, where both cores are searched polygons
    /// ([`ask_square_searches`](crate::polytope::ask_square_searches)).
    #[cfg(not(any(target_os = "none", target_family = "wasm")))]
    #[inline(always)]
    pub fn ask_square_supports(&self, u: V2<R>) {
        if let Some((a, b)) = self.searched_polygon_cores() {
            crate::polytope::ask_square_searches(
                (a.vertices, a.compass, -u),
                (b.vertices, b.compass, self.inverse_rotate(u)),
            );
        }
    }

    /// The vertices of B - A just before and just after its vertex `v` (of
    /// two polygon cores, by `v`'s ids), counter-clockwise: of the two
    /// edges that could leave a vertex (B's, or A's reversed), the one that
    /// turns first, as in the merge of two convex polygons' edges. Any pair
    /// of vertex ids is a point of B - A, so a wrong guess (ids from another
    /// pair) is only a point that is no neighbour.
    #[cfg(not(any(target_os = "none", target_family = "wasm")))]
    #[inline(always)]
    pub fn neighbours(&self, v: &MinkowskiVertex<R>) -> Option<[MinkowskiVertex<R>; 2]> {
        let (a, b) = self.polygon_cores()?;
        let (n, m) = (a.len(), b.len());
        let (ia, ib) = vertex_indices(v.id, n, m)?;
        let (next_a, prev_a) = (if ia + 1 == n { 0 } else { ia + 1 }, if ia == 0 { n - 1 } else { ia - 1 });
        let (next_b, prev_b) = (if ib + 1 == m { 0 } else { ib + 1 }, if ib == 0 { m - 1 } else { ib - 1 });
        // B's edges placed (the offset cancels), A's reversed.
        let edge_b = |from: usize, to: usize| self.rotate(at(b, to) - at(b, from));
        let edge_a = |from: usize, to: usize| at(a, from) - at(a, to);
        // B's edge first where A's turns further (counter-clockwise of it);
        // parallel edges are taken together.
        let pick = |turn: R, of_b: (usize, usize), of_a: (usize, usize), both: (usize, usize)| {
            if turn > R::ZERO {
                of_b
            } else if turn < R::ZERO {
                of_a
            } else {
                both
            }
        };
        let ahead = edge_b(ib, next_b).cross(edge_a(ia, next_a));
        let (na, nb) = pick(ahead, (ia, next_b), (next_a, ib), (next_a, next_b));
        // Behind: the edge that turns last arrives at `v`, so A's where it
        // turns further than B's.
        let behind = edge_b(prev_b, ib).cross(edge_a(prev_a, ia));
        let (pa, pb) = pick(behind, (prev_a, ib), (ia, prev_b), (prev_a, prev_b));
        let vertex = |ja: usize, jb: usize| self.vertex_of((ja, at(a, ja)), (jb, at(b, jb)));
        Some([vertex(pa, pb), vertex(na, nb)])
    }

    /// Both polygon cores, where each is scanned in SIMD whole
    /// ([`squares_in_one_pass`]), with every line of both asked for at once:
    /// read in turn, the second scan's first line would wait for the first
    /// scan's memory.
    #[cfg(not(any(target_os = "none", target_family = "wasm")))]
    #[inline(always)]
    pub fn prefetch_scanned_cores(&self) -> Option<(Vertices<'s, R>, Vertices<'s, R>)> {
        // Both asked first, so that neither polygon is asked for nothing.
        let one_pass =
            |(a, b): &(&[V2<R>], &[V2<R>])| squares_in_one_pass::<R>(a.len()) && squares_in_one_pass::<R>(b.len());
        let (a, b) = self.polygon_cores().filter(one_pass)?;
        crate::polytope::prefetch_all(a);
        crate::polytope::prefetch_all(b);
        Some((a, b))
    }

    /// The two cores as small polygons (of at most [`SMALL_POLYGON_MAX`]
    /// vertices each), where both shapes' types are known when the program
    /// is compiled (through trait objects, GJK and the penetration solver
    /// answer).
    #[cfg(not(any(target_os = "none", target_family = "wasm")))]
    #[inline(always)]
    pub fn small_polygons(&self) -> Option<(Vertices<'s, R>, Vertices<'s, R>)> {
        let small = |v: Vertices<'s, R>| v.len() <= SMALL_POLYGON_MAX;
        self.polygon_cores().filter(|&(a, b)| small(a) && small(b))
    }

    /// The two cores as polygons whose supports are searched
    /// ([`SupportMap::searched_polygon_core`]), where both shapes' types
    /// are known when the program is compiled.
    #[cfg(not(any(target_os = "none", target_family = "wasm")))]
    #[inline(always)]
    fn searched_polygon_cores(&self) -> Option<(SmallPolygon<'s, R>, SmallPolygon<'s, R>)> {
        if !Self::shapes_known() {
            return None;
        }
        let (a, b): (&'s A, &'s B) = (self.a, self.b);
        Some((a.searched_polygon_core()?, b.searched_polygon_core()?))
    }

    /// The two cores as polygons of any size ([`SupportMap::polygon_core`]),
    /// where both shapes' types are known when the program is compiled.
    #[cfg(not(any(target_os = "none", target_family = "wasm")))]
    #[inline(always)]
    pub fn polygon_cores(&self) -> Option<(Vertices<'s, R>, Vertices<'s, R>)> {
        self.polygons().map(|(a, b)| (a.vertices, b.vertices))
    }

    /// [`polygon_cores`](Self::polygon_cores) with their compasses.
    #[cfg(not(any(target_os = "none", target_family = "wasm")))]
    #[inline(always)]
    fn polygons(&self) -> Option<(SmallPolygon<'s, R>, SmallPolygon<'s, R>)> {
        if !Self::shapes_known() {
            return None;
        }
        let (a, b): (&'s A, &'s B) = (self.a, self.b);
        Some((a.polygon_core()?, b.polygon_core()?))
    }

    /// A segment core (a capsule's, a segment's) and a small polygon, where
    /// both shapes' types are known when the program is compiled: the
    /// segment's end points in its own frame, the polygon's vertices, and
    /// whether the segment is A's.
    #[cfg(not(any(target_os = "none", target_family = "wasm")))]
    #[inline(always)]
    pub fn segment_and_small_polygon(&self) -> Option<([V2<R>; 2], Vertices<'s, R>, bool)> {
        if !Self::shapes_known() {
            return None;
        }
        let (a, b): (&'s A, &'s B) = (self.a, self.b);
        if let Some(segment) = a.segment_core() {
            return Some((segment, b.small_polygon()?.vertices, true));
        }
        Some((b.segment_core()?, a.small_polygon()?.vertices, false))
    }

    /// A segment core's end points in a small polygon's frame, and the
    /// polygon's vertices ([`segment_and_small_polygon`](Self::segment_and_small_polygon)
    /// placed): what a verdict that needs no frame of its own is measured in.
    #[cfg(not(any(target_os = "none", target_family = "wasm")))]
    #[inline(always)]
    pub fn segment_in_small_polygon(&self) -> Option<([V2<R>; 2], Vertices<'s, R>)> {
        let (segment, polygon, segment_is_a) = self.segment_and_small_polygon()?;
        let place = |p: V2<R>| if segment_is_a { self.inverse_rotate(p - self.offset) } else { self.b_to_pair(p) };
        // Not `map`: the compiler called that closure out of line.
        Some(([place(segment[0]), place(segment[1])], polygon))
    }

    /// A's core vertices (in the pair frame, which is A's), where A lends
    /// them (a polygon of any size, a segment core) and both types are
    /// known when the program is compiled: a contact manifold then finds a support vertex's edges
    /// by index instead of by asking the support function around it.
    #[cfg(not(any(target_os = "none", target_family = "wasm")))]
    #[inline(always)]
    pub fn corners_a(&self) -> Option<Corners<'s, R>> {
        let a: &'s A = self.a;
        Self::shapes_known().then(|| Corners::lent(a)).flatten()
    }

    /// B's, as [`corners_a`](Self::corners_a) gives A's, in B's frame:
    /// [`b_to_pair`](Self::b_to_pair) places them.
    #[cfg(not(any(target_os = "none", target_family = "wasm")))]
    #[inline(always)]
    pub fn corners_b(&self) -> Option<Corners<'s, R>> {
        let b: &'s B = self.b;
        Self::shapes_known().then(|| Corners::lent(b)).flatten()
    }

    /// A point core (a circle's centre) and a small polygon, where both
    /// shapes' types are known when the program is compiled: the point in
    /// the polygon's frame, the polygon's vertices, and whether the point is
    /// A's (then the polygon is B, and its answers go back through
    /// [`b_to_pair`](Self::b_to_pair) and [`b_vector_to_pair`](Self::b_vector_to_pair)).
    #[cfg(not(any(target_os = "none", target_family = "wasm")))]
    #[inline(always)]
    pub fn point_and_small_polygon(&self) -> Option<(V2<R>, Vertices<'s, R>, bool)> {
        if !Self::shapes_known() {
            return None;
        }
        let (a, b): (&'s A, &'s B) = (self.a, self.b);
        if point_core(a) {
            let polygon = b.small_polygon()?.vertices;
            return Some((self.inverse_rotate(V2::from_glam(a.center()) - self.offset), polygon, true));
        }
        if point_core(b) {
            return Some((self.b_to_pair(V2::from_glam(b.center())), a.small_polygon()?.vertices, false));
        }
        None
    }

    /// A direction of B's frame in the pair frame.
    #[cfg(not(any(target_os = "none", target_family = "wasm")))]
    #[inline(always)]
    pub fn b_vector_to_pair(&self, v: V2<R>) -> V2<R> {
        self.rotate(v)
    }

    /// B's placement in the pair frame: the rotation's cosine and sine, and
    /// its reference point's offset (what a warm start measures motion by).
    #[cfg(not(any(target_os = "none", target_family = "wasm")))]
    #[inline(always)]
    pub fn pose(&self) -> (R, R, V2<R>) {
        (self.cos, self.sin, self.offset)
    }

    /// B's rotation in the pair frame (cosine, sine), `None` for none: for
    /// turning many vectors with the question asked once.
    #[cfg(not(any(target_os = "none", target_family = "wasm")))]
    #[inline(always)]
    pub fn b_rotation(&self) -> Option<(R, R)> {
        self.rotated.then_some((self.cos, self.sin))
    }

    /// Whether the disks the shapes contain about their cores
    /// ([`SupportMap::inner_radius_squared`]) overlap by more than the
    /// placement's rounding: then so do the shapes. Where the types are
    /// not known when the program is compiled, never: trait objects keep
    /// the answers firmware gives. Nor for two disks, whose closed form
    /// costs no more.
    #[cfg(not(any(target_os = "none", target_family = "wasm")))]
    #[inline(always)]
    pub fn inner_disks_overlap(&self) -> bool {
        if !Self::shapes_known() || self.point_cores() {
            return false;
        }
        let (a, b) = (self.a.inner_radius_squared(), self.b.inner_radius_squared());
        if !(a > R::ZERO && b > R::ZERO) {
            return false;
        }
        // Each root apart: their product cannot overflow, and the two run
        // side by side.
        let reach = a + b + R::TWO * a.sqrt() * b.sqrt();
        let (gap, margin) = self.cores_gap_squared(self.core_segment());
        gap * (R::ONE + R::from_u32(64) * R::EPSILON) + margin < reach * (R::ONE - R::from_u32(8) * R::EPSILON)
    }

    /// Whether the disks about the shapes' cores that hold them
    /// ([`SupportMap::bounding_radius`], or a capsule's radius about its
    /// segment) are apart by more than the placement's rounding: then so
    /// are the shapes, and the intersection test answers before any
    /// support (pairs a broad phase passes on whose boxes overlap, and
    /// their disks do not). Where the types are not known when the program
    /// is compiled, never, as [`inner_disks_overlap`](Self::inner_disks_overlap).
    #[cfg(not(any(target_os = "none", target_family = "wasm")))]
    #[inline(always)]
    pub fn bounding_disks_apart(&self) -> bool {
        if !Self::shapes_known() || self.point_cores() {
            return false;
        }
        let segment = self.core_segment();
        let (a, b) = match segment {
            Some((_, true)) => (self.a.radius(), self.b.bounding_radius()),
            Some((_, false)) => (self.a.bounding_radius(), self.b.radius()),
            None => self.bounding_radii(),
        };
        // Each radius is within a few eps of the exact bound it rounds.
        let reach = (a + b) * (R::ONE + R::from_u32(8) * R::EPSILON);
        let (gap, margin) = self.cores_gap_squared(segment);
        gap * (R::ONE - R::from_u32(64) * R::EPSILON) - margin > reach * reach
    }

    /// Half of the segment a capsule (or a segment) is swept about, in the
    /// pair frame, about its center, and whether it is A's; `None` unless
    /// exactly one shape has one. Its disks reach along the segment, where
    /// one about its center would be only its radius.
    #[cfg(not(any(target_os = "none", target_family = "wasm")))]
    #[inline(always)]
    fn core_segment(&self) -> Option<(V2<R>, bool)> {
        match (self.a.segment_core(), self.b.segment_core()) {
            (Some(s), None) => Some(((s[1] - s[0]) * R::HALF, true)),
            (None, Some(s)) => Some((self.rotate((s[1] - s[0]) * R::HALF), false)),
            _ => None,
        }
    }

    /// The square of the distance between the shapes' cores (their
    /// centers, or one center and the other's `segment`, as
    /// [`core_segment`](Self::core_segment) gives it),
    /// and what the exact square may exceed or fall short of it by beyond
    /// 64 eps of it. The computed `centers` is off the exact one by at most
    /// 8 eps of the size it is computed from, the nearest point of a
    /// segment by as much again: the exact square is then within 64 eps of
    /// the computed one, plus 64 eps of the size's square.
    #[cfg(not(any(target_os = "none", target_family = "wasm")))]
    #[inline(always)]
    fn cores_gap_squared(&self, segment: Option<(V2<R>, bool)>) -> (R, R) {
        let size = V2::<R>::from_glam(self.a.center()).l1()
            + V2::<R>::from_glam(self.b.center()).l1()
            + self.reference_a.l1()
            + V2::<R>::from_glam(self.b.reference_point()).l1()
            + self.offset.l1();
        let margin = R::from_u32(64) * R::EPSILON * size * size;
        let Some((half, _)) = segment else {
            return (self.centers.length_squared(), margin);
        };
        // The segment is symmetric about its center: the nearest point to
        // `centers` or to `-centers` is as far.
        let length2 = half.length_squared();
        let along = if length2 > R::ZERO { self.centers.dot(half) / length2 } else { R::ZERO };
        let along = along.max(-R::ONE).min(R::ONE);
        ((self.centers - half * along).length_squared(), margin)
    }

    /// The size of the pair's coordinates in its frame, for margins of
    /// rounding: twice each bounding radius (a vertex from the reference
    /// point) and B's offset.
    #[cfg(not(any(target_os = "none", target_family = "wasm")))]
    #[inline(always)]
    pub fn coordinates_size(&self) -> R {
        R::from_u32(8) * self.scale() + self.offset.l1()
    }

    /// Each shape's bounding radius about its center.
    #[cfg(not(any(target_os = "none", target_family = "wasm")))]
    #[inline(always)]
    pub fn bounding_radii(&self) -> (R, R) {
        (self.a.bounding_radius(), self.b.bounding_radius())
    }

    /// A direction of the pair frame in B's frame.
    #[cfg(not(any(target_os = "none", target_family = "wasm")))]
    #[inline(always)]
    pub fn pair_vector_to_b(&self, v: V2<R>) -> V2<R> {
        self.inverse_rotate(v)
    }

    /// A point of B's frame (relative to its reference point) in the pair
    /// frame.
    #[cfg(not(any(target_os = "none", target_family = "wasm")))]
    #[inline(always)]
    pub fn b_to_pair(&self, p: V2<R>) -> V2<R> {
        self.rotate(p) + self.offset
    }

    /// A's support along `d` on its own, with its feature id: contact
    /// manifolds ask each shape for its faces apart from the other.
    pub fn support_a(&self, d: V2<R>) -> (V2<R>, u32) {
        let (p, id) = self.a.support_feature(d.to_glam(), NO_ID);
        (V2::from_glam(p), id)
    }

    /// B's support along `d` (a direction of the pair frame) on its own, in
    /// the pair frame, with its feature id.
    pub fn support_b(&self, d: V2<R>) -> (V2<R>, u32) {
        let (p, id) = self.b.support_feature(self.inverse_rotate(d).to_glam(), NO_ID);
        (self.rotate(V2::from_glam(p)) + self.offset, id)
    }

    /// Whether A's core and B's core are polytopes.
    pub fn polytopes(&self) -> (bool, bool) {
        (self.a.is_polytope(), self.b.is_polytope())
    }

    /// A point of the pair frame in world coordinates.
    pub fn to_world_point(&self, p: V2<R>) -> R::Vector {
        (self.frame.rotate(p + self.reference_a) + self.frame.translation).to_glam()
    }
    /// A direction of the pair frame in world coordinates.
    pub fn to_world_vector(&self, v: V2<R>) -> R::Vector {
        self.frame.rotate(v).to_glam()
    }
}

/// Whether a shape's core is a single point. A disk
/// ([`SupportMap::disk_radius`]) is one by its type, so the compiler drops
/// the question and its pairs link none of GJK's loop. Any other shape is
/// one where its bounding radius, measured from a point of its core, is no
/// more than its radius: another core point would put part of the shape
/// farther out.
#[inline(always)]
fn point_core<R: Real, S: SupportMap<R> + ?Sized>(shape: &S) -> bool {
    shape.disk_radius().is_some() || (shape.radius() > R::ZERO && shape.bounding_radius() <= shape.radius())
}

impl<R: Real, A: SupportMap<R> + ?Sized, B: SupportMap<R> + ?Sized> MinkowskiDifference<R> for Pair<'_, R, A, B> {
    fn support(&self, direction: R::Vector) -> SupportPoint<R> {
        let v = self.support_shared(V2::from_glam(direction));
        SupportPoint { point: v.w.to_glam(), id: v.id }
    }
    #[cfg(not(any(target_os = "none", target_family = "wasm")))]
    #[inline(always)]
    fn support_between(&self, direction: R::Vector, from: u32, to: u32) -> SupportPoint<R> {
        let v = self.support_between(V2::from_glam(direction), from, to);
        SupportPoint { point: v.w.to_glam(), id: v.id }
    }
    #[cfg(not(any(target_os = "none", target_family = "wasm")))]
    #[inline(always)]
    fn is_face(&self, from: u32, to: u32) -> bool {
        Pair::is_face(self, from, to)
    }
    #[cfg(not(any(target_os = "none", target_family = "wasm")))]
    #[inline(always)]
    fn faces_between(&self, from: u32, to: u32, faces: &mut [(SupportPoint<R>, R::Vector)]) -> Option<usize> {
        Pair::faces_between(self, from, to, faces)
    }
    #[cfg(not(any(target_os = "none", target_family = "wasm")))]
    #[inline(always)]
    fn closest_face_between(&self, from: u32, to: u32, max_faces: usize) -> Option<(R, R::Vector)> {
        Pair::closest_face_between(self, from, to, max_faces).map(|(d, normal)| (d, normal.to_glam()))
    }
    fn scale(&self) -> R {
        Pair::scale(self)
    }
    fn is_polytope(&self) -> bool {
        self.a.is_polytope() && self.b.is_polytope()
    }
    fn vertex_bound(&self) -> usize {
        self.a.core_vertex_bound().saturating_add(self.b.core_vertex_bound())
    }
}

/// A's and B's vertex indices in the support id `id`, where both are in
/// range (`n` and `m` vertices); `None` for [`NO_ID`].
#[cfg(not(any(target_os = "none", target_family = "wasm")))]
#[inline(always)]
fn vertex_indices(id: u32, n: usize, m: usize) -> Option<(usize, usize)> {
    let (ia, ib) = ((id >> 16) as usize, (id & 0xFFFF) as usize);
    (id != NO_ID && ia < n && ib < m).then_some((ia, ib))
}

/// The most faces [`Pair::faces_between`] walks.
#[cfg(not(any(target_os = "none", target_family = "wasm")))]
pub const WALKED_FACES_MAX: usize = 9;

/// A polytope core's vertices as the shape lends them (a polygon's, a
/// segment core's), counter-clockwise, indexed by their support ids, in
/// the shape's own frame: a manifold reads two or three of them, so they
/// are placed as read, not copied and placed all at once.
#[cfg(not(any(target_os = "none", target_family = "wasm")))]
#[derive(Clone, Copy)]
pub(crate) enum Corners<'s, R> {
    Polygon(&'s [V2<R>]),
    Segment([V2<R>; 2]),
}

#[cfg(not(any(target_os = "none", target_family = "wasm")))]
impl<'s, R: Real> Corners<'s, R> {
    fn lent<S: SupportMap<R> + ?Sized>(shape: &'s S) -> Option<Self> {
        if let Some(ends) = shape.segment_core() {
            return Some(Self::Segment(ends));
        }
        Some(Self::Polygon(shape.polygon_core()?.vertices))
    }

    pub fn len(&self) -> usize {
        match self {
            Self::Polygon(v) => v.len(),
            Self::Segment(_) => 2,
        }
    }

    /// Vertex `k` in the shape's frame (zero past the end).
    pub fn at(&self, k: usize) -> V2<R> {
        match self {
            Self::Polygon(v) => v.get(k),
            Self::Segment(v) => v.get(k),
        }
        .copied()
        .unwrap_or_default()
    }
}

#[cfg(all(test, not(any(target_os = "none", target_family = "wasm"))))]
mod tests {
    extern crate std;

    use super::{Pair, NO_ID};
    use crate::real::V2;
    use crate::shape::Polygon;
    use crate::transform::Transform;
    use glam::DVec2;

    /// `is_face` against its definition, on integer polygons whose products
    /// are exact: ids one step apart along one polygon's edge, with the
    /// other's vertex its polygon's support (a greatest dot product, ties
    /// included) along that edge's normal of B - A. Every other pair of ids
    /// is no face.
    #[test]
    fn faces_are_the_edges_of_the_difference() {
        let a = Polygon::<f64, 8>::new(&[
            DVec2::new(0.0, 0.0),
            DVec2::new(4.0, 0.0),
            DVec2::new(4.0, 3.0),
            DVec2::new(0.0, 3.0),
        ])
        .unwrap();
        let b = Polygon::<f64, 8>::new(&[
            DVec2::new(0.0, 0.0),
            DVec2::new(2.0, -1.0),
            DVec2::new(4.0, 0.0),
            DVec2::new(3.0, 2.0),
            DVec2::new(1.0, 3.0),
        ])
        .unwrap();
        let (ta, tb) = (Transform::IDENTITY, Transform::from_translation(DVec2::new(1.0, 2.0)).unwrap());
        let pair = Pair::new(&a, &ta, &b, &tb);
        let (va, vb) = pair.polygon_cores().unwrap();
        // B in the pair frame: the translation is exact on these integers.
        let (n, m) = (va.len(), vb.len());
        let mut placed = [V2::zero(); 8];
        for (slot, &p) in placed.iter_mut().zip(vb) {
            *slot = pair.b_to_pair(p);
        }
        let placed = &placed[..m];
        let supports = |v: &[V2<f64>], k: usize, d: V2<f64>| v.iter().all(|p| p.dot(d) <= v[k].dot(d));
        let mut faces = 0;
        for (ia, ib, ja, jb) in (0..n)
            .flat_map(|ia| (0..m).flat_map(move |ib| (0..n).flat_map(move |ja| (0..m).map(move |jb| (ia, ib, ja, jb)))))
        {
            let expected = if ib == jb && ja == (ia + 1) % n {
                supports(placed, ib, -(va[ja] - va[ia]).perp_cw())
            } else if ia == ja && jb == (ib + 1) % m {
                supports(va, ia, -(placed[jb] - placed[ib]).perp_cw())
            } else {
                false
            };
            let (from, to) = (((ia << 16) | ib) as u32, ((ja << 16) | jb) as u32);
            assert_eq!(pair.is_face(from, to), expected, "ids ({ia}, {ib}) to ({ja}, {jb})");
            faces += usize::from(expected);
        }
        // Every edge of B - A once (no edge of B is parallel to one of A's),
        // and ids that are no vertices at all.
        assert_eq!(faces, n + m);
        assert!(!pair.is_face(NO_ID, 1) && !pair.is_face(1, NO_ID));
        assert!(!pair.is_face(((n as u32) << 16) | 1, 1 << 16));

        // The closest face of every stretch of the boundary, against exact
        // distances: the faces are the pairs `is_face` names, their ends
        // integers, and squared distances compare exactly as fractions.
        let id = |(ia, ib): (usize, usize)| ((ia << 16) | ib) as u32;
        let point = |(ia, ib): (usize, usize)| placed[ib] - va[ia];
        let vertices: std::vec::Vec<(usize, usize)> = (0..n).flat_map(|ia| (0..m).map(move |ib| (ia, ib))).collect();
        let after = |v: (usize, usize)| vertices.iter().copied().find(|&w| pair.is_face(id(v), id(w)));
        let mut cycle =
            std::vec![(0..n).flat_map(|ia| (0..m).map(move |ib| (ia, ib))).find(|&v| after(v).is_some()).unwrap()];
        while let Some(next) = after(*cycle.last().unwrap()).filter(|w| *w != cycle[0]) {
            cycle.push(next);
        }
        assert_eq!(cycle.len(), n + m);
        // Twice the area's cross product and the squared length, exact in i128.
        let exact = |k: usize| {
            let (p, q) = (point(cycle[k % cycle.len()]), point(cycle[(k + 1) % cycle.len()]));
            let e = q - p;
            let cross = (e.x as i128) * (-p.y as i128) - (e.y as i128) * (-p.x as i128);
            assert!(cross > 0, "the origin is inside B - A");
            (cross * cross, (e.x as i128).pow(2) + (e.y as i128).pow(2), k)
        };
        let mut settled = 0;
        for start in 0..cycle.len() {
            for count in 1..cycle.len() {
                let (from, to) = (id(cycle[start]), id(cycle[(start + count) % cycle.len()]));
                // A stretch round a whole polygon has ids that cannot say so.
                let steps_a = (start..start + count)
                    .filter(|&k| cycle[k % cycle.len()].0 != cycle[(k + 1) % cycle.len()].0)
                    .count();
                if steps_a >= n || count - steps_a >= m {
                    assert_eq!(pair.closest_face_between(from, to, count), None, "from {start} over {count}");
                    continue;
                }
                let Some((distance, normal)) = pair.closest_face_between(from, to, count) else {
                    panic!("no closest face from {start} over {count}");
                };
                assert_eq!(pair.closest_face_between(from, to, count - 1), None, "too many faces");
                // The least c^2 / l^2, by cross-multiplying.
                let (c2, l2, k) = (start..start + count)
                    .map(exact)
                    .reduce(|best, f| if f.0 * best.1 < best.0 * f.1 { f } else { best })
                    .unwrap();
                let expected = ((c2 as f64) / (l2 as f64)).sqrt();
                assert!(
                    (distance - expected).abs() <= 1e-12,
                    "from {start} over {count}: {distance} against {expected}"
                );
                let e = point(cycle[(k + 1) % cycle.len()]) - point(cycle[k % cycle.len()]);
                let outward = e.perp_cw() * (1.0 / e.length());
                assert!((normal - outward).length() <= 1e-12, "from {start} over {count}: normal of face {k}");
                settled += 1;
            }
        }
        assert!(settled >= 4 * cycle.len(), "{settled} stretches settled");
    }
}
