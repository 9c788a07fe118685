//! The scalar abstraction: one generic code path for `f32` (with [`glam::Vec2`])
//! and `f64` (with [`glam::DVec2`]).
//!
//! Internally every algorithm works on [`V2`], a plain two-component vector
//! generic over the scalar, so the geometry is written once. Users only ever see
//! glam's vector types: conversions happen at the API boundary and compile to
//! nothing.

use core::fmt::Debug;
use core::ops::{Add, AddAssign, Div, Mul, MulAssign, Neg, Sub, SubAssign};

mod sealed {
    /// Also how generic code reaches per-type choices, and per-type work
    /// through [`per_type`](Self::per_type).
    pub trait Sealed {
        /// Whether GJK runs in few, flat frames (its loop inlined into each
        /// query): f64 on bare metal only, where every frame saves wide
        /// soft-float registers.
        const FLAT_GJK: bool;

        /// Whether [`first_max_dot`](Self::first_max_dot) scans in SIMD,
        /// which makes a scan of a few dozen vertices cheaper than a walk or
        /// a search whose branches a predictor cannot learn.
        const SIMD_SCAN: bool = false;

        /// Whether a warm-started penetration of two small polygons asks
        /// the last leading axes first (their hold, the shapes'
        /// fingerprint, four axes) rather than measuring all sixteen: not
        /// in f32 with SIMD, where four lanes a register make the sixteen
        /// cheaper.
        const WARM_LEADERS: bool = true;

        /// The index of the first vertex with the largest dot product with
        /// `d`, in SIMD where the target has it (x86-64's SSE2): eight
        /// vertices with no branch at all, others eight (f32) or two (f64) at
        /// a time with one branch a chunk. `None` elsewhere, where a scalar
        /// scan does it. The products round as the scalar ones do, and ties
        /// go to the first, so the vertex is the same.
        #[inline(always)]
        fn first_max_dot(vertices: &[super::V2<Self>], d: super::V2<Self>) -> Option<usize>
        where
            Self: Sized,
        {
            let _ = (vertices, d);
            None
        }

        /// The first vertices of largest and of least dot product with `u`
        /// and with `t`, as `[max u, max t, min u, min t]`: the supports
        /// along `u`, `t`, `-u` and `-t`, the very vertices
        /// [`first_max_dot`](Self::first_max_dot) gives each (a least dot
        /// negated is the dot with the negated direction, to the bit), from
        /// one pass where the target has SIMD (its lanes keep 64 vertices'
        /// dots; any more are read one by one). `None` elsewhere.
        #[inline(always)]
        fn extreme_dots(vertices: &[super::V2<Self>], u: super::V2<Self>, t: super::V2<Self>) -> Option<[usize; 4]>
        where
            Self: Sized,
        {
            let _ = (vertices, u, t);
            None
        }

        /// For each axis (`nx`, `ny`, not unit) and its least reach, the
        /// separation along its unit normal, as
        /// [`scaled_separation`](super::scaled_separation) gives it,
        /// to the bit: lanes of SIMD where the target has them, whose square
        /// roots and divisions round as the scalar ones do. `K` a multiple
        /// of four.
        #[inline(always)]
        fn scaled_separations<const K: usize>(nx: &[Self; K], ny: &[Self; K], least: &[Self; K]) -> [Self; K]
        where
            Self: super::Real,
        {
            core::array::from_fn(|k| super::scaled_separation(super::V2::new(nx[k], ny[k]), least[k]))
        }

        /// For each of eight axes (`nx`, `ny`, not unit), the least dot
        /// product of eight vertices (`xs`, `ys`) with it: the
        /// separating-axis test's inner loop. Each axis folds the vertices
        /// in order, keeping the smaller (the one it has on a tie), so SIMD
        /// lanes, where the target has them, give the scalar fold's values
        /// (in f32 its bits; in f64 a zero's sign may differ).
        /// `WIDE` asks for four f64 lanes a register, where the processor
        /// has them ([`wide_lanes`](Self::wide_lanes)); only code compiled
        /// for them should ask (`run_wide`).
        #[inline(always)]
        fn least_dots8<const WIDE: bool>(nx: &[Self; 8], ny: &[Self; 8], xs: &[Self; 8], ys: &[Self; 8]) -> [Self; 8]
        where
            Self: super::Real,
        {
            let mut least = [Self::INFINITY; 8];
            for (&x, &y) in xs.iter().zip(ys) {
                for i in 0..8 {
                    least[i] = super::lesser(nx[i] * x + ny[i] * y, least[i]);
                }
            }
            least
        }

        /// Whether this processor runs four f64 lanes a register (AVX2, its
        /// wide registers saved by the operating system).
        #[inline(always)]
        fn wide_lanes() -> bool {
            false
        }

        /// The value as it is, through a piece of assembly that is empty
        /// where the target has it (x86-64): the compiler cannot see through
        /// it, so its SLP vectorizer does not pack a point's two
        /// coordinates into one register across it, only to shuffle them
        /// apart again for every cross term of a rotation or a cross
        /// product, which costs a short closed form more than its arithmetic.
        #[inline(always)]
        fn scalar_barrier(self) -> Self
        where
            Self: Sized,
        {
            self
        }

        /// A point's coordinates as one 64-bit word for a fingerprint: both
        /// bit patterns side by side in f32; in f64 the second turned by 29
        /// bits onto the first.
        fn point_bits(x: Self, y: Self) -> u64
        where
            Self: Sized;

        /// `W`'s work for this type: [`PerType::f32`](super::PerType::f32)
        /// or [`PerType::f64`](super::PerType::f64).
        fn per_type<W: super::PerType>(input: W::Input<'_, Self>) -> W::Output<Self>
        where
            Self: super::Real;
    }
    impl Sealed for f32 {
        const FLAT_GJK: bool = false;
        #[inline(always)]
        fn point_bits(x: f32, y: f32) -> u64 {
            (u64::from(x.to_bits()) << 32) | u64::from(y.to_bits())
        }
        #[inline(always)]
        fn per_type<W: super::PerType>(input: W::Input<'_, f32>) -> W::Output<f32> {
            W::f32(input)
        }
        #[cfg(all(target_arch = "x86_64", target_feature = "sse2"))]
        #[inline(always)]
        fn scalar_barrier(self) -> f32 {
            super::sse2::scalar_barrier_f32(self)
        }
        #[cfg(all(target_arch = "x86_64", target_feature = "sse2"))]
        #[inline(always)]
        fn least_dots8<const WIDE: bool>(nx: &[f32; 8], ny: &[f32; 8], xs: &[f32; 8], ys: &[f32; 8]) -> [f32; 8] {
            super::sse2::least_dots8_f32(nx, ny, xs, ys)
        }
        #[cfg(all(target_arch = "x86_64", target_feature = "sse2"))]
        #[inline(always)]
        fn scaled_separations<const K: usize>(nx: &[f32; K], ny: &[f32; K], least: &[f32; K]) -> [f32; K] {
            super::sse2::scaled_separations_f32(nx, ny, least)
        }
        #[cfg(all(target_arch = "x86_64", target_feature = "sse2"))]
        const SIMD_SCAN: bool = true;
        #[cfg(all(target_arch = "x86_64", target_feature = "sse2"))]
        const WARM_LEADERS: bool = false;
        #[cfg(all(target_arch = "x86_64", target_feature = "sse2"))]
        #[inline(always)]
        fn first_max_dot(vertices: &[super::V2<f32>], d: super::V2<f32>) -> Option<usize> {
            Some(match vertices.try_into() {
                Ok(eight) => super::sse2::first_max_dot8_f32(eight, d),
                Err(_) => super::sse2::first_max_dot_f32(vertices, d),
            })
        }
        #[cfg(all(target_arch = "x86_64", target_feature = "sse2"))]
        #[inline(always)]
        fn extreme_dots(vertices: &[super::V2<f32>], u: super::V2<f32>, t: super::V2<f32>) -> Option<[usize; 4]> {
            Some(super::sse2::extreme_dots_f32(vertices, u, t))
        }
    }
    impl Sealed for f64 {
        const FLAT_GJK: bool = cfg!(target_os = "none");
        #[inline(always)]
        fn point_bits(x: f64, y: f64) -> u64 {
            x.to_bits() ^ y.to_bits().rotate_left(29)
        }
        #[inline(always)]
        fn per_type<W: super::PerType>(input: W::Input<'_, f64>) -> W::Output<f64> {
            W::f64(input)
        }
        #[cfg(all(target_arch = "x86_64", target_feature = "sse2"))]
        #[inline(always)]
        fn scalar_barrier(self) -> f64 {
            super::sse2::scalar_barrier_f64(self)
        }
        #[cfg(all(target_arch = "x86_64", target_feature = "sse2"))]
        #[inline(always)]
        fn least_dots8<const WIDE: bool>(nx: &[f64; 8], ny: &[f64; 8], xs: &[f64; 8], ys: &[f64; 8]) -> [f64; 8] {
            super::sse2::least_dots8_f64::<WIDE>(nx, ny, xs, ys)
        }
        #[cfg(all(target_arch = "x86_64", target_feature = "sse2"))]
        #[inline(always)]
        fn wide_lanes() -> bool {
            super::sse2::wide()
        }
        #[cfg(all(target_arch = "x86_64", target_feature = "sse2"))]
        #[inline(always)]
        fn scaled_separations<const K: usize>(nx: &[f64; K], ny: &[f64; K], least: &[f64; K]) -> [f64; K] {
            super::sse2::scaled_separations_f64(nx, ny, least)
        }
        #[cfg(all(target_arch = "x86_64", target_feature = "sse2"))]
        const SIMD_SCAN: bool = true;
        #[cfg(all(target_arch = "x86_64", target_feature = "sse2"))]
        #[inline(always)]
        fn first_max_dot(vertices: &[super::V2<f64>], d: super::V2<f64>) -> Option<usize> {
            Some(match vertices.try_into() {
                Ok(eight) => super::sse2::first_max_dot8_f64(eight, d),
                Err(_) => super::sse2::first_max_dot_f64(vertices, d),
            })
        }
        #[cfg(all(target_arch = "x86_64", target_feature = "sse2"))]
        #[inline(always)]
        fn extreme_dots(vertices: &[super::V2<f64>], u: super::V2<f64>, t: super::V2<f64>) -> Option<[usize; 4]> {
            Some(super::sse2::extreme_dots_f64(vertices, u, t))
        }
    }
}

#[cfg(all(target_arch = "x86_64", target_feature = "sse2"))]
pub(crate) use sse2::run_wide;

/// Support scans of eight vertices in SSE2, which every x86-64 processor has.
#[cfg(all(target_arch = "x86_64", target_feature = "sse2"))]
#[allow(unsafe_code)]
mod sse2 {
    use super::V2;
    use core::arch::x86_64::*;

