//! Convex polygons given by their vertices, as shapes and queries both work
//! on them: the support vertex (scanned, searched, or walked to from the
//! last one), vertex access that cannot panic, and ray casts that clip the
//! ray by the edges ([`clip`]). [`Polygon`](crate::Polygon) and
//! [`Rectangle`](crate::Rectangle) build on them, and so do EPA's polytope,
//! the separating-axis test and the ray query's path for small polygons.

mod clip;
#[cfg(not(any(target_os = "none", target_family = "wasm")))]
mod compass;

pub(crate) use clip::{cast_ray_many_sided, cast_ray_polygon, face_cast_to_local, FaceRounding};
#[cfg(not(any(target_os = "none", target_family = "wasm")))]
pub(crate) use clip::{cast_ray_small_polygon, FaceVerdict};

use crate::real::{Real, V2};
#[cfg(not(any(target_os = "none", target_family = "wasm")))]
pub(crate) use compass::{write as write_compass, Compass, SLOTS as COMPASS_SLOTS};

/// The most vertices a polygon may have for the separating-axis test.
#[cfg(not(any(target_os = "none", target_family = "wasm")))]
pub const SMALL_POLYGON_MAX: usize = 8;

/// `items[i % len]`, and `T::default()` for an empty slice: cyclic access to
/// polygon and polytope vertices that can never panic (the callers' indices
/// are in range; this keeps bounds checks and divisions by zero provably out
/// of the code, which the firmware's no-panic link check verifies).
#[inline(always)]
pub(crate) fn cyclic<T: Copy + Default>(items: &[T], i: usize) -> T {
    match items.len() {
        0 => T::default(),
        n => items.get(i % n).copied().unwrap_or_default(),
    }
}

/// Up to this many vertices a polytope is scanned, beyond it searched in
/// O(log n): for its support here, and for a ray cast
/// ([`cast_ray_many_sided`]).
const LINEAR_SCAN_MAX: usize = 24;

/// Whether a polytope of capacity `N` and `len` vertices is searched rather
/// than scanned: for small capacities no search is even compiled in.
#[inline(always)]
pub(crate) const fn searched<const N: usize>(len: usize) -> bool {
    N > LINEAR_SCAN_MAX && len > LINEAR_SCAN_MAX
}

/// Support of a polytope core given as a vertex slice, as (index, vertex):
/// a linear scan, or an O(log n) search over edge directions where
/// [`searched`]. No indexing can panic: an empty slice gives vertex 0 at
/// the origin.
///
/// Out of line on bare-metal targets, like [`polytope_support_near`]: one
/// copy then serves both shapes of a pair and every call site. Hosts inline
/// it for speed.
#[cfg_attr(target_os = "none", inline(never))]
#[cfg_attr(not(target_os = "none"), inline)]
pub(crate) fn polytope_support<R: Real, const N: usize>(vertices: &[V2<R>], d: V2<R>) -> (usize, V2<R>) {
    if searched_here::<R, N>(vertices.len()) {
        let (k, _) = hill_climb(vertices, d, angular_search(vertices, d), vertices.len());
        return (k, at(vertices, k));
    }
    scan_support(vertices, d)
}

/// The first vertex of largest dot product with `d`. On hosts its index is
/// kept by a select, not a branch: which vertex leads changes from query to
/// query, and a branch on it is mispredicted about twice in an 8-gon's scan.
/// Microcontrollers have no predictor to miss, and there the branch is the
/// fewer instructions. Both give the same vertex, to the bit. An empty slice
/// gives vertex 0 at the origin.
#[inline(always)]
fn scan_support<R: Real>(vertices: &[V2<R>], d: V2<R>) -> (usize, V2<R>) {
    let mut best_dot = -R::INFINITY;
    if cfg!(target_os = "none") {
        let mut best = (0, V2::zero());
        for (i, &v) in vertices.iter().enumerate() {
            let dot = v.dot(d);
            if dot > best_dot {
                best = (i, v);
                best_dot = dot;
            }
        }
        return best;
    }
    if let Some(i) = R::first_max_dot(vertices, d) {
        return (i, at(vertices, i));
    }
    let mut best_i = 0;
    for (i, &v) in vertices.iter().enumerate() {
        let dot = v.dot(d);
        let better = dot > best_dot;
        best_i = core::hint::select_unpredictable(better, i, best_i);
        best_dot = core::hint::select_unpredictable(better, dot, best_dot);
    }
    (best_i, at(vertices, best_i))
}

