//! Sine and cosine of an f32 angle in f32 arithmetic only, and of an f64
//! angle in a quarter turn; `const`, so constant shapes that need them
//! (a [`Slice`](crate::Slice)) are computed by the compiler, to the same bits.
//!
//! libm's `sinf`/`cosf` reduce the angle in f64: on a Cortex-M4F (single
//! precision FPU) or an M0 that links soft double arithmetic (`rem_pio2f`,
//! `__muldf3`, `__adddf3`, ...) for one rotation. These stay in f32, a few
//! small kernels, and being plain IEEE operations without fused
//! multiply-adds, they give the same bits on every target.
//!
//! Accuracy: within 2 * 2^-24 of the exact values for |angle| up to 1e5 rad
//! (1.39 * 2^-24 measured at every 97th float there; the tests check every
//! 997th and the multiples of pi/4). The reduction by pi/2 is exact there:
//! pi/2 is split into three parts of 8 significant bits, whose products with
//! a 16-bit quadrant count are exact, and a fourth that carries the rest.
//! Beyond, the reduction rounds like one operation on the angle itself, whose
//! own spacing (ulp) is then 0.008 rad or more; the result is still a unit
//! rotation within that spacing.

/// pi/2 in four parts: three of 8 significant bits, then the rest.
const PIO2: [f32; 4] = [1.5703125, 4.825592e-4, 1.2665987e-6, 9.920936e-10];
const FRAC_2_PI: f32 = core::f32::consts::FRAC_2_PI;
/// 2^23: above it every f32 is an integer; adding and subtracting it (with
/// the sign of the value) rounds to the nearest integer below it.
const TWO_POW_23: f32 = 8_388_608.0;
/// 2^26: from here on every f32 is a multiple of 4.
const QUADRANT_EXACT: f32 = 67_108_864.0;
/// How far from 0 the reduced angle can be: pi/4, plus the rounding of the
/// quadrant count (`x * 2/pi` rounds to a spacing of up to 1 below 2^24).
const REDUCED_BOUND: f32 = 1.6;

/// `(sin x, cos x)`; a non-finite `x` gives `(0, 1)` (callers reject it first).
pub(crate) const fn sin_cos_f32(x: f32) -> (f32, f32) {
    if !x.is_finite() {
        return (0.0, 1.0);
    }
    let y = x * FRAC_2_PI;
    let k = if y.abs() < TWO_POW_23 {
        let m = TWO_POW_23.copysign(y);
        (y + m) - m
    } else {
        y
    };
    let mut r = x;
    let mut i = 0;
    while i < PIO2.len() {
        r -= k * PIO2[i];
        i += 1;
    }
    // Only for angles beyond 2^24 * pi/2 can r leave the kernels' range;
    // keep it there (and the result finite).
    let r = r.clamp(-REDUCED_BOUND, REDUCED_BOUND);
    let (s, c) = (sin_kernel(r), cos_kernel(r));
    // k's two low bits: the quadrant. From 2^26 on, f32 integers are
    // multiples of 4. Below, `as i32` is exact (and one instruction with an
    // FPU, where `as i64` is a library call).
    let quadrant = if k.abs() < QUADRANT_EXACT { (k as i32) & 3 } else { 0 };
    match quadrant {
        0 => (s, c),
        1 => (c, -s),
        2 => (-s, -c),
        _ => (-c, s),
    }
}

/// sin on [-1.6, 1.6]: the Taylor series to r^13 (the next term is below
/// 1e-9 there, under f32's rounding).
const fn sin_kernel(r: f32) -> f32 {
    const S: [f32; 6] =
        [-1.0 / 6.0, 1.0 / 120.0, -1.0 / 5040.0, 1.0 / 362_880.0, -1.0 / 39_916_800.0, 1.0 / 6_227_020_800.0];
    let z = r * r;
    r + r * z * (S[0] + z * (S[1] + z * (S[2] + z * (S[3] + z * (S[4] + z * S[5])))))
}

