//! The fuzz target's body on pseudo-random inputs, so every `cargo test`
//! exercises it on stable Rust; `cargo fuzz run queries` (in fuzz/) explores
//! coverage-guided for as long as you let it.

mod common {
    include!("common/fuzz_body.rs");
}

/// SplitMix64: a seeded, dependency-free byte source.
fn bytes(seed: u64, len: usize) -> Vec<u8> {
    let mut state = seed;
    (0..len)
        .map(|_| {
            state = state.wrapping_add(0x9E37_79B9_7F4A_7C15);
            let mut z = state;
            z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
            z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
            (z ^ (z >> 31)) as u8
        })
        .collect()
}

#[test]
fn random_inputs_never_panic_hang_or_give_non_finite_output() {
    let (mut pairs, mut rays) = (0, 0);
    for seed in 0..100_000u64 {
        let (p, r) = common::fuzz_one(&bytes(seed, 64 + (seed as usize % 400)));
        pairs += p;
        rays += r;
    }
    println!("{pairs} pair queries, {rays} ray casts");
    // Random bytes must reach the queries often, or this test proves nothing.
    assert!(pairs > 10_000 && rays > 10_000, "only {pairs} pair queries and {rays} ray casts ran");
}

/// Inputs the coverage-guided fuzzer (`cargo fuzz run queries`) found to
/// crash, each named after its bug; replayed on every `cargo test`.
#[test]
fn fuzz_crash_regressions() {
    for (name, data) in [
        (
            "gjk-raycast-subnormal-advance-gives-infinite-distance",
            &include_bytes!("data/fuzz-crashes/gjk-raycast-subnormal-advance-gives-infinite-distance")[..],
        ),
        (
            "centroid-overflows-at-f32-coordinate-limit",
            &include_bytes!("data/fuzz-crashes/centroid-overflows-at-f32-coordinate-limit")[..],
        ),
        ("nan-witness-points-f64", &include_bytes!("data/fuzz-crashes/nan-witness-points-f64")[..]),
        (
            "polygon-ray-parallel-to-rounding-hits-at-infinity",
            &include_bytes!("data/fuzz-crashes/polygon-ray-parallel-to-rounding-hits-at-infinity")[..],
        ),
        (
            "segment-weights-overflow-for-subnormal-sum",
            &include_bytes!("data/fuzz-crashes/segment-weights-overflow-for-subnormal-sum")[..],
        ),
        (
            "slice-with-subnormal-angle-has-nan-centroid",
            &include_bytes!("data/fuzz-crashes/slice-with-subnormal-angle-has-nan-centroid")[..],
        ),
    ] {
        let ran = common::fuzz_one(data);
        assert!(ran.0 + ran.1 > 0, "{name}: the input no longer reaches a query");
    }
}
