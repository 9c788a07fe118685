//! Size firmware: every shape kind and every query, f64, the shapes
//! declared as constants.
#![no_std]
#![no_main]

#[path = "../size_common.rs"]
mod common;

#[common::entry]
fn main() -> ! {
    common::fixed_f64::everything_fixed();
    loop {}
}
