//! Size firmware: polygon intersection + distance + EPA penetration (f32).
#![no_std]
#![no_main]

#[path = "../size_common.rs"]
mod common;

#[cortex_m_rt::entry]
fn main() -> ! {
    let gjk = gjk2d::Gjk::<f32>::new();
    common::with_polygons::<f32>(|a, b, tb| {
        common::intersects(&gjk, a, b, tb);
        common::distance(&gjk, a, b, tb);
        common::penetration(&gjk, a, b, tb);
    });
    loop {}
}
