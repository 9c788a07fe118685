use super::SupportMap;
use crate::error::Error;
use crate::polytope::{cast_ray_polygon, FaceRounding};
use crate::real::{Real, V2};
use crate::result::LocalRayCast;
use crate::transform::check_length;

/// An axis-aligned rectangle centered on the local origin (rotate it with
/// its transform). Its support is two sign tests, not a vertex scan.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Rectangle<R: Real> {
    half: V2<R>,
}

impl<R: Real> Rectangle<R> {
    /// A `width` by `height` rectangle (both > 0), as dyn4j's `Rectangle`.
    pub fn new(width: R, height: R) -> Result<Self, Error> {
        Ok(Self { half: V2::new(check_length(width)? * R::HALF, check_length(height)? * R::HALF) })
    }
    pub fn width(&self) -> R {
        self.half.x * R::TWO
    }
    pub fn height(&self) -> R {
        self.half.y * R::TWO
    }
    fn corners(&self) -> [V2<R>; 4] {
        let (x, y) = (self.half.x, self.half.y);
        [V2::new(-x, -y), V2::new(x, -y), V2::new(x, y), V2::new(-x, y)]
    }
}

/// The `const` constructors, for each scalar type (a `const fn` cannot be
/// generic over [`Real`]'s arithmetic).
macro_rules! const_constructors {
    ($R:ty, $vector:ty, $checks:ident) => {
        impl Rectangle<$R> {
            /// [`Rectangle::new`] as a `const fn`: a rectangle declared as a constant is
            /// checked when the program is compiled (an invalid one fails the
            /// build) and stored bit for bit as `new` stores it.
            pub const fn new_const(width: $R, height: $R) -> Result<Self, Error> {
                Ok(Self { half: const_try!(super::polygon_frame::$checks::half_extents(width, height)) })
            }
        }
    };
}

const_constructors!(f32, glam::Vec2, single);
const_constructors!(f64, glam::DVec2, double);

impl<R: Real> SupportMap<R> for Rectangle<R> {
    #[inline]
    fn support(&self, d: R::Vector) -> R::Vector {
        self.support_feature(d, super::NO_FEATURE).0
    }
    // Out of line on bare metal: see the `shape` module.
    #[cfg_attr(target_os = "none", inline(never))]
    #[cfg_attr(not(target_os = "none"), inline)]
    fn support_feature(&self, direction: R::Vector, _near: u32) -> (R::Vector, u32) {
        let d = V2::<R>::from_glam(direction);
        // Ids follow the counter-clockwise corner order from (-x, -y).
        let (px, py) = (d.x > R::ZERO, d.y > R::ZERO);
        let id = match (px, py) {
            (false, false) => 0,
            (true, false) => 1,
            (true, true) => 2,
            (false, true) => 3,
        };
        let x = if px { self.half.x } else { -self.half.x };
        let y = if py { self.half.y } else { -self.half.y };
        (R::vector(x, y), id)
    }
    fn is_polytope(&self) -> bool {
        true
    }
    fn core_vertex_bound(&self) -> usize {
        4
    }
    fn center(&self) -> R::Vector {
        R::vector(R::ZERO, R::ZERO)
    }
    fn bounding_radius(&self) -> R {
        self.half.length()
    }
    #[cfg(not(any(target_os = "none", target_family = "wasm")))]
    fn inner_radius_squared(&self) -> R {
        super::squared_down(self.half.x.min(self.half.y))
    }
    #[cfg(feature = "far-geometry")]
    /// Centred on the local origin.
    fn far_from_origin(&self) -> bool {
        false
    }
    fn cast_local_ray(&self, o: R::Vector, d: R::Vector, max: R) -> Option<LocalRayCast<R>> {
        crate::polytope::face_cast_to_local(self.cast_local_face_ray(o, d, max), d)
    }
    fn casts_face_rays(&self) -> bool {
        true
    }
    fn cast_local_face_ray(&self, o: R::Vector, d: R::Vector, max: R) -> Option<LocalRayCast<R>> {
        let o = V2::from_glam(o);
        // |half|_1: at least the bounding radius, with no square root.
        let size = self.half.x + self.half.y;
        let rounding = FaceRounding::new(o, V2::zero(), size);
        Some(cast_ray_polygon(&self.corners(), o, V2::from_glam(d), max, rounding))
    }
}
