//! Seeded random numbers and case counts shared by the certified suites.
// Each suite uses its own subset.
#![allow(dead_code)]

/// Cases of a property, times `GJK2D_LONG` when set.
pub fn cases(base: u32) -> u32 {
    let long = std::env::var("GJK2D_LONG").ok().and_then(|s| s.parse::<u32>().ok()).unwrap_or(1);
    base * long.max(1)
}

/// SplitMix64: the many vertices of a polygon come from a seed, not from
/// proptest's vectors (shrinking a thousand points tells nothing a seed does
/// not).
pub struct Rng(pub u64);
impl Rng {
    pub fn next(&mut self) -> u64 {
        self.0 = self.0.wrapping_add(0x9E37_79B9_7F4A_7C15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        z ^ (z >> 31)
    }
    pub fn unit(&mut self) -> f64 {
        (self.next() >> 11) as f64 / (1u64 << 53) as f64
    }
    pub fn range(&mut self, lo: f64, hi: f64) -> f64 {
        lo + (hi - lo) * self.unit()
    }
}

/// A convex-ish `n`-gon about the origin: one vertex in each of `n` equal
/// turns (jittered within it), at radii 0.5 to 1.5 on each axis, every
/// coordinate passed through `round` (to the precision under test). Not
/// always convex: the caller skips what the constructor refuses.
pub fn polygon_about_origin(rng: &mut Rng, n: usize, round: fn(f64) -> f64) -> Vec<[f64; 2]> {
    let phase = rng.unit();
    (0..n)
        .map(|k| {
            let t = (k as f64 + phase + 0.4 * rng.unit()) / n as f64 * std::f64::consts::TAU;
            let (a, b) = (rng.range(0.5, 1.5), rng.range(0.5, 1.5));
            [round(a * t.cos()), round(b * t.sin())]
        })
        .collect()
}
