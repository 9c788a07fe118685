//! Penetration depth of overlapping cores: the pluggable solver trait and
//! EPA, the default, on a fixed-capacity polytope.
//!
//! The polytope is a polygon inside the Minkowski difference that winds
//! once around the origin. Each edge bounds from below how far the
//! difference's boundary is within the edge's cone from the origin, so the
//! closest edge gives a *lower* bound of the depth; the support along that
//! edge's normal an *upper* bound. EPA pushes the closest edge out until the
//! bounds meet: exactly when a support vertex repeats or the closest edge
//! is known to be a face or a stretch of faces read whole (polytopes), or
//! within `epsilon * size` (curved cores).

use crate::config::EpaConfig;
use crate::minkowski::{MinkowskiDifference, SupportPoint, NO_ID};
use crate::polytope::cyclic;
use crate::real::{Real, V2};
use crate::result::Status;

/// The depth and direction of the overlap of two cores, as a penetration
/// solver reports it.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct PenetrationEstimate<R: Real> {
    /// Unit vector from A towards B: moving B by `depth` along it separates
    /// the cores.
    pub normal: R::Vector,
    pub depth: R,
    /// Gap between the solver's upper and lower bounds of the depth.
    pub error_bound: R,
    pub iterations: u32,
    pub status: Status,
}

/// A penetration solver (dyn4j's `MinkowskiPenetrationSolver`): given the
/// Minkowski difference of two overlapping cores and GJK's final simplex
/// (1 to 3 points enclosing or touching the origin), find the depth.
pub trait PenetrationSolver<R: Real> {
    /// Whether two polygons of at most eight vertices, whose types are known
    /// when the program is compiled, may be answered by their separating
    /// axes instead of [`solve`](Self::solve) (exact, no iteration; on hosts
    /// only). EPA allows it; a solver of your own is asked unless it says so.
    ///
    /// A solver that allows it is also started, for two larger polygons,
    /// from four supports in place of GJK's simplex where they enclose the
    /// origin: `simplex` then holds 4 points, counter-clockwise.
    const SEPARATING_AXES: bool = false;

    fn solve<M: MinkowskiDifference<R>>(&self, difference: &M, simplex: &[SupportPoint<R>]) -> PenetrationEstimate<R>;
}

/// The expanding polytope algorithm with room for `N` polytope vertices
/// (default 32), on the stack so that no allocator is needed. A full polytope
/// merges away the corner that matters least (one that no longer can, where
/// there is one); when none can go the answer says `Status::CapacityLimit`.
///
/// `N` is at least 3 (a triangle around the origin), checked when the
/// program is compiled:
///
/// ```compile_fail
/// use gjk2d::{Circle, Epa, Gjk, GjkConfig, Transform};
/// let gjk = Gjk::with_solver(GjkConfig::default(), Epa::<f32, 2>::default());
/// let circle = Circle::new(1.0f32).unwrap();
/// let _ = gjk.penetration(&circle, &Transform::IDENTITY, &circle, &Transform::IDENTITY);
/// ```
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Epa<R: Real, const N: usize = 32> {
    pub config: EpaConfig<R>,
}

impl<R: Real, const N: usize> Epa<R, N> {
    pub fn new(config: EpaConfig<R>) -> Self {
        Self { config }
    }
}

impl<R: Real, const N: usize> PenetrationSolver<R> for Epa<R, N> {
    const SEPARATING_AXES: bool = true;

    // Not inlined, so the polytope never shares a frame with GJK's values:
    // a microcontroller's stack is small.
    #[inline(never)]
    fn solve<M: MinkowskiDifference<R>>(&self, difference: &M, simplex: &[SupportPoint<R>]) -> PenetrationEstimate<R> {
        // Checked when the program is compiled: a polytope with no room for
        // a triangle could not hold the origin inside.
        const { assert!(N >= 3, "Epa<R, N>: N must be at least 3") };
        let mut polytope = heapless::Vec::<Corner<R>, N>::new();
        expand(&mut polytope, &self.config, difference, simplex)
    }
}

