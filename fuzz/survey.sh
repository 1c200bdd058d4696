#!/usr/bin/env bash
# Survey how a shadowlab binary copes with every model file under a folder.
#
# Usage: survey.sh BINARY DIR [TIMEOUT_S=60]
#
# Runs `timeout -s KILL TIMEOUT BINARY render --scene FILE --size 160x90 --out TMP/out.png` for each
# model file under DIR (companions such as .bin/.png/.jpg/.mtl are skipped), one at a time, and
# classifies the result:
#   rendered  exit 0
#   refused   exit 2 (the message is on stderr; a refusal must name the file, flagged if not)
#   overtime  killed by the timeout (137 after TIMEOUT seconds)
#   crashed   any other signal: 139 SIGSEGV, 134 SIGABRT, ..., or SIGKILL before the timeout (OOM)
#   other     any other exit code
# The TSV (file, format, outcome, exit, seconds, first stderr line, max RSS in MB, - when over time) goes to
# $SURVEY_TSV when set (the summary then goes to stdout, progress to stderr), otherwise to
# stdout (the summary then goes to stderr). SURVEY_MEM_MB, when set, caps the address space
# (ulimit -v) of each run. SURVEY_COMMAND=import reads each file with `settings --scene FILE`
# instead (the import and its checks, no rendering: several times faster, for long mutation runs).
# SURVEY_ARGS are added to each command (e.g. --import-time-limit 5).
set -u

if [ $# -lt 2 ] || [ $# -gt 3 ]; then
    sed -n '2,4p' "$0" | sed 's/^# \{0,1\}//' >&2
    exit 64
fi
BINARY=$1
DIR=$2
TIMEOUT=${3:-60}
[ -x "$BINARY" ] || { echo "survey.sh: '$BINARY' is not an executable" >&2; exit 64; }
[ -d "$DIR" ] || { echo "survey.sh: '$DIR' is not a folder" >&2; exit 64; }
case $TIMEOUT in ''|*[!0-9]*) echo "survey.sh: TIMEOUT_S must be whole seconds" >&2; exit 64;; esac

TMP=$(mktemp -d "${TMPDIR:-/tmp}/survey.XXXXXX")
trap 'rm -rf "$TMP"' EXIT
BINARY=$(readlink -f "$BINARY")

if [ -n "${SURVEY_TSV:-}" ]; then
    TSV=$SURVEY_TSV
    exec 3>&1       # summary
    exec 4>&2       # progress
else
    TSV=$TMP/survey.tsv
    exec 3>&2
    exec 4>/dev/null
fi
printf 'file\tformat\toutcome\texit\tseconds\tstderr\tmax_rss_mb\n' > "$TSV"
[ -z "${SURVEY_TSV:-}" ] && cat "$TSV"

mapfile -d '' FILES < <(find "$DIR" -type f ! -iregex \
    '.*\.\(bin\|png\|jpe?g\|mtl\|mat\|glsl\|vert\|frag\|vs\|fs\|tga\|bmp\|gif\|dds\|ktx2?\|tsv\|txt\|log\|md\)$' -print0 | sort -z)
