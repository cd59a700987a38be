#!/usr/bin/env bash
# Configures and builds Plumbago into build/ (or $BUILD_DIR). Extra arguments go to cmake.
# BUILD_TARGETS (space-separated) builds only those targets, e.g. BUILD_TARGETS=plumbago for
# the command line program alone (no tests, benchmarks or experiments).
set -euo pipefail
cd "$(dirname "$0")/.."
build_dir=${BUILD_DIR:-build}
cmake -S . -B "$build_dir" -G Ninja -DCMAKE_BUILD_TYPE=Release "$@"
targets=()
for t in ${BUILD_TARGETS:-}; do targets+=(--target "$t"); done
cmake --build "$build_dir" -j"$(nproc)" "${targets[@]}"
