#!/usr/bin/env bash
# gjk2d on microcontrollers, under QEMU: known-answer tests on five targets
# (Cortex-M4F, Cortex-M3 running thumbv6m code, Cortex-M33, RISC-V
# riscv32imac and riscv32imafc), the golden determinism hash (the host's on
# every one), instructions and stack per query, flash budgets and the
# no-panic link check. Writes size-table.md, icount.md and
# stack.md beside this script and compares them with the committed ones:
# a figure that grew fails the run. Checks that README.md beside this script
# (the firmware page) quotes those tables and shows the example it builds, and
# that the repository's README.md quotes the budget figures it measured.
# Exits non-zero on any failure.
#
#   bash firmware/run.sh
#
# Needs qemu-system-arm and qemu-system-riscv32 on PATH (Debian: apt-get
# install qemu-system-arm qemu-system-misc, or firmware/get-qemu.sh where apt
# cannot install them). Installs nothing itself
# but rustup components and targets.
#
# ALLOW_PANIC_PATHS=1 reports surviving panic paths without failing.
# ACCEPT_GROWTH=1 reports figures that grew over the committed ones, and
# pages that quote other figures, without failing.
# ENFORCE_BUDGETS=1 fails on the known budget misses too; =0 only reports.
set -euo pipefail
cd "$(dirname "$0")"
FW="$(pwd)"
ROOT="$(cd .. && pwd)"
export CARGO_TERM_COLOR=never
# The firmware's own target dir (gitignored); never the workspace's.
export CARGO_TARGET_DIR="$FW/target"
start=$(date +%s)
failures=()
misses=()
fail() { failures+=("$*"); echo "FAILED: $*"; }
# Flash and stack budgets. A budget met is enforced: a change that breaks
# it fails the run. The known misses (firmware/README.md says why) are reported and
# fail only with ENFORCE_BUDGETS=1. Sizes depend on the compiler, so budgets
# are enforced with the rustc they were measured with (BUDGET_RUSTC) and only
# reported under another (ENFORCE_BUDGETS=0 reports everything).
BUDGET_RUSTC="1.95.0"
KNOWN_MISSES=(
  "stack budget: f64 distance "
  "stack budget: f64 penetration "
  "stack budget: f64 raycast ellipse (GJK ray cast) "
  "stack budget: f64 cast "
  "stack budget: f64 manifold "
  "stack budget: f64 time of impact "
  "flash budget: (5) every shape and query, f32 "
)
known_misses=()
miss() {
  local known=0 m
  for m in "${KNOWN_MISSES[@]}"; do [[ "$*" == "$m"* ]] && known=1; done
  if [ "$known" = 1 ]; then
    known_misses+=("$*")
    echo "BUDGET MISSED (known): $*"
    [ "${ENFORCE_BUDGETS:-}" = 1 ] && failures+=("$*")
  else
    misses+=("$*")
    echo "BUDGET MISSED: $*"
    [ "$enforce_budgets" = 1 ] && failures+=("$*")
  fi
  return 0
}
step() { printf '\n--- %s ---\n' "$*"; }

M4=thumbv7em-none-eabihf
M0=thumbv6m-none-eabi
M33=thumbv8m.main-none-eabihf
RV=riscv32imac-unknown-none-elf
RVF=riscv32imafc-unknown-none-elf
rustup component add llvm-tools >/dev/null 2>&1 || rustup component add llvm-tools
rustup target add "$M4" "$M0" "$M33" "$RV" "$RVF" >/dev/null 2>&1 || rustup target add "$M4" "$M0" "$M33" "$RV" "$RVF"
HOST="$(rustc -vV | sed -n 's/^host: //p')"
RUSTC_VERSION="$(rustc -vV | sed -n 's/^release: //p')"
case "${ENFORCE_BUDGETS:-}" in
  1) enforce_budgets=1 ;;
  0) enforce_budgets=0 ;;
  *) if [ "$RUSTC_VERSION" = "$BUDGET_RUSTC" ]; then enforce_budgets=1; else enforce_budgets=0; fi ;;
