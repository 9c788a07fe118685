use super::SupportMap;
use crate::error::Error;
use crate::real::{Real, V2};
use crate::result::{hit, LocalRayCast, RayCast, RayOutcome};
use crate::transform::{check_length, check_point};

/// A disk: a point core swept by its radius.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Circle<R: Real> {
    center: V2<R>,
    radius: R,
}

impl<R: Real> Circle<R> {
    /// A circle of `radius` (> 0) centered on the local origin.
    pub fn new(radius: R) -> Result<Self, Error> {
        Self::at(R::vector(R::ZERO, R::ZERO), radius)
    }
    /// A circle of `radius` (> 0) centered on `center` (local coordinates).
    pub fn at(center: R::Vector, radius: R) -> Result<Self, Error> {
        Ok(Self { center: check_point(V2::from_glam(center))?, radius: check_length(radius)? })
    }
    pub fn center_point(&self) -> R::Vector {
        self.center.to_glam()
    }
    pub fn circle_radius(&self) -> R {
        self.radius
    }
}

/// The `const` constructors, for each scalar type (a `const fn` cannot be
/// generic over [`Real`]'s arithmetic).
macro_rules! const_constructors {
    ($R:ty, $vector:ty, $checks:ident) => {
        impl Circle<$R> {
            /// [`Circle::new`] as a `const fn`: a circle declared as a
            /// constant is checked when the program is compiled (an invalid
            /// one fails the build) and stored bit for bit as `new` stores it.
            /// Every shape has one (`Polygon`'s is `from_array`):
            ///
            /// ```
            /// # use gjk2d::Circle;
            #[doc = concat!("const WHEEL: Circle<", stringify!($R), "> = match Circle::<", stringify!($R), ">::new_const(0.5) {")]
            ///     Ok(wheel) => wheel,
            ///     Err(e) => panic!("{}", e.as_str()), // a compile error, never a run-time panic
            /// };
            /// assert_eq!(WHEEL.circle_radius(), 0.5);
            /// ```
            ///
            /// A negative radius fails the build ("a radius, extent or length
            /// must be positive"):
            ///
            /// ```compile_fail
            /// # use gjk2d::Circle;
            #[doc = concat!("const WHEEL: Circle<", stringify!($R), "> = match Circle::<", stringify!($R), ">::new_const(-0.5) {")]
            ///     Ok(wheel) => wheel,
            ///     Err(e) => panic!("{}", e.as_str()),
            /// };
            /// ```
            pub const fn new_const(radius: $R) -> Result<Self, Error> {
                Self::at_const(<$vector>::ZERO, radius)
            }
            /// [`Circle::at`] as a `const fn` (see [`new_const`](Self::new_const)).
            pub const fn at_const(center: $vector, radius: $R) -> Result<Self, Error> {
                let center = V2 { x: center.x, y: center.y };
                const_try!(crate::checks::$checks::check_point(center));
                Ok(Self { center, radius: const_try!(crate::checks::$checks::check_length(radius)) })
            }
        }
    };
}

const_constructors!(f32, glam::Vec2, single);
const_constructors!(f64, glam::DVec2, double);

impl<R: Real> SupportMap<R> for Circle<R> {
    #[inline]
    fn support(&self, _direction: R::Vector) -> R::Vector {
        R::vector(R::ZERO, R::ZERO)
    }
    #[inline]
    fn support_feature(&self, _direction: R::Vector, _near: u32) -> (R::Vector, u32) {
        (R::vector(R::ZERO, R::ZERO), 0)
    }
    fn center(&self) -> R::Vector {
        R::vector(R::ZERO, R::ZERO)
    }
    fn bounding_radius(&self) -> R {
        self.radius
    }
    fn radius(&self) -> R {
        self.radius
    }
    fn is_polytope(&self) -> bool {
        true
    }
    fn core_vertex_bound(&self) -> usize {
        1
    }
    fn reference_point(&self) -> R::Vector {
        self.center.to_glam()
    }
    fn disk_radius(&self) -> Option<R> {
        Some(self.radius)
    }
    #[cfg(not(any(target_os = "none", target_family = "wasm")))]
    fn inner_radius_squared(&self) -> R {
        super::squared_down(self.radius)
    }
    fn cast_local_ray(&self, o: R::Vector, d: R::Vector, max: R) -> Option<LocalRayCast<R>> {
        Some(cast_ray_disk(V2::zero(), self.radius, V2::from_glam(o), V2::from_glam(d), max))
    }
}

