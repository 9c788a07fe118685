//! Shared by the size firmwares (src/bin/size_*.rs): inputs the optimizer
//! cannot see (volatile reads of statics in RAM), a sink for the results
//! (volatile writes), the queries each firmware links, and the no-panic
//! check: the panic handler calls a function that exists nowhere, so the
//! release (LTO) link fails if any panic path survives.
#![allow(dead_code)]

use core::panic::PanicInfo;
use core::ptr::{addr_of, addr_of_mut, read_volatile, write_volatile};
use gjk2d::{
    Capsule, CastOutcome, Circle, Ellipse, Feature, Gjk, HalfEllipse, ImpactConfig, ImpactOutcome, Motion, PairCache,
    Polygon, Ray, RayOutcome, Real, Rectangle, Rounded, Segment, Slice, SupportMap, Sweep, Transform, Triangle,
};

/// The runtime's entry attribute: the same firmwares build for Cortex-M and
/// RISC-V. (Not the library's re-export: linking the library would bring its
/// RISC-V panic handler beside this one.)
#[cfg(target_arch = "arm")]
pub use cortex_m_rt::entry;
#[cfg(target_arch = "riscv32")]
pub use riscv_rt::entry;

#[panic_handler]
fn panic(_: &PanicInfo) -> ! {
    extern "C" {
        /// Defined nowhere: linking it means a panic path survived.
        fn gjk2d_panic_path_linked() -> !;
    }
    unsafe { gjk2d_panic_path_linked() }
}

/// Inputs: a unit square, the same square, a placement (0.5, 0.25) with
/// (cos, sin) = (1, 0), a ray from (-2, 0.5) along +x, then sizes.
const INPUT: [f64; 32] = [
    0.0, 0.0, 1.0, 0.0, 1.0, 1.0, 0.0, 1.0, // polygon A
    0.0, 0.0, 1.0, 0.0, 1.0, 1.0, 0.0, 1.0, // polygon B
    0.5, 0.25, 1.0, 0.0, // B's placement: translation, cos, sin
    -2.0, 0.5, 1.0, 0.0, // ray origin, direction
    0.5, 0.25, 2.0, 1.0, 1.2, 0.0, 3.0, 0.0, // radius, radius, width, height, angle, 0, shape pair, 0
];

#[no_mangle]
static mut GJK2D_IN32: [f32; 32] = {
    let mut a = [0.0f32; 32];
    let mut i = 0;
    while i < 32 {
        a[i] = INPUT[i] as f32;
        i += 1;
    }
    a
};
#[no_mangle]
static mut GJK2D_IN64: [f64; 32] = INPUT;
#[no_mangle]
static mut GJK2D_OUT32: u32 = 0;
#[no_mangle]
static mut GJK2D_OUT64: u64 = 0;

/// A precision whose inputs and outputs go through volatile statics.
pub trait Io: Real {
    fn input(i: usize) -> Self;
    fn sink(self);
}

impl Io for f32 {
    #[inline(always)]
    fn input(i: usize) -> f32 {
        unsafe { read_volatile(addr_of!(GJK2D_IN32).cast::<f32>().add(i & 31)) }
    }
    #[inline(always)]
    fn sink(self) {
        unsafe { write_volatile(addr_of_mut!(GJK2D_OUT32), self.to_bits()) }
    }
}

impl Io for f64 {
    #[inline(always)]
    fn input(i: usize) -> f64 {
        unsafe { read_volatile(addr_of!(GJK2D_IN64).cast::<f64>().add(i & 31)) }
    }
    #[inline(always)]
    fn sink(self) {
        unsafe { write_volatile(addr_of_mut!(GJK2D_OUT64), self.to_bits()) }
    }
}

#[inline(always)]
pub fn sink_u32(x: u32) {
    unsafe { write_volatile(addr_of_mut!(GJK2D_OUT32), x) }
}

#[inline(always)]
fn sink_v<R: Io>(v: R::Vector) {
    let (x, y) = R::components(v);
    x.sink();
    y.sink();
}

fn vec<R: Io>(i: usize) -> R::Vector {
    R::vector(R::input(i), R::input(i + 1))
}

/// The empty firmware's work: one input to the output.
pub fn baseline() {
    f32::input(0).sink();
}

/// Two polygons and B's placement, from the inputs, handed to `f` by
/// reference where they were built, as a firmware keeps its shapes in place
/// (moving an 88-byte polygon is a call to `memcpy`).
pub fn with_polygons<R: Io>(f: impl FnOnce(&Polygon<R, 8>, &Polygon<R, 8>, &Transform<R>)) {
    let a = Polygon::new(&[vec::<R>(0), vec::<R>(2), vec::<R>(4), vec::<R>(6)]);
    let b = Polygon::new(&[vec::<R>(8), vec::<R>(10), vec::<R>(12), vec::<R>(14)]);
    let tb = Transform::from_cos_sin(vec::<R>(16), R::input(18), R::input(19));
    if let (Ok(a), Ok(b), Ok(tb)) = (&a, &b, &tb) {
        f(a, b, tb);
    }
}

