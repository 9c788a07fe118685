//! The penetration of two polygon cores started without GJK: the supports
//! of their difference along the centers' offset, square to it both ways
//! and against it. The four are independent, so the processor looks them
//! up side by side, where GJK's iterations wait on one another; most pairs
//! that overlap have a difference that encloses the origin in them (then
//! the solver starts from the four), and most pairs apart are apart along
//! the first (then there is no penetration).
//!
//! Host only, as the other closed forms: a firmware keeps its code.

use crate::minkowski::{MinkowskiVertex, Pair, SupportPoint};
use crate::real::{Real, V2};
use crate::shape::SupportMap;

/// What the four supports decided.
pub(crate) enum QuadStart<R: Real> {
    /// The cores are apart by more than rounding and have no radius: no
    /// penetration (GJK would find the same separating plane or a better one).
    Apart,
    /// The four supports, counter-clockwise, enclose the origin by more than
    /// rounding: the penetration solver's start (with the first one's two
    /// neighbours, where they keep it so).
    Enclosing(Start<R>),
    /// Neither, within rounding: GJK decides.
    Undecided,
}

/// The solver's start: four supports, or six where the first one's
/// neighbours are in.
pub(crate) struct Start<R: Real> {
    points: [SupportPoint<R>; 6],
    len: usize,
}

impl<R: Real> Start<R> {
    pub fn points(&self) -> &[SupportPoint<R>] {
        self.points.get(..self.len).unwrap_or_default()
    }
}

/// The four supports of the pair's cores and what they decide. Margins of
/// 64 eps of the coordinates' size (twice each bounding radius about its
/// reference point, and B's offset): far above the rounding of a support's
/// dot product or an edge's cross product.
///
/// The first support's two neighbours on the boundary join the start,
/// where they keep it convex: two faces of the difference, exact, that the
/// solver need not find. Where `u` is the last step's normal (a warm
/// start), the closest face most likely still meets the first support, and
/// is then among them from the start; without them the solver would home
/// in on it from both sides. Cold, they save the solver a round on average.
#[inline(always)]
pub(crate) fn quad_start<R, A, B>(pair: &Pair<'_, R, A, B>) -> QuadStart<R>
where
    R: Real,
    A: SupportMap<R> + ?Sized,
    B: SupportMap<R> + ?Sized,
{
    let u = pair.first_direction;
    let size = pair.coordinates_size();
    let margin = R::from_u32(64) * R::EPSILON * size;
    // The first support's plane separates the origin: apart.
    let parted = |first: &MinkowskiVertex<R>| pair.radius() == R::ZERO && first.w.dot(u) < -margin * u.l1();
    let quad = match pair.scanned_square(u) {
        Some(quad) if parted(&quad[0]) => return QuadStart::Apart,
        Some(quad) => quad,
        None => {
            // One at a time, so that a pair apart asks for one support
            // only; the lines of all four asked for first, which a pair
            // apart pays in bandwidth, not in waits.
            pair.ask_square_supports(u);
            let first = pair.support_shared(u);
            if parted(&first) {
                return QuadStart::Apart;
            }
            let turned = u.perp();
            [first, pair.support_shared(turned), pair.support_shared(-u), pair.support_shared(-turned)]
        }
    };
    // Supports along directions turning counter-clockwise are counter-
    // clockwise on the boundary.
    if !surely_encloses(&quad.each_ref().map(|v| v.w), margin, size) {
        return QuadStart::Undecided;
    }
    let point = |v: &MinkowskiVertex<R>| SupportPoint { point: v.w.to_glam(), id: v.id };
    let [q0, q1, q2, q3] = quad.each_ref().map(point);
    if let Some([before, after]) = pair.neighbours(&quad[0]) {
        let six = [before, quad[0], after, quad[1], quad[2], quad[3]];
        if surely_convex_around_origin(&six.each_ref().map(|v| v.w), margin, size) {
            return QuadStart::Enclosing(Start { points: six.each_ref().map(point), len: 6 });
        }
    }
    QuadStart::Enclosing(Start { points: [q0, q1, q2, q3, q0, q0], len: 4 })
}

/// Whether the polygon `w` is convex, counter-clockwise and around the
/// origin once, with the origin inside by more than `margin`
/// ([`surely_encloses`]): every turn left, and one edge only that crosses
/// the ray from the origin along x (each edge passes the origin counter-
/// clockwise, so a polygon that went round twice would cross it twice).
#[inline(always)]
fn surely_convex_around_origin<R: Real, const K: usize>(w: &[V2<R>; K], margin: R, size: R) -> bool {
    let (turns_left, crossings) = (0..K).fold((true, 0), |(left, crossings), k| {
        let (p, q, r) = (w[k], w[(k + 1) % K], w[(k + 2) % K]);
        let crosses = p.y < R::ZERO && q.y >= R::ZERO;
        (left & ((q - p).cross(r - q) > R::ZERO), crossings + usize::from(crosses))
    });
    turns_left && crossings == 1 && surely_encloses(w, margin, size)
}

/// Whether the counter-clockwise polygon `w` encloses the origin by more
/// than `margin` (times each edge's length, by `|x| + |y|`, plus the
/// coordinates' size `size`, which covers the cross products' own
/// rounding): the origin left of every edge. A clockwise one fails. Every
/// edge is tested, with no branch between them: most polygons asked pass.
#[inline(always)]
pub(crate) fn surely_encloses<R: Real, const K: usize>(w: &[V2<R>; K], margin: R, size: R) -> bool {
    (0..K).fold(true, |inside, k| {
        let (p, q) = (w[k], w[(k + 1) % K]);
        inside & (p.cross(q) > margin * ((q - p).l1() + size))
    })
}
