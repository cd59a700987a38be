#!/usr/bin/env bash
# Builds Plumbago and runs the whole test suite: the EGL build (default) with ctest, then
# the OSMesa build's GPU tests and the Python module's (same GPU code through the other GL
# platform).
set -euo pipefail
cd "$(dirname "$0")/.."
werror=${PLUMBAGO_WERROR:-OFF}
# A fresh Mesa shader cache for this run: a shader compiled here for the first time reports
# its compiler's messages, which the GL context turns into errors (gpu/gl/context.cpp),
# whatever an earlier run left cached on this machine.
MESA_SHADER_CACHE_DIR=$(mktemp -d)
export MESA_SHADER_CACHE_DIR
trap 'rm -rf "$MESA_SHADER_CACHE_DIR"' EXIT
BUILD_DIR=build scripts/build.sh -DPLUMBAGO_WERROR="$werror"
(cd build && ctest --output-on-failure -j"$(nproc)" --timeout 900)
cmake -S . -B build-osmesa -G Ninja -DCMAKE_BUILD_TYPE=Release -DPLUMBAGO_GL=osmesa -DPLUMBAGO_WERROR="$werror"
cmake --build build-osmesa -j"$(nproc)" --target plumbago_tests plumbago_python
(cd build-osmesa && ctest --output-on-failure -j"$(nproc)" --timeout 900 -R "GlContext|Parity|GlTest|Frames|SamplerVsGpu|Cli|Golden|Stage|BaseCoat|python_")
