// The determinism batch: a fixed set of queries of every kind, on every shape,
// in f32 and f64, hashed bit-exactly (FNV-1a over the bits of every output
// float, verdict, iteration count and status).
//
// Shared by `include!`: tests/golden.rs (host), firmware/src/lib.rs (Cortex-M
// under QEMU) and the wasm check. It must stay self-contained and no_std: no
// inner attributes, no `use` of anything but `gjk2d`, no allocation, no std.
// The expected hash is committed in tests/golden_hash.txt; a change of any
// output bit of any query changes it (intentionally: update the file then).

/// FNV-1a, 64 bits.
pub struct GoldenHasher(pub u64);

impl Default for GoldenHasher {
    fn default() -> Self {
        Self::new()
    }
}

impl GoldenHasher {
    pub const OFFSET: u64 = 0xcbf2_9ce4_8422_2325;
    pub const PRIME: u64 = 0x0000_0100_0000_01b3;

    pub fn new() -> Self {
        GoldenHasher(Self::OFFSET)
    }
    pub fn word(&mut self, w: u64) {
        for b in w.to_le_bytes() {
            self.0 ^= b as u64;
            self.0 = self.0.wrapping_mul(Self::PRIME);
        }
    }
    /// The float's own bits: f32 values are widened to f64 first, which is
    /// exact, so an f32 hashes the same on every machine.
    pub fn real<R: gjk2d::Real>(&mut self, x: R) {
        self.word(x.to_f64().to_bits());
    }
    pub fn vector<R: gjk2d::Real>(&mut self, v: R::Vector) {
        let (x, y) = R::components(v);
        self.real(x);
        self.real(y);
    }
    pub fn status(&mut self, s: gjk2d::Status) {
        self.word(match s {
            gjk2d::Status::Converged => 1,
            gjk2d::Status::IterationLimit => 2,
            gjk2d::Status::CapacityLimit => 3,
        });
    }
}

/// xorshift64*: a fixed, portable sequence of pseudo-random numbers.
pub struct GoldenRng(pub u64);

impl GoldenRng {
    pub fn next_u64(&mut self) -> u64 {
        let mut x = self.0;
        x ^= x >> 12;
        x ^= x << 25;
        x ^= x >> 27;
        self.0 = x;
        x.wrapping_mul(0x2545_f491_4f6c_dd1d)
    }
    /// Uniform in [lo, hi), computed in f64 and rounded once to R.
    pub fn range<R: gjk2d::Real>(&mut self, lo: f64, hi: f64) -> R {
        let unit = (self.next_u64() >> 11) as f64 * (1.0 / (1u64 << 53) as f64);
        R::from_f64(lo + (hi - lo) * unit)
    }
}

/// Every shape kind of gjk2d, one value each.
pub enum GoldenShape<R: gjk2d::Real> {
    Circle(gjk2d::Circle<R>),
    Polygon(gjk2d::Polygon<R, 8>),
    Rectangle(gjk2d::Rectangle<R>),
    Triangle(gjk2d::Triangle<R>),
    Segment(gjk2d::Segment<R>),
    Capsule(gjk2d::Capsule<R>),
    Ellipse(gjk2d::Ellipse<R>),
    HalfEllipse(gjk2d::HalfEllipse<R>),
    Slice(gjk2d::Slice<R>),
    Rounded(gjk2d::Rounded<R, gjk2d::Rectangle<R>>),
}

impl<R: gjk2d::Real> GoldenShape<R> {
    pub const KINDS: u64 = 10;

    pub fn as_support(&self) -> &dyn gjk2d::SupportMap<R> {
        match self {
            GoldenShape::Circle(s) => s,
            GoldenShape::Polygon(s) => s,
            GoldenShape::Rectangle(s) => s,
            GoldenShape::Triangle(s) => s,
            GoldenShape::Segment(s) => s,
            GoldenShape::Capsule(s) => s,
            GoldenShape::Ellipse(s) => s,
            GoldenShape::HalfEllipse(s) => s,
            GoldenShape::Slice(s) => s,
            GoldenShape::Rounded(s) => s,
        }
    }

    /// Shape `kind` (0..KINDS) with sizes drawn from `rng`. Every draw is
    /// valid; an error (which would be a bug) hashes as a distinct value.
    pub fn make(kind: u64, rng: &mut GoldenRng) -> Result<Self, gjk2d::Error> {
        let v = |x: R, y: R| R::vector(x, y);
        Ok(match kind {
            0 => GoldenShape::Circle(gjk2d::Circle::at(
                v(rng.range(-0.2, 0.2), rng.range(-0.2, 0.2)),
                rng.range(0.2, 1.0),
            )?),
            1 => {
                let count = 3 + (rng.next_u64() % 6) as usize;
                GoldenShape::Polygon(gjk2d::Polygon::regular(count, rng.range(0.3, 1.2))?)
            }
            2 => GoldenShape::Rectangle(gjk2d::Rectangle::new(rng.range(0.2, 2.0), rng.range(0.2, 2.0))?),
            3 => GoldenShape::Triangle(gjk2d::Triangle::new(
                v(rng.range(-1.0, -0.2), rng.range(-1.0, -0.2)),
                v(rng.range(0.2, 1.0), rng.range(-1.0, 0.0)),
                v(rng.range(-0.5, 0.5), rng.range(0.3, 1.0)),
            )?),
            4 => GoldenShape::Segment(gjk2d::Segment::new(
                v(rng.range(-1.0, -0.1), rng.range(-1.0, 1.0)),
                v(rng.range(0.1, 1.0), rng.range(-1.0, 1.0)),
            )?),
            5 => GoldenShape::Capsule(gjk2d::Capsule::new(
                v(rng.range(-1.0, -0.1), rng.range(-0.5, 0.5)),
                v(rng.range(0.1, 1.0), rng.range(-0.5, 0.5)),
                rng.range(0.1, 0.6),
            )?),
            6 => GoldenShape::Ellipse(gjk2d::Ellipse::new(rng.range(0.4, 2.5), rng.range(0.4, 2.5))?),
            7 => GoldenShape::HalfEllipse(gjk2d::HalfEllipse::new(rng.range(0.4, 2.5), rng.range(0.2, 1.2))?),
            8 => GoldenShape::Slice(gjk2d::Slice::new(rng.range(0.4, 1.4), rng.range(0.3, 3.1))?),
            _ => GoldenShape::Rounded(gjk2d::Rounded::new(
                gjk2d::Rectangle::new(rng.range(0.2, 1.5), rng.range(0.2, 1.5))?,
                rng.range(0.05, 0.4),
            )?),
        })
    }
}

