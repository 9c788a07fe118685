//! Warm starting: [`PairCache`], what one query of a pair leaves for the
//! next query of the same pair a step later, so that query starts where
//! the last one ended.
//!
//! Every cached start is checked against the shapes as they are now before
//! it decides anything, so a stale, foreign or garbled cache only costs the
//! cold query:
//! - a separating axis of two small polygons is measured again, and proves
//!   them apart when it still separates them;
//! - a triangle of support ids is looked up again, and proves them
//!   overlapping when it still encloses the origin by more than rounding;
//! - GJK's last simplex, looked up again, is where GJK starts: it ends on
//!   the same criteria from any start;
//! - the few axes of the least overlap are evaluated alone only while the
//!   motion since they led (bounded by the change of pose times the shapes'
//!   radii) is too small to let any other axis catch up, and only for the
//!   very shapes they were measured on (their fingerprint): the answer is
//!   then the cold query's, to the bit.

use crate::minkowski::NO_ID;
use crate::real::{Real, V2};

/// What the queries of one pair of shapes leave for the next step: a small
/// `Copy` value, one per pair, kept between steps by the caller and passed
/// to the `_cached` queries ([`Gjk::intersects_cached`](crate::Gjk::intersects_cached),
/// [`distance_cached`](crate::Gjk::distance_cached),
/// [`penetration_cached`](crate::Gjk::penetration_cached),
/// [`manifold_cached`](crate::Gjk::manifold_cached)), which read and update it.
///
/// The answers are the cold queries' (the same verdicts, and for polygons
/// of up to eight vertices the same penetration to the bit), within the
/// same guarantees; a cache holds only where to start. One that is stale,
/// from another pair, or garbage is detected and costs a cold query, never
/// a wrong answer. [`Default`] is cold.
///
/// The queries' `iterations` count the work done: 0 where the cache alone
/// decided (its axis still separates, its triangle still encloses the
/// origin, its leading axes still lead).
#[derive(Clone, Copy, Debug, PartialEq)]
#[cfg_attr(any(target_os = "none", target_family = "wasm"), allow(dead_code))]
pub struct PairCache<R: Real> {
    /// The last simplex of two polygons by its support ids (A's
    /// vertex in the high 16 bits, B's in the low), [`NO_ID`] in empty slots.
    ids: [u32; 3],
    /// The axis that last separated two small polygons (A's edges, then
    /// B's from slot 8), [`NO_ID`] for none.
    separating: u32,
    /// The opposite of the last normal, in A's frame: GJK's first search
    /// direction for shapes other than small polygons. Zero for none.
    direction: [R; 2],
    /// The `LEADERS` axes of two small polygons with the least overlap
    /// (greatest separation), a bit per slot (none: zero), and how far the
    /// first of them leads every other axis.
    leaders: u32,
    lead: R,
    /// When `leaders` were measured: B's rotation in A's frame (cosine,
    /// sine), the offset of B's center from A's in A's frame and in B's,
    /// each shape's bounding radius about its center, and the size of the
    /// coordinates (for rounding): what turns a change of pose into a bound
    /// on how far any axis's separation moved.
    pose: [R; 6],
    radii: [R; 2],
    reach: R,
    /// How far the axes could have moved at the last check: a lead no
    /// larger is not worth keeping (the next check would likely fail too).
    moved: R,
    /// The two polygons `leaders` were measured on.
    fingerprint: u64,
}

impl<R: Real> Default for PairCache<R> {
    fn default() -> Self {
        Self::new()
    }
}

impl<R: Real> PairCache<R> {
    /// A cold cache: the first query runs as the cold one does, and fills it.
    pub const fn new() -> Self {
        Self {
            ids: [NO_ID; 3],
            separating: NO_ID,
            direction: [R::ZERO; 2],
            leaders: 0,
            lead: R::ZERO,
            pose: [R::ZERO; 6],
            radii: [R::ZERO; 2],
            reach: R::ZERO,
            moved: R::ZERO,
            fingerprint: 0,
        }
    }

