//! A large polygon's supports along sixteen fixed directions, kept with
//! it: any direction lies between two of them, so its support lies on the
//! arc between theirs, about a sixteenth of the polygon. A search there
//! reads that arc's few lines only, all asked for at once, where a search
//! of the whole polygon first reads a sample of it and then halves by
//! branches the predictor misses.
//!
//! Hosts only, as the other searches' aids: a firmware links none of it.

use super::{at, edge_from, prefetch};
use crate::real::{Real, V2};

/// How many directions: arcs of a sixteenth of a 1024-gon are the few
/// lines one wait for memory brings.
const POINTS: usize = 16;

/// Arcs longer than this are left to the search of the whole polygon: the
/// lines of a longer one, all asked for at once, would not be in flight
/// together.
const ARC_MAX: usize = 128;

/// tan(22.5 degrees): the directions are the x axis turned by multiples of
/// it and of quarter turns, compared with no square root or angle.
const TAN_EIGHTH: f64 = 0.414_213_562_373_095_05;

/// How many vertex slots a compass takes, at the end of a polygon's array:
/// two indices a slot, each held exactly as a coordinate (an integer below
/// 2^16 is exact in both precisions).
pub(crate) const SLOTS: usize = POINTS / 2;

/// The support vertices along the sixteen directions, counter-clockwise,
/// read from the slots they were written to ([`write`]); none in no slots.
#[derive(Clone, Copy, Debug)]
pub(crate) struct Compass<'s, R>(&'s [V2<R>]);

impl<'s, R: Real> Compass<'s, R> {
    /// No compass: every support is searched for on the whole polygon.
    pub(crate) const ABSENT: Self = Self(&[]);

    /// The compass [`write`] left in `slots`.
    #[inline(always)]
    pub(crate) fn in_slots(slots: &'s [V2<R>]) -> Self {
        Self(slots)
    }

    /// Direction `k`'s support index (`k` below [`POINTS`]).
    #[inline(always)]
    fn point(&self, k: usize) -> Option<usize> {
        let slot = self.0.get(k / 2)?;
        // `write` stored an integer below 2^16 here, which converts exactly.
        Some((if k.is_multiple_of(2) { slot.x } else { slot.y }).to_f64() as usize)
    }

    /// The arc whose vertices hold the support along `d` (from a direction's
    /// support to the next's), where it is short enough to search.
    #[inline(always)]
    pub(crate) fn arc(&self, n: usize, d: V2<R>) -> Option<Arc> {
        let k = sector(d);
        let (from, to) = (self.point(k)?, self.point((k + 1) % POINTS)?);
        let len = if to >= from { to - from } else { to + n - from };
        (from < n && to < n && len <= ARC_MAX).then_some(Arc { from, len })
    }
}

/// Writes the compass of a convex polygon (counter-clockwise) into `slots`
/// ([`SLOTS`] of them): each direction's support by a climb from the one
/// before, which the next direction's support is at or past, so the whole
/// costs one lap of the polygon.
pub(crate) fn write<R: Real>(vertices: &[V2<R>], slots: &mut [V2<R>]) {
    let n = vertices.len();
    if !(3..usize::from(u16::MAX)).contains(&n) {
        return;
    }
    let first = (0..n).fold(0, |best, i| if at(vertices, i).x > at(vertices, best).x { i } else { best });
    let mut points = [0u16; POINTS];
    let mut k = first;
    for (slot, j) in points.iter_mut().zip(0..) {
        k = super::hill_climb(vertices, direction::<R>(j), k, n).0;
        *slot = k as u16;
    }
    for (slot, pair) in slots.iter_mut().zip(points.chunks_exact(2)) {
        *slot = V2::new(R::from_u32(pair[0].into()), R::from_u32(pair[1].into()));
    }
}

/// Direction `j` of the compass (not of unit length).
fn direction<R: Real>(j: usize) -> V2<R> {
    let t = R::from_f64(TAN_EIGHTH);
    let eighth = [V2::new(R::ONE, R::ZERO), V2::new(R::ONE, t), V2::new(R::ONE, R::ONE), V2::new(t, R::ONE)];
    let mut v = eighth[j % 4];
    for _ in 0..(j / 4) % 4 {
        v = v.perp();
    }
    v
}

