//! Size firmware: polygon intersection + distance + EPA penetration (f32).
#![no_std]
#![no_main]

#[path = "../size_common.rs"]
mod common;

#[cortex_m_rt::entry]
fn main() -> ! {
    let gjk = gjk2d::Gjk::<f32>::new();
    if let Some(p) = common::polygons::<f32>() {
        common::intersects(&gjk, &p.a, &p.b, &p.tb);
        common::distance(&gjk, &p.a, &p.b, &p.tb);
        common::penetration(&gjk, &p.a, &p.b, &p.tb);
    }
    loop {}
}