    #[inline(always)]
    pub fn scalar_barrier_f32(mut x: f32) -> f32 {
        // SAFETY: the assembly is empty: it reads, writes and jumps nowhere,
        // and leaves the register that holds `x` as it found it.
        unsafe { core::arch::asm!("/* {0} */", inout(xmm_reg) x, options(pure, nomem, nostack, preserves_flags)) };
        x
    }

    #[inline(always)]
    pub fn scalar_barrier_f64(mut x: f64) -> f64 {
        // SAFETY: as above.
        unsafe { core::arch::asm!("/* {0} */", inout(xmm_reg) x, options(pure, nomem, nostack, preserves_flags)) };
        x
    }

    /// The first lane set in `mask`, or 0 if none is (never, for finite dots).
    #[inline(always)]
    fn first_lane(mask: i32) -> usize {
        if mask == 0 {
            0
        } else {
            mask.trailing_zeros() as usize
        }
    }

    #[inline(always)]
    pub fn first_max_dot8_f32(v: &[V2<f32>; 8], d: V2<f32>) -> usize {
        // SAFETY: the module is compiled only where the build enables sse2
        // (`cfg(target_feature = "sse2")`), so the processor has it.
        unsafe { dots8_f32(v, d) }
    }

    #[inline(always)]
    pub fn first_max_dot8_f64(v: &[V2<f64>; 8], d: V2<f64>) -> usize {
        // SAFETY: as above.
        unsafe { dots8_f64(v, d) }
    }

    #[inline(always)]
    pub fn first_max_dot_f32(v: &[V2<f32>], d: V2<f32>) -> usize {
        // SAFETY: as above.
        unsafe { running_max_f32(v, d) }
    }

    #[inline(always)]
    pub fn first_max_dot_f64(v: &[V2<f64>], d: V2<f64>) -> usize {
        if wide_fits(v) {
            // SAFETY: `wide_fits` found AVX2 on this processor, its wide
            // registers saved by the operating system.
            return unsafe { wide_max_f64(v, d) };
        }
        // SAFETY: as above.
        unsafe { running_max_f64(v, d) }
    }

    /// Whether the wide scan runs: where the processor has AVX2 and `v`
    /// fills one of its steps (eight vertices) and no more than it keeps
    /// (64). Fewer would be mostly its scalar remainder, more than the
    /// SSE2 scan's.
    #[inline(always)]
    fn wide_fits(v: &[V2<f64>]) -> bool {
        (8..=WIDE_SCAN_MAX).contains(&v.len()) && wide()
    }

    /// The most vertices the wide scan keeps the dots of.
    const WIDE_SCAN_MAX: usize = 64;

    /// Whether this processor runs AVX2 and its operating system saves the
    /// wide registers: asked of the processor once, then read from memory.
    #[inline(always)]
    pub fn wide() -> bool {
        use core::sync::atomic::{AtomicU8, Ordering};
        static KNOWN: AtomicU8 = AtomicU8::new(0);
        match KNOWN.load(Ordering::Relaxed) {
            1 => false,
            2 => true,
            _ => {
                let found = detect_wide();
                KNOWN.store(if found { 2 } else { 1 }, Ordering::Relaxed);
                found
            }
        }
    }

    #[cold]
    #[inline(never)]
    fn detect_wide() -> bool {
        // Leaf 1: AVX (ECX bit 28) and OSXSAVE (bit 27), the operating
        // system's use of XSAVE, which makes XGETBV available.
        let features = cpuid(1, 0);
        if features.ecx & (1 << 27) == 0 || features.ecx & (1 << 28) == 0 {
            return false;
        }
        // SAFETY: OSXSAVE is set, so XGETBV runs; XCR0 bits 1 and 2 say
        // the operating system saves the SSE and AVX registers.
        if unsafe { enabled_state() } & 0b110 != 0b110 {
            return false;
        }
        // Leaf 7, subleaf 0: AVX2 (EBX bit 5), where the processor has leaf 7.
        cpuid(0, 0).eax >= 7 && cpuid(7, 0).ebx & (1 << 5) != 0
    }

    /// `CPUID`, which older compilers this crate supports declare unsafe.
    #[allow(unused_unsafe)]
    fn cpuid(leaf: u32, subleaf: u32) -> CpuidResult {
        // SAFETY: every x86-64 processor has CPUID, and a leaf it lacks
        // reads as another leaf's values, never a fault.
        unsafe { __cpuid_count(leaf, subleaf) }
    }

    /// The SSE2 scan's answer, and the wide one's where the processor has
    /// it: for the test that holds them to the scalar scan.
    #[cfg(test)]
    pub fn both_f64(v: &[V2<f64>], d: V2<f64>) -> (usize, Option<usize>) {
        // SAFETY: as in `first_max_dot_f64`.
        let wide = wide_fits(v).then(|| unsafe { wide_max_f64(v, d) });
        // SAFETY: as above.
        (unsafe { running_max_f64(v, d) }, wide)
    }

    #[target_feature(enable = "xsave")]
    fn enabled_state() -> u64 {
        // SAFETY: the caller has seen OSXSAVE set, so XGETBV runs, and
        // register 0 (XCR0) always exists.
        unsafe { _xgetbv(0) }
    }

    /// [`running_max_f64`] four lanes wide: the dots of eight vertices a
    /// step, all kept, and the first equal to their maximum found from
    /// one mask a register. A register pair's dots come out of the lane
    /// shuffles as vertices 0, 2, 1, 3 and are put back in order.
    #[target_feature(enable = "avx,avx2")]
    #[inline]
    fn wide_max_f64(v: &[V2<f64>], d: V2<f64>) -> usize {
        let (dx, dy) = (_mm256_set1_pd(d.x), _mm256_set1_pd(d.y));
        let dots = |c: &[V2<f64>]| {
            let a = _mm256_setr_pd(c[0].x, c[0].y, c[1].x, c[1].y);
            let b = _mm256_setr_pd(c[2].x, c[2].y, c[3].x, c[3].y);
            let (xs, ys) = (_mm256_unpacklo_pd(a, b), _mm256_unpackhi_pd(a, b));
            let sums = _mm256_add_pd(_mm256_mul_pd(xs, dx), _mm256_mul_pd(ys, dy));
            _mm256_permute4x64_pd::<0b11_01_10_00>(sums)
        };
        let mut best = [_mm256_set1_pd(f64::NEG_INFINITY); 2];
        let mut kept = [_mm256_setzero_pd(); WIDE_SCAN_MAX / 4];
        let mut chunks = v.chunks_exact(8);
        for (slots, c) in kept.chunks_exact_mut(2).zip(&mut chunks) {
            let (low, high) = (dots(&c[..4]), dots(&c[4..]));
            slots.copy_from_slice(&[low, high]);
            best[0] = _mm256_max_pd(low, best[0]);
            best[1] = _mm256_max_pd(high, best[1]);
        }
        let m = _mm256_max_pd(best[0], best[1]);
        let m = _mm_max_pd(_mm256_castpd256_pd128(m), _mm256_extractf128_pd::<1>(m));
        let m = _mm_max_pd(m, _mm_shuffle_pd::<0b01>(m, m));
        let top = chunks.remainder().iter().fold(_mm_cvtsd_f64(m), |top, p| {
            let dot = p.dot(d);
            core::hint::select_unpredictable(dot > top, dot, top)
        });
        let wanted = _mm256_set1_pd(top);
        let whole = 2 * (v.len() / 8);
        let equal = kept.iter().take(whole).enumerate().fold(0u64, |bits, (k, &x)| {
            bits | u64::from(_mm256_movemask_pd(_mm256_cmp_pd::<_CMP_EQ_OQ>(x, wanted)) as u32) << (4 * k)
        });
        if equal != 0 {
            return equal.trailing_zeros() as usize;
        }
        first_equal(chunks.remainder(), 4 * whole, d, top)
    }

