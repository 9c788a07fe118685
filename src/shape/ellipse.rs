use super::SupportMap;
use crate::error::Error;
use crate::real::{Real, V2};
use crate::transform::check_length;

/// An axis-aligned ellipse centered on the local origin: a truly curved
/// shape, so queries on it iterate to the configured epsilon.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Ellipse<R: Real> {
    half: V2<R>,
}

impl<R: Real> Ellipse<R> {
    /// An ellipse `width` by `height` (full extents, both > 0), as dyn4j's.
    pub fn new(width: R, height: R) -> Result<Self, Error> {
        Ok(Self { half: V2::new(check_length(width)? * R::HALF, check_length(height)? * R::HALF) })
    }
    pub fn half_width(&self) -> R {
        self.half.x
    }
    pub fn half_height(&self) -> R {
        self.half.y
    }
}

/// Support of the ellipse with semi-axes `half` centered on the origin:
/// `(a^2 dx, b^2 dy) / |(a dx, b dy)|`. The direction is first scaled by its
/// largest component so neither tiny nor huge directions under- or overflow.
///
/// Out of line on bare metal, like every shape's support code (see the
/// `shape` module); the half ellipse shares it.
#[cfg_attr(target_os = "none", inline(never))]
#[cfg_attr(not(target_os = "none"), inline)]
pub(crate) fn ellipse_support<R: Real>(half: V2<R>, d: V2<R>) -> V2<R> {
    let s = d.max_abs();
    if s == R::ZERO {
        return V2::new(half.x, R::ZERO);
    }
    // Divided, not multiplied by 1/s: 1/s overflows for a subnormal s.
    let u = V2::new(d.x / s, d.y / s);
    let scaled = V2::new(half.x * u.x, half.y * u.y);
    let len = scaled.length();
    V2::new(half.x * scaled.x, half.y * scaled.y) * (R::ONE / len)
}

/// The `const` constructors, for each scalar type (a `const fn` cannot be
/// generic over [`Real`]'s arithmetic).
macro_rules! const_constructors {
    ($R:ty, $vector:ty, $checks:ident) => {
        impl Ellipse<$R> {
            /// [`Ellipse::new`] as a `const fn`: an ellipse declared as a constant is
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

impl<R: Real> SupportMap<R> for Ellipse<R> {
    #[inline]
    fn support(&self, d: R::Vector) -> R::Vector {
        ellipse_support(self.half, V2::from_glam(d)).to_glam()
    }
    fn center(&self) -> R::Vector {
        R::vector(R::ZERO, R::ZERO)
    }
    fn bounding_radius(&self) -> R {
        self.half.x.max(self.half.y)
    }
    #[cfg(feature = "far-geometry")]
    /// Centred on the local origin.
    fn far_from_origin(&self) -> bool {
        false
    }
}
