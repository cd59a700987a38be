#!/usr/bin/env bash
# Runs the benchmarks on a lent GPU machine, in the repository root, from the parts of
# scripts/gpu_bundle.sh under .dev/ (the device tool carries them; .gl/ holds the GL
# dispatch packages its README names). Each call unpacks the parts it carries, then:
#
#   scripts/gpu_bench.sh unpack            # nothing more
#   scripts/gpu_bench.sh micro [FILTER]    # plumbago_bench (bundle-1 alone), default: the GPU ones
#   scripts/gpu_bench.sh paper             # plumbago bench --paper (every part unpacked)
#   scripts/gpu_bench.sh study NAME        # a study of experiments/ with the full config, no Snakemake
#
# Results go to $OUT (micro.txt; paper_claims/ as experiments/paper_claims writes it; NAME/
# as the study's collect step writes it).
set -uo pipefail
bundle=/tmp/plumbago-bundle
out=${OUT:-/tmp/plumbago-out}
mkdir -p "$bundle" "$out"
if [ -d /usr/local/nvidia ]; then  # the GPU machine: its driver behind glvnd's dispatch libraries
  for f in .gl/*.deb; do dpkg -x "$f" /; done
  ldconfig
  vendor=/usr/local/nvidia/share/glvnd/egl_vendor.d/10_nvidia.json
  [ -e "$vendor" ] && export __EGL_VENDOR_LIBRARY_FILENAMES=$vendor
fi
for part in .dev/bundle-*.tar.xz; do
  [ -e "$part" ] && tar -xJf "$part" -C "$bundle" && echo "unpacked $part"
done
export LD_LIBRARY_PATH=$bundle/lib PLUMBAGO_SHADER_DIR=$PWD/shaders PLUMBAGO_MODELS_DIR=$bundle/models
export PLUMBAGO_CACHE_DIR=/tmp/plumbago-cache
[ -e ../shared/models ] || { mkdir -p ../shared && ln -s "$bundle/models" ../shared/models; }
source_dir=$(cat "$bundle/source_dir" 2>/dev/null || true)  # compiled into the programs (scenes, styles)
if [ -n "$source_dir" ] && [ ! -e "$source_dir" ]; then mkdir -p "$(dirname "$source_dir")" && ln -s "$PWD" "$source_dir"; fi
case ${1:-unpack} in
  unpack) ;;
  micro)
    nvidia-smi -L 2>/dev/null
    "$bundle/bin/plumbago_bench" --benchmark_filter="${2:-Gpu}" --benchmark_min_time=0.3 2>&1 | tee "$out/micro.txt" ;;
  paper)
    if ldd "$bundle/bin/plumbago" | grep "not found"; then echo "gpu_bench: a part is missing" >&2; exit 3; fi
    PLUMBAGO=$bundle/bin/plumbago /usr/bin/env python3 experiments/paper_claims/run.py \
      '{"frames": 20, "reference_frames": 3, "size": null}' "$out/paper_claims" ;;
  study)
    name=$2 points=/tmp/plumbago-points/$2 run="experiments/$2/run.py"
    settings=$(python3 -c "import json, sys, yaml; print(json.dumps(yaml.safe_load(open(sys.argv[1]))[sys.argv[2]]))" \
      experiments/config/full.yaml "$name")
    mkdir -p "$points"
    export PLUMBAGO=$bundle/bin/plumbago
    for point in $(python3 "$run" points "$settings"); do python3 "$run" measure "$settings" "$point" "$points/$point.json"; done
    python3 "$run" collect "$settings" "$out/$name" "$points"/*.json ;;
  *) echo "gpu_bench: unpack, micro [FILTER], paper or study NAME" >&2; exit 2 ;;
esac