/// A polytope vertex and the distance of the edge that starts at it, kept
/// small because a penetration query holds a whole polytope of them.
#[derive(Clone, Copy, Debug, Default)]
pub(crate) struct Corner<R> {
    w: V2<R>,
    /// Distance from the origin to the line of the edge to the next corner,
    /// never negative, so its sign bit is free to say whether `w` is a point
    /// of a curve (set) or a vertex of both cores (clear): all the polish
    /// needs to know of the support id.
    signed_distance: R,
    /// The support id, where a support between two corners can use it.
    #[cfg(not(any(target_os = "none", target_family = "wasm")))]
    id: u32,
    /// The outward unit normal of the edge to the next corner, kept on
    /// hosts only, whose stacks have room for it where a microcontroller's
    /// do not: the closest edge's normal is then read, not taken again (a
    /// square root and a division before every support).
    #[cfg(not(any(target_os = "none", target_family = "wasm")))]
    normal: V2<R>,
    /// Whether the edge to the next corner is settled: the boundary between
    /// the two is known face by face, and its closest face is `normal` at
    /// the edge's distance, an answer where it is the closest edge.
    #[cfg(not(any(target_os = "none", target_family = "wasm")))]
    settled: bool,
}

impl<R: Real> Corner<R> {
    /// A support point, its edge distance not known yet (zero). `curved`
    /// is false where both cores are polytopes: the flag is then never set
    /// and never read, and the compiler drops its code (nothing polishes).
    fn new(w: V2<R>, id: u32, curved: bool) -> Self {
        Self {
            w,
            signed_distance: if curved && id == NO_ID { -R::ZERO } else { R::ZERO },
            #[cfg(not(any(target_os = "none", target_family = "wasm")))]
            id,
            #[cfg(not(any(target_os = "none", target_family = "wasm")))]
            normal: V2::new(R::ONE, R::ZERO),
            #[cfg(not(any(target_os = "none", target_family = "wasm")))]
            settled: false,
        }
    }
    #[inline(always)]
    fn edge_distance(&self) -> R {
        self.signed_distance.abs()
    }
    #[inline(always)]
    fn on_curve(&self) -> bool {
        self.signed_distance.is_sign_negative()
    }
    #[inline(always)]
    fn set_edge_distance(&mut self, d: R, curved: bool) {
        // `d` comes from `edge`, which never gives -0.0 (`max` with +0.0
        // returns +0.0): a -0.0 here would flip the flag.
        self.signed_distance = if curved && self.on_curve() { -d } else { d };
        #[cfg(not(any(target_os = "none", target_family = "wasm")))]
        {
            self.settled = false;
        }
    }
    /// Settles the edge to the next corner at its closest face's distance
    /// and normal ([`Corner::settled`]).
    #[cfg(not(any(target_os = "none", target_family = "wasm")))]
    #[inline(always)]
    fn settle(&mut self, (d, normal): (R, V2<R>), curved: bool) {
        self.set_edge((d, normal), curved);
        self.settled = true;
    }
    /// Sets the edge to the next corner from [`edge`]'s distance and normal.
    #[inline(always)]
    fn set_edge(&mut self, (d, normal): (R, V2<R>), curved: bool) {
        self.set_edge_distance(d, curved);
        #[cfg(not(any(target_os = "none", target_family = "wasm")))]
        {
            self.normal = normal;
        }
        #[cfg(any(target_os = "none", target_family = "wasm"))]
        let _ = normal;
    }
    /// The outward unit normal of the edge from here to `next`, as [`edge`]
    /// gives it.
    #[inline(always)]
    fn normal_to(&self, next: &Self) -> V2<R> {
        #[cfg(not(any(target_os = "none", target_family = "wasm")))]
        let normal = {
            let _ = next;
            self.normal
        };
        #[cfg(any(target_os = "none", target_family = "wasm"))]
        let normal = edge(self.w, next.w).1;
        normal
    }
}

