#!/usr/bin/env bash
# The benchmark: `shadowlab report` of every shadow technique at its defaults, under every light
# type, on the scene presets seed, torus, cubes and city and on two real models of Debian's
# assimp-testmodels (a glTF engine and a textured OBJ spider). Writes docs/benchmark.md, a table
# per scene with its machine and GL renderer named, and each report's Pareto charts as SVG under
# docs/benchmark/. A benchmark, not a test: nothing here has a time limit.
#
#   ./scripts/benchmark.sh [--size WxH] [--frames N] [--area-samples N] [--out DIR] [--scenes "A B"]
#                          [--shards N] [--jobs N] [--parts DIR] [--print-jobs | --merge-only]
#
# The defaults (320x180, 6 timed frames after 1 warm-up, 4 x 4 area rays a pixel, no flicker
# walk) keep the whole run to about 8 minutes on two cores with llvmpipe (docs/benchmark.md
# says how long its run took); moment techniques under a point light are the slowest part.
#
# Spread over processes, machines or a scheduler (docs/cli-guide.md shows each):
#   --shards N     cut each scene and light's report into N shares (`report --shard K/N`)
#   --jobs N       run the reports, or their shares, N at a time through GNU parallel; on one
#                  machine they then share its cores, which their times show
#   --parts DIR    where each share's report goes (kept; default: a temporary folder)
#   --print-jobs   print one shell command a line, each share's report, and stop: for a
#                  scheduler (a Slurm job array runs line $SLURM_ARRAY_TASK_ID) or
#                  `parallel --sshlogin` across machines
#   --merge-only   measure nothing: merge the shares already in --parts into docs/benchmark.md;
#                  give it the options the jobs were printed with
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
binary="${SHADOWLAB:-$root/build/release/app/shadowlab}"
models=/usr/share/assimp/models
size=320x180
frames=6
area_samples=4
out="$root/docs"
scenes=(seed torus cubes city "$models/glTF2/2CylinderEngine-glTF-Binary/2CylinderEngine.glb" "$models/OBJ/spider.obj")
shards=1
jobs=1
parts=
mode=run
usage='use [--size WxH] [--frames N] [--area-samples N] [--out DIR] [--scenes "A B"] [--shards N] [--jobs N] [--parts DIR] [--print-jobs | --merge-only]'
count() {   # a whole number of 1 or more for option $1, or exit 2
    [[ $2 =~ ^[1-9][0-9]*$ ]] || { echo "benchmark.sh: $1 $2: give a whole number of 1 or more" >&2; exit 2; }
}
scenes_given=
while [ $# -gt 0 ]; do
    case "$1" in
        --size|--frames|--area-samples|--out|--scenes|--shards|--jobs|--parts)
            [ $# -ge 2 ] || { echo "benchmark.sh: $1 needs a value; $usage" >&2; exit 2; } ;;&
        --size) size=$2; shift 2 ;;
        --frames) frames=$2; shift 2 ;;
        --area-samples) area_samples=$2; shift 2 ;;
        --out) out=$2; shift 2 ;;
        --scenes) read -r -a scenes <<<"$2"; scenes_given=$2; shift 2 ;;
        --shards) count "$1" "$2"; shards=$2; shift 2 ;;
        --jobs) count "$1" "$2"; jobs=$2; shift 2 ;;
        --parts) parts=$2; shift 2 ;;
        --print-jobs|--merge-only)
            [ "$mode" = run ] || { echo "benchmark.sh: give one of --print-jobs and --merge-only" >&2; exit 2; }
            mode=${1#--}; mode=${mode%-*}; shift ;;
        -h|--help) sed -n '2,/^set -euo/{/^set -euo/d;s/^# \{0,1\}//;p}' "$0"; exit 0 ;;
        *) echo "benchmark.sh: unknown option '$1'; $usage" >&2; exit 2 ;;
    esac
