//! Instructions (QEMU -icount shift=0: SysTick on Cortex-M, `minstret` on
//! RISC-V) and peak stack per query, f32 and f64, at the default
//! capacities, and how EPA's capacity N changes the stack. Prints one
//! `MEASURE|...` line per case (run.sh turns them into firmware/icount.md
//! and firmware/stack.md), and fails when the counter's rate is off.
#![no_std]
#![no_main]

use core::hint::black_box as bb;
use gjk2d::{Capsule, Ellipse, Gjk, Polygon, Real, Transform};
#[cfg(not(feature = "measure-step"))]
use gjk2d::{Circle, Epa, GjkConfig, Ray};
#[cfg(feature = "measure-step")]
use gjk2d::{ImpactConfig, Manifold, Motion, PairCache, ShapeCast, Sweep};
use gjk2d_firmware::{debug, entry, hprintln, meter};
#[cfg(target_arch = "arm")]
use panic_semihosting as _;

struct Ctx {
    overhead: u32,
}

fn report(ctx: &Ctx, precision: &str, name: &str, iterations: u32, f: &dyn Fn()) {
    let ix100 = meter::instructions_x100(f, ctx.overhead);
    let stack = meter::stack_bytes(f);
    hprintln!("MEASURE|{}|{}|{}|{}.{:02}|{}", precision, name, iterations, ix100 / 100, ix100 % 100, stack);
}

fn v<R: Real>(x: f64, y: f64) -> R::Vector {
    R::vector(R::from_f64(x), R::from_f64(y))
}

#[cfg(not(feature = "measure-step"))]
fn suite<R: Real>(ctx: &Ctx, p: &str) -> Option<()> {
    let gjk = Gjk::<R>::new();
    let sq = [v::<R>(0.0, 0.0), v::<R>(1.0, 0.0), v::<R>(1.0, 1.0), v::<R>(0.0, 1.0)];
    let a = Polygon::<R, 8>::new(&sq).ok()?;
    let b = Polygon::<R, 8>::regular(6, R::from_f64(0.6)).ok()?;
    let ta = Transform::<R>::IDENTITY;
    let apart = Transform::<R>::new(v::<R>(2.2, 0.7), R::from_f64(0.3)).ok()?;
    let over = Transform::<R>::new(v::<R>(1.3, 0.6), R::from_f64(0.3)).ok()?;
    let circle = Circle::<R>::new(R::from_f64(0.5)).ok()?;
    let capsule = Capsule::<R>::new(v::<R>(-0.5, 0.0), v::<R>(0.5, 0.0), R::from_f64(0.25)).ok()?;
    let ea = Ellipse::<R>::new(R::from_f64(4.0), R::from_f64(2.0)).ok()?;
    let eb = Ellipse::<R>::new(R::from_f64(2.0), R::from_f64(3.0)).ok()?;
    let e_apart = Transform::<R>::new(v::<R>(3.6, 0.9), R::from_f64(0.4)).ok()?;
    let e_over = Transform::<R>::new(v::<R>(2.6, 0.5), R::from_f64(0.4)).ok()?;
    let ray = Ray::<R>::new(v::<R>(-2.0, 0.3), v::<R>(1.0, 0.1)).ok()?;

    let it = |d: Option<u32>| d.unwrap_or(0);
    report(ctx, p, "intersects polygon4-hexagon, apart", gjk.intersects(&a, &ta, &b, &apart).iterations, &|| {
        bb(gjk.intersects(bb(&a), bb(&ta), bb(&b), bb(&apart)));
    });
    report(ctx, p, "intersects polygon4-hexagon, overlapping", gjk.intersects(&a, &ta, &b, &over).iterations, &|| {
        bb(gjk.intersects(bb(&a), bb(&ta), bb(&b), bb(&over)));
    });
    report(ctx, p, "distance polygon4-hexagon", it(gjk.distance(&a, &ta, &b, &apart).map(|s| s.iterations)), &|| {
        bb(gjk.distance(bb(&a), bb(&ta), bb(&b), bb(&apart)));
    });
    report(
        ctx,
        p,
        "penetration polygon4-hexagon (EPA)",
        it(gjk.penetration(&a, &ta, &b, &over).map(|s| s.iterations)),
        &|| {
            bb(gjk.penetration(bb(&a), bb(&ta), bb(&b), bb(&over)));
        },
    );
    report(ctx, p, "raycast polygon4 (closed form)", gjk.raycast(&ray, R::ZERO, &a, &apart).iterations, &|| {
        bb(gjk.raycast(bb(&ray), R::ZERO, bb(&a), bb(&apart)));
    });
    report(ctx, p, "intersects circle-polygon4", gjk.intersects(&a, &ta, &circle, &over).iterations, &|| {
        bb(gjk.intersects(bb(&a), bb(&ta), bb(&circle), bb(&over)));
    });
    report(
        ctx,
        p,
        "distance capsule-polygon4",
        it(gjk.distance(&a, &ta, &capsule, &apart).map(|s| s.iterations)),
        &|| {
            bb(gjk.distance(bb(&a), bb(&ta), bb(&capsule), bb(&apart)));
        },
    );
    report(
        ctx,
        p,
        "penetration capsule-polygon4",
        it(gjk.penetration(&a, &ta, &capsule, &over).map(|s| s.iterations)),
        &|| {
            bb(gjk.penetration(bb(&a), bb(&ta), bb(&capsule), bb(&over)));
        },
    );
    report(ctx, p, "raycast capsule (closed form)", gjk.raycast(&ray, R::ZERO, &capsule, &apart).iterations, &|| {
        bb(gjk.raycast(bb(&ray), R::ZERO, bb(&capsule), bb(&apart)));
    });
    report(ctx, p, "intersects ellipse-ellipse, apart", gjk.intersects(&ea, &ta, &eb, &e_apart).iterations, &|| {
        bb(gjk.intersects(bb(&ea), bb(&ta), bb(&eb), bb(&e_apart)));
    });
    report(
        ctx,
        p,
        "distance ellipse-ellipse",
        it(gjk.distance(&ea, &ta, &eb, &e_apart).map(|s| s.iterations)),
        &|| {
            bb(gjk.distance(bb(&ea), bb(&ta), bb(&eb), bb(&e_apart)));
        },
    );
    report(
        ctx,
        p,
        "penetration ellipse-ellipse (EPA)",
        it(gjk.penetration(&ea, &ta, &eb, &e_over).map(|s| s.iterations)),
        &|| {
            bb(gjk.penetration(bb(&ea), bb(&ta), bb(&eb), bb(&e_over)));
        },
    );
    report(ctx, p, "raycast ellipse (GJK ray cast)", gjk.raycast(&ray, R::ZERO, &ea, &e_apart).iterations, &|| {
        bb(gjk.raycast(bb(&ray), R::ZERO, bb(&ea), bb(&e_apart)));
    });
    // EPA's capacity N (polytope vertices on the stack).
    macro_rules! epa_n {
        ($n:literal) => {{
            let g = Gjk::with_solver(GjkConfig::<R>::default(), Epa::<R, $n>::default());
            let pen = g.penetration(&ea, &ta, &eb, &e_over);
            report(
                ctx,
                p,
                concat!("penetration ellipse-ellipse, Epa N = ", stringify!($n)),
                it(pen.map(|s| s.iterations)),
                &|| {
                    bb(g.penetration(bb(&ea), bb(&ta), bb(&eb), bb(&e_over)));
                },
            );
        }};
    }
    epa_n!(8);
    epa_n!(16);
    epa_n!(32);
    epa_n!(64);
    Some(())
}

