//! GJK on the cores of two shapes: the intersection test and the distance.
//!
//! Termination never rests on an absolute tolerance. In order:
//! - the origin enclosed by the simplex (overlap), or on it (touching);
//! - a support vertex that repeats (exact, for polytope cores: the main
//!   criterion, as in Box2D);
//! - a certified gap: `|v|` is an upper bound of the distance and
//!   `w . v / |v|` a lower bound; stop when they are within
//!   `epsilon * size` (curved cores);
//! - no progress with no support plane yet separating the origin: the
//!   simplex is within rounding of it, touching (the intersection test
//!   stops on any lack of progress: apart if a plane has separated);
//! - the iteration limit, reported as such. The distance loop goes on
//!   through a stall while its bounds are apart: rounding can hide a gain
//!   the next support still makes.

use crate::minkowski::{MinkowskiDifference, MinkowskiVertex, Pair, SupportPoint, NO_ID};
use crate::real::{Real, V2};
use crate::result::Status;
use crate::shape::SupportMap;
use crate::simplex::{Closest, Payload, Simplex, Vertex};

/// What GJK found out about the cores.
/// `P` is what the simplex carries: [`Witness`](crate::simplex::Witness) points when the caller
/// wants closest points (distance), nothing when it does not (penetration).
pub(crate) enum CoreProximity<'s, R: Real, P> {
    /// The cores overlap or touch: the caller's simplex encloses the origin.
    /// Referred to, not copied: the distance query, which needs no points,
    /// would hold the copy in its frame while GJK runs.
    Overlapping { simplex: &'s Simplex<R, P>, iterations: u32 },
    /// The cores are apart: closest point `v` of the Minkowski difference.
    Separated(CoreSeparation<'s, R, P>),
}

/// A simplex whose points enclose (or touch) the origin: a penetration
/// solver's starting point, given as the solver takes them, so the caller's
/// frame needs no copy of its own.
pub(crate) struct Enclosing<R: Real> {
    points: [SupportPoint<R>; 3],
    len: usize,
    pub iterations: u32,
}

impl<R: Real> Enclosing<R> {
    /// The points of a simplex GJK left enclosing the origin. Every slot,
    /// used or not, copied as it is: `len` says which count, and no slot is
    /// first cleared (a call to `memclr` on bare metal).
    pub fn from_simplex<P: Payload<R>>(simplex: &Simplex<R, P>, iterations: u32) -> Self {
        let (slots, len) = simplex.slots();
        let point = |k: usize| SupportPoint { point: slots[k].w.to_glam(), id: slots[k].id };
        Enclosing { points: [point(0), point(1), point(2)], len, iterations }
    }

    pub fn points(&self) -> &[SupportPoint<R>] {
        self.points.get(..self.len).unwrap_or(&[])
    }
}

pub(crate) struct CoreSeparation<'s, R: Real, P> {
    /// The caller's simplex, reduced to the face closest to the origin.
    pub simplex: &'s Simplex<R, P>,
    pub v: V2<R>,
    /// The largest certified lower bound of the core distance seen.
    pub lower_bound: R,
    pub iterations: u32,
    pub status: Status,
}

/// Whether `id` is a vertex (not a curve point) among `ids`.
#[inline(always)]
fn repeats(ids: &[u32; 3], id: u32) -> bool {
    id != NO_ID && ids.contains(&id)
}

