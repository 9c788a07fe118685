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
use crate::real::{lesser, scaled_separation, Real, V2};
use crate::shape::SupportMap;

const M: usize = SMALL_POLYGON_MAX;

/// Up to [`M`] vertices, the unused slots copies of the first: a minimum
/// over every slot is then the minimum over the vertices. Their coordinates
/// also apart, as the SIMD products read them.
struct Padded<R> {
    v: [V2<R>; M],
    xs: [R; M],
    ys: [R; M],
    /// Each edge's outward normal (not unit), taken in the polygon's own
    /// frame and turned: from turned vertices, rounding would tilt a short
    /// edge's normal until the polygon reached past the edge's line along
    /// it, and a turned sliver's depth came out too small.
    normals: [V2<R>; M],
    len: usize,
}

impl<R: Real> Padded<R> {
    /// `place` puts a vertex in the pair frame; `rotation` (cosine, sine),
    /// if any, turns a normal there, asked once for all eight.
    #[inline(always)]
    fn new(vertices: &[V2<R>], place: impl Fn(V2<R>) -> V2<R>, rotation: Option<(R, R)>) -> Self {
        let own_first = vertices.first().copied().unwrap_or_default();
        let own: [V2<R>; M] = core::array::from_fn(|i| vertices.get(i).copied().unwrap_or(own_first));
        // A loop, not `map`: the compiler called that closure out of line,
        // once a vertex.
        let mut v = own;
        for p in &mut v {
            *p = place(*p);
        }
        let (xs, ys) = (core::array::from_fn(|i| v[i].x), core::array::from_fn(|i| v[i].y));
        // The edge turned clockwise, the polygon being counter-clockwise.
        // The slot after the last vertex holds the first, so the closing
        // edge needs no test of the length, and every slot past it has a
        // zero normal.
        let edge = |i: usize| (own[(i + 1) % M] - own[i]).perp_cw();
        let normals = match rotation {
            Some((cos, sin)) => core::array::from_fn(|i| {
                let n = edge(i);
                V2::new(cos * n.x - sin * n.y, sin * n.x + cos * n.y)
            }),
            None => core::array::from_fn(edge),
        };
        Self { v, xs, ys, normals, len: vertices.len().min(M) }
    }

    /// The first vertex furthest along `d` (the padding copies vertex 0,
    /// after it: the first is a vertex).
    #[inline(always)]
    fn support(&self, d: V2<R>) -> usize {
        first_max(&self.v.map(|p| p.dot(d)))
    }

    /// The outward normal of edge `i` (not unit), in the pair frame.
    #[inline(always)]
    fn normal(&self, i: usize) -> V2<R> {
        self.normals[i % M]
    }
}

/// How far `other` reaches past edge `i` of `own` along its outward normal
/// `n` (not unit): the least dot product of `other`'s vertices with it,
/// measured from the edge: what [`faces`] gives that axis.
#[inline(always)]
fn reach<R: Real>(own: &Padded<R>, other: &Padded<R>, n: V2<R>, i: usize) -> R {
    least_dot(n, &other.xs, &other.ys) - n.dot(own.v[i % M])
}

/// The least dot product of the points (`xs`, `ys`) with `n`.
#[inline(always)]
fn least_dot<R: Real>(n: V2<R>, xs: &[R; M], ys: &[R; M]) -> R {
    // A tree of minima, not a chain: three compares deep, not eight.
    let mut least: [R; M] = core::array::from_fn(|j| n.x * xs[j] + n.y * ys[j]);
    let mut width = M;
    while width > 1 {
        width /= 2;
        for k in 0..width {
            least[k] = lesser(least[k + width], least[k]);
        }
    }
    least[0]
}

/// For every edge slot of `own`: the outward normal (not unit) and the least
/// dot product of `other`'s vertices with it, measured from the edge (how
/// far `other` reaches past the edge's line, times the normal's length).
/// Slots past the last edge have a zero normal and a reach of zero, which
/// separates nothing and, scaled, leads nothing ([`scaled_separation`]).
/// `WIDE`: in four f64 lanes a register, where code compiled for them asks.
#[inline(always)]
fn faces<R: Real, const WIDE: bool>(own: &Padded<R>, other: &Padded<R>) -> ([V2<R>; M], [R; M]) {
    let normals: [V2<R>; M] = core::array::from_fn(|i| own.normal(i));
    let (nx, ny) = (normals.map(|n| n.x), normals.map(|n| n.y));
    let least = R::least_dots8::<WIDE>(&nx, &ny, &other.xs, &other.ys);
    let least = core::array::from_fn(|i| least[i] - normals[i].dot(own.v[i]));
    (normals, least)
}

