//! Exact rational helpers and the only inexact step of the oracle: rounding to `f64`.
//!
//! Everything the oracle computes is either a rational number (rounded once, correctly,
//! to the nearest `f64`) or an expression containing square roots of rationals. The
//! latter are enclosed in rational intervals of growing precision until both interval
//! ends round to the same `f64`; because rounding is monotone, that `f64` is then the
//! correctly rounded value of the expression.

use num_bigint::{BigInt, BigUint, Sign};
use num_integer::Integer;
use num_rational::BigRational;
use num_traits::{One, Signed, Zero};
use std::cmp::Ordering;

/// Exact rational number.
pub type Q = BigRational;

/// Least common multiple, with a fast path for powers of two (the usual case: every
/// coordinate built from floats is dyadic).
pub fn lcm_fast(a: &BigInt, b: &BigInt) -> BigInt {
    let pow2 = |x: &BigInt| x.is_positive() && x.trailing_zeros() == Some(x.bits() - 1);
    if pow2(a) && pow2(b) {
        if a >= b {
            a.clone()
        } else {
            b.clone()
        }
    } else {
        a.lcm(b)
    }
}

/// Exact value of a finite `f64` (every finite float is a dyadic rational).
///
/// Panics on NaN or infinity: the oracle has no meaningful answer for them.
pub fn q_from_f64(x: f64) -> Q {
    assert!(x.is_finite(), "gjk2d-oracle: non-finite input {x}");
    let bits = x.to_bits();
    let neg = bits >> 63 == 1;
    let exp = ((bits >> 52) & 0x7ff) as i64;
    let frac = bits & ((1u64 << 52) - 1);
    let (m, e) = if exp == 0 { (frac, -1074) } else { (frac | (1u64 << 52), exp - 1075) };
    let mut num = BigInt::from(m);
    if neg {
        num = -num;
    }
    if e >= 0 {
        Q::from_integer(num << (e as usize))
    } else {
        Q::new(num, BigInt::one() << ((-e) as usize))
    }
}

/// Rounds `(m + f) * 2^e` to the nearest `f64` (ties to even), where `f` is an unknown
/// fraction in (0, 1) when `sticky` is set and 0 otherwise. Requires `m >= 2^54` so that
/// at least two bits are dropped, which makes the sticky information sufficient.
fn round_scaled(neg: bool, m: BigUint, sticky: bool, e: i64) -> f64 {
    let nb = m.bits() as i64;
    debug_assert!(nb >= 55);
    let drop = (nb - 53).max(-1074 - e);
    let drop_u = drop as usize;
    let mut hi: BigUint = &m >> drop_u;
    let low: BigUint = &m - (&hi << drop_u);
    let half: BigUint = BigUint::one() << (drop_u - 1);
    let up = match low.cmp(&half) {
        Ordering::Greater => true,
        Ordering::Less => false,
        Ordering::Equal => sticky || hi.is_odd(),
    };
    if up {
        hi += 1u32;
    }
    let mut exp = e + drop;
    let mut h: u64 = if hi.bits() > 64 { u64::MAX } else { hi.iter_u64_digits().next().unwrap_or(0) };
    if h == 1u64 << 53 {
        h >>= 1;
        exp += 1;
    }
    let bits = if h == 0 {
        0
    } else if h < (1u64 << 52) {
        // Subnormal: `drop` was limited so that exp == -1074.
        h
    } else {
        let be = exp + 1075;
        if be >= 2047 {
            0x7ffu64 << 52
        } else {
            ((be as u64) << 52) | (h - (1u64 << 52))
        }
    };
    let v = f64::from_bits(bits);
    if neg {
        -v
    } else {
        v
    }
}

