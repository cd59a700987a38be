#!/usr/bin/env bash
# Regenerates the golden images in tests/golden/ from the current code (docs/testing.md).
# Run it only when an image change is intended, and say why in the commit.
# Builds (or brings the build up to date) in build/ or $BUILD_DIR, runs the golden tests
# with PLUMBAGO_UPDATE_GOLDEN=1 (they write the goldens that changed instead of comparing),
# then shows which goldens changed. Extra arguments go to the test binary.
set -euo pipefail
cd "$(dirname "$0")/.."
build_dir=${BUILD_DIR:-build}
if [[ -f "$build_dir/build.ninja" ]]; then
  cmake --build "$build_dir" -j"$(nproc)" --target plumbago_tests
else
  BUILD_DIR="$build_dir" scripts/build.sh
fi
# From the build folder, as ctest runs it: the test finds the sources relative to it.
(cd "$build_dir" && PLUMBAGO_UPDATE_GOLDEN=1 ./plumbago_tests --gtest_filter='Golden/GoldenImage.*' "$@")
echo "git status --short tests/golden:"
git status --short tests/golden