/// The first slot of the largest of `K` values (a power of two), by pairs
/// of neighbours, each pair's winner carrying its value along: log2(K)
/// levels of independent selects, not a chain of K dependent loads and
/// selects. Ties keep the first slot, as a scan from the front does, for
/// values without NaN.
#[cfg(not(any(target_os = "none", target_family = "wasm")))]
#[inline(always)]
pub(crate) fn first_max<R: Real, const K: usize>(values: &[R; K]) -> usize {
    const { assert!(K.is_power_of_two()) };
    let mut best: [(usize, R); K] = core::array::from_fn(|i| (i, values[i]));
    let mut width = K;
    while width > 1 {
        width /= 2;
        for k in 0..width {
            let (left, right) = (best[2 * k], best[2 * k + 1]);
            best[k] = core::hint::select_unpredictable(right.1 > left.1, right, left);
        }
    }
    best[0].0 % K
}

/// Vertex `i`, or the origin out of range (never the case for the callers,
/// whose indices stay below the length; this keeps panics out of the code).
#[inline(always)]
pub(crate) fn at<R: Real>(vertices: &[V2<R>], i: usize) -> V2<R> {
    vertices.get(i).copied().unwrap_or_default()
}

/// The support vertex is the start of the first edge whose direction, going
/// counter-clockwise, reaches the tangent `perp(d)`. Edge directions of a
/// convex polygon turn monotonically through one full turn, so angles measured
/// from edge 0 are sorted and a binary search finds that edge. Rounding can make
/// the comparison wrong for nearly parallel edges; the hill climb mends that.
///
/// A polygon searched is large and, in a scene of many, read from memory
/// rather than cache, where each probe waiting for the one before would wait
/// on a miss: so the search asks for the lines it may read before it reads
/// them. First a coarse sample of the whole polygon (one wait for all, and
/// later searches of the same query find it in cache), then at each halving
/// the probes two halvings on, and once the bracket spans few lines, all of
/// them.
fn angular_search<R: Real>(vertices: &[V2<R>], d: V2<R>) -> usize {
    let mut search = AngularSearch::begin(vertices, d);
    search.narrow(vertices);
    search.finish(vertices)
}

/// [`angular_search`] in its three steps, each of which waits for the
/// lines the one before asked for: two polygons' searches, step by step
/// side by side ([`pair_support_near`]), then wait for memory together.
struct AngularSearch<R: Real> {
    turning: Turning<R>,
    /// The bracket of edges the tangent is reached in.
    lo: usize,
    hi: usize,
}

impl<R: Real> AngularSearch<R> {
    const SAMPLES: usize = 16;
    const SWEPT_LINES: usize = 16;
    const PER_LINE: usize = if 64 / core::mem::size_of::<V2<R>>() > 1 { 64 / core::mem::size_of::<V2<R>>() } else { 1 };

    /// A search along `d` that has asked for its sample's lines.
    #[inline(always)]
    fn begin(vertices: &[V2<R>], d: V2<R>) -> Self {
        Self::ask_sample(vertices);
        Self::along(vertices, d)
    }

    /// Asks for the coarse sample's lines, which every direction reads.
    #[inline(always)]
    fn ask_sample(vertices: &[V2<R>]) {
        let n = vertices.len();
        for j in 0..Self::SAMPLES {
            prefetch(vertices, j * n / Self::SAMPLES);
        }
    }

    /// A search whose sample is asked for already.
    #[inline(always)]
    fn along(vertices: &[V2<R>], d: V2<R>) -> Self {
        Self { turning: Turning::from(edge_from(vertices, 0), d), lo: 1, hi: vertices.len() }
    }

    /// Halves the bracket while it spans many lines (reading the sample's,
    /// asking for the probes two halvings on), then asks for all of its few.
    #[inline(always)]
    fn narrow(&mut self, vertices: &[V2<R>]) {
        while self.lo < self.hi && self.hi - self.lo > Self::SWEPT_LINES * Self::PER_LINE {
            let width = self.hi - self.lo;
            for j in [1, 3, 5, 7] {
                prefetch(vertices, self.lo + j * width / 8);
            }
            self.halve(vertices, false);
        }
        if self.lo < self.hi {
            for i in (self.lo..=self.hi).step_by(Self::PER_LINE) {
                prefetch(vertices, i);
            }
            prefetch(vertices, self.hi);
        }
    }