TOTAL=${#FILES[@]}
[ "$TOTAL" -gt 0 ] || { echo "survey.sh: no model files under '$DIR'" >&2; exit 1; }

NOT_NAMED=()
n=0
for file in "${FILES[@]}"; do
    n=$((n + 1))
    base=${file##*/}
    ext=${base##*.}
    [ "$ext" = "$base" ] && ext=-
    format=${ext,,}
    rm -f "$TMP/out.png" "$TMP/stdout" "$TMP/stderr" "$TMP/rss"
    start=$(date +%s%N)
    (
        cd "$TMP" || exit 125
        [ -n "${SURVEY_MEM_MB:-}" ] && ulimit -v $((SURVEY_MEM_MB * 1024))
        if [ "${SURVEY_COMMAND:-render}" = import ]; then
            command=(settings --scene "$(readlink -f "$file")" ${SURVEY_ARGS:-})
        else
            command=(render --scene "$(readlink -f "$file")" --size 160x90 --out "$TMP/out.png" ${SURVEY_ARGS:-})
        fi
        exec /usr/bin/time -f '%M' -o "$TMP/rss" \
            timeout -s KILL "$TIMEOUT" "$BINARY" "${command[@]}" >"$TMP/stdout" 2>"$TMP/stderr"
    ) 2>/dev/null
    code=$?
    end=$(date +%s%N)
    secs=$(awk -v a="$start" -v b="$end" 'BEGIN { printf "%.2f", (b - a) / 1e9 }')
    rss=$(tail -n 1 "$TMP/rss" 2>/dev/null | awk '/^[0-9]+$/ { printf "%.0f", $1 / 1024 }')
    line=$(grep -m 1 -v '^[[:space:]]*$' "$TMP/stderr" | tr '\t\r' '  ' | cut -c 1-300)
    [ -n "$line" ] || line=-
    if [ $code -eq 0 ]; then
        outcome=rendered
        [ "${SURVEY_COMMAND:-render}" = import ] || [ -s "$TMP/out.png" ] || outcome=other   # exit 0 without an image is odd
    elif [ $code -eq 2 ]; then
        outcome=refused
        grep -qF -- "$base" "$TMP/stderr" || NOT_NAMED+=("$file	$line")
    elif [ $code -eq 137 ] && awk -v s="$secs" -v t="$TIMEOUT" 'BEGIN { exit !(s >= t - 0.5) }'; then
        outcome=overtime
    elif [ $code -gt 128 ] && [ $code -lt 160 ]; then
        outcome=crashed
    else
        outcome=other
    fi
    # timeout -s KILL exits without reaping the killed child, so time saw only timeout itself
    [ $outcome = overtime ] && rss=-
    row=$(printf '%s\t%s\t%s\t%s\t%s\t%s\t%s' "$file" "$format" "$outcome" "$code" "$secs" "$line" "${rss:--}")
    printf '%s\n' "$row" >> "$TSV"
    [ -z "${SURVEY_TSV:-}" ] && printf '%s\n' "$row"
    printf '[%d/%d] %-8s %3d %6ss %s\n' "$n" "$TOTAL" "$outcome" "$code" "$secs" "$file" >&4
done

signame() { local c=$1; if [ "$c" -gt 128 ] && [ "$c" -lt 160 ]; then echo "SIG$(kill -l $((c - 128)))"; else echo "exit $c"; fi; }

{
    echo "survey: $BINARY over $DIR ($TOTAL files, timeout ${TIMEOUT}s)"
    echo
    echo "outcomes:"
    tail -n +2 "$TSV" | awk -F'\t' '{ c[$3]++ } END {
        split("rendered refused overtime crashed other", o, " ")
        for (i = 1; i <= 5; i++) printf "  %-9s %5d\n", o[i], c[o[i]] + 0 }'
    echo
    echo "per format:"
    tail -n +2 "$TSV" | awk -F'\t' '{ c[$2, $3]++; f[$2]++ } END {
        split("rendered refused overtime crashed other", o, " ")
        printf "  %-6s", "format"; for (i = 1; i <= 5; i++) printf " %9s", o[i]; printf " %6s\n", "total"
        n = 0; for (k in f) keys[++n] = k
        for (i = 1; i <= n; i++) for (j = i + 1; j <= n; j++) if (keys[j] < keys[i]) { t = keys[i]; keys[i] = keys[j]; keys[j] = t }
        for (i = 1; i <= n; i++) {
            printf "  %-6s", keys[i]; for (j = 1; j <= 5; j++) printf " %9d", c[keys[i], o[j]] + 0
            printf " %6d\n", f[keys[i]] }
    }'
    echo
    echo "10 slowest (seconds, outcome, max RSS MB, file):"
    tail -n +2 "$TSV" | sort -t$'\t' -k5,5 -g -r | head -n 10 |
        awk -F'\t' '{ printf "  %7s  %-8s %6s  %s\n", $5, $3, $7, $1 }'
    problems=$(tail -n +2 "$TSV" | awk -F'\t' '$3 == "crashed" || $3 == "overtime" || $3 == "other"')
    if [ -n "$problems" ]; then
        echo
        echo "crashed, over time or other:"
        while IFS=$'\t' read -r f fmt oc code secs line rss; do
            printf '  %-8s %-8s %6ss %6sMB  %s\n      %s\n' "$oc" "$(signame "$code")" "$secs" "$rss" "$f" "$line"
        done <<< "$problems"
    fi
    if [ ${#NOT_NAMED[@]} -gt 0 ]; then
        echo
        echo "refusals that do not name the file (${#NOT_NAMED[@]}):"
        printf '  %s\n' "${NOT_NAMED[@]}"
    fi
} >&3
