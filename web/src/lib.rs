//! gjk2d in the browser: a plain C ABI over wasm32 memory, no wasm-bindgen.
//!
//! JavaScript writes shapes into the *scene* buffer (`scene_ptr`, `f64`s,
//! `STRIDE` per shape), calls `build(count)` to construct them in both
//! precisions, then runs queries on shapes `i` and `j`. Every query returns a
//! small integer and writes its numbers into the *out* buffer (`out_ptr`,
//! `f64`s: an `f32` result widens to `f64` exactly, so the page sees the very
//! bits the `f32` query computed).
//!
//! Scene record (24 `f64`s): `[kind, x, y, angle, p0, p1, ...]`
//!
//! | kind | shape         | params                                   |
//! |------|---------------|------------------------------------------|
//! | 1    | circle        | radius                                   |
//! | 2    | polygon       | n (3..=8), x0, y0, ... x(n-1), y(n-1)     |
//! | 3    | rectangle     | width, height                            |
//! | 4    | triangle      | ax, ay, bx, by, cx, cy                   |
//! | 5    | segment       | ax, ay, bx, by                           |
//! | 6    | capsule       | width, height (`Capsule::from_size`)     |
//! | 7    | ellipse       | width, height                            |
//! | 8    | half-ellipse  | width, height                            |
//! | 9    | slice         | radius, theta                            |
//! | 10   | rounded poly  | n, x0, y0, ... (16 slots), radius at p17 |
//!
//! Outputs (`out`), by query:
//! - `intersects{32,64}(i, j)` -> 1/0 (-1: no such shape); out = [hit, iterations, status]
//! - `penetration{32,64}(i, j)` -> 1 overlap / 0 apart; out = [nx, ny, depth, error_bound, iterations, status]
//! - `distance{32,64}(i, j)` -> 1 apart / 0 overlap; out = [distance, nx, ny, ax, ay, bx, by, error_bound, iterations, status]
//! - `raycast{32,64}(i, ox, oy, dx, dy, max)` -> 0 miss, 1 hit, 2 inside (-1: bad shape or ray);
//!   out = [distance, px, py, nx, ny, iterations, status]
//! - `cast{32,64}(i, j, mx, my)`: shape `j` moving by (mx, my) against shape `i` -> 0 miss,
//!   1 hit, 2 touching or overlapping at the start (-1: bad shape or motion); out = hit:
//!   [fraction, distance, nx, ny, ax, ay, bx, by, error_bound, iterations, status], start:
//!   [nx, ny, depth, separating, iterations, status], miss: [iterations, status]
//! - `manifold{32,64}(i, j, margin)` -> the number of contact points (0 to 2; -1: bad shape or
//!   margin); out = [nx, ny, iterations, status, then per point px, py, separation, id_a, id_b],
//!   a feature id as a number: vertex k -> k, edge k -> 65536 + k, a curve -> -1
//!
//! Status codes: 0 converged, 1 iteration limit, 2 capacity limit.
//!
//! Other exports: `scene_ptr`, `out_ptr`, `max_shapes`, `stride`, `build`.
//!
//! Features: `f32` and `f64` (both by default; either alone shows what one
//! precision costs) and `golden`, which adds `golden_hash` (and its `_f32` and
//! `_f64` halves): the determinism batch of `tests/golden_batch.rs`, checked
//! against `tests/golden_hash.txt` by `web/test/golden.mjs`. The page's module
//! is built without it.
//!
//! Shapes reach the queries as `&dyn SupportMap`: each query is compiled once
//! per precision rather than once per pair of shape kinds.
#![no_std]

#[cfg(not(any(feature = "f32", feature = "f64")))]
compile_error!("enable the f32 feature, the f64 feature, or both (the default)");

use core::cell::UnsafeCell;
use core::mem::MaybeUninit;
use gjk2d::{
    Capsule, CastOutcome, Circle, Ellipse, Error, Feature, Gjk, HalfEllipse, Motion, Polygon, Ray, RayOutcome, Real,
    Rectangle, Rounded, Segment, Slice, Status, SupportMap, Transform, Triangle,
};

/// Most shapes a scene holds.
pub const MAX_SHAPES: usize = 16;
/// `f64`s per scene record.
pub const STRIDE: usize = 24;
/// Most polygon vertices.
pub const MAX_VERTICES: usize = 8;
const OUT_LEN: usize = 16;

