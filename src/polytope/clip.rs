//! Ray casts at convex polygons (counter-clockwise vertices) by clipping
//! the ray with each edge's half-plane: every edge, every edge at once in
//! lanes for small polygons, or only the edges a binary search finds where
//! the ray's line crosses the boundary.

#[cfg(not(any(target_os = "none", target_family = "wasm")))]
use super::SMALL_POLYGON_MAX;
use super::{at, first_reached, polytope_support};
use crate::real::{Real, V2};
use crate::result::{gap_hit, RayCast, RayHit, RayOutcome};

/// [`cast_ray_polygon`] for a polygon of at most [`SMALL_POLYGON_MAX`]
/// vertices, every edge clipped at once: the same per-edge numerators,
/// denominators and quotients, then the latest entry and the earliest exit
/// taken by selects over the lanes. On hosts, where the clip's branches (is
/// this edge entered, left, the new latest?) change from ray to ray and a
/// predictor misses them. Inlined, so that its answer comes back in
/// registers, not through a copy on the stack.
#[cfg(not(any(target_os = "none", target_family = "wasm")))]
#[inline(always)]
pub(crate) fn cast_ray_small_polygon<R: Real>(
    vertices: &[V2<R>],
    o: V2<R>,
    d: V2<R>,
    max: R,
    rounding: FaceRounding<R>,
) -> FaceCast<R> {
    const M: usize = SMALL_POLYGON_MAX;
    let n = vertices.len().min(M);
    let first = vertices.first().copied().unwrap_or_default();
    // Unused slots copy the first vertex: their edges are empty, with a zero
    // normal, and clip nothing.
    let v: [V2<R>; M] = core::array::from_fn(|i| vertices.get(i).copied().unwrap_or(first));
    let next: [V2<R>; M] = core::array::from_fn(|i| if i + 1 < n { v[(i + 1) % M] } else { first });
    let mut lower = [-R::INFINITY; M];
    let mut upper = [max; M];
    // The same faces moved inwards by the rounding, as the clip has them.
    let mut inner_lower = [R::ZERO; M];
    let mut inner_upper = [max; M];
    let mut outer_exit = [max; M];
    let (mut entered, mut parallel_outside, mut inner_parallel_outside) = (false, false, false);
    for i in 0..M {
        let normal = (next[i] - v[i]).perp_cw();
        // Positive when the origin is on the inner side of this edge.
        let numerator = normal.dot(v[i] - o);
        let denominator = normal.dot(d);
        let t = numerator / denominator;
        // Entered beyond the origin (t > 0), or left before `max`.
        let entering = (denominator < R::ZERO) & (numerator < R::ZERO);
        let leaving = denominator > R::ZERO;
        entered |= entering;
        lower[i] = core::hint::select_unpredictable(entering, t, -R::INFINITY);
        upper[i] = core::hint::select_unpredictable(leaving, t, max);
        parallel_outside |= (denominator == R::ZERO) & (numerator < R::ZERO);
        let (inner_numerator, inner_denominator) = rounding.moved_in(normal, numerator, denominator);
        let inner_t = inner_numerator / inner_denominator;
        let inner_entering = (inner_denominator < R::ZERO) & (inner_numerator < R::ZERO);
        inner_lower[i] = core::hint::select_unpredictable(inner_entering, inner_t, R::ZERO);
        inner_upper[i] = core::hint::select_unpredictable(inner_denominator > R::ZERO, inner_t, max);
        inner_parallel_outside |= (inner_denominator == R::ZERO) & (inner_numerator < R::ZERO);
        let (outer_numerator, outer_denominator) = rounding.moved_out(normal, numerator, denominator);
        let outer_t = outer_numerator / outer_denominator;
        outer_exit[i] = core::hint::select_unpredictable(outer_denominator > R::ZERO, outer_t, max);
    }
    let entry = latest_entry(&lower);
    let mut exit = upper[0];
    let mut inner = Span { lower: inner_lower[0], upper: inner_upper[0] };
    let mut latest_exit = outer_exit[0];
    for i in 1..M {
        exit = exit.min(upper[i]);
        inner = Span { lower: inner.lower.max(inner_lower[i]), upper: inner.upper.min(inner_upper[i]) };
        latest_exit = latest_exit.min(outer_exit[i]);
    }
    let t = if entered { lower[entry] } else { R::ZERO };
    // A subnormal denominator (a ray parallel to a face to rounding) sends t
    // to infinity: no entry, a miss.
    if parallel_outside | (exit < t) | !t.is_finite() {
        return FaceCast::none(FaceVerdict::Miss);
    }
    if !entered {
        return FaceCast::none(FaceVerdict::Inside);
    }
    let normal = (next[entry] - v[entry]).perp_cw();
    let late = rounding.late(t, inner, inner_parallel_outside, latest_exit);
    let t = edge_hit(&v[..n], entry, (o, d), (t, exit), rounding);
    FaceCast { verdict: FaceVerdict::Hit, t, normal, late }
}

