use super::SupportMap;
use crate::error::Error;
use crate::real::{PerType, Real, V2};

/// A circular sector (a pizza slice) with its apex on the local origin,
/// symmetric about the +x axis, as dyn4j's `Slice`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Slice<R: Real> {
    radius: R,
    /// The arc's end points, counter-clockwise one first.
    ends: [V2<R>; 2],
    centroid: V2<R>,
}

impl<R: Real> Slice<R> {
    /// A slice of `radius` (> 0) spanning `theta` radians, 0 < theta <= pi.
    pub fn new(radius: R, theta: R) -> Result<Self, Error> {
        R::per_type::<NewSlice>((radius, theta))
    }
    pub fn slice_radius(&self) -> R {
        self.radius
    }
    /// The full angle the slice spans.
    pub fn theta(&self) -> R {
        self.ends[0].y.atan2(self.ends[0].x) * R::TWO
    }
}

impl<R: Real> SupportMap<R> for Slice<R> {
    #[inline]
    fn support(&self, d: R::Vector) -> R::Vector {
        self.support_feature(d, super::NO_FEATURE).0
    }
    // Out of line on bare metal: see the `shape` module.
    #[cfg_attr(target_os = "none", inline(never))]
    #[cfg_attr(not(target_os = "none"), inline)]
    fn support_feature(&self, direction: R::Vector, _near: u32) -> (R::Vector, u32) {
        let d = V2::from_glam(direction);
        // Within the arc's angular range, between the ends (a slice is at
        // most a half disk): told by the ends' sines against the direction's
        // slope, which keep their digits near the axis. Not by cosines: f32
        // cannot resolve them near 1, and a needle (1e-3 rad) would take
        // directions 1e-4 rad past its ends for the arc, points outside it.
        if self.ends[0].y * d.x >= self.ends[0].x * d.y.abs() {
            if let Some(u) = d.try_normalize() {
                return ((u * self.radius).to_glam(), super::NO_FEATURE);
            }
        }
        // Outside the arc's angular range the farthest point is a corner.
        let (d0, d1) = (self.ends[0].dot(d), self.ends[1].dot(d));
        if d0 >= d1 && d0 > R::ZERO {
            (self.ends[0].to_glam(), 1)
        } else if d1 > R::ZERO {
            (self.ends[1].to_glam(), 2)
        } else {
            (R::vector(R::ZERO, R::ZERO), 0)
        }
    }
    fn center(&self) -> R::Vector {
        self.centroid.to_glam()
    }
    fn bounding_radius(&self) -> R {
        self.centroid.x.max((self.ends[0] - self.centroid).length())
    }
    #[cfg(feature = "far-geometry")]
    /// Centred on the local origin.
    fn far_from_origin(&self) -> bool {
        false
    }
}

/// How generic code ([`Slice::new`]) reaches the per-type `const`
/// constructor: one definition of a slice, at compile time and at run time.
enum NewSlice {}

impl PerType for NewSlice {
    type Input<'a, R: Real> = (R, R);
    type Output<R: Real> = Result<Slice<R>, Error>;
    fn f32((radius, theta): (f32, f32)) -> Result<Slice<f32>, Error> {
        Slice::<f32>::new_const(radius, theta)
    }
    fn f64((radius, theta): (f64, f64)) -> Result<Slice<f64>, Error> {
        Slice::<f64>::new_const(radius, theta)
    }
}

/// The `const` constructor, for each scalar type (a `const fn` cannot be
/// generic over [`Real`]'s arithmetic), with a sine and cosine that are
/// `const` too.
macro_rules! const_constructors {
    ($R:ty, $checks:ident, $sin_cos:path) => {
        impl Slice<$R> {
            /// [`Slice::new`] as a `const fn`: a slice declared as a constant
            /// is checked when the program is compiled (an invalid one fails
            /// the build) and stored bit for bit as `new` stores it.
            pub const fn new_const(radius: $R, theta: $R) -> Result<Self, Error> {
                let radius = const_try!(crate::checks::$checks::check_length(radius));
                if !theta.is_finite() {
                    return Err(Error::NonFinite);
                }
                // Beyond pi exactly, in the type alone (a run-time f64
                // conversion of `theta` would link soft double arithmetic
                // into f32 firmware): pi rounds up to the nearest f32 and
                // down to the nearest f64, and the comparison follows the
                // direction (constants, folded by the compiler).
                let pi = core::f64::consts::PI as $R;
                let beyond_pi = if pi as f64 > core::f64::consts::PI { theta >= pi } else { theta > pi };
                if theta <= 0.0 || beyond_pi {
                    return Err(Error::AngleOutOfRange);
                }
                let half = theta * 0.5;
                let (s, c) = $sin_cos(half);
                // Centroid of a sector: 2 r sin(a) / (3 a) from the apex.
                // sin(a)/a tends to 1; a subnormal theta can halve to
                // exactly 0 (0/0).
                let sinc = if half > 0.0 { s / half } else { 1.0 };
                let cx = 2.0 * radius * sinc / 3.0;
                Ok(Self {
                    radius,
                    ends: [V2 { x: radius * c, y: radius * s }, V2 { x: radius * c, y: -radius * s }],
                    centroid: V2 { x: cx, y: 0.0 },
                })
            }
        }
    };
}

const_constructors!(f32, single, crate::trig::sin_cos_f32);
const_constructors!(f64, double, crate::trig::sin_cos_quarter_f64);
