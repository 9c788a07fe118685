//! The checks every point and length a user gives get: finite, within
//! [`Real::MAX_COORDINATE`], and a length positive. Written once per scalar
//! type as `const fn`s, which a shape declared as a constant is checked with
//! when the program is compiled; generic code reaches them through
//! [`PerType`] (`transform.rs`'s `check_point` and `check_length`), so a point
//! is valid by one definition at compile time and at run time.

use crate::error::Error;
use crate::real::{PerType, Real, V2};

macro_rules! checks {
    ($module:ident, $R:ty) => {
        pub(crate) mod $module {
            use crate::error::Error;
            use crate::real::{Real, V2};

            /// Finite, and within [`Real::MAX_COORDINATE`].
            pub(crate) const fn check_point(p: V2<$R>) -> Result<(), Error> {
                if !(p.x.is_finite() && p.y.is_finite()) {
                    Err(Error::NonFinite)
                } else if max(p.x.abs(), p.y.abs()) > <$R as Real>::MAX_COORDINATE {
                    Err(Error::OutOfRange)
                } else {
                    Ok(())
                }
            }

            /// A length (radius, extent) must be finite, positive and within
            /// [`Real::MAX_COORDINATE`].
            ///
            /// Not inlined on bare metal, whose flash is scarce: a firmware
            /// with every shape calls it from a dozen constructors.
            #[cfg_attr(target_os = "none", inline(never))]
            pub(crate) const fn check_length(r: $R) -> Result<$R, Error> {
                if !r.is_finite() {
                    Err(Error::NonFinite)
                } else if r <= 0.0 {
                    Err(Error::NonPositive)
                } else if r > <$R as Real>::MAX_COORDINATE {
                    Err(Error::OutOfRange)
                } else {
                    Ok(r)
                }
            }

            /// As [`Real::max`]: the same choice for equal values.
            pub(crate) const fn max(a: $R, b: $R) -> $R {
                if a > b {
                    a
                } else {
                    b
                }
            }
        }
    };
}

checks!(single, f32);
checks!(double, f64);

/// [`single::check_point`] or [`double::check_point`], for generic code
/// ([`check_point`](crate::transform::check_point)).
pub(crate) enum CheckPoint {}

impl PerType for CheckPoint {
    type Input<'a, R: Real> = V2<R>;
    type Output<R: Real> = Result<(), Error>;
    #[inline(always)]
    fn f32(p: V2<f32>) -> Result<(), Error> {
        single::check_point(p)
    }
    #[inline(always)]
    fn f64(p: V2<f64>) -> Result<(), Error> {
        double::check_point(p)
    }
}

/// [`single::check_length`] or [`double::check_length`], for generic code
/// ([`check_length`](crate::transform::check_length)).
pub(crate) enum CheckLength {}

impl PerType for CheckLength {
    type Input<'a, R: Real> = R;
    type Output<R: Real> = Result<R, Error>;
    #[inline(always)]
    fn f32(r: f32) -> Result<f32, Error> {
        single::check_length(r)
    }
    #[inline(always)]
    fn f64(r: f64) -> Result<f64, Error> {
        double::check_length(r)
    }
}