/// The same two unit squares as constants, checked when the firmware is
/// compiled (`Polygon::from_array`): a firmware with fixed shapes links no
/// polygon checks. Read through `black_box`, so the queries cannot be
/// specialised to the known vertices.
static SQUARE: Polygon<f32, 4> = match Polygon::<f32, 4>::from_array([
    gjk2d::glam::Vec2::new(0.0, 0.0),
    gjk2d::glam::Vec2::new(1.0, 0.0),
    gjk2d::glam::Vec2::new(1.0, 1.0),
    gjk2d::glam::Vec2::new(0.0, 1.0),
]) {
    Ok(square) => square,
    Err(e) => panic!("{}", e.as_str()),
};

/// [`with_polygons`] for constant polygons: only B's placement is an input.
pub fn with_const_polygons(f: impl FnOnce(&Polygon<f32, 4>, &Polygon<f32, 4>, &Transform<f32>)) {
    let (a, b) = (core::hint::black_box(&SQUARE), core::hint::black_box(&SQUARE));
    if let Ok(tb) = Transform::from_cos_sin(vec::<f32>(16), f32::input(18), f32::input(19)) {
        f(a, b, &tb);
    }
}

/// The firmware of one size row: where its polygons come from
/// ([`with_polygons`] or [`with_const_polygons`]) and the queries it links,
/// each run on the pair.
#[allow(unused_macros)] // not by the empty and the every-shape firmwares
macro_rules! polygon_firmware {
    ($polygons:expr => $($query:ident),+) => {
        #[common::entry]
        fn main() -> ! {
            let gjk = gjk2d::Gjk::<f32>::new();
            $polygons(|a, b, tb| {
                $(common::$query(&gjk, a, b, tb);)+
            });
            loop {}
        }
    };
}

pub fn intersects<R: Io, A: SupportMap<R> + ?Sized, B: SupportMap<R> + ?Sized>(
    gjk: &Gjk<R>,
    a: &A,
    b: &B,
    tb: &Transform<R>,
) {
    let d = gjk.intersects(a, &Transform::IDENTITY, b, tb);
    sink_u32(d.intersecting as u32 | d.iterations << 1 | (d.status as u32) << 16);
}

pub fn distance<R: Io, A: SupportMap<R> + ?Sized, B: SupportMap<R> + ?Sized>(
    gjk: &Gjk<R>,
    a: &A,
    b: &B,
    tb: &Transform<R>,
) {
    if let Some(s) = gjk.distance(a, &Transform::IDENTITY, b, tb) {
        s.distance.sink();
        sink_v::<R>(s.normal);
        sink_v::<R>(s.point_a);
        sink_v::<R>(s.point_b);
        s.error_bound.sink();
        sink_u32(s.iterations | (s.status as u32) << 16);
    }
}

pub fn penetration<R: Io, A: SupportMap<R> + ?Sized, B: SupportMap<R> + ?Sized>(
    gjk: &Gjk<R>,
    a: &A,
    b: &B,
    tb: &Transform<R>,
) {
    if let Some(p) = gjk.penetration(a, &Transform::IDENTITY, b, tb) {
        p.depth.sink();
        sink_v::<R>(p.normal);
        p.error_bound.sink();
        sink_u32(p.iterations | (p.status as u32) << 16);
    }
}

/// [`raycast`] against B, in the shape of the pair queries.
pub fn raycast_b<R: Io, A: ?Sized, B: SupportMap<R> + ?Sized>(gjk: &Gjk<R>, _: &A, b: &B, tb: &Transform<R>) {
    raycast(gjk, b, tb);
}

pub fn raycast<R: Io, S: SupportMap<R> + ?Sized>(gjk: &Gjk<R>, shape: &S, t: &Transform<R>) {
    if let Ok(ray) = Ray::new(vec::<R>(20), vec::<R>(22)) {
        let cast = gjk.raycast(&ray, R::ZERO, shape, t);
        match cast.outcome {
            RayOutcome::Hit(h) => {
                h.distance.sink();
                sink_v::<R>(h.point);
                sink_v::<R>(h.normal);
            }
            RayOutcome::Miss => sink_u32(1),
            RayOutcome::Inside => sink_u32(2),
        }
        sink_u32(cast.iterations | (cast.status as u32) << 16);
    }
}