    /// Forgets everything: the next query runs cold.
    pub fn clear(&mut self) {
        *self = Self::new();
    }

    /// GJK's first search direction, if the cache holds a sound one: finite
    /// and of about unit length (garbage could overflow a support's dots).
    pub(crate) fn first_direction(&self) -> Option<V2<R>> {
        let d = V2::new(self.direction[0], self.direction[1]);
        let dd = d.length_squared();
        (dd >= R::HALF * R::HALF && dd <= R::from_u32(4)).then_some(d)
    }

    /// Keeps the opposite of a result's unit normal (in A's frame) as the
    /// next first search direction.
    pub(crate) fn remember_normal(&mut self, normal: V2<R>) {
        self.direction = [-normal.x, -normal.y];
    }
}

#[cfg(not(any(target_os = "none", target_family = "wasm")))]
mod small {
    //! The warm starts of two small polygons (host only, as their separating
    //! axes are).

    use super::PairCache;
    use crate::minkowski::{MinkowskiVertex, Pair, NO_ID};
    use crate::polytope::first_max;
    use crate::quad_start::surely_encloses;
    use crate::real::{Real, V2};
    use crate::result::{Detection, Penetration, Status};
    use crate::sat::{
        face_and_vertex_by, face_and_vertex_placed, penetration_along, separates_by, Axes, Coordinates, FaceAndVertex,
        Polygons,
    };
    use crate::shape::SupportMap;
    use crate::simplex::{Payload, Simplex, Vertex};

    /// How far inside the cached triangle the origin must be, and by how
    /// much the leading axes must lead, over the coordinates' size: far
    /// above the rounding of either test, so the cold query's computed
    /// answer is certainly the cached one.
    const ROUNDING: u32 = 64;

    /// How many axes of the least overlap a cache keeps: two faces nearly
    /// parallel, as in resting contact, give two axes nearly tied, and the
    /// lead over the rest is what lets a step skip the others.
    pub(super) const LEADERS: usize = 4;

    /// Offset `c` of B's center from A's (in A's frame) in B's frame.
    #[inline(always)]
    fn seen_from_b<R: Real>(cos: R, sin: R, c: V2<R>) -> V2<R> {
        V2::new(cos * c.x + sin * c.y, cos * c.y - sin * c.x)
    }

    /// Both polygons' vertex counts and coordinates, mixed into 64 bits:
    /// each point's bits (one word, `point_bits`) salted by its place and
    /// multiplied by an odd constant (independent products, no chain), then
    /// summed. A product a point, not a coordinate: every cached
    /// penetration takes the fingerprint.
    fn fingerprint<R: Real>(a: &[V2<R>], b: &[V2<R>]) -> u64 {
        const SALT: u64 = 0x9E37_79B9_7F4A_7C15;
        const MIX: u64 = 0xD6E8_FEB8_6659_FD93;
        let mut sum = ((a.len() as u64) << 32 | b.len() as u64).wrapping_mul(MIX);
        let mut salt = SALT;
        // A loop for each polygon: a chain of the two is a branch where it
        // switches, mispredicted as the lengths differ from pair to pair.
        for polygon in [a, b] {
            for v in polygon {
                sum = sum.wrapping_add((R::point_bits(v.x, v.y) ^ salt).wrapping_mul(MIX));
                salt = salt.wrapping_add(SALT);
            }
        }
        (sum ^ (sum >> 32)).wrapping_mul(MIX)
    }

    /// Triangle `w` and its ids counter-clockwise: the second and third
    /// swapped where it turns the other way. By selects, as the
    /// orientation of a pair's triangle is a coin toss.
    #[inline(always)]
    fn counter_clockwise<R: Real>(w: [(V2<R>, u32); 3]) -> [(V2<R>, u32); 3] {
        let clockwise = (w[1].0 - w[0].0).cross(w[2].0 - w[0].0) < R::ZERO;
        let (second, third) = core::hint::select_unpredictable(clockwise, (w[2], w[1]), (w[1], w[2]));
        [w[0], second, third]
    }

