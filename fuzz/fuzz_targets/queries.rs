#![no_main]
//! Constructors and every query on arbitrary bytes: no panic, no hang,
//! finite output. `cargo fuzz run queries` from this directory.

mod common {
    include!("../../tests/common/fuzz_body.rs");
}

libfuzzer_sys::fuzz_target!(|data: &[u8]| {
    common::fuzz_one(data);
});