/// Ray against a disk, in the disk's frame.
#[cfg_attr(not(target_os = "none"), inline)]
pub(crate) fn cast_ray_disk<R: Real>(center: V2<R>, r: R, o: V2<R>, d: V2<R>, max: R) -> RayCast<R> {
    let ray = match DiskRay::new(center, r, o, d) {
        Ok(ray) => ray,
        Err(outcome) => return RayCast::closed_form(outcome),
    };
    // On hosts one branch for every way to miss, not two: which test a miss
    // fails is not predictable.
    RayCast::closed_form(if ray.inside {
        RayOutcome::Inside
    } else if ray.misses | (ray.t > max) {
        RayOutcome::Miss
    } else {
        hit(o, d, ray.t, ray.normal(d, R::ONE / r))
    })
}

/// The numbers of a ray against a disk. The root is taken in the form
/// without cancellation, `t = c / (-b + sqrt(disc))`, and the discriminant
/// from the perpendicular offset `r^2 - p^2 = (r - p)(r + p)`, so grazing
/// rays keep their precision.
pub(crate) struct DiskRay<R: Real> {
    /// The origin is inside the disk or on its circle.
    pub inside: bool,
    /// The ray points away from the disk or passes it by.
    pub misses: bool,
    pub t: R,
    pub half_chord: R,
    /// The offset from the center across the ray: `m = b d + across d⊥`.
    across: R,
}

impl<R: Real> DiskRay<R> {
    /// Bare metal, with no predictor to miss, leaves with the outcome as
    /// soon as it knows. Hosts take every number, so that a caller picks
    /// the outcome by selects or one branch: past the radius the chord is
    /// taken as zero and `t` is then anything but NaN, and unused.
    #[inline(always)]
    pub fn new(center: V2<R>, r: R, o: V2<R>, d: V2<R>) -> Result<Self, RayOutcome<R>> {
        let bare_metal = cfg!(target_os = "none");
        let m = o - center;
        // |m|^2 - r^2: rounds like (|m| - r)(|m| + r) would (|m| is rounded
        // too), without a square root.
        let c = m.length_squared() - r * r;
        let inside = c <= R::ZERO;
        if bare_metal && inside {
            return Err(RayOutcome::Inside);
        }
        let b = m.dot(d);
        let across = d.cross(m);
        let p = across.abs();
        let misses = (b >= R::ZERO) | (p > r);
        if bare_metal && misses {
            return Err(RayOutcome::Miss);
        }
        let chord_squared = (r - p) * (r + p);
        let half_chord = if bare_metal { chord_squared } else { chord_squared.max(R::ZERO) }.sqrt();
        Ok(Self { inside, misses, t: c / (-b + half_chord), half_chord, across })
    }

    /// The unit normal at the hit, from the ray's direction `d` in the
    /// frame wanted (rotating `d` and `d⊥` rotates the normal with them).
    /// The hit point from the center is `m + t d = -half_chord d + across d⊥`
    /// (`b + t = -half_chord`): of length r to rounding, with no
    /// cancellation however far the origin, and no second square root.
    #[inline(always)]
    pub fn normal(&self, d: V2<R>, inverse_radius: R) -> V2<R> {
        (d * -self.half_chord + d.perp() * self.across) * inverse_radius
    }
}
