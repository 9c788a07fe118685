use super::SupportMap;
use crate::error::Error;
use crate::real::Real;
use crate::transform::check_length;

/// Any shape swept by an extra radius (a rounded polygon, a rounded
/// rectangle). The radius is handled in closed form like a circle's, so a
/// rounded polygon is as exact as a polygon in distance and penetration; ray
/// casts against it iterate.
#[derive(Clone, Debug, PartialEq)]
pub struct Rounded<R: Real, S> {
    inner: S,
    radius: R,
}

impl<R: Real, S: SupportMap<R>> Rounded<R, S> {
    /// `inner` swept by `radius` (> 0).
    pub fn new(inner: S, radius: R) -> Result<Self, Error> {
        Ok(Self { inner, radius: check_length(radius)? })
    }
    pub fn inner(&self) -> &S {
        &self.inner
    }
    /// The radius added to the inner shape's own.
    pub fn extra_radius(&self) -> R {
        self.radius
    }
}

/// The `const` constructors, for each scalar type (a `const fn` cannot be
/// generic over [`Real`]'s arithmetic).
macro_rules! const_constructors {
    ($R:ty, $checks:ident) => {
        impl<S: SupportMap<$R>> Rounded<$R, S> {
            /// [`Rounded::new`] as a `const fn`: a rounded shape declared as a constant is
            /// checked when the program is compiled (an invalid one fails the
            /// build) and stored bit for bit as `new` stores it.
            pub const fn new_const(inner: S, radius: $R) -> Result<Self, Error> {
                match crate::checks::$checks::check_length(radius) {
                    Ok(radius) => Ok(Self { inner, radius }),
                    Err(e) => {
                        // Dropped for nothing, as a `const fn` cannot run a
                        // destructor: shapes have none.
                        core::mem::forget(inner);
                        Err(e)
                    }
                }
            }
        }
    };
}

const_constructors!(f32, single);
const_constructors!(f64, double);

impl<R: Real, S: SupportMap<R>> SupportMap<R> for Rounded<R, S> {
    #[inline]
    fn support(&self, d: R::Vector) -> R::Vector {
        self.inner.support(d)
    }
    #[inline]
    fn support_feature(&self, d: R::Vector, near: u32) -> (R::Vector, u32) {
        self.inner.support_feature(d, near)
    }
    fn center(&self) -> R::Vector {
        self.inner.center()
    }
    fn bounding_radius(&self) -> R {
        self.inner.bounding_radius() + self.radius
    }
    fn radius(&self) -> R {
        self.inner.radius() + self.radius
    }
    fn is_polytope(&self) -> bool {
        self.inner.is_polytope()
    }
    fn core_vertex_bound(&self) -> usize {
        self.inner.core_vertex_bound()
    }
    fn reference_point(&self) -> R::Vector {
        self.inner.reference_point()
    }
    #[cfg(feature = "far-geometry")]
    /// The inner shape's answer: far for it is far enough (the radius only
    /// makes the shape larger).
    fn far_from_origin(&self) -> bool {
        self.inner.far_from_origin()
    }
}