/// Growable storage for the polytope: inline (heapless) or, with `std`, a
/// `Vec` without a cap.
pub(crate) trait Storage<R> {
    fn items(&self) -> &[Corner<R>];
    fn items_mut(&mut self) -> &mut [Corner<R>];
    /// Inserts at `index`, at most the length (EPA's indices always are);
    /// false when full.
    fn insert_at(&mut self, index: usize, c: Corner<R>) -> bool;
    fn clear_all(&mut self);
    /// How many corners fit in all.
    fn capacity(&self) -> usize;
}

impl<R: Copy, const N: usize> Storage<R> for heapless::Vec<Corner<R>, N> {
    fn items(&self) -> &[Corner<R>] {
        self
    }
    fn items_mut(&mut self) -> &mut [Corner<R>] {
        self
    }
    // Shifted by swaps of neighbours, not `Vec::insert`, whose overlapping
    // copy would link `memmove` into a firmware for this alone. An index
    // past the end leaves the corner last (`move_item` stops at the end).
    // Inlined on hosts, where a call passed the corner through memory.
    #[cfg_attr(not(any(target_os = "none", target_family = "wasm")), inline(always))]
    fn insert_at(&mut self, index: usize, c: Corner<R>) -> bool {
        if self.push(c).is_err() {
            return false;
        }
        let last = self.len() - 1;
        #[cfg(not(any(target_os = "none", target_family = "wasm")))]
        if index <= last {
            self.copy_within(index..last, index + 1);
            self[index] = c;
            return true;
        }
        move_item(self, last, index);
        true
    }
    fn clear_all(&mut self) {
        self.clear()
    }
    fn capacity(&self) -> usize {
        N
    }
}

/// Moves item `from` to index `to`, the items between shifting by one to
/// make room: swaps of neighbours (nothing out of range, no panic path).
fn move_item<T>(items: &mut [T], mut from: usize, to: usize) {
    while from != to {
        let first = if from < to { from } else { from - 1 };
        let Some([a, b]) = items.get_mut(first..first + 2) else { return };
        core::mem::swap(a, b);
        from = if from < to { from + 1 } else { first };
    }
}

#[cfg(feature = "std")]
impl<R: Copy> Storage<R> for std::vec::Vec<Corner<R>> {
    fn items(&self) -> &[Corner<R>] {
        self
    }
    fn items_mut(&mut self) -> &mut [Corner<R>] {
        self
    }
    fn insert_at(&mut self, index: usize, c: Corner<R>) -> bool {
        if index > self.len() {
            return false;
        }
        self.insert(index, c);
        true
    }
    fn clear_all(&mut self) {
        self.clear()
    }
    fn capacity(&self) -> usize {
        usize::MAX
    }
}

/// Distance from the origin to the line through `p`, `q` (a counter-clockwise
/// edge of a polytope around the origin), and its outward unit normal. A
/// polytope of one point (GJK touching at the origin) has its one edge from
/// the point to itself: zero, and any direction to widen it along.
fn edge<R: Real>(p: V2<R>, q: V2<R>) -> (R, V2<R>) {
    // Componentwise normalisation (try_normalize): exact unit normals for
    // axis-aligned edges, and no under- or overflow for tiny or huge ones.
    match (q - p).perp_cw().try_normalize() {
        Some(unit) => (p.dot(unit).max(R::ZERO), unit),
        None => (R::ZERO, V2::new(R::ONE, R::ZERO)),
    }
}

fn corner<R: Real>(s: &SupportPoint<R>, curved: bool) -> Corner<R> {
    Corner::new(V2::from_glam(s.point), s.id, curved)
}

/// The most faces a stretch of boundary between two corners may have to be
/// read whole ([`MinkowskiDifference::closest_face_between`]) rather than
/// split by another support.
#[cfg(not(any(target_os = "none", target_family = "wasm")))]
const SETTLED_FACES_MAX: usize = 9;