#[cfg(not(test))]
#[panic_handler]
fn panic(_: &core::panic::PanicInfo) -> ! {
    #[cfg(target_arch = "wasm32")]
    core::arch::wasm32::unreachable();
    #[cfg(not(target_arch = "wasm32"))]
    loop {}
}

/// A static the single wasm thread owns.
struct Global<T>(UnsafeCell<T>);
// SAFETY: wasm32-unknown-unknown without threads: one thread touches these.
unsafe impl<T> Sync for Global<T> {}

static SCENE: Global<[f64; MAX_SHAPES * STRIDE]> = Global(UnsafeCell::new([0.0; MAX_SHAPES * STRIDE]));
static OUT: Global<[f64; OUT_LEN]> = Global(UnsafeCell::new([0.0; OUT_LEN]));
// Uninitialised bodies and `false` flags: the stores live in .bss and cost no
// bytes of the module (an initialised store would be 6 KB of data).
#[cfg(feature = "f32")]
static STORE32: Global<Store<f32>> = Global(UnsafeCell::new(Store::EMPTY));
#[cfg(feature = "f64")]
static STORE64: Global<Store<f64>> = Global(UnsafeCell::new(Store::EMPTY));

enum Shape<R: Real> {
    Circle(Circle<R>),
    Polygon(Polygon<R, MAX_VERTICES>),
    Rectangle(Rectangle<R>),
    Triangle(Triangle<R>),
    Segment(Segment<R>),
    Capsule(Capsule<R>),
    Ellipse(Ellipse<R>),
    HalfEllipse(HalfEllipse<R>),
    Slice(Slice<R>),
    Rounded(Rounded<R, Polygon<R, MAX_VERTICES>>),
}

impl<R: Real> Shape<R> {
    /// One `&dyn` for every kind: each query is compiled once per precision,
    /// not once per pair of kinds, which is what keeps the module small.
    fn as_dyn(&self) -> &dyn SupportMap<R> {
        match self {
            Shape::Circle(s) => s,
            Shape::Polygon(s) => s,
            Shape::Rectangle(s) => s,
            Shape::Triangle(s) => s,
            Shape::Segment(s) => s,
            Shape::Capsule(s) => s,
            Shape::Ellipse(s) => s,
            Shape::HalfEllipse(s) => s,
            Shape::Slice(s) => s,
            Shape::Rounded(s) => s,
        }
    }
}

struct Body<R: Real> {
    shape: Shape<R>,
    transform: Transform<R>,
}

struct Store<R: Real> {
    bodies: [MaybeUninit<Body<R>>; MAX_SHAPES],
    /// `bodies[i]` is initialised.
    built: [bool; MAX_SHAPES],
}

impl<R: Real> Store<R> {
    const EMPTY: Self = Self { bodies: [const { MaybeUninit::uninit() }; MAX_SHAPES], built: [false; MAX_SHAPES] };

    fn get(&self, i: u32) -> Option<(&dyn SupportMap<R>, &Transform<R>)> {
        let i = i as usize;
        if !*self.built.get(i)? {
            return None;
        }
        // SAFETY: `built[i]` says `bodies[i]` was written by `build_into`.
        let body = unsafe { self.bodies[i].assume_init_ref() };
        Some((body.shape.as_dyn(), &body.transform))
    }
}

fn polygon<R: Real>(p: &[f64]) -> Result<Polygon<R, MAX_VERTICES>, Error> {
    let n = (p[0] as usize).min(MAX_VERTICES);
    let mut pts = [R::vector(R::ZERO, R::ZERO); MAX_VERTICES];
    for (k, v) in pts.iter_mut().enumerate().take(n) {
        *v = vector::<R>(p[1 + 2 * k], p[2 + 2 * k]);
    }
    Polygon::new(&pts[..n])
}

fn vector<R: Real>(x: f64, y: f64) -> R::Vector {
    R::vector(R::from_f64(x), R::from_f64(y))
}

