//! Seeded cases and exact ellipse rays, shared by the suites that check
//! answers against exact arithmetic (certified, ray_bounds).
// Each suite uses its own subset.
#![allow(dead_code)]

use gjk2d_oracle::exact::{round_iv, sqrt_bounds, Q};

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

/// The exact parameter `t` (in units of `d`) of the first crossing of
/// `o + t d` with the ellipse `x^2/a^2 + y^2/b^2 = 1` (origin outside),
/// correctly rounded from rational arithmetic; `None` when the line misses it.
pub fn ellipse_ray(a: &Q, b: &Q, o: &[Q; 2], d: &[Q; 2]) -> Option<f64> {
    let (a2, b2) = (a * a, b * b);
    let (ox, oy, dx, dy) = (&o[0], &o[1], &d[0], &d[1]);
    let qa = &b2 * dx * dx + &a2 * dy * dy;
    let qb = (&b2 * ox * dx + &a2 * oy * dy) * Q::from_integer(2.into());
    let qc = &b2 * ox * ox + &a2 * oy * oy - &a2 * &b2;
    let disc = &qb * &qb - &qa * &qc * Q::from_integer(4.into());
    let zero = Q::from_integer(0.into());
    if disc < zero || qb >= zero || qa == zero {
        return None;
    }
    // t = 2c / (-b + sqrt(disc)): no cancellation, and monotone in sqrt.
    let two_c = &qc * Q::from_integer(2.into());
    let neg_b = -qb;
    Some(round_iv(|bits| {
        let (lo, hi) = sqrt_bounds(&disc, bits);
        (&two_c / (&neg_b + hi), &two_c / (&neg_b + lo))
    }))
}