esac
LLVM_BIN="$(rustc --print sysroot)/lib/rustlib/$HOST/bin"
SIZE="$LLVM_BIN/llvm-size"
OBJDUMP="$LLVM_BIN/llvm-objdump"
for emulator in qemu-system-arm qemu-system-riscv32; do
  command -v "$emulator" >/dev/null || {
    echo "$emulator not found: apt-get install -y --no-install-recommends qemu-system-arm qemu-system-misc" >&2
    echo "(or: bash firmware/get-qemu.sh && export PATH=\$HOME/.cache/gjk2d-qemu/bin:\$PATH)" >&2
    exit 2
  }
done
board() {
  case "$1" in
    "$M4") echo "mps2-an386 (Cortex-M4F)" ;;
    "$M0") echo "mps2-an385 (Cortex-M3, thumbv6m code)" ;;
    "$M33") echo "mps2-an505 (Cortex-M33)" ;;
    "$RV") echo "virt (RISC-V, riscv32imac: no FPU)" ;;
    "$RVF") echo "virt (RISC-V, riscv32imafc: f32 in hardware)" ;;
  esac
}
out="$CARGO_TARGET_DIR/run"
mkdir -p "$out"
# The committed figures, which this run's are compared with at the end:
# HEAD's in a git checkout, else the files as they were before this run.
FIGURES="icount stack size-table"
for f in $FIGURES; do
  git -C "$ROOT" show "HEAD:firmware/$f.md" >"$out/$f.committed.md" 2>/dev/null ||
    cp "$FW/$f.md" "$out/$f.committed.md" 2>/dev/null || : >"$out/$f.committed.md"
done

# ---------------------------------------------------------------- tests
expected_hash="$(tr -d ' \n' <"$ROOT/tests/golden_hash.txt")"
for target in "$M4" "$M0" "$M33" "$RV" "$RVF"; do
  step "known-answer tests and golden hash on $(board "$target")"
  cargo build --release --bin kat --target "$target" -q
  # The runner in .cargo/config.toml: timeout + qemu-system-arm or -riscv32.
  if cargo run --release --bin kat --target "$target" -q >"$out/kat-$target.txt" 2>&1; then
    grep -v '^golden' "$out/kat-$target.txt" | tail -n 20
  else
    cat "$out/kat-$target.txt"
    fail "known-answer tests on $target"
  fi
  hash="$(sed -n 's/^golden hash \(0x[0-9a-f]*\)$/\1/p' "$out/kat-$target.txt")"
  echo "golden hash on $target: ${hash:-none}, committed: $expected_hash"
  [ "$hash" = "$expected_hash" ] || fail "golden hash on $target is ${hash:-missing}, tests/golden_hash.txt has $expected_hash"
done

step "firmware/README.md's example builds and is the page's main.rs"
cargo build --release --bin readme_example --target "$M4" -q || fail "firmware/README.md's example (src/bin/readme_example.rs) does not build"
# The page's one rust,ignore block is the bin's source, each without its first
# line (which says where the code is shown or comes from).
if ! diff <(sed -n '/^```rust,ignore$/,/^```$/p' "$FW/README.md" | sed '1,2d;$d') <(sed 1d "$FW/src/bin/readme_example.rs") >"$out/readme-example.diff"; then
  cat "$out/readme-example.diff"
  fail "firmware/README.md's main.rs differs from src/bin/readme_example.rs"
fi