impl<R: Real, A: SupportMap<R> + ?Sized, B: SupportMap<R> + ?Sized> Pair<'_, R, A, B> {
    /// Distance between the cores (radii not included): [`distance_loop_from`],
    /// inlined into each query where the scalar asks for flat frames
    /// (`FLAT_GJK`, in `real.rs`), elsewhere one copy that distance and
    /// penetration share.
    #[inline(always)]
    pub(crate) fn core_distance<'s, P: Payload<R>>(
        &self,
        slot: &'s mut Option<Simplex<R, P>>,
        max_iterations: u32,
        epsilon: R,
    ) -> CoreProximity<'s, R, P> {
        if R::FLAT_GJK {
            distance_loop_from(self, slot, None, max_iterations, epsilon)
        } else {
            self.shared_core_distance(slot, max_iterations, epsilon)
        }
    }

    /// No inline hint, because a microcontroller's flash is scarce: the
    /// compiler keeps one copy for several callers and inlines it into one.
    fn shared_core_distance<'s, P: Payload<R>>(
        &self,
        slot: &'s mut Option<Simplex<R, P>>,
        max_iterations: u32,
        epsilon: R,
    ) -> CoreProximity<'s, R, P> {
        distance_loop_from(self, slot, None, max_iterations, epsilon)
    }
}

/// GJK's distance loop ([`Pair::core_distance`]) from a simplex of the
/// caller's, if given (a warm start: the last step's simplex, its points
/// measured again), else from the first support. The simplex lives in the
/// caller's `slot` (pass `None`), started here and reduced in place, never
/// copied. Any points of the Minkowski difference will do: the loop ends on
/// the same criteria, so its answers keep their guarantees however it
/// starts.
#[inline(always)]
pub(crate) fn distance_loop_from<'s, R, A, B, P>(
    pair: &Pair<'_, R, A, B>,
    slot: &'s mut Option<Simplex<R, P>>,
    start: Option<Simplex<R, P>>,
    max_iterations: u32,
    epsilon: R,
) -> CoreProximity<'s, R, P>
where
    R: Real,
    P: Payload<R>,
    A: SupportMap<R> + ?Sized,
    B: SupportMap<R> + ?Sized,
{
    let start = start.unwrap_or_else(|| first_simplex(pair));
    let simplex = slot.insert(start);
    let scale = pair.scale();
    let tolerance = epsilon * scale;
    // How close the bounds must be for a repeat of a just-dropped vertex to
    // end the loop (see below): rounding, or the tolerance if larger.
    let repeat_gap = (R::from_u32(16) * R::EPSILON * scale).max(tolerance);
    let mut lower_bound = R::ZERO;
    // Polytopes stop on their best plane, but for rounding (below): on bare
    // metal, where flash is scarce, a pair known to be one links none of
    // the check.
    let check_plane =
        cfg!(not(target_os = "none")) || !(Pair::<R, A, B>::shapes_known() && MinkowskiDifference::is_polytope(pair));
    let mut previous = R::INFINITY;
    let mut iterations = 1;
    // One exit for both ways of ending apart, so the result is built once.
    let (v, status) = loop {
        // Ids before the reduction: a vertex dropped now and found again next
        // is a repeat too (Box2D compares with the saved vertices likewise).
        let before = simplex.ids();
        // Enclosed, or on the simplex: overlapping, by the same exit.
        let (v, vv) = match simplex.solve() {
            Closest::Point(v) => (v, v.length_squared()),
            Closest::Enclosed => (V2::zero(), R::ZERO),
        };
        if vv == R::ZERO {
            return CoreProximity::Overlapping { simplex, iterations };
        }
        // No progress, and no support plane so far has separated the origin
        // (in exact arithmetic every support then shrinks |v|): the simplex
        // is within rounding of the origin, whose side of it the solve can
        // no longer tell (a segment through the origin, a curved third point
        // beyond it). Touching to rounding; going on would repeat the solve.
        if vv >= previous && lower_bound <= R::ZERO {
            return CoreProximity::Overlapping { simplex, iterations };
        }
        previous = vv;
        // A segment that is a face of the difference, the origin beyond it:
        // its closest point is the answer, exactly, without the support
        // that would only repeat an end.
        #[cfg(not(any(target_os = "none", target_family = "wasm")))]
        if let Some((from, to)) = arc_of(simplex, v) {
            if pair.is_face(from, to) {
                lower_bound = lower_bound.max(vv.sqrt());
                break (v, Status::Converged);
            }
        }
        if iterations >= max_iterations {
            // With no plane separating the origin, the cores may overlap, by
            // at most the sum of their bounding radii: the bound then says
            // so, and the error bounds made of it hold (a depth lies that
            // much above the one reported).
            if lower_bound <= R::ZERO {
                lower_bound = -(scale + scale);
            }
            break (v, Status::IterationLimit);
        }
        let w = support_beyond(pair, simplex, v);
        iterations += 1;
        let length = vv.sqrt();
        let bound = v.dot(w.w) / length;
        lower_bound = lower_bound.max(bound);
        // The gap test needs a positive lower bound: with none, the support
        // plane does not separate the origin, which may well be inside.
        let gap_closed = lower_bound > R::ZERO && length - lower_bound <= tolerance;
        // A repeat of a vertex still in the simplex ends the loop exactly. A
        // repeat of one just dropped does so in exact arithmetic too, but
        // rounding can make it happen with the bounds still apart (a core
        // nearly parallel to a face): then the bounds must agree to rounding,
        // or the loop goes on (the limit still bounds it).
        // (The reduction only drops vertices: a repeat of one still in the
        // simplex is a repeat of one before it too.)
        let repeat = repeats(&before, w.id) && (length - lower_bound <= repeat_gap || simplex.ids().contains(&w.id));
        // The normal is `v`'s: on curved cores the bounds can meet on a
        // plane measured along an earlier direction while `v`'s own falls
        // short by more than the tolerance (then its normal does not achieve
        // the distance); the loop goes on until `v`'s plane agrees too. So
        // on polytopes where rounding solves a simplex to a vertex beside
        // the edge that is nearest (f32 at tiny scales, whose products
        // leave the normal range).
        let short = check_plane && bound < lower_bound - tolerance;
        // Only the bounds end the loop, not a stall (|v| growing by
        // rounding): where a flat edge of the difference ends in a tight
        // curve, supports alternate between the edge's far end and the
        // curve, each step gaining less than rounding, and the next support
        // can still close the gap, as in exact arithmetic.
        if (repeat || gap_closed) && !short {
            break (v, Status::Converged);
        }
        simplex.push(Vertex::from_minkowski(&w));
    };
    separated(simplex, v, lower_bound, iterations, status)
}

