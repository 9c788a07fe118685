//! Square roots in one instruction, where libm does not give one the
//! compiler can see: f32 on hard-float ARM, f32 and f64 on x86-64.
//!
//! libm has no ARM path: on a Cortex-M4F its `sqrtf` is the portable integer
//! algorithm, whose code and table every firmware that normalises a vector
//! carries and whose integer arithmetic every call runs, where the FPU's
//! `vsqrt.f32` is one instruction. Both round correctly, so results stay
//! bit-identical across targets (the golden hash checks it on the M4F).
//!
//! The instruction lives in a two-instruction assembly function: stable
//! Rust does not let inline assembly name FPU registers on the M4F (its
//! single-precision FPU lacks the `vfp2` feature `asm!` asks for), and the
//! hard-float calling convention passes and returns an f32 in `s0`.

// SAFETY: defines one function and nothing else, in its own section; what
// it does is stated where it is called.
#[cfg(all(target_arch = "arm", target_abi = "eabihf"))]
#[allow(unsafe_code)]
mod vsqrt {
    core::arch::global_asm!(
        // Weak: two copies of gjk2d in one firmware share one definition.
        ".section .text.gjk2d_vsqrtf,\"ax\",%progbits",
        ".weak gjk2d_vsqrtf",
        ".type gjk2d_vsqrtf,%function",
        // Assembled in the target's own instruction set (Thumb on Cortex-M,
        // where a function symbol then gets the Thumb bit, ARM on Cortex-R/A):
        // both encode these two instructions.
        ".p2align 2",
        "gjk2d_vsqrtf:",
        // The assembler is not told the target's FPU; VFPv2 is the least
        // one with this instruction, which all later ones share.
        ".fpu vfpv2",
        "vsqrt.f32 s0, s0",
        "bx lr",
        ".size gjk2d_vsqrtf, . - gjk2d_vsqrtf",
    );
}

#[cfg(all(target_arch = "arm", target_abi = "eabihf"))]
extern "C" {
    fn gjk2d_vsqrtf(x: f32) -> f32;
}

/// The correctly rounded square root of `x` (NaN below zero, as IEEE 754).
#[cfg(all(target_arch = "arm", target_abi = "eabihf"))]
#[inline(always)]
#[allow(unsafe_code)]
pub(crate) fn sqrtf(x: f32) -> f32 {
    // SAFETY: `gjk2d_vsqrtf` (above) reads `s0`, writes `s0` and returns,
    // as the hard-float C calling convention expects of an `f32 -> f32`
    // function; every eabihf target has the FPU that executes `vsqrt.f32`.
    unsafe { gjk2d_vsqrtf(x) }
}

/// On x86-64 SSE2's instruction through its intrinsic, which the compiler
/// knows for a square root. libm's is inline assembly there, opaque to the
/// compiler: a root asked for twice was computed twice, and none was
/// scheduled or combined with the code around it.
#[cfg(all(target_arch = "x86_64", target_feature = "sse2"))]
#[inline(always)]
#[allow(unsafe_code)]
pub(crate) fn sqrtf(x: f32) -> f32 {
    use core::arch::x86_64::{_mm_cvtss_f32, _mm_set_ss, _mm_sqrt_ss};
    // SAFETY: compiled only where the build enables SSE2 (and with it SSE),
    // so the processor executes these instructions.
    unsafe { _mm_cvtss_f32(_mm_sqrt_ss(_mm_set_ss(x))) }
}

/// The f64 square root, as [`sqrtf`].
#[cfg(all(target_arch = "x86_64", target_feature = "sse2"))]
#[inline(always)]
#[allow(unsafe_code)]
pub(crate) fn sqrt(x: f64) -> f64 {
    use core::arch::x86_64::{_mm_cvtsd_f64, _mm_set_sd, _mm_sqrt_pd};
    // SAFETY: as in `sqrtf`.
    unsafe { _mm_cvtsd_f64(_mm_sqrt_pd(_mm_set_sd(x))) }
}

/// Elsewhere libm's, which uses the hardware instruction on aarch64 and
/// wasm (and on x86 without SSE2, the x87's).
#[cfg(not(any(
    all(target_arch = "arm", target_abi = "eabihf"),
    all(target_arch = "x86_64", target_feature = "sse2")
)))]
#[inline(always)]
pub(crate) fn sqrtf(x: f32) -> f32 {
    libm::sqrtf(x)
}

#[cfg(not(all(target_arch = "x86_64", target_feature = "sse2")))]
#[inline(always)]
pub(crate) fn sqrt(x: f64) -> f64 {
    libm::sqrt(x)
}
