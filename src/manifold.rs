//! Contact manifolds: the points at which a pair touches, overlaps, or
//! comes within a margin of touching, for a physics step's contact solver.
//!
//! Given the normal `n` (from A towards B) of the distance or penetration
//! query, each shape offers the part of its boundary that faces the other
//! ([`Side`]): a face (an edge of the core, moved out by the radius) where
//! the core is a polytope and one of its edges at the support vertex faces
//! `n` closely enough, else the single support point. Seen along `n`, both
//! parts cover an interval of the tangent line; the contact points are the
//! ends of the two intervals' overlap, each paired with the other shape's
//! boundary straight across along `n`.
//!
//! This is reference-face clipping (Box2D's `b2CollidePolygons`) with the
//! clip lines at right angles to `n` instead of to one of the faces: no face
//! has to be chosen as the reference (nor kept chosen for the ids to stay),
//! every point lies on both boundaries, and the closest (or deepest) pair of
//! points, which lies in both faces, is always within the overlap, so the
//! least separation is the query's. Where `n` is only iterated to a
//! tolerance (curved shapes) and a point straight across a tilted face
//! would miss that pair by more than rounding, the two support points are
//! the deepest point instead: on both boundaries to second order in the
//! normal's error.
//!
//! All in the pair frame (A's frame, relative to its reference point), as
//! every query works: shapes far from the origin keep their precision.

use crate::minkowski::Pair;
use crate::real::{Real, V2};
use crate::result::{ContactPoint, Feature, FeatureId, Manifold};
use crate::shape::{SupportMap, NO_FEATURE};

/// Steps of the search for a vertex's neighbour, at most. Each step finds a
/// vertex between the two it has, usually halfway, so a polygon of any size
/// needs far fewer; the bound stops a support function whose answers do not
/// agree with each other.
const MAX_STEPS: u32 = 64;

/// A support id as a vertex; ids that do not fit 16 bits (a point on a
/// curve) as the curve.
fn vertex(id: u32) -> Feature {
    if id < 0xFFFF {
        Feature::Vertex(id as u16)
    } else {
        Feature::Curve
    }
}

fn edge(start: u32) -> Feature {
    if start < 0xFFFF {
        Feature::Edge(start as u16)
    } else {
        Feature::Curve
    }
}

/// An edge of a core at its support vertex.
#[derive(Clone, Copy)]
struct Face<R> {
    /// The edge's other vertex, and its id.
    other: V2<R>,
    other_id: u32,
    /// Unit outward normal.
    normal: V2<R>,
    /// Whether the edge runs counter-clockwise from the support vertex to
    /// `other` (else from `other` to it).
    ccw: bool,
}

/// One end of a side's interval along the tangent: a point on the shape's
/// boundary, and the feature it belongs to.
#[derive(Clone, Copy)]
struct End<R> {
    point: V2<R>,
    id: Feature,
}

/// The part of a shape's boundary that faces the other shape.
struct Side<R> {
    /// Unit direction towards the other shape: `n` for A, `-n` for B.
    facing: V2<R>,
    radius: R,
    /// The core's support point along `facing`.
    support: V2<R>,
    support_id: u32,
    face: Option<Face<R>>,
}

impl<R: Real> Side<R> {
    /// The side of a shape given by its support function: the edge at the
    /// support vertex whose normal is nearest `facing`, if within 60
    /// degrees of it (a steeper edge is only met at its corner, which is
    /// then the one point), for polytope cores.
    /// `lent` gives the edge at a vertex (by id, either way round) where
    /// the core's vertices are at hand, `None` where they are not.
    fn new(
        support: impl Fn(V2<R>) -> (V2<R>, u32),
        facing: V2<R>,
        radius: R,
        polytope: bool,
        lent: impl Fn(u32, bool) -> Option<Option<Face<R>>>,
    ) -> Self {
        let (v, id) = support(facing);
        let mut side = Self { facing, radius, support: v, support_id: id, face: None };
        if !polytope || id == NO_FEATURE {
            return side;
        }
        let mut best = R::HALF;
        // Off bare metal, the faces lent on both sides (their runs of
        // vertices on one line already walked), counter-clockwise first.
        #[cfg(not(any(target_os = "none", target_family = "wasm")))]
        let mut lent_faces = [None, None];
        for ccw in [true, false] {
            let lent_face = lent(id, ccw);
            #[cfg(not(any(target_os = "none", target_family = "wasm")))]
            {
                lent_faces[usize::from(!ccw)] = lent_face;
            }
            if let Some(face) = lent_face.unwrap_or_else(|| neighbour(&support, v, id, facing, ccw)) {
                let cos = face.normal.dot(facing);
                if cos > best {
                    best = cos;
                    side.face = Some(face);
                }
            }
        }
        // A polygon may have vertices on an edge: the face is the whole
        // edge, its ends the last vertices on its line either way. Looked
        // for only where the face is within 2.5 degrees of `facing`, as in
        // resting contact, where both ends matter: a steeper face meets the
        // other at its support vertex, and the search costs a support at
        // each end. (The support vertex can only move when the face is
        // exactly at right angles: a vertex beyond it on the line would be
        // farther along `facing`.)
        let flat = R::ONE - R::ONE / R::from_u32(1024);
        if let Some(face) = side.face.as_mut().filter(|face| face.normal.dot(facing) >= flat) {
            // The vertices at hand: the face's run was walked, and the
            // support moves back to the other side's run's end where that
            // lies on the face's line, as `along_line` would find it with a
            // support.
            #[cfg(not(any(target_os = "none", target_family = "wasm")))]
            if let Some(back) = lent_faces[usize::from(face.ccw)] {
                if let Some(back) = back.filter(|back| beyond_on_line(face.other, v, back.other)) {
                    (side.support, side.support_id) = (back.other, back.other_id);
                }
                return side;
            }
            (face.other, face.other_id) = along_line(&support, v, (face.other, face.other_id), face.normal);
            (side.support, side.support_id) = along_line(&support, face.other, (v, id), face.normal);
        }
        side
    }

