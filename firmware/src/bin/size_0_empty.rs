//! Size firmware: nothing from gjk2d (the baseline the others are measured against).
#![no_std]
#![no_main]

#[path = "../size_common.rs"]
mod common;

#[common::entry]
fn main() -> ! {
    common::baseline();
    loop {}
}
