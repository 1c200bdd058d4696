#!/usr/bin/env bash
# The house in numbers (docs/architecture.md quotes them): lines per folder, the longest product
# functions, the largest files, and how many product files outside tests name a storage kind.
# Usage: scripts/code-stats.sh [top-N functions, default 10]
set -euo pipefail
cd "$(dirname "$0")/.."
top=${1:-10}
folders=(core scene renderer accuracy lab app platform shaders fuzz tests)
sources() { local d; for d in "$@"; do [ -d "$d" ] && find "$d" -type f \( -name '*.cpp' -o -name '*.h' -o -name '*.glsl' -o -name '*.vert' -o -name '*.frag' \); done; true; }

echo "## Lines per folder"
for d in "${folders[@]}"; do
    [ -d "$d" ] || continue
    printf '%-10s %6d\n' "$d" "$(sources "$d" | xargs cat | wc -l)"
done

product=$(sources core scene renderer accuracy lab app platform | grep -v '^tests/' | sort)

echo
echo "## The $top longest product functions (lines)"
# Universal Ctags gives each function's first and last line.
ctags -x --_xformat='%{line} %{end} %{input} %{scope}::%{name}' --kinds-c++=f --fields=+e --language-force=C++ $product 2>/dev/null \
    | grep -v "::__anon[0-9a-f]*$" | awk '$2 > 0 { name = $4; gsub(/(shadowlab|__anon[0-9a-f]+|cli)::/, "", name); sub(/^::/, "", name)
                   printf "%5d  %s:%d  %s\n", $2 - $1 + 1, $3, $1, name }' | sort -rn | head -n "$top" || true

echo
echo "## Product files over 600 lines"
for f in $product; do n=$(wc -l < "$f"); [ "$n" -gt 600 ] && printf '%5d  %s\n' "$n" "$f"; done | sort -rn || true

echo
echo "## Product C++ files that name a storage or technique kind"
for word in Moments evsm4 pcss; do
    printf '%-8s %3d\n' "$word" "$(grep -l -- "$word" $(echo "$product" | grep -E '\.(cpp|h)$') | wc -l)"
done
