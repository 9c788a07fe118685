// The body of the fuzz target, shared by `fuzz/fuzz_targets/queries.rs`
// (libFuzzer, `cargo fuzz run queries`) and `tests/fuzz_smoke.rs` (stable,
// random bytes, run by `cargo test`). Any input: constructors may refuse it
// with an error but never panic; every query on what they accept (the linear
// cast and the time of impact too) terminates and gives finite output.

use gjk2d::glam::{DVec2, Vec2};
use gjk2d::*;

/// Reads floats and selectors from the fuzzer's bytes; zeros when exhausted.
pub struct Bytes<'a>(&'a [u8]);

impl<'a> Bytes<'a> {
    pub fn new(data: &'a [u8]) -> Self {
        Self(data)
    }
    fn take<const K: usize>(&mut self) -> [u8; K] {
        let mut out = [0u8; K];
        let n = K.min(self.0.len());
        out[..n].copy_from_slice(&self.0[..n]);
        self.0 = &self.0[n..];
        out
    }
    fn byte(&mut self) -> u8 {
        self.take::<1>()[0]
    }
    /// Mostly raw bit patterns (NaN, inf, subnormals, huge), sometimes
    /// small integers so that valid shapes are common too.
    fn f64(&mut self) -> f64 {
        match self.byte() % 8 {
            0 => f64::from_le_bytes(self.take::<8>()),
            1 => f32::from_le_bytes(self.take::<4>()) as f64,
            _ => (self.byte() as i8) as f64 / 8.0,
        }
    }
}

macro_rules! fuzz_precision {
    ($name:ident, $r:ty, $vec:ident) => {
        /// Returns how many (pair queries, ray casts) ran.
        pub fn $name(bytes: &mut Bytes) -> (u32, u32) {
            let mut ran = (0, 0);
            type R = $r;
            let mut f = || bytes.f64() as R;
            let values: Vec<R> = (0..40).map(|_| f()).collect();
            let mut k = 0;
            let mut next = || {
                let v = values[k % values.len()];
                k += 1;
                v
            };
            let shapes: Vec<Box<dyn SupportMap<R>>> = (0..2)
                .filter_map(|i| {
                    let kind = (values[i].abs() * 8.0) as u64 as u8 % 11;
                    build::<R>(kind, &mut next).map(|s| s as Box<dyn SupportMap<R>>)
                })
                .collect();
            let transforms: Vec<Transform<R>> = (0..2)
                .filter_map(|_| Transform::new($vec::new(next(), next()), next()).ok())
                .collect();
            let mut gjk = Gjk::<R>::new();
            let _ = gjk.config.set_max_distance_iterations((next().abs() as u32).clamp(0, 200));
            let _ = gjk.config.set_distance_epsilon(next());
            if let (Some(a), Some(b), Some(ta), Some(tb)) = (shapes.first(), shapes.get(1), transforms.first(), transforms.get(1)) {
                ran.0 += 1;
                let d = gjk.intersects(&**a, ta, &**b, tb);
                assert!(d.iterations <= gjk.config.max_detect_iterations() + 1);
                if let Some(s) = gjk.distance(&**a, ta, &**b, tb) {
                    for x in [s.distance, s.error_bound, s.normal.x, s.normal.y, s.point_a.x, s.point_a.y, s.point_b.x, s.point_b.y] {
                        assert!(x.is_finite(), "non-finite separation {s:?}");
                    }
                    assert!(s.distance >= 0.0);
                }
                if let Some(p) = gjk.penetration(&**a, ta, &**b, tb) {
                    for x in [p.depth, p.error_bound, p.normal.x, p.normal.y] {
                        assert!(x.is_finite(), "non-finite penetration {p:?}");
                    }
                    assert!(p.depth >= 0.0);
                }
                // A margin from the values already read (any value: NaN,
                // infinite and negative ones are errors), so the ray below
                // reads what it read before manifolds were fuzzed.
                let margin = values[2];
                match gjk.manifold(&**a, ta, &**b, tb, margin) {
                    Ok(m) => {
                        assert!(m.len <= 2 && margin >= 0.0, "{m:?}");
                        for p in m.points() {
                            for x in [p.point.x, p.point.y, p.separation] {
                                assert!(x.is_finite(), "non-finite manifold {m:?}");
                            }
                            assert!(p.separation <= margin, "{m:?}");
                        }
                    }
                    Err(e) => assert!(!(margin >= 0.0 && margin.is_finite() && margin <= R::MAX_COORDINATE), "{e}"),
                }
            }
            if let (Some(s), Some(t)) = (shapes.first(), transforms.first()) {
                if let Ok(ray) = Ray::new($vec::new(next(), next()), $vec::new(next(), next())) {
                    ran.1 += 1;
                    for closed in [true, false] {
                        gjk.closed_form_rays = closed;
                        let cast = gjk.raycast(&ray, next(), &**s, t);
                        if let Some(h) = cast.hit() {
                            for x in [h.distance, h.point.x, h.point.y, h.normal.x, h.normal.y] {
                                assert!(x.is_finite(), "non-finite ray hit {cast:?}");
                            }
                        }
                    }
                }
            }
            // Last, so every earlier query reads the values it always read
            // (the kept crashes replay as they were found).
            if let (Some(a), Some(b), Some(ta), Some(tb)) = (shapes.first(), shapes.get(1), transforms.first(), transforms.get(1)) {
                if let Ok(motion) = Motion::new($vec::new(next(), next())) {
                    let cast = gjk.cast(&**a, ta, &**b, tb, &motion);
                    if let Some(h) = cast.hit() {
                        for x in [h.distance, h.fraction, h.error_bound, h.normal.x, h.normal.y, h.point_a.x, h.point_b.y] {
                            assert!(x.is_finite(), "non-finite cast hit {cast:?}");
                        }
                        assert!((0.0..=1.0).contains(&h.fraction));
                    }
                }
                // After the cast, for the same reason: both shapes moving and
                // turning, to a target.
                let mut sweep = |t: &Transform<R>| Sweep::new(t, $vec::new(next(), next()), $vec::new(next(), next()), next());
                let (sa, sb) = (sweep(ta), sweep(tb));
                let config = ImpactConfig::new(next(), next());
                if let (Ok(sa), Ok(sb), Ok(config)) = (sa, sb, config) {
                    let toi = gjk.time_of_impact(&**a, &sa, &**b, &sb, &config);
                    match toi.outcome {
                        ImpactOutcome::Hit(h) => {
                            for x in [h.time, h.separation, h.normal.x, h.normal.y, h.point_a.x, h.point_a.y, h.point_b.x, h.point_b.y] {
                                assert!(x.is_finite(), "non-finite time of impact {toi:?}");
                            }
                            assert!((0.0..=1.0).contains(&h.time) && toi.iterations <= config.max_iterations(), "{toi:?}");
                        }
                        ImpactOutcome::Start(s) => {
                            for x in [s.separation, s.normal.x, s.normal.y] {
                                assert!(x.is_finite(), "non-finite time of impact {toi:?}");
                            }
                        }
                        ImpactOutcome::Miss => assert!(toi.iterations <= config.max_iterations(), "{toi:?}"),
                    }
                }
            }
            ran
        }
    };
}

