#!/usr/bin/env bash
# Every model of assimp-testmodels that moves (a node animation Assimp reads), measured at three
# instants of its clip against the reference traced at each: misclassified pixels per instant,
# and a picture of each instant to look at.
#   scripts/animated-models.sh OUT_DIR [BUILD_DIR]
# Writes OUT_DIR/animated-models.md (a table) and OUT_DIR/<model>/{report.json, t*.png}.
set -euo pipefail
out=${1:?usage: scripts/animated-models.sh OUT_DIR [BUILD_DIR]}
build=${2:-build/release}
shadowlab="$build/app/shadowlab"
models=/usr/share/assimp/models
mkdir -p "$out"
sweep="$out/defaults.json"
echo '[{"label": "defaults", "set": {}}]' > "$sweep"
table="$out/animated-models.md"
echo "| model | clip | misclassified at each instant (%) | worst DSSIM (%) |" > "$table"
echo "| --- | ---: | --- | ---: |" >> "$table"
find "$models" -type f | sort | while read -r model; do
    name=$(realpath --relative-to="$models" "$model")
    dir="$out/$(echo "$name" | tr '/ ' '__')"
    # A still model, or one Assimp cannot read, is refused before any work: skip it.
    if ! "$shadowlab" report --scene "$model" --animation 3 --sweep "$sweep" --size 320x180 --frames 2 --warmup 0 \
            --area-samples 2 --flicker-frames 0 --out "$dir" > "$dir.log" 2>&1; then
        rm -rf "$dir" "$dir.log"
        continue
    fi
    python3 - "$dir/report.json" "$name" >> "$table" <<'PY'
import json, sys
row = json.load(open(sys.argv[1]))["rows"][0]["animation"]
each = ", ".join(f"{t:.2f} s: {m:.3f}" for t, m in zip(row["times"], row["misclassified_pct"]["each"]))
clip = row["times"][1] * 3 if len(row["times"]) > 1 else 0
print(f"| {sys.argv[2]} | {clip:.2f} s | {each} | {row['dssim_pct']['worst']:.2f} |")
PY
    for t in $(python3 -c "import json,sys; print(' '.join(str(x) for x in json.load(open('$dir/report.json'))['rows'][0]['animation']['times']))"); do
        "$shadowlab" render --scene "$model" --time "$t" --size 480x270 --out "$dir/t$t.png" > /dev/null 2>&1 || true
    done
    rm -f "$dir.log"
done
cat "$table"