    impl<R: Real> PairCache<R> {
        /// Vertex `id` of the Minkowski difference of the pair's small
        /// polygons, measured now; `None` for ids out of range. Inlined:
        /// out of line, each of a triangle's three came back through memory.
        #[inline(always)]
        fn vertex<A, B>(pair: &Pair<'_, R, A, B>, a: &[V2<R>], b: &[V2<R>], id: u32) -> Option<MinkowskiVertex<R>>
        where
            A: SupportMap<R> + ?Sized,
            B: SupportMap<R> + ?Sized,
        {
            let (pa, pb) = (*a.get((id >> 16) as usize)?, pair.b_to_pair(*b.get((id & 0xFFFF) as usize)?));
            Some(MinkowskiVertex { w: pb - pa, a: pa, b: pb, id })
        }

        /// Whether the cached triangle of ids (kept counter-clockwise) still
        /// encloses the origin, by more than rounding.
        fn encloses<A, B>(&self, pair: &Pair<'_, R, A, B>, a: &[V2<R>], b: &[V2<R>]) -> bool
        where
            A: SupportMap<R> + ?Sized,
            B: SupportMap<R> + ?Sized,
        {
            let w = |id| Self::vertex(pair, a, b, id).map(|v| v.w);
            // Spelt out, not `map`: the compiler called that closure out of
            // line, once a vertex.
            let [p, q, r] = [w(self.ids[0]), w(self.ids[1]), w(self.ids[2])];
            let (Some(p), Some(q), Some(r)) = (p, q, r) else { return false };
            let size = pair.coordinates_size();
            surely_encloses(&[p, q, r], R::from_u32(ROUNDING) * R::EPSILON * size, size)
        }

        /// A triangle of vertices of B - A that encloses the origin by more
        /// than rounding, the next step's proof of overlap, if one of two
        /// does: the face of the least overlap with the support across
        /// from it (it fails mostly where the origin lies deep), else the
        /// supports along the centers' offset and square to it both ways
        /// (which fails mostly where it lies shallow).
        fn refill_triangle<A, B>(&mut self, pair: &Pair<'_, R, A, B>, polygons: &Polygons<R>, axes: &Axes<R>)
        where
            A: SupportMap<R> + ?Sized,
            B: SupportMap<R> + ?Sized,
        {
            let size = pair.coordinates_size();
            let margin = R::from_u32(ROUNDING) * R::EPSILON * size;
            let (slot, u) = axes.least_overlap_by_square();
            let face = counter_clockwise(polygons.face_triangle(slot, u));
            if surely_encloses(&face.map(|s| s.0), margin, size) {
                self.ids = face.map(|s| s.1);
                return;
            }
            let d = pair.first_direction;
            let supports =
                counter_clockwise([polygons.support(d), polygons.support(d.perp_cw()), polygons.support(-d.perp_cw())]);
            self.ids =
                if surely_encloses(&supports.map(|s| s.0), margin, size) { supports.map(|s| s.1) } else { [NO_ID; 3] };
        }

        /// Whether the cached separating axis (there must be one) still
        /// separates the polygons, measured in its own polygon's frame with
        /// no vertex placed, by a margin above rounding: then the cold
        /// queries say apart too.
        fn still_separates<A, B>(&self, pair: &Pair<'_, R, A, B>, a: &[V2<R>], b: &[V2<R>]) -> bool
        where
            A: SupportMap<R> + ?Sized,
            B: SupportMap<R> + ?Sized,
        {
            let margin = R::from_u32(ROUNDING) * R::EPSILON * pair.coordinates_size();
            separates_by(pair, a, b, self.separating as usize, margin)
        }

        /// The intersection test of two small polygons: the cached
        /// separating axis or enclosing triangle if either still decides,
        /// else the bounding disks where they are apart (the cold test's
        /// next question, after the inner disks its caller asks), else
        /// every axis (and the cache refilled). The verdict is the cold
        /// test's.
        pub(crate) fn intersects_small<A, B>(&mut self, pair: &Pair<'_, R, A, B>, a: &[V2<R>], b: &[V2<R>]) -> Detection
        where
            A: SupportMap<R> + ?Sized,
            B: SupportMap<R> + ?Sized,
        {
            let decided = |intersecting| Detection { intersecting, iterations: 0, status: Status::Converged };
            if self.separating != NO_ID {
                if self.still_separates(pair, a, b) {
                    return decided(false);
                }
            } else if self.ids[0] != NO_ID && self.encloses(pair, a, b) {
                return decided(true);
            }
            // The cold test's next question: a pair whose disks are apart
            // keeps its cache as it was, which costs no more to ask again.
            if pair.bounding_disks_apart() {
                return decided(false);
            }
            let polygons = Polygons::new(pair, a, b);
            let axes = Axes::of(&polygons);
            let separated = axes.separated();
            if separated {
                self.separating = axes.most_separating() as u32;
            } else {
                self.separating = NO_ID;
                self.refill_triangle(pair, &polygons, &axes);
            }
            Detection { intersecting: !separated, iterations: 1, status: Status::Converged }
        }

        /// The distance of two small polygons where their closest features
        /// are an edge and a vertex: `None` where they overlap (the cold
        /// test's verdict), `Some(None)` where two vertices are closest
        /// (GJK answers). First from the cached axis alone, where it still
        /// separates them by a margin above rounding (the cold queries then
        /// say apart too) and its edge and nearest vertex are still the
        /// closest features: one pass over the axis decides and measures,
        /// the common case from step to step. Else the cached intersection
        /// test, and the axis that separates them the most, kept for the
        /// next step ([`face_and_vertex_placed`]).
        pub(crate) fn face_and_vertex<A, B>(
            &mut self,
            pair: &Pair<'_, R, A, B>,
            a: &[V2<R>],
            b: &[V2<R>],
        ) -> Option<Option<FaceAndVertex<R>>>
        where
            A: SupportMap<R> + ?Sized,
            B: SupportMap<R> + ?Sized,
        {
            if self.separating != NO_ID {
                let margin = R::from_u32(ROUNDING) * R::EPSILON * pair.coordinates_size();
                if let Some(found) = face_and_vertex_by(pair, a, b, self.separating as usize, margin) {
                    return Some(Some(found));
                }
            }
            if self.intersects_small(pair, a, b).intersecting {
                return None;
            }
            let best = Axes::new(pair, a, b).most_separating_by_square();
            let found = face_and_vertex_placed(pair, a, b, best);
            if found.is_some() {
                self.separating = best as u32;
            }
            Some(found)
        }

        /// Whether the cache holds an axis that last separated the pair.
        pub(crate) fn expects_apart(&self) -> bool {
            self.separating != NO_ID
        }

        /// The last leading axes, if the motion since cannot have let any
        /// other axis catch up with them (nor separate). Seen from A, B's
        /// vertices move by at most its center's move plus the rotation's
        /// change times B's radius about its center; seen from B, A's
        /// likewise: a bound on each axis's move, A's axes and B's.
        fn leaders_hold<A, B>(&mut self, pair: &Pair<'_, R, A, B>, a: &[V2<R>], b: &[V2<R>]) -> Option<u32>
        where
            A: SupportMap<R> + ?Sized,
            B: SupportMap<R> + ?Sized,
        {
            // No pose kept (or NaN): nothing to measure the motion from.
            let kept = self.reach > R::ZERO;
            if !kept {
                return None;
            }
            let (cos, sin, _) = pair.pose();
            let c = pair.centers;
            let [cos0, sin0, x0, y0, u0, v0] = self.pose;
            let [radius_a, radius_b] = self.radii;
            let turn = V2::new(cos - cos0, sin - sin0).length();
            let moved_a = (c - V2::new(x0, y0)).length();
            let moved_b = (seen_from_b(cos, sin, c) - V2::new(u0, v0)).length();
            let each = (moved_a + turn * radius_b).max(moved_b + turn * radius_a);
            let rounding = R::from_u32(ROUNDING) * R::EPSILON * (self.reach + moved_a);
            // The first leader may fall by `each`, any other axis rise by it.
            self.moved = R::TWO * each + rounding;
            // Written so that NaN anywhere fails it.
            let holds = self.leaders != 0 && self.lead > self.moved;
            (holds && self.fingerprint == fingerprint(a, b)).then_some(self.leaders)
        }

        /// Keeps the pose and the shapes' radii, and the leading axes with
        /// their lead if that exceeds the last motion (the shapes'
        /// fingerprint is then worth taking).
        fn remember_leaders<A, B>(&mut self, pair: &Pair<'_, R, A, B>, a: &[V2<R>], b: &[V2<R>], leaders: u32, lead: R)
        where
            A: SupportMap<R> + ?Sized,
            B: SupportMap<R> + ?Sized,
        {
            let (cos, sin, _) = pair.pose();
            let c = pair.centers;
            let from_b = seen_from_b(cos, sin, c);
            let centre_a = V2::<R>::from_glam(pair.a_center());
            let (radius_a, radius_b) = pair.bounding_radii();
            self.separating = NO_ID;
            self.pose = [cos, sin, c.x, c.y, from_b.x, from_b.y];
            self.radii = [radius_a, radius_b];
            self.reach = R::TWO * (centre_a.l1() + c.l1() + radius_a + radius_b);
            if lead > self.moved {
                (self.leaders, self.lead, self.fingerprint) = (leaders, lead, fingerprint(a, b));
            } else {
                self.leaders = 0;
            }
        }

        /// The penetration by the leading axes alone, as [`Axes`] would
        /// give it from every axis: the first greatest separation among
        /// them (`None` for a leader that separates, or a slot out of range).
        /// Always [`LEADERS`] axes, fewer leaders repeating the first, and
        /// the first greatest picked by selects: how many lead and which
        /// wins differ from pair to pair, and branches on them were
        /// mispredicted several times a query.
        fn by_leaders<A, B>(
            &mut self,
            pair: &Pair<'_, R, A, B>,
            coordinates: &Coordinates<'_, R>,
            leaders: u32,
        ) -> Option<Option<(R, V2<R>)>>
        where
            A: SupportMap<R> + ?Sized,
            B: SupportMap<R> + ?Sized,
        {
            // Set bits in ascending order: ties go to the first, as in `Axes`.
            let first = leaders.trailing_zeros() as usize;
            let mut rest = leaders;
            // Loops, not `from_fn`: the compiler called its closure out of
            // line, once a slot.
            let mut slots = [first; LEADERS];
            for slot in &mut slots {
                *slot = core::hint::select_unpredictable(rest == 0, first, rest.trailing_zeros() as usize);
                rest &= rest.wrapping_sub(1);
            }
            let mut axes = [(V2::zero(), R::ZERO, false); LEADERS];
            for (axis, &slot) in axes.iter_mut().zip(&slots) {
                *axis = coordinates.axis(pair, slot);
            }
            if !axes.iter().all(|axis| axis.2) {
                return None;
            }
            // A leader that separates now (seldom, so a predictable branch):
            // so would the cold query say.
            if let Some(k) = axes.iter().position(|axis| axis.1 > R::ZERO) {
                (self.separating, self.leaders) = (slots[k] as u32, 0);
                return Some(None);
            }
            // Every leader's separation and unit normal, independent of one
            // another, before the pick, rather than the winner's normal
            // after it: that waited on a square root and two divisions in
            // a row.
            // Coordinates in arrays apart: as one array of vectors, the
            // cached penetration read slower.
            let (nx, ny) = (axes.map(|axis| axis.0.x), axes.map(|axis| axis.0.y));
            let separation = R::scaled_separations(&nx, &ny, &axes.map(|axis| axis.1));
            let length: [R; LEADERS] = core::array::from_fn(|k| (nx[k] * nx[k] + ny[k] * ny[k]).sqrt());
            let ux: [R; LEADERS] = core::array::from_fn(|k| nx[k] / length[k]);
            let uy: [R; LEADERS] = core::array::from_fn(|k| ny[k] / length[k]);
            let best = first_max(&separation);
            let normal = axes[best].0;
            // The unit normal as `penetration_along` gives it, where its
            // common case (no tiny or non-finite normal) holds: computed in
            // every lane without its branches, which asked of each leader
            // cost more than the lanes save.
            let m = normal.max_abs();
            if m >= R::EPSILON * R::EPSILON && m.is_finite() {
                return Some(Some((R::ZERO - separation[best], V2::new(ux[best], uy[best]))));
            }
            Some(Some(penetration_along(separation[best], normal)))
        }

        /// The penetration of two small polygons (`None`: apart), as the
        /// cold query answers it by their separating axes, to the bit: from
        /// the cached separating axis or the cached leading axes alone where
        /// they still decide, else from every axis (and the cache refilled).
        pub(crate) fn penetration_small<A, B>(
            &mut self,
            pair: &Pair<'_, R, A, B>,
            a: &[V2<R>],
            b: &[V2<R>],
        ) -> Option<Penetration<R>>
        where
            A: SupportMap<R> + ?Sized,
            B: SupportMap<R> + ?Sized,
        {
            if self.separating != NO_ID && self.still_separates(pair, a, b) {
                return None;
            }
            let found = |(depth, normal): (R, V2<R>), iterations| Penetration {
                normal: pair.to_world_vector(normal),
                depth,
                error_bound: R::ZERO,
                iterations,
                status: Status::Converged,
            };
            if !R::WARM_LEADERS {
                let polygons = Polygons::new(pair, a, b);
                let axes = Axes::of(&polygons);
                let separated = axes.separated();
                self.separating = if separated { axes.most_separating() as u32 } else { NO_ID };
                return (!separated).then(|| found(axes.penetration(), 1));
            }
            // The leaders first: they are kept for overlapping polygons,
            // and where they hold, no axis outside them (the cached
            // separating one included) can change their answer.
            if let Some(leaders) = self.leaders_hold(pair, a, b) {
                if let Some(answer) = self.by_leaders(pair, &Coordinates::new(pair, a, b), leaders) {
                    return answer.map(|answer| found(answer, 0));
                }
            }
            let polygons = Polygons::new(pair, a, b);
            let (_, least, exists) = polygons.axis(self.separating as usize);
            if exists & (least > R::ZERO) {
                return None;
            }
            let axes = Axes::of(&polygons);
            if axes.separated() {
                (self.separating, self.leaders) = (axes.most_separating() as u32, 0);
                return None;
            }
            let (answer, leaders, lead) = axes.penetration_leaders(LEADERS);
            self.remember_leaders(pair, a, b, leaders, lead);
            Some(found(answer, 1))
        }

        /// The cached simplex of two polygons, its points measured
        /// now: GJK's start. `None` when the cache holds none or an id is
        /// out of range.
        pub(crate) fn simplex<A, B, P>(
            &self,
            pair: &Pair<'_, R, A, B>,
            a: &[V2<R>],
            b: &[V2<R>],
        ) -> Option<Simplex<R, P>>
        where
            A: SupportMap<R> + ?Sized,
            B: SupportMap<R> + ?Sized,
            P: Payload<R>,
        {
            let [first, second, third] = self.ids;
            let mut simplex = Simplex::new(Vertex::from_minkowski(&Self::vertex(pair, a, b, first)?));
            // A repeated id would make a flat simplex: dropped.
            if second != NO_ID && second != first {
                simplex.push(Vertex::from_minkowski(&Self::vertex(pair, a, b, second)?));
            }
            if third != NO_ID && third != first && third != second {
                simplex.push(Vertex::from_minkowski(&Self::vertex(pair, a, b, third)?));
            }
            Some(simplex)
        }

        /// Keeps GJK's last simplex (by its ids) for the next step.
        pub(crate) fn remember_simplex<P: Payload<R>>(&mut self, simplex: &Simplex<R, P>) {
            self.ids = simplex.ids();
        }
    }
}
