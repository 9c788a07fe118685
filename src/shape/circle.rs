use super::SupportMap;
use crate::ray::cast_ray_disk;
use crate::real::{Real, V2};
use crate::result::LocalRayCast;
use crate::transform::{check_length, check_point};
use crate::Error;

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
                const_try!(super::polygon_frame::$checks::check_point(center));
                Ok(Self { center, radius: const_try!(super::polygon_frame::$checks::check_length(radius)) })
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
    fn reference_point(&self) -> R::Vector {
        self.center.to_glam()
    }
    fn cast_local_ray(&self, o: R::Vector, d: R::Vector, max: R) -> Option<LocalRayCast<R>> {
        Some(cast_ray_disk(V2::zero(), self.radius, V2::from_glam(o), V2::from_glam(d), max))
    }
}