    /// The first vertex of largest dot product, in two passes: the maximum
    /// (two chains of four lanes), then the first vertex whose dot equals
    /// it. Carrying an index in every lane would cost as much again as the
    /// dots; the second pass compares the dots the first kept (of up to 64
    /// vertices; beyond, it computes them again), the kept ones all at once
    /// into one word of matches. The dots round as the scalar ones
    /// (`x dx + y dy`), so equality finds the very vertex, ties the first
    /// of them.
    #[target_feature(enable = "sse2")]
    #[inline]
    fn running_max_f32(v: &[V2<f32>], d: V2<f32>) -> usize {
        let dd = _mm_setr_ps(d.x, d.y, d.x, d.y);
        let pair = |p: &[V2<f32>]| _mm_mul_ps(_mm_setr_ps(p[0].x, p[0].y, p[1].x, p[1].y), dd);
        // Products (x dx, y dy, ...) of vertices 0 to 3, summed in pairs.
        let dots = |c: &[V2<f32>]| {
            let (low, high) = (pair(&c[..2]), pair(&c[2..4]));
            _mm_add_ps(_mm_shuffle_ps::<0b10_00_10_00>(low, high), _mm_shuffle_ps::<0b11_01_11_01>(low, high))
        };
        let mut best = [_mm_set1_ps(f32::NEG_INFINITY); 2];
        // The dots of the first 64 vertices, kept for the second pass.
        let mut kept = [_mm_setzero_ps(); 16];
        let mut chunks = v.chunks_exact(8);
        for (k, c) in (&mut chunks).enumerate() {
            let (low, high) = (dots(&c[..4]), dots(&c[4..]));
            if let Some(slots) = kept.get_mut(2 * k..2 * k + 2) {
                slots.copy_from_slice(&[low, high]);
            }
            // A NaN dot leaves the maximum as it was (the second operand).
            best[0] = _mm_max_ps(low, best[0]);
            best[1] = _mm_max_ps(high, best[1]);
        }
        let m = _mm_max_ps(best[0], best[1]);
        let m = _mm_max_ps(m, _mm_shuffle_ps::<0b01_00_11_10>(m, m));
        let m = _mm_max_ps(m, _mm_shuffle_ps::<0b10_11_00_01>(m, m));
        let top = chunks.remainder().iter().fold(_mm_cvtss_f32(m), |top, p| {
            let dot = p.dot(d);
            core::hint::select_unpredictable(dot > top, dot, top)
        });
        let wanted = _mm_set1_ps(top);
        let whole = (2 * (v.len() / 8)).min(kept.len());
        if let Some(i) =
            first_match(kept.get(..whole).unwrap_or_default(), 4, |quad| _mm_movemask_ps(_mm_cmpeq_ps(quad, wanted)))
        {
            return i;
        }
        let rest = v.get(4 * whole..).unwrap_or_default();
        let mut quads = rest.chunks_exact(4);
        for (k, c) in (&mut quads).enumerate() {
            let mask = _mm_movemask_ps(_mm_cmpeq_ps(dots(c), wanted));
            if mask != 0 {
                return 4 * (whole + k) + mask.trailing_zeros() as usize;
            }
        }
        first_equal(quads.remainder(), v.len() - quads.remainder().len(), d, top)
    }

    /// Two lanes, as [`running_max_f32`].
    #[target_feature(enable = "sse2")]
    #[inline]
    fn running_max_f64(v: &[V2<f64>], d: V2<f64>) -> usize {
        let dd = _mm_setr_pd(d.x, d.y);
        // The products (x dx, y dy) of two vertices, summed across: their dots.
        let dots = |c: &[V2<f64>]| {
            let p = _mm_mul_pd(_mm_setr_pd(c[0].x, c[0].y), dd);
            let q = _mm_mul_pd(_mm_setr_pd(c[1].x, c[1].y), dd);
            _mm_add_pd(_mm_unpacklo_pd(p, q), _mm_unpackhi_pd(p, q))
        };
        let mut best = [_mm_set1_pd(f64::NEG_INFINITY); 2];
        let mut kept = [_mm_setzero_pd(); 32];
        let mut chunks = v.chunks_exact(4);
        for (k, c) in (&mut chunks).enumerate() {
            let (low, high) = (dots(&c[..2]), dots(&c[2..]));
            if let Some(slots) = kept.get_mut(2 * k..2 * k + 2) {
                slots.copy_from_slice(&[low, high]);
            }
            best[0] = _mm_max_pd(low, best[0]);
            best[1] = _mm_max_pd(high, best[1]);
        }
        let m = _mm_max_pd(best[0], best[1]);
        let m = _mm_max_pd(m, _mm_shuffle_pd::<0b01>(m, m));
        let top = chunks.remainder().iter().fold(_mm_cvtsd_f64(m), |top, p| {
            let dot = p.dot(d);
            core::hint::select_unpredictable(dot > top, dot, top)
        });
        let wanted = _mm_set1_pd(top);
        let whole = (2 * (v.len() / 4)).min(kept.len());
        let equal = equal_f64(&kept, whole, wanted);
        if equal != 0 {
            return equal.trailing_zeros() as usize;
        }
        let rest = v.get(2 * whole..).unwrap_or_default();
        let mut pairs = rest.chunks_exact(2);
        for (k, c) in (&mut pairs).enumerate() {
            let mask = _mm_movemask_pd(_mm_cmpeq_pd(dots(c), wanted));
            if mask != 0 {
                return 2 * (whole + k) + mask.trailing_zeros() as usize;
            }
        }
        first_equal(pairs.remainder(), v.len() - pairs.remainder().len(), d, top)
    }

    /// The most vertices [`extreme_dots_f32`] and [`extreme_dots_f64`] keep
    /// the dots of: the longest polygon scanned in SIMD.
    pub const EXTREMES_MAX: usize = 64;

    #[inline(always)]
    pub fn extreme_dots_f32(v: &[V2<f32>], u: V2<f32>, t: V2<f32>) -> [usize; 4] {
        // SAFETY: as above.
        unsafe { extremes_f32(v, u, t) }
    }

    #[inline(always)]
    pub fn extreme_dots_f64(v: &[V2<f64>], u: V2<f64>, t: V2<f64>) -> [usize; 4] {
        if wide_fits(v) {
            // SAFETY: `wide_fits` found AVX2 on this processor, its wide
            // registers saved by the operating system.
            return unsafe { wide_extremes_f64(v, u, t) };
        }
        // SAFETY: as above.
        unsafe { extremes_f64(v, u, t) }
    }

    /// [`running_max_f32`] along two directions at once, keeping both ends
    /// of each: every vertex is loaded once for four supports. The extremes
    /// first (their chains side by side), then the first vertex equal to
    /// each, from the dots kept.
    #[target_feature(enable = "sse2")]
    #[inline]
    fn extremes_f32(v: &[V2<f32>], u: V2<f32>, t: V2<f32>) -> [usize; 4] {
        let (du, dt) = (_mm_setr_ps(u.x, u.y, u.x, u.y), _mm_setr_ps(t.x, t.y, t.x, t.y));
        let load = |p: &[V2<f32>]| _mm_setr_ps(p[0].x, p[0].y, p[1].x, p[1].y);
        // Products of vertices 0 to 3 (two registers), summed in pairs.
        let dots = |(low, high): (__m128, __m128), d: __m128| {
            let (low, high) = (_mm_mul_ps(low, d), _mm_mul_ps(high, d));
            _mm_add_ps(_mm_shuffle_ps::<0b10_00_10_00>(low, high), _mm_shuffle_ps::<0b11_01_11_01>(low, high))
        };
        let mut kept = [[_mm_setzero_ps(); EXTREMES_MAX / 4]; 2];
        let mut top = [_mm_set1_ps(f32::NEG_INFINITY); 2];
        let mut bottom = [_mm_set1_ps(f32::INFINITY); 2];
        for (k, c) in v.chunks_exact(4).take(EXTREMES_MAX / 4).enumerate() {
            let points = (load(&c[..2]), load(&c[2..]));
            let (x, y) = (dots(points, du), dots(points, dt));
            kept[0][k] = x;
            kept[1][k] = y;
            // A NaN dot leaves each extreme as it was (the second operand).
            top = [_mm_max_ps(x, top[0]), _mm_max_ps(y, top[1])];
            bottom = [_mm_min_ps(x, bottom[0]), _mm_min_ps(y, bottom[1])];
        }
        let highest = |m: __m128| {
            let m = _mm_max_ps(m, _mm_shuffle_ps::<0b01_00_11_10>(m, m));
            _mm_cvtss_f32(_mm_max_ps(m, _mm_shuffle_ps::<0b10_11_00_01>(m, m)))
        };
        let lowest = |m: __m128| {
            let m = _mm_min_ps(m, _mm_shuffle_ps::<0b01_00_11_10>(m, m));
            _mm_cvtss_f32(_mm_min_ps(m, _mm_shuffle_ps::<0b10_11_00_01>(m, m)))
        };
        let whole = (v.len() / 4).min(EXTREMES_MAX / 4);
        let lanes = [top.map(highest), bottom.map(lowest)];
        first_at_extremes((v, 4 * whole), [u, t], lanes, |axis, extreme| {
            let wanted = _mm_set1_ps(extreme);
            // Every kept register, a fixed count the compiler unrolls with
            // constant shifts; slots past the vertices' masked off.
            let bits = kept[axis].iter().enumerate().fold(0u64, |bits, (k, &quad)| {
                bits | u64::from(_mm_movemask_ps(_mm_cmpeq_ps(quad, wanted)) as u32) << (4 * k)
            }) & low_bits(4 * whole);
            (bits != 0).then(|| bits.trailing_zeros() as usize)
        })
    }

