#!/usr/bin/env bash
# Serves the demo page on http://127.0.0.1:${PORT:-8000}/ (build it first: web/build.sh).
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
port="${PORT:-8000}"
[ -f "$here/www/gjk2d.wasm" ] || { echo "web/www/gjk2d.wasm is missing: run web/build.sh first" >&2; exit 1; }
echo "gjk2d demo: http://127.0.0.1:$port/"
exec python3 -m http.server "$port" --bind 127.0.0.1 --directory "$here/www"
