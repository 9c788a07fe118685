//! Determinism: the fixed query batch of tests/golden_batch.rs (shared with
//! the Cortex-M firmware under QEMU and the wasm build) must hash to the value
//! committed in tests/golden_hash.txt, bit for bit.
//!
//! After an intended change of results, print the new value with
//! `cargo test --test golden -- --nocapture` and commit it.

include!("golden_batch.rs");

fn committed() -> u64 {
    let text = include_str!("golden_hash.txt").trim();
    let hex = text.strip_prefix("0x").unwrap_or(text);
    u64::from_str_radix(hex, 16).expect("tests/golden_hash.txt holds one hex u64")
}

#[test]
fn golden_hash_matches_committed_value() {
    let f32_hash = golden_hash_f32();
    let f64_hash = golden_hash_f64();
    let hash = golden_hash();
    println!("golden hash f32 {f32_hash:#018x}");
    println!("golden hash f64 {f64_hash:#018x}");
    println!("golden hash {hash:#018x}");
    assert_eq!(hash, committed(), "golden hash {hash:#018x} differs from tests/golden_hash.txt");
}

#[test]
fn golden_batch_is_repeatable() {
    assert_eq!(golden_hash(), golden_hash());
}
