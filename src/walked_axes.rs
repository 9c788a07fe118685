//! The separating-axis test of two convex polygons of up to
//! [`WALKED_MAX`] vertices, for their penetration: every edge normal of
//! either, as for small polygons (`sat.rs`), but the other polygon's least
//! vertex along each normal is followed from edge to edge (rotating
//! calipers) rather than searched, so the `n + m` axes cost `O(n + m)`
//! products. On hosts it beats EPA, whose every iteration scans both
//! polygons for a support.
//!
//! Measured in the pair's frame (A's, relative to A's reference point), B's
//! vertices placed there once, as every query does; but each walk reads the
//! polygon it follows in that polygon's own frame, where it is convex.

use crate::minkowski::Pair;
use crate::polytope::polytope_support;
use crate::real::scaled_separation;
use crate::real::{Real, V2};
use crate::sat::penetration_along;
use crate::shape::SupportMap;

/// Up to this many vertices a side, polygons' penetrations are walked;
/// beyond, EPA answers. The manifold decides it: it takes the penetration
/// query's answer, and after GJK has found the cores overlapping, EPA
/// finishes 64-gons sooner than the walk does.
pub(crate) const WALKED_MAX: usize = 32;

/// What the axes say about two polygons.
pub(crate) enum Walked<R> {
    /// An axis separates them (touching does not).
    Apart,
    /// They overlap: the least depth over the axes and its unit normal,
    /// from A towards B.
    Overlapping(R, V2<R>),
}

/// The axes of the pair's two polygons (`a` in the pair frame, `b` in B's),
/// or `None` where either has more than [`WALKED_MAX`] vertices or rounding
/// broke the order the walk relies on: then EPA answers.
pub(crate) fn penetration<R, A, B>(pair: &Pair<'_, R, A, B>, a: &[V2<R>], b: &[V2<R>]) -> Option<Walked<R>>
where
    R: Real,
    A: SupportMap<R> + ?Sized,
    B: SupportMap<R> + ?Sized,
{
    let (n, m) = (a.len(), b.len());
    if !(3..=WALKED_MAX).contains(&n) || !(3..=WALKED_MAX).contains(&m) {
        return None;
    }
    let mut placed = [V2::zero(); WALKED_MAX];
    for (slot, &p) in placed.iter_mut().zip(b) {
        *slot = pair.b_to_pair(p);
    }
    // B as the walks read it: in its own frame, where it is convex as its
    // constructor checked (turned, a sliver's vertices can round into a
    // dent, and its short edges' normals turn every way), and placed, where
    // each reach is measured.
    let b_own = Walking { own: b, placed: &placed[..m] };
    // A's axes, then B's.
    let mut normals = [V2::zero(); 2 * WALKED_MAX];
    let mut least = [R::ZERO; 2 * WALKED_MAX];
    let (normals_a, normals_b) = normals.split_at_mut(n);
    let (least_a, least_b) = least.split_at_mut(n);
    let a_own = Walking { own: a, placed: a };
    match walk(a_own, |n| n, b_own, |n| pair.pair_vector_to_b(n), normals_a, least_a) {
        Walk::Measured => {}
        Walk::Parted => return Some(Walked::Apart),
        Walk::Lost => return None,
    }
    let (normals_b, least_b) = (&mut normals_b[..m], &mut least_b[..m]);
    match walk(b_own, |n| pair.b_vector_to_pair(n), a_own, |n| n, normals_b, least_b) {
        Walk::Measured => {}
        Walk::Parted => return Some(Walked::Apart),
        Walk::Lost => return None,
    }
    let axes = n + m;
    let (best, top) = least_overlap(&normals[..axes], &least[..axes]);
    if !top.is_finite() {
        return None;
    }
    // B's normals point away from B, towards A: turned round, every
    // normal points from A towards B.
    let normal = if best < n { normals[best] } else { -normals[best] };
    let (depth, unit) = penetration_along(top, normal);
    Some(Walked::Overlapping(depth, unit))
}

/// The axis of the least overlap (of the greatest separation along its unit
/// normal: all are at most zero here), the first of any tied, and that
/// separation. Picked by `-least^2 / |n|^2`, the separation's square,
/// negated, with no square root or second division an axis (written
/// `least / |n|^2 * least`, so that it underflows only with the separation
/// itself); where that square is too small or too large to tell axes
/// apart, every separation is measured as `sat.rs` measures it.
fn least_overlap<R: Real>(normals: &[V2<R>], least: &[R]) -> (usize, R) {
    let mut keys = [-R::INFINITY; 2 * WALKED_MAX];
    for ((key, normal), &reach) in keys.iter_mut().zip(normals).zip(least) {
        *key = -(reach / normal.length_squared() * reach);
    }
    let top = keys.iter().fold(-R::INFINITY, |top, &key| if key > top { key } else { top });
    let best = keys.iter().position(|&key| key == top).unwrap_or(0);
    if top < -R::MIN_POSITIVE && top.is_finite() {
        return (best, scaled_separation(normals[best], least[best]));
    }
    let (mut best, mut top) = (0, -R::INFINITY);
    for (i, (&normal, &reach)) in normals.iter().zip(least).enumerate() {
        let separation = scaled_separation(normal, reach);
        let greater = separation > top;
        best = core::hint::select_unpredictable(greater, i, best);
        top = core::hint::select_unpredictable(greater, separation, top);
    }
    (best, top)
}

/// How a walk ended.
enum Walk {
    /// Every axis measured.
    Measured,
    /// An axis separates the polygons (touching does not): the rest need
    /// not be measured. Overlapping pairs never take the branch, so it
    /// costs them nothing a predictor misses.
    Parted,
    /// Rounding would take the walk past two turns.
    Lost,
}

/// A polygon walked along: its vertices in its own frame, where they are
/// convex, and the same vertices in the pair frame.
#[derive(Clone, Copy)]
struct Walking<'v, R> {
    own: &'v [V2<R>],
    placed: &'v [V2<R>],
}