step "defmt: every result type formatted on the M4F (frames over semihosting)"
# Frames are binary; decoding needs defmt-print (cargo install, kept out of
# CI). Checked here: the firmware runs and exits 0, writes frames, and links
# the format string of each public type it logs.
if DEFMT_LOG=info cargo run --release --bin defmt_demo --features defmt -q >"$out/defmt.bin" 2>"$out/defmt.err"; then
  frames=$(wc -c <"$out/defmt.bin")
  echo "defmt_demo: $frames bytes of defmt frames"
  [ "$frames" -gt 0 ] || fail "defmt_demo wrote no frames"
  strings_linked="$("$LLVM_BIN/llvm-nm" "$CARGO_TARGET_DIR/$M4/release/defmt_demo")"
  for type in Detection Separation Penetration RayCast RayHit Ray Transform Circle Polygon GjkConfig NonFinite Converged; do
    grep -q "\"data\":\"$type" <<<"$strings_linked" || fail "defmt_demo: no format string for $type"
  done
else
  cat "$out/defmt.err"
  fail "defmt_demo did not run"
fi

step "golden hash on the host (tests/golden.rs)"
# Uses the main workspace's own target dir (CI's cargo test built it already).
if (cd "$ROOT" && env -u CARGO_TARGET_DIR cargo test -q --test golden -- --nocapture 2>&1) >"$out/golden-host.txt"; then
  grep '^golden hash' "$out/golden-host.txt" || true
else
  cat "$out/golden-host.txt"
  fail "host golden hash differs from tests/golden_hash.txt"
fi

# ---------------------------------------------------------------- icount and stack
step "instructions and stack per query on $(board "$M4"), $(board "$M0") and $(board "$RV"), QEMU -icount shift=0"
for target in "$M4" "$M0" "$RV"; do
  # The shape cast's and the manifold's rows from a build of their own (see
  # Cargo.toml's measure-step), appended after the others.
  if cargo run --release --bin measure --target "$target" -q >"$out/measure-$target.txt" 2>&1 &&
    cargo run --release --bin measure --features measure-step --target "$target" -q >"$out/measure-step-$target.txt" 2>&1; then
    grep '^MEASURE|' "$out/measure-step-$target.txt" >>"$out/measure-$target.txt"
    echo "$target: $(grep '^CALIBRATION' "$out/measure-$target.txt" | cut -d'|' -f2-)"
  else
    cat "$out/measure-step-$target.txt" 2>/dev/null || true
    cat "$out/measure-$target.txt"
    fail "measure firmware on $target"
  fi
done
# One line per query: MEASURE|precision|query|iterations|M4F instructions|
# M4F stack|thumbv6m instructions|thumbv6m stack|RISC-V instructions|
# RISC-V stack. The iterations must agree: the results are bit-identical on
# every target (the golden hash), so the paths are.
awk -F'|' -v others="$M0 $RV" '
  BEGIN { split(others, name, " ") }
  FNR == 1 { file++ }
  file < 3 { if ($1 == "MEASURE") other[file, $2 "|" $3] = $4 "|" $5 "|" $6; next }
  $1 == "MEASURE" {
    key = $2 "|" $3
    line = $0
    for (f = 1; f <= 2; f++) {
      if (!((f, key) in other)) { print "MISSING|" key "|" name[f]; next }
      split(other[f, key], o, "|")
      if (o[1] != $4) print "ITERATIONS|" key "|" name[f] "|" $4 "|" o[1]
      line = line "|" o[2] "|" o[3]
    }
    print line
  }' "$out/measure-$M0.txt" "$out/measure-$RV.txt" "$out/measure-$M4.txt" >"$out/measure.txt"
while IFS='|' read -r what precision name target m4 other; do
  case "$what" in
    MISSING) fail "measure: $precision $name missing on $target" ;;
    ITERATIONS) fail "measure: $precision $name takes $m4 iterations on $M4 but $other on $target" ;;
  esac