pub(crate) fn expand<R: Real, S: Storage<R>, M: MinkowskiDifference<R>>(
    polytope: &mut S,
    config: &EpaConfig<R>,
    difference: &M,
    simplex: &[SupportPoint<R>],
) -> PenetrationEstimate<R> {
    let curved = !difference.is_polytope();
    // A closure, not a function: the query's deepest point gets no extra frame.
    let support = |d: V2<R>| corner(&difference.support(d.to_glam()), curved);
    let tolerance = config.epsilon() * difference.scale();
    let mut iterations = 0;
    // Every corner is a vertex of the difference, none twice (a support
    // that repeats an end stops the loop): a polytope with room for all of
    // them never fills. Known when the program is compiled for shapes of
    // fixed size, so their code for a full polytope drops out.
    let can_fill = difference.vertex_bound() >= polytope.capacity();

    // GJK's simplex, counter-clockwise, is the polytope to expand. One that
    // only touches the origin (a point, or an edge through it) has no
    // interior yet: the loop below widens it with supports along its edges'
    // normals, as it widens any polytope, so the seed needs no support call
    // of its own.
    // A point that repeats one already in is left out: an edge needs two.
    polytope.clear_all();
    let ccw = match simplex {
        [a, b, c] => {
            let w = |s: &SupportPoint<R>| V2::<R>::from_glam(s.point);
            (w(b) - w(a)).cross(w(c) - w(a)) >= R::ZERO
        }
        _ => true,
    };
    // No simplex at all (a solver called by hand) is taken as the origin.
    for k in 0..simplex.len().max(1) {
        // Clockwise triangles are read backwards from their first point.
        let c = simplex
            .get(if ccw || k == 0 { k } else { 3 - k })
            .map_or(Corner::new(V2::zero(), NO_ID, curved), |s| corner(s, curved));
        if polytope.items().iter().all(|p| p.w != c.w) {
            polytope.insert_at(polytope.items().len(), c);
        }
    }
    let items = polytope.items_mut();
    let n = items.len();
    for i in 0..n {
        // The next corner, cyclically, without a division.
        let next = if i + 1 < n { i + 1 } else { 0 };
        let Some(q) = items.get(next).map(|c| c.w) else { break };
        if let Some(c) = items.get_mut(i) {
            c.set_edge(edge(c.w, q), curved);
        }
    }

    let mut upper = R::INFINITY;
    let mut best = V2::new(R::ONE, R::ZERO);
    // Ends with how it ended, the closest edge and its distance (polished
    // where curved, if it stopped short).
    let (closest, lower, status) = loop {
        let items = polytope.items();
        let n = items.len();
        let (mut i, mut lower) = (0, R::INFINITY);
        for (k, c) in items.iter().enumerate() {
            let closer = c.edge_distance() < lower;
            // Bare metal has no predictor to miss: its branch stays, and so
            // does its firmware's code.
            if cfg!(target_os = "none") {
                if closer {
                    (i, lower) = (k, c.edge_distance());
                }
            } else {
                // Selected, not branched on, where a predictor would miss:
                // which corner leads is as unpredictable as the shapes.
                i = core::hint::select_unpredictable(closer, k, i);
                lower = if closer { c.edge_distance() } else { lower };
            }
        }
        let j = if i + 1 >= n { 0 } else { i + 1 };
        let (p, q) = (items.get(i).copied().unwrap_or_default(), items.get(j).copied().unwrap_or_default());
        let normal = p.normal_to(&q);
        // The closest edge on the boundary, or settled: its distance is
        // reached, so the bounds meet without the support that would repeat
        // an end.
        #[cfg(not(any(target_os = "none", target_family = "wasm")))]
        if p.settled || difference.is_face(p.id, q.id) {
            if lower <= upper {
                (upper, best) = (lower, normal);
            }
            break (i, lower, Status::Converged);
        }
        if iterations >= config.max_iterations() {
            break (i, lower, Status::IterationLimit);
        }
        // A stretch of boundary between the edge's ends short enough to
        // read whole: settled at its closest face, where a support at a
        // time would split the edge again and again.
        #[cfg(not(any(target_os = "none", target_family = "wasm")))]
        if let Some((depth, normal)) = difference.closest_face_between(p.id, q.id, SETTLED_FACES_MAX) {
            iterations += 1;
            if let Some(c) = polytope.items_mut().get_mut(i) {
                c.settle((depth, V2::from_glam(normal)), curved);
            }
            continue;
        }
        #[cfg(not(any(target_os = "none", target_family = "wasm")))]
        let w = corner(&difference.support_between(normal.to_glam(), p.id, q.id), curved);
        #[cfg(any(target_os = "none", target_family = "wasm"))]
        let w = support(normal);
        iterations += 1;
        let reach = w.w.dot(normal);
        // The upper bound and its direction are an achievable answer: moving
        // B by `reach` against `normal` separates the cores. Reported as the
        // result, so depth and normal always belong together (the closest
        // chord's normal can be off where the chord is not a face).
        if cfg!(target_os = "none") {
            if reach < upper {
                upper = reach;
                best = normal;
            }
        } else {
            // Selected: whether a support lowers the bound is a coin toss.
            let lowered = reach < upper;
            best = if lowered { normal } else { best };
            upper = if lowered { reach } else { upper };
        }
        // A support equal to an end of the edge: exactly no progress (equal
        // vertex ids give equal points, computed the same way). As one
        // `contains`, which compiles smaller than two `==`.
        let repeated = [p.w, q.w].contains(&w.w);
        if repeated || upper - lower <= tolerance {
            break (i, lower, Status::Converged);
        }
        let mut new = w;
        new.set_edge(edge(w.w, q.w), curved);
        // Right after the edge's start (after the last corner when the edge
        // closes the polygon).
        let at = i + 1;
        // Where the edge's start `p` is once `new` is in.
        let start = if polytope.insert_at(at, new) {
            i
        } else if !can_fill {
            // Only a support repeated past rounding could have filled it.
            break (i, lower, Status::CapacityLimit);
        } else {
            // Full: `new` takes the place of the corner that matters least,
            // moved to where it belongs (the corners between shift by one).
            let items = polytope.items_mut();
            let Some(k) = prune(items, upper - tolerance, lower, curved) else {
                break (i, lower, Status::CapacityLimit);
            };
            if let Some(slot) = items.get_mut(k) {
                *slot = new;
            }
            if k < i {
                move_item(items, k, i);
                i - 1
            } else {
                move_item(items, k, at);
                i
            }
        };
        if let Some(c) = polytope.items_mut().get_mut(start) {
            c.set_edge(edge(p.w, w.w), curved);
        }
    };
    // Converged, or stopped short without a polish: the best achievable
    // answer seen, or (before any support was taken) the closest chord.
    let fallback = if upper.is_finite() {
        estimate(best, upper, (upper - lower).max(R::ZERO), iterations, status)
    } else {
        estimate(V2::new(R::ONE, R::ZERO), lower, R::ZERO, iterations, status)
    };
    // Polytopes have no curved region to polish: a firmware with polytopes
    // alone then links none of it. A converged answer needs none either.
    if difference.is_polytope() || status == Status::Converged {
        return fallback;
    }
    finish_curved(polytope, closest, &support, lower, upper, tolerance, iterations, fallback)
}

