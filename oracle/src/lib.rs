//! Exact-arithmetic oracle for gjk2d's tests and accuracy report.
//!
//! Inputs are `f32`/`f64` values, i.e. exact dyadic rationals. All geometry is done in
//! exact rational / big-integer arithmetic; the only inexact step is the final rounding
//! to `f64`, which is *correct rounding* (nearest, ties to even) of the exact value:
//! rational results are divided out with big integers, single square roots of
//! rationals use an exact integer square root with a sticky bit, and expressions with
//! square roots (e.g. `sqrt(d2) - R`, ray hit distances) are enclosed in rational
//! intervals refined until both ends round alike. Floats are only used to *select*
//! candidates (prefilters with a documented safety margin), never to decide an answer.

mod core;
pub mod curved;
pub mod exact;
mod pair;
mod ray;
mod shape;

pub use pair::{pair, PairAnswer};
pub use ray::{ray, RayAnswer, RayStatus};
pub use shape::{transform_shape, ExactShape, Pt, Shape};