fn build_body<R: Real>(record: &[f64]) -> Result<Body<R>, Error> {
    let f = |k: usize| R::from_f64(record[4 + k]);
    let v = |k: usize| vector::<R>(record[4 + k], record[5 + k]);
    let p = &record[4..];
    let shape = match record[0] as u32 {
        1 => Shape::Circle(Circle::new(f(0))?),
        2 => Shape::Polygon(polygon(p)?),
        3 => Shape::Rectangle(Rectangle::new(f(0), f(1))?),
        4 => Shape::Triangle(Triangle::new(v(0), v(2), v(4))?),
        5 => Shape::Segment(Segment::new(v(0), v(2))?),
        6 => Shape::Capsule(Capsule::from_size(f(0), f(1))?),
        7 => Shape::Ellipse(Ellipse::new(f(0), f(1))?),
        8 => Shape::HalfEllipse(HalfEllipse::new(f(0), f(1))?),
        9 => Shape::Slice(Slice::new(f(0), f(1))?),
        10 => Shape::Rounded(Rounded::new(polygon(p)?, f(17))?),
        _ => return Err(Error::NonFinite),
    };
    let transform = Transform::new(vector::<R>(record[1], record[2]), R::from_f64(record[3]))?;
    Ok(Body { shape, transform })
}

fn build_into<R: Real>(store: &mut Store<R>, scene: &[f64], count: usize) -> u32 {
    let mut failed = 0u32;
    for i in 0..MAX_SHAPES {
        // Bodies hold no heap and need no drop: overwriting is enough.
        store.built[i] = false;
        if i < count {
            match build_body(&scene[i * STRIDE..(i + 1) * STRIDE]) {
                Ok(body) => {
                    store.bodies[i].write(body);
                    store.built[i] = true;
                }
                Err(_) => failed |= 1 << i,
            }
        }
    }
    failed
}

fn out() -> &'static mut [f64; OUT_LEN] {
    // SAFETY: single-threaded; no other reference to OUT is alive during an export.
    unsafe { &mut *OUT.0.get() }
}

#[cfg(feature = "f32")]
fn store32() -> &'static Store<f32> {
    // SAFETY: single-threaded; `build` is the only writer and never runs during a query.
    unsafe { &*STORE32.0.get() }
}

#[cfg(feature = "f64")]
fn store64() -> &'static Store<f64> {
    // SAFETY: as for `store32`.
    unsafe { &*STORE64.0.get() }
}

fn status_code(s: Status) -> f64 {
    match s {
        Status::Converged => 0.0,
        Status::IterationLimit => 1.0,
        Status::CapacityLimit => 2.0,
    }
}

fn put_vec<R: Real>(o: &mut [f64], at: usize, v: R::Vector) {
    let (x, y) = R::components(v);
    o[at] = x.to_f64();
    o[at + 1] = y.to_f64();
}

fn intersects<R: Real>(store: &Store<R>, i: u32, j: u32) -> i32 {
    let (Some((a, ta)), Some((b, tb))) = (store.get(i), store.get(j)) else {
        return -1;
    };
    let d = Gjk::<R>::new().intersects(a, ta, b, tb);
    let o = out();
    o[0] = d.intersecting as u32 as f64;
    o[1] = d.iterations as f64;
    o[2] = status_code(d.status);
    d.intersecting as i32
}

fn penetration<R: Real>(store: &Store<R>, i: u32, j: u32) -> i32 {
    let (Some((a, ta)), Some((b, tb))) = (store.get(i), store.get(j)) else {
        return -1;
    };
    let o = out();
    match Gjk::<R>::new().penetration(a, ta, b, tb) {
        Some(p) => {
            put_vec::<R>(o, 0, p.normal);
            o[2] = p.depth.to_f64();
            o[3] = p.error_bound.to_f64();
            o[4] = p.iterations as f64;
            o[5] = status_code(p.status);
            1
        }
        None => 0,
    }
}

fn distance<R: Real>(store: &Store<R>, i: u32, j: u32) -> i32 {
    let (Some((a, ta)), Some((b, tb))) = (store.get(i), store.get(j)) else {
        return -1;
    };
    let o = out();
    match Gjk::<R>::new().distance(a, ta, b, tb) {
        Some(s) => {
            o[0] = s.distance.to_f64();
            put_vec::<R>(o, 1, s.normal);
            put_vec::<R>(o, 3, s.point_a);
            put_vec::<R>(o, 5, s.point_b);
            o[7] = s.error_bound.to_f64();
            o[8] = s.iterations as f64;
            o[9] = status_code(s.status);
            1
        }
        None => 0,
    }
}

