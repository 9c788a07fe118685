// The firmware page's example (firmware/README.md), built by firmware/run.sh so it keeps compiling.
#![no_std]
#![no_main]

use cortex_m_rt::entry;
use gjk2d::glam::Vec2;
use gjk2d::{Circle, Gjk, Polygon, Ray, RayOutcome, Transform};

// A fixed shape is best a constant: the compiler checks it (an invalid one
// fails the build) and the firmware carries no checking code (1.7 KB).
static SQUARE: Polygon<f32, 4> = match Polygon::<f32, 4>::from_array([
    Vec2::new(0.0, 0.0),
    Vec2::new(1.0, 0.0),
    Vec2::new(1.0, 1.0),
    Vec2::new(0.0, 1.0),
]) {
    Ok(square) => square,
    Err(e) => panic!("{}", e.as_str()), // a compile error, never a run-time panic
};

#[entry]
fn main() -> ! {
    // Shapes built at run time are checked then (no allocator).
    let Ok(ball) = Circle::new(0.5) else { loop {} };
    let square = &SQUARE;
    let gjk = Gjk::<f32>::new(); // EPA with room for 32 polytope vertices

    loop {
        let here = Transform::IDENTITY;
        let Ok(there) = Transform::new(Vec2::new(1.2, 0.5), 0.3) else { continue };

        if gjk.intersects(square, &here, &ball, &there).intersecting {
            if let Some(p) = gjk.penetration(square, &here, &ball, &there) {
                // move the ball by p.depth along p.normal to separate
                let _push = p.normal * p.depth;
            }
        } else if let Some(s) = gjk.distance(square, &here, &ball, &there) {
            let _gap = (s.distance, s.point_a, s.point_b);
        }

        if let Ok(ray) = Ray::new(Vec2::new(-2.0, 0.5), Vec2::X) {
            if let RayOutcome::Hit(hit) = gjk.raycast(&ray, 10.0, square, &here).outcome {
                let _ = (hit.distance, hit.point, hit.normal);
            }
        }
    }
}

#[panic_handler]
fn panic(_: &core::panic::PanicInfo) -> ! {
    // gjk2d itself has no panic path (firmware/run.sh checks it at link time).
    loop {}
}