done < <(grep -E '^(MISSING|ITERATIONS)\|' "$out/measure.txt" || true)
calibration() { grep '^CALIBRATION' "$out/measure-$1.txt" | cut -d'|' -f2 | sed 's/ ticks.*//'; }
{
  echo "| query (opt-level \"s\", LTO) | precision | iterations | instructions, Cortex-M4F | instructions, thumbv6m | instructions, riscv32imac |"
  echo "| --- | --- | ---: | ---: | ---: | ---: |"
  grep '^MEASURE|' "$out/measure.txt" | grep -v 'Epa N' | awk -F'|' '{printf "| %s | %s | %s | %.0f | %.0f | %.0f |\n", $3, $2, $4, $5, $7, $9}'
  echo
  echo "Instructions executed per query (QEMU \`-icount shift=0\`: SysTick at 25 MHz counts 40 instructions per tick;"
  echo "on RISC-V \`minstret\`, one instruction per count; each query is run 20 times between two reads, net of the loop's"
  echo "cost). Calibration: 20 x 10000 instructions read $(calibration "$M4") ticks on the M4F and $(calibration "$M0") on thumbv6m"
  echo "(5000 expected), $(calibration "$RV") counts on RISC-V (200000 and the loop's calls expected)."
  echo "thumbv6m is Cortex-M0/M0+ code (no FPU: f32 and f64 in software), run on QEMU's Cortex-M3 board (mps2-an385);"
  echo "riscv32imac has no FPU either (QEMU's virt board)."
  echo "Instructions, not cycles: for regressions and comparisons, not for real-time budgets."
} >"$FW/icount.md"
{
  echo "| query (opt-level \"s\", LTO) | precision | peak stack, Cortex-M4F (bytes) | peak stack, thumbv6m (bytes) | peak stack, riscv32imac (bytes) |"
  echo "| --- | --- | ---: | ---: | ---: |"
  grep '^MEASURE|' "$out/measure.txt" | grep -v 'Epa N' | awk -F'|' '{printf "| %s | %s | %s | %s | %s |\n", $3, $2, $6, $8, $10}'
  echo
  echo "EPA's capacity \`N\` (\`Epa<R, N>\`, polytope vertices kept on the stack) against the peak stack of a penetration query"
  echo "(two overlapping ellipses, the case that needs the most vertices):"
  echo
  echo "| \`Epa<R, N>\` | precision | iterations | peak stack, Cortex-M4F (bytes) | peak stack, thumbv6m (bytes) | peak stack, riscv32imac (bytes) |"
  echo "| --- | --- | ---: | ---: | ---: | ---: |"
  grep '^MEASURE|' "$out/measure.txt" | grep 'Epa N' | awk -F'|' '{n=$3; sub(/.*N = /, "", n); printf "| N = %s | %s | %s | %s | %s | %s |\n", n, $2, $4, $6, $8, $10}'
  echo
  echo "Measured by painting 8 KB below the stack pointer, running the query and finding the lowest word that changed"
  echo "(includes the call itself). The default is N = 32. The budget (1 KB) is the M4F's."
} >"$FW/stack.md"
cat "$FW/icount.md" "$FW/stack.md"
# Budget: 1 KB for any query at the default capacities.
while IFS='|' read -r _ precision name _ _ stack _; do
  if [ "$stack" -gt 1024 ]; then miss "stack budget: $precision $name uses $stack bytes (> 1024)"; fi
done < <(grep '^MEASURE|' "$out/measure.txt" | grep -v 'Epa N' || true)

