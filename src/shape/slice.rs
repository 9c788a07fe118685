use super::SupportMap;
use crate::real::{Real, V2};
use crate::transform::check_length;
use crate::Error;

/// A circular sector (a pizza slice) with its apex on the local origin,
/// symmetric about the +x axis, as dyn4j's `Slice`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Slice<R: Real> {
    radius: R,
    cos_half: R,
    /// The arc's end points, counter-clockwise one first.
    ends: [V2<R>; 2],
    centroid: V2<R>,
}

impl<R: Real> Slice<R> {
    /// A slice of `radius` (> 0) spanning `theta` radians, 0 < theta <= pi.
    pub fn new(radius: R, theta: R) -> Result<Self, Error> {
        let radius = check_length(radius)?;
        if !theta.is_finite() {
            return Err(Error::NonFinite);
        }
        if theta <= R::ZERO || beyond_pi(theta) {
            return Err(Error::AngleOutOfRange);
        }
        let half = theta * R::HALF;
        let (s, c) = half.sin_cos();
        // Centroid of a sector: 2 r sin(a) / (3 a) from the apex. sin(a)/a
        // tends to 1; a subnormal theta can halve to exactly 0 (0/0).
        let sinc = if half > R::ZERO { s / half } else { R::ONE };
        let cx = R::TWO * radius * sinc / R::from_u32(3);
        Ok(Self {
            radius,
            cos_half: c,
            ends: [V2::new(radius * c, radius * s), V2::new(radius * c, -radius * s)],
            centroid: V2::new(cx, R::ZERO),
        })
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
        self.support_feature(d).0
    }
    // Out of line on bare metal: see the `shape` module.
    #[cfg_attr(target_os = "none", inline(never))]
    #[cfg_attr(not(target_os = "none"), inline)]
    fn support_feature(&self, direction: R::Vector) -> (R::Vector, u32) {
        let d = V2::from_glam(direction);
        if let Some(u) = d.try_normalize() {
            if u.x >= self.cos_half {
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
}

/// Whether `theta` exceeds pi exactly, in `R` alone: converting `theta` to
/// f64 would link soft double arithmetic into f32 firmware. pi rounds up to
/// the nearest f32 and down to the nearest f64; the test against the
/// rounded value follows the direction (a constant, folded at compile time).
fn beyond_pi<R: Real>(theta: R) -> bool {
    let pi = R::from_f64(core::f64::consts::PI);
    if pi.to_f64() > core::f64::consts::PI {
        theta >= pi
    } else {
        theta > pi
    }
}