fn raycast<R: Real>(store: &Store<R>, i: u32, ox: f64, oy: f64, dx: f64, dy: f64, max: f64) -> i32 {
    let Some((s, t)) = store.get(i) else {
        return -1;
    };
    let Ok(ray) = Ray::new(vector::<R>(ox, oy), vector::<R>(dx, dy)) else {
        return -1;
    };
    let cast = Gjk::<R>::new().raycast(&ray, R::from_f64(max), s, t);
    let o = out();
    o[5] = cast.iterations as f64;
    o[6] = status_code(cast.status);
    match cast.outcome {
        RayOutcome::Hit(h) => {
            o[0] = h.distance.to_f64();
            put_vec::<R>(o, 1, h.point);
            put_vec::<R>(o, 3, h.normal);
            1
        }
        RayOutcome::Miss => 0,
        RayOutcome::Inside => 2,
    }
}

fn cast<R: Real>(store: &Store<R>, i: u32, j: u32, mx: f64, my: f64) -> i32 {
    let (Some((a, ta)), Some((b, tb))) = (store.get(i), store.get(j)) else {
        return -1;
    };
    let Ok(motion) = Motion::new(vector::<R>(mx, my)) else {
        return -1;
    };
    let cast = Gjk::<R>::new().cast(a, ta, b, tb, &motion);
    let o = out();
    let (iterations, status) = (cast.iterations as f64, status_code(cast.status));
    match cast.outcome {
        CastOutcome::Hit(h) => {
            o[0] = h.fraction.to_f64();
            o[1] = h.distance.to_f64();
            put_vec::<R>(o, 2, h.normal);
            put_vec::<R>(o, 4, h.point_a);
            put_vec::<R>(o, 6, h.point_b);
            o[8] = h.error_bound.to_f64();
            o[9] = iterations;
            o[10] = status;
            1
        }
        CastOutcome::Start(start) => {
            put_vec::<R>(o, 0, start.penetration.normal);
            o[2] = start.penetration.depth.to_f64();
            o[3] = start.separating as u32 as f64;
            o[4] = iterations;
            o[5] = status;
            2
        }
        CastOutcome::Miss => {
            o[0] = iterations;
            o[1] = status;
            0
        }
    }
}

fn feature_code(f: Feature) -> f64 {
    match f {
        Feature::Vertex(k) => k as f64,
        Feature::Edge(k) => 65536.0 + k as f64,
        Feature::Curve => -1.0,
    }
}

fn manifold<R: Real>(store: &Store<R>, i: u32, j: u32, margin: f64) -> i32 {
    let (Some((a, ta)), Some((b, tb))) = (store.get(i), store.get(j)) else {
        return -1;
    };
    let Ok(m) = Gjk::<R>::new().manifold(a, ta, b, tb, R::from_f64(margin)) else {
        return -1;
    };
    let o = out();
    put_vec::<R>(o, 0, m.normal);
    o[2] = m.iterations as f64;
    o[3] = status_code(m.status);
    for (k, p) in m.points().iter().enumerate() {
        put_vec::<R>(o, 4 + 5 * k, p.point);
        o[6 + 5 * k] = p.separation.to_f64();
        o[7 + 5 * k] = feature_code(p.id.a);
        o[8 + 5 * k] = feature_code(p.id.b);
    }
    m.points().len() as i32
}

/// The scene buffer: `MAX_SHAPES * STRIDE` `f64`s.
#[unsafe(no_mangle)]
pub extern "C" fn scene_ptr() -> *mut f64 {
    SCENE.0.get().cast()
}

/// The output buffer: 16 `f64`s.
#[unsafe(no_mangle)]
pub extern "C" fn out_ptr() -> *mut f64 {
    OUT.0.get().cast()
}

#[unsafe(no_mangle)]
pub extern "C" fn max_shapes() -> u32 {
    MAX_SHAPES as u32
}

#[unsafe(no_mangle)]
pub extern "C" fn stride() -> u32 {
    STRIDE as u32
}

