//! The GJK simplex (at most a triangle in 2D) and the closest point of it
//! to the origin.
//!
//! Closest points are computed in the form that keeps the most precision: on
//! an edge, `v = n (n . w1) / (n . n)` with `n` perpendicular to the edge, so
//! `v` is exactly normal to the edge's direction and no `w1 + t (w2 - w1)`
//! cancellation is spent on it; `w1` is the end nearer the origin, so the
//! product rounds at the near end's magnitude, not at the far one's.
//!
//! The simplex is generic over what each vertex carries besides its point
//! and id: the intersection test carries nothing (`()`), the distance query
//! the shape points it needs for closest points ([`Witness`]), so the
//! test's simplex is as small and as quick to copy as it can be.

use crate::minkowski::{MinkowskiVertex, NO_ID};
use crate::real::{Real, V2};

/// What a simplex vertex carries besides its Minkowski point.
pub(crate) trait Payload<R>: Copy + Default {
    fn from_vertex(v: &MinkowskiVertex<R>) -> Self;
    /// The vertex's barycentric weight in the closest point: kept only where
    /// closest points are wanted, so the other queries neither store nor
    /// compute it.
    fn set_weight(&mut self, weight: R);
    /// Whether [`Simplex::solve`] is one shared copy rather than inlined
    /// at each call (on bare metal, whose flash is scarce; hosts always
    /// inline it, for speed).
    const SHARED_SOLVE: bool;
}

impl<R> Payload<R> for () {
    #[inline(always)]
    fn from_vertex(_: &MinkowskiVertex<R>) -> Self {}
    #[inline(always)]
    fn set_weight(&mut self, _: R) {}
    /// Only the intersection test carries nothing: its loop is the fastest
    /// query, and a firmware has one copy of it.
    const SHARED_SOLVE: bool = false;
}

/// The shape points a Minkowski point is the difference of, and its weight
/// in the closest point.
#[derive(Clone, Copy, Debug, Default)]
pub(crate) struct Witness<R> {
    pub a: V2<R>,
    pub b: V2<R>,
    pub weight: R,
}

impl<R: Real> Payload<R> for Witness<R> {
    #[inline(always)]
    fn from_vertex(v: &MinkowskiVertex<R>) -> Self {
        Witness { a: v.a, b: v.b, weight: R::ONE }
    }
    #[inline(always)]
    fn set_weight(&mut self, weight: R) {
        self.weight = weight;
    }
    /// GJK distance and the GJK ray cast both solve this simplex: one
    /// copy then serves both, and a firmware that calls it from one place
    /// still gets it inlined.
    const SHARED_SOLVE: bool = true;
}

#[derive(Clone, Copy, Debug)]
pub(crate) struct Vertex<R, P> {
    pub w: V2<R>,
    pub id: u32,
    pub payload: P,
}

impl<R: Real, P: Payload<R>> Vertex<R, P> {
    #[inline(always)]
    pub fn from_minkowski(v: &MinkowskiVertex<R>) -> Self {
        Self { w: v.w, id: v.id, payload: P::from_vertex(v) }
    }
}

#[derive(Clone, Copy, Debug)]
pub(crate) struct Simplex<R, P> {
    verts: [Vertex<R, P>; 3],
    len: usize,
}

/// Where the origin is relative to the simplex.
pub(crate) enum Closest<R> {
    /// The closest point of the simplex (the simplex reduced to its support).
    Point(V2<R>),
    /// The origin lies inside the triangle or on its boundary.
    Enclosed,
}

impl<R: Real, P: Payload<R>> Simplex<R, P> {
    pub fn new(first: Vertex<R, P>) -> Self {
        let free = Vertex { id: NO_ID, ..first };
        Self { verts: [first, free, free], len: 1 }
    }

    /// No vertex yet, the slots holding copies of `filler`: all zeros
    /// would be a call to `memclr` on bare metal.
    pub fn empty_like(filler: Vertex<R, P>) -> Self {
        let free = Vertex { id: NO_ID, ..filler };
        Self { verts: [free, free, free], len: 0 }
    }

    /// No vertex yet: for a loop whose one support call fills it.
    pub fn empty() -> Self {
        Self::empty_like(Vertex { w: V2::zero(), id: NO_ID, payload: P::default() })
    }

    /// All three slots and how many of them are vertices.
    pub fn slots(&self) -> (&[Vertex<R, P>; 3], usize) {
        (&self.verts, self.len)
    }

    /// The ids of the vertices, [`NO_ID`] for empty slots (which always
    /// hold it): what the loops compare new supports against.
    pub fn ids(&self) -> [u32; 3] {
        let [p, q, r] = &self.verts;
        [p.id, q.id, r.id]
    }

