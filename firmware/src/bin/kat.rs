//! Known-answer tests of every query on every shape, f32 and f64, then the
//! golden determinism hash. Prints `N passed, M failed` and exits QEMU with
//! 0 (all passed) or 1 through semihosting.
#![no_std]
#![no_main]

use gjk2d_firmware::{debug, entry, golden, harness::Tally, hprintln, kat};
#[cfg(target_arch = "arm")]
use panic_semihosting as _;

#[entry]
fn main() -> ! {
    let mut t = Tally::new();
    t.context = "f32";
    kat::run::<f32>(&mut t);
    kat::const_polygons_f32(&mut t);
    let after_f32 = t.passed + t.failed;
    t.context = "f64";
    kat::run::<f64>(&mut t);
    kat::const_polygons_f64(&mut t);
    hprintln!("checks: {} in f32, {} in f64", after_f32, t.passed + t.failed - after_f32);

    hprintln!("golden hash f32 {:#018x}", golden::golden_hash_f32());
    hprintln!("golden hash f64 {:#018x}", golden::golden_hash_f64());
    hprintln!("golden hash {:#018x}", golden::golden_hash());

    hprintln!("{} passed, {} failed", t.passed, t.failed);
    debug::exit(if t.failed == 0 { debug::EXIT_SUCCESS } else { debug::EXIT_FAILURE });
    loop {}
}
