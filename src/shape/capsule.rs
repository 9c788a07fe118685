use super::circle::cast_ray_disk;
use super::{Segment, SupportMap};
use crate::error::Error;
use crate::real::{Real, V2};
use crate::result::{hit, LocalRayCast, RayCast, RayOutcome};
use crate::transform::check_length;

/// A segment swept by a radius (a stadium).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Capsule<R: Real> {
    core: Segment<R>,
    radius: R,
}

impl<R: Real> Capsule<R> {
    /// The segment `a`-`b` (distinct points) swept by `radius` (> 0).
    pub fn new(a: R::Vector, b: R::Vector, radius: R) -> Result<Self, Error> {
        let radius = check_length(radius)?;
        Segment::new(a, b).map(|core| Self { core, radius })
    }

    /// dyn4j's constructor: a capsule `width` by `height` centered on the
    /// origin, its long axis along x if `width >= height`, else along y.
    /// Equal sides give a circle-like capsule with a tiny core, as dyn4j does.
    pub fn from_size(width: R, height: R) -> Result<Self, Error> {
        let (w, h) = (check_length(width)?, check_length(height)?);
        let (long, short, along_x) = if w >= h { (w, h, true) } else { (h, w, false) };
        let radius = short * R::HALF;
        // A capsule of equal sides has a zero-length core; give it the
        // shortest segment that is still a segment, as a point core would do.
        let mut half_core = (long - short) * R::HALF;
        if half_core <= R::ZERO {
            half_core = radius * R::EPSILON;
        }
        let (a, b) = if along_x {
            (R::vector(-half_core, R::ZERO), R::vector(half_core, R::ZERO))
        } else {
            (R::vector(R::ZERO, -half_core), R::vector(R::ZERO, half_core))
        };
        Self::new(a, b, radius)
    }
    pub fn segment(&self) -> &Segment<R> {
        &self.core
    }
    pub fn capsule_radius(&self) -> R {
        self.radius
    }
}

/// The `const` constructors, for each scalar type (a `const fn` cannot be
/// generic over [`Real`]'s arithmetic).
macro_rules! const_constructors {
    ($R:ty, $vector:ty, $checks:ident) => {
        impl Capsule<$R> {
            /// [`Capsule::new`] as a `const fn`: a capsule declared as a constant is
            /// checked when the program is compiled (an invalid one fails the
            /// build) and stored bit for bit as `new` stores it.
            pub const fn new_const(a: $vector, b: $vector, radius: $R) -> Result<Self, Error> {
                let radius = const_try!(crate::checks::$checks::check_length(radius));
                Ok(Self { core: const_try!(Segment::<$R>::new_const(a, b)), radius })
            }
        }
    };
}

const_constructors!(f32, glam::Vec2, single);
const_constructors!(f64, glam::DVec2, double);

impl<R: Real> SupportMap<R> for Capsule<R> {
    #[inline]
    fn support(&self, direction: R::Vector) -> R::Vector {
        self.core.support(direction)
    }
    #[inline]
    fn support_feature(&self, direction: R::Vector, near: u32) -> (R::Vector, u32) {
        self.core.support_feature(direction, near)
    }
    fn center(&self) -> R::Vector {
        self.core.center()
    }
    fn bounding_radius(&self) -> R {
        self.core.bounding_radius() + self.radius
    }
    fn radius(&self) -> R {
        self.radius
    }
    fn is_polytope(&self) -> bool {
        true
    }
    fn core_vertex_bound(&self) -> usize {
        2
    }
    /// The center is the core's midpoint, exactly (a halving).
    #[cfg(not(any(target_os = "none", target_family = "wasm")))]
    fn inner_radius_squared(&self) -> R {
        super::squared_down(self.radius)
    }
    fn reference_point(&self) -> R::Vector {
        self.core.reference_point()
    }
    #[cfg(feature = "far-geometry")]
    /// Squared, with no root: `(2 (l / 2 + r))^2 <= 2 l^2 + 8 r^2`, so what
    /// this calls far is farther than twice the bounding radius.
    fn far_from_origin(&self) -> bool {
        let (l2, r) = (self.core.delta.length_squared(), self.radius);
        self.core.start.length_squared() > R::TWO * l2 + R::from_u32(8) * r * r
    }
    fn cast_local_ray(&self, o: R::Vector, d: R::Vector, max: R) -> Option<LocalRayCast<R>> {
        Some(cast_ray_capsule(V2::zero(), self.core.delta, self.radius, V2::from_glam(o), V2::from_glam(d), max))
    }
    #[cfg(not(any(target_os = "none", target_family = "wasm")))]
    fn segment_core(&self) -> Option<[V2<R>; 2]> {
        self.core.segment_core()
    }
}

/// Ray against the segment `a`-`a + delta` swept by `r` (> 0, as a
/// [`Capsule`] has). Within the band of the two side lines,
/// the capsule beyond an end of the core is that end's disk, and the other
/// disk lies behind it; so the first hit is on the side the ray comes in
/// through or, where it comes in beyond an end (or starts in the band), on
/// that end's disk: one disk cast, not a comparison of three hits. A bare
/// segment has its own cast (in `segment.rs`), so a firmware with capsules
/// links no segment cast.
///
/// Heights and positions along the core are kept scaled by its length `l`
/// (dot and cross products with `delta`): the tests compare them with `r l`
/// and `l^2`, so no division waits before the hit's own, and the unit
/// normal's `1 / l` is taken beside it.
pub(crate) fn cast_ray_capsule<R: Real>(a: V2<R>, delta: V2<R>, r: R, o: V2<R>, d: V2<R>, max: R) -> RayCast<R> {
    let len2 = delta.length_squared();
    let rel = o - a;
    let normal_dir = delta.perp();
    // Height over the core's line, and how far along it, both times `l`.
    let h = normal_dir.dot(rel);
    let mut along = delta.dot(rel);
    let length = len2.sqrt();
    let reach = r * length;
    // The closest point of the core to the ray origin decides "inside":
    // an end beyond the core's ends, else the foot on its line (not `h`
    // squared: at the largest coordinates that overflows). All three
    // measured and one picked by selects: where along the core a ray
    // starts is a coin toss.
    let (near_a, near_b) = (rel.length_squared() <= r * r, (rel - delta).length_squared() <= r * r);
    let beside = core::hint::select_unpredictable(along >= len2, near_b, h.abs() <= reach);
    let inside = core::hint::select_unpredictable(along <= R::ZERO, near_a, beside);
    if inside {
        return RayCast::closed_form(RayOutcome::Inside);
    }
    if h.abs() > reach {
        // Outside the band: it comes in through the nearer side line or not
        // at all.
        let toward = if h >= R::ZERO { R::ONE } else { -R::ONE };
        let dn = normal_dir.dot(d);
        if toward * dn >= R::ZERO {
            return RayCast::closed_form(RayOutcome::Miss);
        }
        let t = (h.abs() - reach) / dn.abs();
        along = delta.dot(rel + d * t);
        if along >= R::ZERO && along <= len2 {
            let outcome = if t <= max { hit(o, d, t, normal_dir * (toward / length)) } else { RayOutcome::Miss };
            return RayCast::closed_form(outcome);
        }
    }
    cast_ray_disk(if along < R::ZERO { a } else { a + delta }, r, o, d, max)
}
