//! Size firmware: nothing from gjk2d (the baseline the others are measured against).
#![no_std]
#![no_main]

#[path = "../size_common.rs"]
mod common;

#[cortex_m_rt::entry]
fn main() -> ! {
    common::baseline();
    loop {}
}
