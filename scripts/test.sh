#!/usr/bin/env bash
# Set up, build and run the whole test suite (Qt Test through CTest, headless).
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
"$root/scripts/setup.sh"
cd "$root"
QT_QPA_PLATFORM=osmesa ctest --preset "${SHADOWLAB_PRESET:-release}" "$@"
