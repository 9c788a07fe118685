#!/usr/bin/env bash
# The browser test, end to end: builds the wasm module and the native
# reference, installs playwright-core (npm ci), serves web/www on a free
# localhost port, drives Debian's Chromium over it, checks the golden hash in
# wasm under Node, and stops the server. Checks that web/README.md's table of
# module sizes, and README.md's figures from it, are what this build measures.
# Exit status: the tests' verdict.
#
# Needs: rustup target wasm32-unknown-unknown, node + npm, and
# `apt-get install -y --no-install-recommends chromium` (/usr/bin/chromium).
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
web="$(dirname "$here")"
root="$(dirname "$web")"
start=$(date +%s)

echo "--- npm ci (playwright-core, binaryen's wasm-opt)"
(cd "$here" && npm ci --no-audit --no-fund --loglevel=error)

echo "--- wasm module for the page"
"$web/build.sh"

status=0
echo "--- module sizes, against web/README.md and README.md"
# web/README.md's size table must be this build's (web/build.sh --sizes prints
# its rows), and README.md's status row must quote its figures in KB.
# ACCEPT_GROWTH=1 reports a difference without failing, to measure a change
# before committing it.
sizes="$("$web/build.sh" --sizes)"
echo "$sizes"
source "$root/.ci/quoted.sh"
quotes_rows "$web/README.md" "$sizes"
kb() { awk -v b="$1" 'BEGIN { printf "%.1f KB", b / 1000 }'; }
bytes() { grep -F -- "$1" <<<"$sizes" | cut -d'|' -f3 | tr -d ' '; }
quotes "$root/README.md" "$(kb "$(bytes '`f32` only')") f32" "$(kb "$(bytes '`f64` only')") f64" \
  "carries both, is $(kb "$(bytes "the page's")")"
enforce=1
[ "${ACCEPT_GROWTH:-0}" = 1 ] && enforce=0
quoted_verdict "$enforce" || {
  echo "FAILED: module sizes differ from web/README.md's or README.md's in $stale place(s)"
  status=1
}

golden=0
if [ -f "$root/tests/golden_batch.rs" ] && [ -f "$root/tests/golden_hash.txt" ]; then
  golden=1
  echo "--- wasm module with the golden batch"
  # Same target dir as build.sh (it already copied the page's module out):
  # only the web crate itself is rebuilt.
  target="${CARGO_TARGET_DIR:-$web/target}"
  cargo build --manifest-path "$web/Cargo.toml" --release --target wasm32-unknown-unknown \
    --target-dir "$target" --features golden
  cp "$target/wasm32-unknown-unknown/release/gjk2d_web.wasm" "$here/golden.wasm"
fi

echo "--- native reference (examples/web_expected.rs)"
(cd "$root" && cargo build --quiet --release --example web_expected)

port=$(python3 -c 'import socket; s = socket.socket(); s.bind(("127.0.0.1", 0)); print(s.getsockname()[1]); s.close()')
python3 -m http.server "$port" --bind 127.0.0.1 --directory "$web/www" >"$here/server.log" 2>&1 &
server=$!
trap 'kill "$server" 2>/dev/null || true' EXIT
for _ in $(seq 50); do
  python3 -c "import urllib.request; urllib.request.urlopen('http://127.0.0.1:$port/index.html')" 2>/dev/null && break
  sleep 0.1
done

echo "--- browser test (Chromium, http://127.0.0.1:$port/)"
GJK_URL="http://127.0.0.1:$port/" node "$here/browser-test.mjs" || status=1
if [ $golden = 1 ]; then
  echo "--- golden hash in wasm (Node)"
  node "$here/golden.mjs" "$here/golden.wasm" || status=1
else
  echo "--- golden hash in wasm: skipped (no tests/golden_batch.rs)"
fi

echo "--- web/test/run.sh: $([ $status = 0 ] && echo PASS || echo FAIL) in $(( $(date +%s) - start )) s"
exit $status
