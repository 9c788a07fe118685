//! gjk2d's results through defmt: every query's result type, a shape and
//! the configuration, logged with `defmt::info!` over semihosting (frames on
//! QEMU's stdout; decode them with `defmt-print -e <elf>`). run.sh checks that
//! it runs, writes frames, and links each type's format string.
#![no_std]
#![no_main]

use cortex_m_rt::entry;
use cortex_m_semihosting::debug;
use defmt_semihosting as _;
use gjk2d::glam::Vec2;
use gjk2d::*;
use panic_semihosting as _;

#[entry]
fn main() -> ! {
    let run = || -> Result<(), Error> {
        let square = Polygon::<f32, 8>::new(&[
            Vec2::new(0.0, 0.0),
            Vec2::new(1.0, 0.0),
            Vec2::new(1.0, 1.0),
            Vec2::new(0.0, 1.0),
        ])?;
        let ball = Circle::new(0.5)?;
        let gjk = Gjk::<f32>::new();
        let here = Transform::IDENTITY;
        let apart = Transform::from_translation(Vec2::new(3.0, 0.5))?;
        let close = Transform::from_translation(Vec2::new(1.25, 0.5))?;
        defmt::info!("{}", square);
        defmt::info!("{}", ball);
        defmt::info!("{}", gjk.config);
        defmt::info!("{}", apart);
        defmt::info!("{}", gjk.intersects(&square, &here, &ball, &close));
        if let Some(s) = gjk.distance(&square, &here, &ball, &apart) {
            defmt::info!("{}", s);
        }
        if let Some(p) = gjk.penetration(&square, &here, &ball, &close) {
            defmt::info!("{}", p);
        }
        let ray = Ray::new(Vec2::new(-2.0, 0.5), Vec2::X)?;
        defmt::info!("{}", ray);
        defmt::info!("{}", gjk.raycast(&ray, 0.0, &square, &here));
        defmt::info!("{}", Error::NotConvex);
        Ok(())
    };
    let code = if run().is_ok() { debug::EXIT_SUCCESS } else { debug::EXIT_FAILURE };
    debug::exit(code);
    #[allow(clippy::empty_loop)]
    loop {}
}