/// cos on [-1.6, 1.6]: the series to r^14 (next term below 1e-10).
const fn cos_kernel(r: f32) -> f32 {
    const C: [f32; 6] =
        [1.0 / 24.0, -1.0 / 720.0, 1.0 / 40_320.0, -1.0 / 3_628_800.0, 1.0 / 479_001_600.0, -1.0 / 87_178_291_200.0];
    let z = r * r;
    let tail = z * z * (C[0] + z * (C[1] + z * (C[2] + z * (C[3] + z * (C[4] + z * C[5])))));
    let half = 0.5 * z;
    // 1 - z/2 rounds once; the tail is added to what it rounded away.
    let w = 1.0 - half;
    w + (((1.0 - w) - half) + tail)
}

/// pi/2 as the nearest f64 and the rest.
const PIO2_HI: f64 = core::f64::consts::FRAC_PI_2;
const PIO2_LO: f64 = 6.123_233_995_736_766e-17;

/// `(sin x, cos x)` for `x` in [0, pi/2] (a slice's half angle), in f64
/// arithmetic only, so that it can be `const`: libm's, which the rest of the
/// f64 code uses, is not. Above pi/4 it works on the complement
/// `pi/2 - x`, exact there (Sterbenz) but for the low part of pi/2, so both
/// kernels stay within |r| <= pi/4. Within one ulp of libm (the tests).
pub(crate) const fn sin_cos_quarter_f64(x: f64) -> (f64, f64) {
    if x <= core::f64::consts::FRAC_PI_4 {
        (sin_kernel_f64(x), cos_kernel_f64(x))
    } else {
        let r = (PIO2_HI - x) + PIO2_LO;
        (cos_kernel_f64(r), sin_kernel_f64(r))
    }
}

/// sin on [-pi/4, pi/4]: the Taylor series to r^19 (the next term is below
/// 1e-19 there, a thousandth of an ulp).
const fn sin_kernel_f64(r: f64) -> f64 {
    const S: [f64; 9] = [
        -1.0 / 6.0,
        1.0 / 120.0,
        -1.0 / 5040.0,
        1.0 / 362_880.0,
        -1.0 / 39_916_800.0,
        1.0 / 6_227_020_800.0,
        -1.0 / 1_307_674_368_000.0,
        1.0 / 355_687_428_096_000.0,
        -1.0 / 121_645_100_408_832_000.0,
    ];
    let z = r * r;
    let mut poly = S[8];
    let mut i = 8;
    while i > 0 {
        i -= 1;
        poly = S[i] + z * poly;
    }
    r + r * z * poly
}

/// cos on [-pi/4, pi/4]: the series to r^20, with 1 - r^2/2 compensated
/// as in the f32 kernel.
const fn cos_kernel_f64(r: f64) -> f64 {
    const C: [f64; 9] = [
        1.0 / 24.0,
        -1.0 / 720.0,
        1.0 / 40_320.0,
        -1.0 / 3_628_800.0,
        1.0 / 479_001_600.0,
        -1.0 / 87_178_291_200.0,
        1.0 / 20_922_789_888_000.0,
        -1.0 / 6_402_373_705_728_000.0,
        1.0 / 2_432_902_008_176_640_000.0,
    ];
    let z = r * r;
    let mut poly = C[8];
    let mut i = 8;
    while i > 0 {
        i -= 1;
        poly = C[i] + z * poly;
    }
    let half = 0.5 * z;
    let w = 1.0 - half;
    w + (((1.0 - w) - half) + z * z * poly)
}

#[cfg(test)]
mod tests {
    use super::{sin_cos_f32, sin_cos_quarter_f64};

    /// Distance in ulps between two positive finite f64s.
    fn ulps(a: f64, b: f64) -> u64 {
        a.to_bits().abs_diff(b.to_bits())
    }

