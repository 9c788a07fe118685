//! Shared code of the gjk2d test firmwares: a tiny test harness that prints
//! through semihosting, the known-answer tests, the golden batch (included
//! from the main crate's tests/golden_batch.rs) and the instruction and
//! stack meters.
#![no_std]

pub mod harness;
pub mod kat;
pub mod meter;

// The entry attribute and semihosting from the target's runtime: the same
// `#[entry]`, `hprintln!` and `debug::exit` on Cortex-M and RISC-V, so the
// tests are written once.
#[cfg(target_arch = "arm")]
pub use {
    cortex_m_rt::entry,
    cortex_m_semihosting::{debug, hprintln},
};
#[cfg(target_arch = "riscv32")]
pub use {
    riscv_rt::entry,
    riscv_semihosting::{debug, hprintln},
};

/// On RISC-V a panic (a failed `unwrap` in a test, never in gjk2d: the
/// size firmwares prove that at link time) is reported and ends QEMU with a
/// failure, as panic-semihosting does on Cortex-M.
#[cfg(target_arch = "riscv32")]
#[panic_handler]
fn panic(info: &core::panic::PanicInfo) -> ! {
    hprintln!("{}", info);
    debug::exit(debug::EXIT_FAILURE);
    loop {}
}

/// The determinism batch shared with the host test tests/golden.rs.
pub mod golden {
    include!("../../tests/golden_batch.rs");
}