/// A cast in face form as plain numbers: a caller keeps them in
/// registers, where a [`RayOutcome`] with its payload was built in memory
/// and read back before it had been written out (a store the load could
/// not forward).
#[cfg(not(any(target_os = "none", target_family = "wasm")))]
#[derive(Clone, Copy)]
pub(crate) struct FaceCast<R> {
    pub verdict: FaceVerdict,
    /// Along the ray, and the entered face's outward normal (not unit) and
    /// how much later an exact ray may enter: zero but for a hit.
    pub t: R,
    pub normal: V2<R>,
    pub late: R,
}

#[cfg(not(any(target_os = "none", target_family = "wasm")))]
#[derive(Clone, Copy, PartialEq, Eq)]
pub(crate) enum FaceVerdict {
    Hit,
    Miss,
    Inside,
}

#[cfg(not(any(target_os = "none", target_family = "wasm")))]
impl<R: Real> FaceCast<R> {
    fn none(verdict: FaceVerdict) -> Self {
        Self { verdict, t: R::ZERO, normal: V2::zero(), late: R::ZERO }
    }
}

/// The lane of the latest entry: the one a scan from lane 0 keeps, taking
/// a lane only when it is greater (the first of ties; never a NaN, and a
/// NaN in lane 0 is never left). Found by halving the lanes, not by that
/// scan, whose selects each waited for the one before: the cast's longest
/// wait.
#[cfg(not(any(target_os = "none", target_family = "wasm")))]
#[inline(always)]
fn latest_entry<R: Real>(lower: &[R; SMALL_POLYGON_MAX]) -> usize {
    let mut ranked = *lower;
    for (i, value) in ranked.iter_mut().enumerate() {
        #[allow(clippy::eq_op)]
        if *value != *value {
            *value = if i == 0 { R::INFINITY } else { -R::INFINITY };
        }
    }
    super::first_max(&ranked)
}

/// The distance of the hit at `t` through edge `i` (from vertex `i` to the
/// next), or of an end of the edge where rounding put the ray's point past one: a ray
/// along a neighbouring face, outside it by less than rounding, crosses
/// this edge's line beyond the vertex they share, by the miss over the sine
/// of their angle, which is far off the polygon for a sliver. The end's own
/// distance along the ray is then the hit's, so its point lies on the
/// boundary within the miss. Where the next edge that way goes on along the
/// line through the point (a vertex on an edge: the clip may enter a run of
/// collinear edges by any of them), the point is on the boundary already,
/// and the walk goes on to that edge. A ray along the edge itself meets
/// the boundary where [`along_edge`] says.
#[inline(always)]
fn edge_hit<R: Real>(
    vertices: &[V2<R>],
    i: usize,
    (o, d): (V2<R>, V2<R>),
    (t, exit): (R, R),
    rounding: FaceRounding<R>,
) -> R {
    if let Some(first) = along_edge(vertices, i, (o, d), rounding.on_line()).filter(|&first| first < t) {
        return first.max(R::ZERO).min(exit);
    }
    let n = vertices.len();
    let p = o + d * t;
    let mut k = i;
    let mut end = None;
    // Each step moves one edge along a run of them on one line: at most n.
    for _ in 0..n {
        let (a, b) = (at(vertices, k), at(vertices, wrap(k + 1, n)));
        let along = (p - a).dot(b - a);
        let (vertex, beyond, step) = if along < R::ZERO {
            (a, at(vertices, wrap(k + n - 1, n)), n - 1)
        } else if along > (b - a).dot(b - a) {
            (b, at(vertices, wrap(k + 2, n)), 1)
        } else {
            end = None;
            break;
        };
        end = Some(vertex);
        if !rounding.goes_on(vertex, beyond, p, t) {
            break;
        }
        k = wrap(k + step, n);
    }
    end.map_or(t, |end| (end - o).dot(d).max(R::ZERO).min(exit))
}

