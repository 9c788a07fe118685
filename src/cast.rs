//! The linear shape cast: B translating by a motion against A, as a ray from
//! the origin against their Minkowski difference. B at `B + t m` touches A
//! when the origin reaches the boundary of `B - A + t m`, that is when
//! `-t m` does the boundary of `B - A`: a ray from the origin along `-m`.
//!
//! The ray is cast by portal refinement on the difference's support map
//! (the cores' difference swept by both radii): two support points on either
//! side of the ray, refined by the support along their chord's normal until
//! the chord is on the boundary. For polytope cores that ends exactly, on a
//! vertex id already in the chord, and the hit comes from the closed form of
//! the ray against the final chord's core feature swept by the radii (a face,
//! or a vertex's disk), so polygons, circles, capsules and segments are cast
//! to rounding; curved cores stop at the ray-cast epsilon. Unlike the GJK ray
//! cast ([`Gjk::raycast`](crate::Gjk::raycast)) it keeps both shapes' points,
//! for the touching points, and the exact normal of the face hit.

use crate::error::Error;
use crate::minkowski::{MinkowskiVertex, Pair, NO_ID};
use crate::real::{Real, V2};
use crate::result::{Penetration, RayOutcome, Status};
use crate::shape::{cast_ray_capsule, cast_ray_disk, SupportMap};
use crate::transform::check_point;

/// B's translation over the cast, relative to A: validated once, so the
/// cast itself never meets NaN or infinity.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Motion<R: Real> {
    pub(crate) translation: V2<R>,
}

impl<R: Real> Motion<R> {
    /// B moving by `translation` while A stays: finite and within
    /// [`Real::MAX_COORDINATE`]. Zero is allowed (the cast then only
    /// tells whether the shapes overlap at the start).
    pub fn new(translation: R::Vector) -> Result<Self, Error> {
        Ok(Self { translation: check_point(V2::from_glam(translation))? })
    }
    /// Both shapes moving: A by `motion_a` and B by `motion_b` over the same
    /// time, which is B moving by `motion_b - motion_a` relative to A.
    pub fn relative(motion_a: R::Vector, motion_b: R::Vector) -> Result<Self, Error> {
        let (a, b) = (Self::new(motion_a)?, Self::new(motion_b)?);
        Ok(Self { translation: check_point(b.translation - a.translation)? })
    }
    /// B's translation relative to A.
    pub fn translation(&self) -> R::Vector {
        self.translation.to_glam()
    }
}

/// Where a linear cast ended.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum CastOutcome<R: Real> {
    /// The shapes first touch along the motion.
    Hit(CastHit<R>),
    /// They do not touch over the whole motion.
    Miss,
    /// They overlap or touch already at the start: there is no first
    /// contact to report, but there is a penetration to get out of.
    Start(CastStart<R>),
}

/// The first contact of a linear cast, in world coordinates.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct CastHit<R: Real> {
    /// The fraction of the motion travelled at the contact, in [0, 1].
    pub fraction: R,
    /// The distance travelled: `fraction` times the motion's length.
    pub distance: R,
    /// Unit normal from A towards B: the exact normal of the face hit (of
    /// the Minkowski difference), or of the disk at a rounded vertex.
    pub normal: R::Vector,
    /// The touching point on A.
    pub point_a: R::Vector,
    /// The touching point on B, with B moved to the contact.
    pub point_b: R::Vector,
    /// Bound on `|distance - exact distance|`: the iteration's tolerance
    /// (zero for polytope cores, which end exactly) and rounding at the
    /// scale of the pair's size and placement, over the incidence
    /// `|normal . motion| / |motion|`, as [`RayHit::error_bound`](crate::RayHit::error_bound).
    pub error_bound: R,
}

/// Shapes that overlap or touch at the start of a cast.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct CastStart<R: Real> {
    /// Their penetration, as [`Gjk::penetration`](crate::Gjk::penetration)
    /// gives it (depth zero when they only touch).
    pub penetration: Penetration<R>,
    /// Whether the motion moves B away from A (`motion . normal > 0`): a
    /// shape resting against or sliding out of another may then move on.
    pub separating: bool,
}

/// The answer of a linear cast.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ShapeCast<R: Real> {
    pub outcome: CastOutcome<R>,
    /// Support evaluations of the cast (the penetration's iterations for
    /// [`CastOutcome::Start`]).
    pub iterations: u32,
    pub status: Status,
}