done
[ ${#scenes[@]} -gt 0 ] || { echo "benchmark.sh: --scenes names no scene; give presets or model files, e.g. --scenes \"seed torus\"" >&2; exit 2; }
[ "$mode" != merge ] || [ -n "$parts" ] || { echo "benchmark.sh: --merge-only merges the shares in --parts DIR; say where they are" >&2; exit 2; }
[ "$mode" != print ] || [ -n "$parts" ] || { echo "benchmark.sh: --print-jobs needs --parts DIR, a folder every job can write its share to" >&2; exit 2; }
if [ "$jobs" -gt 1 ] && ! command -v parallel >/dev/null; then
    echo "benchmark.sh: --jobs runs the reports through GNU parallel, which is missing; scripts/setup.sh installs it" >&2
    exit 2
fi
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
techniques=$(python3 -c 'import json, sys; print(len(json.load(open(sys.argv[1]))))' "$work/techniques.json")
[ "$shards" -le "$techniques" ] || { echo "benchmark.sh: --shards $shards: each report has $techniques techniques, so cut it into at most $techniques shares" >&2; exit 2; }

for scene in "${scenes[@]}"; do
    [ "$mode" = merge ] || [ -f "$scene" ] || [[ "$scene" != */* ]] || { echo "benchmark.sh: $scene is missing; install assimp-testmodels (scripts/setup.sh)" >&2; exit 2; }
done
parts=${parts:-$work/parts}
mkdir -p "$parts"
parts=$(cd "$parts" && pwd)

# One line a share: a shell command that measures it into $parts/<scene>/<light>/<k>, its log
# beside it. Every line reads the sweep from $parts, so a scheduler's job needs nothing else.
names=()
: >"$work/jobs"
for scene in "${scenes[@]}"; do
    name=$(basename "$scene"); name=${name%.*}
    names+=("$name")
    for light in "${light_types[@]}"; do
        mkdir -p "$parts/$name/$light"
        for ((k = 1; k <= shards; k++)); do
            printf 'QT_QPA_PLATFORM=headless %q report --scene %q --set light.type=%q --size %q --sweep %q --frames %q --warmup 1 --area-samples %q --flicker-frames 0 --shard %d/%d --out %q >%q 2>&1\n' \
                "$binary" "$scene" "$light" "$size" "$parts/techniques.json" "$frames" "$area_samples" "$k" "$shards" \
                "$parts/$name/$light/$k" "$parts/$name/$light/$k.log" >>"$work/jobs"
        done
    done
done
[ "$mode" = merge ] || cp "$work/techniques.json" "$parts/techniques.json"
if [ "$mode" = print ]; then
    cat "$work/jobs"
    exit 0
fi

start=$(date +%s)
if [ "$mode" = run ]; then
    echo "==> $(wc -l <"$work/jobs") reports ($shards share(s) of each scene and light), $jobs at a time; each log beside its report in $parts"
    if [ "$jobs" -gt 1 ]; then
        parallel --jobs "$jobs" --halt now,fail=1 <"$work/jobs" \
            || { echo "benchmark.sh: a report failed; its log is beside its folder in $parts" >&2; exit 1; }
    else
        while IFS= read -r job; do
            if ! bash -c "$job" </dev/null; then
                log=${job% 2>&1}; log=${log##*>}
                echo "benchmark.sh: a report failed: $job" >&2
                cat "$log" >&2 || true
                exit 1
            fi
        done <"$work/jobs"
    fi
fi

# Each scene and light's shares, put together into one report.
for name in "${names[@]}"; do
    mkdir -p "$work/reports/$name"
    for light in "${light_types[@]}"; do
        shares=()
        for ((k = 1; k <= shards; k++)); do
            shares+=("$parts/$name/$light/$k")
        done
        if ! "$binary" report --merge --out "$work/reports/$name/$light" "${shares[@]}" >"$work/merge.log" 2>&1; then
            cat "$work/merge.log" >&2
            echo "benchmark.sh: the shares of $name under the $light light did not merge; a job may have failed: see its log, $parts/$name/$light/K.log" >&2
            exit 1
        fi
    done
done
seconds=$(( $(date +%s) - start ))
if [ "$mode" = merge ]; then
    # Measured elsewhere: the options the page names must be those the shares were measured with.
    python3 -c 'import json, math, sys
r = json.load(open(sys.argv[1]))
measured = (r["size"], r["frames"], round(math.sqrt(r["area_samples_per_pixel"])))
given = (sys.argv[2], int(sys.argv[3]), int(sys.argv[4]))
if measured != given:
    sys.exit("benchmark.sh: the shares were measured with --size %s --frames %d --area-samples %d; give --merge-only the same options "
             "(it was given --size %s --frames %d --area-samples %d)" % (measured + given))' \
        "$work/reports/${names[0]}/${light_types[0]}/report.json" "$size" "$frames" "$area_samples" || exit 2
    # Their own time, every share's added.
    seconds=$(python3 -c 'import json, sys
print(round(sum(json.load(open(f))["seconds"] for f in sys.argv[1:])))' "$work"/reports/*/*/report.json)
fi

command="scripts/benchmark.sh --size $size --frames $frames --area-samples $area_samples"
[ "$shards" -eq 1 ] || command+=" --shards $shards"
[ "$jobs" -eq 1 ] || command+=" --jobs $jobs"
[ -z "$scenes_given" ] || command+=" --scenes \"$scenes_given\""
python3 "$root/scripts/benchmark-doc.py" --reports "$work/reports" --out "$out" --seconds "$seconds" \
    --scenes "${names[@]}" --lights "${light_types[@]}" --command "$command"
echo "wrote $out/benchmark.md in $seconds s"
