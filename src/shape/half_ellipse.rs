use super::ellipse::ellipse_support;
use super::SupportMap;
use crate::error::Error;
use crate::real::{Real, V2};
use crate::transform::check_length;

/// The upper half (y >= 0) of an axis-aligned ellipse centered on the local
/// origin, as dyn4j's `HalfEllipse`: flat side on the x axis, dome up.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct HalfEllipse<R: Real> {
    /// Half the width and the full height (the vertical semi-axis).
    axes: V2<R>,
    centroid: V2<R>,
}

/// The centroid's height over the flat side, per unit of height: 4 / (3 pi).
const CENTROID_HEIGHT: f64 = 4.0 / (3.0 * core::f64::consts::PI);

impl<R: Real> HalfEllipse<R> {
    /// `width` (the flat side) and `height` (of the dome), both > 0.
    pub fn new(width: R, height: R) -> Result<Self, Error> {
        let axes = V2::new(check_length(width)? * R::HALF, check_length(height)?);
        let cy = R::from_f64(CENTROID_HEIGHT) * axes.y;
        Ok(Self { axes, centroid: V2::new(R::ZERO, cy) })
    }
    pub fn half_width(&self) -> R {
        self.axes.x
    }
    pub fn height(&self) -> R {
        self.axes.y
    }
}

/// The `const` constructors, for each scalar type (a `const fn` cannot be
/// generic over [`Real`]'s arithmetic).
macro_rules! const_constructors {
    ($R:ty, $vector:ty, $checks:ident) => {
        impl HalfEllipse<$R> {
            /// [`HalfEllipse::new`] as a `const fn`: a half ellipse declared as a constant is
            /// checked when the program is compiled (an invalid one fails the
            /// build) and stored bit for bit as `new` stores it.
            pub const fn new_const(width: $R, height: $R) -> Result<Self, Error> {
                let width = const_try!(crate::checks::$checks::check_length(width));
                let height = const_try!(crate::checks::$checks::check_length(height));
                let axes = V2 { x: width * 0.5, y: height };
                Ok(Self { axes, centroid: V2 { x: 0.0, y: CENTROID_HEIGHT as $R * axes.y } })
            }
        }
    };
}

const_constructors!(f32, glam::Vec2, single);
const_constructors!(f64, glam::DVec2, double);

impl<R: Real> SupportMap<R> for HalfEllipse<R> {
    #[inline]
    fn support(&self, d: R::Vector) -> R::Vector {
        self.support_feature(d, super::NO_FEATURE).0
    }
    // Out of line on bare metal: see the `shape` module.
    #[cfg_attr(target_os = "none", inline(never))]
    #[cfg_attr(not(target_os = "none"), inline)]
    fn support_feature(&self, direction: R::Vector, _near: u32) -> (R::Vector, u32) {
        let d = V2::from_glam(direction);
        if d.y > R::ZERO {
            (ellipse_support(self.axes, d).to_glam(), super::NO_FEATURE)
        } else if d.x >= R::ZERO {
            (R::vector(self.axes.x, R::ZERO), 1)
        } else {
            (R::vector(-self.axes.x, R::ZERO), 0)
        }
    }
    fn center(&self) -> R::Vector {
        self.centroid.to_glam()
    }
    fn bounding_radius(&self) -> R {
        // |p - c| <= |p| + |c| for every point p of the half ellipse.
        self.axes.x.max(self.axes.y) + self.centroid.y
    }
    #[cfg(feature = "far-geometry")]
    /// Centred on the local origin.
    fn far_from_origin(&self) -> bool {
        false
    }
}