/// EPA stopped short (polytope full or out of iterations). On a curved
/// region its certified lower bound converges slowly: every basin of a smooth
/// boundary needs chords shrinking towards it from both sides. The depth
/// itself is found much faster as the minimum of the support function
/// `h(u) = max_p p.u` near the closest edge: its derivative along the
/// direction, `s(u) . perp(u)`, vanishes there, and a safeguarded secant finds
/// that root between the normals of the neighbouring edges in a few support
/// calls. The answer is an achievable translation (the boundary is reached
/// along it) and `error_bound` stays the certified gap to EPA's lower bound;
/// it keeps EPA's status unless that gap is within the tolerance. Polytope
/// regions, or a polish that does not bracket a minimum, keep EPA's answer.
#[allow(clippy::too_many_arguments)]
fn finish_curved<R: Real, S: Storage<R>>(
    polytope: &S,
    closest: usize,
    support: &impl Fn(V2<R>) -> Corner<R>,
    lower: R,
    upper: R,
    tolerance: R,
    mut iterations: u32,
    fallback: PenetrationEstimate<R>,
) -> PenetrationEstimate<R> {
    let items = polytope.items();
    let n = items.len();
    if n < 3 || closest >= n {
        return fallback;
    }
    let (p, q) = (cyclic(items, closest), cyclic(items, closest + 1));
    let (_, normal) = edge(p.w, q.w);
    if !p.on_curve() && !q.on_curve() {
        return fallback;
    }
    let slope = |u: V2<R>| support_along(support, u).1;
    // Bracket the root between the normals of two polytope edges: from the
    // closest edge's normal, walk edge by edge (at most 8) the way the slope
    // points until it changes sign. Consecutive normals are less than a half
    // turn apart, so directions between them interpolate.
    let edge_normal = |k: usize| edge(cyclic(items, k).w, cyclic(items, k + 1).w).1;
    let slope_here = slope(normal);
    iterations += 1;
    let (mut a, mut g0, mut b, mut g1) = (normal, slope_here, normal, slope_here);
    let steps = n.min(8);
    // One loop for either way, so the support call appears once.
    let forward = slope_here <= R::ZERO;
    for k in 1..=steps {
        // k <= steps <= n: going back k edges is going forward n - k.
        let u = edge_normal(closest + if forward { k } else { n - k });
        let g = slope(u);
        iterations += 1;
        (a, g0, b, g1) = if forward { (b, g1, u, g) } else { (u, g, a, g0) };
        // The slope changed sign: the root is bracketed.
        let bracketed = if forward { g >= R::ZERO } else { g <= R::ZERO };
        if bracketed {
            break;
        }
    }
    if !(g0 <= R::ZERO && g1 >= R::ZERO) || a.cross(b) <= R::ZERO {
        return fallback;
    }
    let direction = |t: R| (a * (R::ONE - t) + b * t).try_normalize().unwrap_or(normal);
    let (mut t0, mut t1) = (R::ZERO, R::ONE);
    // Illinois variant of regula falsi: superlinear, never leaves the bracket.
    let mut side = 0i8;
    let limit = iterations + 60;
    let step_tolerance = tolerance.min(R::ONE).max(R::EPSILON);
    while iterations < limit && t1 - t0 > step_tolerance {
        // The secant's root; bisection where it is not strictly inside
        // (a NaN when both slopes are zero fails the test too).
        let mut t = t0 - g0 * (t1 - t0) / (g1 - g0);
        if !(t > t0 && t < t1) {
            t = (t0 + t1) * R::HALF;
        }
        let g = slope(direction(t));
        iterations += 1;
        if g == R::ZERO {
            t0 = t;
            t1 = t;
        } else if g < R::ZERO {
            t0 = t;
            g0 = g;
            if side == -1 {
                g1 *= R::HALF;
            }
            side = -1;
        } else {
            t1 = t;
            g1 = g;
            if side == 1 {
                g0 *= R::HALF;
            }
            side = 1;
        }
    }
    let u = direction((t0 + t1) * R::HALF);
    let depth = support_along(support, u).0;
    iterations += 1;
    if depth > upper {
        return fallback;
    }
    // Converged only where EPA's lower bound certifies it: the polish finds
    // a local minimum of `h`, and a nearly round difference can have a
    // second, deeper one in a cone EPA had not refined.
    let gap = (depth - lower).max(R::ZERO);
    let status = if gap <= tolerance { Status::Converged } else { fallback.status };
    estimate(u, depth, gap, iterations, status)
}