    /// The edge's feature: named by the vertex it starts from.
    fn edge(&self, face: &Face<R>) -> Feature {
        edge(if face.ccw { self.support_id } else { face.other_id })
    }

    /// The feature that faces the other shape: the face when it is flat to
    /// `facing` (within 2.5 degrees, as [`new`](Self::new) looks for a
    /// face's far end), else the support vertex (or the curve).
    fn facing_feature(&self) -> Feature {
        let flat = R::ONE - R::ONE / R::from_u32(1024);
        match self.face.filter(|face| face.normal.dot(self.facing) >= flat) {
            Some(face) => self.edge(&face),
            None => vertex(self.support_id),
        }
    }

    /// The ends of the side along the tangent: the support point, and the
    /// far end of the face's flat side.
    fn ends(&self) -> (End<R>, Option<End<R>>) {
        let near = End { point: self.support + self.facing * self.radius, id: vertex(self.support_id) };
        let far = self.face.map(|f| End { point: f.other + f.normal * self.radius, id: vertex(f.other_id) });
        (near, far)
    }

    /// How far from `x` along `facing` the side's boundary is, on the line
    /// through `x` along the normal, and the feature it meets there: the
    /// highest of the flat side and the arcs around its vertices.
    fn reach(&self, x: V2<R>) -> (R, Feature) {
        let f = self.facing;
        let r = self.radius;
        let mut best: Option<(R, Feature)> = None;
        let mut keep = |mu: R, id: Feature| {
            if best.is_none_or(|(b, _)| mu > b) {
                best = Some((mu, id));
            }
        };
        // The flat side from `p0` by `e`, met where `x + mu f = p0 + nu e`.
        // A face at most 60 degrees from `facing` is never parallel to it,
        // but an edge too short for its cross product (subnormal) is no face.
        let flat = self.face.and_then(|face| {
            let p0 = self.support + face.normal * r;
            let e = face.other + face.normal * r - p0;
            let across = f.cross(e);
            let (mu, nu) = ((p0 - x).cross(e) / across, (p0 - x).cross(f) / across);
            (across != R::ZERO).then_some((p0, e, mu, nu, self.edge(&face)))
        });
        if let Some((_, _, mu, nu, id)) = flat {
            if nu >= R::ZERO && nu <= R::ONE {
                keep(mu, id);
            }
        }
        if r > R::ZERO {
            let other = self.face.map(|face| (face.other, vertex(face.other_id)));
            for (c, id) in [Some((self.support, vertex(self.support_id))), other].into_iter().flatten() {
                let w = x - c;
                let h = w.cross(f);
                if h * h <= r * r {
                    keep((r * r - h * h).sqrt() - w.dot(f), id);
                }
            }
        }
        // Off every piece by rounding only (the overlap keeps `x` within
        // the side's interval): the nearest end of the flat side, or the
        // support point.
        best.unwrap_or_else(|| match flat {
            Some((p0, e, _, nu, id)) => ((p0 + e * nu.max(R::ZERO).min(R::ONE) - x).dot(f), id),
            None => ((self.support + f * r - x).dot(f), vertex(self.support_id)),
        })
    }
}