    /// [`extremes_f32`] in two lanes, as [`running_max_f64`].
    #[target_feature(enable = "sse2")]
    #[inline]
    fn extremes_f64(v: &[V2<f64>], u: V2<f64>, t: V2<f64>) -> [usize; 4] {
        let (du, dt) = (_mm_setr_pd(u.x, u.y), _mm_setr_pd(t.x, t.y));
        let load = |p: V2<f64>| _mm_setr_pd(p.x, p.y);
        // The products (x dx, y dy) of two vertices, summed across.
        let dots = |(p, q): (__m128d, __m128d), d: __m128d| {
            let (p, q) = (_mm_mul_pd(p, d), _mm_mul_pd(q, d));
            _mm_add_pd(_mm_unpacklo_pd(p, q), _mm_unpackhi_pd(p, q))
        };
        let mut kept = [[_mm_setzero_pd(); EXTREMES_MAX / 2]; 2];
        let mut top = [_mm_set1_pd(f64::NEG_INFINITY); 2];
        let mut bottom = [_mm_set1_pd(f64::INFINITY); 2];
        for (k, c) in v.chunks_exact(2).take(EXTREMES_MAX / 2).enumerate() {
            let points = (load(c[0]), load(c[1]));
            let (x, y) = (dots(points, du), dots(points, dt));
            kept[0][k] = x;
            kept[1][k] = y;
            top = [_mm_max_pd(x, top[0]), _mm_max_pd(y, top[1])];
            bottom = [_mm_min_pd(x, bottom[0]), _mm_min_pd(y, bottom[1])];
        }
        let highest = |m: __m128d| _mm_cvtsd_f64(_mm_max_pd(m, _mm_shuffle_pd::<0b01>(m, m)));
        let lowest = |m: __m128d| _mm_cvtsd_f64(_mm_min_pd(m, _mm_shuffle_pd::<0b01>(m, m)));
        let whole = (v.len() / 2).min(EXTREMES_MAX / 2);
        let lanes = [top.map(highest), bottom.map(lowest)];
        first_at_extremes((v, 2 * whole), [u, t], lanes, |axis, extreme| {
            let equal = equal_f64(&kept[axis], whole, _mm_set1_pd(extreme));
            (equal != 0).then(|| equal.trailing_zeros() as usize)
        })
    }

    /// [`extremes_f64`] in four lanes, as [`wide_max_f64`]: the dots of
    /// vertices 0 to 3 come out of their shuffles as 0, 2, 1, 3 and are put
    /// back in order before they are kept.
    #[target_feature(enable = "avx,avx2")]
    #[inline]
    fn wide_extremes_f64(v: &[V2<f64>], u: V2<f64>, t: V2<f64>) -> [usize; 4] {
        let (ux, uy, tx, ty) = (_mm256_set1_pd(u.x), _mm256_set1_pd(u.y), _mm256_set1_pd(t.x), _mm256_set1_pd(t.y));
        let mut kept = [[_mm256_setzero_pd(); WIDE_SCAN_MAX / 4]; 2];
        let mut top = [_mm256_set1_pd(f64::NEG_INFINITY); 2];
        let mut bottom = [_mm256_set1_pd(f64::INFINITY); 2];
        for (k, c) in v.chunks_exact(4).take(WIDE_SCAN_MAX / 4).enumerate() {
            let a = _mm256_setr_pd(c[0].x, c[0].y, c[1].x, c[1].y);
            let b = _mm256_setr_pd(c[2].x, c[2].y, c[3].x, c[3].y);
            let (xs, ys) = (_mm256_unpacklo_pd(a, b), _mm256_unpackhi_pd(a, b));
            let along = |dx: __m256d, dy: __m256d| {
                let sums = _mm256_add_pd(_mm256_mul_pd(xs, dx), _mm256_mul_pd(ys, dy));
                _mm256_permute4x64_pd::<0b11_01_10_00>(sums)
            };
            let (x, y) = (along(ux, uy), along(tx, ty));
            kept[0][k] = x;
            kept[1][k] = y;
            top = [_mm256_max_pd(x, top[0]), _mm256_max_pd(y, top[1])];
            bottom = [_mm256_min_pd(x, bottom[0]), _mm256_min_pd(y, bottom[1])];
        }
        let highest = |m: __m256d| {
            let m = _mm_max_pd(_mm256_castpd256_pd128(m), _mm256_extractf128_pd::<1>(m));
            _mm_cvtsd_f64(_mm_max_pd(m, _mm_shuffle_pd::<0b01>(m, m)))
        };
        let lowest = |m: __m256d| {
            let m = _mm_min_pd(_mm256_castpd256_pd128(m), _mm256_extractf128_pd::<1>(m));
            _mm_cvtsd_f64(_mm_min_pd(m, _mm_shuffle_pd::<0b01>(m, m)))
        };
        let whole = (v.len() / 4).min(WIDE_SCAN_MAX / 4);
        let lanes = [top.map(highest), bottom.map(lowest)];
        first_at_extremes((v, 4 * whole), [u, t], lanes, |axis, extreme| {
            let wanted = _mm256_set1_pd(extreme);
            let bits = kept[axis].iter().enumerate().fold(0u64, |bits, (k, &quad)| {
                bits | u64::from(_mm256_movemask_pd(_mm256_cmp_pd::<_CMP_EQ_OQ>(quad, wanted)) as u32) << (4 * k)
            }) & low_bits(4 * whole);
            (bits != 0).then(|| bits.trailing_zeros() as usize)
        })
    }

    /// The first vertex at each extreme of the dots with `u` and `t`, as
    /// `[max u, max t, min u, min t]`: each extreme of the lanes
    /// (`lanes[0]` the largest along `u` and `t`, `lanes[1]` the least)
    /// taken on over the vertices of `v` past the lanes' `covered`, then
    /// found in the lanes (`in_lanes`, the first kept dot equal to it along
    /// an axis) or else past them.
    #[inline(always)]
    fn first_at_extremes<R: super::Real>(
        (v, covered): (&[V2<R>], usize),
        [u, t]: [V2<R>; 2],
        lanes: [[R; 2]; 2],
        in_lanes: impl Fn(usize, R) -> Option<usize>,
    ) -> [usize; 4] {
        let tail = v.get(covered..).unwrap_or_default();
        #[inline(always)]
        fn first<R: super::Real>(
            (tail, covered): (&[V2<R>], usize),
            d: V2<R>,
            (axis, least): (usize, bool),
            lane: R,
            in_lanes: &impl Fn(usize, R) -> Option<usize>,
        ) -> usize {
            let extreme = tail.iter().fold(lane, |m, p| {
                let dot = p.dot(d);
                core::hint::select_unpredictable(if least { dot < m } else { dot > m }, dot, m)
            });
            in_lanes(axis, extreme).unwrap_or_else(|| first_equal(tail, covered, d, extreme))
        }
        // Written out, not `array::from_fn`, whose closure was called out
        // of line four times a polygon.
        let tail = (tail, covered);
        [
            first(tail, u, (0, false), lanes[0][0], &in_lanes),
            first(tail, t, (1, false), lanes[0][1], &in_lanes),
            first(tail, u, (0, true), lanes[1][0], &in_lanes),
            first(tail, t, (1, true), lanes[1][1], &in_lanes),
        ]
    }

    /// The first lane whose bit `mask` sets, over `blocks` of `lanes` lanes
    /// each (at most 64 lanes in all): every block's mask gathered in one
    /// word, the first its lowest bit, with no branch a block, whose exit
    /// the predictor would miss.
    #[inline(always)]
    fn first_match<T: Copy>(blocks: &[T], lanes: usize, mask: impl Fn(T) -> i32) -> Option<usize> {
        let matches = blocks.iter().enumerate().fold(0u64, |m, (k, &b)| m | u64::from(mask(b) as u32) << (lanes * k));
        (matches != 0).then(|| matches.trailing_zeros() as usize)
    }