/// Correctly rounded (nearest, ties to even) conversion of a rational to `f64`.
///
/// `ToPrimitive` on `BigRational` is not guaranteed to be correctly rounded, so the
/// quotient is formed with big-integer division keeping >= 55 bits plus a sticky bit.
pub fn q_to_f64(q: &Q) -> f64 {
    if q.is_zero() {
        return 0.0;
    }
    let neg = q.is_negative();
    let p = q.numer().magnitude().clone();
    let d = q.denom().magnitude().clone();
    let s = 55 + d.bits() as i64 - p.bits() as i64;
    let (m, rem) = if s >= 0 { (p << (s as usize)).div_rem(&d) } else { p.div_rem(&(d << ((-s) as usize))) };
    round_scaled(neg, m, !rem.is_zero(), -s)
}

/// Correctly rounded `x * 2^-shift` for an integer `x`.
pub fn big_to_f64_shifted(x: &BigInt, shift: u64) -> f64 {
    if x.is_zero() {
        return 0.0;
    }
    let m = x.magnitude() << 60usize;
    round_scaled(x.sign() == Sign::Minus, m, false, -(shift as i64) - 60)
}

fn floor_div2(x: i64) -> i64 {
    x.div_euclid(2)
}

/// `floor(sqrt(x) * 2^s)` and whether that floor is exact, for rational `x >= 0`.
fn sqrt_scaled(x: &Q, s: i64) -> (BigUint, bool) {
    let p = x.numer().magnitude().clone();
    let d = x.denom().magnitude().clone();
    let (n, rem) = if s >= 0 { (p << ((2 * s) as usize)).div_rem(&d) } else { p.div_rem(&(d << ((-2 * s) as usize))) };
    let m = n.sqrt();
    let exact = rem.is_zero() && &m * &m == n;
    (m, exact)
}

/// Correctly rounded square root of a non-negative rational.
pub fn sqrt_to_f64(x: &Q) -> f64 {
    assert!(!x.is_negative(), "sqrt of negative rational");
    if x.is_zero() {
        return 0.0;
    }
    let bp = x.numer().magnitude().bits() as i64;
    let bd = x.denom().magnitude().bits() as i64;
    // sqrt(x) > 2^((bp-1-bd)/2), so m = floor(sqrt(x)*2^s) >= 2^55.
    let s = 56 - floor_div2(bp - 1 - bd);
    let (m, exact) = sqrt_scaled(x, s);
    round_scaled(false, m, !exact, -s)
}

fn dyadic(m: BigUint, s: i64) -> Q {
    if m.is_zero() {
        return Q::zero();
    }
    // Reduce by the common power of two directly (no general gcd needed).
    let tz = m.trailing_zeros().unwrap_or(0) as i64;
    let k = tz.min(s.max(0));
    let m = BigInt::from(m >> (k as usize));
    let s = s - k;
    if s >= 0 {
        Q::new_raw(m, BigInt::one() << (s as usize))
    } else {
        Q::from_integer(m << ((-s) as usize))
    }
}

/// Rational bounds `lo <= sqrt(x) <= hi` with relative width below `2^-bits`
/// (`lo == hi` when the root is exactly rational at that scale).
pub fn sqrt_bounds(x: &Q, bits: u64) -> (Q, Q) {
    assert!(!x.is_negative(), "sqrt of negative rational");
    if x.is_zero() {
        return (Q::zero(), Q::zero());
    }
    let bp = x.numer().magnitude().bits() as i64;
    let bd = x.denom().magnitude().bits() as i64;
    let s = bits as i64 + 2 - floor_div2(bp - 1 - bd);
    let (m, exact) = sqrt_scaled(x, s);
    let lo = dyadic(m.clone(), s);
    let hi = if exact { lo.clone() } else { dyadic(m + 1u32, s) };
    (lo, hi)
}