/// Hashes `PAIRS` queries of each kind in precision R into `h`.
pub fn golden_batch<R: gjk2d::Real>(h: &mut GoldenHasher, seed: u64) {
    const PAIRS: u32 = 100;
    let mut rng = GoldenRng(seed);
    let gjk = gjk2d::Gjk::<R>::new();
    for pair in 0..PAIRS {
        // Every ordered pair of kinds comes up over the batch (kind a runs
        // through all kinds, kind b is drawn).
        let ka = pair as u64 % GoldenShape::<R>::KINDS;
        let kb = rng.next_u64() % GoldenShape::<R>::KINDS;
        let (a, b) = match (GoldenShape::<R>::make(ka, &mut rng), GoldenShape::<R>::make(kb, &mut rng)) {
            (Ok(a), Ok(b)) => (a, b),
            _ => {
                h.word(0xbad0_5a9e);
                continue;
            }
        };
        let ta = gjk2d::Transform::new(R::vector(rng.range(-1.0, 1.0), rng.range(-1.0, 1.0)), rng.range(-3.2, 3.2));
        let tb = gjk2d::Transform::new(R::vector(rng.range(-2.0, 2.0), rng.range(-2.0, 2.0)), rng.range(-3.2, 3.2));
        let (ta, tb) = match (ta, tb) {
            (Ok(ta), Ok(tb)) => (ta, tb),
            _ => {
                h.word(0xbad0_7a9e);
                continue;
            }
        };
        // Rays from around the pair aimed near B: mostly hits, some misses.
        let (ox, oy): (R, R) = (rng.range(-4.0, 4.0), rng.range(-4.0, 4.0));
        let (bx, by) = R::components(tb.translation());
        let (jx, jy): (R, R) = (rng.range(-1.0, 1.0), rng.range(-1.0, 1.0));
        let ray = match gjk2d::Ray::new(R::vector(ox, oy), R::vector(bx - ox + jx, by - oy + jy)) {
            Ok(ray) => ray,
            Err(_) => {
                h.word(0xbad0_4a9e);
                continue;
            }
        };
        // Zero or negative: unbounded.
        let max_length: R = rng.range(-2.0, 8.0);
        let (a, b) = (a.as_support(), b.as_support());

        let d = gjk.intersects(a, &ta, b, &tb);
        h.word(d.intersecting as u64);
        h.word(d.iterations as u64);
        h.status(d.status);

        match gjk.distance(a, &ta, b, &tb) {
            None => h.word(0xd15_0000),
            Some(s) => {
                h.word(0xd15_0001);
                h.real(s.distance);
                h.vector::<R>(s.normal);
                h.vector::<R>(s.point_a);
                h.vector::<R>(s.point_b);
                h.real(s.error_bound);
                h.word(s.iterations as u64);
                h.status(s.status);
            }
        }

        match gjk.penetration(a, &ta, b, &tb) {
            None => h.word(0x9e0_0000),
            Some(p) => {
                h.word(0x9e0_0001);
                h.vector::<R>(p.normal);
                h.real(p.depth);
                h.real(p.error_bound);
                h.word(p.iterations as u64);
                h.status(p.status);
            }
        }

        let cast = gjk.raycast(&ray, max_length, b, &tb);
        match cast.outcome {
            gjk2d::RayOutcome::Hit(hit) => {
                h.word(0x4a7_0001);
                h.real(hit.distance);
                h.vector::<R>(hit.point);
                h.vector::<R>(hit.normal);
                h.real(hit.error_bound);
            }
            gjk2d::RayOutcome::Miss => h.word(0x4a7_0002),
            gjk2d::RayOutcome::Inside => h.word(0x4a7_0003),
        }
        h.word(cast.iterations as u64);
        h.status(cast.status);
    }
}

/// The f32 half of the batch.
pub fn golden_hash_f32() -> u64 {
    let mut h = GoldenHasher::new();
    golden_batch::<f32>(&mut h, 0x9e37_79b9_7f4a_7c15);
    h.0
}

/// The f64 half of the batch.
pub fn golden_hash_f64() -> u64 {
    let mut h = GoldenHasher::new();
    golden_batch::<f64>(&mut h, 0x9e37_79b9_7f4a_7c15);
    h.0
}

/// The hash of the whole batch, f32 then f64: what tests/golden_hash.txt holds.
pub fn golden_hash() -> u64 {
    let mut h = GoldenHasher::new();
    golden_batch::<f32>(&mut h, 0x9e37_79b9_7f4a_7c15);
    golden_batch::<f64>(&mut h, 0x9e37_79b9_7f4a_7c15);
    h.0
}