/// The rows of the physics-step queries alone (`--features measure-step`):
/// the shape cast, B moving towards A until they touch (a start in contact
/// would measure the penetration query instead), and the contact manifold
/// of a pair apart (within the margin) and of one overlapping.
#[cfg(feature = "measure-step")]
fn suite<R: Real>(ctx: &Ctx, p: &str) -> Option<()> {
    let gjk = Gjk::<R>::new();
    let sq = [v::<R>(0.0, 0.0), v::<R>(1.0, 0.0), v::<R>(1.0, 1.0), v::<R>(0.0, 1.0)];
    let a = Polygon::<R, 8>::new(&sq).ok()?;
    let b = Polygon::<R, 8>::regular(6, R::from_f64(0.6)).ok()?;
    let ta = Transform::<R>::IDENTITY;
    let apart = Transform::<R>::new(v::<R>(2.2, 0.7), R::from_f64(0.3)).ok()?;
    let over = Transform::<R>::new(v::<R>(1.3, 0.6), R::from_f64(0.3)).ok()?;
    let capsule = Capsule::<R>::new(v::<R>(-0.5, 0.0), v::<R>(0.5, 0.0), R::from_f64(0.25)).ok()?;
    let ea = Ellipse::<R>::new(R::from_f64(4.0), R::from_f64(2.0)).ok()?;
    let eb = Ellipse::<R>::new(R::from_f64(2.0), R::from_f64(3.0)).ok()?;
    let e_apart = Transform::<R>::new(v::<R>(3.6, 0.9), R::from_f64(0.4)).ok()?;
    let towards = Motion::<R>::new(v::<R>(-1.6, -0.4)).ok()?;
    let cast_iterations = |c: ShapeCast<R>| if c.hit().is_some() { c.iterations } else { 0 };
    report(ctx, p, "cast polygon4-hexagon", cast_iterations(gjk.cast(&a, &ta, &b, &apart, &towards)), &|| {
        bb(gjk.cast(bb(&a), bb(&ta), bb(&b), bb(&apart), bb(&towards)));
    });
    report(ctx, p, "cast capsule-polygon4", cast_iterations(gjk.cast(&a, &ta, &capsule, &apart, &towards)), &|| {
        bb(gjk.cast(bb(&a), bb(&ta), bb(&capsule), bb(&apart), bb(&towards)));
    });
    report(ctx, p, "cast ellipse-ellipse", cast_iterations(gjk.cast(&ea, &ta, &eb, &e_apart, &towards)), &|| {
        bb(gjk.cast(bb(&ea), bb(&ta), bb(&eb), bb(&e_apart), bb(&towards)));
    });
    let margin = R::from_f64(2.0);
    let manifold_iterations = |m: Result<Manifold<R>, gjk2d::Error>| m.map_or(0, |m| m.iterations);
    report(
        ctx,
        p,
        "manifold polygon4-hexagon, apart",
        manifold_iterations(gjk.manifold(&a, &ta, &b, &apart, margin)),
        &|| {
            let _ = bb(gjk.manifold(bb(&a), bb(&ta), bb(&b), bb(&apart), bb(margin)));
        },
    );
    report(
        ctx,
        p,
        "manifold polygon4-hexagon, overlapping",
        manifold_iterations(gjk.manifold(&a, &ta, &b, &over, margin)),
        &|| {
            let _ = bb(gjk.manifold(bb(&a), bb(&ta), bb(&b), bb(&over), bb(margin)));
        },
    );
    // B moving towards A and turning a quarter turn, A still.
    let config = ImpactConfig::<R>::new(R::from_f64(0.01), R::from_f64(0.005)).ok()?;
    let turning = Sweep::new(&apart, v::<R>(0.0, 0.0), v::<R>(-1.6, -0.4), R::from_f64(1.5)).ok()?;
    let still = Sweep::still(&ta);
    let toi = gjk.time_of_impact(&a, &still, &b, &turning, &config);
    report(ctx, p, "time of impact polygon4-hexagon", toi.iterations, &|| {
        bb(gjk.time_of_impact(bb(&a), bb(&still), bb(&b), bb(&turning), bb(&config)));
    });
    // A cache from the step before, B moved a little since.
    let (mut cache, near) =
        (PairCache::<R>::default(), Transform::<R>::new(v::<R>(2.21, 0.7), R::from_f64(0.31)).ok()?);
    let _ = gjk.distance_cached(&a, &ta, &b, &apart, &mut cache);
    let warm = gjk.distance_cached(&a, &ta, &b, &near, &mut cache.clone()).map_or(0, |s| s.iterations);
    report(ctx, p, "distance cached polygon4-hexagon", warm, &|| {
        bb(gjk.distance_cached(bb(&a), bb(&ta), bb(&b), bb(&near), &mut bb(cache)));
    });
    let (mut cache, deeper) =
        (PairCache::<R>::default(), Transform::<R>::new(v::<R>(1.31, 0.6), R::from_f64(0.31)).ok()?);
    let _ = gjk.penetration_cached(&a, &ta, &b, &over, &mut cache);
    let warm = gjk.penetration_cached(&a, &ta, &b, &deeper, &mut cache.clone()).map_or(0, |p| p.iterations);
    report(ctx, p, "penetration cached polygon4-hexagon", warm, &|| {
        bb(gjk.penetration_cached(bb(&a), bb(&ta), bb(&b), bb(&deeper), &mut bb(cache)));
    });
    Some(())
}

