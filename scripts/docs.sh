#!/usr/bin/env bash
# Regenerates docs/cli.md (from `shadowlab --help` and `shadowlab help <command>`) and
# docs/settings.md (from the settings table, `shadowlab settings --json`) with the release
# build's program. The docs_up_to_date test runs this into a temporary folder and compares.
# Usage: scripts/docs.sh [BINARY [FOLDER]]
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
binary="${1:-$root/build/${SHADOWLAB_PRESET:-release}/app/shadowlab}"
folder="${2:-$root/docs}"
[ -x "$binary" ] || { echo "docs.sh: no program at $binary; build first (scripts/setup.sh)" >&2; exit 1; }
python3 "$root/scripts/help-docs.py" cli-md "$binary" "$folder/cli.md"
python3 "$root/scripts/help-docs.py" settings-md "$binary" "$folder/settings.md"
