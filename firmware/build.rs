//! Writes the memory map of the board the target runs on, as the memory.x
//! that cortex-m-rt's and riscv-rt's link.x include: the mps2 boards for
//! Cortex-M0/M3/M4F code, mps2-an505 for the Cortex-M33, QEMU's virt board
//! for RISC-V. (The maps live in memory/, not beside Cargo.toml: the
//! linker looks for memory.x in its working directory first.)
use std::{env, fs, path::PathBuf};

fn main() {
    let out = PathBuf::from(env::var_os("OUT_DIR").unwrap());
    let target = env::var("TARGET").unwrap_or_default();
    let map: &[u8] = if target.starts_with("riscv32") {
        include_bytes!("memory/riscv-virt.x")
    } else if target.starts_with("thumbv8m") {
        include_bytes!("memory/mps2-an505.x")
    } else {
        include_bytes!("memory/mps2.x")
    };
    fs::write(out.join("memory.x"), map).unwrap();
    println!("cargo:rustc-link-search={}", out.display());
    // defmt's linker script (its interned strings), for the defmt demo only.
    println!("cargo:rustc-link-arg-bin=defmt_demo=-Tdefmt.x");
    println!("cargo:rerun-if-changed=memory");
    println!("cargo:rerun-if-changed=build.rs");
}