/// Correctly rounded value of a real number given by an enclosure oracle: `f(bits)`
/// returns rational bounds `lo <= value <= hi` whose width shrinks with `bits`.
/// Precision doubles until both bounds round to the same `f64` (then that is the
/// correctly rounded value, rounding being monotone). The loop stops at 8192 bits and
/// returns the rounding of `lo`; that can only happen for a value within 2^-8000
/// (relative) of a rounding boundary, i.e. essentially for exact halfway cases.
pub fn round_iv(mut f: impl FnMut(u64) -> (Q, Q)) -> f64 {
    let mut bits = 128;
    loop {
        let (lo, hi) = f(bits);
        debug_assert!(lo <= hi);
        let a = q_to_f64(&lo);
        if lo == hi {
            return a;
        }
        let b = q_to_f64(&hi);
        if a == b || bits >= 8192 {
            return a;
        }
        bits *= 2;
    }
}

/// Correctly rounded unit vector `v / |v|` given `vv = v·v > 0`:
/// each component is `sign(v_i) * sqrt(v_i^2 / vv)`, one correctly rounded square root.
pub fn unit_q(v: &[Q; 2], vv: &Q) -> [f64; 2] {
    let c = |x: &Q| {
        let m = sqrt_to_f64(&(x * x / vv));
        if x.is_negative() {
            -m
        } else {
            m
        }
    };
    [c(&v[0]), c(&v[1])]
}

/// `unit_q` for an integer vector.
pub fn unit_int(v: &[BigInt; 2]) -> [f64; 2] {
    let q = [Q::from_integer(v[0].clone()), Q::from_integer(v[1].clone())];
    let vv = &q[0] * &q[0] + &q[1] * &q[1];
    unit_q(&q, &vv)
}

/// The real number `a + b * sqrt(g)` with rational `a`, `b` and `g >= 0`: the form of
/// every ray hit parameter against round shapes. Its sign is decided exactly.
#[derive(Clone, Debug)]
pub struct QSqrt {
    pub a: Q,
    pub b: Q,
    pub g: Q,
}

fn sgn(x: &Q) -> i32 {
    if x.is_positive() {
        1
    } else if x.is_negative() {
        -1
    } else {
        0
    }
}

impl QSqrt {
    pub fn rational(a: Q) -> Self {
        QSqrt { a, b: Q::zero(), g: Q::zero() }
    }

    /// Exact sign (-1, 0, 1).
    pub fn sign(&self) -> i32 {
        let sa = sgn(&self.a);
        let sb = if self.g.is_zero() { 0 } else { sgn(&self.b) };
        if sb == 0 {
            return sa;
        }
        if sa == 0 || sa == sb {
            return sb;
        }
        // Opposite signs: compare a^2 with b^2 g.
        let a2 = &self.a * &self.a;
        let b2g = &self.b * &self.b * &self.g;
        match a2.cmp(&b2g) {
            Ordering::Greater => sa,
            Ordering::Less => sb,
            Ordering::Equal => 0,
        }
    }

    /// `self + q`.
    pub fn add_q(&self, q: &Q) -> Self {
        QSqrt { a: &self.a + q, b: self.b.clone(), g: self.g.clone() }
    }

    /// `self * q`.
    pub fn mul_q(&self, q: &Q) -> Self {
        QSqrt { a: &self.a * q, b: &self.b * q, g: self.g.clone() }
    }

    /// `self^2`, which has the same form.
    pub fn square(&self) -> Self {
        QSqrt {
            a: &self.a * &self.a + &self.b * &self.b * &self.g,
            b: Q::from_integer(BigInt::from(2)) * &self.a * &self.b,
            g: self.g.clone(),
        }
    }

    /// Rational enclosure with relative precision about `2^-bits` on the root.
    pub fn bounds(&self, bits: u64) -> (Q, Q) {
        if self.b.is_zero() || self.g.is_zero() {
            return (self.a.clone(), self.a.clone());
        }
        let (sl, sh) = sqrt_bounds(&self.g, bits);
        let x = &self.a + &self.b * &sl;
        let y = &self.a + &self.b * &sh;
        if x <= y {
            (x, y)
        } else {
            (y, x)
        }
    }
}
