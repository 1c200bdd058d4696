#!/usr/bin/env bash
# The benchmark: `shadowlab report` of every shadow technique at its defaults, under every light
# type, on the scene presets seed, torus, cubes and city and on two real models of Debian's
# assimp-testmodels (a glTF engine and a textured OBJ spider). Writes docs/benchmark.md, a table
# per scene with its machine and GL renderer named, and each report's Pareto charts as SVG under
# docs/benchmark/. A benchmark, not a test: nothing here has a time limit.
#
#   ./scripts/benchmark.sh [--size WxH] [--frames N] [--area-samples N] [--out DIR]
#
# The defaults (320x180, 6 timed frames after 1 warm-up, 4 x 4 area rays a pixel, no flicker
# walk) keep the whole run to about 8 minutes on two cores with llvmpipe (docs/benchmark.md
# says how long its run took); moment techniques under a point light are the slowest part.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
binary="${SHADOWLAB:-$root/build/release/app/shadowlab}"
models=/usr/share/assimp/models
size=320x180
frames=6
area_samples=4
out="$root/docs"
while [ $# -gt 0 ]; do
    case "$1" in
        --size) size=$2; shift 2 ;;
        --frames) frames=$2; shift 2 ;;
        --area-samples) area_samples=$2; shift 2 ;;
        --out) out=$2; shift 2 ;;
        *) echo "benchmark.sh: unknown option '$1'; use [--size WxH] [--frames N] [--area-samples N] [--out DIR]" >&2; exit 2 ;;
    esac
done
[ -x "$binary" ] || { echo "benchmark.sh: no program at $binary; build it with scripts/setup.sh (or set SHADOWLAB)" >&2; exit 2; }
export QT_QPA_PLATFORM=headless

work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

# Techniques and light types as the program lists them, so a new one is benchmarked unasked.
"$binary" settings --json > "$work/settings.json"
read -r -a light_types < <(python3 -c 'import json, sys
print(" ".join(next(s for s in json.load(open(sys.argv[1])) if s["key"] == "light.type")["choices"]))' "$work/settings.json")
python3 -c 'import json, sys
modes = next(s for s in json.load(open(sys.argv[1])) if s["key"] == "filter.mode")["choices"]
json.dump([{"label": m, "set": {"filter.mode": m}} for m in modes], open(sys.argv[2], "w"))' "$work/settings.json" "$work/techniques.json"

scenes=(seed torus cubes city "$models/glTF2/2CylinderEngine-glTF-Binary/2CylinderEngine.glb" "$models/OBJ/spider.obj")
for scene in "${scenes[@]}"; do
    [ -f "$scene" ] || [[ "$scene" != */* ]] || { echo "benchmark.sh: $scene is missing; install assimp-testmodels (scripts/setup.sh)" >&2; exit 2; }
done

start=$(date +%s)
names=()
for scene in "${scenes[@]}"; do
    name=$(basename "$scene"); name=${name%.*}
    names+=("$name")
    mkdir -p "$work/reports/$name"
    for light in "${light_types[@]}"; do
        echo "==> $name, $light light"
        report_start=$(date +%s)
        "$binary" report --scene "$scene" --set "light.type=$light" --size "$size" --sweep "$work/techniques.json" \
            --frames "$frames" --warmup 1 --area-samples "$area_samples" --flicker-frames 0 --out "$work/reports/$name/$light" \
            > "$work/report.log" 2>&1 || { cat "$work/report.log" >&2; exit 1; }
        echo "$(( $(date +%s) - report_start )) s"
    done
done
seconds=$(( $(date +%s) - start ))

python3 "$root/scripts/benchmark-doc.py" --reports "$work/reports" --out "$out" --seconds "$seconds" \
    --scenes "${names[@]}" --lights "${light_types[@]}" --command "scripts/benchmark.sh --size $size --frames $frames --area-samples $area_samples"
echo "wrote $out/benchmark.md in $seconds s"