# ---------------------------------------------------------------- flash and panics
SIZE_BINS="size_0_empty size_1_intersect_const size_1_intersect size_2_distance_const size_2_distance size_3_penetration_const size_3_penetration size_4_raycast_const size_4_raycast size_5_all_f32_const size_5_all_f32 size_5_all_f64_const size_5_all_f64 size_6_cast_const size_7_manifold_const size_8_impact_const size_9_cached_const"
declare -A TEXT FLASH PANIC
panic_report="$out/panic-paths.txt"
: >"$panic_report"
# Cargo hashes a path dependency's location into its symbols, and the order
# of functions (with the padding between them) follows: the size firmwares
# are built from a copy of the sources at one fixed path, so their figures
# are the same wherever the repository is cloned.
SIZE_SRC=/tmp/gjk2d-size-firmware
SIZE_TARGET="$CARGO_TARGET_DIR/fixed-path"
rm -rf "$SIZE_SRC" && mkdir -p "$SIZE_SRC"
tar -C "$ROOT" --exclude=./.git --exclude=target -cf - . | tar -C "$SIZE_SRC" -xf -
for target in "$M4" "$M0" "$RV"; do
  step "size firmwares and the no-panic link check, $target"
  for bin in $SIZE_BINS; do
    elf="$SIZE_TARGET/$target/release/$bin"
    if (cd "$SIZE_SRC/firmware" && CARGO_TARGET_DIR="$SIZE_TARGET" cargo build --release --bin "$bin" --target "$target" -q) >"$out/build-$bin-$target.txt" 2>&1; then
      PANIC[$bin.$target]=no
    else
      if ! grep -q gjk2d_panic_path_linked "$out/build-$bin-$target.txt"; then
        cat "$out/build-$bin-$target.txt"
        fail "build of $bin for $target"
        continue
      fi
      PANIC[$bin.$target]=yes
      # Link again with the symbol defined, to measure and to name the callers.
      (cd "$SIZE_SRC/firmware" && RUSTFLAGS="-C link-arg=-Tlink.x -C link-arg=--defsym=gjk2d_panic_path_linked=0" \
        CARGO_TARGET_DIR="$FW/target/panic-diag" cargo build --release --bin "$bin" --target "$target" -q)
      elf="$FW/target/panic-diag/$target/release/$bin"
      {
        echo "== $bin ($target): panic paths (caller, innermost source line, panic entry)"
        "$OBJDUMP" -d -C -l "$elf" | awk -f "$FW/panic-callers.awk" | sed 's/::h[0-9a-f]\{16\}//'
      } >>"$panic_report"
      echo "$bin: a panic path survives (see below)"
    fi
    sizes="$("$SIZE" -A "$elf")"
    text=$(awk '$1==".text"{print $2}' <<<"$sizes")
    # Everything stored in flash (riscv-rt adds its start code, .init.rust,
    # and keeps the unwind tables, .eh_frame).
    flash=$(awk '$1==".vector_table"||$1==".text"||$1==".init.rust"||$1==".rodata"||$1==".eh_frame"||$1==".data"{s+=$2} END{print s}' <<<"$sizes")
    TEXT[$bin.$target]=$text
    FLASH[$bin.$target]=$flash
  done
done
if [ -s "$panic_report" ]; then
  step "panic paths that survive in release (LTO) builds"
  cat "$panic_report"
  if [ "${ALLOW_PANIC_PATHS:-0}" = 1 ]; then
    echo "(ALLOW_PANIC_PATHS=1: reported, not failed)"
  else
    fail "panic paths survive in the size firmwares (see $panic_report)"
  fi
fi

