//! Two shapes whose cores are single points (circles): GJK's loop would end
//! on the one-vertex simplex of their offset, found twice. The queries are
//! finished here from that vertex directly, to the loop's bit (through
//! `dyn SupportMap` the loop still runs, and `tests/point_cores.rs` holds
//! the two together), without a simplex to build and read back.

use crate::minkowski::{MinkowskiVertex, Pair};
use crate::real::{Real, V2};
use crate::result::{Detection, Penetration, Separation, Status};
use crate::shape::SupportMap;

/// The intersection test: GJK's verdict, iteration count and status (its
/// first support is the centers' offset, and its second repeats it).
#[inline(always)]
pub(crate) fn overlap_test<R, A, B>(pair: &Pair<'_, R, A, B>, detect_epsilon: R) -> Detection
where
    R: Real,
    A: SupportMap<R> + ?Sized,
    B: SupportMap<R> + ?Sized,
{
    let reach = pair.detect_reach(detect_epsilon);
    let intersecting = pair.centers.length_squared() <= reach * reach;
    Detection { intersecting, iterations: if intersecting { 1 } else { 2 }, status: Status::Converged }
}

/// The cores' offset as GJK's support finds it. `None` for coincident
/// cores, which the loop calls overlapping.
pub(crate) struct PointCores<R: Real> {
    w: MinkowskiVertex<R>,
}

impl<R: Real> PointCores<R> {
    #[inline(always)]
    pub fn new<A, B>(pair: &Pair<'_, R, A, B>) -> Option<Self>
    where
        A: SupportMap<R> + ?Sized,
        B: SupportMap<R> + ?Sized,
    {
        let w = pair.support(pair.first_direction);
        if w.w.length_squared() == R::ZERO {
            return None;
        }
        Some(Self { w })
    }

    /// Whether the cores are certainly within `radius` (the radii's sum)
    /// of each other, decided on the squared offset with a margin of 16 eps:
    /// where it says so, the distance query's answer is `None` as well. Its
    /// branch is as unpredictable as the shapes' overlap, but no longer
    /// waits for a square root to learn which way it goes.
    #[inline(always)]
    pub fn certainly_within(&self, radius: R) -> bool {
        let vv = self.w.w.length_squared();
        // Normal numbers only: then the square and the limit round relatively.
        vv >= R::MIN_POSITIVE && vv < radius * radius * (R::ONE - R::from_u32(16) * R::EPSILON)
    }

    /// The cores' distance and unit offset, with the loop's certified lower
    /// bound `w . w / |w|` (`v = w`). Where the offset is neither tiny nor
    /// huge the distance is that same root, and one root serves both: the
    /// compiler does not merge the two it would otherwise take.
    #[inline(always)]
    fn length_unit_and_lower_bound(&self) -> Option<(R, V2<R>, R)> {
        let w = self.w.w;
        let vv = w.length_squared();
        let root = vv.sqrt();
        let lower_bound = R::ZERO.max(vv / root);
        // Above this square the largest coordinate is at least eps^2, where
        // `try_length_and_unit` takes this same root.
        let tiny = R::EPSILON * R::EPSILON;
        if vv >= R::from_u32(4) * tiny * tiny && vv.is_finite() {
            return Some((root, V2::new(w.x / root, w.y / root), lower_bound));
        }
        let (length, unit) = w.try_length_and_unit()?;
        Some((length, unit, lower_bound))
    }

    /// The distance query's answer; `None` where the shapes touch or overlap.
    #[inline(always)]
    pub fn separation<A, B>(&self, pair: &Pair<'_, R, A, B>) -> Option<Separation<R>>
    where
        A: SupportMap<R> + ?Sized,
        B: SupportMap<R> + ?Sized,
    {
        let (core_distance, normal, lower_bound) = self.length_unit_and_lower_bound()?;
        let (radius_a, radius_b) = (pair.radius_a(), pair.radius_b());
        let radius = radius_a + radius_b;
        if core_distance <= radius {
            return None;
        }
        // The simplex's witness points are weighted sums from zero: a -0
        // comes out +0.
        let (a, b) = (V2::zero() + self.w.a, V2::zero() + self.w.b);
        Some(Separation {
            distance: (core_distance - radius).max(R::ZERO),
            normal: pair.to_world_vector(normal),
            point_a: pair.to_world_point(a + normal * radius_a),
            point_b: pair.to_world_point(b - normal * radius_b),
            error_bound: (core_distance - lower_bound).max(R::ZERO),
            iterations: 2,
            status: Status::Converged,
        })
    }

    /// The penetration query's answer; `None` where the shapes are apart.
    #[inline(always)]
    pub fn penetration<A, B>(&self, pair: &Pair<'_, R, A, B>) -> Option<Penetration<R>>
    where
        A: SupportMap<R> + ?Sized,
        B: SupportMap<R> + ?Sized,
    {
        let radius = pair.radius();
        // A closest point too small to give a direction is touching.
        let (distance, normal, lower_bound) = self
            .length_unit_and_lower_bound()
            .unwrap_or_else(|| (R::ZERO, pair.centers.try_normalize().unwrap_or(V2::new(R::ONE, R::ZERO)), R::ZERO));
        if distance > radius {
            return None;
        }
        Some(Penetration {
            normal: pair.to_world_vector(normal),
            depth: (radius - distance).max(R::ZERO),
            error_bound: (distance - lower_bound).max(R::ZERO),
            iterations: 2,
            status: Status::Converged,
        })
    }
}
