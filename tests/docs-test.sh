#!/usr/bin/env bash
# docs/cli.md and docs/settings.md are generated from the program and committed; fails when they
# no longer say what the program says. Usage: docs-test.sh BINARY
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
"$root/scripts/docs.sh" "$1" "$work"
stale=0
for page in cli.md settings.md; do
    if ! diff -u "$root/docs/$page" "$work/$page"; then
        echo "docs/$page is stale: regenerate it with scripts/docs.sh and commit it" >&2
        stale=1
    fi
done
exit $stale