/// B moving by the ray's direction (inputs 22 and 23) against A: the
/// linear shape cast, with what it reports at a start in contact.
pub fn cast<R: Io, A: SupportMap<R> + ?Sized, B: SupportMap<R> + ?Sized>(
    gjk: &Gjk<R>,
    a: &A,
    b: &B,
    tb: &Transform<R>,
) {
    if let Ok(motion) = Motion::new(vec::<R>(22)) {
        let cast = gjk.cast(a, &Transform::IDENTITY, b, tb, &motion);
        match cast.outcome {
            CastOutcome::Hit(h) => {
                h.fraction.sink();
                sink_v::<R>(h.normal);
                sink_v::<R>(h.point_a);
                sink_v::<R>(h.point_b);
                h.error_bound.sink();
            }
            CastOutcome::Start(s) => {
                s.penetration.depth.sink();
                sink_v::<R>(s.penetration.normal);
                sink_u32(s.separating as u32);
            }
            CastOutcome::Miss => sink_u32(1),
        }
        sink_u32(cast.iterations | (cast.status as u32) << 16);
    }
}

/// The contact manifold of A and B within a margin (input 24).
pub fn manifold<R: Io, A: SupportMap<R> + ?Sized, B: SupportMap<R> + ?Sized>(
    gjk: &Gjk<R>,
    a: &A,
    b: &B,
    tb: &Transform<R>,
) {
    if let Ok(m) = gjk.manifold(a, &Transform::IDENTITY, b, tb, R::input(24)) {
        sink_v::<R>(m.normal);
        for p in m.points() {
            sink_v::<R>(p.point);
            p.separation.sink();
            sink_u32(feature(p.id.a) | feature(p.id.b) << 16);
        }
        sink_u32(m.iterations | (m.status as u32) << 16);
    }
}

/// B moving by the ray's direction (inputs 22 and 23) and turning by
/// input 24 about its origin, against A still: the time of impact, its
/// target and tolerance inputs 25 and 26.
pub fn impact<R: Io, A: SupportMap<R> + ?Sized, B: SupportMap<R> + ?Sized>(
    gjk: &Gjk<R>,
    a: &A,
    b: &B,
    tb: &Transform<R>,
) {
    let origin = R::vector(R::ZERO, R::ZERO);
    let (Ok(sweep), Ok(config)) =
        (Sweep::new(tb, origin, vec::<R>(22), R::input(24)), ImpactConfig::new(R::input(25), R::input(26)))
    else {
        return;
    };
    let toi = gjk.time_of_impact(a, &Sweep::still(&Transform::IDENTITY), b, &sweep, &config);
    match toi.outcome {
        ImpactOutcome::Hit(h) => {
            h.time.sink();
            h.separation.sink();
            sink_v::<R>(h.normal);
            sink_v::<R>(h.point_a);
            sink_v::<R>(h.point_b);
            sink_u32(feature(h.features.a) | feature(h.features.b) << 16);
        }
        ImpactOutcome::Start(s) => {
            s.separation.sink();
            sink_v::<R>(s.normal);
        }
        ImpactOutcome::Miss => sink_u32(1),
    }
    sink_u32(toi.iterations | (toi.status as u32) << 16);
}

/// Distance and penetration warm started, two steps of the same pair (B
/// moved by input 22 between them), the cache kept between them.
pub fn cached<R: Io, A: SupportMap<R> + ?Sized, B: SupportMap<R> + ?Sized>(
    gjk: &Gjk<R>,
    a: &A,
    b: &B,
    tb: &Transform<R>,
) {
    let mut cache = PairCache::default();
    let (x, y) = R::components(tb.translation());
    let moved = Transform::new(R::vector(x + R::input(22), y + R::input(23)), R::input(24));
    for t in [Ok(*tb), moved].into_iter().flatten() {
        if let Some(s) = gjk.distance_cached(a, &Transform::IDENTITY, b, &t, &mut cache) {
            s.distance.sink();
            sink_v::<R>(s.normal);
        }
        if let Some(p) = gjk.penetration_cached(a, &Transform::IDENTITY, b, &t, &mut cache) {
            p.depth.sink();
            sink_v::<R>(p.normal);
        }
    }
}

fn feature(f: Feature) -> u32 {
    match f {
        Feature::Vertex(i) => i as u32,
        Feature::Edge(i) => 0x8000 | i as u32,
        Feature::Curve => 0xFFFF,
    }
}