# The budgets are for the queries: the rows with constant shapes. The rows
# with shapes built at run time add the shapes' checks (Polygon::new, ...).
declare -A BUDGET=([size_1_intersect_const]=2048 [size_2_distance_const]=4096 [size_3_penetration_const]=6144 [size_5_all_f32_const]=12288)
declare -A LABEL=(
  [size_0_empty]="(0) empty firmware (baseline)"
  [size_1_intersect_const]="(1) polygon intersection"
  [size_1_intersect]="(1) with polygons built at run time"
  [size_2_distance_const]="(2) + distance"
  [size_2_distance]="(2) with polygons built at run time"
  [size_3_penetration_const]="(3) + EPA penetration"
  [size_3_penetration]="(3) with polygons built at run time"
  [size_4_raycast_const]="(4) + ray casts"
  [size_4_raycast]="(4) with polygons built at run time"
  [size_5_all_f32_const]="(5) every shape and query, f32"
  [size_5_all_f32]="(5) f32, shapes built at run time"
  [size_5_all_f64_const]="(5) every shape and query, f64"
  [size_5_all_f64]="(5) f64, shapes built at run time"
  [size_6_cast_const]="(6) polygon shape cast alone"
  [size_7_manifold_const]="(7) polygon contact manifold alone"
  [size_8_impact_const]="(8) polygon time of impact alone"
  [size_9_cached_const]="(9) polygon distance and penetration, warm started"
)
kb() { awk -v b="$1" 'BEGIN{printf "%.2f KB", b/1024}'; }
{
  echo "| firmware | thumbv7em .text | thumbv7em flash | budget (.text) | thumbv6m .text | thumbv6m flash | riscv32imac .text | riscv32imac flash |"
  echo "| --- | ---: | ---: | ---: | ---: | ---: | ---: | ---: |"
  for bin in $SIZE_BINS; do
    row="| ${LABEL[$bin]}"
    for target in "$M4" "$M0" "$RV"; do
      t=${TEXT[$bin.$target]:-0}
      f=${FLASH[$bin.$target]:-0}
      if [ "$bin" = size_0_empty ]; then
        row="$row | $t B (absolute) | $f B (absolute)"
      else
        dt=$((t - ${TEXT[size_0_empty.$target]:-0}))
        df=$((f - ${FLASH[size_0_empty.$target]:-0}))
        mark=""
        [ "${PANIC[$bin.$target]:-no}" = yes ] && mark=" (panic path!)"
        row="$row | +$dt B ($(kb $dt))$mark | +$df B ($(kb $df))"
      fi
      if [ "$target" = "$M4" ]; then
        if [ -n "${BUDGET[$bin]:-}" ]; then row="$row | <= $(kb ${BUDGET[$bin]})"; else row="$row | -"; fi
      fi
    done
    echo "$row |"
  done
  echo
  echo "Growth over the empty firmware (cortex-m-rt, or riscv-rt on RISC-V), release profile with \`opt-level = \"s\"\`, \`lto = true\`,"
  echo "\`codegen-units = 1\`, \`panic = \"abort\"\`. Flash = .vector_table + .text + .rodata + .data (on RISC-V also"
  echo "riscv-rt's .init.rust and the unwind tables, .eh_frame, which its linker script keeps). Inputs come from"
  echo "volatile statics and every output goes to one, so nothing is constant-folded away. (1) to (4) test two"
  echo "unit squares, B placed by \`Transform::from_cos_sin\` from inputs. The squares are constants"
  echo "(\`Polygon::<f32, 4>::from_array\`, checked by the compiler, read through \`black_box\`), or, in the rows"
  echo "\"with polygons built at run time\", \`Polygon::<f32, 8>::new\` from inputs, which adds the polygon checks."
  echo "(5) runs every query through \`&dyn SupportMap\` on a pair of the ten shape kinds picked by the inputs."
  echo "Its shapes are constants (each shape's \`const\` constructor: \`Circle::new_const\`, ..., checked by the"
  echo "compiler), B placed by \`Transform::from_cos_sin\`; or, in the rows \"shapes built at run time\", built"
  echo "with \`new\` from inputs and placed by \`Transform::new\` (sin, cos), which adds every shape's checks and"
  echo "the sine. On thumbv6m (Cortex-M0/M0+/M3 code) and riscv32imac (no F extension) f32 is soft-float."
} >"$FW/size-table.md"
step "flash"
cat "$FW/size-table.md"
for bin in "${!BUDGET[@]}"; do
  t=${TEXT[$bin.$M4]:-}
  [ -n "$t" ] || continue
  dt=$((t - ${TEXT[size_0_empty.$M4]:-0}))
  [ "$dt" -le "${BUDGET[$bin]}" ] || miss "flash budget: ${LABEL[$bin]} is $dt bytes of .text on thumbv7em (> ${BUDGET[$bin]})"
