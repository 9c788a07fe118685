// Determinism in wasm: the fixed query batch of tests/golden_batch.rs, built
// into the web crate with `--features golden`, run under Node, must hash to
// tests/golden_hash.txt bit for bit, as it does on the host and on Cortex-M.
//
//   node golden.mjs [path/to/gjk2d_web.wasm built with --features golden]
import fs from "node:fs";
import path from "node:path";
import { fileURLToPath } from "node:url";

const here = path.dirname(fileURLToPath(import.meta.url));
const root = path.resolve(here, "../..");
const wasmPath = process.argv[2] || path.join(here, "golden.wasm");
const hex = (x) => "0x" + x.toString(16).padStart(16, "0");

const text = fs.readFileSync(path.join(root, "tests/golden_hash.txt"), "utf8").trim();
const committed = BigInt(text.startsWith("0x") ? text : "0x" + text);

const { instance } = await WebAssembly.instantiate(fs.readFileSync(wasmPath), {});
const w = instance.exports;
if (typeof w.golden_hash !== "function") {
  console.log(`FAIL: ${wasmPath} has no golden_hash export (build the web crate with --features golden)`);
  process.exit(1);
}
const t0 = performance.now();
const hash = BigInt.asUintN(64, w.golden_hash());
const ms = performance.now() - t0;
const f32 = BigInt.asUintN(64, w.golden_hash_f32());
const f64 = BigInt.asUintN(64, w.golden_hash_f64());
console.log(`wasm golden hash f32 ${hex(f32)}`);
console.log(`wasm golden hash f64 ${hex(f64)}`);
console.log(`wasm golden hash     ${hex(hash)} (${ms.toFixed(1)} ms), tests/golden_hash.txt ${hex(committed)}`);
if (hash === committed) {
  console.log("PASS: the wasm build hashes the golden batch to the committed value");
  process.exit(0);
}
console.log("FAIL: the wasm build's golden hash differs from tests/golden_hash.txt");
process.exit(1);