/// Where a ray that runs along edge `i` (both its ends within `reach` of
/// the ray's line) first meets the boundary: at the end it reaches first,
/// or at the first vertex of a run of them along the line before that end.
/// The clip's crossing of such an edge's line is rounding alone, anywhere
/// along the edge or past it. `None` for any other edge.
#[inline(always)]
fn along_edge<R: Real>(vertices: &[V2<R>], i: usize, (o, d): (V2<R>, V2<R>), reach: R) -> Option<R> {
    let n = vertices.len();
    let near = |q: V2<R>| d.cross(q - o).abs() <= reach;
    let (a, b) = (at(vertices, i), at(vertices, wrap(i + 1, n)));
    if !(near(a) && near(b)) {
        return None;
    }
    // Back along the ray, round the ring the other way from the edge's
    // direction of travel.
    let (mut first, step) = if (b - a).dot(d) > R::ZERO { (i, n - 1) } else { (wrap(i + 1, n), 1) };
    for _ in 0..n {
        let before = wrap(first + step, n);
        let (p, q) = (at(vertices, first), at(vertices, before));
        if !near(q) || (q - p).dot(d) >= R::ZERO {
            break;
        }
        first = before;
    }
    Some((at(vertices, first) - o).dot(d))
}

/// Clips the ray against each edge's half-plane (counter-clockwise vertices):
/// the hit is the last entry, its normal the entered face's. Every cast
/// here answers in face form
/// ([`SupportMap::cast_local_face_ray`](crate::SupportMap::cast_local_face_ray)).
pub(crate) fn cast_ray_polygon<R: Real>(
    vertices: &[V2<R>],
    o: V2<R>,
    d: V2<R>,
    max: R,
    rounding: FaceRounding<R>,
) -> RayCast<R> {
    let mut clip = Clip::new(o, d, max, rounding);
    for (k, (&a, &b)) in vertices.iter().zip(vertices.iter().skip(1).chain(vertices.first())).enumerate() {
        if clip.misses(k, a, b) {
            return RayCast::closed_form(RayOutcome::Miss);
        }
    }
    clip.outcome(vertices)
}

/// The ray's line meets a convex polygon's boundary on two edges: one on
/// the chain that faces the ray (counter-clockwise from the vertex farthest
/// to the ray's left to the one farthest to its right), one on the chain
/// that faces away. Along each chain the vertices' side of the line changes
/// monotonically, so a binary search finds where it changes, in O(log n).
/// Only the edges there are clipped against (the far crossing only when the
/// origin is past the near one): the scan's clip, with the scan's result
/// wherever the decisive edges are among them.
///
/// Rounding can misplace the change among vertices within rounding of the
/// line (`slack`, from `reach`, a bound on the vertices' distance from the
/// ray's origin): every edge that touches them is clipped. A line within
/// rounding of a tangent has no reliable crossing (edges along it give
/// none); `None` then leaves the ray to the scan.
pub(crate) fn cast_ray_many_sided<R: Real, const N: usize>(
    v: &[V2<R>],
    o: V2<R>,
    d: V2<R>,
    max: R,
    reach: R,
    rounding: FaceRounding<R>,
) -> Option<RayCast<R>> {
    let n = v.len();
    let left = d.perp();
    let side = |i: usize| left.dot(at(v, i) - o);
    // `side` rounds by at most 3 eps |v - o|_1 <= 3 sqrt(2) eps reach.
    let slack = R::from_u32(8) * R::EPSILON * reach;
    let leftmost = polytope_support::<R, N>(v, left).0;
    let rightmost = polytope_support::<R, N>(v, -left).0;
    let (farthest_left, farthest_right) = (side(leftmost), side(rightmost));
    // The line passes the polygon by.
    if farthest_left < -slack || farthest_right > slack {
        return Some(RayCast::closed_form(RayOutcome::Miss));
    }
    // Within rounding of a tangent: the scan decides.
    if farthest_left <= slack || farthest_right >= -slack {
        return None;
    }
    let is_left = |i: usize| side(i) > slack;
    let is_right = |i: usize| side(i) < -slack;
    let entry = first_vertex_reaching(n, leftmost, rightmost, |i| side(i) <= R::ZERO)?;
    let mut clip = Clip::new(o, d, max, rounding);
    if clip.misses_around(v, entry, is_left, is_right) {
        return Some(RayCast::closed_form(RayOutcome::Miss));
    }
    // Entered ahead of the origin: the line leaves the polygon farther on,
    // so the hit stands without the search for where.
    if clip.entered.is_none() {
        let exit = first_vertex_reaching(n, rightmost, leftmost, |i| side(i) >= R::ZERO)?;
        if clip.misses_around(v, exit, is_right, is_left) {
            return Some(RayCast::closed_form(RayOutcome::Miss));
        }
    }
    Some(clip.outcome(v))
}

