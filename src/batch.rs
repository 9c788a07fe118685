//! The `std` layer: results that need a `Vec`. Thin on purpose: each is a
//! loop over the no_std queries, so both give identical answers.

use std::vec::Vec;

use crate::config::EpaConfig;
use crate::detector::Gjk;
use crate::epa::{expand, PenetrationEstimate, PenetrationSolver};
use crate::minkowski::{MinkowskiDifference, SupportPoint};
use crate::ray::Ray;
use crate::real::Real;
use crate::result::{Penetration, RayHit, Separation};
use crate::shape::SupportMap;
use crate::transform::Transform;

impl<R: Real, P: PenetrationSolver<R>> Gjk<R, P> {
    /// The separation of `a` from each of `others`, in order: `None` where
    /// they overlap.
    ///
    /// ```
    /// use gjk2d::{Circle, Gjk, Transform};
    /// use glam::Vec2;
    ///
    /// let gjk = Gjk::<f32>::new();
    /// let at = |x: f32| Transform::from_translation(Vec2::new(x, 0.0));
    /// let ball = Circle::new(1.0)?;
    /// let others = [(ball, at(3.0)?), (ball, at(1.0)?)];
    /// let found = gjk.distances(&ball, &Transform::IDENTITY, &others);
    /// assert!((found[0].expect("apart").distance - 1.0).abs() < 1e-6);
    /// assert!(found[1].is_none()); // overlapping
    /// # Ok::<(), gjk2d::Error>(())
    /// ```
    pub fn distances<A, B>(&self, a: &A, ta: &Transform<R>, others: &[(B, Transform<R>)]) -> Vec<Option<Separation<R>>>
    where
        A: SupportMap<R> + ?Sized,
        B: SupportMap<R>,
    {
        others.iter().map(|(b, tb)| self.distance(a, ta, b, tb)).collect()
    }

    /// The penetration of `a` into each of `others`, in order: `None` where
    /// they are apart.
    ///
    /// ```
    /// use gjk2d::{Circle, Gjk, Transform};
    /// use glam::Vec2;
    ///
    /// let gjk = Gjk::<f32>::new();
    /// let at = |x: f32| Transform::from_translation(Vec2::new(x, 0.0));
    /// let ball = Circle::new(1.0)?;
    /// let found = gjk.penetrations(&ball, &Transform::IDENTITY, &[(ball, at(3.0)?), (ball, at(1.5)?)]);
    /// assert!(found[0].is_none()); // apart
    /// assert!((found[1].expect("overlap").depth - 0.5).abs() < 1e-6);
    /// # Ok::<(), gjk2d::Error>(())
    /// ```
    pub fn penetrations<A, B>(
        &self,
        a: &A,
        ta: &Transform<R>,
        others: &[(B, Transform<R>)],
    ) -> Vec<Option<Penetration<R>>>
    where
        A: SupportMap<R> + ?Sized,
        B: SupportMap<R>,
    {
        others.iter().map(|(b, tb)| self.penetration(a, ta, b, tb)).collect()
    }

    /// Every shape the ray hits within `max_length`, nearest first, with
    /// its index in `shapes`. Rays starting inside a shape do not list it.
    ///
    /// ```
    /// use gjk2d::{Circle, Gjk, Ray, Transform};
    /// use glam::Vec2;
    ///
    /// let gjk = Gjk::<f32>::new();
    /// let at = |x: f32| Transform::from_translation(Vec2::new(x, 0.0));
    /// let post = Circle::new(0.5)?;
    /// let posts = [(post, at(6.0)?), (post, at(2.0)?), (post, at(-4.0)?)];
    /// let ray = Ray::new(Vec2::ZERO, Vec2::X)?;
    /// let hits = gjk.raycast_all(&ray, 0.0, &posts);
    /// // Nearest first, by index into `posts`; the post behind the ray is not hit.
    /// assert_eq!(hits.iter().map(|(i, _)| *i).collect::<Vec<_>>(), [1, 0]);
    /// assert!((hits[0].1.distance - 1.5).abs() < 1e-6);
    /// # Ok::<(), gjk2d::Error>(())
    /// ```
    pub fn raycast_all<S>(&self, ray: &Ray<R>, max_length: R, shapes: &[(S, Transform<R>)]) -> Vec<(usize, RayHit<R>)>
    where
        S: SupportMap<R>,
    {
        let mut hits: Vec<(usize, RayHit<R>)> = shapes
            .iter()
            .enumerate()
            .filter_map(|(i, (s, t))| self.raycast(ray, max_length, s, t).hit().map(|h| (i, *h)))
            .collect();
        // Distances are finite, so the order is total.
        hits.sort_by(|x, y| x.1.distance.partial_cmp(&y.1.distance).unwrap_or(core::cmp::Ordering::Equal));
        hits
    }
}

/// EPA on a heap-allocated polytope that grows as needed: no capacity limit,
/// only the iteration limit.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct EpaVec<R: Real> {
    pub config: EpaConfig<R>,
}

impl<R: Real> PenetrationSolver<R> for EpaVec<R> {
    const SEPARATING_AXES: bool = true;

    fn solve<M: MinkowskiDifference<R>>(&self, difference: &M, simplex: &[SupportPoint<R>]) -> PenetrationEstimate<R> {
        let mut polytope = Vec::with_capacity(16);
        expand(&mut polytope, &self.config, difference, simplex)
    }
}