/// The edge at `v` (support vertex of id `id` along `facing`) on its
/// counter-clockwise (`ccw`) or clockwise side: gift wrapping with the
/// support function alone. The support a quarter turn round is a vertex on
/// that side; the support along the normal of the chord to it is a vertex
/// beyond the chord, between the two, until none is: then the chord is the
/// edge. `None` when `v` is also the support a quarter turn round (its
/// edge on that side faces away) or the ids leave the polytope.
fn neighbour<R: Real>(
    support: &impl Fn(V2<R>) -> (V2<R>, u32),
    v: V2<R>,
    id: u32,
    facing: V2<R>,
    ccw: bool,
) -> Option<Face<R>> {
    let chord = |w: V2<R>| if ccw { w - v } else { v - w };
    let (mut w, mut wid) = support(if ccw { facing.perp() } else { facing.perp_cw() });
    for _ in 0..MAX_STEPS {
        if wid == id || wid == NO_FEATURE {
            return None;
        }
        let normal = chord(w).perp_cw();
        let (q, qid) = support(normal);
        if qid == wid || qid == id || qid == NO_FEATURE || (q - w).dot(normal) <= R::ZERO {
            break;
        }
        (w, wid) = (q, qid);
    }
    let normal = chord(w).perp_cw().try_normalize()?;
    Some(Face { other: w, other_id: wid, normal, ccw })
}

/// The edge at vertex `id` of a core whose vertices are at hand, on its
/// counter-clockwise (`ccw`) or clockwise side: the next vertex that way,
/// or the last of a run of them on one line (within `4 eps` of its length,
/// as [`along_line`] takes them), so that the face is the whole edge.
#[cfg(not(any(target_os = "none", target_family = "wasm")))]
fn lent_face<R: Real>(n: usize, at: impl Fn(usize) -> V2<R>, id: u32, ccw: bool) -> Option<Face<R>> {
    let i = id as usize;
    if i >= n || n < 2 {
        return None;
    }
    let step = |k: usize| {
        if ccw {
            if k + 1 == n {
                0
            } else {
                k + 1
            }
        } else if k == 0 {
            n - 1
        } else {
            k - 1
        }
    };
    let v = at(i);
    let mut j = step(i);
    for _ in 0..n {
        let k = step(j);
        let (e, f) = (at(j) - v, at(k) - v);
        let slack = R::from_u32(4) * R::EPSILON * e.length_squared().max(f.length_squared());
        if k == i || e.cross(f).abs() > slack || e.dot(f) <= e.length_squared() {
            break;
        }
        j = k;
    }
    let w = at(j);
    let chord = if ccw { w - v } else { v - w };
    let normal = chord.perp_cw().try_normalize()?;
    Some(Face { other: w, other_id: j as u32, normal, ccw })
}

/// The last vertex on the line from `from` through `end` (with its id),
/// beyond `end`: the support along the face's `normal` turned a little
/// (1/1024) towards that side, which among the vertices on the line is the
/// farthest along it. Kept if it lies on the line to rounding (within
/// `4 eps` of its length: a bend that small moves no point off the
/// boundary by more); a next face that turns by less than the tilt is
/// not followed.
fn along_line<R: Real>(
    support: &impl Fn(V2<R>) -> (V2<R>, u32),
    from: V2<R>,
    end: (V2<R>, u32),
    normal: V2<R>,
) -> (V2<R>, u32) {
    let e = end.0 - from;
    let Some(onward) = e.try_normalize() else { return end };
    let (q, qid) = support(normal + onward * (R::ONE / R::from_u32(1024)));
    // `beyond_on_line`'s test, written out: the manifold is the deepest
    // query on a microcontroller's small stack, and a call here would add
    // a frame to it.
    let f = q - from;
    let slack = R::from_u32(4) * R::EPSILON * e.length_squared().max(f.length_squared());
    if qid == end.1 || qid == NO_FEATURE || e.cross(f).abs() > slack || e.dot(f) <= e.length_squared() {
        return end;
    }
    (q, qid)
}

/// Whether `q` lies on the line from `from` through `end`, beyond `end`:
/// within `4 eps` of the longer offset's length of it (a bend that small
/// moves no point off the boundary by more).
#[cfg(not(any(target_os = "none", target_family = "wasm")))]
#[inline(always)]
fn beyond_on_line<R: Real>(from: V2<R>, end: V2<R>, q: V2<R>) -> bool {
    let (e, f) = (end - from, q - from);
    let slack = R::from_u32(4) * R::EPSILON * e.length_squared().max(f.length_squared());
    e.cross(f).abs() <= slack && e.dot(f) > e.length_squared()
}

