//! The exact first crossing of a ray with an ellipse, for the suites that
//! check answers against exact arithmetic.

use gjk2d_oracle::exact::{round_iv, sqrt_bounds, Q};

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