done

# ---------------------------------------------------------------- regressions
# Instruction counts, peak stacks and sizes are deterministic for one
# compiler, so any difference from the committed figures is a change of the
# code. Growth fails the run where the budgets are enforced: a change that
# makes a query slower, deeper or bigger must commit the figures it
# measured (this script has just written them), where the diff shows it.
# ACCEPT_GROWTH=1 reports growth, and pages that quote other figures,
# without failing (to measure a change before committing it).
step "figures against the committed ones"
figures_fail=0
[ "$enforce_budgets" = 1 ] && [ "${ACCEPT_GROWTH:-0}" != 1 ] && figures_fail=1
grown=()
for f in $FIGURES; do
  changes="$(awk -f "$FW/compare-figures.awk" "$out/$f.committed.md" "$FW/$f.md")"
  if [ -z "$changes" ]; then
    echo "$f.md: as committed"
    continue
  fi
  echo "$f.md: $(grep -c . <<<"$changes") change(s) from the committed figures"
  sed 's/^/  /' <<<"$changes"
  while IFS= read -r change; do grown+=("$f.md: ${change#GREW    }"); done < <(grep '^GREW' <<<"$changes" || true)
done
# The firmware page quotes the three tables whole: each of their rows must be
# there as measured, or the page states figures nobody measured. README.md's
# status table quotes the .text of the budgeted firmwares on the M4F and the
# range of its stacks per precision, checked the same way.
source "$ROOT/.ci/quoted.sh"
for f in $FIGURES; do
  quotes_rows "$FW/README.md" "$(grep '^|' "$FW/$f.md")"
done
summary=()
for bin in size_1_intersect_const size_2_distance_const size_3_penetration_const size_5_all_f32_const; do
  summary+=("${LABEL[$bin]} $(kb $((${TEXT[$bin.$M4]:-0} - ${TEXT[size_0_empty.$M4]:-0})))")
done
for precision in f32 f64; do
  summary+=("$(grep '^MEASURE|' "$out/measure.txt" | grep -v 'Epa N' | awk -F'|' -v p="$precision" '
    $2 == p { s = $6 + 0; if (n++ == 0 || s < lo) lo = s; if (s > hi) hi = s }
    END { printf "%s: %d to %d B", p, lo, hi }')")
done
quotes "$ROOT/README.md" "${summary[@]}"
quoted_verdict "$figures_fail" || fail "firmware/README.md or README.md quote other figures than the measured ones in $stale place(s)"
if [ ${#grown[@]} -gt 0 ]; then
  if [ "$figures_fail" = 1 ]; then
    fail "${#grown[@]} figure(s) grew over the committed ones (commit the new firmware/*.md if intended; ACCEPT_GROWTH=1 reports only)"
  else
    echo "${#grown[@]} figure(s) grew (reported, not failed)"
  fi
fi

step "summary"
echo "run.sh took $(($(date +%s) - start)) s"
if [ "$enforce_budgets" = 1 ]; then
  echo "budgets enforced (rustc $RUSTC_VERSION); ${#known_misses[@]} known miss(es) reported:"
else
  echo "budgets reported, not enforced (rustc $RUSTC_VERSION, measured with $BUDGET_RUSTC); ${#known_misses[@]} known miss(es):"
fi
[ ${#known_misses[@]} -eq 0 ] || printf '  %s\n' "${known_misses[@]}"
if [ ${#misses[@]} -gt 0 ]; then
  echo "${#misses[@]} budget(s) missed that were met before:"
  printf '  %s\n' "${misses[@]}"
fi
if [ ${#failures[@]} -gt 0 ]; then
  printf 'FAILED: %s\n' "${failures[@]}"
  exit 1
fi
echo "firmware: all checks passed"
