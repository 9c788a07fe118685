//! Time of impact of two shapes that translate and rotate over a step, by
//! conservative advancement (Mirtich; Catto's "Continuous Collision").
//!
//! At a time `t` the distance query gives the normal `n` from A towards B.
//! Along a fixed `n`, the gap between the shapes' extents can close no
//! faster than the relative velocity of their rotation centres along `n`
//! plus each angular speed times the shape's reach from its centre: every
//! point's velocity is its centre's plus `w x r`. While that gap is positive
//! it is a lower bound of the distance, so the shapes cannot come closer
//! than the target before the gap closes to it at that speed; the time
//! advances that far and asks again. The bound is a true upper bound and
//! the gap is measured by support points (not taken from the distance's
//! own estimate), so no step passes the first contact.

use crate::config::ImpactConfig;
use crate::error::Error;
use crate::manifold::facing_features;
use crate::minkowski::Pair;
use crate::real::{Real, V2};
use crate::result::{FeatureId, Penetration, Separation, Status};
use crate::shape::SupportMap;
use crate::transform::{check_point, Transform};

/// The largest rotation over one step a [`Sweep`] takes, in radians: beyond
/// it an angle's sine and cosine lose their accuracy in f32.
pub const MAX_SWEEP_ANGLE: f64 = 1.0e5;

/// How one shape moves over a step, for [`Gjk::time_of_impact`](crate::Gjk::time_of_impact):
/// from its start placement, a point of it (the rotation centre, in the
/// shape's local coordinates) translates by `translation` while the shape
/// turns by `angle` about that point, both at constant speed. Validated
/// once, so the query never meets NaN or infinity.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Sweep<R: Real> {
    start: Transform<R>,
    /// The rotation centre in the shape's local coordinates.
    center: V2<R>,
    /// The rotation centre in the world at the start.
    center_start: V2<R>,
    translation: V2<R>,
    angle: R,
}

impl<R: Real> Sweep<R> {
    /// The shape placed by `start` at the beginning of the step, its local
    /// point `local_center` moving by `translation` while the shape turns
    /// by `angle` radians (counter-clockwise) about it. Points must be
    /// finite and within [`Real::MAX_COORDINATE`] (at both ends of the
    /// step); the angle finite and at most [`MAX_SWEEP_ANGLE`] in magnitude
    /// ([`Error::AngleOutOfRange`]).
    pub fn new(start: &Transform<R>, local_center: R::Vector, translation: R::Vector, angle: R) -> Result<Self, Error> {
        if !angle.is_finite() {
            return Err(Error::NonFinite);
        }
        if angle.abs() > R::from_f64(MAX_SWEEP_ANGLE) {
            return Err(Error::AngleOutOfRange);
        }
        let center = check_point(V2::from_glam(local_center))?;
        let translation = check_point(V2::from_glam(translation))?;
        let center_start = check_point(start.rotate(center) + start.translation)?;
        check_point(center_start + translation)?;
        check_point(start.translation + translation)?;
        Ok(Self { start: *start, center, center_start, translation, angle })
    }

    /// The shape placed by `start`, translating by `translation` without
    /// turning.
    pub fn translation(start: &Transform<R>, translation: R::Vector) -> Result<Self, Error> {
        Self::new(start, R::vector(R::ZERO, R::ZERO), translation, R::ZERO)
    }

    /// The shape staying where `start` places it.
    pub fn still(start: &Transform<R>) -> Self {
        let zero = V2::zero();
        Self { start: *start, center: zero, center_start: start.translation, translation: zero, angle: R::ZERO }
    }

    /// The placement at `time` (a fraction of the step, clamped to [0, 1];
    /// NaN is 0): the one the query measures at, so the placement of its
    /// answer.
    pub fn transform_at(&self, time: R) -> Transform<R> {
        let t = if time > R::ZERO { time.min(R::ONE) } else { R::ZERO };
        if self.angle == R::ZERO {
            // No turn: the start's rotation to the bit, and the translation
            // moved without a detour through the centre.
            return Transform { translation: self.start.translation + self.translation * t, ..self.start };
        }
        let (s, c) = (self.angle * t).sin_cos();
        let (c0, s0) = (self.start.cos, self.start.sin);
        let (cos, sin) = (c0 * c - s0 * s, s0 * c + c0 * s);
        // Both factors are unit to rounding, and so is their product; the
        // division keeps the drift from adding up.
        let len = (cos * cos + sin * sin).sqrt();
        let mut placed = Transform { cos: cos / len, sin: sin / len, ..self.start };
        placed.translation = self.center_start + self.translation * t - placed.rotate(self.center);
        placed
    }