/// Builds the first `count` scene records in f32 and f64. Returns a bit
/// mask of the shapes whose parameters the crate rejected (0: all built);
/// a rejected shape makes its queries return -1.
#[unsafe(no_mangle)]
pub extern "C" fn build(count: u32) -> u32 {
    // SAFETY: single-threaded; no query runs while the stores are rebuilt.
    let scene = unsafe { &*SCENE.0.get() };
    let count = (count as usize).min(MAX_SHAPES);
    let mut failed = 0;
    #[cfg(feature = "f32")]
    {
        // SAFETY: as above.
        failed |= build_into(unsafe { &mut *STORE32.0.get() }, scene, count);
    }
    #[cfg(feature = "f64")]
    {
        // SAFETY: as above.
        failed |= build_into(unsafe { &mut *STORE64.0.get() }, scene, count);
    }
    failed
}

#[cfg(feature = "f32")]
#[unsafe(no_mangle)]
pub extern "C" fn intersects32(i: u32, j: u32) -> i32 {
    intersects(store32(), i, j)
}
#[cfg(feature = "f64")]
#[unsafe(no_mangle)]
pub extern "C" fn intersects64(i: u32, j: u32) -> i32 {
    intersects(store64(), i, j)
}
#[cfg(feature = "f32")]
#[unsafe(no_mangle)]
pub extern "C" fn penetration32(i: u32, j: u32) -> i32 {
    penetration(store32(), i, j)
}
#[cfg(feature = "f64")]
#[unsafe(no_mangle)]
pub extern "C" fn penetration64(i: u32, j: u32) -> i32 {
    penetration(store64(), i, j)
}
#[cfg(feature = "f32")]
#[unsafe(no_mangle)]
pub extern "C" fn distance32(i: u32, j: u32) -> i32 {
    distance(store32(), i, j)
}
#[cfg(feature = "f64")]
#[unsafe(no_mangle)]
pub extern "C" fn distance64(i: u32, j: u32) -> i32 {
    distance(store64(), i, j)
}
#[cfg(feature = "f32")]
#[unsafe(no_mangle)]
pub extern "C" fn raycast32(i: u32, ox: f64, oy: f64, dx: f64, dy: f64, max: f64) -> i32 {
    raycast(store32(), i, ox, oy, dx, dy, max)
}
#[cfg(feature = "f64")]
#[unsafe(no_mangle)]
pub extern "C" fn raycast64(i: u32, ox: f64, oy: f64, dx: f64, dy: f64, max: f64) -> i32 {
    raycast(store64(), i, ox, oy, dx, dy, max)
}
#[cfg(feature = "f32")]
#[unsafe(no_mangle)]
pub extern "C" fn cast32(i: u32, j: u32, mx: f64, my: f64) -> i32 {
    cast(store32(), i, j, mx, my)
}
#[cfg(feature = "f64")]
#[unsafe(no_mangle)]
pub extern "C" fn cast64(i: u32, j: u32, mx: f64, my: f64) -> i32 {
    cast(store64(), i, j, mx, my)
}
#[cfg(feature = "f32")]
#[unsafe(no_mangle)]
pub extern "C" fn manifold32(i: u32, j: u32, margin: f64) -> i32 {
    manifold(store32(), i, j, margin)
}
#[cfg(feature = "f64")]
#[unsafe(no_mangle)]
pub extern "C" fn manifold64(i: u32, j: u32, margin: f64) -> i32 {
    manifold(store64(), i, j, margin)
}

/// The determinism batch shared with the host test and the firmware.
#[cfg(feature = "golden")]
mod golden {
    include!("../../tests/golden_batch.rs");
}

/// The FNV-1a hash of the fixed query batch, f32 then f64: must equal
/// tests/golden_hash.txt (web/test/golden.mjs checks it under Node).
#[cfg(feature = "golden")]
#[unsafe(no_mangle)]
pub extern "C" fn golden_hash() -> u64 {
    golden::golden_hash()
}

/// The f32 half of the batch alone.
#[cfg(feature = "golden")]
#[unsafe(no_mangle)]
pub extern "C" fn golden_hash_f32() -> u64 {
    golden::golden_hash_f32()
}

/// The f64 half of the batch alone.
#[cfg(feature = "golden")]
#[unsafe(no_mangle)]
pub extern "C" fn golden_hash_f64() -> u64 {
    golden::golden_hash_f64()
}
