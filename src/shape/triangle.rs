use super::{Polygon, SupportMap};
use crate::error::Error;
use crate::real::Real;
use crate::result::LocalRayCast;

/// A triangle: a three-vertex [`Polygon`] with its own constructor.
#[derive(Clone, Debug, PartialEq)]
pub struct Triangle<R: Real>(Polygon<R, 3>);

impl<R: Real> Triangle<R> {
    /// Three distinct, non-collinear points in either winding.
    pub fn new(a: R::Vector, b: R::Vector, c: R::Vector) -> Result<Self, Error> {
        Polygon::new(&[a, b, c]).map(Self)
    }
    pub fn polygon(&self) -> &Polygon<R, 3> {
        &self.0
    }
}

/// The `const` constructors, for each scalar type (a `const fn` cannot be
/// generic over [`Real`]'s arithmetic).
macro_rules! const_constructors {
    ($R:ty, $vector:ty) => {
        impl Triangle<$R> {
            /// [`Triangle::new`] as a `const fn`: a triangle declared as a constant is
            /// checked when the program is compiled (an invalid one fails the
            /// build) and stored bit for bit as `new` stores it.
            pub const fn new_const(a: $vector, b: $vector, c: $vector) -> Result<Self, Error> {
                Ok(Self(const_try!(Polygon::<$R, 3>::from_array([a, b, c]))))
            }
        }
    };
}

const_constructors!(f32, glam::Vec2);
const_constructors!(f64, glam::DVec2);

impl<R: Real> SupportMap<R> for Triangle<R> {
    #[inline]
    fn support(&self, d: R::Vector) -> R::Vector {
        self.0.support(d)
    }
    #[inline]
    fn support_feature(&self, d: R::Vector, near: u32) -> (R::Vector, u32) {
        self.0.support_feature(d, near)
    }
    #[cfg(not(any(target_os = "none", target_family = "wasm")))]
    fn small_polygon(&self) -> Option<super::SmallPolygon<'_, R>> {
        self.0.small_polygon()
    }
    #[cfg(not(any(target_os = "none", target_family = "wasm")))]
    fn polygon_core(&self) -> Option<super::SmallPolygon<'_, R>> {
        self.0.polygon_core()
    }
    #[cfg(not(any(target_os = "none", target_family = "wasm")))]
    fn inner_radius_squared(&self) -> R {
        self.0.inner_radius_squared()
    }
    fn is_polytope(&self) -> bool {
        true
    }
    fn core_vertex_bound(&self) -> usize {
        3
    }
    fn center(&self) -> R::Vector {
        self.0.center()
    }
    fn bounding_radius(&self) -> R {
        self.0.bounding_radius()
    }
    fn reference_point(&self) -> R::Vector {
        self.0.reference_point()
    }
    #[cfg(feature = "far-geometry")]
    fn far_from_origin(&self) -> bool {
        self.0.far_from_origin()
    }
    fn cast_local_ray(&self, o: R::Vector, d: R::Vector, max: R) -> Option<LocalRayCast<R>> {
        self.0.cast_local_ray(o, d, max)
    }
    fn casts_face_rays(&self) -> bool {
        true
    }
    fn cast_local_face_ray(&self, o: R::Vector, d: R::Vector, max: R) -> Option<LocalRayCast<R>> {
        self.0.cast_local_face_ray(o, d, max)
    }
}
