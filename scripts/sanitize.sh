#!/usr/bin/env bash
# The ASan + UBSan build (clang, -DPLUMBAGO_SANITIZE=ON) in build-sanitize/ (or $BUILD_DIR):
#   scripts/sanitize.sh           the non-GL tests under the sanitizers, then the fuzz smoke run
#   scripts/sanitize.sh tests     the non-GL tests only
#   scripts/sanitize.sh fuzz [T]  the fuzz run only (every target, or those named: fuzz_mesh_ply ...)
# Each fuzz target first replays its regression inputs (tests/corpus/fuzz/TARGET/), then
# fuzzes for $FUZZ_SECONDS (default 20) from its seeds (fuzz/make_seeds.py) and the inputs
# earlier runs kept (build-sanitize/fuzz-corpus/TARGET/). A crash, sanitizer report, hang
# (over $FUZZ_TIMEOUT s, default 10, for one input) or an input using over 2 GB stops the
# run; the input is saved as build-sanitize/fuzz-findings/TARGET-crash-... (or -timeout-,
# -oom-, -leak-) and the script fails. Fuzz longer with FUZZ_SECONDS=600.
set -euo pipefail
cd "$(dirname "$0")/.."
root=$PWD
build=${BUILD_DIR:-build-sanitize}
what=${1:-all}
[ $# -gt 0 ] && shift

fuzz_targets=(fuzz_mesh_obj fuzz_mesh_off fuzz_mesh_ply fuzz_mesh_stl fuzz_scene fuzz_svg fuzz_strokes)
[ "$what" = fuzz ] && [ $# -gt 0 ] && fuzz_targets=("$@")
case "$what" in
  all) targets=(plumbago_tests "${fuzz_targets[@]}") ;;
  tests) targets=(plumbago_tests) ;;
  fuzz) targets=("${fuzz_targets[@]}") ;;
  *) echo "sanitize.sh: unknown mode '$what' (all, tests or fuzz)" >&2; exit 2 ;;
esac

cmake -S . -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=Release -DCMAKE_CXX_COMPILER=clang++-14 -DPLUMBAGO_SANITIZE=ON \
  -DPLUMBAGO_WERROR="${PLUMBAGO_WERROR:-OFF}"
cmake --build "$build" -j"$(nproc)" --target "${targets[@]}"

export PATH=/usr/lib/llvm-14/bin:$PATH  # llvm-symbolizer: reports name functions and lines
export ASAN_OPTIONS=detect_stack_use_after_return=1:strict_string_checks=1:check_initialization_order=1
export UBSAN_OPTIONS=print_stacktrace=1
export LSAN_OPTIONS=suppressions=$root/scripts/lsan.supp

if [ "$what" != fuzz ]; then
  (cd "$build" && ctest --output-on-failure -j"$(nproc)" --timeout 900)
fi
[ "$what" = tests ] && exit 0

seconds=${FUZZ_SECONDS:-20}
export TMPDIR=$root/$build/fuzz-tmp  # the mesh targets write each input to a file there
findings=$build/fuzz-findings
mkdir -p "$TMPDIR" "$findings"
python3 fuzz/make_seeds.py ../shared/models scenes styles tests/corpus "$build/fuzz-seeds"
failed=()
for target in "${fuzz_targets[@]}"; do
  format=${target#fuzz_}
  format=${format#mesh_}
  corpus=$build/fuzz-corpus/$target
  mkdir -p "$corpus"
  regressions=()
  [ -d "tests/corpus/fuzz/$target" ] && mapfile -t regressions < <(find "tests/corpus/fuzz/$target" -type f | sort)
  flags=(-timeout="${FUZZ_TIMEOUT:-10}" -rss_limit_mb=2048 -max_len=4096 -artifact_prefix="$findings/$target-")
  echo "== $target: ${#regressions[@]} regression inputs, then $seconds s of fuzzing"
  log=$findings/$target.log
  if { [ ${#regressions[@]} -eq 0 ] || "$build/fuzz/$target" "${flags[@]}" "${regressions[@]}"; } >"$log" 2>&1 &&
     "$build/fuzz/$target" "${flags[@]}" -max_total_time="$seconds" -print_final_stats=1 \
       "$corpus" "$build/fuzz-seeds/$format" >>"$log" 2>&1; then
    grep -E '^#[0-9]+[[:space:]]+DONE' "$log"
  else
    tail -n 40 "$log"
    failed+=("$target")
  fi
done
if [ ${#failed[@]} -gt 0 ]; then
  echo "sanitize.sh: findings in ${failed[*]}: inputs in $findings/, logs in $findings/TARGET.log" >&2
  exit 1
fi