    /// The start placement.
    pub fn start(&self) -> Transform<R> {
        self.start
    }
    /// The rotation centre's translation over the step.
    pub fn linear(&self) -> R::Vector {
        self.translation.to_glam()
    }
    /// The turn over the step, in radians.
    pub fn angle(&self) -> R {
        self.angle
    }

    /// An upper bound of the distance from the rotation centre to any point
    /// of `shape`: the centre's distance from the shape's own centre plus
    /// the shape's bounding radius, a little over for rounding.
    fn reach<S: SupportMap<R> + ?Sized>(&self, shape: &S) -> R {
        if self.angle == R::ZERO {
            return R::ZERO;
        }
        let own = V2::from_glam(shape.reference_point()) + V2::from_glam(shape.center());
        let r = (self.center - own).length() + shape.bounding_radius();
        r * (R::ONE + R::from_u32(8) * R::EPSILON)
    }
}

/// Where a time-of-impact query ended.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum ImpactOutcome<R: Real> {
    /// The shapes come within the target separation (and the tolerance)
    /// at [`Impact::time`], and no closer before.
    Hit(Impact<R>),
    /// They stay farther apart than the target over the whole step.
    Miss,
    /// They are closer than the target at the start already.
    Start(ImpactStart<R>),
}

/// The shapes just before they touch, placed at `time` by their sweeps
/// ([`Sweep::transform_at`]), in world coordinates.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Impact<R: Real> {
    /// The fraction of the step, in [0, 1]: never after the first time the
    /// shapes come within the target separation.
    pub time: R,
    /// Their distance at `time`: within the tolerance above the target when
    /// the query converged (to rounding), more when it stopped at its
    /// iteration limit.
    pub separation: R,
    /// Unit normal from A towards B at `time`.
    pub normal: R::Vector,
    /// The closest point on A at `time`.
    pub point_a: R::Vector,
    /// The closest point on B at `time`.
    pub point_b: R::Vector,
    /// The features that face each other there, as a contact manifold
    /// names them: a face within 2.5 degrees of the normal, else the
    /// vertex nearest the other shape (on a rounded shape, the arc around
    /// it; [`Feature::Curve`](crate::Feature::Curve) on a curved core).
    pub features: FeatureId,
}

/// Shapes closer than the target at the start.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ImpactStart<R: Real> {
    /// Their distance, or minus their penetration depth when they overlap
    /// (zero when they only touch).
    pub separation: R,
    /// Unit normal from A towards B: the distance's, or the penetration's.
    pub normal: R::Vector,
}

/// The answer of a time-of-impact query.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct TimeOfImpact<R: Real> {
    pub outcome: ImpactOutcome<R>,
    /// Distance queries asked (one per advancement).
    pub iterations: u32,
    /// [`Status::IterationLimit`]: the advancement ran out of iterations (or
    /// could not advance: the distance's normal no better than the
    /// tolerance), and the hit is where it stopped, a time no later than the
    /// first contact with the shapes still apart by its `separation`.
    pub status: Status,
}

impl<R: Real> TimeOfImpact<R> {
    pub fn hit(&self) -> Option<&Impact<R>> {
        match &self.outcome {
            ImpactOutcome::Hit(h) => Some(h),
            _ => None,
        }
    }
}