/// The sector of `d`: the `k` whose direction `d` has reached and whose
/// next direction it has not, by comparisons with no branch. Rounding may
/// put a direction within rounding of a compass direction on either side:
/// its support is then at the arc's end, where the climb after checks it.
#[inline(always)]
fn sector<R: Real>(d: V2<R>) -> usize {
    // A half turn back where `d` is in the lower half plane, a quarter
    // where it is then in the second quadrant: `q` is in the first.
    let lower = d.y < R::ZERO || (d.y == R::ZERO && d.x < R::ZERO);
    let h = core::hint::select_unpredictable(lower, -d, d);
    let second = h.x <= R::ZERO;
    let q = core::hint::select_unpredictable(second, V2::new(h.y, -h.x), h);
    let t = R::from_f64(TAN_EIGHTH);
    let within = usize::from(q.y >= t * q.x) + usize::from(q.y >= q.x) + usize::from(t * q.y >= q.x);
    8 * usize::from(lower) + 4 * usize::from(second) + within
}

/// An arc of a polygon: `len` edges from vertex `from`, counter-clockwise.
#[derive(Clone, Copy, Debug)]
pub(crate) struct Arc {
    from: usize,
    len: usize,
}

impl Arc {
    /// How many edges the arc spans.
    #[cfg(test)]
    pub(crate) fn len(&self) -> usize {
        self.len
    }

    /// Asks for every line of the arc at once.
    #[inline(always)]
    pub(crate) fn ask<R: Real>(&self, vertices: &[V2<R>]) {
        let n = vertices.len();
        let per_line = (64 / core::mem::size_of::<V2<R>>()).max(1);
        let end = self.from + self.len;
        for i in (self.from..=end).step_by(per_line) {
            prefetch(vertices, if i >= n { i - n } else { i });
        }
        prefetch(vertices, if end >= n { end - n } else { end });
    }

    /// The first vertex of the arc whose next edge does not rise along `d`
    /// (its end where every edge rises): the support, where `d` is in the
    /// arc's sector.
    #[inline(always)]
    pub(crate) fn top<R: Real>(&self, vertices: &[V2<R>], d: V2<R>) -> usize {
        let n = vertices.len();
        let k = self.from + first_not_rising(vertices, d, self.from, self.len);
        if k >= n {
            k - n
        } else {
            k
        }
    }
}

/// The first `k` in `0..len` whose edge `from + k` (cyclically) does not rise
/// along `d`, `len` where all rise, given that the edges rise and then stop
/// rising. Halved by branches, not selects: where lines are still in
/// flight, a branch lets the processor read ahead on its guess.
#[inline(always)]
pub(crate) fn first_not_rising<R: Real>(vertices: &[V2<R>], d: V2<R>, from: usize, len: usize) -> usize {
    let n = vertices.len();
    // Not rising, NaN too, as the climb stops.
    super::first_reached(0, len, |k| {
        let i = from + k;
        let rises = edge_from(vertices, if i >= n { i - n } else { i }).dot(d) > R::ZERO;
        !rises
    })
}

#[cfg(test)]
mod tests {
    use super::{direction, sector, POINTS};
    use crate::real::V2;

    /// Each compass direction is in its own sector, and a direction turned a
    /// little either way is in its sector or the one before.
    #[test]
    fn directions_start_their_sectors() {
        for j in 0..POINTS {
            let d = direction::<f64>(j);
            assert_eq!(sector(d), j, "direction {j}");
            let turn =
                |angle: f64| V2::new(d.x * angle.cos() - d.y * angle.sin(), d.x * angle.sin() + d.y * angle.cos());
            assert_eq!(sector(turn(1e-6)), j, "direction {j} turned forwards");
            assert_eq!(sector(turn(-1e-6)), (j + POINTS - 1) % POINTS, "direction {j} turned back");
        }
    }
}
