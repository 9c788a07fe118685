//! A point core (a circle's centre) against a small polygon, in closed form:
//! the nearest edge or vertex over every edge at once, then one exact
//! formula for the distance or the depth. GJK and EPA reach the same answer
//! in a few iterations whose branches a predictor cannot learn across pairs.
//!
//! Worked in the pair's frame (A's, relative to A's reference point), as every
//! query is.

use crate::polytope::{first_max, SMALL_POLYGON_MAX};
use crate::real::{Real, V2};

const M: usize = SMALL_POLYGON_MAX;

/// Where a point is relative to a convex polygon, with the polygon's outward
/// unit normal at its nearest feature.
#[derive(Clone, Copy)]
pub(crate) enum Nearest<R> {
    /// Outside (or on the boundary, at distance 0): the distance, the unit
    /// normal from the polygon towards the point, and the nearest point.
    Outside { distance: R, normal: V2<R>, point: V2<R> },
    /// Strictly inside: how far the point is from the nearest edge's line,
    /// and that edge's outward unit normal.
    Inside { depth: R, normal: V2<R> },
}

/// Each edge's start and end, a slot per edge.
type EdgeSlots<R> = ([V2<R>; M], [V2<R>; M]);

/// Edge `i` of the counter-clockwise polygon `vertices` (3 to [`M`]) in
/// slot `i`, as its start and end; the slots past the last edge repeat the
/// closing one, which then leads no choice (ties go to the first slot).
/// Indices are selected, not branched on, and the arithmetic runs over
/// every slot in SIMD lanes, coordinates apart.
#[inline(always)]
pub(crate) fn edge_slots<R: Real>(vertices: &[V2<R>]) -> Option<EdgeSlots<R>> {
    let n = vertices.len();
    if !(3..=M).contains(&n) {
        return None;
    }
    let from = core::array::from_fn(|i| vertices[i.min(n - 1)]);
    let to = core::array::from_fn(|i| vertices[if i + 1 < n { i + 1 } else { 0 }]);
    Some((from, to))
}

/// Every edge measured from `p` with the same arithmetic, a SIMD lane an
/// edge: what the queries choose the nearest feature from.
struct Lanes<R> {
    from: [V2<R>; M],
    to: [V2<R>; M],
    /// The clamped parameter of the nearest point on each edge.
    along: [R; M],
    /// The squared distance to that point.
    squared: [R; M],
    /// The outward normal (not unit) dotted with the offset: positive
    /// outside the edge's line.
    outward: [R; M],
    /// The edge's squared length.
    ee: [R; M],
    /// The polygon's vertex count.
    n: usize,
}

impl<R: Real> Lanes<R> {
    /// `None` where the squares this takes could under- or overflow (edges
    /// shorter than the square root of the least normal number).
    #[inline(always)]
    fn new(vertices: &[V2<R>], p: V2<R>) -> Option<Self> {
        let (from, to) = edge_slots(vertices)?;
        let mut along = [R::ZERO; M];
        let mut squared = [R::ZERO; M];
        let mut outward = [R::ZERO; M];
        let mut ee = [R::ONE; M];
        let mut usable = true;
        for i in 0..M {
            let (ex, ey) = (to[i].x - from[i].x, to[i].y - from[i].y);
            let (wx, wy) = (p.x - from[i].x, p.y - from[i].y);
            let length2 = ex * ex + ey * ey;
            let t = ((wx * ex + wy * ey) / length2).max(R::ZERO).min(R::ONE);
            let (dx, dy) = (wx - ex * t, wy - ey * t);
            usable &= (length2 >= R::MIN_POSITIVE) & (length2 * (wx * wx + wy * wy)).is_finite();
            along[i] = t;
            ee[i] = length2;
            squared[i] = dx * dx + dy * dy;
            outward[i] = ey * wx - ex * wy;
        }
        usable.then_some(Self { from, to, along, squared, outward, ee, n: vertices.len() })
    }

    #[inline(always)]
    fn edge(&self, i: usize) -> V2<R> {
        self.to[i % M] - self.from[i % M]
    }

    #[inline(always)]
    fn unit_normal(&self, i: usize) -> V2<R> {
        self.edge(i).perp_cw().try_normalize_inlined().unwrap_or(V2::new(R::ONE, R::ZERO))
    }

    /// The edge whose line `p` lies deepest beyond (or least inside).
    #[inline(always)]
    fn deepest(&self) -> usize {
        first_max(&self.outward)
    }

    /// Whether `p` lies strictly inside every edge's line: the deepest
    /// edge's verdict, without the lane that gives it.
    #[inline(always)]
    fn inside(&self) -> bool {
        self.outward.iter().fold(self.outward[0], |most, &x| most.max(x)) < R::ZERO
    }