/// On the chain counter-clockwise from vertex `from` to vertex `to` (where
/// `reached` holds), the first vertex where it holds, if the chain is not
/// empty.
fn first_vertex_reaching(n: usize, from: usize, to: usize, reached: impl Fn(usize) -> bool) -> Option<usize> {
    let length = wrap(to + n - from, n);
    if length == 0 {
        return None;
    }
    // The first step in 1..=length with `reached`, which holds at `length`.
    let step = first_reached(1, length, |step| reached(wrap(from + step, n)));
    Some(wrap(from + step, n))
}

/// A cast in face form as [`SupportMap::cast_local_ray`](crate::SupportMap::cast_local_ray)
/// gives it: the unit normal (the ray's reverse for a face too small to
/// have one), and the gap across the face, the lateness times the
/// incidence. Out of line on bare metal, so that one copy serves every
/// polygon type a firmware's trait objects link.
#[cfg_attr(target_os = "none", inline(never))]
pub(crate) fn face_cast_to_local<R: Real>(cast: Option<RayCast<R>>, direction: R::Vector) -> Option<RayCast<R>> {
    let (cast, d) = (cast?, V2::<R>::from_glam(direction));
    let outcome = match cast.outcome {
        RayOutcome::Hit(h) => {
            let normal = V2::from_glam(h.normal).try_normalize().unwrap_or(-d);
            let gap = h.error_bound * normal.dot(d).abs();
            RayOutcome::Hit(RayHit { normal: normal.to_glam(), error_bound: gap, ..h })
        }
        other => other,
    };
    Some(RayCast { outcome, ..cast })
}

/// `i mod n` for `i < 2 n`, without a division.
#[inline(always)]
fn wrap(i: usize, n: usize) -> usize {
    if i >= n {
        i - n
    } else {
        i
    }
}

/// How far rounding may have moved a polygon's faces across a ray: at the
/// scale of the ray's origin, the shape's reference point and its size
/// (`across`), and by 8 eps per unit along the ray, as the hit's error bound
/// models it ([`Gjk::raycast`](crate::Gjk::raycast)); and the shape's size
/// (at least its bounding radius).
#[derive(Clone, Copy, Debug)]
pub(crate) struct FaceRounding<R> {
    across: R,
    size: R,
}

impl<R: Real> FaceRounding<R> {
    /// For a ray from `o` (relative to the shape's `reference` point) at a
    /// shape of bounding radius at most `size`.
    #[inline(always)]
    pub fn new(o: V2<R>, reference: V2<R>, size: R) -> Self {
        Self { across: R::from_u32(8) * R::EPSILON * (o.l1() + reference.l1() + size), size }
    }
}

impl<R: Real> FaceRounding<R> {
    /// A face's clip (`numerator`, `denominator`, for its outward `normal`)
    /// with the face moved inwards by the rounding: by `across` and by 8 eps
    /// per unit of distance along the ray, in units of `|normal|_1` (at least
    /// its length, and no square root).
    #[inline(always)]
    fn moved_in(&self, normal: V2<R>, numerator: R, denominator: R) -> (R, R) {
        self.moved(normal, numerator, denominator, R::ONE)
    }

