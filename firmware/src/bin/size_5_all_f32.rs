//! Size firmware: every shape kind and every query, f32.
#![no_std]
#![no_main]

#[path = "../size_common.rs"]
mod common;

#[common::entry]
fn main() -> ! {
    common::everything::<f32>();
    loop {}
}
