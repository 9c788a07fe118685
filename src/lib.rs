//! # gjk2d
//!
//! 2D convex collision detection with GJK and EPA: `#![no_std]`, no
//! allocator, one generic code path for `f32` ([`glam::Vec2`]) and `f64`
//! ([`glam::DVec2`]).
//!
//! - [`Gjk::intersects`]: does A overlap B? The cheap query.
//! - [`Gjk::penetration`]: normal and depth of the overlap (EPA by default,
//!   any [`PenetrationSolver`] can be plugged in).
//! - [`Gjk::distance`]: distance, normal and closest points when apart, with
//!   a certified error bound.
//! - [`Gjk::raycast`]: first hit of a ray on any convex shape.
//! - [`Gjk::cast`]: when a shape translating along a motion first touches
//!   another (a linear shape cast).
//! - [`Gjk::time_of_impact`]: when two shapes that translate and rotate
//!   over a step first come within a target distance.
//! - [`Gjk::manifold`]: up to two contact points with feature ids, within a
//!   speculative margin, for a physics step.
//! - The `_cached` queries ([`Gjk::intersects_cached`] and the others):
//!   the same answers, warm started from a [`PairCache`] kept per pair
//!   between steps.
//!
//! Shapes: [`Circle`], [`Polygon`], [`Rectangle`], [`Triangle`], [`Segment`],
//! [`Capsule`], [`Ellipse`], [`HalfEllipse`], [`Slice`], [`Rounded`], and your
//! own through [`SupportMap`].
//!
//! ```
//! use gjk2d::{Gjk, Polygon, Circle, Transform};
//! use glam::Vec2;
//!
//! let square = Polygon::<f32, 4>::new(&[
//!     Vec2::new(0.0, 0.0), Vec2::new(1.0, 0.0), Vec2::new(1.0, 1.0), Vec2::new(0.0, 1.0),
//! ])?;
//! let ball = Circle::new(0.5)?;
//! let gjk = Gjk::<f32>::new();
//! let here = Transform::IDENTITY;
//! let there = Transform::from_translation(Vec2::new(3.0, 0.5))?;
//! let sep = gjk.distance(&square, &here, &ball, &there).expect("apart");
//! assert!((sep.distance - 1.5).abs() < 1e-6);
//! assert_eq!(sep.normal, Vec2::X);
//! # Ok::<(), gjk2d::Error>(())
//! ```
#![cfg_attr(not(feature = "std"), no_std)]
#![deny(unsafe_code)]
#![warn(missing_debug_implementations)]

#[cfg(feature = "std")]
extern crate std;

pub use glam;

mod cast;
mod checks;
#[cfg(feature = "far-geometry")]
mod compensated;
mod config;
mod detector;
mod epa;
mod error;
mod gjk;
mod hw_sqrt;
mod impact;
mod manifold;
mod minkowski;
mod point_cores;
#[cfg(not(any(target_os = "none", target_family = "wasm")))]
mod point_polygon;
mod polytope;
#[cfg(not(any(target_os = "none", target_family = "wasm")))]
mod quad_start;
mod ray;
mod real;
mod result;
#[cfg(not(any(target_os = "none", target_family = "wasm")))]
mod sat;
#[cfg(not(any(target_os = "none", target_family = "wasm")))]
mod segment_polygon;
pub mod shape;
mod simplex;
mod transform;
mod trig;
#[cfg(not(any(target_os = "none", target_family = "wasm")))]
mod walked_axes;
mod warm;

#[cfg(feature = "std")]
mod batch;
#[cfg(feature = "defmt")]
mod defmt_impls;

pub use cast::{CastHit, CastOutcome, CastStart, Motion, ShapeCast};
pub use config::{EpaConfig, GjkConfig, ImpactConfig, MIN_ITERATIONS};
pub use detector::Gjk;
pub use epa::{Epa, PenetrationEstimate, PenetrationSolver};
pub use error::Error;
pub use impact::{Impact, ImpactOutcome, ImpactStart, Sweep, TimeOfImpact, MAX_SWEEP_ANGLE};
pub use minkowski::{MinkowskiDifference, SupportPoint, NO_ID};
pub use ray::Ray;
pub use real::Real;
pub use result::{
    ContactPoint, Detection, Feature, FeatureId, LocalRayCast, Manifold, Penetration, RayCast, RayHit, RayOutcome,
    Separation, Status,
};
pub use shape::{
    Capsule, Circle, Ellipse, HalfEllipse, Polygon, Rectangle, Rounded, Segment, Slice, SupportMap, Triangle,
    NO_FEATURE,
};
pub use transform::Transform;
pub use warm::PairCache;

#[cfg(feature = "std")]
pub use batch::EpaVec;

/// The README's examples, compiled and run as doctests.
#[doc = include_str!("../README.md")]
#[cfg(doctest)]
pub struct ReadmeDoctests;

/// The examples page's examples, compiled and run as doctests.
#[doc = include_str!("../docs/examples.md")]
#[cfg(doctest)]
pub struct ExamplesDoctests;