fn build<R: Real>(kind: u8, next: &mut impl FnMut() -> R) -> Option<Box<dyn SupportMap<R>>> {
    fn v<R: Real>(next: &mut impl FnMut() -> R) -> R::Vector {
        R::vector(next(), next())
    }
    Some(match kind {
        0 => Box::new(Circle::at(v(next), next()).ok()?),
        1 => {
            let n = 3 + (next().abs().to_f64() as usize % 8);
            let pts: Vec<R::Vector> = (0..n).map(|_| v(next)).collect();
            Box::new(Polygon::<R, 12>::new(&pts).ok()?)
        }
        2 => Box::new(Rectangle::new(next(), next()).ok()?),
        3 => Box::new(Triangle::new(v(next), v(next), v(next)).ok()?),
        4 => Box::new(Segment::new(v(next), v(next)).ok()?),
        5 => Box::new(Capsule::new(v(next), v(next), next()).ok()?),
        6 => Box::new(Ellipse::new(next(), next()).ok()?),
        7 => Box::new(HalfEllipse::new(next(), next()).ok()?),
        8 => Box::new(Slice::new(next(), next()).ok()?),
        9 => Box::new(Capsule::from_size(next(), next()).ok()?),
        _ => Box::new(Rounded::new(Polygon::<R, 8>::regular(5, next()).ok()?, next()).ok()?),
    })
}

fuzz_precision!(fuzz_f32, f32, Vec2);
fuzz_precision!(fuzz_f64, f64, DVec2);

/// One fuzz input, both precisions: how many (pair queries, ray casts) ran.
pub fn fuzz_one(data: &[u8]) -> (u32, u32) {
    let a = fuzz_f32(&mut Bytes::new(data));
    let b = fuzz_f64(&mut Bytes::new(data));
    (a.0 + b.0, a.1 + b.1)
}