    /// Appends a vertex; a full simplex (which the loops never push to)
    /// replaces its last one.
    pub fn push(&mut self, v: Vertex<R, P>) {
        let i = self.len.min(2);
        if let Some(slot) = self.verts.get_mut(i) {
            *slot = v;
        }
        self.len = i + 1;
    }

    /// Reduces the simplex to the smallest face holding the closest point to
    /// the origin, and returns that point. The geometry is the same for
    /// every payload ([`closest_face`]); only keeping the face is not.
    #[inline(always)]
    pub fn solve(&mut self) -> Closest<R> {
        if P::SHARED_SOLVE {
            self.solve_shared()
        } else {
            self.solve_inline()
        }
    }

    /// No inline hint on bare metal, whose flash is scarce: the compiler
    /// inlines a function called from one place, and keeps one copy for
    /// several.
    #[cfg_attr(not(target_os = "none"), inline)]
    fn solve_shared(&mut self) -> Closest<R> {
        self.solve_inline()
    }

    #[inline]
    fn solve_inline(&mut self) -> Closest<R> {
        // The points by value, in registers: an array in memory, for a
        // reference, takes more code to fill and read.
        let [p, q, r] = &self.verts;
        let face = closest_face([p.w, q.w, r.w], self.len);
        self.keep(face)
    }

    #[inline(always)]
    fn keep(&mut self, face: Face<R>) -> Closest<R> {
        match face {
            Face::Enclosed => Closest::Enclosed,
            Face::Vertex(i, v) => {
                self.keep_one(i);
                Closest::Point(v)
            }
            Face::Edge { edge, weights, v } => {
                self.keep_edge(edge, weights);
                Closest::Point(v)
            }
        }
    }

    /// Keeps edge `verts[i]`-`verts[j]` in slots 0 and 1, with the closest
    /// point's weights `first / sum` (for `i`) and `second / sum` (for `j`).
    #[inline(always)]
    fn keep_edge(&mut self, (i, j): (usize, usize), Weights { first, second, sum }: Weights<R>) {
        // The vertex left out gets the third's place, copied from a constant
        // slot so that no `memmove` is linked; the edge may come out
        // reversed, which nothing downstream minds.
        let (slot_0, slot_1) = match (i, j) {
            (1, 2) => {
                self.verts[0] = self.verts[2];
                (second, first)
            }
            (2, 0) => {
                self.verts[1] = self.verts[2];
                (second, first)
            }
            _ => (first, second),
        };
        // Divided, not multiplied by 1/sum: 1/sum overflows for a subnormal
        // sum (coordinates near 1e-154 in f64).
        self.verts[0].payload.set_weight(slot_0 / sum);
        self.verts[1].payload.set_weight(slot_1 / sum);
        self.verts[2].id = NO_ID;
        self.len = 2;
    }

    #[inline(always)]
    fn keep_one(&mut self, i: usize) {
        match i {
            1 => self.verts[0] = self.verts[1],
            2 => self.verts[0] = self.verts[2],
            _ => {}
        }
        self.verts[0].payload.set_weight(R::ONE);
        self.verts[1].id = NO_ID;
        self.verts[2].id = NO_ID;
        self.len = 1;
    }
}

impl<R: Real> Simplex<R, Witness<R>> {
    /// The closest point's pre-images on A and B (pair frame).
    ///
    /// After a reduction that found a closest point, the simplex has one
    /// vertex or two (three enclose the origin).
    pub fn witness_points(&self) -> (V2<R>, V2<R>) {
        let [p, q, _] = &self.verts;
        // Sums from zero: a -0 comes out +0.
        let pa = V2::zero() + p.payload.a * p.payload.weight;
        let pb = V2::zero() + p.payload.b * p.payload.weight;
        if self.len == 2 {
            return (pa + q.payload.a * q.payload.weight, pb + q.payload.b * q.payload.weight);
        }
        (pa, pb)
    }

    /// Measures every vertex again from `x`: the GJK ray cast's vertices
    /// are `x - p` for shape points `p` (kept as `b`), and `x` moves along
    /// the ray. The simplex is kept and re-measured rather than rebuilt.
    pub fn measure_from(&mut self, x: V2<R>) {
        for v in self.verts.iter_mut().take(self.len) {
            v.w = x - v.payload.b;
        }
    }
}