/// The support function `h(u)` along `u` and its slope `s(u) . perp(u)`:
/// one out-of-line copy of the support call on bare metal for every place
/// the polish evaluates them, not an inlined copy at each.
#[cfg_attr(target_os = "none", inline(never))]
fn support_along<R: Real>(support: &impl Fn(V2<R>) -> Corner<R>, u: V2<R>) -> (R, R) {
    let w = support(u).w;
    (w.dot(u), w.dot(u.perp()))
}

/// The corner to drop from a full polytope, merging its two edges into
/// one: the corner whose merged edge keeps the largest bound. The corner
/// before it starts the merged edge and takes that bound. `None` when no
/// corner can go.
///
/// An edge's stored distance is a lower bound of how far the difference's
/// boundary is from the origin within the edge's cone (the triangle of the
/// origin and the edge lies inside the difference), and a merged edge keeps
/// the smaller of its two edges' bounds, which holds for both cones. The
/// distance of the merged chord itself is no bound worth keeping: around a
/// nearly round difference it is below the depth even where both faces it
/// replaces are certified.
///
/// A merged bound of at least `threshold` (the upper bound less the
/// tolerance) is certified: the merged edge can never be the closest before
/// EPA converges, so it is never split again and dropping the corner costs
/// nothing. That is how 32 corners converge on a 1000-gon around the origin:
/// the faces found at the depth merge away. Its ends may then be more than a
/// half turn apart, which does no harm to an edge never refined.
///
/// Where no bound is certified yet (a square centred in a round polygon
/// ties the depth in four directions, and the polytope fills before any
/// face is found), the largest bound is the corner that matters least, and
/// merging it trades information for room: the bounds stay sound, and EPA
/// may come back to refine the merged edge. Only a corner whose merged
/// chord keeps the origin on its inner side qualifies: an edge that does
/// not, once refined, bounds its parts by zero alone (sound, but EPA stalls
/// there; without the check 5 or 6 more of 76 round cases stop short with
/// 8 to 12 corners). Either way, the ends of the closest edge never go:
/// their merged bound is `lower`, and a candidate must beat it.
fn prune<R: Real>(items: &mut [Corner<R>], threshold: R, lower: R, curved: bool) -> Option<usize> {
    let n = items.len();
    // Walking corner `k`, the candidate is the corner before it, `b`, with
    // `a` before that: corners copied along, not indexed (no bounds checks).
    let [.., mut a, mut b] = *items else { return None };
    // The corner after the candidate, and the largest merged bound so far
    // (edge bounds are never NaN: `edge` takes a `max` with zero).
    let (mut after, mut bound) = (0, lower);
    for (k, &c) in items.iter().enumerate() {
        let merged = a.edge_distance().min(b.edge_distance());
        // Uncertified, the merged chord must keep the origin inside (for
        // progress, not soundness).
        if merged > bound && (merged >= threshold || a.w.cross(c.w) > R::ZERO) {
            (after, bound) = (k, merged);
        }
        (a, b) = (b, c);
    }
    if bound <= lower {
        return None;
    }
    let pick = if after == 0 { n } else { after } - 1;
    let start = if pick == 0 { n } else { pick } - 1;
    #[cfg(not(any(target_os = "none", target_family = "wasm")))]
    let end = items.get(after).map_or(V2::zero(), |c| c.w);
    let corner = items.get_mut(start)?;
    corner.set_edge_distance(bound, curved);
    #[cfg(not(any(target_os = "none", target_family = "wasm")))]
    {
        corner.normal = edge(corner.w, end).1;
    }
    Some(pick)
}

fn estimate<R: Real>(
    outward: V2<R>,
    depth: R,
    error_bound: R,
    iterations: u32,
    status: Status,
) -> PenetrationEstimate<R> {
    PenetrationEstimate {
        // The polytope's outward normal points from B into A's side; B moves
        // the other way.
        normal: (-outward).to_glam(),
        // Touching cores can round a bound a hair below zero.
        depth: depth.max(R::ZERO),
        error_bound,
        iterations,
        status,
    }
}