    /// One bit a vertex, set where its dot (of the first `whole` kept)
    /// equals `wanted`. Every 16 comparisons are packed into one mask moved
    /// out of the vector unit, not one mask a pair of dots: moving the masks
    /// out pair by pair was much of the f64 scan. In f32, whose masks carry
    /// four dots each, the packing did not pay.
    #[target_feature(enable = "sse2")]
    #[inline]
    fn equal_f64(kept: &[__m128d; 32], whole: usize, wanted: __m128d) -> u64 {
        let mut bits = 0u64;
        for (g, eight) in kept.chunks_exact(8).take(whole.div_ceil(8)).enumerate() {
            let equal = |i: usize| _mm_castpd_ps(_mm_cmpeq_pd(eight[i], wanted));
            let halves = |i: usize| _mm_castps_si128(_mm_shuffle_ps::<0b11_01_11_01>(equal(i), equal(i + 1)));
            let (low, high) = (_mm_packs_epi32(halves(0), halves(2)), _mm_packs_epi32(halves(4), halves(6)));
            bits |= u64::from(_mm_movemask_epi8(_mm_packs_epi16(low, high)) as u16) << (16 * g);
        }
        bits & low_bits(2 * whole)
    }

    /// The lowest `n` bits set (all of them from 64 on): kept slots past
    /// the vertices' hold zeros, which must not match a top of zero.
    #[inline(always)]
    fn low_bits(n: usize) -> u64 {
        if n >= 64 {
            u64::MAX
        } else {
            (1u64 << n) - 1
        }
    }

    /// The first of `tail` (vertices from `start` on) whose dot is `top`;
    /// 0 when none is (every dot NaN).
    #[inline(always)]
    fn first_equal<R: super::Real>(tail: &[V2<R>], start: usize, d: V2<R>, top: R) -> usize {
        tail.iter().position(|p| p.dot(d) == top).map_or(0, |j| start + j)
    }

    #[inline(always)]
    pub fn least_dots8_f32(nx: &[f32; 8], ny: &[f32; 8], xs: &[f32; 8], ys: &[f32; 8]) -> [f32; 8] {
        // SAFETY: as above.
        unsafe { least_dots8_sse_f32(nx, ny, xs, ys) }
    }

    #[inline(always)]
    pub fn least_dots8_f64<const WIDE: bool>(nx: &[f64; 8], ny: &[f64; 8], xs: &[f64; 8], ys: &[f64; 8]) -> [f64; 8] {
        if WIDE && wide() {
            // SAFETY: `wide` found AVX2 (and with it AVX) on this processor,
            // its wide registers saved by the operating system.
            return unsafe { least_dots8_wide_f64(nx, ny, xs, ys) };
        }
        // SAFETY: as above.
        unsafe { least_dots8_sse_f64(nx, ny, xs, ys) }
    }

    /// `f`, compiled for AVX2 and run so where [`wide`] finds it (else as
    /// it is): `f` then asks for wide lanes where it has use for them
    /// ([`Real::wide_lanes`](super::Real::wide_lanes)). Only a small `f`
    /// gains: a whole query compiled so spilled its registers and called
    /// its helpers out of line.
    #[inline(always)]
    pub fn run_wide<T>(f: impl FnOnce() -> T) -> T {
        #[target_feature(enable = "avx,avx2")]
        #[inline(never)]
        fn compiled_wide<T>(f: impl FnOnce() -> T) -> T {
            f()
        }
        if wide() {
            // SAFETY: as in `least_dots8_f64`.
            return unsafe { compiled_wide(f) };
        }
        f()
    }

    #[inline(always)]
    pub fn scaled_separations_f32<const K: usize>(nx: &[f32; K], ny: &[f32; K], least: &[f32; K]) -> [f32; K] {
        // SAFETY: as above.
        unsafe { scaled_separations_sse_f32(nx, ny, least) }
    }

    #[inline(always)]
    pub fn scaled_separations_f64<const K: usize>(nx: &[f64; K], ny: &[f64; K], least: &[f64; K]) -> [f64; K] {
        // SAFETY: as above.
        unsafe { scaled_separations_sse_f64(nx, ny, least) }
    }

    /// `scaled_separation` four lanes at a time, its branches as masks:
    /// `maxps(a, b)` is `if a > b { a } else { b }`, as `Real::max`.
    #[target_feature(enable = "sse2")]
    #[inline]
    fn scaled_separations_sse_f32<const K: usize>(nx: &[f32; K], ny: &[f32; K], least: &[f32; K]) -> [f32; K] {
        let mut out = [0.0; K];
        let quad = |a: &[f32; K], k: usize| _mm_setr_ps(a[k], a[k + 1], a[k + 2], a[k + 3]);
        let (sign, zero, one) = (_mm_set1_ps(-0.0), _mm_setzero_ps(), _mm_set1_ps(1.0));
        for k in (0..K).step_by(4) {
            let (x, y) = (quad(nx, k), quad(ny, k));
            let m = _mm_max_ps(_mm_andnot_ps(sign, x), _mm_andnot_ps(sign, y));
            let inv = _mm_div_ps(one, m);
            let (sx, sy) = (_mm_mul_ps(x, inv), _mm_mul_ps(y, inv));
            let scaled = _mm_mul_ps(m, _mm_sqrt_ps(_mm_add_ps(_mm_mul_ps(sx, sx), _mm_mul_ps(sy, sy))));
            // A zero normal's scaled length is NaN here, not zero as in the
            // scalar function: either way no separation is kept for it.
            let length = scaled;
            let s = _mm_div_ps(quad(least, k), length);
            let kept = _mm_cmpgt_ps(length, zero);
            let s = _mm_or_ps(_mm_and_ps(kept, s), _mm_andnot_ps(kept, _mm_set1_ps(f32::NEG_INFINITY)));
            // SAFETY: one register of four f32 lanes is four f32s, in lane
            // order, and every bit pattern is a valid f32.
            let lanes = unsafe { core::mem::transmute::<__m128, [f32; 4]>(s) };
            out[k..k + 4].copy_from_slice(&lanes);
        }
        out
    }

    /// [`scaled_separations_sse_f32`] two lanes at a time.
    #[target_feature(enable = "sse2")]
    #[inline]
    fn scaled_separations_sse_f64<const K: usize>(nx: &[f64; K], ny: &[f64; K], least: &[f64; K]) -> [f64; K] {
        let mut out = [0.0; K];
        let pair = |a: &[f64; K], k: usize| _mm_setr_pd(a[k], a[k + 1]);
        let (sign, zero, one) = (_mm_set1_pd(-0.0), _mm_setzero_pd(), _mm_set1_pd(1.0));
        for k in (0..K).step_by(2) {
            let (x, y) = (pair(nx, k), pair(ny, k));
            let m = _mm_max_pd(_mm_andnot_pd(sign, x), _mm_andnot_pd(sign, y));
            let inv = _mm_div_pd(one, m);
            let (sx, sy) = (_mm_mul_pd(x, inv), _mm_mul_pd(y, inv));
            let scaled = _mm_mul_pd(m, _mm_sqrt_pd(_mm_add_pd(_mm_mul_pd(sx, sx), _mm_mul_pd(sy, sy))));
            // A zero normal's scaled length is NaN here, not zero as in the
            // scalar function: either way no separation is kept for it.
            let length = scaled;
            let s = _mm_div_pd(pair(least, k), length);
            let kept = _mm_cmpgt_pd(length, zero);
            let s = _mm_or_pd(_mm_and_pd(kept, s), _mm_andnot_pd(kept, _mm_set1_pd(f64::NEG_INFINITY)));
            // SAFETY: one register of two f64 lanes is two f64s, in lane
            // order, and every bit pattern is a valid f64.
            let lanes = unsafe { core::mem::transmute::<__m128d, [f64; 2]>(s) };
            out[k..k + 2].copy_from_slice(&lanes);
        }
        out
    }

    /// The dots of vertices 0 to 3 and 4 to 7, four lanes each.
    #[target_feature(enable = "sse2")]
    #[inline]
    fn quads_f32(v: &[V2<f32>; 8], d: V2<f32>) -> (__m128, __m128) {
        let (dx, dy) = (_mm_set1_ps(d.x), _mm_set1_ps(d.y));
        let dots = |k: usize| {
            let xs = _mm_setr_ps(v[k].x, v[k + 1].x, v[k + 2].x, v[k + 3].x);
            let ys = _mm_setr_ps(v[k].y, v[k + 1].y, v[k + 2].y, v[k + 3].y);
            _mm_add_ps(_mm_mul_ps(xs, dx), _mm_mul_ps(ys, dy))
        };
        (dots(0), dots(4))
    }