/// The manifold's points of a pair whose normal (in the pair frame, from A
/// towards B) the distance or penetration query gave: those whose
/// separation is at most `margin`, added to `out`.
pub(crate) fn contact_points<R, A, B>(pair: &Pair<'_, R, A, B>, normal: V2<R>, margin: R, out: &mut Manifold<R>)
where
    R: Real,
    A: SupportMap<R> + ?Sized,
    B: SupportMap<R> + ?Sized,
{
    let (a, b) = sides(pair, normal);
    let tangent = normal.perp();
    let along = |e: &End<R>| e.point.dot(tangent);
    // Each side's interval, its lower end first; then the overlap, the
    // source of each end (true for A) kept.
    let interval = |side: &Side<R>| {
        let (near, far) = side.ends();
        match far {
            Some(far) if along(&far) < along(&near) => (far, near),
            Some(far) => (near, far),
            None => (near, near),
        }
    };
    let ((a_lo, a_hi), (b_lo, b_hi)) = (interval(&a), interval(&b));
    let lo = if along(&b_lo) > along(&a_lo) { (b_lo, false) } else { (a_lo, true) };
    let hi = if along(&b_hi) < along(&a_hi) { (b_hi, false) } else { (a_hi, true) };
    // An end of one side, paired with the other side's boundary across.
    let across = |(end, from_a): (End<R>, bool)| {
        if from_a {
            let (mu, id) = b.reach(end.point);
            (end.point, -mu, FeatureId { a: end.id, b: id })
        } else {
            let (mu, id) = a.reach(end.point);
            (end.point + normal * mu, -mu, FeatureId { a: id, b: end.id })
        }
    };
    // The support points: their gap along the normal is the least any two
    // points straight across can have, and to second order in the normal's
    // error the query's separation.
    let (sa, sb) = (a.ends().0, b.ends().0);
    let supports = (sa.point, (sb.point - sa.point).dot(normal), FeatureId { a: sa.id, b: sb.id });
    let (l, h) = (along(&lo.0), along(&hi.0));
    // Ends closer than rounding are one point (two supports straight
    // across from each other, their faces turning apart).
    let rounding = R::from_u32(16) * R::EPSILON * (l.abs().max(h.abs()) + pair.scale());
    let mut points = if h - l > rounding {
        [Some(across(lo)), Some(across(hi))]
    } else if l <= h {
        [Some(across(lo)), None]
    } else {
        // No overlap, by rounding only: the closest (or deepest) pair.
        [Some(supports), None]
    };
    // A normal off by `e` (a curved shape's, iterated to a tolerance) moves
    // a point straight across a tilted face by `e` times the reach, and its
    // separation with it: the deepest point is then the supports' pair,
    // whose separation is off by `e` squared.
    let deepest = if points[1].is_some_and(|q| points[0].is_none_or(|p| q.1 < p.1)) { 1 } else { 0 };
    if points[deepest].is_some_and(|p| p.1 - supports.1 > rounding) {
        points[deepest] = Some(supports);
    }
    for (point, separation, id) in points.into_iter().flatten() {
        if separation <= margin {
            out.push(ContactPoint { point: pair.to_world_point(point), separation, id });
        }
    }
}

/// The features of A and B that face each other along `normal` (in the pair
/// frame, from A towards B): each shape's face flat to it, or its support
/// vertex, as the manifold names them.
pub(crate) fn facing_features<R, A, B>(pair: &Pair<'_, R, A, B>, normal: V2<R>) -> FeatureId
where
    R: Real,
    A: SupportMap<R> + ?Sized,
    B: SupportMap<R> + ?Sized,
{
    let (a, b) = sides(pair, normal);
    FeatureId { a: a.facing_feature(), b: b.facing_feature() }
}

/// The sides of A and B that face each other along `normal` (in the pair
/// frame, from A towards B).
#[inline(always)]
fn sides<R, A, B>(pair: &Pair<'_, R, A, B>, normal: V2<R>) -> (Side<R>, Side<R>)
where
    R: Real,
    A: SupportMap<R> + ?Sized,
    B: SupportMap<R> + ?Sized,
{
    let (polytope_a, polytope_b) = pair.polytopes();
    #[cfg(not(any(target_os = "none", target_family = "wasm")))]
    let (corners_a, corners_b) = (pair.corners_a(), pair.corners_b());
    #[cfg(not(any(target_os = "none", target_family = "wasm")))]
    let (lent_a, lent_b) = (
        |id: u32, ccw: bool| corners_a.as_ref().map(|c| lent_face(c.len(), |k| c.at(k), id, ccw)),
        |id: u32, ccw: bool| corners_b.as_ref().map(|c| lent_face(c.len(), |k| pair.b_to_pair(c.at(k)), id, ccw)),
    );
    #[cfg(any(target_os = "none", target_family = "wasm"))]
    let (lent_a, lent_b) = (|_: u32, _: bool| None, |_: u32, _: bool| None);
    let a = Side::new(|d| pair.support_a(d), normal, pair.radius_a(), polytope_a, lent_a);
    let b = Side::new(|d| pair.support_b(d), -normal, pair.radius_b(), polytope_b, lent_b);
    (a, b)
}
