#!/usr/bin/env bash
# Builds the libFuzzer target for settings and sweep files (clang, ASan + UBSan; the `fuzz`
# preset) and runs it for a bounded time, default 300 s: ./scripts/fuzz.sh [seconds].
# Not part of the test suite. Findings (crash-*, leak-*, timeout-*) land in build/fuzz/findings.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
seconds="${1:-300}"
SHADOWLAB_PRESET=fuzz "$root/scripts/setup.sh"

work="$root/build/fuzz"
mkdir -p "$work/corpus" "$work/findings"
cp -n "$root"/fuzz/corpus/* "$work/corpus/"   # the seeds stay as they are in the repository
cd "$work/findings"
status=0
UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1 \
    "$work/fuzz/fuzz_settings_files" -max_total_time="$seconds" -max_len=65536 -timeout=10 \
    -print_final_stats=1 "$work/corpus" >"$work/fuzz.log" 2>&1 || status=$?
grep -E '^(#[0-9]+ +(INITED|DONE)|stat::number_of_executed_units|==[0-9]+==ERROR|SUMMARY)' "$work/fuzz.log" || true
echo "==> log: $work/fuzz.log; exit status $status (0: no crash, leak, timeout or sanitizer report)"
exit "$status"