    /// The dots of vertex pairs (0, 1), (2, 3), (4, 5), (6, 7), two lanes each.
    #[target_feature(enable = "sse2")]
    #[inline]
    fn pairs_f64(v: &[V2<f64>; 8], d: V2<f64>) -> [__m128d; 4] {
        let dd = _mm_setr_pd(d.x, d.y);
        // The products (x dx, y dy) of two vertices, summed across: their dots.
        let dots = |k: usize| {
            let p = _mm_mul_pd(_mm_setr_pd(v[k].x, v[k].y), dd);
            let q = _mm_mul_pd(_mm_setr_pd(v[k + 1].x, v[k + 1].y), dd);
            _mm_add_pd(_mm_unpacklo_pd(p, q), _mm_unpackhi_pd(p, q))
        };
        [dots(0), dots(2), dots(4), dots(6)]
    }

    /// Eight axes in two registers of four lanes, the vertices broadcast
    /// one at a time: a multiply-add and a minimum a vertex for four axes,
    /// and no sum across lanes. `_mm_min_ps(dot, least)` keeps `least`
    /// unless `dot` is smaller, as the scalar fold does.
    #[target_feature(enable = "sse2")]
    #[inline]
    fn least_dots8_sse_f32(nx: &[f32; 8], ny: &[f32; 8], xs: &[f32; 8], ys: &[f32; 8]) -> [f32; 8] {
        let quad = |a: &[f32; 8], k: usize| _mm_setr_ps(a[k], a[k + 1], a[k + 2], a[k + 3]);
        let (nx0, nx1, ny0, ny1) = (quad(nx, 0), quad(nx, 4), quad(ny, 0), quad(ny, 4));
        let mut least = [_mm_set1_ps(f32::INFINITY); 2];
        for (&x, &y) in xs.iter().zip(ys) {
            let (x, y) = (_mm_set1_ps(x), _mm_set1_ps(y));
            least[0] = _mm_min_ps(_mm_add_ps(_mm_mul_ps(nx0, x), _mm_mul_ps(ny0, y)), least[0]);
            least[1] = _mm_min_ps(_mm_add_ps(_mm_mul_ps(nx1, x), _mm_mul_ps(ny1, y)), least[1]);
        }
        // SAFETY: two registers of four f32 lanes are eight f32s, in lane
        // order, and every bit pattern is a valid f32.
        unsafe { core::mem::transmute::<[__m128; 2], [f32; 8]>(least) }
    }

    /// [`least_dots8_sse_f32`]'s layout in f64, four axes a register: a
    /// broadcast vertex costs a multiply, an add and a minimum for four
    /// axes, half the operations of two lanes. Worth it only inlined into
    /// code compiled for AVX: called out of SSE2 code, the arrays crossing
    /// the boundary cost more than it saves.
    #[target_feature(enable = "avx")]
    #[inline]
    fn least_dots8_wide_f64(nx: &[f64; 8], ny: &[f64; 8], xs: &[f64; 8], ys: &[f64; 8]) -> [f64; 8] {
        let quad = |a: &[f64; 8], k: usize| _mm256_setr_pd(a[k], a[k + 1], a[k + 2], a[k + 3]);
        let (nx0, nx1, ny0, ny1) = (quad(nx, 0), quad(nx, 4), quad(ny, 0), quad(ny, 4));
        let mut least = [_mm256_set1_pd(f64::INFINITY); 2];
        for (&x, &y) in xs.iter().zip(ys) {
            let (x, y) = (_mm256_set1_pd(x), _mm256_set1_pd(y));
            least[0] = _mm256_min_pd(_mm256_add_pd(_mm256_mul_pd(nx0, x), _mm256_mul_pd(ny0, y)), least[0]);
            least[1] = _mm256_min_pd(_mm256_add_pd(_mm256_mul_pd(nx1, x), _mm256_mul_pd(ny1, y)), least[1]);
        }
        // SAFETY: two registers of four f64 lanes are eight f64s, in lane
        // order, and every bit pattern is a valid f64.
        unsafe { core::mem::transmute::<[__m256d; 2], [f64; 8]>(least) }
    }

    /// Two lanes: an axis at a time, its eight dots in four registers
    /// folded to one. With two lanes a register, broadcasting each vertex
    /// (as [`least_dots8_sse_f32`] does) saves no work and spills. The
    /// minimum is the scalar fold's, the sign of a zero aside, which no
    /// reach's use tells apart (`> 0`, `0 - s`).
    #[target_feature(enable = "sse2")]
    #[inline]
    fn least_dots8_sse_f64(nx: &[f64; 8], ny: &[f64; 8], xs: &[f64; 8], ys: &[f64; 8]) -> [f64; 8] {
        let pair = |a: &[f64; 8], k: usize| _mm_setr_pd(a[k], a[k + 1]);
        let (x, y) = (
            [pair(xs, 0), pair(xs, 2), pair(xs, 4), pair(xs, 6)],
            [pair(ys, 0), pair(ys, 2), pair(ys, 4), pair(ys, 6)],
        );
        let axis = |i: usize| {
            let (dx, dy) = (_mm_set1_pd(nx[i]), _mm_set1_pd(ny[i]));
            let dot = |k: usize| _mm_add_pd(_mm_mul_pd(dx, x[k]), _mm_mul_pd(dy, y[k]));
            let m = _mm_min_pd(_mm_min_pd(dot(0), dot(1)), _mm_min_pd(dot(2), dot(3)));
            _mm_cvtsd_f64(_mm_min_pd(m, _mm_shuffle_pd::<0b01>(m, m)))
        };
        // Spelt out, not `from_fn`: the compiler called that closure out of
        // line at some call sites, once an axis.
        [axis(0), axis(1), axis(2), axis(3), axis(4), axis(5), axis(6), axis(7)]
    }

    #[target_feature(enable = "sse2")]
    #[inline]
    fn dots8_f32(v: &[V2<f32>; 8], d: V2<f32>) -> usize {
        let (low, high) = quads_f32(v, d);
        let m = _mm_max_ps(low, high);
        let m = _mm_max_ps(m, _mm_shuffle_ps::<0b01_00_11_10>(m, m));
        let m = _mm_max_ps(m, _mm_shuffle_ps::<0b10_11_00_01>(m, m));
        first_lane(_mm_movemask_ps(_mm_cmpeq_ps(low, m)) | (_mm_movemask_ps(_mm_cmpeq_ps(high, m)) << 4))
    }