    /// The same, moved outwards: where the ray may leave at the latest.
    #[inline(always)]
    fn moved_out(&self, normal: V2<R>, numerator: R, denominator: R) -> (R, R) {
        self.moved(normal, numerator, denominator, -R::ONE)
    }

    #[inline(always)]
    fn moved(&self, normal: V2<R>, numerator: R, denominator: R, inwards: R) -> (R, R) {
        let length = normal.l1() * inwards;
        (numerator - self.across * length, denominator + R::from_u32(8) * R::EPSILON * length)
    }

    /// Whether the boundary goes on from `vertex` towards `beyond` through
    /// the ray's point `p` (at `t` along it): `p` lies that way from the
    /// vertex, on the edge's line to within what rounding may move a face.
    #[inline(always)]
    fn goes_on(&self, vertex: V2<R>, beyond: V2<R>, p: V2<R>, t: R) -> bool {
        let (e, q) = (beyond - vertex, p - vertex);
        e.dot(q) > R::ZERO && e.cross(q).abs() <= self.reach(t) * e.l1()
    }

    /// How far from the ray's line a vertex may be and count as on it: the
    /// rounding of one coordinate, not a face's (which adds up several),
    /// so a hit moved to the vertex stays on the boundary to rounding.
    #[inline(always)]
    fn on_line(&self) -> R {
        self.across / R::from_u32(8)
    }

    /// How far rounding may move a face across the ray `t` along it.
    #[inline(always)]
    fn reach(&self, t: R) -> R {
        self.across + R::from_u32(8) * R::EPSILON * t.abs()
    }

    /// How much later than `t` an exact ray may enter: where the faces
    /// moved in are entered, no later than they are; where they are not
    /// (the exact ray may miss, or cross a sliver), no later than the faces
    /// moved out are left (`outer_exit`), and never more than twice the
    /// size.
    fn late(&self, t: R, inner: Span<R>, inner_empty: bool, outer_exit: R) -> R {
        let missed = inner_empty || inner.upper < inner.lower || !inner.lower.is_finite();
        let latest = if missed { outer_exit.min(t + R::TWO * self.size) } else { inner.lower };
        (latest - t).max(R::ZERO)
    }
}

/// Where a line enters (`lower`) and leaves (`upper`) an intersection of
/// half-planes, clipped one at a time.
#[derive(Clone, Copy)]
struct Span<R> {
    lower: R,
    upper: R,
}

impl<R: Real> Span<R> {
    /// Clips by the half-plane where `numerator - t denominator >= 0`:
    /// whether the span is now empty, and whether this raised its entry.
    #[inline(always)]
    fn clip(&mut self, numerator: R, denominator: R) -> (bool, bool) {
        if denominator == R::ZERO {
            return (numerator < R::ZERO, false);
        }
        if denominator < R::ZERO {
            // Entering. t = numerator / denominator > lower, multiplied out
            // (denominator < 0 flips it): one division per update, not per
            // edge. A subnormal denominator (a ray parallel to the face to
            // rounding) sends t to infinity: no entry, empty.
            if numerator < self.lower * denominator {
                self.lower = numerator / denominator;
                return (self.upper < self.lower || !self.lower.is_finite(), true);
            }
        } else if numerator < self.upper * denominator {
            // Leaving: t < upper.
            self.upper = numerator / denominator;
            return (self.upper < self.lower, false);
        }
        (false, false)
    }
}

/// The ray clipped by edge half-planes, one at a time (Cyrus-Beck): where
/// it enters and leaves the intersection of those seen so far. Beside it,
/// the ray clipped by the same faces moved inwards by what rounding may
/// have moved them ([`FaceRounding`]): where a ray passes a vertex within
/// rounding along a grazing face, the exact ray may enter through that face
/// far later than the hit, or miss, and the hit's error bound must say so.
struct Clip<R: Real> {
    o: V2<R>,
    d: V2<R>,
    span: Span<R>,
    /// The edge the ray last entered through (by its first vertex), and
    /// its normal.
    entered: Option<(usize, V2<R>)>,
    rounding: FaceRounding<R>,
    inner: Span<R>,
    inner_empty: bool,
    /// Where the ray leaves the faces moved outwards, at the latest.
    outer_exit: R,
}