    #[test]
    fn quarter_turn_f64_within_one_ulp_of_libm() {
        // Dense in [0, pi/2], the ends and the switch at pi/4 included.
        let n = 200_000;
        let top = core::f64::consts::FRAC_PI_2;
        let grid = (0..=n).map(|i| top * i as f64 / n as f64);
        let quarter = core::f64::consts::FRAC_PI_4;
        let edges = [quarter, f64::from_bits(quarter.to_bits() + 1), f64::from_bits(quarter.to_bits() - 1), top];
        let tiny = (1..2000u64).map(|i| f64::from_bits(i * 1_000_000_000_000));
        let angles = grid.chain(edges).chain(tiny);
        for x in angles {
            let (s, c) = sin_cos_quarter_f64(x);
            let (es, ec) = (libm::sin(x), libm::cos(x));
            assert!(ulps(s, es) <= 1 && ulps(c, ec) <= 1, "{x}: ({s}, {c}) against ({es}, {ec})");
        }
        assert_eq!(sin_cos_quarter_f64(0.0), (0.0, 1.0));
        assert_eq!(sin_cos_quarter_f64(top).0, 1.0);
    }

    /// Worst error in units of 2^-24 (half an ulp of 1), against f64 libm
    /// (correctly rounded to well below that).
    fn worst_error(angles: impl Iterator<Item = f32>) -> f64 {
        let mut worst = 0.0f64;
        for x in angles {
            let (s, c) = sin_cos_f32(x);
            let (es, ec) = (libm::sin(x as f64), libm::cos(x as f64));
            worst = worst.max((s as f64 - es).abs()).max((c as f64 - ec).abs());
        }
        worst * 16_777_216.0
    }

    #[test]
    fn accurate_to_the_last_bits_up_to_1e5() {
        // Every 997th float in [0, 1e5] and their negatives, plus the quadrant
        // boundaries, where reduction errors would show.
        let step = 997u32;
        let top = 1.0e5f32.to_bits();
        let grid = (0..top / step).map(|i| f32::from_bits(i * step));
        let err = worst_error(grid.clone().chain(grid.map(|x| -x)));
        assert!(err <= 2.0, "worst error {err} x 2^-24");
        let boundaries = (1..20_000).map(|k| k as f32 * core::f32::consts::FRAC_PI_4);
        let err = worst_error(boundaries);
        assert!(err <= 2.0, "worst error at multiples of pi/4: {err} x 2^-24");
    }

    #[test]
    fn exact_where_it_must_be() {
        assert_eq!(sin_cos_f32(0.0), (0.0, 1.0));
        assert_eq!(sin_cos_f32(-0.0).1, 1.0);
    }

    #[test]
    fn huge_and_bad_angles_give_unit_rotations() {
        for x in [1.0e6f32, -3.3e7, 1.0e20, f32::MAX, -f32::MAX, 8.5e6] {
            let (s, c) = sin_cos_f32(x);
            let norm = (s as f64).hypot(c as f64);
            assert!((norm - 1.0).abs() < 1e-6, "{x}: ({s}, {c})");
        }
        assert_eq!(sin_cos_f32(f32::NAN), (0.0, 1.0));
        assert_eq!(sin_cos_f32(f32::INFINITY), (0.0, 1.0));
    }

    #[test]
    fn beyond_1e5_within_the_angle_spacing() {
        // The angle's own spacing there is 2^-7 or more; the result must be
        // within one spacing of the exact rotation.
        for i in 0..2000 {
            let x = 1.0e5f32 + i as f32 * 5113.7;
            let (s, c) = sin_cos_f32(x);
            let ulp = (f32::from_bits(x.to_bits() + 1) - x) as f64;
            let (es, ec) = (libm::sin(x as f64), libm::cos(x as f64));
            assert!((s as f64 - es).abs() <= ulp && (c as f64 - ec).abs() <= ulp, "{x}");
        }
    }
}