/// The support along `-v`, `v` the closest point of the reduced simplex.
/// Where that is a segment, `-v` is its normal, and the support lies on
/// the boundary between its ends: on hosts two polygons then search only
/// that arc ([`Pair::support_between`]).
#[inline(always)]
fn support_beyond<R, A, B, P>(pair: &Pair<'_, R, A, B>, simplex: &Simplex<R, P>, v: V2<R>) -> MinkowskiVertex<R>
where
    R: Real,
    P: Payload<R>,
    A: SupportMap<R> + ?Sized,
    B: SupportMap<R> + ?Sized,
{
    #[cfg(not(any(target_os = "none", target_family = "wasm")))]
    if let Some((from, to)) = arc_of(simplex, v) {
        return pair.support_between(-v, from, to);
    }
    let _ = simplex;
    pair.support_shared(-v)
}

/// The ids of a segment simplex's ends, counter-clockwise round the
/// difference where `-v` (from its closest point `v` to the origin) is on
/// the right of the first to the second, as a polytope's outward normal is.
#[cfg(not(any(target_os = "none", target_family = "wasm")))]
#[inline(always)]
fn arc_of<R: Real, P: Payload<R>>(simplex: &Simplex<R, P>, v: V2<R>) -> Option<(u32, u32)> {
    let ([p, q, _], 2) = simplex.slots() else { return None };
    Some(if (q.w - p.w).cross(v) > R::ZERO { (p.id, q.id) } else { (q.id, p.id) })
}

/// The simplex of the first support point, for [`distance_loop_from`]. Inlined,
/// so it is built where it stays; an empty simplex to fill instead has its
/// slots cleared (a call to `memclr`).
#[inline(always)]
fn first_simplex<R, A, B, P>(pair: &Pair<'_, R, A, B>) -> Simplex<R, P>
where
    R: Real,
    P: Payload<R>,
    A: SupportMap<R> + ?Sized,
    B: SupportMap<R> + ?Sized,
{
    Simplex::new(Vertex::from_minkowski(&pair.support_shared(pair.first_direction)))
}

fn separated<R: Real, P>(
    simplex: &Simplex<R, P>,
    v: V2<R>,
    lower_bound: R,
    iterations: u32,
    status: Status,
) -> CoreProximity<'_, R, P> {
    CoreProximity::Separated(CoreSeparation { simplex, v, lower_bound, iterations, status })
}

/// The intersection test: GJK that stops as soon as either verdict is
/// certain, and never computes closest points. The shapes are widened by
/// `detect_epsilon` times the pair's size.
pub(crate) fn intersect<R, A, B>(
    pair: &Pair<'_, R, A, B>,
    max_iterations: u32,
    detect_epsilon: R,
    epsilon: R,
) -> (bool, u32, Status)
where
    R: Real,
    A: SupportMap<R> + ?Sized,
    B: SupportMap<R> + ?Sized,
{
    let reach = pair.detect_reach(detect_epsilon);
    let reach2 = reach * reach;
    // The gap tolerance, for curved cores only (computed on first use).
    let mut tolerance = None;
    // One support call, at the top of the loop, serves the first point too.
    let mut simplex: Simplex<R, ()> = Simplex::empty();
    let mut direction = pair.first_direction;
    let (mut v, mut vv) = (V2::zero(), R::ZERO);
    let mut before = [NO_ID; 3];
    let mut previous = R::INFINITY;
    // Whether any support plane has had the origin behind it, as `apart`
    // needs when the loop stops making progress.
    let mut separated = false;
    let mut iterations = 0;
    loop {
        let w = if Pair::<R, A, B>::shapes_known() { pair.support(direction) } else { pair.support_shared(direction) };
        iterations += 1;
        if iterations > 1 {
            // w . v / |v| is a lower bound: beyond `reach`, certainly apart.
            // Compared squared so polygons (reach 0) need no square root.
            let vw = v.dot(w.w);
            separated |= vw > R::ZERO;
            if vw > R::ZERO && vw * vw > reach2 * vv {
                return (false, iterations, Status::Converged);
            }
            // A vertex of the simplex before its reduction (which only drops
            // vertices, so this covers the reduced simplex too): no progress.
            // In exact arithmetic the repeated support then has `v . w >=
            // |v|^2 > 0`, a plane that separates. Without any so far, `v` is
            // rounding off an edge through the origin (a slice's apex inside a
            // rectangle gave two opposite supports, then a triangle the solve
            // called the origin outside of): the cores touch to rounding.
            if repeats(&before, w.id) {
                return (!separated, iterations, Status::Converged);
            }
            if w.id == NO_ID && vw > R::ZERO {
                let tolerance = *tolerance.get_or_insert_with(|| epsilon * pair.scale());
                if vv - vw <= tolerance * vv.sqrt() {
                    return (false, iterations, Status::Converged);
                }
            }
        }
        simplex.push(Vertex::from_minkowski(&w));
        before = simplex.ids();
        v = match simplex.solve() {
            Closest::Enclosed => return (true, iterations, Status::Converged),
            Closest::Point(v) => v,
        };
        vv = v.length_squared();
        // |v| is an upper bound of the core distance.
        if vv <= reach2 {
            return (true, iterations, Status::Converged);
        }
        // |v| grew: only rounding does that. Apart if a support plane has
        // separated the origin; with none, the simplex is as close to the
        // origin as the solve can tell, and the cores touch to rounding (as
        // in the distance loop). A half ellipse and a slice overlapping by
        // 7e-6 L in f32 stalled at |v| = 1e-5 L with every plane behind the
        // origin, and were called apart.
        if vv > previous {
            return (!separated, iterations, Status::Converged);
        }
        previous = vv;
        if iterations >= max_iterations {
            return (false, iterations, Status::IterationLimit);
        }
        direction = -v;
    }
}