    /// The first edge k in 1..n with angle(e_k) >= angle(tangent); 0 for
    /// none. These halvings read lines already asked for, and which way
    /// each goes is a coin toss: on hosts a select each, not a branch the
    /// predictor misses half the time (while lines are still coming, a
    /// branch lets the processor read ahead on its guess, and pays).
    /// Microcontrollers have no predictor to miss.
    #[inline(always)]
    fn finish(mut self, vertices: &[V2<R>]) -> usize {
        while self.lo < self.hi {
            self.halve(vertices, cfg!(not(target_os = "none")));
        }
        if self.lo >= vertices.len() {
            0
        } else {
            self.lo
        }
    }

    #[inline(always)]
    fn halve(&mut self, vertices: &[V2<R>], by_select: bool) {
        let mid = self.lo + (self.hi - self.lo) / 2;
        let short = self.turning.short_of_tangent(edge_from(vertices, mid));
        if by_select {
            self.lo = core::hint::select_unpredictable(short, mid + 1, self.lo);
            self.hi = core::hint::select_unpredictable(short, self.hi, mid);
        } else if short {
            self.lo = mid + 1;
        } else {
            self.hi = mid;
        }
    }
}

/// The supports of two polytopes that both are searched here
/// ([`searched_here`]), A's along `da` and B's along `db`: the vertices
/// [`polytope_support_near`] gives each, from each one's hint. Where both
/// are searched, the two searches go step by step side by side (on their
/// compasses' arcs where both have one), so each wait for memory serves
/// both: large polygons in a scene are read from memory, not cache, and
/// their searches wait on little else.
#[cfg(not(any(target_os = "none", target_family = "wasm")))]
#[inline(always)]
pub(crate) fn pair_support_near<R: Real>(
    (a, compass_a, da, hint_a): (&[V2<R>], Compass<'_, R>, V2<R>, u32),
    (b, compass_b, db, hint_b): (&[V2<R>], Compass<'_, R>, V2<R>, u32),
) -> (usize, usize) {
    let climbed = |v: &[V2<R>], d: V2<R>, start: usize| hill_climb(v, d, start, v.len()).0;
    match (walked(a, da, hint_a), walked(b, db, hint_b)) {
        (Some(i), Some(j)) => (i, j),
        (Some(i), None) => (i, searched_support(b, compass_b, db)),
        (None, Some(j)) => (searched_support(a, compass_a, da), j),
        (None, None) => match (compass_a.arc(a.len(), da), compass_b.arc(b.len(), db)) {
            (Some(arc_a), Some(arc_b)) => {
                arc_a.ask(a);
                arc_b.ask(b);
                (climbed(a, da, arc_a.top(a, da)), climbed(b, db, arc_b.top(b, db)))
            }
            _ => {
                let (mut search_a, mut search_b) = (AngularSearch::begin(a, da), AngularSearch::begin(b, db));
                search_a.narrow(a);
                search_b.narrow(b);
                let (i, j) = (search_a.finish(a), search_b.finish(b));
                (climbed(a, da, i), climbed(b, db, j))
            }
        },
    }
}

/// The support of a searched polytope along `d`, from the vertex `hint`
/// where it is a few steps away, else as [`searched_support`] finds it.
#[cfg(not(any(target_os = "none", target_family = "wasm")))]
#[inline]
pub(crate) fn searched_support_near<R: Real>(
    vertices: &[V2<R>],
    compass: Compass<'_, R>,
    d: V2<R>,
    hint: u32,
) -> usize {
    walked(vertices, d, hint).unwrap_or_else(|| searched_support(vertices, compass, d))
}

/// The support of a searched polytope along `d`: on its compass's arc
/// where it has one short enough, else by a search of the whole; then
/// checked by a climb.
#[cfg(not(any(target_os = "none", target_family = "wasm")))]
#[inline(always)]
pub(crate) fn searched_support<R: Real>(vertices: &[V2<R>], compass: Compass<'_, R>, d: V2<R>) -> usize {
    let start = match compass.arc(vertices.len(), d) {
        Some(arc) => {
            arc.ask(vertices);
            arc.top(vertices, d)
        }
        None => angular_search(vertices, d),
    };
    hill_climb(vertices, d, start, vertices.len()).0
}

/// Asks for every line the searches of two searched polytopes' supports
/// along `d`, its quarter turns counter-clockwise and its reverse will read
/// (A's from `da`, B's from `db`): the eight compass arcs, or, for a
/// polytope without a compass, the eight searches narrowed side by side,
/// each wait for memory shared, and left unfinished. The supports looked
/// up one after another then find their lines there or on their way,
/// where each would wait for memory in turn.
#[cfg(not(any(target_os = "none", target_family = "wasm")))]
#[inline(always)]
pub(crate) fn ask_square_searches<R: Real>(
    (a, compass_a, da): (&[V2<R>], Compass<'_, R>, V2<R>),
    (b, compass_b, db): (&[V2<R>], Compass<'_, R>, V2<R>),
) {
    let square = |d: V2<R>| [d, d.perp(), -d, -d.perp()];
    let arcs = |v: &[V2<R>], compass: Compass<'_, R>, d: V2<R>| square(d).map(|d| compass.arc(v.len(), d));
    let (arcs_a, arcs_b) = (arcs(a, compass_a, da), arcs(b, compass_b, db));
    if arcs_a.iter().chain(&arcs_b).all(Option::is_some) {
        arcs_a.iter().flatten().for_each(|arc| arc.ask(a));
        arcs_b.iter().flatten().for_each(|arc| arc.ask(b));
        return;
    }
    AngularSearch::<R>::ask_sample(a);
    AngularSearch::<R>::ask_sample(b);
    for (da, db) in square(da).into_iter().zip(square(db)) {
        AngularSearch::along(a, da).narrow(a);
        AngularSearch::along(b, db).narrow(b);
    }
}

/// Whether a polytope of capacity `N` and `len` vertices has its support
/// searched (after a walk from its hint), not scanned, on this target. The
/// capacity alone says no where every length it holds is scanned, so that
/// no search is compiled in for it.
#[inline(always)]
pub(crate) fn searched_here<R: Real, const N: usize>(len: usize) -> bool {
    (!R::SIMD_SCAN || N > SIMD_SCAN_MAX) && searched::<N>(len) && !simd_scanned::<R>(len)
}

/// The edge from vertex `i` to the next, cyclically (zero out of range).
#[inline(always)]
fn edge_from<R: Real>(vertices: &[V2<R>], i: usize) -> V2<R> {
    let n = vertices.len();
    at(vertices, if i + 1 >= n { 0 } else { i + 1 }) - at(vertices, i)
}

/// Angles measured counter-clockwise from a reference edge, compared
/// exactly by half turns and cross products, against the tangent `perp(d)`
/// of a support direction `d`.
struct Turning<R: Real> {
    reference: V2<R>,
    tangent: V2<R>,
    tangent_half: bool,
}

impl<R: Real> Turning<R> {
    #[inline(always)]
    fn from(reference: V2<R>, d: V2<R>) -> Self {
        let mut turning = Self { reference, tangent: d.perp(), tangent_half: false };
        turning.tangent_half = turning.second_half(turning.tangent);
        turning
    }
    /// Whether `u` is a half turn or more past the reference.
    #[inline(always)]
    fn second_half(&self, u: V2<R>) -> bool {
        let c = self.reference.cross(u);
        !(c > R::ZERO || (c == R::ZERO && self.reference.dot(u) > R::ZERO))
    }
    /// Whether edge `e` has turned less than the tangent from the reference.
    #[inline(always)]
    fn short_of_tangent(&self, e: V2<R>) -> bool {
        let half = self.second_half(e);
        if half != self.tangent_half {
            !half
        } else {
            e.cross(self.tangent) > R::ZERO
        }
    }
}

/// Polygons of more vertices than this search an arc for a support between
/// two known ones ([`polytope_support_between`]); fewer are scanned whole,
/// in fewer instructions than the search's branches cost.
#[cfg(not(any(target_os = "none", target_family = "wasm")))]
pub(crate) const ARC_SEARCH_MIN: usize = 16;

/// Arcs of more vertices than this are searched as the whole polygon is,
/// whose search asks for its lines ahead ([`angular_search`]); a shorter
/// arc is read in a few lines, mostly in cache already.
#[cfg(not(any(target_os = "none", target_family = "wasm")))]
const ARC_SEARCH_MAX: usize = 128;

/// Support of a polytope along `d` where `d` is known to turn between the
/// directions whose supports were vertices `from` and `to` (as an EPA
/// polytope's edge normal lies between its ends'): the support is on the
/// arc from `from` counter-clockwise to `to`, and a search of that arc
/// alone finds it, in few steps once the arcs are short. The arc's edges
/// rise along `d` and then stop rising (their normals turn by less than a
/// half turn), so the first that does not rise is halved for, its own
/// edge and the one before measured as a climb would measure them. At
/// the arc's ends, or with hints that are not such a pair, a short climb
/// checks the vertex, and where it fails, or the arc is long, the support
/// is searched for on the compass's arc (or the whole polygon's).
#[cfg(not(any(target_os = "none", target_family = "wasm")))]
pub(crate) fn polytope_support_between<R: Real>(
    vertices: &[V2<R>],
    compass: Compass<'_, R>,
    d: V2<R>,
    from: u32,
    to: u32,
) -> (usize, V2<R>) {
    let n = vertices.len();
    let (from, to) = (from as usize, to as usize);
    let wrap = |i: usize| if i >= n { i - n } else { i };
    let length = (from < n && to < n).then(|| wrap(to + n - from));
    if let Some(length) = length.filter(|&length| n > ARC_SEARCH_MIN && length <= ARC_SEARCH_MAX) {
        let k = compass::first_not_rising(vertices, d, from, length);
        if (1..length).contains(&k) {
            let top = wrap(from + k);
            return (top, at(vertices, top));
        }
        if let (top, true) = hill_climb(vertices, d, wrap(from + k), 2) {
            return (top, at(vertices, top));
        }
    }
    if let Some(arc) = compass.arc(n, d) {
        arc.ask(vertices);
        let (top, _) = hill_climb(vertices, d, arc.top(vertices, d), n);
        return (top, at(vertices, top));
    }
    // The capacity is not known here: any, so the length alone decides.
    polytope_support::<R, { usize::MAX }>(vertices, d)
}

/// Asks the processor to bring vertex `i`'s cache line in, without waiting
/// for it. Indices past the end are harmless: a prefetch never faults.
#[inline(always)]
fn prefetch<R: Real>(vertices: &[V2<R>], i: usize) {
    prefetch_address(vertices.as_ptr().wrapping_add(i).cast());
}

#[inline(always)]
fn prefetch_address(address: *const u8) {
    #[cfg(target_arch = "x86_64")]
    #[allow(unsafe_code)]
    // SAFETY: SSE is part of every x86_64 processor, and a prefetch is a
    // hint that reads nothing the program sees and never faults, whatever
    // the address (here one computed without `unsafe` pointer arithmetic).
    unsafe {
        use core::arch::x86_64::{_mm_prefetch, _MM_HINT_T0};
        _mm_prefetch::<_MM_HINT_T0>(address.cast());
    }
    #[cfg(not(target_arch = "x86_64"))]
    let _ = address;
}

/// Asks for every cache line of a value of at most four lines at once (of
/// a larger one, none: a query may read few of them), so that the fields a
/// query reads first and those it reads last arrive together, not one
/// wait after another.
#[cfg(not(any(target_os = "none", target_family = "wasm")))]
#[inline(always)]
pub(crate) fn prefetch_small<T: ?Sized>(value: &T) {
    let size = core::mem::size_of_val(value);
    if size > 256 {
        return;
    }
    let start = (value as *const T).cast::<u8>();
    for offset in (0..size).step_by(64) {
        prefetch_address(start.wrapping_add(offset));
    }
    prefetch_address(start.wrapping_add(size.saturating_sub(1)));
}

/// Asks for every cache line of `vertices` at once, where a scan would
/// wait on them one after another (the last vertex too: a slice that
/// starts within a line ends within one more).
#[cfg(not(any(target_os = "none", target_family = "wasm")))]
#[inline(always)]
pub(crate) fn prefetch_all<R: Real>(vertices: &[V2<R>]) {
    let per_line = (64 / core::mem::size_of::<V2<R>>()).max(1);
    for i in (0..vertices.len()).step_by(per_line) {
        prefetch(vertices, i);
    }
    prefetch(vertices, vertices.len().saturating_sub(1));
}

/// The first index in `lo..hi` where `reached` holds, given that it holds
/// from there on; `hi` where it holds nowhere. A binary search over indices
/// rather than a slice (the searches here go round a polygon).
pub(crate) fn first_reached(mut lo: usize, mut hi: usize, reached: impl Fn(usize) -> bool) -> usize {
    while lo < hi {
        let mid = lo + (hi - lo) / 2;
        if reached(mid) {
            hi = mid;
        } else {
            lo = mid + 1;
        }
    }
    lo
}

/// Up to this many vertices a polytope is scanned, not walked or searched,
/// where the scan is SIMD: a branch-free pass over a few dozen vertices
/// beats a walk or a binary search whose branches the predictor misses.
const SIMD_SCAN_MAX: usize = 64;

/// Whether `len` vertices are scanned in SIMD rather than walked or searched.
#[inline(always)]
fn simd_scanned<R: Real>(len: usize) -> bool {
    R::SIMD_SCAN && len <= SIMD_SCAN_MAX
}

/// Whether a polytope of `len` vertices gives its supports along `u`, `t`,
/// `-u` and `-t` from one SIMD pass ([`Real::extreme_dots`]): where each alone
/// would be a SIMD scan of every vertex. Shapes of a few vertices (a
/// rectangle's closed-form support) are left to their own.
#[cfg(not(any(target_os = "none", target_family = "wasm")))]
#[inline(always)]
pub(crate) fn squares_in_one_pass<R: Real>(len: usize) -> bool {
    len > SCAN_ONLY_MAX && simd_scanned::<R>(len)
}

/// Up to this capacity a polytope is always scanned: firmware with small
/// polygons then links no walk, and on hosts a branch-free scan of a few
/// vertices beats a walk whose steps the branch predictor cannot guess.
pub(crate) const SCAN_ONLY_MAX: usize = 8;

/// Support from the previous support vertex `start`, by walking at most 3
/// steps; a direction that turned farther than that (or an out-of-range
/// hint) falls back to the full search, so a jump never costs O(n).
#[inline(always)]
pub(crate) fn polytope_support_near<R: Real, const N: usize>(
    vertices: &[V2<R>],
    d: V2<R>,
    start: u32,
) -> (usize, V2<R>) {
    if N > SCAN_ONLY_MAX && !simd_scanned::<R>(vertices.len()) {
        walk_from::<R, N>(vertices, d, start)
    } else {
        polytope_support::<R, N>(vertices, d)
    }
}

/// The walk of [`polytope_support_near`], out of line on bare-metal targets
/// like [`polytope_support`].
#[cfg_attr(target_os = "none", inline(never))]
#[cfg_attr(not(target_os = "none"), inline)]
fn walk_from<R: Real, const N: usize>(vertices: &[V2<R>], d: V2<R>, start: u32) -> (usize, V2<R>) {
    match walked(vertices, d, start) {
        Some(k) => (k, at(vertices, k)),
        None => polytope_support::<R, N>(vertices, d),
    }
}

/// The top along `d` within 3 steps of the vertex `start`, if it is there
/// (and `start` a vertex).
#[inline(always)]
fn walked<R: Real>(vertices: &[V2<R>], d: V2<R>, start: u32) -> Option<usize> {
    const MAX_WALK: usize = 3;
    if (start as usize) < vertices.len() {
        if let (k, true) = hill_climb(vertices, d, start as usize, MAX_WALK) {
            return Some(k);
        }
    }
    None
}

/// Walk from `start` towards the top along `d`, at most `max_steps` steps:
/// returns the vertex and whether it is the top. Each step is decided by the
/// sign of an edge's rise `(v[k+1] - v[k]) . d`, not by comparing two rounded
/// vertex dot products: the rise rounds with the edge's length, not with the
/// vertices' distance from the origin, so a long run of vertices whose dot
/// products tie to rounding is climbed to its true top. The walk keeps one
/// way and stops where the next edge does not rise: on a convex polygon,
/// the top (the first end of an edge perpendicular to `d`, as the scan picks
/// the first of tied vertices). `max_steps = n` always gets there; a wrong
/// sign can only come from an edge perpendicular to `d` within rounding,
/// which moves the dot product by as little.
fn hill_climb<R: Real>(vertices: &[V2<R>], d: V2<R>, start: usize, max_steps: usize) -> (usize, bool) {
    let n = vertices.len();
    if n == 0 {
        return (0, true);
    }
    let next = |k: usize| if k + 1 >= n { 0 } else { k + 1 };
    let prev = |k: usize| if k == 0 { n - 1 } else { k - 1 };
    let mut k = start.min(n - 1);
    let rise = |from: usize, to: usize| (at(vertices, to) - at(vertices, from)).dot(d);
    let (ahead, behind) = (rise(k, next(k)), rise(prev(k), k));
    // Forward up a rising edge (the steeper way at a bottom), back where the
    // edge behind falls; then on that way while the next edge rises (not
    // rising, NaN too: the top).
    let mut forward = ahead > R::ZERO && ahead >= -behind;
    let backward = behind < R::ZERO;
    let mut steps = max_steps;
    if ahead == R::ZERO && behind == R::ZERO {
        // Inside a run of edges perpendicular to `d`, at the top or at the
        // bottom: the first edge past the run says which. A bottom climbs on
        // from the run's end.
        let mut end = next(k);
        loop {
            if steps == 0 {
                return (k, false);
            }
            steps -= 1;
            let beyond = rise(end, next(end));
            if beyond > R::ZERO {
                (k, forward) = (end, true);
                break;
            }
            if beyond != R::ZERO {
                return (k, true);
            }
            end = next(end);
        }
    } else if !forward && !backward {
        return (k, true);
    }
    let step = |k: usize| if forward { next(k) } else { prev(k) };
    for _ in 0..steps {
        let j = step(k);
        let up = rise(k, j) > R::ZERO;
        if !up {
            return (k, true);
        }
        k = j;
    }
    (k, false)
}

#[cfg(all(test, not(any(target_os = "none", target_family = "wasm"))))]
mod tests {
    extern crate std;

    use super::{pair_support_near, polytope_support, polytope_support_between, polytope_support_near, Compass, V2};
    use crate::real::Real;
    use std::vec::Vec;

    /// A counter-clockwise polygon of at most `n` vertices near an ellipse,
    /// from a seeded generator: unevenly spaced, so its edges turn by uneven
    /// steps. Its vertices lie on a grid that both precisions hold exactly,
    /// and those that do not turn strictly left (by exact integer cross
    /// products) are dropped: a support is one vertex only on a polygon
    /// that is convex as stored, not merely as drawn.
    fn polygon<R: Real>(seed: &mut u64, n: usize) -> Vec<V2<R>> {
        const GRID: f64 = (1u64 << 20) as f64;
        let mut next = || {
            *seed = seed.wrapping_mul(6364136223846793005).wrapping_add(1442695040888963407);
            (*seed >> 11) as f64 / (1u64 << 53) as f64
        };
        let (a, b) = (0.3 + next(), 0.3 + next());
        let mut points: Vec<(i64, i64)> = (0..n)
            .map(|_| next() * core::f64::consts::TAU)
            .map(|t| ((a * t.cos() * GRID).round() as i64, (b * t.sin() * GRID).round() as i64))
            .collect();
        points.sort_unstable();
        points.dedup();
        // Andrew's monotone chain: the lower hull left to right, then the upper back.
        let turns_left = |o: (i64, i64), p: (i64, i64), q: (i64, i64)| {
            i128::from(p.0 - o.0) * i128::from(q.1 - o.1) - i128::from(p.1 - o.1) * i128::from(q.0 - o.0) > 0
        };
        let mut hull: Vec<(i64, i64)> = Vec::new();
        for pass in [points.clone(), points.into_iter().rev().collect()] {
            let floor = hull.len();
            for p in pass {
                while hull.len() >= floor + 2 && !turns_left(hull[hull.len() - 2], hull[hull.len() - 1], p) {
                    hull.pop();
                }
                hull.push(p);
            }
            hull.pop();
        }
        hull.into_iter().map(|(x, y)| V2::new(R::from_f64(x as f64 / GRID), R::from_f64(y as f64 / GRID))).collect()
    }

    /// The compass of `v`, in slots of its own.
    fn compass_of<R: Real>(v: &[V2<R>]) -> [V2<R>; super::COMPASS_SLOTS] {
        let mut slots = [V2::zero(); super::COMPASS_SLOTS];
        super::write_compass(v, &mut slots);
        slots
    }

    /// Both searched side by side, A's and B's vertices are those each one's
    /// own search finds, from every kind of hint: none, far off, near.
    fn pairs_search_as_each_alone<R: Real>() {
        let mut seed = 11;
        for round in 0..400 {
            let (a, b) = (polygon::<R>(&mut seed, 65 + round % 700), polygon::<R>(&mut seed, 65 + (round * 7) % 300));
            let (slots_a, slots_b) = (compass_of(&a), compass_of(&b));
            let (compass_a, compass_b, none) =
                (Compass::in_slots(&slots_a), Compass::in_slots(&slots_b), Compass::ABSENT);
            for k in 0..16u32 {
                let angle = f64::from(k) * 0.41 + round as f64;
                let d = V2::new(R::from_f64(angle.cos()), R::from_f64(angle.sin()));
                let e = V2::new(R::from_f64((angle * 1.7).sin()), R::from_f64((angle * 1.7).cos()));
                let top_a = polytope_support_near::<R, 1024>(&a, d, u32::MAX).0 as u32;
                let top_b = polytope_support_near::<R, 1024>(&b, e, u32::MAX).0 as u32;
                // Walks that arrive from both, from one of the two, from neither.
                let hints = [(top_a.saturating_sub(2), top_b + 1), (top_a + 1, k * 5), (9_999, top_b), (k * 37, 3)];
                for (hint_a, hint_b) in hints.into_iter().chain([(u32::MAX, u32::MAX)]) {
                    let alone = (
                        polytope_support_near::<R, 1024>(&a, d, hint_a).0,
                        polytope_support_near::<R, 1024>(&b, e, hint_b).0,
                    );
                    // With compasses, with none, and with one of the two.
                    for (ca, cb) in [(compass_a, compass_b), (none, none), (compass_a, none)] {
                        let pair = pair_support_near((&a, ca, d, hint_a), (&b, cb, e, hint_b));
                        assert_eq!(pair, alone, "round {round}, k {k}");
                    }
                }
            }
        }
    }

    #[test]
    fn pairs_search_as_each_alone_f32() {
        pairs_search_as_each_alone::<f32>();
    }

    #[test]
    fn pairs_search_as_each_alone_f64() {
        pairs_search_as_each_alone::<f64>();
    }

    /// A support searched on the arc between two known supports (as EPA
    /// asks for one) is the one the whole polygon's scan finds, on arcs
    /// short enough to be searched alone and on longer ones, and from ends
    /// given the wrong way round.
    fn arcs_search_as_the_whole<R: Real>() {
        let mut seed = 5;
        let (mut alone, mut whole_searched) = (0, 0);
        let turn = |t: f64| V2::new(R::from_f64(t.cos()), R::from_f64(t.sin()));
        for round in 0..3000 {
            let v = polygon::<R>(&mut seed, 17 + (round * 7) % 1100);
            let start = round as f64 * 0.37;
            let spread = [0.05, 0.3, 1.5, 3.0][round % 4];
            let (from, to) = (
                polytope_support::<R, 1024>(&v, turn(start)).0,
                polytope_support::<R, 1024>(&v, turn(start + spread)).0,
            );
            let length = (to + v.len() - from) % v.len();
            if v.len() > super::ARC_SEARCH_MIN && length <= super::ARC_SEARCH_MAX {
                alone += 1;
            } else {
                whole_searched += 1;
            }
            for k in 1..8 {
                let d = turn(start + spread * f64::from(k) / 8.0);
                let whole = polytope_support::<R, 1024>(&v, d).0;
                let slots = compass_of(&v);
                for compass in [Compass::in_slots(&slots), Compass::ABSENT] {
                    let arc = polytope_support_between(&v, compass, d, from as u32, to as u32).0;
                    assert_eq!(arc, whole, "round {round}, k {k}, arc {from} to {to} of {}", v.len());
                    // Ends given the wrong way round: the climb catches it.
                    let other = polytope_support_between(&v, compass, d, to as u32, from as u32).0;
                    assert_eq!(other, whole, "round {round}, k {k}, arc {to} to {from} of {}", v.len());
                }
            }
        }
        assert!(alone > 1000 && whole_searched > 100, "{alone} arcs searched alone, {whole_searched} not");
    }

    #[test]
    fn arcs_search_as_the_whole_in_both_precisions() {
        arcs_search_as_the_whole::<f32>();
        arcs_search_as_the_whole::<f64>();
    }

    /// A compass's arc holds the support along any direction: its top is
    /// a vertex of greatest dot product, by exact arithmetic (vertices on
    /// a 2^-20 grid, directions of small integers: every product and sum
    /// is exact in f64), before any climb; and arcs are short.
    #[test]
    fn compass_arcs_hold_the_support() {
        let mut seed = 3;
        let (mut searched, mut longest) = (0, 0);
        for round in 0..300 {
            let v = polygon::<f64>(&mut seed, 65 + (round * 13) % 1100);
            let slots = compass_of(&v);
            let compass = Compass::in_slots(&slots);
            for (i, j) in (-12..=12).flat_map(|i| (-12..=12).map(move |j| (i, j))).filter(|&d| d != (0, 0)) {
                let d = V2::new(f64::from(i), f64::from(j));
                let Some(arc) = compass.arc(v.len(), d) else { continue };
                searched += 1;
                longest = longest.max(arc.len());
                let top = arc.top(&v, d);
                let most = v.iter().map(|p| p.dot(d)).fold(f64::NEG_INFINITY, f64::max);
                assert_eq!(v[top].dot(d), most, "round {round}, direction ({i}, {j}), {} vertices", v.len());
            }
        }
        assert!(searched > 100_000 && longest > 16, "{searched} arcs searched, the longest {longest}");
    }
}