#[entry]
fn main() -> ! {
    meter::start();

    // Check the rate: 2 x 100_000 known instructions.
    let overhead = meter::ticks(&|| {});
    let known = meter::ticks(&|| meter::known_instructions(bb(5_000)));
    // REPEAT x (2 x 5000 + call) instructions.
    let per_tick_x100 = (meter::REPEAT * 10_000) as u64 * 100 / known.saturating_sub(overhead).max(1) as u64;
    hprintln!(
        "CALIBRATION|{} ticks for {} x 10000 instructions: {}.{:02} instructions per tick (expected {})|loop overhead {} ticks",
        known - overhead,
        meter::REPEAT,
        per_tick_x100 / 100,
        per_tick_x100 % 100,
        meter::INSTRUCTIONS_PER_TICK,
        overhead
    );
    // A counter that does not run (or runs at another rate) would read as
    // figures that shrank, which the figure check lets through.
    let expected_x100 = meter::INSTRUCTIONS_PER_TICK as u64 * 100;
    let calibrated = per_tick_x100.abs_diff(expected_x100) * 50 <= expected_x100;
    if !calibrated {
        hprintln!("measure FAILED: the counter's rate is more than 2% off");
    }
    let ctx = Ctx { overhead };
    let ok = calibrated && suite::<f32>(&ctx, "f32").is_some() & suite::<f64>(&ctx, "f64").is_some();
    hprintln!("measure {}", if ok { "done" } else { "FAILED" });
    debug::exit(if ok { debug::EXIT_SUCCESS } else { debug::EXIT_FAILURE });
    loop {}
}
