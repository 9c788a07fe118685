//! Placement of a shape: a rotation followed by a translation.

use crate::checks::{CheckLength, CheckPoint};
use crate::error::Error;
use crate::real::{Real, V2};

/// A rigid transform: `world = rotation * local + translation`.
///
/// The rotation is kept as its cosine and sine, as dyn4j does, so a
/// transform built from an angle is computed once.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Transform<R: Real> {
    pub(crate) translation: V2<R>,
    pub(crate) cos: R,
    pub(crate) sin: R,
}

impl<R: Real> Default for Transform<R> {
    fn default() -> Self {
        Self::IDENTITY
    }
}

impl<R: Real> Transform<R> {
    /// No rotation, no translation.
    pub const IDENTITY: Self = Self { translation: V2::new(R::ZERO, R::ZERO), cos: R::ONE, sin: R::ZERO };

    /// A translation and a rotation by `angle` radians (counter-clockwise).
    pub fn new(translation: R::Vector, angle: R) -> Result<Self, Error> {
        if !angle.is_finite() {
            return Err(Error::NonFinite);
        }
        let mut t = Self::from_translation(translation)?;
        if angle != R::ZERO {
            (t.sin, t.cos) = angle.sin_cos();
        }
        Ok(t)
    }

    /// A pure translation.
    pub fn from_translation(translation: R::Vector) -> Result<Self, Error> {
        let t = V2::from_glam(translation);
        check_point(t)?;
        Ok(Self { translation: t, ..Self::IDENTITY })
    }

    /// A translation and a rotation given by its cosine and sine, which are
    /// normalised (so `(2, 0)` is no rotation). They must be finite, within
    /// the coordinate range, and not both zero (nor so small their squares
    /// underflow to zero: below about 2.6e-23 in f32, 1.6e-162 in f64).
    pub fn from_cos_sin(translation: R::Vector, cos: R, sin: R) -> Result<Self, Error> {
        let mut t = Self::from_translation(translation)?;
        // Within the coordinate range, as a point: then its squared length
        // cannot overflow (at (1e30, 1e30) in f32 it would, and the division
        // by an infinite length would give no rotation at all).
        let r = check_point(V2::new(cos, sin))?;
        let len = r.length();
        if len == R::ZERO {
            return Err(Error::ZeroLength);
        }
        // A (cos, sin) whose length rounds to 1 stays as given: division by
        // exactly 1 is exact.
        t.cos = cos / len;
        t.sin = sin / len;
        Ok(t)
    }

    pub fn translation(&self) -> R::Vector {
        self.translation.to_glam()
    }
    pub fn cos(&self) -> R {
        self.cos
    }
    pub fn sin(&self) -> R {
        self.sin
    }
    /// The rotation angle in (-pi, pi].
    pub fn angle(&self) -> R {
        self.sin.atan2(self.cos)
    }

    /// Local point to world.
    pub fn transform_point(&self, p: R::Vector) -> R::Vector {
        (self.rotate(V2::from_glam(p)) + self.translation).to_glam()
    }
    /// World point to local.
    pub fn inverse_transform_point(&self, p: R::Vector) -> R::Vector {
        self.inverse_rotate(V2::from_glam(p) - self.translation).to_glam()
    }

    /// Every number through [`Real`]'s scalar barrier.
    #[cfg(not(any(target_os = "none", target_family = "wasm")))]
    #[inline(always)]
    pub(crate) fn scalar_barrier(&self) -> Self {
        Self {
            translation: self.translation.scalar_barrier(),
            cos: self.cos.scalar_barrier(),
            sin: self.sin.scalar_barrier(),
        }
    }
    #[inline(always)]
    pub(crate) fn rotate(&self, v: V2<R>) -> V2<R> {
        V2::new(self.cos * v.x - self.sin * v.y, self.sin * v.x + self.cos * v.y)
    }
    #[inline(always)]
    pub(crate) fn inverse_rotate(&self, v: V2<R>) -> V2<R> {
        V2::new(self.cos * v.x + self.sin * v.y, -self.sin * v.x + self.cos * v.y)
    }
    /// Whether placing by it changes no coordinate.
    #[cfg(feature = "far-geometry")]
    #[inline(always)]
    pub(crate) fn is_identity(&self) -> bool {
        self.sin == R::ZERO && self.cos == R::ONE && self.translation == V2::zero()
    }
}

/// A point must be finite and within [`Real::MAX_COORDINATE`].
///
/// Not inlined on bare metal, whose flash is scarce: shape constructors and
/// transforms call it from many places, and one copy serves them all.
#[cfg_attr(target_os = "none", inline(never))]
pub(crate) fn check_point<R: Real>(p: V2<R>) -> Result<V2<R>, Error> {
    // The same check a constant polygon's vertices get at compile time.
    R::per_type::<CheckPoint>(p).map(|()| p)
}

/// A length (radius, half-extent) must be finite, positive and within range:
/// the same check a constant shape's lengths get at compile time.
#[inline(always)]
pub(crate) fn check_length<R: Real>(r: R) -> Result<R, Error> {
    R::per_type::<CheckLength>(r)
}
