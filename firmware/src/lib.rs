//! Shared code of the gjk2d test firmwares: a tiny test harness that prints
//! through semihosting, the known-answer tests, the golden batch (included
//! from the main crate's tests/golden_batch.rs) and the instruction and
//! stack meters.
#![no_std]

pub mod harness;
pub mod kat;
pub mod meter;

/// The determinism batch shared with the host test tests/golden.rs.
pub mod golden {
    include!("../../tests/golden_batch.rs");
}