    #[target_feature(enable = "sse2")]
    #[inline]
    fn dots8_f64(v: &[V2<f64>; 8], d: V2<f64>) -> usize {
        let [a, b, c, e] = pairs_f64(v, d);
        let m = _mm_max_pd(_mm_max_pd(a, b), _mm_max_pd(c, e));
        let m = _mm_max_pd(m, _mm_shuffle_pd::<0b01>(m, m));
        let lanes = |x: __m128d, at: u32| _mm_movemask_pd(_mm_cmpeq_pd(x, m)) << at;
        first_lane(lanes(a, 0) | lanes(b, 2) | lanes(c, 4) | lanes(e, 6))
    }
}

/// Work written once for each scalar type, as a `const fn` must be (it
/// cannot do arithmetic through [`Real`]), which generic code runs as
/// `R::per_type::<W>(input)`: that is [`f32`](Self::f32) or
/// [`f64`](Self::f64), chosen when the program is compiled. The checks of a
/// point and a length, a polygon's framing and a slice's constructor are
/// written so, in the layers above; this one knows only that there are two
/// types.
pub trait PerType {
    type Input<'a, R: Real>;
    type Output<R: Real>;
    fn f32(input: Self::Input<'_, f32>) -> Self::Output<f32>;
    fn f64(input: Self::Input<'_, f64>) -> Self::Output<f64>;
}

/// A floating-point scalar gjk2d computes in: `f32` or `f64`.
///
/// Sealed: the error bounds gjk2d states are derived for IEEE binary32 and
/// binary64, so no other type may stand in.
pub trait Real:
    sealed::Sealed
    + Copy
    + Debug
    + Default
    + PartialOrd
    + PartialEq
    + Add<Output = Self>
    + Sub<Output = Self>
    + Mul<Output = Self>
    + Div<Output = Self>
    + Neg<Output = Self>
    + AddAssign
    + SubAssign
    + MulAssign
    + 'static
{
    /// The glam vector users pass in and get back: `Vec2` for f32, `DVec2` for f64.
    type Vector: Copy + Debug + PartialEq + Default;

    const ZERO: Self;
    const ONE: Self;
    const TWO: Self;
    const HALF: Self;
    /// Machine epsilon (the gap between 1 and the next representable value).
    const EPSILON: Self;
    const INFINITY: Self;
    /// The least positive normal number.
    const MIN_POSITIVE: Self;
    /// Largest coordinate magnitude a shape may have. Squares of differences of
    /// such coordinates, summed, stay finite, so no query can overflow to inf/NaN.
    const MAX_COORDINATE: Self;

    fn from_f64(value: f64) -> Self;
    fn to_f64(self) -> f64;
    fn from_u32(value: u32) -> Self;
    fn sqrt(self) -> Self;
    fn abs(self) -> Self;
    /// `(sin, cos)`. For f32 computed in f32 alone (module `trig`): libm's
    /// `sinf`/`cosf` go through soft f64 on microcontrollers.
    fn sin_cos(self) -> (Self, Self);
    fn atan2(self, x: Self) -> Self;
    fn is_finite(self) -> bool;
    /// The sign bit (set for -0.0 too).
    fn is_sign_negative(self) -> bool;
    /// Veltkamp's splitter, `2^ceil(p/2) + 1` for a `p`-bit significand: splits
    /// a value into two halves whose products are exact (Dekker's
    /// two-product), so exact predicates need no fma. An fma is software on
    /// Cortex-M4F for f32 (libm's fmaf goes through soft f64, which f32
    /// firmware would then link).
    const SPLITTER: Self;

    fn vector(x: Self, y: Self) -> Self::Vector;
    fn components(v: Self::Vector) -> (Self, Self);

    #[inline(always)]
    fn max(self, other: Self) -> Self {
        if self > other {
            self
        } else {
            other
        }
    }
    #[inline(always)]
    fn min(self, other: Self) -> Self {
        if self < other {
            self
        } else {
            other
        }
    }
}

macro_rules! impl_real {
    ($t:ty, $vec:ty, $sqrt:path, $sin_cos:path, $atan2:path, $splitter:expr, $max_coord:expr) => {
        impl Real for $t {
            type Vector = $vec;
            const ZERO: Self = 0.0;
            const ONE: Self = 1.0;
            const TWO: Self = 2.0;
            const HALF: Self = 0.5;
            const EPSILON: Self = <$t>::EPSILON;
            const INFINITY: Self = <$t>::INFINITY;
            const MIN_POSITIVE: Self = <$t>::MIN_POSITIVE;
            const MAX_COORDINATE: Self = $max_coord;
            const SPLITTER: Self = $splitter;

            #[inline(always)]
            fn from_f64(value: f64) -> Self {
                value as $t
            }
            #[inline(always)]
            fn to_f64(self) -> f64 {
                self as f64
            }
            #[inline(always)]
            fn from_u32(value: u32) -> Self {
                value as $t
            }
            #[inline(always)]
            fn sqrt(self) -> Self {
                $sqrt(self)
            }
            #[inline(always)]
            fn abs(self) -> Self {
                <$t>::abs(self)
            }
            #[inline(always)]
            fn sin_cos(self) -> (Self, Self) {
                $sin_cos(self)
            }
            #[inline(always)]
            fn atan2(self, x: Self) -> Self {
                $atan2(self, x)
            }
            #[inline(always)]
            fn is_finite(self) -> bool {
                <$t>::is_finite(self)
            }
            #[inline(always)]
            fn is_sign_negative(self) -> bool {
                <$t>::is_sign_negative(self)
            }
            #[inline(always)]
            fn vector(x: Self, y: Self) -> Self::Vector {
                <$vec>::new(x, y)
            }
            #[inline(always)]
            fn components(v: Self::Vector) -> (Self, Self) {
                (v.x, v.y)
            }
        }
    };
}

impl_real!(f32, glam::Vec2, crate::hw_sqrt::sqrtf, crate::trig::sin_cos_f32, libm::atan2f, 4097.0, 1.0e15);
impl_real!(f64, glam::DVec2, crate::hw_sqrt::sqrt, sin_cos_f64, libm::atan2, 134_217_729.0, 1.0e150);

/// The separation along an axis's unit normal, from its normal (not unit)
/// and least reach; minus infinity for an axis with no normal (a slot past
/// the last edge), which then never leads.
#[inline(always)]
pub(crate) fn scaled_separation<R: Real>(normal: V2<R>, least: R) -> R {
    // Lengths scaled by the larger component first, so the squares of a
    // tiny polygon's normals neither underflow nor lose their digits.
    let length = scaled_length(normal);
    let s = least / length;
    if length > R::ZERO {
        s
    } else {
        -R::INFINITY
    }
}

/// `|n|`, scaled by the larger component first, so the square of a tiny
/// vector neither underflows nor loses its digits.
#[inline(always)]
fn scaled_length<R: Real>(n: V2<R>) -> R {
    let m = n.x.abs().max(n.y.abs());
    if m > R::ZERO {
        m * (n * (R::ONE / m)).length_squared().sqrt()
    } else {
        R::ZERO
    }
}

/// The smaller of `dot` and `least`, `least` on a tie (and on a NaN): a
/// comparison and a select, which an SSE minimum does in every lane at once.
#[inline(always)]
pub(crate) fn lesser<R: PartialOrd>(dot: R, least: R) -> R {
    if dot < least {
        dot
    } else {
        least
    }
}

/// f64 keeps libm's correctly reduced sine and cosine: f64 code pays for soft
/// double arithmetic anyway where there is no double FPU.
#[inline(always)]
fn sin_cos_f64(x: f64) -> (f64, f64) {
    (libm::sin(x), libm::cos(x))
}

/// The internal 2D vector, generic over the scalar.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct V2<R> {
    pub x: R,
    pub y: R,
}

impl<R: Real> V2<R> {
    #[inline(always)]
    pub const fn new(x: R, y: R) -> Self {
        Self { x, y }
    }
    /// Both coordinates through [`Real`]'s scalar barrier.
    #[inline(always)]
    pub fn scalar_barrier(self) -> Self {
        Self::new(self.x.scalar_barrier(), self.y.scalar_barrier())
    }
    #[inline(always)]
    pub fn zero() -> Self {
        Self::new(R::ZERO, R::ZERO)
    }
    #[inline(always)]
    pub fn from_glam(v: R::Vector) -> Self {
        let (x, y) = R::components(v);
        Self { x, y }
    }
    #[inline(always)]
    pub fn to_glam(self) -> R::Vector {
        R::vector(self.x, self.y)
    }
    #[inline(always)]
    pub fn dot(self, o: Self) -> R {
        self.x * o.x + self.y * o.y
    }
    /// z-component of the 3D cross product: positive when `o` lies
    /// counter-clockwise of `self`.
    #[inline(always)]
    pub fn cross(self, o: Self) -> R {
        self.x * o.y - self.y * o.x
    }
    /// Rotated a quarter turn counter-clockwise.
    #[inline(always)]
    pub fn perp(self) -> Self {
        Self::new(-self.y, self.x)
    }
    /// Rotated a quarter turn clockwise: the outward normal of a
    /// counter-clockwise edge with this direction.
    #[inline(always)]
    pub fn perp_cw(self) -> Self {
        Self::new(self.y, -self.x)
    }
    #[inline(always)]
    pub fn length_squared(self) -> R {
        self.dot(self)
    }
    #[inline(always)]
    pub fn length(self) -> R {
        self.length_squared().sqrt()
    }
    /// Unit vector, or `None` for the zero vector (never a NaN). Divided by
    /// its largest component first, so no square under- or overflows: a
    /// subnormal vector normalises as well as a unit one, and an axis-aligned
    /// one gives exactly (0, +-1) or (+-1, 0).
    #[inline(always)]
    pub fn try_normalize(self) -> Option<Self> {
        self.try_length_and_unit().map(|(_, unit)| unit)
    }
    /// [`try_normalize`](Self::try_normalize) inlined everywhere: for EPA's
    /// edge normals, one per support point, each of which would otherwise
    /// pay for a call.
    #[inline(always)]
    pub fn try_normalize_inlined(self) -> Option<Self> {
        self.try_length_and_unit_inlined().map(|(_, unit)| unit)
    }
    /// The length and the unit vector, with the care of
    /// [`try_normalize`](Self::try_normalize): one definition for both.
    ///
    /// Not inlined on bare metal, whose flash is scarce: called from a
    /// dozen places, one copy serves them all.
    #[cfg_attr(target_os = "none", inline(never))]
    #[cfg_attr(not(target_os = "none"), inline)]
    pub fn try_length_and_unit(self) -> Option<(R, Self)> {
        self.try_length_and_unit_inlined()
    }
    #[inline(always)]
    fn try_length_and_unit_inlined(self) -> Option<(R, Self)> {
        let m = self.max_abs();
        if !(m > R::ZERO && m.is_finite()) {
            return None;
        }
        // The common case first: above eps^2 the square is a normal number
        // (coordinates are bounded, so it cannot overflow either).
        if m >= R::EPSILON * R::EPSILON {
            let len = self.length();
            return Some((len, V2::new(self.x / len, self.y / len)));
        }
        let u = V2::new(self.x / m, self.y / m);
        let len = u.length();
        Some((m * len, V2::new(u.x / len, u.y / len)))
    }
    #[inline(always)]
    pub fn is_finite(self) -> bool {
        self.x.is_finite() && self.y.is_finite()
    }
    #[inline(always)]
    pub fn max_abs(self) -> R {
        self.x.abs().max(self.y.abs())
    }
    /// `|x| + |y|`: at least the length, with no square root, for margins
    /// of rounding.
    #[inline(always)]
    pub fn l1(self) -> R {
        self.x.abs() + self.y.abs()
    }
}

impl<R: Real> Add for V2<R> {
    type Output = Self;
    #[inline(always)]
    fn add(self, o: Self) -> Self {
        Self::new(self.x + o.x, self.y + o.y)
    }
}
impl<R: Real> Sub for V2<R> {
    type Output = Self;
    #[inline(always)]
    fn sub(self, o: Self) -> Self {
        Self::new(self.x - o.x, self.y - o.y)
    }
}
impl<R: Real> Neg for V2<R> {
    type Output = Self;
    #[inline(always)]
    fn neg(self) -> Self {
        Self::new(-self.x, -self.y)
    }
}
impl<R: Real> Mul<R> for V2<R> {
    type Output = Self;
    #[inline(always)]
    fn mul(self, s: R) -> Self {
        Self::new(self.x * s, self.y * s)
    }
}

#[cfg(all(test, target_arch = "x86_64", target_feature = "sse2"))]
mod tests {
    extern crate std;
    use super::lesser;

