#!/usr/bin/env bash
# The speed guard: builds BASE (default: the previous merge on main, else HEAD~1) in build/bench/base
# and the working tree in build/release (the same RelWithDebInfo flags), runs a fixed suite against both, interleaved, and prints
# HEAD/BASE ratios with their spread, flagging any figure more than 5 % slower. Writes the table to
# docs/performance.md. A benchmark, not a test: CI times nothing.
#
#   ./scripts/bench.sh [BASE] [--rounds N] [--quick]
#
# The suite: seed steady, moving light and moving camera at 1280x720; the city steady and with a
# moving camera; a generated 10^6-triangle mesh steady and its load; a small report. Each round
# runs every case once on each build, in alternating order, so a machine that drifts moves both.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
base=""
args=()
while [ $# -gt 0 ]; do
    case "$1" in
        --rounds|--quick|--out) args+=("$1"); [ "$1" = --rounds ] || [ "$1" = --out ] && { args+=("$2"); shift; }; shift ;;
        -*) echo "bench.sh: unknown option '$1'; use [BASE] [--rounds N] [--quick]" >&2; exit 2 ;;
        *) [ -z "$base" ] || { echo "bench.sh: give one BASE" >&2; exit 2; }; base=$1; shift ;;
    esac
done
cd "$root"
if [ -z "$base" ]; then
    # The previous merge on main's first-parent line, not HEAD itself.
    base=$(git rev-list --first-parent --merges -n 1 HEAD~1 2>/dev/null || true)
    [ -n "$base" ] || base=HEAD~1
fi
base_commit=$(git rev-parse --verify "$base^{commit}") || { echo "bench.sh: '$base' is not a commit" >&2; exit 2; }

echo "==> building HEAD (the working tree) in build/release"
"$root/scripts/setup.sh" >/dev/null     # the packages, and build/release: HEAD
work="$root/build/bench"
mkdir -p "$work"

# BASE: its own checkout and build folder, kept between runs.
if [ ! -d "$work/base-src/.git" ] && [ ! -f "$work/base-src/.git" ]; then
    git worktree add --detach "$work/base-src" "$base_commit" >/dev/null
else
    git -C "$work/base-src" checkout --detach -q "$base_commit"
fi
echo "==> building BASE $(git rev-parse --short "$base_commit") in $work/base"
cmake -S "$work/base-src" -B "$work/base" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo >/dev/null
cmake --build "$work/base" --target shadowlab -j "$(nproc)" >/dev/null
[ -f "$work/mesh1m.ply" ] || python3 "$root/scripts/make-mesh.py" 1000000 "$work/mesh1m.ply" >/dev/null
python3 "$root/scripts/bench.py" --base "$work/base/app/shadowlab" --head "$root/build/release/app/shadowlab" \
    --base-name "$(git rev-parse --short "$base_commit")" --head-name "$(git rev-parse --short HEAD)$(git diff --quiet HEAD -- . ':!docs' || echo +)" \
    --mesh "$work/mesh1m.ply" --out "$root/docs/performance.md" "${args[@]}"
