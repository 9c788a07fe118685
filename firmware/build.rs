//! Puts the memory maps where the linker finds them: memory.x for
//! cortex-m-rt's link.x, memory-riscv.x for riscv-rt's (named in
//! .cargo/config.toml: a script named memory.x would be found in this
//! directory first, the Cortex-M one).
use std::{env, fs, path::PathBuf};

fn main() {
    let out = PathBuf::from(env::var_os("OUT_DIR").unwrap());
    fs::write(out.join("memory.x"), include_bytes!("memory.x")).unwrap();
    fs::write(out.join("memory-riscv.x"), include_bytes!("memory-riscv.x")).unwrap();
    println!("cargo:rustc-link-search={}", out.display());
    // defmt's linker script (its interned strings), for the defmt demo only.
    println!("cargo:rustc-link-arg-bin=defmt_demo=-Tdefmt.x");
    println!("cargo:rerun-if-changed=memory.x");
    println!("cargo:rerun-if-changed=memory-riscv.x");
    println!("cargo:rerun-if-changed=build.rs");
}
