#!/usr/bin/env bash
# Fuzzing; not part of the test suite.
#   ./scripts/fuzz.sh [settings] [seconds]   libFuzzer on settings files, --set lines and sweep files
#   ./scripts/fuzz.sh import-answer [seconds] libFuzzer on the import worker's answer as the parent
#                                            decodes it, seeded with real models' answers
#   ./scripts/fuzz.sh models [count]         a mutation run: COUNT damaged copies (default 2000) of
#                                            real models of assimp-testmodels in nine formats, each
#                                            read through the import worker by the release build
# The libFuzzer targets build the `fuzz` preset (clang, ASan + UBSan) and run for a bounded time,
# default 300 s; findings (crash-*, leak-*, timeout-*) land in build/fuzz/findings. The mutation
# run fails when ShadowLab itself crashes or overruns its import time limit on any file.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
target=settings
if [ $# -gt 0 ] && [[ ! "$1" =~ ^[0-9]+$ ]]; then
    target=$1
    shift
fi

if [ "$target" = models ]; then
    count="${1:-2000}"
    "$root/scripts/setup.sh"
    work="$root/build/fuzz-models"
    rm -rf "$work" && mkdir -p "$work"
    python3 "$root/fuzz/damage-models.py" "$work/files" --count "$count" --seed "${FUZZ_SEED:-1}"
    # The worker gets 5 s a file here (a hang costs that, not the default 30 s); a run much longer
    # than that is ShadowLab's own fault.
    SURVEY_COMMAND=import SURVEY_ARGS="--import-time-limit 5" SURVEY_TSV="$work/survey.tsv" \
        "$root/fuzz/survey.sh" "$root/build/release/app/shadowlab" "$work/files" 20 | tee "$work/summary.txt"
    if awk -F'\t' '$3 == "crashed" || $3 == "overtime" || $3 == "other" { bad = 1 } END { exit !bad }' "$work/survey.tsv"; then
        echo "==> ShadowLab crashed, hung or failed on some file: see $work/survey.tsv"
        exit 1
    fi
    echo "==> every file was read or refused with a message: $work/survey.tsv"
    exit 0
fi

seconds="${1:-300}"
case "$target" in
    settings) binary=fuzz_settings_files ;;
    import-answer) binary=fuzz_import_answer ;;
    *) echo "fuzz.sh: unknown target '$target'; use settings, import-answer or models" >&2; exit 2 ;;
esac
SHADOWLAB_PRESET=fuzz "$root/scripts/setup.sh"

work="$root/build/fuzz"
corpus="$work/corpus-$target"
mkdir -p "$corpus" "$work/findings"
if [ "$target" = settings ]; then
    cp -n "$root"/fuzz/corpus/* "$corpus/"   # the seeds stay as they are in the repository
else
    # Seeds: the worker's answers for real models of every format it reads, and a refusal.
    models=/usr/share/assimp/models
    for file in "$models/glTF2/BoxTextured-glTF/BoxTextured.gltf" "$models/glTF2/2CylinderEngine-glTF-Binary/2CylinderEngine.glb" \
                "$models/OBJ/box.obj" "$models/PLY/cube.ply" "$models/STL/Spider_ascii.stl" "$models/Collada/duck.dae" \
                "$models/FBX/box.fbx" "$models/3DS/fels.3ds" "$models/OFF/Cube.off" "$models/invalid/empty.obj"; do
        [ -f "$file" ] && "$work/app/shadowlab-import-worker" "$file" >"$corpus/$(basename "$file").answer" 2>/dev/null || true
    done
fi
cd "$work/findings"
status=0
UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1 \
    "$work/fuzz/$binary" -max_total_time="$seconds" -max_len=$((1 << 20)) -timeout=10 -rss_limit_mb=4096 \
    -print_final_stats=1 "$corpus" >"$work/fuzz-$target.log" 2>&1 || status=$?
grep -E '^(#[0-9]+ +(INITED|DONE)|stat::number_of_executed_units|==[0-9]+==ERROR|SUMMARY)' "$work/fuzz-$target.log" || true
echo "==> log: $work/fuzz-$target.log; exit status $status (0: no crash, leak, timeout or sanitizer report)"
exit "$status"
