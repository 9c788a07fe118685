//! Error-free sums and products (Knuth's TwoSum; Dekker's TwoProduct with
//! Veltkamp's split, no fma, which is software on a Cortex-M4F) and the
//! one place they serve: the gap between two placed points, where the
//! points are far from their local origins and the gap is small, rounded
//! once at the gap's scale rather than at the origins' distance.

use crate::real::{Real, V2};

/// `s + e == a + b` exactly (Knuth's TwoSum, no branch on magnitudes).
#[inline(always)]
fn two_sum<R: Real>(a: R, b: R) -> (R, R) {
    let s = a + b;
    let bv = s - a;
    let av = s - bv;
    (s, (a - av) + (b - bv))
}

/// `p + e == a * b` exactly, barring underflow (whose error is below the
/// smallest normal number). No overflow: coordinates are bounded by
/// [`Real::MAX_COORDINATE`] and rotations by one.
#[inline(always)]
fn two_product<R: Real>(a: R, b: R) -> (R, R) {
    let p = a * b;
    let (ah, al) = split(a);
    let (bh, bl) = split(b);
    (p, ((ah * bh - p) + ah * bl + al * bh) + al * bl)
}

/// Veltkamp's split: `a == hi + lo`, each of at most half the significand's
/// bits, so that products of halves are exact.
#[inline(always)]
fn split<R: Real>(a: R) -> (R, R) {
    let c = R::SPLITTER * a;
    let hi = c - (c - a);
    (hi, a - hi)
}

/// `sum + prod.0 * prod.1 ...` as if in twice the precision, then rounded:
/// within an ulp or so of the exact value, plus `(n eps)^2` of the terms'
/// magnitudes (Ogita, Rump and Oishi's Sum2 over the products' exact
/// halves). One copy for both components on bare metal: inlined twice, it
/// would take twice a microcontroller's scarce flash for the same work.
#[cfg_attr(target_os = "none", inline(never))]
#[cfg_attr(not(target_os = "none"), inline(always))]
fn accurate_sum<R: Real>(sums: [R; 2], products: [(R, R); 4]) -> R {
    let (mut s, mut tail) = two_sum(sums[0], sums[1]);
    for (a, b) in products {
        let (p, e) = two_product(a, b);
        let (t, f) = two_sum(s, p);
        s = t;
        tail = tail + f + e;
    }
    s + tail
}

/// `(tb + Mb pb) - (ta + Ma pa)`, where `M` is a transform's rotation: the
/// world offset from the point `pa` placed by A's transform to `pb` placed
/// by B's, each component rounded once from (nearly) its exact value. The
/// translations' and the rotated points' rounding at their own scale would
/// otherwise be left in a gap much smaller than they are.
#[inline(never)]
pub(crate) fn placed_gap<R: Real>(ta: &crate::Transform<R>, pa: V2<R>, tb: &crate::Transform<R>, pb: V2<R>) -> V2<R> {
    let (ca, sa, cb, sb) = (ta.cos, ta.sin, tb.cos, tb.sin);
    let x = accurate_sum([tb.translation.x, -ta.translation.x], [(cb, pb.x), (-sb, pb.y), (-ca, pa.x), (sa, pa.y)]);
    let y = accurate_sum([tb.translation.y, -ta.translation.y], [(sb, pb.x), (cb, pb.y), (-sa, pa.x), (-ca, pa.y)]);
    V2::new(x, y)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn randoms() -> impl FnMut() -> f64 {
        let mut seed = 0x2545_f491_4f6c_dd1d_u64;
        move || {
            seed ^= seed << 13;
            seed ^= seed >> 7;
            seed ^= seed << 17;
            (seed >> 11) as f64 / (1u64 << 53) as f64 - 0.5
        }
    }

    /// Against the sum in f64, where f32 products are exact and these sums
    /// nearly so: within an ulp of the result plus Sum2's term of the
    /// magnitudes, where the plain f32 sum is off by far more.
    #[test]
    fn accurate_sum_rounds_near_the_exact_value() {
        let mut next = randoms();
        let mut plain_off = 0;
        for _ in 0..20_000 {
            // Terms of up to 500 that cancel to about 1.
            let big = 1e3 * next() as f32;
            let (c, s) = ((next() * 2.0) as f32, (next() * 2.0) as f32);
            let sums = [big, -(big * 0.999)];
            let products = [(c, big), (-s, big * 0.5), (-c, big), (s, big * 0.5 + next() as f32)];
            let exact: f64 = sums.iter().map(|&x| x as f64).sum::<f64>()
                + products.iter().map(|&(a, b)| a as f64 * b as f64).sum::<f64>();
            let magnitude: f64 = sums.iter().map(|x| x.abs() as f64).sum::<f64>()
                + products.iter().map(|&(a, b)| (a as f64 * b as f64).abs()).sum::<f64>();
            let bound = exact.abs() * f32::EPSILON as f64 + 1e-12 * magnitude;
            let got = accurate_sum(sums, products) as f64;
            assert!((got - exact).abs() <= bound, "{got} against {exact}");
            let plain = sums[0] + sums[1] + products.iter().map(|&(a, b)| a * b).sum::<f32>();
            plain_off += usize::from((plain as f64 - exact).abs() > bound);
        }
        assert!(plain_off > 10_000, "the cases should defeat the plain sum: {plain_off}");
    }

    /// Exact against f64, where the f32 product of two f32 values is exact.
    #[test]
    fn two_product_is_exact_in_f32() {
        let mut next = randoms();
        for _ in 0..20_000 {
            let (a, b) = ((next() * 1e4) as f32, (next() * 1e-3) as f32);
            let (p, e) = two_product(a, b);
            assert_eq!(p as f64 + e as f64, a as f64 * b as f64);
        }
    }
}
