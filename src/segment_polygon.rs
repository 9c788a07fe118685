//! A segment core (a capsule's) against a small polygon, decided in closed
//! form: the cores' distance is at most the radius where an end of the
//! segment lies within it of the polygon, a vertex of the polygon within it
//! of the segment, or the cores cross. Two convex cores apart are nearest at
//! a vertex of one of them, so these are all the cases. GJK's iterations
//! would branch on the geometry at every step; these lanes do not.
//!
//! Worked in the polygon's frame, relative to its reference point.

use crate::point_polygon::edge_slots;
use crate::polytope::SMALL_POLYGON_MAX;
use crate::real::{Real, V2};

const M: usize = SMALL_POLYGON_MAX;

/// Per edge of the polygon, one end `p` of the segment measured against it:
/// how far within `rr` (the squared radius) of the edge `p` is (at most
/// zero where it is within reach), and how far beyond the edge's line
/// (positive outside), with products only.
#[inline(always)]
fn end_against_edge<R: Real>(from: V2<R>, to: V2<R>, p: V2<R>, rr: R) -> (R, R) {
    let (e, w) = (to - from, p - from);
    let (length2, along) = (e.length_squared(), w.dot(e));
    // Outward: the polygon turns counter-clockwise, so w x e.
    let across = w.cross(e);
    let short = if along <= R::ZERO {
        w.length_squared() - rr
    } else if along >= length2 {
        (w - e).length_squared() - rr
    } else {
        across * across - rr * length2
    };
    (short, across)
}

/// Whether the segment from `p` to `q` lies within `radius` of the
/// counter-clockwise polygon `vertices` (3 to [`M`]), touching included.
/// Every edge and vertex is measured at once in SIMD lanes folded by
/// minimum and maximum, so the verdict waits for no division, square root
/// or branch on the geometry.
///
/// `None` where the products could under- or overflow (an edge or the
/// segment shorter than about the fourth root of the least normal number):
/// GJK answers.
pub(crate) fn within<R: Real>(vertices: &[V2<R>], p: V2<R>, q: V2<R>, radius: R) -> Option<bool> {
    let (from, to) = edge_slots(vertices)?;
    let rr = radius * radius;
    let f = q - p;
    let ff = f.length_squared();
    let mut short = [R::ZERO; M];
    // Where each end lies beyond an edge's line, the lesser of the two: an
    // edge parts the cores where both ends lie beyond it.
    let mut beyond = [R::ZERO; M];
    // Which side of the segment's line each vertex lies on.
    let mut side = [R::ZERO; M];
    let mut least = [R::ZERO; M];
    let mut most = [R::ZERO; M];
    for i in 0..M {
        let (short_p, across_p) = end_against_edge(from[i], to[i], p, rr);
        let (short_q, across_q) = end_against_edge(from[i], to[i], q, rr);
        // The vertex `from[i]` against the segment.
        let s = from[i] - p;
        let along = s.dot(f);
        side[i] = s.cross(f);
        let start = s.length_squared();
        let short_v = if along <= R::ZERO {
            start - rr
        } else if along >= ff {
            (s - f).length_squared() - rr
        } else {
            side[i] * side[i] - rr * ff
        };
        short[i] = short_p.min(short_q).min(short_v);
        beyond[i] = across_p.min(across_q);
        let length2 = (to[i] - from[i]).length_squared();
        least[i] = length2 * length2;
        // `start` is the vertex's squared distance from `p` as well.
        let reach = start.max((q - from[i]).length_squared()).max(rr);
        most[i] = reach * length2.max(ff);
    }
    let fold = |v: &[R; M], f: fn(R, R) -> R| v.iter().skip(1).fold(v[0], |a, &b| f(a, b));
    // Products of four lengths: normal numbers, so that they round
    // relatively (edges or segments under about 1e-9 in f32 leave it to GJK).
    let usable = fold(&least, R::min).min(ff * ff) >= R::MIN_POSITIVE && fold(&most, R::max) < R::INFINITY;
    if !usable {
        return None;
    }
    // The cores cross where neither an edge's line nor the segment's parts
    // them (touching does not part).
    let edge_parts = fold(&beyond, R::max) > R::ZERO;
    let segment_parts = fold(&side, R::min) > R::ZERO || fold(&side, R::max) < R::ZERO;
    Some(fold(&short, R::min) <= R::ZERO || !(edge_parts || segment_parts))
}