/// The distance of two polygons whose closest features are an edge and a
/// vertex, the unit normal from A towards B, and the closest points on A and
/// on B ([`face_and_vertex_placed`]).
pub(crate) type FaceAndVertex<R> = (R, V2<R>, V2<R>, V2<R>);

/// The pair's two small polygons, both in A's frame relative to A's
/// reference point: what every axis is measured on.
pub(crate) struct Polygons<R> {
    a: Padded<R>,
    b: Padded<R>,
}

impl<R: Real> Polygons<R> {
    /// The pair's two small polygons (`a`, `b`, as
    /// [`Pair::small_polygons`] gives them), B's vertices placed once.
    #[inline(always)]
    pub fn new<A, B>(pair: &Pair<'_, R, A, B>, a: &[V2<R>], b: &[V2<R>]) -> Self
    where
        A: SupportMap<R> + ?Sized,
        B: SupportMap<R> + ?Sized,
    {
        Self { a: Padded::new(a, |p| p, None), b: Padded::new(b, |p| pair.b_to_pair(p), pair.b_rotation()) }
    }

    /// The support point of B - A along `d` and its id (A's vertex index
    /// in the high 16 bits, B's in the low), as GJK's supports name them.
    /// The padding copies vertex 0, after it: the first greatest is a vertex.
    pub fn support(&self, d: V2<R>) -> (V2<R>, u32) {
        let (ia, ib) = (self.a.support(-d), self.b.support(d));
        (self.b.v[ib] - self.a.v[ia], ((ia as u32) << 16) | ib as u32)
    }

    /// Three vertices of B - A around axis `slot`'s overlap (A's edges
    /// first, then B's), with their ids: the axis's face (the edge less the
    /// other polygon's vertex reaching furthest past it) and the support
    /// along the axis's normal `u`, from A towards B. Where the axis is the
    /// least overlap, the origin's foot on that face lies on it.
    pub fn face_triangle(&self, slot: usize, u: V2<R>) -> [(V2<R>, u32); 3] {
        let of_a = slot < M;
        let (own, other) = if of_a { (&self.a, &self.b) } else { (&self.b, &self.a) };
        let edge = slot % M;
        let deepest = other.support(-own.normal(edge));
        let next = (edge + 1) % own.len.max(1);
        let (p, q, v) = (own.v[edge], own.v[next % M], other.v[deepest]);
        let (edge, next, deepest) = (edge as u32, next as u32, deepest as u32);
        let apex = self.support(u);
        if of_a {
            [(v - p, edge << 16 | deepest), (v - q, next << 16 | deepest), apex]
        } else {
            [(p - v, deepest << 16 | edge), (q - v, deepest << 16 | next), apex]
        }
    }

    /// Axis `slot` alone (A's edges first, then B's, as in [`Axes`]): its
    /// normal from A towards B (not unit), the least reach along it,
    /// computed as [`Axes::new`] computes them, to the bit, and whether the
    /// slot has an edge (one past either polygon's last edge is measured on
    /// some edge and flagged). No branch on the slot, which differs from pair
    /// to pair: both polygons' parts are picked by selects.
    #[inline(always)]
    pub fn axis(&self, slot: usize) -> (V2<R>, R, bool) {
        let of_a = slot < M;
        let (own, other) = core::hint::select_unpredictable(of_a, (&self.a, &self.b), (&self.b, &self.a));
        let edge = slot % M;
        let n = own.normal(edge);
        let least = reach(own, other, n, edge);
        (core::hint::select_unpredictable(of_a, n, -n), least, edge < own.len && slot < 2 * M)
    }
}

/// The pair's small polygons as a few axes read them: each one's
/// coordinates apart (B's placed, unused slots repeating vertex 0), and none
/// of the sixteen edge normals [`Polygons`] turns and keeps.
pub(crate) struct Coordinates<'s, R> {
    a: &'s [V2<R>],
    b: &'s [V2<R>],
    xs: [[R; M]; 2],
    ys: [[R; M]; 2],
}