    /// The distance, the unit normal from the polygon towards `p` and the
    /// nearest point, as they are where `p` is outside (or on the
    /// boundary): the nearest edge's signed distance, or its corner's
    /// offset.
    #[inline(always)]
    fn outside(&self, p: V2<R>) -> (R, V2<R>, V2<R>) {
        let n = self.n;
        let mut best = first_max(&self.squared.map(|d| -d));
        // A corner, where the edge on its other side has the point's foot
        // inside it and the point beyond its line: that edge's region. Next
        // to the corner the two squared distances differ by the square of
        // the foot's offset from it, which rounding hides, while the two
        // normals differ by its first power.
        if !(self.along[best] > R::ZERO && self.along[best] < R::ONE) {
            let adjacent = match self.along[best] > R::ZERO {
                true if best + 1 >= n => 0,
                true => best + 1,
                false if best == 0 => n - 1,
                false => best - 1,
            };
            let inside = self.along[adjacent % M] > R::ZERO && self.along[adjacent % M] < R::ONE;
            if inside && self.outward[adjacent % M] > R::ZERO {
                best = adjacent % M;
            }
        }
        let t = self.along[best];
        if t > R::ZERO && t < R::ONE {
            // Across the edge: the signed distance to its line.
            let length = self.ee[best].sqrt();
            let normal = self.edge(best).perp_cw() * (R::ONE / length);
            let distance = (self.outward[best] / length).max(R::ZERO);
            return (distance, normal, p - normal * distance);
        }
        let corner = if t > R::ZERO { self.to[best] } else { self.from[best] };
        match (p - corner).try_length_and_unit() {
            Some((distance, normal)) => (distance, normal, corner),
            // On the vertex: touching, along the deepest edge's normal.
            None => (R::ZERO, self.unit_normal(self.deepest()), corner),
        }
    }
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
    let lanes = Lanes::new(vertices, p)?;
    if lanes.inside() {
        // Inside every edge's line: the least depth is over the unit normals.
        let least: [R; M] = core::array::from_fn(|i| lanes.outward[i] / lanes.ee[i].sqrt());
        let best = first_max(&least);
        return Some(Nearest::Inside { depth: -least[best], normal: lanes.unit_normal(best) });
    }
    let (distance, normal, point) = lanes.outside(p);
    Some(Nearest::Outside { distance, normal, point })
}

/// What the distance query needs of [`nearest`]: whether `p` is strictly
/// inside, and the answer it would have outside, computed either way. The
/// distance query has no use for a depth (eight square roots), and one
/// branch on whether the shapes are apart (inside, or within the radius)
/// then decides it instead of one on each.
#[inline(always)]
pub(crate) fn beyond<R: Real>(vertices: &[V2<R>], p: V2<R>) -> Option<(bool, R, V2<R>, V2<R>)> {
    let lanes = Lanes::new(vertices, p)?;
    let (distance, normal, point) = lanes.outside(p);
    Some((lanes.inside(), distance, normal, point))
}

/// Whether `p` lies within `radius` of the counter-clockwise polygon
/// `vertices` (3 to [`M`]), touching included: inside every edge's line, or
/// within `radius` of some edge. Every edge is measured at once with
/// products only (an edge's interior by `cross^2 <= r^2 |e|^2`, its ends by
/// their squared distances) in lanes folded by minimum and maximum, so the
/// verdict waits for no division, square root or branch on the geometry.
///
/// `None` where the products could under- or overflow.
pub(crate) fn within<R: Real>(vertices: &[V2<R>], p: V2<R>, radius: R) -> Option<bool> {
    let (from, to) = edge_slots(vertices)?;
    let rr = radius * radius;
    // Per edge: at most zero where `p` is within reach of it; positive
    // where `p` lies beyond its line.
    let mut short = [R::ZERO; M];
    let mut across = [R::ZERO; M];
    let mut least = [R::ZERO; M];
    let mut most = [R::ZERO; M];
    for i in 0..M {
        let (e, w) = (to[i] - from[i], p - from[i]);
        let (length2, start) = (e.length_squared(), w.length_squared());
        let along = w.dot(e);
        // Outward: the polygon turns counter-clockwise, so w x e.
        across[i] = w.cross(e);
        let interior = across[i] * across[i] - rr * length2;
        let end = (w - e).length_squared() - rr;
        short[i] = if along <= R::ZERO {
            start - rr
        } else if along >= length2 {
            end
        } else {
            interior
        };
        least[i] = length2 * length2;
        most[i] = (length2 * start).max(rr * length2);
    }
    let fold = |v: &[R; M], f: fn(R, R) -> R| v.iter().skip(1).fold(v[0], |a, &b| f(a, b));
    // Products of four lengths: normal numbers, so that they round
    // relatively (edges under about 1e-9 in f32 leave it to GJK).
    let usable = fold(&least, R::min) >= R::MIN_POSITIVE && fold(&most, R::max) < R::INFINITY;
    usable.then(|| fold(&short, R::min) <= R::ZERO || fold(&across, R::max) <= R::ZERO)
}