impl<R: Real, P> Simplex<R, P> {
    /// Distance from the origin to the simplex's closest point `v` and the
    /// unit normal towards it, in the most precise form for the face it
    /// lies on. `toward` (B's center minus A's) orients the normal where the edge's
    /// distance is within rounding of zero (64 eps of its ends' size, |x| +
    /// |y|) and its sign says nothing: convex shapes apart or touching have
    /// their centers on either side of the line between them, so `toward`
    /// points the normal's way. (An edge of an ellipse and a polygon passing
    /// within rounding of the origin took its sign from rounding, and gave
    /// the normal from B towards A.)
    #[cfg_attr(not(target_os = "none"), inline(always))]
    pub fn distance_and_normal(&self, v: V2<R>, toward: V2<R>) -> Option<(R, V2<R>)> {
        if self.len == 2 {
            let [p, q, _] = &self.verts;
            // Normalised componentwise (try_normalize), an axis-aligned
            // normal comes out as exactly (0, +-1) or (+-1, 0), so axis-aligned
            // contacts give exact distances (a touching pair gives exactly 0).
            if let Some(unit) = (q.w - p.w).perp().try_normalize() {
                // From the end nearer the origin: a far end's product
                // rounds at its own magnitude. (Not `unit . v`: an
                // axis-aligned edge's exact distance would round.)
                let near = if p.w.length_squared() <= q.w.length_squared() { p.w } else { q.w };
                let signed = unit.dot(near);
                let size = p.w.x.abs() + p.w.y.abs() + q.w.x.abs() + q.w.y.abs();
                let rounding = R::from_u32(64) * R::EPSILON * size;
                let outward = if signed.abs() <= rounding { unit.dot(toward) >= R::ZERO } else { signed > R::ZERO };
                return if outward { Some((signed, unit)) } else { Some((-signed, -unit)) };
            }
        }
        v.try_length_and_unit()
    }
}

/// The face of a simplex that holds its closest point to the origin.
enum Face<R> {
    /// The origin lies inside the triangle or on its boundary.
    Enclosed,
    /// Vertex `i` alone, which is the closest point.
    Vertex(usize, V2<R>),
    /// Strictly inside the edge between vertices `edge.0` and `edge.1`.
    Edge { edge: (usize, usize), weights: Weights<R>, v: V2<R> },
}

/// Barycentric weights of an edge's ends in its closest point, as
/// `first / sum` and `second / sum`.
#[derive(Clone, Copy, Debug)]
struct Weights<R> {
    first: R,
    second: R,
    sum: R,
}

/// The face of the first `len` of `w` (1 to 3 points) holding the closest
/// point to the origin, and that point.
///
/// Only a dispatch: the geometry it calls ([`segment_foot`],
/// [`closest_triangle_edge`]) is one out-of-line copy on bare metal, shared
/// by every payload, since a microcontroller's flash is scarce. The
/// dispatch itself is left to the compiler there, which inlines it into
/// each GJK loop, where it is smaller than a call. Hosts inline it
/// everywhere for speed.
#[cfg_attr(target_os = "none", inline)]
#[cfg_attr(not(target_os = "none"), inline(always))]
fn closest_face<R: Real>(w: [V2<R>; 3], len: usize) -> Face<R> {
    let (edge, foot) = match len {
        2 => ((0, 1), segment_foot(w[0], w[1])),
        3 => match closest_triangle_edge(w[0], w[1], w[2]) {
            Some(closest) => closest,
            None => return Face::Enclosed,
        },
        _ => return Face::Vertex(0, w[0]),
    };
    face_of(edge, foot)
}

/// An edge (its vertex indices) and the foot of the origin on it.
type EdgeFoot<R> = ((usize, usize), (Foot<R>, V2<R>));

/// The edge of triangle `w` holding its closest point to the origin, and
/// the foot on it; `None` when the triangle encloses the origin (the
/// boundary counts: touching).
///
/// Out of line on bare metal in f32, so the GJK loop that calls it keeps a
/// small frame on a microcontroller's small stack; inlined where the
/// scalar asks for flat frames (`FLAT_GJK`, in `real.rs`).
#[inline(always)]
fn closest_triangle_edge<R: Real>(wa: V2<R>, wb: V2<R>, wc: V2<R>) -> Option<EdgeFoot<R>> {
    if R::FLAT_GJK {
        triangle_edge_body(wa, wb, wc)
    } else {
        triangle_edge_nested(wa, wb, wc)
    }
}

#[cfg_attr(target_os = "none", inline(never))]
#[cfg_attr(not(target_os = "none"), inline(always))]
fn triangle_edge_nested<R: Real>(wa: V2<R>, wb: V2<R>, wc: V2<R>) -> Option<EdgeFoot<R>> {
    triangle_edge_body(wa, wb, wc)
}

