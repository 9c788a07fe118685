//! The one error type of gjk2d: every constructor and setter returns it
//! instead of panicking, and says what was wrong.

use core::fmt;

/// Why a shape, transform, ray or setting was rejected.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub enum Error {
    /// A coordinate, angle or length is NaN or infinite.
    NonFinite,
    /// A coordinate's magnitude exceeds `Real::MAX_COORDINATE` (1e15 for f32,
    /// 1e150 for f64), beyond which squared lengths could overflow.
    OutOfRange,
    /// A radius, half-extent or length is zero or negative.
    NonPositive,
    /// A direction (ray direction, segment) has zero length.
    ZeroLength,
    /// Fewer vertices than the shape needs (3 for a polygon).
    TooFewVertices,
    /// More vertices than the polygon's capacity `N`.
    OverCapacity,
    /// Two consecutive vertices coincide.
    DuplicateVertex,
    /// The polygon turns the wrong way at some vertex, or winds more than once.
    NotConvex,
    /// All vertices lie on one line: the polygon has no area.
    Degenerate,
    /// An angle outside the range the shape allows (a slice's angle in (0, pi]).
    AngleOutOfRange,
    /// An iteration limit below the minimum of 5.
    TooFewIterations,
    /// An epsilon out of range (negative; or zero where it must be positive).
    InvalidEpsilon,
}

impl Error {
    /// What went wrong, in words: `const`, so a constant shape's
    /// `panic!("{}", e.as_str())` can say it in the compile error.
    pub const fn as_str(self) -> &'static str {
        match self {
            Error::NonFinite => "a value is NaN or infinite",
            Error::OutOfRange => "a coordinate is too large (over 1e15 in f32, 1e150 in f64)",
            Error::NonPositive => "a radius, extent or length must be positive",
            Error::ZeroLength => "a direction or segment has zero length",
            Error::TooFewVertices => "a polygon needs at least 3 vertices",
            Error::OverCapacity => "more vertices than the polygon's capacity",
            Error::DuplicateVertex => "two consecutive vertices coincide",
            Error::NotConvex => "the polygon is not convex",
            Error::Degenerate => "the polygon has no area (all vertices collinear)",
            Error::AngleOutOfRange => "an angle is out of range",
            Error::TooFewIterations => "an iteration limit must be at least 5",
            Error::InvalidEpsilon => "an epsilon is out of range",
        }
    }
}

impl fmt::Display for Error {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.as_str())
    }
}

impl core::error::Error for Error {}
