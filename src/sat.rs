//! The separating-axis test of two small convex polygons (as dyn4j's `Sat`):
//! two polygons are apart exactly when one edge normal of either separates
//! them, and when they overlap, the least overlap over those normals is the
//! penetration depth. Eight vertices a side make it 16 axes of 8 products,
//! a fixed amount of arithmetic with no branch on the geometry: on hosts it
//! beats GJK and EPA, whose branches a predictor cannot learn across pairs.
//!
//! Both polygons are worked on in A's frame, relative to A's reference point
//! (B's vertices placed there once), as every query does.

use crate::minkowski::Pair;
use crate::polytope::{first_max, SMALL_POLYGON_MAX};
use crate::real::{Real, V2};
use crate::shape::SupportMap;

const M: usize = SMALL_POLYGON_MAX;

/// Up to [`M`] vertices, the unused slots copies of the first: a minimum
/// over every slot is then the minimum over the vertices. Their coordinates
/// also apart, as the SIMD products read them.
struct Padded<R> {
    v: [V2<R>; M],
    xs: [R; M],
    ys: [R; M],
    len: usize,
}

impl<R: Real> Padded<R> {
    fn new(vertices: &[V2<R>], place: impl Fn(V2<R>) -> V2<R>) -> Self {
        let first = place(vertices.first().copied().unwrap_or_default());
        let v: [V2<R>; M] = core::array::from_fn(|i| vertices.get(i).map_or(first, |&p| place(p)));
        let (xs, ys) = (core::array::from_fn(|i| v[i].x), core::array::from_fn(|i| v[i].y));
        Self { v, xs, ys, len: vertices.len().min(M) }
    }

    /// The outward normal of edge `i` (not unit): the edge turned clockwise,
    /// the polygon being counter-clockwise.
    #[inline(always)]
    fn normal(&self, i: usize) -> V2<R> {
        let next = if i + 1 < self.len { self.v[(i + 1) % M] } else { self.v[0] };
        (next - self.v[i % M]).perp_cw()
    }
}

/// For every edge slot of `own`: the outward normal (not unit) and the least
/// dot product of `other`'s vertices with it, measured from the edge (how
/// far `other` reaches past the edge's line, times the normal's length).
/// Slots past the last edge get a separation of minus infinity.
#[inline(always)]
fn faces<R: Real>(own: &Padded<R>, other: &Padded<R>) -> ([V2<R>; M], [R; M]) {
    let normals: [V2<R>; M] = core::array::from_fn(|i| own.normal(i));
    let least = core::array::from_fn(|i| {
        let n = normals[i];
        let reach = R::min_dot8(&other.xs, &other.ys, n) - n.dot(own.v[i]);
        core::hint::select_unpredictable(i < own.len, reach, -R::INFINITY)
    });
    (normals, least)
}

/// What the separating axes say about two polygon cores.
pub(crate) struct Axes<R> {
    normals: [V2<R>; 2 * M],
    least: [R; 2 * M],
}

impl<R: Real> Axes<R> {
    /// The separating axes of the pair's two small polygons (`a`, `b`, as
    /// [`Pair::small_polygons`] gives them).
    pub fn new<A, B>(pair: &Pair<'_, R, A, B>, a: &[V2<R>], b: &[V2<R>]) -> Self
    where
        A: SupportMap<R> + ?Sized,
        B: SupportMap<R> + ?Sized,
    {
        let pa = Padded::new(a, |p| p);
        let pb = Padded::new(b, |p| pair.b_to_pair(p));
        let (na, la) = faces(&pa, &pb);
        let (nb, lb) = faces(&pb, &pa);
        // B's face normals point away from B, towards A: turned round, every
        // normal points from A towards B.
        let normals = core::array::from_fn(|i| if i < M { na[i] } else { -nb[i - M] });
        let least = core::array::from_fn(|i| if i < M { la[i] } else { lb[i - M] });
        Self { normals, least }
    }

    /// The separating axes of a segment core and a small polygon, where
    /// the pair has them ([`Pair::segment_and_small_polygon`]): the segment
    /// is a polygon of two vertices, whose two edges are its two sides.
    pub fn of_segment_and_polygon<A, B>(pair: &Pair<'_, R, A, B>) -> Option<Self>
    where
        A: SupportMap<R> + ?Sized,
        B: SupportMap<R> + ?Sized,
    {
        let (segment, polygon, segment_is_a) = pair.segment_and_small_polygon()?;
        Some(if segment_is_a { Self::new(pair, &segment, polygon) } else { Self::new(pair, polygon, &segment) })
    }

    /// Whether an axis separates the polygons (touching does not).
    pub fn separated(&self) -> bool {
        self.least.iter().fold(false, |any, &s| any | (s > R::ZERO))
    }

    /// The least overlap along a unit normal, and that normal (from A
    /// towards B): the penetration depth and normal of overlapping
    /// polygons. Ties go to the first axis, A's before B's.
    pub fn penetration(&self) -> (R, V2<R>) {
        // Lengths scaled by the larger component first, so the squares of a
        // tiny polygon's normals neither underflow nor lose their digits.
        let lengths: [R; 2 * M] = core::array::from_fn(|i| scaled_length(self.normals[i]));
        let separation: [R; 2 * M] = core::array::from_fn(|i| {
            let s = self.least[i] / lengths[i];
            // A slot past the last edge (no normal) never leads.
            if lengths[i] > R::ZERO {
                s
            } else {
                -R::INFINITY
            }
        });
        let best = first_max(&separation);
        let normal = self.normals[best];
        let normal = normal.try_normalize_inlined().unwrap_or(V2::new(R::ONE, R::ZERO));
        // From zero: a separation of -0 is a depth of +0.
        (R::ZERO - separation[best], normal)
    }
}

/// `|n|`, scaled by the larger component first, so the square of a tiny
/// vector neither underflows nor loses its digits.
#[inline(always)]
fn scaled_length<R: Real>(n: V2<R>) -> R {
    let m = n.x.abs().max(n.y.abs());
    if m > R::ZERO {
        m * (n * (R::ONE / m)).length_squared().sqrt()
    } else {
        R::ZERO
    }
}