#[inline(always)]
fn triangle_edge_body<R: Real>(wa: V2<R>, wb: V2<R>, wc: V2<R>) -> Option<EdgeFoot<R>> {
    let w = [wa, wb, wc];
    let area = (wb - wa).cross(wc - wa);
    // The origin is on the inner side of edge i->j when cross(wi, wj)
    // has the sign of the area (zero counts as inside: touching).
    let sides = [wa.cross(wb), wb.cross(wc), wc.cross(wa)];
    // Each side's verdict once, for both the enclosure test and the edge loop.
    let outside = sides.map(|side| {
        if area > R::ZERO {
            side < R::ZERO
        } else if area < R::ZERO {
            side > R::ZERO
        } else {
            true
        }
    });
    // A flat triangle (area zero) has every side outside: never enclosing.
    if !outside.contains(&true) {
        return None;
    }
    // The closest point lies on an edge the origin is outside of; a
    // degenerate (flat) triangle tries all three.
    const EDGES: [(usize, usize); 3] = [(0, 1), (1, 2), (2, 0)];
    let mut best: Option<(EdgeFoot<R>, R)> = None;
    for (&edge, &outside) in EDGES.iter().zip(outside.iter()) {
        if outside {
            let foot = segment_foot(w[edge.0], w[edge.1]);
            let vv = foot.1.length_squared();
            if best.as_ref().is_none_or(|b| vv < b.1) {
                best = Some(((edge, foot), vv));
            }
        }
    }
    best.map(|b| b.0)
}

/// The face that a foot on the edge between vertices `i` and `j` lies on.
#[inline(always)]
fn face_of<R: Real>((i, j): (usize, usize), foot: (Foot<R>, V2<R>)) -> Face<R> {
    match foot {
        (Foot::AtFirst, v) => Face::Vertex(i, v),
        (Foot::AtSecond, v) => Face::Vertex(j, v),
        (Foot::Between(weights), v) => Face::Edge { edge: (i, j), weights, v },
    }
}

/// Where the closest point of a segment to the origin lies.
#[derive(Clone, Copy, Debug)]
enum Foot<R> {
    AtFirst,
    AtSecond,
    /// Strictly inside, with these weights.
    Between(Weights<R>),
}

/// The closest point of segment `p`-`q` to the origin and where it lies.
/// Inside, it is `n (n . p) / (n . n)` with `n` normal to the edge (no
/// `p + t (q - p)` cancellation). An edge so short its squared length
/// underflows, or weights that would be 0 * inf (coordinates below 1e-19 in
/// f32), keep the nearer end: as good as rounding allows.
///
/// Out of line on bare metal in f32, so the triangle's unrolled loop and
/// the segment share one copy of a microcontroller's scarce flash; inlined
/// where the scalar asks for flat frames (`FLAT_GJK`, in `real.rs`) and on
/// hosts, for speed.
#[inline(always)]
fn segment_foot<R: Real>(p: V2<R>, q: V2<R>) -> (Foot<R>, V2<R>) {
    if R::FLAT_GJK {
        segment_foot_body(p, q)
    } else {
        segment_foot_nested(p, q)
    }
}

#[cfg_attr(target_os = "none", inline(never))]
#[cfg_attr(not(target_os = "none"), inline)]
fn segment_foot_nested<R: Real>(p: V2<R>, q: V2<R>) -> (Foot<R>, V2<R>) {
    segment_foot_body(p, q)
}

#[inline(always)]
fn segment_foot_body<R: Real>(p: V2<R>, q: V2<R>) -> (Foot<R>, V2<R>) {
    let e = q - p;
    let toward_q = -p.dot(e);
    let toward_p = q.dot(e);
    let n = e.perp();
    let nn = n.length_squared();
    let p_nearer = p.length_squared() <= q.length_squared();
    let degenerate = nn <= R::ZERO;
    if toward_q <= R::ZERO || (degenerate && p_nearer) {
        return (Foot::AtFirst, p);
    }
    if toward_p <= R::ZERO || degenerate {
        return (Foot::AtSecond, q);
    }
    let sum = toward_q + toward_p;
    if !(sum > R::ZERO && sum.is_finite()) {
        return if p_nearer { (Foot::AtFirst, p) } else { (Foot::AtSecond, q) };
    }
    // From the end nearer the origin: `n . p` cancels to the edge's small
    // distance, and a far end rounds at its own magnitude. Both products
    // first, then the choice, which waits on the lengths: GJK's next step
    // waits on this foot.
    let (from_p, from_q) = (n.dot(p), n.dot(q));
    let offset = if p_nearer { from_p } else { from_q };
    (Foot::Between(Weights { first: toward_p, second: toward_q, sum }), n * (offset / nn))
}
