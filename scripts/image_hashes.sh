#!/usr/bin/env bash
# Renders every scene in scenes/ and every built-in scene on both backends, with every
# intermediate buffer (--dump-stages), and prints one "sha256  backend/scene/file" line per
# file written, sorted. Two builds that should draw the same (a refactoring) must print the
# same list: scripts/image_hashes.sh build > a.txt; ...; diff a.txt b.txt.
# Usage: scripts/image_hashes.sh BUILD_DIR [SCENE ...]
set -euo pipefail
cd "$(dirname "$0")/.."
build=${1:?usage: scripts/image_hashes.sh BUILD_DIR [SCENE ...]}
shift
scenes=("$@")
if [ ${#scenes[@]} -eq 0 ]; then
  mapfile -t scenes < <(ls scenes/*.json | grep -v schema)
  scenes+=(builtin:pencil builtin:cad builtin:sphere builtin:torus)
fi
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
for scene in "${scenes[@]}"; do
  name=$(basename "${scene#builtin:}" .json)
  for backend in gpu reference; do
    dir="$out/$backend/$name"
    mkdir -p "$dir"
    "$build/plumbago" render "$scene" --backend "$backend" -o "$dir/frame.png" \
      --dump-stages "$dir/stages" > /dev/null
  done
done
(cd "$out" && find . -type f -print0 | sort -z | xargs -0 sha256sum)
