//! Instruction and stack meters for QEMU.
//!
//! Instructions, on Cortex-M: with `-icount shift=0` QEMU advances virtual
//! time by 1 ns per instruction, and the mps2 boards clock SysTick at 25 MHz,
//! so one SysTick tick is 40 instructions. On RISC-V: the `minstret` counter,
//! which QEMU counts from the same instruction count under `-icount`, one
//! tick per instruction. A query is run `REPEAT` times between two reads and
//! the loop's own cost (measured on an empty closure) subtracted, which
//! brings the resolution to `INSTRUCTIONS_PER_TICK / REPEAT` instructions.
//!
//! Stack: the words below the current stack pointer are painted with a
//! pattern, the query runs, and the lowest word that changed gives its peak
//! use (including its call's return address and saved registers).

pub const REPEAT: u32 = 20;

#[cfg(target_arch = "arm")]
mod counter {
    use cortex_m::peripheral::{syst::SystClkSource, SYST};

    pub const INSTRUCTIONS_PER_TICK: u32 = 40;

    /// Starts SysTick from the core clock, counting down from 2^24 - 1.
    pub fn start() {
        // Taken once, by the measuring firmware alone.
        if let Some(mut cp) = cortex_m::Peripherals::take() {
            cp.SYST.set_clock_source(SystClkSource::Core);
            cp.SYST.set_reload(0x00ff_ffff);
            cp.SYST.clear_current();
            cp.SYST.enable_counter();
        }
    }

    /// Ticks from `start` to `end` readings: SysTick counts down, in 24 bits
    /// (a run must stay under 2^24 ticks = 671M instructions).
    #[inline(always)]
    pub fn elapsed(start: u32, end: u32) -> u32 {
        start.wrapping_sub(end) & 0x00ff_ffff
    }

    #[inline(always)]
    pub fn now() -> u32 {
        SYST::get_current()
    }

    #[inline(always)]
    pub fn stack_pointer() -> usize {
        cortex_m::register::msp::read() as usize
    }

    /// The body of a 2-instruction countdown loop on `{0}` (subs, bne).
    macro_rules! countdown {
        () => {
            "subs {0}, {0}, #1\nbne 2b"
        };
    }
    pub(super) use countdown;
}

#[cfg(target_arch = "riscv32")]
mod counter {
    pub const INSTRUCTIONS_PER_TICK: u32 = 1;

    /// `minstret` runs from reset in machine mode.
    pub fn start() {}

    /// Ticks from `start` to `end` readings: `minstret` counts up (its low
    /// 32 bits: a run must stay under 2^32 instructions).
    #[inline(always)]
    pub fn elapsed(start: u32, end: u32) -> u32 {
        end.wrapping_sub(start)
    }

    #[inline(always)]
    pub fn now() -> u32 {
        riscv::register::minstret::read() as u32
    }

    #[inline(always)]
    pub fn stack_pointer() -> usize {
        let sp: usize;
        // SAFETY: copies the stack pointer into a register; nothing else.
        unsafe { core::arch::asm!("mv {0}, sp", out(reg) sp, options(nomem, nostack)) };
        sp
    }

    /// The body of a 2-instruction countdown loop on `{0}` (addi, bnez).
    macro_rules! countdown {
        () => {
            "addi {0}, {0}, -1\nbnez {0}, 2b"
        };
    }
    pub(super) use countdown;
}

pub use counter::{start, INSTRUCTIONS_PER_TICK};

/// Counter ticks spent in `f` called `REPEAT` times.
#[inline(never)]
pub fn ticks(f: &dyn Fn()) -> u32 {
    let start = counter::now();
    for _ in 0..REPEAT {
        f();
    }
    counter::elapsed(start, counter::now())
}

/// Instructions per call of `f` (x 100, for two decimals), net of the
/// measuring loop's own cost `overhead_ticks` (from an empty closure).
pub fn instructions_x100(f: &dyn Fn(), overhead_ticks: u32) -> u32 {
    let t = ticks(f).saturating_sub(overhead_ticks);
    t * INSTRUCTIONS_PER_TICK * 100 / REPEAT
}

/// Runs `loops` iterations of a 2-instruction loop: 2 * loops
/// instructions, to check the counter's rate.
#[inline(never)]
pub fn known_instructions(loops: u32) {
    // SAFETY: a register-only countdown; no memory or stack is touched.
    unsafe {
        core::arch::asm!("2:", counter::countdown!(), inout(reg) loops => _, options(nomem, nostack));
    }
}

const PAINT: u32 = 0x5a5a_a5a5;
/// Bytes painted below the stack pointer.
pub const PAINT_BYTES: usize = 8 * 1024;

/// Peak stack bytes used by `f`, measured from this function's stack pointer.
#[inline(never)]
pub fn stack_bytes(f: &dyn Fn()) -> usize {
    let sp = counter::stack_pointer();
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
