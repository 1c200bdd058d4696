#!/usr/bin/env bash
# Set up, build and run the whole test suite (Qt Test through CTest, on the headless platform: EGL, and OSMesa for the platform tests).
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
"$root/scripts/setup.sh"
cd "$root"
ctest --preset "${SHADOWLAB_PRESET:-release}" "$@"