impl<'s, R: Real> Coordinates<'s, R> {
    #[inline(always)]
    pub fn new<A, B>(pair: &Pair<'_, R, A, B>, a: &'s [V2<R>], b: &'s [V2<R>]) -> Self
    where
        A: SupportMap<R> + ?Sized,
        B: SupportMap<R> + ?Sized,
    {
        let padded = |v: &[V2<R>]| -> [V2<R>; M] {
            let first = v.first().copied().unwrap_or_default();
            core::array::from_fn(|i| v.get(i).copied().unwrap_or(first))
        };
        let (own_a, mut placed_b) = (padded(a), padded(b));
        for p in &mut placed_b {
            *p = pair.b_to_pair(*p);
        }
        let xs = [own_a.map(|p| p.x), placed_b.map(|p| p.x)];
        let ys = [own_a.map(|p| p.y), placed_b.map(|p| p.y)];
        Self { a, b, xs, ys }
    }

    /// [`Polygons::axis`] of the same pair, to the bit: the same products
    /// in the same order, on the same placed points.
    #[inline(always)]
    pub fn axis<A, B>(&self, pair: &Pair<'_, R, A, B>, slot: usize) -> (V2<R>, R, bool)
    where
        A: SupportMap<R> + ?Sized,
        B: SupportMap<R> + ?Sized,
    {
        let of_a = slot < M;
        let own = core::hint::select_unpredictable(of_a, self.a, self.b);
        let edge = slot % M;
        let exists = edge < own.len() && slot < 2 * M;
        let (p, q) = edge_ends(own, edge).unwrap_or_default();
        let n = (q - p).perp_cw();
        let (n, p) = if of_a { (n, p) } else { (pair.b_vector_to_pair(n), pair.b_to_pair(p)) };
        let other = usize::from(of_a);
        let least = least_dot(n, &self.xs[other], &self.ys[other]);
        (core::hint::select_unpredictable(of_a, n, -n), least - n.dot(p), exists)
    }
}

/// The ends of edge `i` of the counter-clockwise polygon `v`, the closing
/// edge ending at vertex 0; `None` past the last edge.
#[inline(always)]
fn edge_ends<R: Real>(v: &[V2<R>], i: usize) -> Option<(V2<R>, V2<R>)> {
    Some((*v.get(i)?, *v.get(i + 1).or(v.first())?))
}

/// Edge `slot` of the pair's small polygons (A's edges, then B's from slot
/// [`M`]) measured in the frame of its own polygon, its normal turned once
/// and no vertex of the other placed: what a cached axis costs to ask again.
struct AxisReach<'s, R> {
    own_is_a: bool,
    /// The edge's ends and outward normal (not unit), in its polygon's frame.
    p: V2<R>,
    q: V2<R>,
    n: V2<R>,
    /// The other polygon, the normal in its frame, and how far its nearest
    /// vertex lies beyond the edge's line, times `|n|`.
    other: &'s [V2<R>],
    d: V2<R>,
    reach: R,
}

impl<R: Real> AxisReach<'_, R> {
    /// The other polygon's first vertex nearest the edge's line, in its own
    /// frame (asked only where the distance is wanted: the verdict needs
    /// only the least dot product, a cheaper tree).
    #[inline(always)]
    fn nearest(&self) -> Option<V2<R>> {
        let first = self.other.first().copied().unwrap_or_default();
        let dots: [R; M] = core::array::from_fn(|i| -self.d.dot(self.other.get(i).copied().unwrap_or(first)));
        self.other.get(first_max(&dots)).copied()
    }
}

