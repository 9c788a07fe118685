//! Size firmware: every shape kind and every query, f64.
#![no_std]
#![no_main]

#[path = "../size_common.rs"]
mod common;

#[common::entry]
fn main() -> ! {
    common::everything::<f64>();
    loop {}
}