/// For every edge of `own` (counter-clockwise): its outward normal (not
/// unit), taken in `own`'s frame and turned into the pair frame by
/// `to_pair`, and how far `other` reaches past the edge's line along it,
/// times the normal's length (the least dot product of `other`'s vertices
/// with it, from the edge), as `sat.rs` measures its axes. The normals turn
/// counter-clockwise from edge to edge, and so does `other`'s least vertex
/// along them: it is followed forwards, in `other`'s own frame (`to_other`
/// turns a normal there), while `other`'s next edge falls along the normal,
/// from the first normal's, found by a scan. Both polygons are read where
/// they are convex, so convexity bounds the whole walk by one turn round
/// `other` (and rounding, on edges nearly parallel to a normal, by a vertex
/// whose dot product ties to rounding).
fn walk<R: Real>(
    own: Walking<'_, R>,
    to_pair: impl Fn(V2<R>) -> V2<R>,
    other: Walking<'_, R>,
    to_other: impl Fn(V2<R>) -> V2<R>,
    normals: &mut [V2<R>],
    least: &mut [R],
) -> Walk {
    let (n, m) = (own.own.len().min(own.placed.len()), other.own.len().min(other.placed.len()));
    let next = |k: usize, len: usize| if k + 1 >= len { 0 } else { k + 1 };
    let normal = |i: usize| to_pair((own.own[next(i, n)] - own.own[i]).perp_cw());
    // The first of the least dots along the first normal is the first of
    // the greatest along its opposite (negation is exact).
    let (mut j, _) = polytope_support::<R, WALKED_MAX>(other.own, -to_other(normal(0)));
    let mut steps = 2 * m;
    for (i, (slot, reach)) in normals.iter_mut().zip(least.iter_mut()).enumerate().take(n) {
        let normal = normal(i);
        let along = to_other(normal);
        while (other.own[next(j, m)] - other.own[j]).dot(along) < R::ZERO {
            if steps == 0 {
                return Walk::Lost;
            }
            j = next(j, m);
            steps -= 1;
        }
        *slot = normal;
        // The vertices' offset first: near the edge's line it is short, and
        // its dot rounds with its own length, not with the vertices'
        // distance from the reference point (nearly tied axes, as a polygon
        // of many vertices has, are then told apart as EPA tells them).
        *reach = normal.dot(other.placed[j] - own.placed[i]);
        if *reach > R::ZERO {
            return Walk::Parted;
        }
    }
    Walk::Measured
}