/// [`AxisReach`] of edge `slot`; `None` for a slot out of range. Which
/// polygon owns the edge is a coin toss from pair to pair: both ways are
/// computed and one picked, not branched on, and the least dot product is
/// a tree of minima over lanes padded with the first vertex (which leaves
/// the minimum as it is), not a chain over the slice.
#[inline(always)]
fn axis_reach<'s, R, A, B>(
    pair: &Pair<'_, R, A, B>,
    a: &'s [V2<R>],
    b: &'s [V2<R>],
    slot: usize,
) -> Option<AxisReach<'s, R>>
where
    R: Real,
    A: SupportMap<R> + ?Sized,
    B: SupportMap<R> + ?Sized,
{
    let own_is_a = slot < M;
    let (own, other) = core::hint::select_unpredictable(own_is_a, (a, b), (b, a));
    let (p, q) = edge_ends(own, core::hint::select_unpredictable(own_is_a, slot, slot.wrapping_sub(M)))?;
    let n = (q - p).perp_cw();
    // The normal in the other polygon's frame, and the offset of B's
    // reference from A's seen along the normal from the edge's side.
    let (to_b, to_pair) = (pair.pair_vector_to_b(n), pair.b_vector_to_pair(n));
    let offset = pair.pose().2;
    let (d, along_offset) =
        core::hint::select_unpredictable(own_is_a, (to_b, n.dot(offset)), (to_pair, -to_pair.dot(offset)));
    let first = other.first().copied().unwrap_or_default();
    let v: [V2<R>; M] = core::array::from_fn(|i| other.get(i).copied().unwrap_or(first));
    let reach = least_dot(d, &v.map(|p| p.x), &v.map(|p| p.y)) + along_offset - n.dot(p);
    Some(AxisReach { own_is_a, p, q, n, other, d, reach })
}