impl<R: Real> Clip<R> {
    #[inline(always)]
    fn new(o: V2<R>, d: V2<R>, max: R, rounding: FaceRounding<R>) -> Self {
        let span = Span { lower: R::ZERO, upper: max };
        Self { o, d, span, entered: None, rounding, inner: span, inner_empty: false, outer_exit: max }
    }

    /// Clips by the inner side of edge `k`, from `a` to `b`; true when the
    /// ray certainly misses.
    #[inline(always)]
    fn misses(&mut self, k: usize, a: V2<R>, b: V2<R>) -> bool {
        let normal = (b - a).perp_cw();
        // Positive when the origin is on the inner side of this edge.
        let numerator = normal.dot(a - self.o);
        let denominator = normal.dot(self.d);
        let (inner_numerator, inner_denominator) = self.rounding.moved_in(normal, numerator, denominator);
        self.inner_empty |= self.inner.clip(inner_numerator, inner_denominator).0;
        let (outer_numerator, outer_denominator) = self.rounding.moved_out(normal, numerator, denominator);
        if outer_denominator > R::ZERO && outer_numerator < self.outer_exit * outer_denominator {
            self.outer_exit = outer_numerator / outer_denominator;
        }
        let (empty, raised) = self.span.clip(numerator, denominator);
        if raised {
            self.entered = Some((k, normal));
        }
        empty
    }

    /// Clips by the edges around `vertex`, where a chain crosses the ray's
    /// line: from the last vertex before it clearly on the side the chain
    /// comes from to the first clearly on the side it goes to. True when the
    /// ray certainly misses. Each walk is bounded by the vertex count.
    fn misses_around(
        &mut self,
        v: &[V2<R>],
        vertex: usize,
        came_from: impl Fn(usize) -> bool,
        goes_to: impl Fn(usize) -> bool,
    ) -> bool {
        let n = v.len();
        let mut first = wrap(vertex + n - 1, n);
        let mut steps = 0;
        while !came_from(first) && steps < n {
            first = wrap(first + n - 1, n);
            steps += 1;
        }
        let mut last = vertex;
        while !goes_to(last) && steps < n {
            last = wrap(last + 1, n);
            steps += 1;
        }
        let mut k = first;
        while k != last && steps < 2 * n {
            let next = wrap(k + 1, n);
            if self.misses(k, at(v, k), at(v, next)) {
                return true;
            }
            k = next;
            steps += 1;
        }
        false
    }

    /// The hit, or inside, of the ray clipped by every edge that decides it
    /// among `vertices`.
    fn outcome(self, vertices: &[V2<R>]) -> RayCast<R> {
        RayCast::closed_form(match self.entered {
            None => RayOutcome::Inside,
            Some((edge, normal)) => {
                let t = self.span.lower;
                let late = self.rounding.late(t, self.inner, self.inner_empty, self.outer_exit);
                let t = edge_hit(vertices, edge, (self.o, self.d), (t, self.span.upper), self.rounding);
                gap_hit(self.o, self.d, t, normal, late)
            }
        })
    }
}

#[cfg(all(test, not(any(target_os = "none", target_family = "wasm"))))]
mod tests {
    use super::{latest_entry, SMALL_POLYGON_MAX};

    /// The scan the halving replaces.
    fn scanned(lower: &[f64; SMALL_POLYGON_MAX]) -> usize {
        let mut entry = 0;
        for i in 1..SMALL_POLYGON_MAX {
            if lower[i] > lower[entry] {
                entry = i;
            }
        }
        entry
    }

    /// Every array of eight lanes drawn from values that tie, order, and
    /// poison comparisons (NaN, both infinities, both zeros): the same lane.
    #[test]
    fn latest_entry_is_the_scans_lane() {
        let values = [f64::NAN, -f64::INFINITY, f64::INFINITY, -0.0, 0.0, 1.0, 2.0];
        let mut state = 0x2545_F491_4F6C_DD1Du64;
        for _ in 0..200_000 {
            let mut lower = [0.0; SMALL_POLYGON_MAX];
            for lane in &mut lower {
                state ^= state << 13;
                state ^= state >> 7;
                state ^= state << 17;
                *lane = values[(state % values.len() as u64) as usize];
            }
            assert_eq!(latest_entry(&lower), scanned(&lower), "{lower:?}");
        }
    }
}
