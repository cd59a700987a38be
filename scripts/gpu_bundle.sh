#!/usr/bin/env bash
# Packs a build's programs with the shared libraries they load (not glibc, not the GL
# dispatch libraries: those must be the target machine's, to reach its GPU driver) and the
# shared models, to run the benchmarks on another x86-64 Linux machine that has no Debian
# packages (a lent GPU machine; scripts/gpu_bench.sh runs them there):
#
#   scripts/gpu_bundle.sh [BUILD_DIR] [OUT_DIR] [PARTS]     # default: build .dev 3
#
# OUT_DIR/bundle-1.tar.xz holds both programs, plumbago_bench's few libraries and the
# models: plumbago_bench runs from it alone. bundle-2 .. bundle-PARTS hold the other
# libraries `plumbago` loads (OpenImageIO's: about 400 MB, 100 MB compressed, more than
# one device call carries), spread evenly by size.
set -euo pipefail
cd "$(dirname "$0")/.."
build=${1:-build}
out=${2:-.dev}
parts=${3:-3}
stage=$(mktemp -d)
trap 'rm -rf "$stage"' EXIT
mkdir -p "$stage/bin" "$stage/lib" "$out"
cp "$build/plumbago" "$build/plumbago_bench" "$stage/bin/"
system='^(libc|libm|libdl|libpthread|librt|ld-linux-x86-64|libEGL|libGL|libGLX|libGLdispatch|libOpenGL)\.so'
libraries() { ldd "$@" | awk '/=> \// {print $3}' | sort -u; }
copy() { while read -r lib; do [[ $(basename "$lib") =~ $system ]] || cp -L "$lib" "$stage/lib/"; done; }
libraries "$build/plumbago_bench" | copy
[ -d ../shared/models ] && cp -r ../shared/models "$stage/models"
# The checkout the programs were built from: they look for scenes, styles and shaders there.
sed -n 's/^CMAKE_HOME_DIRECTORY:INTERNAL=//p' "$build/CMakeCache.txt" > "$stage/source_dir"
(cd "$stage" && find . -type f -printf '%P\n') > "$stage/.part1"
libraries "$build/plumbago" | copy
# The rest, largest first, each to the part that holds the fewest bytes so far.
(cd "$stage" && find . -type f ! -name '.part*' -printf '%s %P\n' | sort -rn) | while read -r bytes path; do
  grep -qxF "$path" "$stage/.part1" || echo "$bytes $path"
done | awk -v n="$parts" -v dir="$stage" '
  { k = 2; for (i = 3; i <= n; ++i) if (bytes[i] < bytes[k]) k = i; bytes[k] += $1; print $2 > (dir "/.part" k) }'
for k in $(seq "$parts"); do
  XZ_OPT=-9 tar -cJf "$out/bundle-$k.tar.xz" -C "$stage" -T "$stage/.part$k"
  echo "gpu_bundle: $out/bundle-$k.tar.xz, $(du -h "$out/bundle-$k.tar.xz" | cut -f1)"
done