    /// The scalar fold that hosts without SSE2 run: every axis folds the
    /// vertices in order, keeping the smaller.
    fn folded<R: Copy + PartialOrd + core::ops::Mul<Output = R> + core::ops::Add<Output = R>>(
        nx: &[R; 8],
        ny: &[R; 8],
        xs: &[R; 8],
        ys: &[R; 8],
        infinity: R,
    ) -> [R; 8] {
        core::array::from_fn(|i| (0..8).fold(infinity, |least, j| lesser(nx[i] * xs[j] + ny[i] * ys[j], least)))
    }

    /// Small integers (exact products, many ties and zeros of both signs)
    /// half the time, spread values otherwise, and a large one now and then:
    /// finite, as bounded coordinates and their edges are.
    fn values(seed: &mut u64) -> [f64; 8] {
        core::array::from_fn(|_| {
            *seed = seed.wrapping_mul(6364136223846793005).wrapping_add(1442695040888963407);
            let bits = *seed >> 11;
            match bits % 16 {
                0 => -0.0,
                1 => 1e15,
                2..=8 => (bits >> 8) as f64 % 7.0 - 3.0,
                _ => ((bits >> 4) as f64 / (1u64 << 49) as f64 - 0.5) * 1e3,
            }
        })
    }

    #[test]
    fn sse_minima_are_the_scalar_folds() {
        let mut seed = 7;
        for _ in 0..20_000 {
            let [nx, ny, xs, ys] = [0; 4].map(|_| values(&mut seed));
            // f32: the same bits, zeros' signs included.
            let single = |a: [f64; 8]| a.map(|x| x as f32);
            let (nx32, ny32, xs32, ys32) = (single(nx), single(ny), single(xs), single(ys));
            let lanes = super::sse2::least_dots8_f32(&nx32, &ny32, &xs32, &ys32);
            let scalar = folded(&nx32, &ny32, &xs32, &ys32, f32::INFINITY);
            assert_eq!(lanes.map(f32::to_bits), scalar.map(f32::to_bits), "{nx32:?} {ny32:?} {xs32:?} {ys32:?}");
            // f64: the same values (a tree of minima may differ in a zero's
            // sign).
            let lanes = super::sse2::least_dots8_f64::<false>(&nx, &ny, &xs, &ys);
            let scalar = folded(&nx, &ny, &xs, &ys, f64::INFINITY);
            assert_eq!(lanes, scalar, "{nx:?} {ny:?} {xs:?} {ys:?}");
            // Four lanes, where the processor has them (else two again):
            // the scalar fold's order, so its bits.
            let wide = super::sse2::least_dots8_f64::<true>(&nx, &ny, &xs, &ys);
            if super::sse2::wide() {
                assert_eq!(wide.map(f64::to_bits), scalar.map(f64::to_bits), "{nx:?} {ny:?} {xs:?} {ys:?}");
            }
            assert_eq!(wide, scalar, "{nx:?} {ny:?} {xs:?} {ys:?}");
        }
    }

    /// The first vertex of largest dot product, by a scalar fold.
    fn scalar_scan<R: super::Real>(v: &[super::V2<R>], d: super::V2<R>) -> usize {
        let first = |(best, top): (usize, R), (i, p): (usize, &super::V2<R>)| {
            let dot = p.dot(d);
            if dot > top {
                (i, dot)
            } else {
                (best, top)
            }
        };
        v.iter().enumerate().fold((0, -R::INFINITY), first).0
    }

    /// The SIMD support scans (f64's in SSE2, and in AVX2 where the
    /// processor has it; f32's in SSE2) give the scalar scan's vertex: the
    /// first of the largest dots, over every length up to past the wide
    /// scan's, with many ties.
    #[test]
    fn simd_scans_find_the_scalar_scans_vertex() {
        use super::V2;
        let mut seed = 5;
        let mut wide_ran = 0;
        for round in 0..40_000 {
            let len: usize = 1 + round % 72;
            let coordinates: std::vec::Vec<f64> = (0..len.div_ceil(4) + 1).flat_map(|_| values(&mut seed)).collect();
            let v: std::vec::Vec<V2<f64>> =
                (0..len).map(|i| V2::new(coordinates[2 * i], coordinates[2 * i + 1])).collect();
            let d = values(&mut seed);
            let d = V2::new(d[0], d[1]);
            let (two, four) = super::sse2::both_f64(&v, d);
            let expected = scalar_scan(&v, d);
            assert_eq!(two, expected, "{v:?} {d:?}");
            if let Some(four) = four {
                assert_eq!(four, expected, "{v:?} {d:?}");
                wide_ran += 1;
            }
            // The same in f32, whose values round to ties more often still.
            let (v, d) = (
                v.iter().map(|p| V2::new(p.x as f32, p.y as f32)).collect::<std::vec::Vec<_>>(),
                V2::new(d.x as f32, d.y as f32),
            );
            assert_eq!(super::sse2::first_max_dot_f32(&v, d), scalar_scan(&v, d), "{v:?} {d:?}");
        }
        std::println!("the wide scan ran {wide_ran} times");
    }

    /// The four supports of one SIMD pass are the scalar scan's along `u`,
    /// `t`, `-u` and `-t`, in f64 and f32, over every length up to past
    /// the lanes' most (the rest read one by one), with many ties (values drawn from few, zeros of both
    /// signs among them).
    #[test]
    fn extreme_dots_are_the_scalar_scans_vertices() {
        use super::V2;
        let mut seed = 13;
        for round in 0..40_000 {
            let len: usize = 1 + round % (super::sse2::EXTREMES_MAX + 8);
            let coordinates: std::vec::Vec<f64> = (0..len.div_ceil(4) + 1).flat_map(|_| values(&mut seed)).collect();
            let v: std::vec::Vec<V2<f64>> =
                (0..len).map(|i| V2::new(coordinates[2 * i], coordinates[2 * i + 1])).collect();
            let [u, t] = [0; 2].map(|_| values(&mut seed)).map(|d| V2::new(d[0], d[1]));
            let expected = [u, t, -u, -t].map(|d| scalar_scan(&v, d));
            assert_eq!(super::sse2::extreme_dots_f64(&v, u, t), expected, "{v:?} {u:?} {t:?}");
            let single = |p: &V2<f64>| V2::new(p.x as f32, p.y as f32);
            let (v, u, t) = (v.iter().map(single).collect::<std::vec::Vec<_>>(), single(&u), single(&t));
            let expected = [u, t, -u, -t].map(|d| scalar_scan(&v, d));
            assert_eq!(super::sse2::extreme_dots_f32(&v, u, t), expected, "{v:?} {u:?} {t:?}");
        }
    }

    /// Separations in lanes are `scaled_separation`'s, to the bit: zero
    /// normals (minus infinity), zeros of both signs, and normals tiny
    /// enough that their squares would underflow unscaled, or large.
    #[test]
    fn sse_separations_are_the_scalar_ones() {
        use super::{scaled_separation, V2};
        let mut seed = 11;
        for round in 0..20_000 {
            let scale = [1.0, 1e-25, 1e-200, 1e20][round % 4];
            let [nx, ny] = [0; 2].map(|_| values(&mut seed).map(|x| x * scale));
            let least = values(&mut seed);
            let joined =
                |a: [f64; 8]| -> [f64; 16] { core::array::from_fn(|i| a[i % 8] * if i < 8 { 1.0 } else { -2.0 }) };
            let (nx, ny, least) = (joined(nx), joined(ny), joined(least));
            let single = |a: [f64; 16]| a.map(|x| x as f32);
            let (nx32, ny32, least32) = (single(nx), single(ny), single(least));
            let lanes = super::sse2::scaled_separations_f32(&nx32, &ny32, &least32);
            let scalar: [f32; 16] = core::array::from_fn(|k| scaled_separation(V2::new(nx32[k], ny32[k]), least32[k]));
            assert_eq!(lanes.map(f32::to_bits), scalar.map(f32::to_bits), "{nx32:?} {ny32:?} {least32:?}");
            let lanes = super::sse2::scaled_separations_f64(&nx, &ny, &least);
            let scalar: [f64; 16] = core::array::from_fn(|k| scaled_separation(V2::new(nx[k], ny[k]), least[k]));
            assert_eq!(lanes.map(f64::to_bits), scalar.map(f64::to_bits), "{nx:?} {ny:?} {least:?}");
        }
    }
}
