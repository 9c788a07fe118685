#!/usr/bin/env bash
# Builds the gjk2d demo page: web/src (the wasm bindings) -> web/www/gjk2d.wasm.
# Runs wasm-opt -Oz when it finds one (web/test/node_modules from npm's
# binaryen, or one on PATH). Prints the module's size.
#   web/build.sh            build
#   web/build.sh --serve    build, then serve web/www on http://127.0.0.1:8000
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
target="${CARGO_TARGET_DIR:-$here/target}"

cargo build --manifest-path "$here/Cargo.toml" --release --target wasm32-unknown-unknown --target-dir "$target"
raw="$target/wasm32-unknown-unknown/release/gjk2d_web.wasm"
out="$here/www/gjk2d.wasm"

wasm_opt=""
if [ -x "$here/test/node_modules/.bin/wasm-opt" ]; then
  wasm_opt="$here/test/node_modules/.bin/wasm-opt"
elif command -v wasm-opt >/dev/null 2>&1; then
  wasm_opt="$(command -v wasm-opt)"
fi

size() { wc -c <"$1" | tr -d ' '; }
if [ -n "$wasm_opt" ]; then
  "$wasm_opt" -Oz --enable-bulk-memory --enable-sign-ext --enable-mutable-globals \
    --enable-nontrapping-float-to-int --strip-debug --strip-producers "$raw" -o "$out"
  echo "gjk2d.wasm: $(size "$raw") bytes from cargo, $(size "$out") bytes after wasm-opt -Oz -> $out"
else
  cp "$raw" "$out"
  echo "gjk2d.wasm: $(size "$out") bytes (no wasm-opt found; 'npm ci' in web/test brings one) -> $out"
fi

if [ "${1:-}" = "--serve" ]; then
  exec "$here/serve.sh"
fi