/// Whether edge `slot` of the pair's small polygons (A's edges, then B's
/// from slot [`M`]) separates them by more than `margin` times its normal's
/// length (by `|x| + |y|`), measured as [`AxisReach`] is. With a margin
/// above rounding, [`Axes::separated`] then says apart too.
pub(crate) fn separates_by<R, A, B>(pair: &Pair<'_, R, A, B>, a: &[V2<R>], b: &[V2<R>], slot: usize, margin: R) -> bool
where
    R: Real,
    A: SupportMap<R> + ?Sized,
    B: SupportMap<R> + ?Sized,
{
    axis_reach(pair, a, b, slot).is_some_and(|axis| axis.reach > margin * axis.n.l1())
}

/// Where vertex `v` lies beyond the edge from `p` to `q` (outward normal
/// `n`, not unit; `reach` the separation times its length) with its foot on
/// the edge: the separation, the unit normal and the foot. `None` where it
/// is not beyond, or its foot falls off the edge.
#[inline(always)]
fn foot_on_edge<R: Real>(p: V2<R>, q: V2<R>, n: V2<R>, v: V2<R>, reach: R) -> Option<(R, V2<R>, V2<R>)> {
    let along = (v - p).dot(q - p);
    let distance = scaled_separation(n, reach);
    let unit = n.try_normalize_inlined()?;
    let found = distance > R::ZERO && along >= R::ZERO && along <= (q - p).length_squared();
    found.then(|| (distance, unit, v - unit * distance))
}

/// The distance of two small polygons where their closest features are an
/// edge and a vertex whose foot lies on it (the common case), from axis
/// `slot` (A's edges, then B's): an axis whose nearest vertex has its foot
/// on the edge separates them by exactly their distance, as the foot is a
/// point of the edge's polygon that far from the vertex (no axis separates
/// them by more). The distance, the unit normal from A towards B, and the
/// closest points on A and on B; `None` where the axis does not separate
/// them or the vertex's foot falls off the edge (two vertices closest, or
/// another axis's edge).
///
/// Measured as the axes are ([`Axes::new`]), in the pair frame on B's
/// placed vertices, but for the one axis alone: no polygon laid out, and
/// the rounding of the answer the axes' own.
pub(crate) fn face_and_vertex_placed<R, A, B>(
    pair: &Pair<'_, R, A, B>,
    a: &[V2<R>],
    b: &[V2<R>],
    slot: usize,
) -> Option<FaceAndVertex<R>>
where
    R: Real,
    A: SupportMap<R> + ?Sized,
    B: SupportMap<R> + ?Sized,
{
    // The other polygon's vertices in the pair frame, padded as `Padded`
    // pads them; the first nearest to the edge's line along `n`, and how
    // far beyond the line through `p` the nearest reaches (times `|n|`).
    let nearest = |v: [V2<R>; M], n: V2<R>, p: V2<R>| {
        let (xs, ys) = (v.map(|v| v.x), v.map(|v| v.y));
        (v[first_max(&v.map(|v| -v.dot(n)))], least_dot(n, &xs, &ys) - n.dot(p))
    };
    if slot < M {
        let (p, q) = edge_ends(a, slot)?;
        let n = (q - p).perp_cw();
        let (v, reach) = nearest(padded(b, |p| pair.b_to_pair(p)), n, p);
        let (distance, unit, foot) = foot_on_edge(p, q, n, v, reach)?;
        Some((distance, unit, foot, v))
    } else {
        let (p, q) = edge_ends(b, slot.checked_sub(M)?)?;
        let n = pair.b_vector_to_pair((q - p).perp_cw());
        let (p, q) = (pair.b_to_pair(p), pair.b_to_pair(q));
        let (v, reach) = nearest(padded(a, |p| p), n, p);
        let (distance, unit, foot) = foot_on_edge(p, q, n, v, reach)?;
        Some((distance, -unit, v, foot))
    }
}

/// Up to [`M`] vertices placed by `place`, the unused slots copies of the
/// first, as [`Padded`] holds them.
#[inline(always)]
fn padded<R: Real>(vertices: &[V2<R>], place: impl Fn(V2<R>) -> V2<R>) -> [V2<R>; M] {
    let first = vertices.first().copied().unwrap_or_default();
    let mut v: [V2<R>; M] = core::array::from_fn(|i| vertices.get(i).copied().unwrap_or(first));
    // A loop, not `map`, as in `Padded::new`.
    for p in &mut v {
        *p = place(*p);
    }
    v
}

/// [`face_and_vertex_placed`], measured as [`AxisReach`] is, only the
/// nearest vertex (or the edge) placed. `None` also where the axis
/// separates by no more than `margin` times its normal's length (by
/// `|x| + |y|`): with a margin above rounding, an answer proves the
/// polygons apart as [`separates_by`] does, in the same pass.
pub(crate) fn face_and_vertex_by<R, A, B>(
    pair: &Pair<'_, R, A, B>,
    a: &[V2<R>],
    b: &[V2<R>],
    slot: usize,
    margin: R,
) -> Option<FaceAndVertex<R>>
where
    R: Real,
    A: SupportMap<R> + ?Sized,
    B: SupportMap<R> + ?Sized,
{
    let axis = axis_reach(pair, a, b, slot)?;
    let AxisReach { own_is_a, p, q, n, reach, .. } = axis;
    (reach > margin * n.l1()).then_some(())?;
    let nearest = axis.nearest()?;
    if own_is_a {
        let v = pair.b_to_pair(nearest);
        let (distance, unit, foot) = foot_on_edge(p, q, n, v, reach)?;
        Some((distance, unit, foot, v))
    } else {
        let (p, q, m) = (pair.b_to_pair(p), pair.b_to_pair(q), pair.b_vector_to_pair(n));
        let (distance, unit, foot) = foot_on_edge(p, q, m, nearest, reach)?;
        Some((distance, -unit, nearest, foot))
    }
}

/// What the separating axes say about two polygon cores.
pub(crate) struct Axes<R> {
    normals: [V2<R>; 2 * M],
    least: [R; 2 * M],
}

impl<R: Real> Axes<R> {
    /// The separating axes of the pair's two small polygons (`a`, `b`, as
    /// [`Pair::small_polygons`] gives them).
    #[inline(always)]
    pub fn new<A, B>(pair: &Pair<'_, R, A, B>, a: &[V2<R>], b: &[V2<R>]) -> Self
    where
        A: SupportMap<R> + ?Sized,
        B: SupportMap<R> + ?Sized,
    {
        Self::of(&Polygons::new(pair, a, b))
    }

    /// [`new`](Self::new) in four f64 lanes a register, for code compiled
    /// for them (`run_wide`); elsewhere the same.
    #[cfg(all(target_arch = "x86_64", target_feature = "sse2"))]
    #[inline(always)]
    pub fn new_wide<A, B>(pair: &Pair<'_, R, A, B>, a: &[V2<R>], b: &[V2<R>]) -> Self
    where
        A: SupportMap<R> + ?Sized,
        B: SupportMap<R> + ?Sized,
    {
        Self::of_lanes::<true>(&Polygons::new(pair, a, b))
    }

    /// [`new`](Self::new), measured in code compiled for AVX2's four f64
    /// lanes where the processor has them (`run_wide`).
    #[inline(always)]
    pub fn new_in_wide_lanes<A, B>(pair: &Pair<'_, R, A, B>, a: &[V2<R>], b: &[V2<R>]) -> Self
    where
        A: SupportMap<R> + ?Sized,
        B: SupportMap<R> + ?Sized,
    {
        #[cfg(all(target_arch = "x86_64", target_feature = "sse2"))]
        if R::wide_lanes() {
            return crate::real::run_wide(
                #[inline(always)]
                || Self::new_wide(pair, a, b),
            );
        }
        Self::new(pair, a, b)
    }

    /// Every axis of the two polygons.
    #[inline(always)]
    pub fn of(polygons: &Polygons<R>) -> Self {
        Self::of_lanes::<false>(polygons)
    }

    /// [`of`](Self::of), in four f64 lanes a register where `WIDE`.
    #[inline(always)]
    fn of_lanes<const WIDE: bool>(polygons: &Polygons<R>) -> Self {
        let (pa, pb) = (&polygons.a, &polygons.b);
        let (na, la) = faces::<R, WIDE>(pa, pb);
        let (nb, lb) = faces::<R, WIDE>(pb, pa);
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
    #[inline(always)]
    pub fn separated(&self) -> bool {
        self.least.iter().fold(false, |any, &s| any | (s > R::ZERO))
    }

    /// The least overlap along a unit normal, and that normal (from A
    /// towards B): the penetration depth and normal of overlapping
    /// polygons. Ties go to the first axis, A's before B's.
    #[inline(always)]
    pub fn penetration(&self) -> (R, V2<R>) {
        let (separation, best) = self.separations();
        penetration_along(separation[best], self.normals[best])
    }

    /// The axis of the least overlap of overlapping polygons, picked by the
    /// overlap's square over the normal's (no square root), and its normal
    /// from A towards B (not unit).
    pub fn least_overlap_by_square(&self) -> (usize, V2<R>) {
        let key: [R; 2 * M] = core::array::from_fn(|i| {
            let (least, nn) = (self.least[i], self.normals[i].length_squared());
            if nn > R::ZERO {
                -(least * least / nn)
            } else {
                -R::INFINITY
            }
        });
        let best = first_max(&key);
        (best, self.normals[best])
    }

    /// The axis that separates the polygons the most, measured unscaled
    /// (a cheap pick: any axis that separates proves it).
    #[inline(always)]
    pub fn most_separating(&self) -> usize {
        first_max(&self.least)
    }

    /// The axis that separates the polygons the most along its unit
    /// normal, picked by the separation's square over the normal's (no
    /// square root; a pick that under- or overflows is merely not the best,
    /// which [`face_and_vertex_placed`] does not rely on).
    #[inline(always)]
    pub fn most_separating_by_square(&self) -> usize {
        let key: [R; 2 * M] = core::array::from_fn(|i| {
            let (least, nn) = (self.least[i], self.normals[i].length_squared());
            let key = least * least / nn;
            if least > R::ZERO && nn > R::ZERO {
                key
            } else {
                -R::INFINITY
            }
        });
        first_max(&key)
    }

    /// [`penetration`](Self::penetration), with the `count` axes of the
    /// greatest separation (a bit per slot) and how far the first of them
    /// leads every other axis: how much the axes may move before one not
    /// among them could win.
    #[inline(always)]
    pub fn penetration_leaders(&self, count: usize) -> ((R, V2<R>), u32, R) {
        let (mut separation, best) = self.separations();
        let answer = penetration_along(separation[best], self.normals[best]);
        let first = separation[best];
        let (mut leaders, mut next) = (0u32, best);
        for _ in 0..count {
            leaders |= 1 << next;
            separation[next] = -R::INFINITY;
            next = first_max(&separation);
        }
        (answer, leaders, first - separation[next])
    }

    /// Every axis's separation along its unit normal (minus infinity for
    /// slots with no edge), and the first greatest.
    #[inline(always)]
    fn separations(&self) -> ([R; 2 * M], usize) {
        let (nx, ny) = (self.normals.map(|n| n.x), self.normals.map(|n| n.y));
        let separation = R::scaled_separations(&nx, &ny, &self.least);
        let best = first_max(&separation);
        (separation, best)
    }
}

/// The depth and unit normal of the axis whose separation is `separation`.
#[inline(always)]
pub(crate) fn penetration_along<R: Real>(separation: R, normal: V2<R>) -> (R, V2<R>) {
    let normal = normal.try_normalize_inlined().unwrap_or(V2::new(R::ONE, R::ZERO));
    // From zero: a separation of -0 is a depth of +0.
    (R::ZERO - separation, normal)
}
