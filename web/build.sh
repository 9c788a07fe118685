#!/usr/bin/env bash
# Builds the gjk2d demo page: web/src (the wasm bindings) -> web/www/gjk2d.wasm.
# Runs wasm-opt -Oz when it finds one (web/test/node_modules from npm's
# binaryen, or one on PATH). Prints the module's size.
#   web/build.sh            build
#   web/build.sh --serve    build, then serve web/www on http://127.0.0.1:8000
#   web/build.sh --sizes    print the rows of web/README.md's size table: the
#                           page's module and each precision alone (needs
#                           wasm-opt; leaves web/www alone)
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
target="${CARGO_TARGET_DIR:-$here/target}"
raw="$target/wasm32-unknown-unknown/release/gjk2d_web.wasm"

wasm_opt=""
if [ -x "$here/test/node_modules/.bin/wasm-opt" ]; then
  wasm_opt="$here/test/node_modules/.bin/wasm-opt"
elif command -v wasm-opt >/dev/null 2>&1; then
  wasm_opt="$(command -v wasm-opt)"
fi

size() { wc -c <"$1" | tr -d ' '; }
# The module with the given cargo feature flags, optimised (copied as it is
# without wasm-opt) to $1.
module() {
  local out="$1"
  shift
  # Source paths that reach the module (panic locations) are remapped, so
  # its bytes, and the size table, do not depend on where the checkout is.
  RUSTFLAGS="--remap-path-prefix=$(cd "$here/.." && pwd)=/gjk2d --remap-path-prefix=${CARGO_HOME:-$HOME/.cargo}=/cargo" \
    cargo build --manifest-path "$here/Cargo.toml" --release --target wasm32-unknown-unknown --target-dir "$target" "$@"
  if [ -n "$wasm_opt" ]; then
    "$wasm_opt" -Oz --enable-bulk-memory --enable-sign-ext --enable-mutable-globals \
      --enable-nontrapping-float-to-int --strip-debug --strip-producers "$raw" -o "$out"
  else
    cp "$raw" "$out"
  fi
}

if [ "${1:-}" = "--sizes" ]; then
  [ -n "$wasm_opt" ] || { echo "web/build.sh --sizes needs wasm-opt ('npm ci' in web/test brings one)" >&2; exit 2; }
  tmp="$(mktemp -d)"
  trap 'rm -rf "$tmp"' EXIT
  grouped() { printf '%s' "$1" | sed -e ':a' -e 's/\([0-9]\)\([0-9]\{3\}\)\($\| \)/\1 \2\3/' -e 'ta'; }
  for variant in "both|\`f32\` and \`f64\` (the page's)" "f32|\`f32\` only" "f64|\`f64\` only"; do
    name="${variant%%|*}"
    flags=()
    [ "$name" = both ] || flags=(--no-default-features --features "$name")
    module "$tmp/$name.wasm" -q "${flags[@]}"
    # No gzip column: compressed sizes moved by a few bytes with the
    # checkout's path even where the module's length did not.
    echo "| ${variant#*|} | $(grouped "$(size "$tmp/$name.wasm")") | $(grouped "$(size "$raw")") |"
  done
  exit 0
fi

out="$here/www/gjk2d.wasm"
module "$out"
if [ -n "$wasm_opt" ]; then
  echo "gjk2d.wasm: $(size "$raw") bytes from cargo, $(size "$out") bytes after wasm-opt -Oz -> $out"
else
  echo "gjk2d.wasm: $(size "$out") bytes (no wasm-opt found; 'npm ci' in web/test brings one) -> $out"
fi

if [ "${1:-}" = "--serve" ]; then
  exec "$here/serve.sh"
fi
