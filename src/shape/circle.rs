use super::SupportMap;
use crate::ray::{cast_ray_disk, LocalRayCast};
use crate::real::{Real, V2};
use crate::transform::{check_length, check_point};
use crate::Error;

/// A disk: a point core swept by its radius.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Circle<R: Real> {
    center: V2<R>,
    radius: R,
}

impl<R: Real> Circle<R> {
    /// A circle of `radius` (> 0) centered on the local origin.
    pub fn new(radius: R) -> Result<Self, Error> {
        Self::at(R::vector(R::ZERO, R::ZERO), radius)
    }
    /// A circle of `radius` (> 0) centered on `center` (local coordinates).
    pub fn at(center: R::Vector, radius: R) -> Result<Self, Error> {
        Ok(Self { center: check_point(V2::from_glam(center))?, radius: check_length(radius)? })
    }
    pub fn center_point(&self) -> R::Vector {
        self.center.to_glam()
    }
    pub fn circle_radius(&self) -> R {
        self.radius
    }
}

impl<R: Real> SupportMap<R> for Circle<R> {
    #[inline]
    fn support(&self, _direction: R::Vector) -> R::Vector {
        R::vector(R::ZERO, R::ZERO)
    }
    #[inline]
    fn support_feature(&self, _direction: R::Vector) -> (R::Vector, u32) {
        (R::vector(R::ZERO, R::ZERO), 0)
    }
    fn center(&self) -> R::Vector {
        R::vector(R::ZERO, R::ZERO)
    }
    fn bounding_radius(&self) -> R {
        self.radius
    }
    fn radius(&self) -> R {
        self.radius
    }
    fn is_polytope(&self) -> bool {
        true
    }
    fn reference_point(&self) -> R::Vector {
        self.center.to_glam()
    }
    fn cast_local_ray(&self, o: R::Vector, d: R::Vector, max: R) -> Option<LocalRayCast<R>> {
        Some(cast_ray_disk(V2::zero(), self.radius, V2::from_glam(o), V2::from_glam(d), max))
    }
}