/// Every shape kind, every query, through `&dyn SupportMap` (one copy of
/// each query for all pairs, as a firmware with a shape enum would do), the
/// shapes built at run time from the inputs.
pub fn everything<R: Io>() {
    let (r1, r2, w, h, angle) = (R::input(24), R::input(25), R::input(26), R::input(27), R::input(28));
    let a = Polygon::<R, 8>::new(&[vec::<R>(0), vec::<R>(2), vec::<R>(4), vec::<R>(6)]);
    let (Ok(polygon), Ok(circle), Ok(rect), Ok(tri), Ok(seg), Ok(cap), Ok(ell), Ok(half), Ok(slice), Ok(round)) = (
        &a,
        Circle::at(vec::<R>(0), r1),
        Rectangle::new(w, h),
        Triangle::new(vec::<R>(0), vec::<R>(2), vec::<R>(4)),
        Segment::new(vec::<R>(0), vec::<R>(4)),
        Capsule::new(vec::<R>(0), vec::<R>(2), r2),
        Ellipse::new(w, h),
        HalfEllipse::new(w, h),
        Slice::new(r1, angle),
        Rectangle::new(w, h).and_then(|s| Rounded::new(s, r2)),
    ) else {
        sink_u32(0xdead);
        return;
    };
    let Ok(tb) = Transform::new(vec::<R>(16), angle) else {
        sink_u32(0xdead);
        return;
    };
    every_query(&[polygon, &circle, &rect, &tri, &seg, &cap, &ell, &half, &slice, &round], &tb);
}

/// The same shapes as [`everything`], declared as constants (each shape's
/// `const` constructor, checked when the firmware is compiled), as a
/// firmware with fixed shapes keeps them: in flash, with no checks linked.
/// B's placement comes from the inputs (`Transform::from_cos_sin`), as in
/// the polygon rows.
macro_rules! fixed_shapes {
    ($R:ty, $V:ident) => {
        pub fn everything_fixed() {
            macro_rules! fixed {
                ($e:expr) => {
                    match $e {
                        Ok(shape) => shape,
                        Err(e) => panic!("{}", e.as_str()),
                    }
                };
            }
            use gjk2d::glam::$V;
            static POLYGON: Polygon<$R, 4> = fixed!(Polygon::<$R, 4>::from_array([
                $V::new(0.0, 0.0),
                $V::new(1.0, 0.0),
                $V::new(1.0, 1.0),
                $V::new(0.0, 1.0)
            ]));
            static CIRCLE: Circle<$R> = fixed!(Circle::<$R>::at_const($V::new(0.0, 0.0), 0.5));
            static RECTANGLE: Rectangle<$R> = fixed!(Rectangle::<$R>::new_const(2.0, 1.0));
            static TRIANGLE: Triangle<$R> =
                fixed!(Triangle::<$R>::new_const($V::new(0.0, 0.0), $V::new(1.0, 0.0), $V::new(1.0, 1.0)));
            static SEGMENT: Segment<$R> = fixed!(Segment::<$R>::new_const($V::new(0.0, 0.0), $V::new(1.0, 1.0)));
            static CAPSULE: Capsule<$R> = fixed!(Capsule::<$R>::new_const($V::new(0.0, 0.0), $V::new(1.0, 0.0), 0.25));
            static ELLIPSE: Ellipse<$R> = fixed!(Ellipse::<$R>::new_const(2.0, 1.0));
            static HALF_ELLIPSE: HalfEllipse<$R> = fixed!(HalfEllipse::<$R>::new_const(2.0, 1.0));
            static SLICE: Slice<$R> = fixed!(Slice::<$R>::new_const(0.5, 1.2));
            static ROUNDED: Rounded<$R, Rectangle<$R>> = fixed!(Rounded::<$R, _>::new_const(RECTANGLE, 0.25));
            let Ok(tb) = Transform::from_cos_sin(vec::<$R>(16), <$R>::input(18), <$R>::input(19)) else {
                sink_u32(0xdead);
                return;
            };
            // Through `black_box`, so no query is specialised to the shapes.
            every_query(
                core::hint::black_box(&[
                    &POLYGON,
                    &CIRCLE,
                    &RECTANGLE,
                    &TRIANGLE,
                    &SEGMENT,
                    &CAPSULE,
                    &ELLIPSE,
                    &HALF_ELLIPSE,
                    &SLICE,
                    &ROUNDED,
                ]),
                &tb,
            );
        }
    };
}

pub mod fixed_f32 {
    use super::*;
    fixed_shapes!(f32, Vec2);
}

pub mod fixed_f64 {
    use super::*;
    fixed_shapes!(f64, DVec2);
}

/// Every query on a pair picked by the inputs, B also cast against.
#[inline(always)]
fn every_query<R: Io>(shapes: &[&dyn SupportMap<R>; 10], tb: &Transform<R>) {
    let gjk = Gjk::<R>::new();
    let pick = |x: R| {
        let (mut i, mut t) = (0usize, R::ONE);
        while t <= x && i < 9 {
            i += 1;
            t += R::ONE;
        }
        shapes[i]
    };
    let (a, b) = (pick(R::input(30)), pick(R::input(31)));
    intersects(&gjk, a, b, tb);
    distance(&gjk, a, b, tb);
    penetration(&gjk, a, b, tb);
    raycast(&gjk, b, tb);
}