impl<R: Real> ShapeCast<R> {
    pub fn hit(&self) -> Option<&CastHit<R>> {
        match &self.outcome {
            CastOutcome::Hit(h) => Some(h),
            _ => None,
        }
    }
    fn miss(iterations: u32) -> Self {
        Self { outcome: CastOutcome::Miss, iterations, status: Status::Converged }
    }
}

/// A point of the swept difference with the cores' points it comes from.
#[derive(Clone, Copy, Debug)]
struct Corner<R> {
    /// The swept difference's point (the core's plus the radii along the
    /// direction it was asked for).
    w: V2<R>,
    /// The cores' points: A's, B's, and B's minus A's.
    a: V2<R>,
    b: V2<R>,
    core: V2<R>,
    id: u32,
}

/// The ray's entry into the final chord's core feature swept by the radii.
struct Entry<R> {
    /// Distance along the ray.
    s: R,
    /// Outward unit normal of the difference there.
    normal: V2<R>,
    /// Weight of the chord's left corner in the core point touched.
    left: R,
}

/// The linear cast of the placed pair, B moving by `motion` (in the pair's
/// frame), with the cores' support; the caller has ruled out an overlap at
/// the start. `max_iterations` and `epsilon` bound the refinement on curved
/// cores (relative to the pair's size), as they do the GJK ray cast. Out
/// of line on bare metal, so its working values and the caller's are never
/// held at once (see `Gjk::cast`).
#[cfg_attr(target_os = "none", inline(never))]
pub(crate) fn cast_pair<R, A, B>(
    pair: &Pair<'_, R, A, B>,
    motion: V2<R>,
    max_iterations: u32,
    epsilon: R,
) -> ShapeCast<R>
where
    R: Real,
    A: SupportMap<R> + ?Sized,
    B: SupportMap<R> + ?Sized,
{
    let Some((length, unit)) = motion.try_length_and_unit() else {
        return ShapeCast::miss(0);
    };
    // The ray from the origin along u = -m, against the difference B - A.
    let u = -unit;
    let (radius_a, radius_b) = (pair.radius_a(), pair.radius_b());
    let radius = radius_a + radius_b;
    let scale = pair.scale();
    let support = |d: V2<R>| corner(pair.support_shared(d), d, radius);
    let left = u.perp();
    let mut l = support(left);
    let mut r = support(-left);
    let mut iterations = 2;
    let (side_l, side_r) = (left.dot(l.w), left.dot(r.w));
    // Both widest points on one side: the ray's line passes the difference.
    if side_l < R::ZERO || side_r > R::ZERO {
        return ShapeCast::miss(iterations);
    }
    let mut gap = R::ZERO;
    let status = loop {
        // One core point on both sides (circles' cores, a vertex's disk):
        // the boundary between them is that point's disk.
        if l.id == r.id && l.id != NO_ID {
            gap = R::ZERO;
            break Status::Converged;
        }
        let Some(n) = (l.w - r.w).perp().try_normalize() else {
            break Status::Converged;
        };
        if iterations >= max_iterations {
            break Status::IterationLimit;
        }
        iterations += 1;
        let mut s = support(n);
        // How far the support plane lies beyond the chord, towards the ray's
        // origin: nothing beyond it, the chord is on the boundary.
        gap = n.dot(s.w - l.w);
        if gap <= R::ZERO {
            gap = R::ZERO;
            break Status::Converged;
        }
        if s.id == NO_ID {
            if gap <= epsilon * scale {
                break Status::Converged;
            }
        } else if (s.id == l.id || s.id == r.id) && l.id != NO_ID && r.id != NO_ID {
            // Polytope cores: the chord's core points are one feature when
            // the support along their own normal is one of them (a face of
            // the cores' difference); else that support lies between them.
            // Not where one end is a curve point (a half-ellipse's dome
            // beside its corner): that chord is no face, and the support,
            // a point of the vertex's disk, brackets the ray as any does.
            let core_normal = (l.core - r.core).perp();
            if radius == R::ZERO || core_normal.max_abs() == R::ZERO {
                gap = R::ZERO;
                break Status::Converged;
            }
            iterations += 1;
            s = support(core_normal);
            if s.id == l.id || s.id == r.id {
                gap = R::ZERO;
                break Status::Converged;
            }
        }
        if left.dot(s.w) >= R::ZERO {
            l = s;
        } else {
            r = s;
        }
    };
    let entry = entry(l, r, radius, u).unwrap_or_else(|| chord_entry(l.w, r.w, u));
    // Entered before the start: the difference lies behind the ray's origin
    // (a miss), or, to rounding, touches it (a contact at once).
    let s = if entry.s < R::ZERO {
        if chord_entry(l.w, r.w, u).s <= R::ZERO {
            return ShapeCast::miss(iterations);
        }
        R::ZERO
    } else {
        entry.s
    };
    if !s.is_finite() || s > length {
        return ShapeCast::miss(iterations);
    }
    let w = entry.left;
    let a = l.a * w + r.a * (R::ONE - w);
    let b = l.b * w + r.b * (R::ONE - w);
    let n = entry.normal;
    let a = if radius_a > R::ZERO { a - n * radius_a } else { a };
    let b = if radius_b > R::ZERO { b + n * radius_b } else { b };
    let size = pair.centers.l1() + R::TWO * scale;
    let hit = CastHit {
        fraction: (s / length).min(R::ONE),
        distance: s,
        normal: pair.to_world_vector(-n),
        point_a: pair.to_world_point(a),
        point_b: pair.to_world_point(b + u * -s),
        error_bound: error_bound(gap, s, -n.dot(u), size),
    };
    ShapeCast { outcome: CastOutcome::Hit(hit), iterations, status }
}

