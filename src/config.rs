//! Tunables of the queries, validated when set.
//!
//! Epsilons are *relative*: the absolute tolerance of a query is the epsilon
//! times the size of the pair (the larger bounding radius). An absolute
//! tolerance is what makes today's peers fail on tiny and huge shapes.

use crate::error::Error;
use crate::real::Real;
use crate::transform::check_length;

/// The minimum for every iteration limit, as in dyn4j.
pub const MIN_ITERATIONS: u32 = 5;

/// Iteration limits and epsilons of the GJK queries.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct GjkConfig<R: Real> {
    max_detect_iterations: u32,
    max_distance_iterations: u32,
    max_raycast_iterations: u32,
    detect_epsilon: R,
    distance_epsilon: R,
    raycast_epsilon: R,
}

/// The default relative epsilon of the iterative (curved-shape) queries:
/// 5e-7 in f32 and 5e-13 in f64, half the accuracy they are meant to give
/// (1e-6 L and 1e-12 L): the epsilon bounds the iteration's gap, and rounding
/// comes on top of it.
pub fn default_epsilon<R: Real>() -> R {
    if R::EPSILON > R::from_f64(1e-10) {
        R::from_f64(5e-7)
    } else {
        R::from_f64(5e-13)
    }
}

impl<R: Real> Default for GjkConfig<R> {
    /// 30 iterations for each query (dyn4j's defaults); detect epsilon 0; distance
    /// and ray-cast epsilons 5e-7 (f32) or 5e-13 (f64), relative to the pair's size.
    fn default() -> Self {
        Self {
            max_detect_iterations: 30,
            max_distance_iterations: 30,
            max_raycast_iterations: 30,
            detect_epsilon: R::ZERO,
            distance_epsilon: default_epsilon(),
            raycast_epsilon: default_epsilon(),
        }
    }
}

fn check_iterations(n: u32) -> Result<u32, Error> {
    if n < MIN_ITERATIONS {
        Err(Error::TooFewIterations)
    } else {
        Ok(n)
    }
}

fn check_epsilon<R: Real>(eps: R, zero_allowed: bool) -> Result<R, Error> {
    if !eps.is_finite() {
        Err(Error::NonFinite)
    } else if eps < R::ZERO || (eps == R::ZERO && !zero_allowed) {
        Err(Error::InvalidEpsilon)
    } else {
        Ok(eps)
    }
}

impl<R: Real> GjkConfig<R> {
    pub fn max_detect_iterations(&self) -> u32 {
        self.max_detect_iterations
    }
    pub fn max_distance_iterations(&self) -> u32 {
        self.max_distance_iterations
    }
    pub fn max_raycast_iterations(&self) -> u32 {
        self.max_raycast_iterations
    }
    pub fn detect_epsilon(&self) -> R {
        self.detect_epsilon
    }
    pub fn distance_epsilon(&self) -> R {
        self.distance_epsilon
    }
    pub fn raycast_epsilon(&self) -> R {
        self.raycast_epsilon
    }

    /// At least 5 ([`MIN_ITERATIONS`]).
    pub fn set_max_detect_iterations(&mut self, n: u32) -> Result<(), Error> {
        self.max_detect_iterations = check_iterations(n)?;
        Ok(())
    }
    /// At least 5 ([`MIN_ITERATIONS`]).
    pub fn set_max_distance_iterations(&mut self, n: u32) -> Result<(), Error> {
        self.max_distance_iterations = check_iterations(n)?;
        Ok(())
    }
    /// At least 5 ([`MIN_ITERATIONS`]).
    pub fn set_max_raycast_iterations(&mut self, n: u32) -> Result<(), Error> {
        self.max_raycast_iterations = check_iterations(n)?;
        Ok(())
    }
    /// Zero or more. A positive value makes the intersection test report
    /// shapes closer than `epsilon * size` as intersecting (a contact margin).
    pub fn set_detect_epsilon(&mut self, eps: R) -> Result<(), Error> {
        self.detect_epsilon = check_epsilon(eps, true)?;
        Ok(())
    }
    /// Greater than zero: the distance query stops once its certified error
    /// bound is below `epsilon * size`. Polytope pairs stop earlier, exactly,
    /// when a support point repeats.
    pub fn set_distance_epsilon(&mut self, eps: R) -> Result<(), Error> {
        self.distance_epsilon = check_epsilon(eps, false)?;
        Ok(())
    }
    /// Greater than zero: a ray cast against a curved shape stops when the ray
    /// point is within `epsilon * size` of the surface.
    pub fn set_raycast_epsilon(&mut self, eps: R) -> Result<(), Error> {
        self.raycast_epsilon = check_epsilon(eps, false)?;
        Ok(())
    }
}

/// Iteration limit and epsilon of the expanding polytope algorithm.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct EpaConfig<R: Real> {
    max_iterations: u32,
    epsilon: R,
}

impl<R: Real> Default for EpaConfig<R> {
    /// 100 iterations (dyn4j's default), epsilon 5e-7 (f32) or 5e-13 (f64),
    /// relative to the pair's size.
    fn default() -> Self {
        Self { max_iterations: 100, epsilon: default_epsilon() }
    }
}

impl<R: Real> EpaConfig<R> {
    pub fn max_iterations(&self) -> u32 {
        self.max_iterations
    }
    pub fn epsilon(&self) -> R {
        self.epsilon
    }
    /// At least 5 ([`MIN_ITERATIONS`]).
    pub fn set_max_iterations(&mut self, n: u32) -> Result<(), Error> {
        self.max_iterations = check_iterations(n)?;
        Ok(())
    }
    /// Greater than zero: EPA stops when the gap between its lower and upper
    /// bound on the depth is below `epsilon * size`.
    pub fn set_epsilon(&mut self, eps: R) -> Result<(), Error> {
        self.epsilon = check_epsilon(eps, false)?;
        Ok(())
    }
}

/// The target and the limits of [`Gjk::time_of_impact`](crate::Gjk::time_of_impact):
/// absolute lengths, as a physics step's slop is.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ImpactConfig<R: Real> {
    target: R,
    tolerance: R,
    max_iterations: u32,
}

impl<R: Real> ImpactConfig<R> {
    /// Stop the shapes `target` apart (zero or more: a small positive
    /// target leaves the contact solver a speculative gap and spares the
    /// advancement its slow last steps), accepting up to `tolerance` more
    /// (greater than zero). Both finite and within
    /// [`Real::MAX_COORDINATE`]; 50 iterations.
    pub fn new(target: R, tolerance: R) -> Result<Self, Error> {
        let target = if target == R::ZERO { target } else { check_length(target)? };
        Ok(Self { target, tolerance: check_length(tolerance)?, max_iterations: 50 })
    }
    pub fn target(&self) -> R {
        self.target
    }
    pub fn tolerance(&self) -> R {
        self.tolerance
    }
    pub fn max_iterations(&self) -> u32 {
        self.max_iterations
    }
    /// At least 5 ([`MIN_ITERATIONS`]).
    pub fn set_max_iterations(&mut self, n: u32) -> Result<(), Error> {
        self.max_iterations = check_iterations(n)?;
        Ok(())
    }
}