/// Conservative advancement of two sweeps: `distance` is the distance query
/// of the placed shapes, `penetration` the penetration query for shapes that
/// overlap at the start.
pub(crate) fn advance<R, A, B>(
    a: &A,
    sweep_a: &Sweep<R>,
    b: &B,
    sweep_b: &Sweep<R>,
    config: &ImpactConfig<R>,
    distance: impl Fn(&Transform<R>, &Transform<R>) -> Option<Separation<R>>,
    penetration: impl FnOnce(&Transform<R>, &Transform<R>) -> Option<Penetration<R>>,
) -> TimeOfImpact<R>
where
    R: Real,
    A: SupportMap<R> + ?Sized,
    B: SupportMap<R> + ?Sized,
{
    let (target, tolerance) = (config.target(), config.tolerance());
    let relative = sweep_b.translation - sweep_a.translation;
    let spin = sweep_a.angle.abs() * sweep_a.reach(a) + sweep_b.angle.abs() * sweep_b.reach(b);
    let mut t = R::ZERO;
    let mut iterations = 0;
    let mut last: Option<(R, Separation<R>)> = None;
    loop {
        // Made one at a time and borrowed, not held across the loop: the
        // distance query below then has a microcontroller's small stack to
        // itself.
        let ta = sweep_a.transform_at(t);
        let tb = sweep_b.transform_at(t);
        iterations += 1;
        let done = |t: R, sep: &Separation<R>, status| {
            let (ta, tb) = (sweep_a.transform_at(t), sweep_b.transform_at(t));
            let normal = ta.inverse_rotate(V2::from_glam(sep.normal));
            let hit = Impact {
                time: t,
                separation: sep.distance,
                normal: sep.normal,
                point_a: sep.point_a,
                point_b: sep.point_b,
                features: facing_features(&Pair::new(a, &ta, b, &tb), normal),
            };
            TimeOfImpact { outcome: ImpactOutcome::Hit(hit), iterations, status }
        };
        let Some(ref sep) = distance(&ta, &tb) else {
            return match last {
                // Touching where the last step proved them apart: rounding
                // at a target of about zero. The last time is still safe,
                // but no closer than it was.
                Some((t, ref sep)) => done(t, sep, Status::IterationLimit),
                None => start_overlap(penetration(&ta, &tb), iterations),
            };
        };
        if t == R::ZERO && sep.distance < target {
            let start = ImpactStart { separation: sep.distance, normal: sep.normal };
            return TimeOfImpact { outcome: ImpactOutcome::Start(start), iterations, status: Status::Converged };
        }
        if sep.distance <= target + tolerance {
            return done(t, sep, Status::Converged);
        }
        let n = V2::from_glam(sep.normal);
        let gap = gap_along(a, &ta, b, &tb, n).min(sep.distance);
        // How fast the gap along `n` can close, over by its rounding (which
        // the difference may cancel down to).
        let rounding = R::from_u32(8) * R::EPSILON * (spin + relative.x.abs() + relative.y.abs());
        let closing = spin - relative.dot(n) + rounding;
        let miss = TimeOfImpact { outcome: ImpactOutcome::Miss, iterations, status: Status::Converged };
        // No gap beyond the target along this normal (a normal iterated to
        // a tolerance wider than the caller's): no step can be proved safe.
        if gap <= target {
            return done(t, sep, Status::IterationLimit);
        }
        // The gap never closes to the target: not within the step either.
        if closing <= R::ZERO {
            return miss;
        }
        let next = t + (gap - target) / closing;
        if next > R::ONE {
            return miss;
        }
        if iterations >= config.max_iterations() {
            return done(t, sep, Status::IterationLimit);
        }
        last = Some((t, *sep));
        t = next;
    }
}

/// Shapes overlapping or touching at the start.
fn start_overlap<R: Real>(penetration: Option<Penetration<R>>, iterations: u32) -> TimeOfImpact<R> {
    let (separation, normal, status, more) = match penetration {
        Some(p) => (-p.depth, p.normal, p.status, p.iterations),
        // Touching to the distance query, apart to the penetration query.
        None => (R::ZERO, R::vector(R::ONE, R::ZERO), Status::Converged, 0),
    };
    TimeOfImpact {
        outcome: ImpactOutcome::Start(ImpactStart { separation, normal }),
        iterations: iterations + more,
        status,
    }
}

/// A lower bound of the gap between the placed shapes along the world unit
/// `n` (from A towards B): B's lowest point along `n` less A's highest, from
/// one support point of their difference, less its rounding at the scale of
/// the pair. (The placements' own rounding, far from the origin, is the
/// caller's, as in every query.) Out of line on bare metal, to keep the
/// advancement's frame small.
#[cfg_attr(target_os = "none", inline(never))]
fn gap_along<R, A, B>(a: &A, ta: &Transform<R>, b: &B, tb: &Transform<R>, n: V2<R>) -> R
where
    R: Real,
    A: SupportMap<R> + ?Sized,
    B: SupportMap<R> + ?Sized,
{
    let pair = Pair::new(a, ta, b, tb);
    let local = ta.inverse_rotate(n);
    let w = pair.support_shared(-local).w;
    let size = pair.centers.l1() + w.l1() + R::TWO * pair.scale();
    local.dot(w) - pair.radius() - R::from_u32(8) * R::EPSILON * size
}
