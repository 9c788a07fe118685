//! A point core (a circle's centre) against a small polygon, in closed form:
//! the nearest edge or vertex over every edge at once, then one exact
//! formula for the distance or the depth. GJK and EPA reach the same answer
//! in a few iterations whose branches a predictor cannot learn across pairs.
//!
//! Worked in the pair's frame (A's, relative to A's reference point), as every
//! query is.

use crate::polytope::SMALL_POLYGON_MAX;
use crate::real::{Real, V2};

const M: usize = SMALL_POLYGON_MAX;

/// Where a point is relative to a convex polygon, with the polygon's outward
/// unit normal at its nearest feature.
pub(crate) enum Nearest<R> {
    /// Outside (or on the boundary, at distance 0): the distance, the unit
    /// normal from the polygon towards the point, and the nearest point.
    Outside { distance: R, normal: V2<R>, point: V2<R> },
    /// Strictly inside: how far the point is from the nearest edge's line,
    /// and that edge's outward unit normal.
    Inside { depth: R, normal: V2<R> },
}

/// The nearest feature of the counter-clockwise polygon `vertices` (3 to
/// [`M`]) to `p`. Every edge is measured with the same arithmetic, so the
/// choice has no branch on the geometry; the answer is then computed in the
/// form exact to rounding for that feature: a signed distance along the
/// edge's normal, or a vertex's offset.
///
/// `None` where the squares this takes could under- or overflow (edges
/// shorter than the square root of the least normal number): GJK answers.
pub(crate) fn nearest<R: Real>(vertices: &[V2<R>], p: V2<R>) -> Option<Nearest<R>> {
    let n = vertices.len().min(M);
    let first = vertices.first().copied().unwrap_or_default();
    // Coordinates apart, the unused slots copies of the first vertex
    // (zero-length edges, masked below), and each edge's far end: then
    // straight-line arithmetic over all slots, which the compiler keeps in
    // SIMD lanes.
    let (mut vx, mut vy) = ([first.x; M], [first.y; M]);
    for (i, v) in vertices.iter().take(M).enumerate() {
        vx[i] = v.x;
        vy[i] = v.y;
    }
    let (mut nx, mut ny) = ([first.x; M], [first.y; M]);
    let last = n.saturating_sub(1);
    nx[..last].copy_from_slice(&vx[1..=last]);
    ny[..last].copy_from_slice(&vy[1..=last]);
    let live: [bool; M] = core::array::from_fn(|i| i < n);
    let mut along = [R::ZERO; M];
    let mut squared = [R::INFINITY; M];
    let mut outward = [-R::INFINITY; M];
    let mut ee = [R::ONE; M];
    let mut usable = true;
    for i in 0..M {
        let (ex, ey) = (nx[i] - vx[i], ny[i] - vy[i]);
        let (wx, wy) = (p.x - vx[i], p.y - vy[i]);
        let length2 = ex * ex + ey * ey;
        // The clamped parameter of the nearest point, the squared distance
        // to it, and the outward normal (not unit) dotted with the offset:
        // positive outside the edge's line.
        let t = ((wx * ex + wy * ey) / length2).max(R::ZERO).min(R::ONE);
        let (dx, dy) = (wx - ex * t, wy - ey * t);
        usable &= !live[i] | ((length2 >= R::MIN_POSITIVE) & (length2 * (wx * wx + wy * wy)).is_finite());
        along[i] = t;
        ee[i] = core::hint::select_unpredictable(live[i], length2, R::ONE);
        squared[i] = core::hint::select_unpredictable(live[i], dx * dx + dy * dy, R::INFINITY);
        outward[i] = core::hint::select_unpredictable(live[i], ey * wx - ex * wy, -R::INFINITY);
    }
    if !usable {
        return None;
    }
    let next = |i: usize| if i + 1 < n { i + 1 } else { 0 };
    let vertex = |i: usize| V2::new(vx[i % M], vy[i % M]);
    let edge = |i: usize| vertex(next(i)) - vertex(i);
    let first_max =
        |values: &[R; M]| (1..M).fold(0, |best, i| core::hint::select_unpredictable(values[i] > values[best], i, best));
    let unit_normal = |i: usize| edge(i).perp_cw().try_normalize_inlined().unwrap_or(V2::new(R::ONE, R::ZERO));
    let deepest = first_max(&outward);
    if outward[deepest] < R::ZERO {
        // Inside every edge's line: the least depth is over the unit normals.
        let least: [R; M] = core::array::from_fn(|i| outward[i] / ee[i].sqrt());
        let best = first_max(&least);
        return Some(Nearest::Inside { depth: -least[best], normal: unit_normal(best) });
    }
    let best = first_max(&squared.map(|d| -d));
    let t = along[best];
    if t > R::ZERO && t < R::ONE {
        // Across the edge: the signed distance to its line.
        let length = ee[best].sqrt();
        let normal = edge(best).perp_cw() * (R::ONE / length);
        let distance = (outward[best] / length).max(R::ZERO);
        return Some(Nearest::Outside { distance, normal, point: p - normal * distance });
    }
    let corner = if t > R::ZERO { vertex(next(best)) } else { vertex(best) };
    Some(match (p - corner).try_length_and_unit() {
        Some((distance, normal)) => Nearest::Outside { distance, normal, point: corner },
        // On the vertex: touching, along the deepest edge's normal.
        None => Nearest::Outside { distance: R::ZERO, normal: unit_normal(deepest), point: corner },
    })
}
