//! Instruction and stack meters for QEMU.
//!
//! Instructions: with `-icount shift=0` QEMU advances virtual time by 1 ns per
//! instruction, and the mps2 boards clock SysTick at 25 MHz, so one SysTick
//! tick is 40 instructions. A query is run `REPEAT` times between two reads
//! and the loop's own cost (measured on an empty closure) subtracted, which
//! brings the resolution to 40 / REPEAT instructions.
//!
//! Stack: the words below the current stack pointer are painted with a
//! pattern, the query runs, and the lowest word that changed gives its peak
//! use (including its call's return address and saved registers).

use cortex_m::peripheral::{syst::SystClkSource, SYST};

pub const INSTRUCTIONS_PER_TICK: u32 = 40;
pub const REPEAT: u32 = 20;

pub fn start_systick(syst: &mut SYST) {
    syst.set_clock_source(SystClkSource::Core);
    syst.set_reload(0x00ff_ffff);
    syst.clear_current();
    syst.enable_counter();
}

#[inline(always)]
fn now() -> u32 {
    SYST::get_current()
}

/// SysTick ticks spent in `f` called `REPEAT` times (the counter counts down
/// from 2^24 - 1; a run must stay under 2^24 ticks = 671M instructions).
#[inline(never)]
pub fn ticks(f: &dyn Fn()) -> u32 {
    let start = now();
    for _ in 0..REPEAT {
        f();
    }
    let end = now();
    start.wrapping_sub(end) & 0x00ff_ffff
}

/// Instructions per call of `f` (x 100, for two decimals), net of the
/// measuring loop's own cost `overhead_ticks` (from an empty closure).
pub fn instructions_x100(f: &dyn Fn(), overhead_ticks: u32) -> u32 {
    let t = ticks(f).saturating_sub(overhead_ticks);
    t * INSTRUCTIONS_PER_TICK * 100 / REPEAT
}

/// Runs `loops` iterations of a 2-instruction loop (subs, bne): 2 * loops
/// instructions, to check the 40-instructions-per-tick rate.
#[inline(never)]
pub fn known_instructions(loops: u32) {
    unsafe {
        core::arch::asm!(
            "2:",
            "subs {0}, {0}, #1",
            "bne 2b",
            inout(reg) loops => _,
            options(nomem, nostack)
        );
    }
}

const PAINT: u32 = 0x5a5a_a5a5;
/// Bytes painted below the stack pointer.
pub const PAINT_BYTES: usize = 8 * 1024;

/// Peak stack bytes used by `f`, measured from this function's stack pointer.
#[inline(never)]
pub fn stack_bytes(f: &dyn Fn()) -> usize {
    let sp = cortex_m::register::msp::read() as usize;
    let bottom = sp - PAINT_BYTES;
    // Paint [bottom, sp - 64): the loop itself keeps to registers, and the
    // 64 bytes just below sp are left for the call below.
    let mut a = bottom;
    while a < sp - 64 {
        unsafe { core::ptr::write_volatile(a as *mut u32, PAINT) };
        a += 4;
    }
    f();
    let mut a = bottom;
    while a < sp && unsafe { core::ptr::read_volatile(a as *const u32) } == PAINT {
        a += 4;
    }
    sp - a
}