/// A support point of the cores' difference swept by `radius` along `d`.
#[inline(always)]
fn corner<R: Real>(v: MinkowskiVertex<R>, d: V2<R>, radius: R) -> Corner<R> {
    let w = match (radius > R::ZERO).then(|| d.try_normalize()).flatten() {
        Some(unit) => v.w + unit * radius,
        None => v.w,
    };
    Corner { w, a: v.a, b: v.b, core: v.w, id: v.id }
}

/// Where the ray crosses the chord from `r` to `l` (its normal towards the
/// ray's origin): the entry when the chord is a face.
fn chord_entry<R: Real>(l: V2<R>, r: V2<R>, u: V2<R>) -> Entry<R> {
    let e = l - r;
    let n = e.perp();
    let den = n.dot(u);
    let Some(normal) = n.try_normalize().filter(|_| den < R::ZERO) else {
        // A single point, or a chord along the ray: the nearer end.
        let (s, left) = if u.dot(l) <= u.dot(r) { (u.dot(l), R::ONE) } else { (u.dot(r), R::ZERO) };
        return Entry { s, normal: -u, left };
    };
    let s = n.dot(l) / den;
    let left = ((u * s - r).dot(e) / e.length_squared()).max(R::ZERO).min(R::ONE);
    Entry { s, normal, left }
}

/// The ray's entry into the chord's core feature (the segment between its
/// core points, or the one point) swept by `radius`: the capsule's or the
/// disk's own closed-form cast, from the origin. `None` where it would not
/// enter (rounding at a grazing ray), and the chord stands in.
fn entry<R: Real>(l: Corner<R>, r: Corner<R>, radius: R, u: V2<R>) -> Option<Entry<R>> {
    if radius == R::ZERO {
        return Some(chord_entry(l.w, r.w, u));
    }
    let e = l.core - r.core;
    let one_point = (l.id == r.id && l.id != NO_ID) || e.max_abs() == R::ZERO;
    let cast = if one_point {
        cast_ray_disk(l.core, radius, V2::zero(), u, R::INFINITY)
    } else {
        cast_ray_capsule(r.core, e, radius, V2::zero(), u, R::INFINITY)
    };
    let RayOutcome::Hit(hit) = cast.outcome else {
        return None;
    };
    // The core point touched, as a weight of the chord's ends: the hit's
    // foot on the segment (an end for a hit on its disk).
    let left = if one_point {
        R::ONE
    } else {
        ((u * hit.distance - r.core).dot(e) / e.length_squared()).max(R::ZERO).min(R::ONE)
    };
    Some(Entry { s: hit.distance, normal: V2::from_glam(hit.normal), left })
}

/// The cast distance's error bound: the iteration's gap and rounding at the
/// scale of the pair (`size`) and the distance, over the incidence `cos`;
/// capped by the distance plus the pair's extent, so never inf or NaN.
fn error_bound<R: Real>(gap: R, s: R, cos: R, size: R) -> R {
    let eps = R::EPSILON;
    let across = gap + R::from_u32(8) * eps * (size + s);
    let cap = s + R::TWO * size + gap;
    let cos = cos - R::TWO * eps;
    if cos * cap > across {
        (across / cos + R::from_u32(4) * eps * s).min(cap)
    } else {
        cap
    }
}
